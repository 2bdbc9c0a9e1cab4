// A continuous-time 1-D motion profile: a short chain of constant-jerk segments.
//
// Every generator of this folder (T-curve, S-curve, jog, stops) plans one of these and a ProfileGenerator
// samples it once per tick. Units are the generator's internal ones: position in pulse, time in ticks
// (velocity pulse/tick, acceleration pulse/tick^2, jerk pulse/tick^3). Vendor units (pulse/ST, pulse/ms,
// pulse/s) are converted before planning (see units.hpp). Positions are kept fractional here; whole pulses
// are what the card reports (ProfileGenerator::reported_pos).
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace servobench::motion {

// Kinematic state at one instant: pulse, pulse/tick, pulse/tick^2, pulse/tick^3.
struct MotionState {
  double pos = 0.0;
  double vel = 0.0;
  double acc = 0.0;
  double jerk = 0.0;
};

// One constant-jerk piece starting in state (p, v, a) and lasting `duration` ticks (may be +inf: a cruise
// that lasts until the next command).
struct Segment {
  double duration = 0.0;
  double p = 0.0, v = 0.0, a = 0.0, j = 0.0;

  MotionState at(double t) const {
    const double t2 = t * t;
    return {p + v * t + 0.5 * a * t2 + j * t2 * t * (1.0 / 6.0), v + a * t + 0.5 * j * t2, a + j * t, j};
  }
};

// Up to kMaxSegments segments followed by rest at `end` (or the last segment continuing forever if its
// duration is infinite). Planning never allocates: the plan is a value type.
class Profile {
 public:
  static constexpr int kMaxSegments = 12;

  Profile() = default;
  // A profile that stays at `state` (velocity and acceleration kept: a profile with no segments holds the
  // position only if vel == acc == 0; callers use rest() for that).
  static Profile rest(double pos) {
    Profile p;
    p.start_ = {pos, 0.0, 0.0, 0.0};
    p.end_ = p.start_;
    return p;
  }

  // Starts a new profile at `state` (segments are appended with push()).
  explicit Profile(const MotionState& start) : start_(start), end_(start) { end_.jerk = 0.0; }

  // Appends a segment of `duration` ticks with jerk j from the current end state. Zero-length segments are
  // dropped. Returns *this.
  Profile& push(double duration, double j) {
    if (!(duration > 0.0)) return *this;
    Segment s{duration, end_.pos, end_.vel, end_.acc, j};
    seg_[static_cast<std::size_t>(n_++)] = s;
    if (std::isinf(duration)) {
      open_ended_ = true;
    } else {
      end_ = s.at(duration);
      end_.jerk = 0.0;
      total_ += duration;
    }
    return *this;
  }
  // Appends a segment that starts with acceleration `a` (a step in acceleration, as in a T-curve).
  Profile& push_with_acc(double duration, double a, double j) {
    end_.acc = a;
    return push(duration, j);
  }
  // Sets the acceleration at the end to 0 (after a T ramp, whose acceleration steps back to 0).
  Profile& settle_acc() {
    end_.acc = 0.0;
    return *this;
  }
  // Sets the end state exactly (removes rounding of the integrated end, e.g. the target position) and
  // forces rest there.
  Profile& finish_at_rest(double pos) {
    end_ = {pos, 0.0, 0.0, 0.0};
    return *this;
  }

  int size() const { return n_; }
  const Segment& segment(int i) const { return seg_[static_cast<std::size_t>(i)]; }
  const MotionState& start() const { return start_; }
  // The state after the last finite segment (the target for point-to-point moves).
  const MotionState& end() const { return end_; }
  // Total duration in ticks of the finite segments; infinite if the profile ends in an open cruise.
  double duration() const { return open_ended_ ? std::numeric_limits<double>::infinity() : total_; }
  bool open_ended() const { return open_ended_; }

  // State at time t ticks after the profile start (t >= 0). After the end: the end state (at rest).
  MotionState at(double t) const {
    double t0 = 0.0;
    for (int i = 0; i < n_; ++i) {
      const Segment& s = seg_[static_cast<std::size_t>(i)];
      if (t < t0 + s.duration) return s.at(t - t0);
      t0 += s.duration;
    }
    return end_;
  }

 private:
  std::array<Segment, kMaxSegments> seg_{};
  int n_ = 0;
  MotionState start_{};
  MotionState end_{};
  double total_ = 0.0;
  bool open_ended_ = false;
};

}  // namespace servobench::motion
