// The feed (path-speed) profile of one segment: a trapezoid in the path speed, from the entry speed v0 to the
// exit speed v1 with the cruise speed capped at vmax and one acceleration a for every ramp (GT §5.4.3
// L1950-1965: "T-curve ... no S-curve for paths"; GE L1668; GUC/iDEABOX Figs 4-2/4-4).
//
// evenTime (GUC L775, iDEABOX L1189-1195): when the cruise would last less than even_time, the cruise speed is
// lowered so that a cruise of even_time remains (closed form in ideabox.md §3.4), never below max(v0, v1).
// Entry above the cap (an override lowered mid-segment) decelerates to the cap first. An exit speed that
// cannot be reached in the length (only when the caller asks the impossible) is replaced by the nearest
// reachable one: exit_speed() tells. Units: length in the coordinate unit, time in ms (any unit works).
#pragma once

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

class FeedProfile {
 public:
  FeedProfile() = default;
  // length > 0; v0, v1 >= 0; vmax > 0; acc > 0; even_time >= 0.
  FeedProfile(double length, double v0, double v1, double vmax, double acc, double even_time = 0.0);

  double length() const { return length_; }
  double duration() const { return duration_; }
  double entry_speed() const { return v0_; }
  double exit_speed() const { return v1_; }
  double peak_speed() const { return vp_; }
  double acc() const { return acc_; }
  double cruise_time() const { return tc_; }
  // (s, v, a) at time t from the segment start; after the end: (length, exit speed, 0).
  MotionState at(double t) const;

 private:
  Profile p_;
  double length_ = 0.0, v0_ = 0.0, v1_ = 0.0, vp_ = 0.0, acc_ = 0.0, tc_ = 0.0, duration_ = 0.0;
};

// Rest-to-rest duration of a segment of `length` at cruise cap vmax, acceleration acc, evenTime even_time.
double feed_time(double length, double vmax, double acc, double even_time = 0.0);

}  // namespace servobench::motion
