// GE look-ahead module A in mm and s (GE manual ../shared/seeds/001_b26ef06a365efe59.txt L1666-1727, L3370-3394,
// L3790-3800, L4879-4887; digest ge.md §4.6 (A)).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "servobench/motion/ge_lookahead.hpp"
#include "servobench/motion/generator.hpp"

namespace sm = servobench::motion;

TEST(GeLookAheadA, MmUnitsMatchThePulsePlanner) {
  // GE Ex 6-4 parameters (L1819-1940, T7): T = 0.002 s, amax = 500 mm/s^2, am = 200 mm/s^2, con = 2000 pulse/mm;
  // a zig-zag polyline at 50 mm/s (MvXYZEx feed). The end velocities in mm/s equal the pulse/ms planner's
  // scaled by 1000/con, the last ends at 0, and a repeated point returns 1.
  sm::GeLookAheadParams p;
  p.t_s = 0.002;
  p.acc_max = 500;
  p.acc = 200;
  p.vel = 50;
  p.n = 200;
  p.con = 2000;
  sm::GeLookAhead ge(p);
  std::vector<double> pts;  // pulse, for the reference planner
  pts.push_back(0);
  pts.push_back(0);
  for (int k = 1; k <= 300; ++k) {
    const double x = k * 0.5, y = (k % 2) * 0.05;
    EXPECT_EQ(ge.add(1, 17, 0, x, y, 0, 50, 0, 0, 1000 + k, false), 0);
    pts.push_back(x * 2000);
    pts.push_back(y * 2000);
  }
  EXPECT_EQ(ge.add(1, 17, 0, 150, 0, 0, 50, 0, 0, 9999, false), 1);  // same point as the last (L3392-3394)
  sm::LookAheadParams q{2.0, 500 * 2000 / 1e6, 200, {}};
  // Reference: the look-ahead at acc_run (the polyline helper takes one acc for ramps, here acc_run).
  std::vector<sm::LookAheadSegment> segs;
  for (std::size_t i = 1; i < pts.size() / 2; ++i) {
    const auto g = sm::PathSegmentGeometry::line({pts[2 * i - 2], pts[2 * i - 1], 0, 0}, {pts[2 * i], pts[2 * i + 1], 0, 0}, 3);
    segs.push_back(sm::lookahead_segment(g, 50 * 2000 / 1000.0, 200 * 2000 / 1e6));
  }
  const auto ref = sm::plan_lookahead(segs, q);
  double v = 0;
  long long num = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const int rc = ge.cal_vel(v, num);
    EXPECT_EQ(num, 1001 + static_cast<long long>(i));
    EXPECT_NEAR(v, ref[i] * 1000 / 2000, 1e-9);
    EXPECT_EQ(rc, i + 1 == ref.size() ? 1 : 0);
  }
  EXPECT_EQ(v, 0.0);
  EXPECT_THROW(ge.cal_vel(v, num), sm::MotionCommandRefused);
}

TEST(GeLookAheadA, ArcsG0AndFlagAndBadInput) {
  sm::GeLookAheadParams p;
  p.con = 1000;
  p.acc_max = 2000;
  p.acc = 1000;
  p.vel = 100;
  sm::GeLookAhead ge(p);
  ge.add(1, 17, 0, 10, 0, 0, 100, 0, 0, 1, false);
  ge.add(3, 17, 10, 20, 10, 0, 100, 20, 0, 2, false);  // G03: CCW 270 deg about (20, 0), a 90 deg corner
  ge.add(1, 17, 0, 20, 30, 0, 100, 0, 0, 3, true);      // flag: stop at its end
  ge.add(1, 17, 0, 20, 40, 0, 100, 0, 0, 4, false);
  ge.add(0, 17, 0, 0, 0, 0, 100, 0, 0, 5, false);       // G00: the previous segment ends at 0
  double v = 0;
  long long n = 0;
  ge.cal_vel(v, n);
  EXPECT_GT(v, 0.0);  // line -> arc: a corner cap, not a stop
  ge.cal_vel(v, n);
  EXPECT_GT(v, 0.0);
  EXPECT_LE(v, std::sqrt(2000.0 * 10.0) + 1e-9);  // centripetal cap sqrt(acc_max * r) in mm/s, mm/s^2, mm
  ge.cal_vel(v, n);
  EXPECT_EQ(v, 0.0);  // flag
  ge.cal_vel(v, n);
  EXPECT_EQ(v, 0.0);  // before a G00
  EXPECT_EQ(ge.cal_vel(v, n), 1);
  EXPECT_EQ(n, 5);
  EXPECT_THROW(ge.add(2, 17, 5, 0, 0, 0, 100, 30, 0, 6, false), std::invalid_argument);  // r disagrees
  EXPECT_THROW(ge.add(4, 17, 0, 1, 1, 0, 100, 0, 0, 6, false), std::invalid_argument);
  EXPECT_THROW(ge.add(2, 20, 5, 0, 0, 0, 100, 0, 0, 6, false), std::invalid_argument);
  p.acc = p.acc_max;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}
