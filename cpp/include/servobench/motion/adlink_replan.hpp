// ADLINK on-the-fly point-to-point change (ADLINK L2757-2767; velocity move -> PTP, L2564-2566).
//
// The manual allows, during a PTP move, a new target with the same speeds, a new maximum speed with the same
// target, or a whole new PTP command (Figure 4-33, lost). We replan from a moving state whose acceleration is
// zero (a cruise, or the instant an S-factor ramp ends; the generator defers the change to that instant,
// decision M44), with the same rules as a move from rest (adlink_profile.hpp): ramps at ACC when the speed
// grows, at DEC when it falls, S-factor shaped, peak VM' = min(VM, the reachable peak), end at VE.
// If the new target cannot be reached without passing it (it lies behind the stopping point, or behind the
// axis), the axis stops at DEC and then runs a PTP move from rest to the target.
// Internal units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// From `from` (from.acc must be 0: throws std::invalid_argument otherwise) to rest at `target` (pulse).
Profile plan_adlink_ptp_from(const MotionState& from, double target, const AdlinkLimits& lim);

// Distance (pulse, >= 0) an S-factor ramp from speed v0 to v1 (both >= 0) travels at peak rate `rate`.
double adlink_ramp_distance(double v0, double v1, double rate, double sf);

}  // namespace servobench::motion
