// Electronic gear: GT manual 000_0c49d4aa9b235bd5.txt L1029-1090, L4407-4437 (digest gt.md §3.4, TV10, TV11).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/motion/gear.hpp"
#include "servobench/motion/generator.hpp"

namespace sm = servobench::motion;

// GT TV10, 000 L1055-1059: axis 1 PrflG(2), Ratio -1: delta pos1 = -delta pos2.
TEST(MotionGear, GtTV10_RatioMinusOne) {
  sm::ProfileGenerator master;
  master.move_t_curve(5000, {3, 0.05});
  sm::ElectronicGear slave(-1, master.reported_pos(), 100);
  while (master.moving()) {
    master.step();
    slave.step(master.reported_pos());
    ASSERT_EQ(slave.reported_pos() - 100, -master.reported_pos());
  }
}

// GT TV11, 000 L4425-4435: axis 4 T-curve; axis 1 = -1.5 x axis 4; axis 3 = 0.5 x axis 1 (chained).
TEST(MotionGear, GtTV11_ChainedGears) {
  sm::ProfileGenerator axis4;
  axis4.move_t_curve(40000, {7, 0.1});
  sm::ElectronicGear axis1(-1.5, 0, 0), axis3(0.5, 0, 0);
  while (axis4.moving()) {
    axis4.step();
    axis1.step(axis4.reported_pos());
    axis3.step(axis1.reported_pos());
  }
  EXPECT_EQ(axis1.reported_pos(), -60000);
  EXPECT_EQ(axis3.reported_pos(), -30000);  // = -0.75 x axis 4
}

// A long run does not drift: ratio 1/3 over 10^7 single-pulse master steps ends within half a pulse of the
// exact ratio x travel, and the remainder stays below half a pulse every tick.
TEST(MotionGear, LongRunsDoNotDrift) {
  sm::ElectronicGear g(1.0 / 3.0, 0, 0);
  double worst = 0;
  for (long long m = 1; m <= 10000000; ++m) {
    g.step(m);
    worst = std::max(worst, std::fabs(g.remainder()));
  }
  EXPECT_LE(worst, 0.5);
  EXPECT_EQ(g.reported_pos(), 3333333);
  EXPECT_NEAR(g.state().pos, 1e7 / 3.0, 1e-6);
  g.set_ratio(-2, 10000000);  // rebases without a jump
  g.step(10000000);
  EXPECT_NEAR(g.state().pos, 1e7 / 3.0, 1e-6);
  g.step(10000001);
  EXPECT_NEAR(g.state().vel, -2, 1e-9);
  EXPECT_THROW(sm::ElectronicGear(16385, 0, 0), std::invalid_argument);
  EXPECT_THROW((sm::GtGearParams{7, 1}.validate()), std::invalid_argument);
}
