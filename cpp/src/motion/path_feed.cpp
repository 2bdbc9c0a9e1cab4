#include "servobench/motion/path_feed.hpp"

#include <algorithm>
#include <cmath>

namespace servobench::motion {

FeedProfile::FeedProfile(double length, double v0, double v1, double vmax, double acc, double even_time)
    : length_(length), v0_(v0), v1_(v1), acc_(acc) {
  const double a = acc, L = length;
  auto dist = [&](double vp) { return (std::fabs(vp * vp - v0 * v0) + std::fabs(vp * vp - v1 * v1)) / (2.0 * a); };
  double vp;
  if (std::fabs(v0 * v0 - v1 * v1) > 2.0 * a * L) {
    // The exit speed is out of reach: one ramp over the whole length, ending as near v1 as possible.
    v1_ = v1 < v0 ? std::sqrt(v0 * v0 - 2.0 * a * L) : std::sqrt(v0 * v0 + 2.0 * a * L);
    vp = std::max(v0, v1_);
    vp_ = vp;
    tc_ = 0.0;
  } else {
    if (dist(vmax) <= L) {
      vp = vmax;
    } else if (vmax >= std::max(v0, v1)) {
      vp = std::sqrt((2.0 * a * L + v0 * v0 + v1 * v1) / 2.0);
    } else {
      vp = std::sqrt(std::max((v0 * v0 + v1 * v1 - 2.0 * a * L) / 2.0, 0.0));
    }
    double tc = vp > 0.0 ? std::max(L - dist(vp), 0.0) / vp : 0.0;
    if (even_time > 0.0 && tc < even_time && vp >= std::max(v0, v1)) {
      const double k = L + (v0 * v0 + v1 * v1) / (2.0 * a);
      const double ve = 0.5 * a * (-even_time + std::sqrt(even_time * even_time + 4.0 * k / a));
      const double floor = std::max(v0, v1);
      vp = std::max(std::min(ve, vp), floor);
      tc = vp > 0.0 ? std::max(L - dist(vp), 0.0) / vp : 0.0;
    }
    vp_ = vp;
    tc_ = tc;
  }
  const double t1 = std::fabs(vp_ - v0_) / a, t3 = std::fabs(vp_ - v1_) / a;
  p_ = Profile(MotionState{0.0, v0_, 0.0, 0.0});
  p_.push_with_acc(t1, vp_ >= v0_ ? a : -a, 0.0).settle_acc();
  p_.push_with_acc(tc_, 0.0, 0.0);
  p_.push_with_acc(t3, v1_ >= vp_ ? a : -a, 0.0).settle_acc();
  duration_ = t1 + tc_ + t3;
}

MotionState FeedProfile::at(double t) const {
  if (t >= duration_) return {length_, v1_, 0.0, 0.0};
  MotionState s = p_.at(std::max(t, 0.0));
  s.pos = std::min(s.pos, length_);
  return s;
}

double feed_time(double length, double vmax, double acc, double even_time) {
  return FeedProfile(length, 0.0, 0.0, vmax, acc, even_time).duration();
}

}  // namespace servobench::motion
