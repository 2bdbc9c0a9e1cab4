// The grey-box plant models the identification fits: the simulator's own rigid and two-mass mechanics, driven by a
// torque command through a known current loop, with the simulator's dry-friction sub-step -- on any scalar type, so
// that Ceres differentiates the very code the simulator runs.
//
//   state  z = [current-loop torque (only with a finite current_bw_hz); mechanical states]
//   input  u = [torque command (N*m), external torque on the motor body, external torque on the load body]
//
// Parameter vectors use the names of the plant objects (RigidPlant / TwoMassPlant fields), so an estimate becomes a
// plant for simulation by name.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "servobench/plant/dry_friction.hpp"
#include "servobench/plant/rigid.hpp"
#include "servobench/plant/two_mass.hpp"

namespace servobench::identify {

enum class PlantModel { kRigid = 0, kTwoMass = 1 };

struct ParameterInfo {
  const char* name;
  const char* unit;
  double lower;     // physical lower bound (inertias and the stiffness strictly above 0: a tiny positive floor)
  bool linear;      // enters the linear part (A, B); the others enter the friction or the load
  const char* meaning;
};

// The parameters of a model, in the order of its parameter vector.
//   rigid:    inertia_kgm2, viscous_nms, coulomb_nm, static_nm, stribeck_speed_rad_s, load_nm
//   two-mass: jm_kgm2, jl_kgm2, k_nm_per_rad, c_nms_per_rad, motor_viscous_nms, load_viscous_nms,
//             motor_coulomb_nm, motor_static_nm, motor_stribeck_speed_rad_s, load_coulomb_nm, load_nm
const std::vector<ParameterInfo>& model_parameters(PlantModel model);
int parameter_count(PlantModel model);
int linear_parameter_count(PlantModel model);  // the first ones of the vector
int mechanical_states(PlantModel model);        // 2 or 4
int body_count(PlantModel model);               // 1 or 2
const char* model_name(PlantModel model);

// Plant parameter objects (for simulation) from a parameter vector.
plant::RigidPlantParams rigid_plant(const std::vector<double>& p, double stribeck_exponent);
plant::TwoMassPlantParams two_mass_plant(const std::vector<double>& p, double stribeck_exponent);

// The index of the breakaway level (static_nm / motor_static_nm) and of its Coulomb level in the vector.
inline int static_index(PlantModel m) { return m == PlantModel::kRigid ? 3 : 7; }
inline int coulomb_index(PlantModel m) { return m == PlantModel::kRigid ? 2 : 6; }
inline int stribeck_index(PlantModel m) { return m == PlantModel::kRigid ? 4 : 8; }
// User vector (breakaway level Fs; at or below Fc: no peak) <-> internal vector (excess Fs - Fc >= 0).
std::vector<double> to_internal(PlantModel m, std::vector<double> p);
std::vector<double> to_external(PlantModel m, std::vector<double> p);

// The structure shared by every evaluation: which states are where.
struct ModelLayout {
  PlantModel model = PlantModel::kRigid;
  double current_bw_hz = std::numeric_limits<double>::infinity();  // known current-loop bandwidth, Hz
  double stribeck_exponent = 2.0;
  int lag_states() const { return std::isinf(current_bw_hz) ? 0 : 1; }
  int states() const { return lag_states() + mechanical_states(model); }
  int motor_angle() const { return lag_states(); }
  int motor_speed() const { return lag_states() + 1; }
  int load_angle() const { return lag_states() + (model == PlantModel::kRigid ? 0 : 2); }
  int load_speed() const { return lag_states() + (model == PlantModel::kRigid ? 1 : 3); }
  plant::BodyIndex body(int b) const {
    return b == 0 ? plant::BodyIndex{motor_angle(), motor_speed(), 1} : plant::BodyIndex{load_angle(), load_speed(), 2};
  }
};

// The continuous linear part (A: n x n, B: n x 3) from the linear parameters p[0..linear_parameter_count) -- the
// current loop (torque command -> torque, first order at current_bw_hz; none when infinite) in series with the
// plant's own matrices (plant::rigid_linear / two_mass_linear), the same series connection as machine::PowerTrain.
template <class T, class MatA, class MatB>
void model_linear(const ModelLayout& layout, const T* p, MatA& a, MatB& b) {
  const int nl = layout.lag_states();
  const int nm = mechanical_states(layout.model);
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4> am(nm, nm);
  Eigen::Matrix<T, Eigen::Dynamic, 3, 0, 4, 3> bm(nm, 3);
  if (layout.model == PlantModel::kRigid)
    plant::rigid_linear(p[0], p[1], am, bm);
  else
    plant::two_mass_linear(p[0], p[1], p[2], p[3], p[4], p[5], am, bm);
  a.setZero(nl + nm, nl + nm);
  b.setZero(nl + nm, 3);
  a.bottomRightCorner(nm, nm) = am;
  b.bottomRightCorner(nm, 2) = bm.rightCols(2);
  if (nl == 0) {
    b.bottomLeftCorner(nm, 1) = bm.col(0);
  } else {
    const double wc = 2.0 * M_PI * layout.current_bw_hz;
    a(0, 0) = T(-wc);
    b(0, 0) = T(wc);
    a.bottomLeftCorner(nm, 1) = bm.col(0);
  }
}

// The dry friction of each body and the constant load torque (N*m, on the load body, opposing positive motion)
// from the parameter vector of model M. In this (internal) vector the breakaway entry holds the Stribeck EXCESS
// Fs - Fc >= 0 rather than Fs: a breakaway level below the Coulomb level would switch the peak off and with it
// every derivative (see to_internal / to_external).
template <PlantModel M, class T>
void model_friction(const ModelLayout& layout, const T* p, plant::DryFriction<T>* dry, T* load_nm) {
  const double e = layout.stribeck_exponent;
  if constexpr (M == PlantModel::kRigid) {
    dry[0] = plant::DryFriction<T>{p[2], p[2] + p[3], p[4], e};
    *load_nm = p[5];
  } else {
    dry[0] = plant::DryFriction<T>{p[6], p[6] + p[7], p[8], e};
    dry[1] = plant::DryFriction<T>{p[9], p[9], T(1.0), e};
    *load_nm = p[10];
  }
}

// The model's discretisation over one sub-step h, for every set of bodies locked by stiction (index = bit mask),
// with the derivatives with respect to the linear parameters -- computed in double once per parameter point and
// shared by all segments of a fit.
struct Discretisation {
  std::vector<double> linear_values;            // the linear parameters it was computed for
  std::vector<Eigen::MatrixXd> phi, gamma;      // [mask]
  std::vector<std::vector<Eigen::MatrixXd>> dphi, dgamma;  // [mask][k]
};

Discretisation discretise(const ModelLayout& layout, const std::vector<double>& linear_values, double h,
                          bool derivatives);

// Thread-safe memo of the last discretisations (one with derivatives, one without).
class DiscretisationCache {
 public:
  DiscretisationCache(ModelLayout layout, double h) : layout_(layout), h_(h) {}
  std::shared_ptr<const Discretisation> get(const double* linear_values, bool derivatives);

 private:
  ModelLayout layout_;
  double h_;
  std::mutex mutex_;
  std::shared_ptr<const Discretisation> with_, without_;
};

}  // namespace servobench::identify
