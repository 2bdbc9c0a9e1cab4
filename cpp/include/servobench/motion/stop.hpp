// Stops: smooth (decelerate to zero at the commanded limits) and abrupt (velocity to zero at once).
//
// GT_SmthStp decelerates at the commanded acceleration, jerk-limited in S-curve mode (GT L1142-1148,
// GE L1310-1312); ADLINK APS_stop_move decelerates at PRA_SD_DEC with the move's S-factor (ADLINK L2570).
// GT_AbptStp / APS_emg_stop set the profile velocity to zero at once, the position holds (GT L1128-1130,
// GE L1317). Internal units: pulse, pulse/tick, pulse/tick^2, pulse/tick^3.
#pragma once

#include <limits>

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// Decelerate from `from` to rest with |a| <= acc and |jerk| <= jerk (+inf: linear ramp).
Profile plan_smooth_stop(const MotionState& from, double acc,
                         double jerk = std::numeric_limits<double>::infinity());

// Velocity and acceleration zero at once; the (fractional) position holds.
Profile plan_abrupt_stop(const MotionState& from);

}  // namespace servobench::motion
