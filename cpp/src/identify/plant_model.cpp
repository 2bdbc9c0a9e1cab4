#include "servobench/identify/plant_model.hpp"

#include <ceres/jet.h>

#include "servobench/plant/zoh.hpp"

namespace servobench::identify {

namespace {
constexpr double kTiny = 1e-300;

const std::vector<ParameterInfo> kRigid = {
    {"inertia_kgm2", "kg*m^2", kTiny, true, "total inertia seen by the motor"},
    {"viscous_nms", "N*m*s/rad", 0.0, true, "viscous friction"},
    {"coulomb_nm", "N*m", 0.0, false, "Coulomb (sliding) friction"},
    {"static_nm", "N*m", 0.0, false, "breakaway (Stribeck) level; at or below coulomb_nm: no Stribeck peak"},
    {"stribeck_speed_rad_s", "rad/s", kTiny, false, "Stribeck speed"},
    {"load_nm", "N*m", -std::numeric_limits<double>::infinity(), false, "constant load torque (e.g. gravity)"},
};
const std::vector<ParameterInfo> kTwoMass = {
    {"jm_kgm2", "kg*m^2", kTiny, true, "motor inertia"},
    {"jl_kgm2", "kg*m^2", kTiny, true, "load inertia"},
    {"k_nm_per_rad", "N*m/rad", kTiny, true, "shaft stiffness"},
    {"c_nms_per_rad", "N*m*s/rad", 0.0, true, "shaft damping"},
    {"motor_viscous_nms", "N*m*s/rad", 0.0, true, "motor-side viscous friction"},
    {"load_viscous_nms", "N*m*s/rad", 0.0, true, "load-side viscous friction"},
    {"motor_coulomb_nm", "N*m", 0.0, false, "motor-side Coulomb friction"},
    {"motor_static_nm", "N*m", 0.0, false, "motor-side breakaway level; at or below motor_coulomb_nm: no peak"},
    {"motor_stribeck_speed_rad_s", "rad/s", kTiny, false, "motor-side Stribeck speed"},
    {"load_coulomb_nm", "N*m", 0.0, false, "load-side Coulomb friction"},
    {"load_nm", "N*m", -std::numeric_limits<double>::infinity(), false, "constant load torque on the load side"},
};
}  // namespace

const std::vector<ParameterInfo>& model_parameters(PlantModel model) {
  return model == PlantModel::kRigid ? kRigid : kTwoMass;
}
int parameter_count(PlantModel model) { return static_cast<int>(model_parameters(model).size()); }
int linear_parameter_count(PlantModel model) { return model == PlantModel::kRigid ? 2 : 6; }
int mechanical_states(PlantModel model) { return model == PlantModel::kRigid ? 2 : 4; }
int body_count(PlantModel model) { return model == PlantModel::kRigid ? 1 : 2; }
const char* model_name(PlantModel model) { return model == PlantModel::kRigid ? "rigid" : "two_mass"; }

std::vector<double> to_internal(PlantModel m, std::vector<double> p) {
  const std::size_t s = static_cast<std::size_t>(static_index(m)), c = static_cast<std::size_t>(coulomb_index(m));
  p[s] = p[s] > p[c] ? p[s] - p[c] : 0.0;
  return p;
}
std::vector<double> to_external(PlantModel m, std::vector<double> p) {
  const std::size_t s = static_cast<std::size_t>(static_index(m)), c = static_cast<std::size_t>(coulomb_index(m));
  p[s] = p[c] + p[s];
  return p;
}

plant::RigidPlantParams rigid_plant(const std::vector<double>& p, double stribeck_exponent) {
  plant::RigidPlantParams r;
  r.inertia_kgm2 = p.at(0);
  r.viscous_nms = p.at(1);
  r.coulomb_nm = p.at(2);
  r.static_nm = p.at(3) > p.at(2) ? p.at(3) : 0.0;
  r.stribeck_speed_rad_s = p.at(4);
  r.stribeck_exponent = stribeck_exponent;
  r.load_nm = p.at(5);
  return r;
}

plant::TwoMassPlantParams two_mass_plant(const std::vector<double>& p, double stribeck_exponent) {
  plant::TwoMassPlantParams r;
  r.jm_kgm2 = p.at(0);
  r.jl_kgm2 = p.at(1);
  r.k_nm_per_rad = p.at(2);
  r.c_nms_per_rad = p.at(3);
  r.motor_viscous_nms = p.at(4);
  r.load_viscous_nms = p.at(5);
  r.motor_coulomb_nm = p.at(6);
  r.motor_static_nm = p.at(7) > p.at(6) ? p.at(7) : 0.0;
  r.motor_stribeck_speed_rad_s = p.at(8);
  r.motor_stribeck_exponent = stribeck_exponent;
  r.load_coulomb_nm = p.at(9);
  r.load_nm = p.at(10);
  return r;
}

Discretisation discretise(const ModelLayout& layout, const std::vector<double>& linear_values, double h,
                          bool derivatives) {
  const int nlin = linear_parameter_count(layout.model);
  const int n = layout.states();
  // A and B with their derivatives with respect to the linear parameters, from the templated builder on Jets.
  using J = ceres::Jet<double, 6>;
  std::vector<J> pj(static_cast<std::size_t>(nlin));
  for (int k = 0; k < nlin; ++k) pj[static_cast<std::size_t>(k)] = J(linear_values[static_cast<std::size_t>(k)], k);
  Eigen::Matrix<J, Eigen::Dynamic, Eigen::Dynamic> aj;
  Eigen::Matrix<J, Eigen::Dynamic, Eigen::Dynamic> bj;
  model_linear(layout, pj.data(), aj, bj);
  Eigen::MatrixXd a(n, n), b(n, 3);
  std::vector<Eigen::MatrixXd> da(static_cast<std::size_t>(derivatives ? nlin : 0), Eigen::MatrixXd(n, n));
  std::vector<Eigen::MatrixXd> db(da.size(), Eigen::MatrixXd(n, 3));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      a(r, c) = aj(r, c).a;
      for (std::size_t k = 0; k < da.size(); ++k) da[k](r, c) = aj(r, c).v[static_cast<Eigen::Index>(k)];
    }
    for (int c = 0; c < 3; ++c) {
      b(r, c) = bj(r, c).a;
      for (std::size_t k = 0; k < db.size(); ++k) db[k](r, c) = bj(r, c).v[static_cast<Eigen::Index>(k)];
    }
  }
  Discretisation d;
  d.linear_values = linear_values;
  const int nb = body_count(layout.model);
  const unsigned masks = 1u << nb;
  d.phi.resize(masks);
  d.gamma.resize(masks);
  d.dphi.resize(masks);
  d.dgamma.resize(masks);
  for (unsigned mask = 0; mask < masks; ++mask) {
    Eigen::MatrixXd al = a, bl = b;
    std::vector<Eigen::MatrixXd> dal = da, dbl = db;
    std::vector<int> frozen;
    for (int i = 0; i < nb; ++i) {
      if (!(mask & (1u << i))) continue;
      frozen.push_back(layout.body(i).angle);
      frozen.push_back(layout.body(i).speed);
    }
    for (int r : frozen) {
      al.row(r).setZero();
      bl.row(r).setZero();
      for (auto& m : dal) m.row(r).setZero();
      for (auto& m : dbl) m.row(r).setZero();
    }
    plant::ZohDerivatives z = plant::discretize_zoh_with_derivatives(al, bl, dal, dbl, h);
    for (int r : frozen) {  // exactly frozen, as machine::PowerTrain does
      z.zoh.phi.row(r).setZero();
      z.zoh.phi(r, r) = 1.0;
      z.zoh.gamma.row(r).setZero();
      for (auto& m : z.dphi) m.row(r).setZero();
      for (auto& m : z.dgamma) m.row(r).setZero();
    }
    d.phi[mask] = z.zoh.phi;
    d.gamma[mask] = z.zoh.gamma;
    d.dphi[mask] = std::move(z.dphi);
    d.dgamma[mask] = std::move(z.dgamma);
  }
  return d;
}

std::shared_ptr<const Discretisation> DiscretisationCache::get(const double* linear_values, bool derivatives) {
  const int nlin = linear_parameter_count(layout_.model);
  std::vector<double> v(linear_values, linear_values + nlin);
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = derivatives ? with_ : without_;
  if (!slot || slot->linear_values != v) slot = std::make_shared<const Discretisation>(discretise(layout_, v, h_, derivatives));
  return slot;
}

}  // namespace servobench::identify
