// A simple trapezoidal point-to-point move sampled at the servo ticks, for tests and the demo.
//
// The continuous-time profile (accelerate at acc to vel, cruise, decelerate at acc; a triangle when the
// distance is too short to reach vel) is sampled at every tick k = 0..; the last sample is exactly the
// target. The manuals' T-curve and S-curve generators, with their own integer semantics, are separate.
// Units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include <cstddef>
#include <vector>

namespace servobench::motion {

struct SampledProfile {
  std::vector<double> pos;  // pulse
  std::vector<double> vel;  // pulse/tick
  std::vector<double> acc;  // pulse/tick^2
};

// start_pulse: initial position; distance_pulse: signed move length; vel_max > 0 (pulse/tick);
// acc > 0 (pulse/tick^2); dwell_before/after: ticks held at rest before and after the move.
SampledProfile trapezoid_move(double start_pulse, double distance_pulse, double vel_max, double acc,
                              std::size_t dwell_before, std::size_t dwell_after);

}  // namespace servobench::motion
