// Jog / velocity mode: GT_PrflV (GT L980-1027) and GE GT_PrflV (GE L1190-1266).
//
// The axis ramps at Acc to the signed commanded velocity and holds it until a new velocity or a stop;
// velocity, acceleration and direction may all change during motion (GT L1025, GE L1263-1264). The GT/GE
// ramps are linear (a T ramp); the jerk-limited ramp is used by the ADLINK velocity move (adlink_profile.hpp).
// Internal units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include <limits>

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// From any state: change to `vel` (pulse/tick, signed) with |a| <= acc (pulse/tick^2) and |jerk| <= jerk
// (pulse/tick^3; +inf = linear ramp), then hold it forever (open-ended profile). vel = 0: ends at rest.
Profile plan_jog(const MotionState& from, double vel, double acc,
                 double jerk = std::numeric_limits<double>::infinity());

// GT_PrflV parameters, per sample time: GT L994-995.
struct GtJogParams {
  double vel = 0.0;  // pulse/ST, signed, -16384..16384 (L994); the sign is the direction
  double acc = 0.0;  // pulse/ST^2, 0 < acc <= 16384 (L995; Table 4-6 says 16383, decision M6)
  void validate() const;
};

// GE / GUC-ECAT / iDEABOX GT_PrflV parameters in pulse/ms (GE L1202-1206).
struct GeJogParams {
  double vel = 0.0;  // pulse/ms, signed, -40958..40957
  double acc = 0.0;  // pulse/ms^2, 0 < acc <= 102400
  void validate() const;
  double vel_per_tick(double period_s) const;
  double acc_per_tick(double period_s) const;
};

}  // namespace servobench::motion
