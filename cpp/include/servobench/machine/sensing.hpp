// What the card's inputs saw during one servo tick: switch levels and edges, the index mark, and the actual
// (encoder) position at each edge, interpolated inside the tick.
//
// Between two tick instants the mechanism's angle is interpolated by the cubic Hermite polynomial through
// the angles and speeds at both ends (exact for motion at constant acceleration, error O(Ts^4) otherwise).
// An edge's instant is where the switched angle (the load's, for the switches; the encoder's, for the index)
// crosses the switch edge or the index angle; the capture is the encoder's (noise-free) count at that instant
// (decision M40). This is what the cards' hardware latches do ("+-1 pulse, independent of speed", GT L2015-
// 2017). The switches are taken as active-on (polarity is the card's business, plant/switches.hpp).
#pragma once

#include "servobench/machine/axis.hpp"
#include "servobench/motion/home_sequence.hpp"

namespace servobench::machine {

// The mechanism at one tick instant (rad, rad/s).
struct MechSample {
  double enc_angle = 0.0, enc_speed = 0.0;
  double load_angle = 0.0, load_speed = 0.0;
};

MechSample sample_mechanism(const Axis& axis);

// Angle at fraction tau (0..1) of a tick of h seconds from (x0, v0) to (x1, v1): cubic Hermite.
double hermite_angle(double x0, double v0, double x1, double v1, double h, double tau);
// Fraction tau in [0, 1] at which the Hermite crosses `level` (x0 and x1 on either side of it; bisection).
double crossing_fraction(double x0, double v0, double x1, double v1, double h, double level);

// The tick's events in raw encoder pulses (motion::HomeInputs in the axis's own counts).
struct TickSense {
  motion::HomeInputs in;
  double index_tau = 0.0, home_tau = 0.0;  // fractions of the tick at the index / home edges
};

class Sensing {
 public:
  // Senses with the axis's own switches and encoder (kept by reference: the axis must outlive this).
  explicit Sensing(const Axis& axis);
  // Levels only (no edges), at one instant.
  motion::HomeInputs levels(const MechSample& now) const;
  // Events between two successive tick instants `h` seconds apart.
  TickSense between(const MechSample& before, const MechSample& after, double h) const;
  // Encoder count (noise-free) at fraction tau of the tick.
  double pulse_at(const MechSample& before, const MechSample& after, double h, double tau) const;

 private:
  void switch_event(motion::SignalEvent& e, bool was, bool is, double bound_lo, double bound_hi,
                    const MechSample& b, const MechSample& a, double h, double* tau_out) const;
  plant::SwitchParams sw_;
  const plant::Encoder& enc_;  // the Axis's own encoder (one encoder per axis)
};

}  // namespace servobench::machine
