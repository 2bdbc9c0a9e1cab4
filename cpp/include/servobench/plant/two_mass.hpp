// A two-mass mechanism: motor inertia Jm and load inertia Jl joined by a shaft of stiffness k and damping c.
//
//   Jm*wm' = T_motor - k(thm - thl) - c(wm - wl) - Tf_m(wm) + cogging*sin(N*thm)
//   Jl*wl' =           k(thm - thl) + c(wm - wl) - Tf_l(wl) - load - unbalance*sin(thl)
//
// Tf_m / Tf_l: friction of each side (viscous + Coulomb + Stribeck, stiction). Seen from the motor torque to
// the motor angle, the undamped anti-resonance is sqrt(k/Jl) and the resonance sqrt(k (Jm+Jl)/(Jm Jl)).
#pragma once

#include "servobench/plant/friction.hpp"
#include "servobench/plant/mechanics.hpp"

namespace servobench::plant {

struct TwoMassPlantParams {
  double jm_kgm2 = 2.0e-5;             // motor inertia, kg*m^2, > 0
  double jl_kgm2 = 6.0e-5;             // load inertia, kg*m^2, > 0
  double k_nm_per_rad = 400.0;         // shaft (coupling) stiffness, N*m/rad, > 0
  double c_nms_per_rad = 0.005;        // shaft damping, N*m*s/rad, >= 0
  double motor_viscous_nms = 1.0e-5;   // motor-side viscous friction, N*m*s/rad
  double motor_coulomb_nm = 0.0;       // motor-side Coulomb friction, N*m
  double motor_static_nm = 0.0;        // motor-side breakaway friction, N*m (0 = coulomb)
  double motor_stribeck_speed_rad_s = 0.01;
  double motor_stribeck_exponent = 2.0;
  double load_viscous_nms = 1.0e-5;    // load-side viscous friction, N*m*s/rad
  double load_coulomb_nm = 0.0;        // load-side Coulomb friction, N*m
  double load_static_nm = 0.0;         // load-side breakaway friction, N*m (0 = coulomb)
  double load_stribeck_speed_rad_s = 0.01;
  double load_stribeck_exponent = 2.0;
  double motor_coulomb_asym_nm = 0.0;  // motor-side Coulomb asymmetry (Fc+ - Fc-)/2, N*m (friction.hpp)
  double motor_viscous_asym_nms = 0.0; // motor-side viscous asymmetry (b+ - b-)/2, N*m*s/rad
  double load_coulomb_asym_nm = 0.0;   // load-side Coulomb asymmetry, N*m
  double load_viscous_asym_nms = 0.0;  // load-side viscous asymmetry, N*m*s/rad
  double load_nm = 0.0;                // constant load torque on the load side, N*m
  double unbalance_nm = 0.0;           // gravity torque -unbalance*sin(load angle), N*m
  double cogging_nm = 0.0;             // motor cogging amplitude, N*m
  double cogging_periods = 0.0;        // cogging periods per motor revolution
  void validate() const;
  FrictionParams motor_friction() const {
    return {motor_viscous_nms, motor_coulomb_nm,           motor_static_nm,       motor_stribeck_speed_rad_s,
            motor_stribeck_exponent, motor_coulomb_asym_nm, motor_viscous_asym_nms};
  }
  FrictionParams load_friction() const {
    return {load_viscous_nms,       load_coulomb_nm,      load_static_nm,       load_stribeck_speed_rad_s,
            load_stribeck_exponent, load_coulomb_asym_nm, load_viscous_asym_nms};
  }
  // Undamped anti-resonance sqrt(k/Jl) and resonance sqrt(k(Jm+Jl)/(Jm Jl)) frequencies, Hz.
  double antiresonance_hz() const;
  double resonance_hz() const;
};

Mechanics two_mass_mechanics(const TwoMassPlantParams& params);

// The linear part x' = A x + B u of the two-mass mechanism, x = [motor angle, motor speed, load angle, load speed],
// u = [motor torque, external torque on the motor, external torque on the load], in any scalar type (the simulator
// on double, the identification on Jets). a: 4x4, b: 4x3.
template <class T, class MatA, class MatB>
void two_mass_linear(const T& jm, const T& jl, const T& k, const T& c, const T& motor_viscous, const T& load_viscous,
                     MatA& a, MatB& b) {
  a.setZero();
  b.setZero();
  a(0, 1) = T(1.0);
  a(1, 0) = -k / jm;
  a(1, 1) = -(c + motor_viscous) / jm;
  a(1, 2) = k / jm;
  a(1, 3) = c / jm;
  a(2, 3) = T(1.0);
  a(3, 0) = k / jl;
  a(3, 1) = c / jl;
  a(3, 2) = -k / jl;
  a(3, 3) = -(c + load_viscous) / jl;
  b(1, 0) = T(1.0) / jm;
  b(1, 1) = T(1.0) / jm;
  b(3, 2) = T(1.0) / jl;
}

}  // namespace servobench::plant
