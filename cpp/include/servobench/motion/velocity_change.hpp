// Time-optimal change of velocity: from (v0, a0) to (v1, acceleration 0) with |a| <= amax and |jerk| <= jmax.
//
// With a finite jerk limit this is the three-phase "S" ramp (jerk +-jmax, a hold at +-amax if reached, jerk
// -+jmax), starting from a possibly non-zero acceleration a0 (|a0| <= amax assumed). With jmax = +inf it is
// the T ramp: the acceleration steps to +-amax and back to 0. Units: pulse/tick, pulse/tick^2, pulse/tick^3.
// The building block of the S-curve, jog and stop generators.
#pragma once

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// Distance (pulse) and duration (ticks) of the velocity change.
struct ChangeExtent {
  double dist = 0.0;
  double time = 0.0;
};

// Phase durations (ticks) and jerks of the change; the T ramp uses phase 2 only (with `acc` its acceleration).
struct ChangePhases {
  double t1 = 0.0, t2 = 0.0, t3 = 0.0;  // ticks
  double j1 = 0.0, j3 = 0.0;            // pulse/tick^3
  double a2 = 0.0;                      // acceleration of phase 2, pulse/tick^2
};

ChangePhases velocity_change_phases(double v0, double a0, double v1, double amax, double jmax);

// Distance and time of the change, without building a profile.
ChangeExtent velocity_change_extent(double v0, double a0, double v1, double amax, double jmax);

// Appends the change from the profile's current end state to v1 (a ends at 0).
void push_velocity_change(Profile& prof, double v1, double amax, double jmax);

}  // namespace servobench::motion
