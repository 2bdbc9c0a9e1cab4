// Property tests over random moves: every plan ends exactly at its target, never exceeds its limits by more
// than 1e-9 (relative), and rest-to-rest T/S moves take the analytic minimal time (computed here a second,
// independent way: by bisection on the peak velocity instead of the planner's closed-form roots).
// Each test prints its count and worst figures (reported in docs/motion.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "motion_check.hpp"
#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/s_curve.hpp"
#include "servobench/motion/t_curve.hpp"
#include "servobench/motion/velocity_change.hpp"

namespace sm = servobench::motion;
using sm::MotionState;
using sm::testing::integrated_end_state;
using sm::testing::profile_peaks;

namespace {

constexpr int kMoves = 100000;
constexpr double kRel = 1e-9;
// The integrated end of a plan (before it is snapped to the target) lies within kGap pulse of the target:
// double rounding at the card's positions (|p| <= 2^31), 10^5 times finer than the reported whole pulse.
constexpr double kGap = 1e-5;

struct Rng {
  std::mt19937_64 g{20240611};
  double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  double log_uni(double lo, double hi) { return std::exp(uni(std::log(lo), std::log(hi))); }
  double sign() { return uni(0, 1) < 0.5 ? -1.0 : 1.0; }
  // A whole-pulse distance with a log-uniform magnitude in [1, hi].
  double distance(double hi) { return sign() * std::round(log_uni(1.0, hi)); }
};

struct Worst {
  double vel = 0, acc = 0, jerk = 0, end = 0, time = 0;
  void limits(const sm::testing::Peaks& k, double V, double A, double J) {
    vel = std::max(vel, k.vel / V - 1);
    acc = std::max(acc, k.acc / A - 1);
    if (J > 0) jerk = std::max(jerk, k.jerk / J - 1);
  }
  void print(const char* what, int n) const {
    std::printf("[%s] %d moves: worst relative excess vel %.3g acc %.3g jerk %.3g; worst end gap %.3g "
                "pulse; worst duration vs analytic (relative) %.3g\n",
                what, n, vel, acc, jerk, end, time);
  }
};

// Independent minimal rest-to-rest time of the jerk-limited profile: bisection on the peak velocity.
double s_min_time_by_bisection(double D, double V, double A, double J) {
  auto t_acc = [&](double v) { return v >= A * A / J ? v / A + A / J : 2.0 * std::sqrt(v / J); };
  auto dist = [&](double v) { return v * t_acc(v); };  // both ramps, no cruise
  double vp = V;
  if (dist(V) > D) {
    double lo = 0, hi = V;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (dist(mid) <= D ? lo : hi) = mid;
    }
    vp = 0.5 * (lo + hi);
  }
  return 2.0 * t_acc(vp) + (D - dist(vp)) / vp;
}

double t_min_time_independent(double D, double V, double A) {
  const double vp = std::min(V, std::sqrt(A * D));
  return 2.0 * vp / A + (D - vp * vp / A) / vp;
}

// Pontryagin structure of a time-optimal profile: in every segment the jerk is +-J, or it is 0 with |a| = A,
// or 0 with a = 0 and |v| = V (cruise).
bool bang_bang(const sm::Profile& p, double V, double A, double J) {
  for (int i = 0; i < p.size(); ++i) {
    const auto& s = p.segment(i);
    if (std::fabs(std::fabs(s.j) - J) <= 1e-9 * J) continue;
    if (s.j != 0) return false;
    if (std::fabs(std::fabs(s.a) - A) <= 1e-9 * A) continue;
    if (std::fabs(s.a) <= 1e-9 * A && std::fabs(std::fabs(s.v) - V) <= 1e-9 * V) continue;
    return false;
  }
  return true;
}

}  // namespace

TEST(MotionProperties, SCurveRestToRestIsExactWithinLimitsAndMinimal) {
  Rng r;
  Worst w;
  for (int i = 0; i < kMoves; ++i) {
    const double V = r.log_uni(1e-2, 1e4), A = r.log_uni(1e-6, 1e2), J = r.log_uni(1e-9, 1e2);
    const double start = std::round(r.uni(-5e8, 5e8));
    const double D = r.distance(5e8);
    const auto p = sm::plan_s_curve_rest_to_rest(start, start + D, {V, A, J});
    w.limits(profile_peaks(p), V, A, J);
    const auto e = integrated_end_state(p);
    w.end = std::max(w.end, std::fabs(e.pos - (start + D)));
    ASSERT_LE(std::fabs(e.vel), 1e-9 * V) << i;
    ASSERT_LE(std::fabs(e.acc), 1e-9 * A) << i;
    ASSERT_EQ(p.end().pos, start + D);
    const double tmin = s_min_time_by_bisection(std::fabs(D), V, A, J);
    w.time = std::max(w.time, std::fabs(p.duration() / tmin - 1));
    ASSERT_TRUE(bang_bang(p, V, A, J)) << i;
  }
  w.print("S-curve rest-to-rest", kMoves);
  EXPECT_LE(w.vel, kRel);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.jerk, kRel);
  EXPECT_LE(w.end, kGap);
  EXPECT_LE(w.time, 1e-9);
}

TEST(MotionProperties, TCurveRestToRestIsExactWithinLimitsAndMinimal) {
  Rng r;
  Worst w;
  for (int i = 0; i < kMoves; ++i) {
    const double V = r.log_uni(1e-2, 1.6e4), A = r.log_uni(1e-6, 1.6e4);
    const double start = std::round(r.uni(-5e8, 5e8));
    const double D = r.distance(5e8);
    const auto p = sm::plan_t_curve({start, 0, 0, 0}, start + D, {V, A});
    w.limits(profile_peaks(p), V, A, 0);
    const auto e = integrated_end_state(p);
    w.end = std::max(w.end, std::fabs(e.pos - (start + D)));
    ASSERT_LE(std::fabs(e.vel), 1e-9 * V) << i;
    w.time = std::max(w.time, std::fabs(p.duration() / t_min_time_independent(std::fabs(D), V, A) - 1));
    ASSERT_TRUE(bang_bang(p, V, A, 1.0)) << i;  // (no jerk segments: every segment is +-A or cruise)
  }
  w.print("T-curve rest-to-rest", kMoves);
  EXPECT_LE(w.vel, kRel);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.end, kGap);
  EXPECT_LE(w.time, 1e-9);
}

// On-the-fly target change of an S-curve: from a random moving state (|a| <= A and a velocity that can be
// brought to rest without exceeding V) to a random new target, possibly behind the braking point.
TEST(MotionProperties, SCurveRetargetFromMotion) {
  Rng r;
  Worst w;
  int reversals = 0, n = 0;
  for (int i = 0; n < kMoves; ++i) {
    const double V = r.log_uni(1e-2, 1e4), A = r.log_uni(1e-6, 1e2), J = r.log_uni(1e-9, 1e2);
    const double a0 = r.uni(-A, A);
    const double vlim = V - a0 * a0 / (2 * J);  // |v0 + a0|a0|/2J| <= V keeps V reachable
    if (vlim <= 0) continue;
    const double v0 = r.uni(-1, 1) * vlim;
    const double vs = v0 + a0 * std::fabs(a0) / (2 * J);
    if (std::fabs(vs) > V) continue;
    const double p0 = r.uni(-1e6, 1e6);
    const double target = std::round(p0 + r.distance(1e7));
    const MotionState from{p0, v0, a0, 0};
    // stay inside the card's position range: braking distance and reversal within 2^30
    if (std::fabs(sm::velocity_change_extent(v0, a0, 0, A, J).dist) > 1e8) continue;
    ++n;
    const auto p = sm::plan_s_curve(from, target, {V, A, J});
    ASSERT_TRUE(bang_bang(p, V, A, J)) << i;  // time-optimal structure (MO1); durations vs Ruckig: Python test
    const auto s0 = p.at(0);
    ASSERT_EQ(s0.pos, p0);
    ASSERT_EQ(s0.vel, v0);
    ASSERT_NEAR(s0.acc, a0, 1e-15 * A);
    w.limits(profile_peaks(p), V, A, J);
    const auto e = integrated_end_state(p);
    w.end = std::max(w.end, std::fabs(e.pos - target));
    ASSERT_LE(std::fabs(e.vel), 1e-8 * V) << i;
    ASSERT_LE(std::fabs(e.acc), 1e-8 * A) << i;
    const double brake = sm::velocity_change_extent(v0, a0, 0, A, J).dist;
    if ((target - p0 - brake) * v0 < 0) ++reversals;
  }
  w.print("S-curve retarget in motion", n);
  EXPECT_EQ(n, kMoves);
  std::printf("  of which %d went behind the braking point and reversed\n", reversals);
  EXPECT_GT(reversals, 1000);
  EXPECT_LE(w.vel, kRel);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.jerk, kRel);
  EXPECT_LE(w.end, kGap);
}

// Replanning from a state the limits do not reach (decision MO2): |a| up to 3A, |v| up to 3V. A brake pre-phase at
// full jerk brings the state inside (|a| <= A, |v + a|a|/2J| <= V); once also |v| <= V the limits hold to the end;
// the plan ends at rest on the target.
TEST(MotionProperties, SCurveReplanFromOutsideTheLimitsBrakesFirst) {
  Rng r;
  int n = 0, outside = 0;
  double worst_end = 0;
  for (int i = 0; n < 20000; ++i) {
    const double V = r.log_uni(1e-1, 1e2), A = r.log_uni(1e-3, 1), J = r.log_uni(1e-3, 1e-1);
    const double a0 = r.uni(-3, 3) * A, v0 = r.uni(-3, 3) * V;
    const double p0 = r.uni(-1e6, 1e6), target = std::round(p0 + r.distance(1e6));
    const auto p = sm::plan_s_curve({p0, v0, a0, 0}, target, {V, A, J});
    ++n;
    if (std::fabs(a0) > A || std::fabs(v0 + a0 * std::fabs(a0) / (2 * J)) > V) ++outside;
    ASSERT_TRUE(std::isfinite(p.duration())) << i;
    double t = 0, travel = std::fabs(p0) + std::fabs(target);
    bool inside = false;
    for (int k = 0; k < p.size(); ++k) {
      const auto& s = p.segment(k);
      ASSERT_LE(std::fabs(s.j), J * (1 + 1e-12)) << i;
      const auto e = s.at(s.duration);
      travel += std::fabs(s.v) * s.duration;
      const bool in = std::fabs(s.a) <= A * (1 + 1e-9) && std::fabs(s.v) <= V * (1 + 1e-9) &&
                      std::fabs(s.v + s.a * std::fabs(s.a) / (2 * J)) <= V * (1 + 1e-9) + 1e-12;
      inside = inside || in;
      if (inside) {  // once inside, never out again
        ASSERT_LE(std::fabs(e.acc), A * (1 + 1e-9)) << i << " seg " << k;
        ASSERT_LE(std::fabs(e.vel), V * (1 + 1e-9)) << i << " seg " << k;
      }
      t += s.duration;
    }
    const auto e = integrated_end_state(p);
    ASSERT_LE(std::fabs(e.vel), 1e-8 * V) << i;
    ASSERT_LE(std::fabs(e.acc), 1e-8 * A) << i;
    worst_end = std::max(worst_end, std::fabs(e.pos - target) / travel);
  }
  std::printf("[S-curve replan from outside the limits] %d moves, %d outside: worst end gap %.3g of the travel\n", n,
              outside, worst_end);
  EXPECT_GT(outside, 10000);
  EXPECT_LE(worst_end, 1e-9);  // measured 2e-10: double rounding over long brake + cruise chains
}

// On-the-fly target and velocity change of a T-curve: from a random velocity up to twice the new limit.
TEST(MotionProperties, TCurveRetargetAndNewVelocityFromMotion) {
  Rng r;
  Worst w;
  int n = 0;
  for (int i = 0; n < kMoves; ++i) {
    const double V = r.log_uni(1e-2, 1e4), A = r.log_uni(1e-6, 1e2);
    const double v0 = r.uni(-2, 2) * V;
    if (v0 * v0 / (2 * A) > 1e8) continue;  // braking distance inside the card's position range
    ++n;
    const double p0 = r.uni(-1e6, 1e6);
    const double target = std::round(p0 + r.distance(1e7));
    const auto p = sm::plan_t_curve({p0, v0, 0, 0}, target, {V, A});
    const auto k = profile_peaks(p);
    w.acc = std::max(w.acc, k.acc / A - 1);
    // after the first ramp the velocity never exceeds V
    double vmax_after = 0;
    for (int s = 1; s < p.size(); ++s) vmax_after = std::max(vmax_after, std::fabs(p.segment(s).v));
    w.vel = std::max(w.vel, vmax_after / std::max(V, std::fabs(v0)) - 1);
    if (std::fabs(v0) <= V) w.vel = std::max(w.vel, k.vel / V - 1);
    const auto e = integrated_end_state(p);
    w.end = std::max(w.end, std::fabs(e.pos - target));
    ASSERT_LE(std::fabs(e.vel), 1e-9 * std::max(V, std::fabs(v0))) << i;
  }
  w.print("T-curve retarget in motion", n);
  EXPECT_EQ(n, kMoves);
  EXPECT_LE(w.vel, kRel);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.end, kGap);
}

TEST(MotionProperties, JogReachesTheVelocityWithinLimits) {
  Rng r;
  Worst w;
  for (int i = 0; i < kMoves; ++i) {
    const double A = r.log_uni(1e-6, 1e2), J = r.uni(0, 1) < 0.5 ? INFINITY : r.log_uni(1e-9, 1e2);
    const double v1 = r.uni(-1e3, 1e3);
    double a0 = std::isinf(J) ? 0.0 : r.uni(-A, A);
    if (a0 * a0 / (2 * J) > 1e3) a0 = std::copysign(std::sqrt(2e3 * J), a0);  // states of this velocity range
    const MotionState from{r.uni(-1e6, 1e6), r.uni(-1e3, 1e3), a0, 0};
    const auto p = sm::plan_jog(from, v1, A, J);
    const auto k = profile_peaks(p);
    w.acc = std::max(w.acc, k.acc / A - 1);
    if (!std::isinf(J)) w.jerk = std::max(w.jerk, k.jerk / J - 1);
    ASSERT_TRUE(p.open_ended() || v1 == 0);
    const auto& last = p.segment(p.size() - 1);
    w.end = std::max(w.end, std::fabs(last.v - v1) / std::max(1.0, std::fabs(v1)));
  }
  w.print("jog (end = velocity error)", kMoves);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.jerk, kRel);
  EXPECT_LE(w.end, 1e-9);  // relative velocity error
}

TEST(MotionProperties, AdlinkPtpKeepsAccDecAndShortMoveRule) {
  Rng r;
  Worst w;
  int n = 0;
  for (int i = 0; n < kMoves; ++i) {
    const double vm = r.log_uni(1e-2, 1e3);
    const sm::AdlinkLimits lim{r.uni(0, 0.3) * vm, vm, r.uni(0, 0.3) * vm, r.log_uni(1e-5, 1e1), r.log_uni(1e-5, 1e1),
                               r.uni(0, 1) < 0.2 ? 0.0 : r.uni(0, 1)};
    const double D = r.distance(1e8);
    const double k = 1 + lim.sf;
    const double need = k * std::fabs(lim.vs * lim.vs - lim.ve * lim.ve) / (2 * std::min(lim.acc, lim.dec));
    if (std::fabs(D) <= need) continue;
    ++n;
    const auto p = sm::plan_adlink_ptp(0, D, lim);
    const auto pk = profile_peaks(p);
    w.acc = std::max(w.acc, pk.acc / std::max(lim.acc, lim.dec) - 1);
    const double vm2 = (2 * lim.acc * lim.dec * std::fabs(D) / k + lim.dec * lim.vs * lim.vs + lim.acc * lim.ve * lim.ve) /
                       (lim.acc + lim.dec);
    const double vpk = std::min(vm, std::sqrt(vm2));
    w.vel = std::max(w.vel, std::fabs(pk.vel / vpk - 1));
    const auto e = integrated_end_state(p);
    w.end = std::max(w.end, std::fabs(e.pos - D));
    ASSERT_NEAR(std::fabs(e.vel), lim.ve, 1e-9 * vm) << i;
    ASSERT_EQ(std::fabs(p.start().vel), lim.vs);
  }
  w.print("ADLINK PTP (vel = |peak/VM' - 1|)", n);
  EXPECT_EQ(n, kMoves);
  EXPECT_LE(w.acc, kRel);
  EXPECT_LE(w.vel, kRel);
  EXPECT_LE(w.end, kGap);
}

// Sampled at the ticks through the ProfileGenerator: the finite differences of the fractional position respect
// the limits (a difference is an average of the continuous quantity), the move lasts ceil(T) ticks, and the
// reported whole-pulse position ends exactly at the target.
TEST(MotionProperties, SampledTicksRespectLimitsAndEndOnThePulse) {
  Rng r;
  double worst_v = 0, worst_a = 0, worst_j = 0;
  const int n = 3000;
  for (int i = 0; i < n; ++i) {
    const bool s_mode = i % 2 == 0;
    const double V = r.log_uni(0.1, 50), A = r.log_uni(1e-3, 1), J = r.log_uni(1e-4, 1);
    const double target = r.distance(2e4);
    sm::ProfileGenerator g;
    if (s_mode) {
      g.move_s_curve(target, {V, A, J});
    } else {
      g.move_t_curve(target, {V, A});
    }
    const double T = g.profile().duration();
    std::vector<double> pos{0.0};
    while (g.moving()) pos.push_back(g.step().pos);
    ASSERT_EQ(static_cast<double>(pos.size() - 1), std::ceil(T)) << i;
    ASSERT_EQ(g.reported_pos(), static_cast<long long>(target));
    for (int k = 0; k < 3; ++k) pos.push_back(target);
    const double tol = 16 * 2.2e-16 * 2e4;  // rounding of the differences themselves
    for (std::size_t k = 1; k < pos.size(); ++k) {
      worst_v = std::max(worst_v, (std::fabs(pos[k] - pos[k - 1]) - tol) / V - 1);
      if (k >= 2) worst_a = std::max(worst_a, (std::fabs(pos[k] - 2 * pos[k - 1] + pos[k - 2]) - tol) / A - 1);
      if (k >= 3 && s_mode)
        worst_j = std::max(worst_j, (std::fabs(pos[k] - 3 * pos[k - 1] + 3 * pos[k - 2] - pos[k - 3]) - tol) / J - 1);
    }
  }
  std::printf("[sampled ticks] %d moves: worst relative excess of the finite differences: vel %.3g acc %.3g jerk %.3g\n",
              n, worst_v, worst_a, worst_j);
  EXPECT_LE(worst_v, kRel);
  EXPECT_LE(worst_a, kRel);
  EXPECT_LE(worst_j, kRel);
}
