// The GE SX coordinate system on the card (vendor/googol/ge_crd.hpp, formerly machine/card_group_ge.hpp): X..A = axes 1..4 with GT_MapCnt offsets,
// the pulse/ms time base, the start velocity and MaxVel clamp, refusals. GE seed 001 §6 (ge.md §4).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/machine/card.hpp"
#include "card_fixtures.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/googol/ge_crd.hpp"

namespace mc = servobench::machine;
namespace sm = servobench::motion;
namespace gg = servobench::vendor::googol;

namespace {

mc::AxisConfig axis_cfg(double period_s) { return servobench::test::tuned_axis(period_s); }

}  // namespace

TEST(CardGroupGe, LineInPulsePerMsWithOffsetsAndClamp) {
  // 1 ms servo period: the generator's cycle is 1 ms. A 30000-pulse line at a feed of 300 clamped to MaxVel 100
  // with acceleration 1 from StrtVel 0.5: 2 ramps of 99.5 ms plus (30000 - 9999.75) / 100 ms of cruise.
  mc::Card c(4, axis_cfg(1e-3));
  for (std::size_t i = 0; i < 4; ++i) c.axis_on(i);
  gg::GeCrdSetup s;
  s.offsets = {1000, -500};
  s.max_vel = 100;
  gg::ge_crd_setup(c, s);
  EXPECT_TRUE(gg::ge_crd_exists(c));
  EXPECT_EQ(c.state(3).mode, mc::AxisMode::Coordinated);
  sm::PathGenerator& g = gg::ge_path(c);
  EXPECT_DOUBLE_EQ(g.setup().cycle_ms, 1.0);
  EXPECT_DOUBLE_EQ(g.state().pos[0], -1000.0);  // work coordinate = axis - offset
  g.push_segment(sm::PathSegmentGeometry::line(g.tail(), {29000, 500, 0, 0}, 4), 300, 1, 0, false, false, true);
  c.modes().before_group_start(gg::kGeCrdSlot);
  g.start();
  c.run(2);
  EXPECT_GE(g.state().speed, 0.5);
  c.run(150);
  EXPECT_DOUBLE_EQ(g.state().speed, 100.0);
  c.run(240);
  EXPECT_TRUE(g.busy());
  c.run(10);
  EXPECT_FALSE(g.busy());
  EXPECT_EQ(c.profile_pos(0), 30000);
  EXPECT_EQ(c.profile_pos(1), 0);
  // refused while it moves; rebuilt at rest at the new positions
  g.push_segment(sm::PathSegmentGeometry::line(g.tail(), {0, 500, 0, 0}, 4), 50, 1, 0, false, false, true);
  c.modes().before_group_start(gg::kGeCrdSlot);
  g.start();
  c.run(5);
  EXPECT_THROW(gg::ge_crd_setup(c, s), mc::CardCommandRefused);
  gg::GeCrdSetup bad;
  bad.max_vel = 0;
  EXPECT_THROW(gg::ge_crd_setup(c, bad), std::invalid_argument);
}

TEST(CardGroupGe, NotSetUpIsRefused) {
  mc::Card c(4, axis_cfg(200e-6));
  EXPECT_FALSE(gg::ge_crd_exists(c));
  EXPECT_THROW(gg::ge_path(c), mc::CardCommandRefused);
  EXPECT_EQ(c.last_fault(), mc::CommandFault::CrdStateError);
}
