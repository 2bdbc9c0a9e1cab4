// A user's linear plant in the loop (issue 23): any continuous single-input single-output state-space model
//
//   x' = A x + B u,   y = C x   (D must be 0),   n = 2..kMaxLtiStates states,
//
// from the motor torque u (N*m) to the encoder angle y (rad). With lead_m_per_rev > 0 the model is a linear axis
// in its own units, force F (N) to position s (m), behind an ideal lossless screw/belt of that lead:
//   F = 2 pi u / lead,   y = 2 pi s / lead   (so B and C are scaled by 2 pi / lead; docs/decisions.md LT3).
//
// The simulator integrates it like the built-in plants: the linear part exactly by zero-order hold over each
// sub-step (plant/zoh.hpp, one matrix exponential; so inside a servo tick too), optionally with the dry friction of
// one body acting at the input (plant/friction.hpp: Coulomb, Stribeck, stiction, asymmetry, N*m at the motor) and a
// constant load torque (N*m). Viscous friction belongs in A.
//
// Requirements (decision LT1): relative degree >= 2 (C B = 0: a torque accelerates, it does not move the angle at
// once), so the angle's derivative y' = C A x is a state too -- the speed (rad/s) a velocity-mode drive and the
// friction read. The plant compiles to the common description (plant/mechanics.hpp) in the coordinates
//   z = T x,   T = [C; C A; Q'],   Q: an orthonormal basis of the complement of span{C', (C A)'},
// so z0 = angle, z1 = speed. Dry friction needs a finite high-frequency inertia J = 1 / (C A B) > 0 (relative
// degree exactly 2); it is what the friction solver divides by. Unstable and marginally stable plants are allowed
// (a position loop stabilises them or the run's guards stop it); stability() says which.
#pragma once

#include <string>

#include <Eigen/Core>

#include "servobench/plant/friction.hpp"
#include "servobench/plant/mechanics.hpp"

namespace servobench::plant {

// The largest state count of an LtiPlant: the power train holds at most 8 states (machine/powertrain.hpp), one of
// them the drive's current loop (decision LT2).
constexpr int kMaxLtiStates = 7;

struct LtiPlantParams {
  Eigen::MatrixXd a;             // n x n, 1/s (model units)
  Eigen::MatrixXd b;             // n x 1, model state units per s per N*m (or per N)
  Eigen::MatrixXd c;             // 1 x n, rad (or m) per model state unit
  double d = 0.0;                // feed-through, must be 0
  double lead_m_per_rev = 0.0;   // 0: rotary model (N*m -> rad); > 0: linear model (N -> m) behind this lead, m/rev
  double coulomb_nm = 0.0;       // Coulomb (sliding) friction at the motor, N*m, >= 0
  double static_nm = 0.0;        // breakaway friction, N*m; 0 = equal to coulomb_nm
  double stribeck_speed_rad_s = 0.01;  // Stribeck speed, rad/s, > 0
  double stribeck_exponent = 2.0;      // Stribeck shape exponent, 0.5..4
  double coulomb_asym_nm = 0.0;  // Coulomb asymmetry (Fc+ - Fc-)/2, N*m, |.| <= coulomb_nm
  double load_nm = 0.0;          // constant load torque at the motor, N*m (positive opposes positive motion)

  LtiPlantParams();  // the default: a rigid body J = 1e-4 kg*m^2, b = 1e-4 N*m*s/rad, as RigidPlant's default
  void validate() const;
  int states() const { return static_cast<int>(a.rows()); }
  FrictionParams friction() const {
    return FrictionParams{0.0, coulomb_nm, static_nm, stribeck_speed_rad_s, stribeck_exponent, coulomb_asym_nm, 0.0};
  }
  // The model seen from the ports: motor torque (N*m) -> encoder angle (rad), i.e. b and c scaled by 2 pi / lead
  // for a linear model. a: n x n, b: n x 1, c: 1 x n.
  void port_model(Eigen::MatrixXd& a_out, Eigen::MatrixXd& b_out, Eigen::MatrixXd& c_out) const;
  // "stable" (every pole in Re s < 0), "marginal (k poles at s = 0 or on the imaginary axis)" or
  // "unstable (k poles in Re s > 0)"; poles within 1e-6 * max|pole| (and 1e-12 1/s) of the axis count as on it.
  std::string stability() const;
  // The high-frequency inertia 1 / (C A B) at the motor, kg*m^2; 0 when the relative degree is above 2.
  double inertia_kgm2() const;
};

Mechanics lti_mechanics(const LtiPlantParams& params);

}  // namespace servobench::plant
