// A rigid single-inertia mechanism in SI units (rad, rad/s, N*m, kg*m^2).
//
//   J * dw/dt = torque_motor - T_friction(w) - load - unbalance*sin(theta) + cogging*sin(N*theta),  dtheta/dt = w
//
// Friction: viscous + Coulomb + Stribeck with stiction (plant/friction.hpp). The motor and the load are one
// body, so the encoder reads the same angle whether it is mounted on the motor or on the load.
#pragma once

#include "servobench/plant/friction.hpp"
#include "servobench/plant/mechanics.hpp"

namespace servobench::plant {

struct RigidPlantParams {
  double inertia_kgm2 = 1.0e-4;       // total inertia seen by the motor, kg*m^2, > 0
  double viscous_nms = 1.0e-4;        // viscous friction, N*m*s/rad, >= 0
  double coulomb_nm = 0.0;            // Coulomb (sliding) friction, N*m, >= 0
  double static_nm = 0.0;             // breakaway (static) friction, N*m; 0 = equal to coulomb_nm
  double stribeck_speed_rad_s = 0.01; // Stribeck speed, rad/s, > 0
  double stribeck_exponent = 2.0;     // Stribeck shape exponent, 0.5..4
  double coulomb_asym_nm = 0.0;       // Coulomb asymmetry (Fc+ - Fc-)/2, N*m, |.| <= coulomb_nm (friction.hpp)
  double viscous_asym_nms = 0.0;      // viscous asymmetry (b+ - b-)/2, N*m*s/rad, |.| <= viscous_nms
  double load_nm = 0.0;               // constant load torque (e.g. gravity on a vertical screw axis), N*m
  double unbalance_nm = 0.0;          // gravity torque of an unbalanced arm: -unbalance*sin(theta), N*m
  double cogging_nm = 0.0;            // cogging ripple amplitude, N*m, >= 0
  double cogging_periods = 0.0;       // cogging periods per revolution, whole number 0..1000
  void validate() const;
  FrictionParams friction() const {
    return FrictionParams{viscous_nms, coulomb_nm, static_nm, stribeck_speed_rad_s, stribeck_exponent,
                          coulomb_asym_nm, viscous_asym_nms};
  }
};

Mechanics rigid_mechanics(const RigidPlantParams& params);

// The linear part x' = A x + B u of a rigid body, x = [angle, speed], u = [motor torque, external torque on the
// body, load torque], in any scalar type (the simulator on double, the identification on Jets). a: 2x2, b: 2x3.
template <class T, class MatA, class MatB>
void rigid_linear(const T& inertia_kgm2, const T& viscous_nms, MatA& a, MatB& b) {
  const T inv_j = T(1.0) / inertia_kgm2;
  a.setZero();
  b.setZero();
  a(0, 1) = T(1.0);
  a(1, 1) = -viscous_nms * inv_j;
  b(1, 0) = inv_j;
  b(1, 1) = inv_j;
  b(1, 2) = inv_j;
}

}  // namespace servobench::plant
