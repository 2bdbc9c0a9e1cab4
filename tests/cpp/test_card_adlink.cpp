// The card's ADLINK-side machinery: moves waiting for a trigger, the limit stop mode, pre/post-distance events,
// homing on the card. Manual lines: ADLINK seed 004 (digest adlink.md §6.3-6.8).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace va = servobench::vendor::adlink;
using servobench::test::aps_axis;
namespace sm = servobench::motion;

namespace {

sm::AdlinkPtpParams ptp(double pos, double vm = 40000) {
  sm::AdlinkPtpParams p;
  p.pos = pos;
  p.vm = vm;
  p.acc = p.dec = 4e5;
  return p;
}

bool msts(const mc::Card& c, std::size_t i, va::ApsMsts b) {
  return (va::aps_motion_status(c, i) >> static_cast<int>(b)) & 1u;
}

}  // namespace

TEST(CardAdlink, WaitingMovesStartTogetherAtTheTrigger) {
  // L3781-3790: two axes wait (MTS WAIT), APS_move_trigger starts both in the same tick.
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  c.axis_on(1);
  va::adlink(c).move_ptp_wait(0, ptp(10000));
  va::adlink(c).move_ptp_wait(1, ptp(20000));
  c.run(50);
  EXPECT_TRUE(msts(c, 0, va::ApsMsts::WAIT) && msts(c, 1, va::ApsMsts::WAIT));
  EXPECT_FALSE(c.moving(0) || c.moving(1));
  va::adlink(c).move_trigger(0b11);
  EXPECT_FALSE(va::adlink(c).waiting_trigger(0) || va::adlink(c).waiting_trigger(1));
  c.run(1);
  EXPECT_TRUE(c.moving(0) && c.moving(1));
  EXPECT_DOUBLE_EQ(c.profile_vel(0), c.profile_vel(1));  // same ACC, same first tick
  c.run(4000);
  EXPECT_EQ(c.profile_pos(0), 10000);
  EXPECT_EQ(c.profile_pos(1), 20000);
  EXPECT_THROW(va::adlink(c).move_trigger(0), std::invalid_argument);
  EXPECT_THROW(va::adlink(c).move_trigger(1u << 4), std::invalid_argument);
}

TEST(CardAdlink, LimitStopDeceleratesWithElMode) {
  // PRA_EL_MODE 1 (L3994): the soft limit stops at PRA_SD_DEC: overshoot v^2 / (2 dec).
  for (bool decelerate : {false, true}) {
    mc::Card c(4, aps_axis());
    c.axis_on(0);
    mc::LimitConfig lim;
    lim.soft_pos_enabled = true;
    lim.soft_pos_pulse = 20000;
    c.set_limits(0, lim);
    va::adlink(c).set_limit_stop_mode(0, decelerate, 2e6);
    va::adlink(c).move_velocity(0, 100000, ptp(0, 100000));
    c.run(8000);
    EXPECT_FALSE(c.moving(0));
    EXPECT_EQ(c.state(0).stop_cause, mc::StopCause::SoftPosLimit);
    const double over = static_cast<double>(c.profile_pos(0)) - 20000;
    if (decelerate) {
      EXPECT_NEAR(over, 2500, 60);
    } else {
      EXPECT_LT(over, 100);
    }
  }
  mc::Card c(4, aps_axis());
  EXPECT_THROW(va::adlink(c).set_limit_stop_mode(0, true, 0.0), std::invalid_argument);
}

TEST(CardAdlink, PreAndPostDistanceEvents) {
  // L3284-3292: PRED after 2000 pulse travelled, POSTD with less than 1000 remaining; cleared at the next start.
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  va::adlink(c).set_move_event_distances(0, 2000, 1000);
  va::adlink(c).move_ptp(0, ptp(10000));
  bool pred_seen_early = false;
  for (int k = 0; k < 3000; ++k) {
    c.run(1);
    const double p = static_cast<double>(c.profile_pos(0));
    if (msts(c, 0, va::ApsMsts::PRED) && p < 2000) pred_seen_early = true;
    if (msts(c, 0, va::ApsMsts::POSTD)) {
      EXPECT_GT(p, 9000);
    }
  }
  EXPECT_FALSE(pred_seen_early);
  EXPECT_TRUE(msts(c, 0, va::ApsMsts::PRED) && msts(c, 0, va::ApsMsts::POSTD));
  va::adlink(c).move_ptp(0, ptp(0));
  EXPECT_FALSE(msts(c, 0, va::ApsMsts::PRED) || msts(c, 0, va::ApsMsts::POSTD));
  EXPECT_THROW(va::adlink(c).set_move_event_distances(0, -1, 0), std::invalid_argument);
}

TEST(CardAdlink, StopMoveDuringHomingDecelerates) {
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  sm::AdlinkHomeParams h;
  h.dir = 0;  // no switches on this axis: the search runs at VM until stopped
  va::adlink(c).home(0, h);
  EXPECT_TRUE(msts(c, 0, va::ApsMsts::HMV));
  c.run(400);
  const double v = c.profile_vel(0) / 250e-6;
  EXPECT_NEAR(v, 1e5, 1e-3);
  const double start = static_cast<double>(c.profile_pos(0));
  sm::AdlinkPtpParams stop = ptp(0);
  stop.sd_dec = 1e6;
  va::adlink(c).stop_move(0, stop);
  EXPECT_FALSE(msts(c, 0, va::ApsMsts::HMV));
  c.run(2000);
  EXPECT_FALSE(c.moving(0));
  EXPECT_NEAR(static_cast<double>(c.profile_pos(0)) - start, 5000, 30);  // v^2 / (2 SD_DEC)
}
