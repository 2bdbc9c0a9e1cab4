// Helpers for the motion tests: limit checks over a continuous profile.
#pragma once

#include <algorithm>
#include <cmath>

#include "servobench/motion/profile.hpp"

namespace servobench::motion::testing {

// Largest |v|, |a|, |j| over the whole profile (segment ends and interior velocity extrema).
struct Peaks {
  double vel = 0.0, acc = 0.0, jerk = 0.0;
};

inline Peaks profile_peaks(const Profile& p) {
  Peaks k;
  auto see = [&](const MotionState& s) {
    k.vel = std::max(k.vel, std::fabs(s.vel));
    k.acc = std::max(k.acc, std::fabs(s.acc));
  };
  for (int i = 0; i < p.size(); ++i) {
    const Segment& s = p.segment(i);
    k.jerk = std::max(k.jerk, std::fabs(s.j));
    see(s.at(0.0));
    if (std::isinf(s.duration)) continue;
    see(s.at(s.duration));
    if (s.j != 0.0) {
      const double t = -s.a / s.j;
      if (t > 0.0 && t < s.duration) see(s.at(t));
    }
  }
  return k;
}

// Integrated end position of the last finite segment (before finish_at_rest snapped it to the target).
inline double integrated_end(const Profile& p) {
  if (p.size() == 0) return p.start().pos;
  const Segment& s = p.segment(p.size() - 1);
  return s.at(s.duration).pos;
}

// Integrated end state of the last segment.
inline MotionState integrated_end_state(const Profile& p) {
  if (p.size() == 0) return p.start();
  const Segment& s = p.segment(p.size() - 1);
  return s.at(s.duration);
}

}  // namespace servobench::motion::testing
