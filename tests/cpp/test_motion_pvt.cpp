// PVT: the manuals' test vectors and property tests. Manual files in ../shared/seeds/:
// GUC = 002_b2237d67fd2eb602.txt (GUC-ECAT advanced manual, digest guc-ecat.md §6.6-6.10),
// iDEABOX = 003_2c62cffc310de7fb.txt (digest ideabox.md §6 items 11-18). Units: ms, pulse, pulse/ms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "servobench/motion/generator.hpp"
#include "servobench/motion/pvt.hpp"
#include "servobench/motion/pvt_table.hpp"

namespace sm = servobench::motion;
using V = std::vector<double>;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Largest |position| error between a curve and the pieces' own ends at every point, and the largest jump in
// position / velocity / acceleration where two pieces meet.
struct Joints {
  double pos = 0, vel = 0, acc = 0;
};
Joints joint_jumps(const sm::PvtCurve& c) {
  Joints j;
  for (std::size_t k = 0; k + 1 < c.pieces.size(); ++k) {
    const auto& a = c.pieces[k].seg;
    const auto& b = c.pieces[k + 1].seg;
    const auto e = a.at(a.duration);
    j.pos = std::max(j.pos, std::fabs(e.pos - b.p));
    j.vel = std::max(j.vel, std::fabs(e.vel - b.v));
    j.acc = std::max(j.acc, std::fabs(e.acc - b.a));
  }
  return j;
}

// Runs a PVT axis for n ticks; returns the position after each tick.
V run_axis(sm::PvtAxis& ax, long n) {
  V out;
  for (long k = 0; k < n; ++k) out.push_back(ax.step().pos);
  return out;
}
}  // namespace

// GUC Tab 4-17 set 1 (002 L1339-1347), iDEABOX Table 4-6 group 1 (003 L2842-2857): an exact trapezoid.
TEST(PvtVectors, GucTab4_17_Set1_Trapezoid) {
  const auto c = sm::pvt_table({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, {0, 10, 10, 0});
  EXPECT_NEAR(c.at(0).acc, 0.01, 1e-15);
  EXPECT_NEAR(c.at(999.9).acc, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(c.pieces[0].seg.j, 0.0);
  EXPECT_NEAR(c.at(1500).vel, 10.0, 1e-12);
  EXPECT_NEAR(c.at(1500).acc, 0.0, 1e-15);
  EXPECT_NEAR(c.at(2500).acc, -0.01, 1e-15);
  EXPECT_NEAR(c.at(500).pos, 1250.0, 1e-9);
}

// GUC Tab 4-17 set 2 (002 L1347-1354), iDEABOX Table 4-6 group 2: smooth, v peaks 10.5 at 1500.
TEST(PvtVectors, GucTab4_17_Set2_Smooth) {
  const auto c = sm::pvt_table({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, {0, 9, 9, 0});
  EXPECT_NEAR(c.at(0).acc, 0.012, 1e-15);
  EXPECT_NEAR(c.at(1000).acc, 0.006, 1e-12);
  EXPECT_NEAR(c.at(1500).vel, 10.5, 1e-12);
  EXPECT_NEAR(c.at(1999.999999).acc, -0.006, 1e-9);
  const auto j = joint_jumps(c);
  EXPECT_LT(j.acc, 1e-12);  // C2: it equals the Complete result (iDEABOX L2858-2864)
}

// GUC Tab 4-17 set 3 (002 L1355-1361): seg 1 acc 0.015 -> 0, seg 2 v about 7.5 (max 7.5028).
TEST(PvtVectors, GucTab4_17_Set3) {
  const auto c = sm::pvt_table({0, 1000, 2333, 3333}, {0, 5000, 15000, 20000}, {0, 7.5, 7.5, 0});
  EXPECT_NEAR(c.at(0).acc, 0.015, 1e-15);
  EXPECT_NEAR(c.at(999.9999999).acc, 0.0, 1e-9);
  double vmax = 0;
  for (double t = 1000; t <= 2333; t += 0.5) vmax = std::max(vmax, c.at(t).vel);
  EXPECT_NEAR(vmax, 7.5028, 1e-4);
}

// GUC Tab 4-17 set 4 (002 L1362-1368), iDEABOX Table 4-6 group 4: S-shaped, v peaks 13.3325 at 1500,
// p(375) = 208.48, v(375) = 1.6673, jerk 2.37e-5 in seg 1.
TEST(PvtVectors, GucTab4_17_Set4_SShaped) {
  const auto c = sm::pvt_table({0, 750, 2250, 3000}, {0, 1667, 18333, 20000}, {0, 6.6669, 6.6669, 0});
  EXPECT_NEAR(c.at(0).acc, 0.0, 1e-5);
  EXPECT_NEAR(c.at(749.9999999).acc, 0.017775, 1e-6);
  EXPECT_NEAR(c.at(1500).vel, 13.3325, 1e-4);
  EXPECT_NEAR(c.at(375).pos, 208.48, 0.01);
  EXPECT_NEAR(c.at(375).vel, 1.6673, 1e-4);
  EXPECT_NEAR(c.pieces[0].seg.j, 2.37e-5, 0.01e-5);
}

// GUC Tab 4-18 (002 L1375-1389), iDEABOX Table 4-7 (003 L2895-2917): the "improper" sets.
TEST(PvtVectors, GucTab4_18_ImproperSets) {
  const auto a = sm::pvt_table({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, {0, 15, 15, 0});
  EXPECT_NEAR(a.at(1500).vel, 7.5, 1e-12);  // velocity dips between the points
  EXPECT_NEAR(a.at(1000).acc, -0.03, 1e-12);
  EXPECT_NEAR(a.at(1999.9999999).acc, 0.03, 1e-8);
  const auto b = sm::pvt_table({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, {0, 5, 5, 0});
  EXPECT_NEAR(b.at(2000.0 / 3.0).vel, 20.0 / 3.0, 1e-9);  // overshoot to 6.667 at 666.7
  EXPECT_NEAR(b.at(1500).vel, 12.5, 1e-12);
  EXPECT_NEAR(b.at(7000.0 / 3.0).vel, 20.0 / 3.0, 1e-9);
  EXPECT_NEAR(b.at(0).acc, 0.02, 1e-15);
  EXPECT_NEAR(b.at(999.9999999).acc, -0.01, 1e-8);
  EXPECT_NEAR(b.at(1000).acc, 0.03, 1e-12);
  const auto jb = joint_jumps(b);
  EXPECT_NEAR(jb.acc, 0.04, 1e-9);  // non-smooth: the acceleration jumps at P2 (Fig 4-19)
}

// GUC Tab 4-19 (002 L1397-1409), iDEABOX Table 4-8 (003 L2928-2942): Complete, v = 0, 9, 9, 0.
TEST(PvtVectors, GucTab4_19_Complete) {
  const auto v = sm::pvt_complete_velocities({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, 0, 0);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_NEAR(v[1], 9.0, 1e-12);
  EXPECT_NEAR(v[2], 9.0, 1e-12);
  const auto c = sm::pvt_table_complete({0, 1000, 2000, 3000}, {0, 5000, 15000, 20000}, 0, 0);
  EXPECT_NEAR(c.at(500).pos, 1375.0, 1e-9);
  EXPECT_NEAR(c.at(500).vel, 5.25, 1e-12);
  EXPECT_NEAR(c.at(500).acc, 0.009, 1e-12);
  EXPECT_NEAR(c.at(1500).pos, 10000.0, 1e-9);
  EXPECT_NEAR(c.at(1500).vel, 10.5, 1e-12);
  EXPECT_NEAR(c.at(1500).acc, 0.0, 1e-15);
  EXPECT_NEAR(c.at(0).acc, 0.012, 1e-15);
  EXPECT_EQ(c.blocks(), 4);
}

// GUC Tab 4-20 and Fig 4-22 (002 L1413-1432), iDEABOX Table 4-9 (003 L2951-2980): 50000 sin^2(pi t/2000).
TEST(PvtVectors, GucTab4_20_CompleteSineSquared) {
  auto f = [](double t) { return 50000.0 * std::pow(std::sin(kPi * t / 2000.0), 2); };
  const V t{0, 500, 1000, 1500, 2000};
  V p;
  for (double x : t) p.push_back(std::round(f(x)));
  const auto v = sm::pvt_complete_velocities(t, p, 0, 0);
  EXPECT_NEAR(v[1], 75.0, 1e-12);
  EXPECT_NEAR(v[2], 0.0, 1e-12);
  EXPECT_NEAR(v[3], -75.0, 1e-12);
  const auto c = sm::pvt_table_complete(t, p, 0, 0);
  EXPECT_NEAR(c.at(250).pos, 7812.5, 1e-9);
  EXPECT_NEAR(c.at(750).pos, 42187.5, 1e-9);
  // Fig 4-22: the largest |error| against the true function for 5, 10 and 50 points over one period.
  auto max_err = [&](int n) {
    V tt, pp;
    for (int i = 0; i < n; ++i) {
      tt.push_back(2000.0 * i / (n - 1));
      pp.push_back(f(tt.back()));
    }
    const auto cc = sm::pvt_table_complete(tt, pp, 0, 0);
    double e = 0, at = 0;
    for (double x = 0; x <= 2000; x += 0.25) {
      const double d = std::fabs(cc.at(x).pos - f(x));
      if (d > e) e = d, at = x;
    }
    return std::make_pair(e, at);
  };
  const auto e5 = max_err(5);
  EXPECT_NEAR(e5.first, 500.4, 0.1);
  EXPECT_NEAR(std::min(e5.second, 2000 - e5.second), 721, 2);
  EXPECT_NEAR(max_err(10).first, 17.43, 0.01);
  EXPECT_NEAR(max_err(50).first, 0.018, 0.001);
}

// GUC Tab 4-21 (002 L1436-1471), iDEABOX Table 4-10 (003 L3012-3024): Percent 60/0/100/0.
TEST(PvtVectors, GucTab4_21_Percent) {
  const V t{0, 1000, 2000, 3000}, p{0, 5000, 15000, 20000}, q{60, 0, 100, 0};
  const auto v = sm::pvt_percent_calculate(t, p, q, 0);
  EXPECT_EQ(v, (V{0, 10, 10, 0}));
  const auto c = sm::pvt_table_percent(t, p, q, 0);
  // Seg 1 (60 %): ta = 300, te = 400, A = 10/700.
  EXPECT_NEAR(c.at(300).pos, 214.2857142857, 1e-6);
  EXPECT_NEAR(c.at(300).vel, 2.142857142857, 1e-9);
  EXPECT_NEAR(c.at(300).acc, 10.0 / 700.0, 1e-12);
  EXPECT_NEAR(c.at(500).pos, 928.5714285714, 1e-6);
  EXPECT_NEAR(c.at(500).vel, 5.0, 1e-12);
  EXPECT_NEAR(c.at(700).pos, 2214.285714286, 1e-6);
  EXPECT_NEAR(c.at(700).vel, 7.857142857143, 1e-9);
  EXPECT_EQ(c.blocks_per_point, (std::vector<int>{3, 1, 2, 1}));  // 1-3 blocks per point (GUC L1202)
  // Seg 3 (100 %): triangular acceleration, peak -0.02 at the middle; v = 5, p = 15000 + 4166.667.
  EXPECT_NEAR(c.at(2500).acc, -0.02, 1e-12);
  EXPECT_NEAR(c.at(2500).vel, 5.0, 1e-12);
  EXPECT_NEAR(c.at(2500).pos, 15000 + 4166.6666667, 1e-6);
  EXPECT_NEAR(c.at(3000).pos, 20000.0, 1e-12);
}

// GUC Tab 4-22 (002 L1475-1504), iDEABOX Table 4-11 (003 L3053-3069): Continuous, both acc readings.
TEST(PvtVectors, GucTab4_22_Continuous) {
  sm::ContinuousPoints g1{{0, 20000}, {0, 0}, {60, 0}, {60, 0}, {10, 10}, {0.01, 0.01}, {0.01, 0.01}};
  EXPECT_NEAR(sm::pvt_continuous_calculate(g1)[1], 3428.5714285714, 1e-6);
  EXPECT_NEAR(sm::pvt_continuous_calculate(g1, sm::ContinuousAcc::Average)[1], 3000.0, 1e-9);
  const auto c1 = sm::pvt_table_continuous(g1, 0);
  EXPECT_NEAR(c1.at(1428.5714285714).pos, 7142.857142857, 1e-5);  // end of the acceleration phase
  EXPECT_NEAR(c1.at(1428.5714285714).vel, 10.0, 1e-9);
  sm::ContinuousPoints g2{{0, 19800, 21800}, {0, 2, 0}, {60, 0, 0}, {60, 0, 0}, {10, 2, 2},
                          {0.01, 0.02, 0.02}, {0.01, 0.02, 0.02}};
  const auto tp = sm::pvt_continuous_calculate(g2);
  EXPECT_NEAR(tp[1], 3151.4285714286, 1e-6);
  EXPECT_NEAR(tp[2] - tp[1], 1050.0, 1e-9);
  const auto ta = sm::pvt_continuous_calculate(g2, sm::ContinuousAcc::Average);
  EXPECT_NEAR(ta[1], 2800.0, 1e-9);
  EXPECT_NEAR(ta[2] - ta[1], 1050.0, 1e-9);
}

// GUC §4.2.4 PVT example, Tab 4-23 (002 L1506-1604), iDEABOX Ex 4-11, Table 4-12 (003 L3088-3197).
TEST(PvtVectors, GucTab4_23_PvtExample) {
  const auto c = sm::pvt_table({0, 1200, 2000, 3000, 3800, 5000}, {0, 9750, 24483, 44483, 59216, 68966},
                               {1, 15.25, 20, 20, 15.25, 1});
  EXPECT_NEAR(c.pieces[0].seg.a, 0.011875, 1e-15);
  EXPECT_NEAR(c.pieces[0].seg.j, 0.0, 1e-15);
  EXPECT_NEAR(c.pieces[1].seg.j, -1.484e-5, 0.001e-5);
  EXPECT_NEAR(c.at(600).pos, 2737.5, 1e-9);
  EXPECT_NEAR(c.at(600).vel, 8.125, 1e-12);
  EXPECT_NEAR(c.at(1600).pos, 16641.5, 0.05);
  EXPECT_NEAR(c.at(1600).vel, 18.8119, 1e-4);
  EXPECT_NEAR(c.at(2500).pos, 34483, 1e-9);
  EXPECT_NEAR(c.at(2500).vel, 20.0, 1e-12);
  EXPECT_NEAR(c.at(4400).pos, 66228.5, 1e-9);
  EXPECT_NEAR(c.at(4400).vel, 8.125, 1e-12);
  // Sampled on a 1 ms axis: ends on the last point and stays there (decision M23).
  sm::PvtTables tables;
  tables.download(1, c);
  sm::PvtAxis ax(tables, 0.0, 1e-3);
  ax.select(1);
  ax.start();
  const auto pos = run_axis(ax, 5002);
  EXPECT_DOUBLE_EQ(pos[599], 2737.5);
  EXPECT_DOUBLE_EQ(pos[4999], 68966.0);
  EXPECT_DOUBLE_EQ(pos[5001], 68966.0);
  EXPECT_FALSE(ax.moving());
}

// GUC Tab 4-16 (002 L1314-1333), iDEABOX Table 4-5 (003 L2801-2826): start delay 1000 ms once, then
// passes of 3000 ms that restart at the first point's time.
TEST(PvtVectors, GucTab4_16_LoopAndStartDelay) {
  sm::PvtTables tables;
  tables.download(2, sm::pvt_table({1000, 2000, 3000, 4000}, {0, 5000, 15000, 20000}, {0, 10, 10, 0}));
  sm::PvtAxis ax(tables, 0.0, 1e-3);
  ax.select(2);
  ax.set_loop(3);
  ax.start();
  V pos, vel, tm;
  for (int k = 0; k < 10100; ++k) {
    const auto& s = ax.step();
    pos.push_back(s.pos);
    vel.push_back(s.vel);
    tm.push_back(ax.time_ms());
  }
  // Still during the delay, moving right after it.
  EXPECT_EQ(pos[999 - 1], 0.0);
  EXPECT_EQ(pos[999], 0.0);  // t = 1000: P1
  EXPECT_NEAR(pos[1000 + 499], 1250.0, 1e-9);
  EXPECT_NEAR(pos[3999], 20000.0, 1e-9);  // t = 4000: end of pass 1
  EXPECT_NEAR(tm[3999], 1000.0, 1e-9);   // time re-initialised to P1's, not 0
  EXPECT_NEAR(pos[4000 + 499], 21250.0, 1e-9);  // pass 2 continues from 20000, no second delay
  EXPECT_NEAR(vel[4000 + 1499], 10.0 * 1e-3 * 1e3, 1e-9);  // 10 pulse/ms = 10 pulse/tick at 1 ms
  EXPECT_EQ(ax.loop_count(), 3);
  EXPECT_FALSE(ax.moving());
  EXPECT_NEAR(pos[9999], 60000.0, 1e-9);  // three passes end at 1000 + 3 x 3000 ms
  EXPECT_NEAR(pos.back(), 60000.0, 1e-9);
}

// GUC §4.2.4 Complete example (002 L1606-1773, Fig 4-28), iDEABOX Ex 4-12 (003 L3206-3360): 40000 sin^2,
// velocities 60, 0, -60; infinite loop; a new table selected while moving takes over at the next pass end.
TEST(PvtVectors, GucComplete_LiveTableSwap) {
  auto table_for = [](double amp) {
    V t, p;
    for (int i = 0; i <= 4; ++i) {
      t.push_back(500.0 * i);
      p.push_back(std::round(amp * std::pow(std::sin(3.1415926 * t.back() / 2000.0), 2)));
    }
    return sm::pvt_table_complete(t, p, 0, 0);
  };
  const auto c1 = table_for(40000);
  EXPECT_NEAR(c1.vel[1], 60.0, 1e-12);
  EXPECT_NEAR(c1.vel[2], 0.0, 1e-12);
  EXPECT_NEAR(c1.vel[3], -60.0, 1e-12);
  sm::PvtTables tables;
  tables.download(1, c1);
  sm::PvtAxis ax(tables, 0.0, 1e-3);
  ax.set_loop(0);
  ax.start();
  run_axis(ax, 2700);  // into pass 2
  EXPECT_THROW(tables.download(1, table_for(60000)), sm::MotionCommandRefused);  // in use (GUC L1306)
  tables.download(2, table_for(60000));  // key 'A': x1.5 into the other table (L1746)
  ax.select(2);
  EXPECT_EQ(ax.table_id(), 1);  // deferred
  V pos = run_axis(ax, 3000);   // ticks 2701..5700
  EXPECT_EQ(ax.table_id(), 2);
  // Pass 2 of table 1 ends at 4000 ms; from there on the 60000 table: its peak at 5000 ms.
  EXPECT_NEAR(pos[4000 - 2701], 0.0, 1e-9);
  EXPECT_NEAR(pos[5000 - 2701], 60000.0, 1e-9);
  EXPECT_NEAR(pos[3000 - 2701], 40000.0, 1e-9);
  EXPECT_EQ(ax.loop_count(), 2);
  EXPECT_TRUE(ax.moving());
  ax.stop();  // 'Q': GT_Stop
  EXPECT_FALSE(ax.moving());
  EXPECT_EQ(tables.users(2), 0);
}

// GUC §4.2.4 Percent example, Tabs 4-24..4-27 (002 L1775-1944), iDEABOX Ex 4-13, Tables 4-13..4-16
// (003 L3362-3579): X loops 2, Y loops 3 with a 2000 ms delay; Y still while X cruises; Y feeds forward.
TEST(PvtVectors, GucPercentExample_TwoAxesPhaseOffset) {
  const V tx{0, 1000, 2000, 3000, 4000, 5000, 6000}, px{0, 5000, 15000, 20000, 15000, 5000, 0},
      qx{60, 0, 60, 60, 0, 60, 0};
  const V ty{2000, 2500, 3500, 4000, 5000}, py{0, 2500, 12500, 15000, 15000}, qy{60, 0, 60, 0, 0};
  EXPECT_EQ(sm::pvt_percent_calculate(tx, px, qx, 0), (V{0, 10, 10, 0, -10, -10, 0}));  // L1797-1803
  EXPECT_EQ(sm::pvt_percent_calculate(ty, py, qy, 0), (V{0, 10, 10, 0, 0}));            // L1818-1822
  sm::PvtTables tables;
  tables.download(1, sm::pvt_table_percent(tx, px, qx, 0));
  tables.download(2, sm::pvt_table_percent(ty, py, qy, 0));
  sm::PvtAxis x(tables, 0.0, 1e-3), y(tables, 0.0, 1e-3);
  x.select(1);
  y.select(2);
  x.set_loop(2);
  y.set_loop(3);
  sm::pvt_start({&x, &y});
  V xv, yv, yp;
  for (int k = 1; k <= 12500; ++k) {
    xv.push_back(x.step().vel);
    const auto& s = y.step();
    yv.push_back(s.vel);
    yp.push_back(s.pos);
  }
  auto at = [](const V& v, int ms) { return v[static_cast<std::size_t>(ms - 1)]; };
  EXPECT_EQ(at(yp, 2000), 0.0);  // the delay
  EXPECT_GT(at(yv, 2100), 0.0);
  for (int ms : {4200, 4500, 4900, 7200, 7500, 7900, 10200, 10500, 10900}) {
    EXPECT_EQ(at(yv, ms), 0.0) << ms;                  // Y still ...
    EXPECT_NEAR(std::fabs(at(xv, ms)), 10.0, 1e-9) << ms;  // ... while X cruises
  }
  for (int ms : {5500, 8500}) EXPECT_GT(at(yv, ms), 0.0) << ms;  // new Y passes at 5000 and 8000
  EXPECT_NEAR(at(yp, 7000), 30000.0, 1e-9);
  EXPECT_NEAR(at(yp, 11000), 45000.0, 1e-9);  // 15000 per pass, 45000 in all
  EXPECT_FALSE(y.moving());
  EXPECT_FALSE(x.moving());
  EXPECT_EQ(x.loop_count(), 2);
  EXPECT_EQ(y.loop_count(), 3);
}

// GUC §4.2.4 Continuous example (002 L1946-2098, Fig 4-31), iDEABOX Ex 4-14 (003 L3581-3772): the shorter
// axis is delayed so both end together; timeBegin_y = 1000 in both acc readings.
TEST(PvtVectors, GucContinuousExample_Synchronised) {
  auto pts = [](double d) {
    return sm::ContinuousPoints{{0, d}, {0, 0}, {100, 100}, {100, 100}, {10, 10}, {0.01, 0.01}, {0.01, 0.01}};
  };
  const double tx = sm::pvt_continuous_calculate(pts(30000))[1], ty = sm::pvt_continuous_calculate(pts(20000))[1];
  EXPECT_NEAR(tx, 5000.0, 1e-9);
  EXPECT_NEAR(ty, 4000.0, 1e-9);
  const double txa = sm::pvt_continuous_calculate(pts(30000), sm::ContinuousAcc::Average)[1];
  const double tya = sm::pvt_continuous_calculate(pts(20000), sm::ContinuousAcc::Average)[1];
  EXPECT_NEAR(txa, 4000.0, 1e-9);
  EXPECT_NEAR(tya, 3000.0, 1e-9);
  EXPECT_NEAR(tx - ty, 1000.0, 1e-9);
  EXPECT_NEAR(txa - tya, 1000.0, 1e-9);
  sm::PvtTables tables;
  tables.download(1, sm::pvt_table_continuous(pts(30000), 0));
  tables.download(2, sm::pvt_table_continuous(pts(20000), tx - ty));
  sm::PvtAxis x(tables, 0.0, 1e-3), y(tables, 0.0, 1e-3);
  x.select(1);
  y.select(2);
  sm::pvt_start({&x, &y});
  long kx = 0, ky = 0;
  for (long k = 1; k <= 6000; ++k) {
    if (x.moving()) kx = k;
    if (y.moving()) ky = k;
    x.step();
    y.step();
  }
  EXPECT_EQ(kx, ky);  // both finish on the same tick
  EXPECT_EQ(kx, 5000);
  EXPECT_DOUBLE_EQ(x.state().pos, 30000.0);
  EXPECT_DOUBLE_EQ(y.state().pos, 20000.0);
}

// Tables and their limits: 32 tables, 1024 blocks, empty tables (GUC L1272-1310, iDEABOX L2779-2791,
// L6319-6327, L6436-6438, L7048).
TEST(PvtTables, SizesEmptyTablesAndRefusals) {
  sm::PvtTables tables;
  EXPECT_THROW(tables.download(0, sm::pvt_table({0, 1}, {0, 1}, {0, 0})), std::invalid_argument);
  EXPECT_THROW(tables.download(33, sm::pvt_table({0, 1}, {0, 1}, {0, 0})), std::invalid_argument);
  V t(1024), p(1024), v(1024, 0.0);
  for (int i = 0; i < 1024; ++i) t[i] = i, p[i] = i;
  tables.download(32, sm::pvt_table(t, p, v));  // exactly 1024 blocks fit
  t.push_back(1024);
  p.push_back(1024);
  v.push_back(0);
  EXPECT_THROW(tables.download(32, sm::pvt_table(t, p, v)), sm::MotionCommandRefused);
  // Percent: 1-3 blocks a point, so 400 points at 60 % need 3 x 399 + 1 = 1198 blocks.
  V tp(400), pp(400), qp(400, 60.0);
  for (int i = 0; i < 400; ++i) tp[i] = 10.0 * i, pp[i] = (i % 2) * 100.0;
  const auto big = sm::pvt_table_percent(tp, pp, qp, 0);
  EXPECT_EQ(big.blocks(), 1198);
  try {
    tables.download(3, big);
    FAIL();
  } catch (const sm::MotionCommandRefused& e) {
    EXPECT_NE(std::string(e.what()).find("1198 memory blocks, a table holds 1024"), std::string::npos);
  }
  sm::PvtAxis ax(tables, 0.0, 1e-3);
  EXPECT_THROW(ax.start(), sm::MotionCommandRefused);  // default table 1 is empty
  EXPECT_THROW(ax.select(5), sm::MotionCommandRefused);
  EXPECT_THROW(ax.set_loop(-1), std::invalid_argument);
  ax.select(32);
  ax.start();
  EXPECT_THROW(ax.start(), sm::MotionCommandRefused);
  EXPECT_EQ(tables.users(32), 1);
}

TEST(PvtTables, BadPointsNameTheParameter) {
  auto msg = [](auto f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(msg([] { sm::pvt_table({0, 1000, 1000}, {0, 1, 2}, {0, 0, 0}); }).find("PvtTable.time_ms[2] = 1000 must be greater"),
            std::string::npos);
  EXPECT_NE(msg([] { sm::pvt_table({0}, {0}, {0}); }).find("PvtTable.count = 1"), std::string::npos);
  EXPECT_NE(msg([] { sm::pvt_table({0, 1}, {0, 1}, {0}); }).find("PvtTable.vel has 1 values; expected 2"),
            std::string::npos);
  EXPECT_NE(msg([] { sm::pvt_table({-5, 1}, {0, 1}, {0, 0}); }).find("time_ms[0] = -5 must be >= 0"),
            std::string::npos);
  EXPECT_NE(msg([] { sm::pvt_table_percent({0, 1}, {0, 1}, {101, 0}, 0); })
                .find("PvtTablePercent.percent[0] = 101 is outside the allowed range 0..100"),
            std::string::npos);
  sm::ContinuousPoints bad{{0, 100}, {0, 0}, {0, 0}, {0, 0}, {0, 10}, {0.01, 0.01}, {0.01, 0.01}};
  EXPECT_NE(msg([&] { sm::pvt_continuous_calculate(bad); }).find("PvtTableContinuous.vel_max[0] = 0 must be > 0"),
            std::string::npos);
  sm::ContinuousPoints wrong_dir{{0, 100}, {-1, 0}, {0, 0}, {0, 0}, {10, 10}, {0.01, 0.01}, {0.01, 0.01}};
  EXPECT_NE(msg([&] { sm::pvt_continuous_calculate(wrong_dir); }).find("PvtTableContinuous.vel[0] = -1 must point along"),
            std::string::npos);
  sm::ContinuousPoints too_short{{0, 100}, {10, 0}, {0, 0}, {0, 0}, {10, 10}, {0.01, 0.01}, {0.01, 0.01}};
  EXPECT_NE(msg([&] { sm::pvt_continuous_calculate(too_short); }).find("pos[1] = 100 is too close"),
            std::string::npos);
}

// Properties over random tables: every mode hits its points exactly (p and v; t for Continuous as planned);
// PVT/Complete/Percent are continuous in position and velocity at every joint; Complete also in
// acceleration; Percent's acceleration is the trapezoid of the manual's definition; Continuous keeps
// |v| <= vMax and |a| <= acc/dec (peak reading) or the average rate (average reading).
TEST(PvtProperties, RandomTablesHitTheirPointsAndKeepTheirPromises) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst_p = 0, worst_v = 0, worst_a = 0, worst_vlim = 0, worst_alim = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + static_cast<int>(U(rng) * 20);
    V t(n), p(n), v(n), q(n);
    t[0] = std::floor(U(rng) * 100);
    for (int i = 0; i < n; ++i) {
      if (i) t[i] = t[i - 1] + 1 + std::floor(U(rng) * 2000);
      p[i] = std::round((U(rng) - 0.5) * 1e5);
      v[i] = (U(rng) - 0.5) * 100;
      q[i] = std::floor(U(rng) * 101);
    }
    auto check_points = [&](const sm::PvtCurve& c, const V& vel) {
      for (int i = 0; i + 1 < n; ++i) {
        const auto s = c.at(t[i]);
        worst_p = std::max(worst_p, std::fabs(s.pos - p[i]) / (1 + std::fabs(p[i])));
        worst_v = std::max(worst_v, std::fabs(s.vel - vel[i]) / (1 + std::fabs(vel[i])));
      }
      worst_p = std::max(worst_p, std::fabs(c.at(t[n - 1]).pos - p[n - 1]));
      const auto j = joint_jumps(c);
      worst_p = std::max(worst_p, j.pos / 1e5);
      worst_v = std::max(worst_v, j.vel / 100);
    };
    check_points(sm::pvt_table(t, p, v), v);
    const auto cc = sm::pvt_table_complete(t, p, v[0], v[n - 1]);
    check_points(cc, cc.vel);
    worst_a = std::max(worst_a, joint_jumps(cc).acc / (1e-3 + std::fabs(cc.at(t[0]).acc)));
    const auto pc = sm::pvt_table_percent(t, p, q, v[0]);
    check_points(pc, pc.vel);
    // Percent shape: |acc| rises linearly over ta, holds A over te, falls over ta.
    for (int i = 0; i + 1 < n; ++i) {
      const double T = t[i + 1] - t[i], dv = pc.vel[i + 1] - pc.vel[i], qq = q[i] / 100;
      if (dv == 0) continue;
      const double ta = qq * T / 2, A = dv / (T - ta);
      const double mid = pc.at(t[i] + T / 2).acc;
      worst_a = std::max(worst_a, std::fabs(mid - A) / std::fabs(A));
      if (qq > 0) {
        worst_a = std::max(worst_a, std::fabs(pc.at(t[i] + ta / 2).acc - A / 2) / std::fabs(A));
        worst_a = std::max(worst_a, std::fabs(pc.at(t[i]).acc) / std::fabs(A));
      }
    }
    // Continuous: monotone points, velocities along the motion, limits kept.
    V cp(n), cv(n), qa(n), qd(n), vm(n), ac(n), dc(n);
    double x = 0;
    for (int i = 0; i < n; ++i) {
      vm[i] = 1 + U(rng) * 50;
      ac[i] = 0.05 + U(rng) * 0.1;
      dc[i] = 0.05 + U(rng) * 0.1;
      qa[i] = std::floor(U(rng) * 101);
      qd[i] = std::floor(U(rng) * 101);
    }
    for (int i = 0; i < n; ++i) {
      cp[i] = x;
      cv[i] = (i == 0 || i == n - 1) ? 0.0 : U(rng) * std::min(vm[i - 1], vm[i]);
      x += 60000 + U(rng) * 50000;  // long enough for any velocity change at these limits
    }
    sm::ContinuousPoints P{cp, cv, qa, qd, vm, ac, dc};
    for (auto meaning : {sm::ContinuousAcc::Peak, sm::ContinuousAcc::Average}) {
      const auto c = sm::pvt_table_continuous(P, 0, meaning, true);
      const auto tt = sm::pvt_continuous_calculate(P, meaning);
      for (int i = 0; i + 1 < n; ++i) {
        worst_p = std::max(worst_p, std::fabs(c.at(c.time_ms[i]).pos - cp[i]) / (1 + cp[i]));
        worst_v = std::max(worst_v, std::fabs(c.at(c.time_ms[i]).vel - cv[i]) / (1 + cv[i]));
        worst_p = std::max(worst_p, std::fabs(c.time_ms[i] - tt[i]) / (1 + tt[i]));
      }
      for (std::size_t k = 0; k < c.pieces.size(); ++k) {
        const auto& pc0 = c.pieces[k];
        const auto i = static_cast<std::size_t>(
            std::upper_bound(c.time_ms.begin(), c.time_ms.end(), pc0.t0_ms + 1e-9) - c.time_ms.begin() - 1);
        for (double f : {0.0, 0.5, 1.0}) {
          const auto s = pc0.seg.at(f * pc0.seg.duration);
          worst_vlim = std::max(worst_vlim, s.vel / vm[i] - 1);
          const double lim = std::max(ac[i], dc[i]);
          const double alim = meaning == sm::ContinuousAcc::Peak ? lim : 2 * lim;  // average: peak <= 2x
          worst_alim = std::max(worst_alim, std::fabs(s.acc) / alim - 1);
        }
      }
      const auto j = joint_jumps(c);
      worst_v = std::max(worst_v, j.vel / 100);
    }
  }
  EXPECT_LT(worst_p, 1e-9);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_a, 1e-6);
  EXPECT_LT(worst_vlim, 1e-12);
  EXPECT_LT(worst_alim, 1e-9);
}
