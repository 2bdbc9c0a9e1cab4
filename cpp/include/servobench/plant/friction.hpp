// Friction of one moving body: viscous + Coulomb + Stribeck, with true stiction.
//
//   moving (w != 0):  T_f(w) = -sign(w) * (Fc + (Fs - Fc) * exp(-(|w|/ws)^delta)) - b*w
//   at rest:          |T_f| <= Fs, whatever holds the body still (static friction)
//
// Fc = coulomb_nm, Fs = static_nm (breakaway level, >= Fc; 0 means "equal to Fc", no Stribeck peak),
// ws = stribeck_speed_rad_s, delta = stribeck_exponent, b = viscous_nms. The viscous part is linear and goes into
// the exact linear integration; the rest is solved implicitly over each sub-step by the machine layer.
//
// Asymmetric friction (issue 19; e.g. a fatigued ball screw): a = coulomb_asym_nm, bv = viscous_asym_nms give
//   w > 0:  Fc+ = Fc + a, Fs+ = Fs + a, b+ = b + bv;   w < 0:  Fc- = Fc - a, Fs- = Fs - a, b- = b - bv,
// i.e. Fc = (Fc+ + Fc-)/2, a = (Fc+ - Fc-)/2, b = (b+ + b-)/2, bv = (b+ - b-)/2; |a| <= Fc, |bv| <= b. 0: symmetric.
#pragma once

#include <cmath>

#include "servobench/plant/dry_friction.hpp"

namespace servobench::plant {

struct FrictionParams {
  double viscous_nms = 0.0;           // N*m*s/rad, >= 0
  double coulomb_nm = 0.0;            // Fc, N*m, >= 0
  double static_nm = 0.0;             // Fs, N*m, 0 (= Fc) or >= Fc
  double stribeck_speed_rad_s = 0.01; // ws, rad/s, > 0
  double stribeck_exponent = 2.0;     // delta, 0.5..4
  double coulomb_asym_nm = 0.0;       // a = (Fc+ - Fc-)/2, N*m, |a| <= coulomb_nm
  double viscous_asym_nms = 0.0;      // bv = (b+ - b-)/2, N*m*s/rad, |bv| <= viscous_nms
  // owner: the parameter object's name for messages; prefix: field prefix ("" or "motor_"/"load_").
  void validate(const char* owner, const char* prefix) const;

  double breakaway_nm() const { return static_nm > coulomb_nm ? static_nm : coulomb_nm; }
  bool has_dry_friction() const { return breakaway_nm() > 0.0; }
  // Magnitude of the dry friction while sliding at |speed| (N*m): Fc + (Fs-Fc) exp(-(|w|/ws)^delta).
  double sliding_nm(double speed_rad_s) const { return sliding_friction_nm(dry(), speed_rad_s); }
  // The dry part in the form the sub-step integrator uses (plant/dry_friction.hpp).
  DryFriction<double> dry() const {
    return DryFriction<double>{coulomb_nm, breakaway_nm(), stribeck_speed_rad_s, stribeck_exponent, coulomb_asym_nm,
                               viscous_asym_nms};
  }
  // The steady friction torque opposing motion at a given speed (N*m, sign of the speed), viscous included;
  // at zero speed it returns 0 (static friction is whatever holds the body). For friction curves.
  double steady_torque_nm(double speed_rad_s) const {
    if (speed_rad_s == 0.0) return 0.0;
    const double dir = speed_rad_s > 0 ? 1.0 : -1.0;
    return dir * directional_sliding_nm(dry(), speed_rad_s, dir) + viscous_nms * speed_rad_s;
  }
};

}  // namespace servobench::plant
