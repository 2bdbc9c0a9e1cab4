// The signals an Axis records every servo tick (the simulator's scope).
//
// One list, SERVOBENCH_TRACE_SIGNALS, names every signal with its unit and meaning; the C++ recorder, the
// pybind11 binding and the Python result object are all generated from it. Sampling instant: tick k is the
// instant t = k*Ts at which the controller reads the encoder; mechanical signals are their values at that
// instant; `volts` is what the controller computed at tick k, which the drive receives from tick k+1 on
// (so with an ideal current loop current_a[k+1] = amps_per_volt * volts[k]).
#pragma once

#include <cstddef>

// X(name, unit, description)
#define SERVOBENCH_TRACE_SIGNALS(X)                                                              \
  X(time_s, "s", "time of the tick, k*Ts")                                                       \
  X(cmd_pos, "pulse", "command (target) position")                                               \
  X(cmd_vel, "pulse/tick", "command velocity the law used (GT: profile's; APS: difference)")     \
  X(cmd_acc, "pulse/tick^2", "command acceleration the law used")                                \
  X(fb_pos, "pulse", "feedback position read from the encoder")                                  \
  X(error, "pulse", "following error cmd_pos - fb_pos")                                          \
  X(p, "count", "proportional term")                                                             \
  X(i, "count", "integral term")                                                                 \
  X(d, "count", "derivative term")                                                               \
  X(vff, "count", "velocity feed-forward term")                                                  \
  X(aff, "count", "acceleration feed-forward term")                                              \
  X(bias, "count", "bias term (GT MtrBias)")                                                     \
  X(u, "count", "law output after its clamp (PID_CALC)")                                         \
  X(biquad0, "count", "output of filter slot 0 (BIQUAD_0_CALC)")                                 \
  X(biquad1, "count", "output of filter slot 1 (BIQUAD_1_CALC)")                                 \
  X(volts, "V", "DAC output computed this tick, applied from the next")                          \
  X(current_a, "A", "motor current (ideal loop: the current held from this tick)")                                                             \
  X(torque_nm, "N*m", "motor torque")                                                            \
  X(angle_rad, "rad", "motor angle")                                                             \
  X(speed_rad_s, "rad/s", "motor speed")                                                         \
  X(load_angle_rad, "rad", "load angle (= motor angle on a rigid plant)")                        \
  X(load_speed_rad_s, "rad/s", "load speed")                                                     \
  X(alarm, "bool", "drive alarm (1 once tripped)")                                               \
  X(index, "bool", "1 if the encoder index mark passed since the previous tick")                 \
  X(home_sw, "bool", "home switch state (load angle in the home window)")                        \
  X(pos_limit_sw, "bool", "positive limit switch state")                                         \
  X(neg_limit_sw, "bool", "negative limit switch state")

namespace servobench::machine {

// Destination buffers, one per signal; a null pointer means "do not record". Each must hold n doubles.
struct Trace {
#define SERVOBENCH_TRACE_FIELD(name, unit, doc) double* name = nullptr;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_TRACE_FIELD)
#undef SERVOBENCH_TRACE_FIELD
};

}  // namespace servobench::machine
