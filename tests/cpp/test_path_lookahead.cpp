// Look-ahead properties (the algorithm is ours, decisions C10-C16; the manuals state only the properties):
// path acceleration <= accMax (GUC L969-971, iDEABOX L1933-1935, L2085-2087), larger T or accMax gives faster
// corners (GUC L967, iDEABOX L2079-2083, GE L1779-1783), the path stops at its end and at forced stops (G0,
// BufDelay: GUC L981-983), windows of 200 segments and more (GE L1729-1812: n >= 200).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "servobench/motion/lookahead.hpp"
#include "servobench/motion/path_generator.hpp"

namespace sm = servobench::motion;
using G = sm::PathSegmentGeometry;

namespace {
// A random path of lines and tangent-discontinuous arcs in XY around the origin.
void random_path(sm::PathGenerator& g, std::mt19937& rng, int n, double vel, double acc) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> len(20.0, 4000.0);
  for (int i = 0; i < n; ++i) {
    const auto t = g.tail();
    if (u(rng) > 0.3) {
      const double a = 3.14159 * u(rng), L = len(rng);
      g.line({t[0] + L * std::cos(a), t[1] + L * std::sin(a)}, vel * (1.5 + u(rng)) / 2, acc);
    } else {
      const double r = len(rng) / 2, a = 3.14159 * u(rng);
      g.push_segment(G::arc_center_angle(t, 2, sm::ArcPlane::XY, t[0] + r * std::cos(a), t[1] + r * std::sin(a),
                                         300 * u(rng) + (u(rng) > 0 ? 10 : -10)),
                     vel, acc);
    }
  }
}

struct Check {
  double max_acc_ratio = 0, max_centripetal_ratio = 0, end_speed = -1;
  long ticks = 0;
};

Check run_checked(sm::PathGenerator& g, double acc_max) {
  Check c;
  double prev = 0;
  while (!g.done() && c.ticks < 10000000) {
    const auto& s = g.step();
    c.max_acc_ratio = std::max(c.max_acc_ratio, std::fabs(s.speed - prev) / g.setup().cycle_ms / acc_max);
    c.max_acc_ratio = std::max(c.max_acc_ratio, std::fabs(s.acc) / acc_max);
    prev = s.speed;
    ++c.ticks;
  }
  c.end_speed = g.state().speed;
  return c;
}
}  // namespace

TEST(LookAheadProperties, AccelerationNeverAboveTheLimitOnRandomPaths) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 20; ++trial) {
    const double acc_max = 0.2 + trial * 0.1, T = 1 + trial % 10;
    sm::PathGenerator g(sm::CoordSystem::identity(2));
    g.init_lookahead({T, acc_max, 200});
    random_path(g, rng, 300, 60, acc_max * 2);  // the segments ask for more than accMax: it must win
    ASSERT_TRUE(g.flush());
    g.start();
    const double end_x = g.tail()[0], end_y = g.tail()[1];
    const Check c = run_checked(g, acc_max);
    EXPECT_LE(c.max_acc_ratio, 1 + 1e-9) << "trial " << trial;
    EXPECT_EQ(c.end_speed, 0.0);
    EXPECT_EQ(g.state().pos[0], end_x);
    EXPECT_EQ(g.state().pos[1], end_y);
    EXPECT_EQ(g.state().segments_done, 300);
  }
}

TEST(LookAheadProperties, CentripetalAccelerationOnArcsBounded) {
  // A circle of radius 1000 at feed 100 with accMax 1: the arc speed is capped at sqrt(accMax R) = 31.6.
  sm::PathGenerator g(sm::CoordSystem::identity(2));
  g.init_lookahead({5, 1, 200});
  g.line({1000, 0}, 100, 1);
  g.push_segment(G::arc_center_angle(g.tail(), 2, sm::ArcPlane::XY, 0, 0, 360), 100, 1);
  g.line({2000, 0}, 100, 1);
  g.flush();
  g.start();
  double worst = 0;
  while (!g.done()) {
    const auto& s = g.step();
    if (s.segments_done == 1) worst = std::max(worst, s.speed * s.speed / 1000.0);
  }
  EXPECT_LE(worst, 1 + 1e-12);
  EXPECT_GT(worst, 0.999);
}

TEST(LookAheadProperties, LargerCornerTimeOrAccelerationGivesFasterCorners) {
  // A zig-zag with 30 deg turns: the end speeds grow with T and with accMax, elementwise (GUC L967).
  std::vector<sm::LookAheadSegment> segs;
  for (int i = 0; i < 400; ++i) {
    const double a = (i % 2 ? 15.0 : -15.0) * 3.14159265358979 / 180;
    sm::LookAheadSegment s;
    s.length = 500;
    s.vmax = 200;
    s.acc = 1;
    s.u_in = s.u_out = {std::cos(a), std::sin(a), 0, 0};
    s.curvature_radius = INFINITY;
    segs.push_back(s);
  }
  std::vector<double> prev(segs.size(), 0.0);
  for (double T : {1.0, 2.0, 5.0, 10.0, 40.0}) {
    const auto v = sm::plan_lookahead(segs, {T, 1, 200});
    for (std::size_t i = 0; i < v.size(); ++i) ASSERT_GE(v[i], prev[i]);
    EXPECT_GT(v[200], prev[200]);
    EXPECT_NEAR(v[200], std::min(200.0, T / (2 * std::sin(15 * 3.14159265358979 / 180))), 1e-9);
    prev = v;
  }
  std::fill(prev.begin(), prev.end(), 0.0);
  for (double am : {0.25, 0.5, 1.0, 2.0}) {
    const auto v = sm::plan_lookahead(segs, {5, am, 200});
    for (std::size_t i = 0; i < v.size(); ++i) ASSERT_GE(v[i], prev[i]);
    EXPECT_GT(v[200], prev[200]);
    prev = v;
  }
  EXPECT_EQ(prev.back(), 0.0);  // the path ends at rest
}

TEST(LookAheadProperties, ForcedStopsAtG0AndDelay) {
  // A 10 us cycle: a stop between two samples shows as a sampled speed <= accMax x cycle = 0.01.
  sm::PathSetup fine;
  fine.cycle_ms = 0.01;
  sm::PathGenerator g(sm::CoordSystem::identity(2), fine);
  g.init_lookahead({5, 1, 200});
  for (int k = 1; k <= 10; ++k) g.line({1000.0 * k, 0}, 50, 1);
  g.buf_delay(10);
  for (int k = 11; k <= 20; ++k) g.line({1000.0 * k, 0}, 50, 1);
  g.push_segment(G::line(g.tail(), {21000, 0}, 2), 50, 1, 0, true);
  for (int k = 22; k <= 30; ++k) g.line({1000.0 * k, 0}, 50, 1);
  g.flush();
  g.start();
  // The lowest speed sampled within 1 pulse of each point (a forced stop is sampled at rest there).
  double v_at_10000 = 1e9, v_at_20000 = 1e9, v_at_21000 = 1e9, v_mid = 0;
  while (!g.done()) {
    const auto& s = g.step();
    if (std::fabs(s.pos[0] - 10000) <= 1) v_at_10000 = std::min(v_at_10000, s.speed);
    if (std::fabs(s.pos[0] - 20000) <= 1) v_at_20000 = std::min(v_at_20000, s.speed);
    if (std::fabs(s.pos[0] - 21000) <= 1) v_at_21000 = std::min(v_at_21000, s.speed);
    if (s.pos[0] > 4000 && s.pos[0] < 6000) v_mid = std::max(v_mid, s.speed);
  }
  EXPECT_EQ(v_at_10000, 0.0);  // before the delay
  EXPECT_LE(v_at_20000, 0.01);  // before the G0
  EXPECT_LE(v_at_21000, 0.01);  // after the G0
  EXPECT_EQ(v_mid, 50.0);      // no stop at the collinear joints in between
  EXPECT_EQ(g.state().pos[0], 30000);
}

TEST(LookAheadProperties, WindowsOf200AndMoreAndThePlanningRate) {
  // 200 000 collinear segments of 10 pulse at feed 100, accMax 1: a window of n segments reaches the speed the
  // window's length allows (sqrt(accMax * n * 10)), never more; n >= 200 works like any other window.
  std::vector<double> pts;
  for (int i = 0; i <= 200000; ++i) pts.push_back(10.0 * i), pts.push_back(0.0);
  for (double n : {200.0, 500.0, 2000.0}) {
    const auto v = sm::plan_polyline_lookahead(pts.data(), 200001, 2, 100, 1, {5, 1, n});
    ASSERT_EQ(v.size(), 200000u);
    const double cruise = v[100000];
    EXPECT_NEAR(cruise, std::min(100.0, std::sqrt(2 * 1 * 10 * n)), 1e-9) << n;
    EXPECT_EQ(v.back(), 0.0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto v = sm::plan_polyline_lookahead(pts.data(), 200001, 2, 100, 1, {5, 1, 200});
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("look-ahead planning: %.2f M segments/s\n", 200000 / s / 1e6);
  EXPECT_GT(200000 / s, 2e5);  // loose here; the benchmark (bench/bench_paths.py) measures the 1 M/s goal
  EXPECT_EQ(v.size(), 200000u);
}

TEST(AxisAccLimits, CornerCapLeavesEachAxisItsBudget) {
  // VF9: v_c <= min_k (A_k - max(d_out_k, d_in_k)) h / |du_k|; a 90 deg corner X -> Y, ramps 0.2 on each side.
  sm::AxisAccLimits lim;
  lim.acc = {1.0, 0.5, 0.0, 0.0};
  lim.cycle_ms = 2.0;
  sm::AxisDemand out, in;
  out.u_out = {1, 0, 0, 0};
  out.acc = {0.2, 0, 0, 0};
  in.u_in = {0, 1, 0, 0};
  in.acc = {0, 0.2, 0, 0};
  // X: (1 - 0.2) * 2 / 1 = 1.6; Y: (0.5 - 0.2) * 2 / 1 = 0.6
  EXPECT_DOUBLE_EQ(sm::axis_corner_speed_limit(out, in, lim), 0.6);
  // a budget used up by the ramp: the corner is taken at rest
  in.acc[1] = 0.5;
  EXPECT_EQ(sm::axis_corner_speed_limit(out, in, lim), 0.0);
  // collinear, or no limits: no cap
  in.u_in = out.u_out;
  EXPECT_TRUE(std::isinf(sm::axis_corner_speed_limit(out, in, lim)));
  EXPECT_TRUE(std::isinf(sm::axis_corner_speed_limit(out, in, sm::AxisAccLimits{})));
}
