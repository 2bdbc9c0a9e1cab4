// The ADLINK status words (motion status MSTS, motion I/O MIO, stop codes) as functions of the Card state.
// Manual lines: ADLINK seed 004 (digest adlink.md §7).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace va = servobench::vendor::adlink;
namespace sm = servobench::motion;
using servobench::test::aps_axis;

namespace {

constexpr double kRadPerPulse = 2 * M_PI / 10000;

sm::AdlinkPtpParams ptp(double pos) {
  sm::AdlinkPtpParams p;
  p.pos = pos;
  p.vm = 40000;   // pulse/s
  p.acc = 4e5;    // pulse/s^2
  p.dec = 4e5;
  return p;
}

bool has(std::uint32_t w, va::ApsMsts b) { return w & (1u << static_cast<int>(b)); }
bool has(std::uint32_t w, va::ApsMio b) { return w & (1u << static_cast<int>(b)); }

}  // namespace

TEST(ApsStatus, AtRestAfterPowerOn) {
  mc::Card c(4, aps_axis());
  const auto m = va::aps_motion_status(c, 0);
  EXPECT_EQ(m, (1u << 0) | (1u << 5));  // CSTP and MDN only; DIR 0 (no motion yet)
  EXPECT_EQ(va::aps_stop_code(c, 0), 0);
  EXPECT_EQ(va::aps_motion_io_status(c, 0), 0u);  // servo off: no SVON, no INP
  c.axis_on(0);
  c.run(2);
  const auto io = va::aps_motion_io_status(c, 0);
  EXPECT_TRUE(has(io, va::ApsMio::SVON));
  EXPECT_TRUE(has(io, va::ApsMio::INP));
}

TEST(ApsStatus, AccelerationCruiseDecelerationDirectionAndDone) {
  // L3164-3218: ACC, VM, DEC while moving; DIR kept after the stop; MDN and CSTP at the end.
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  va::adlink(c).move_ptp(0, ptp(20000));  // 0.1 s ramps (400 ticks of 250 us), 0.4 s cruise: DEC over ticks 2000-2400
  c.run(100);
  auto m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::ACC));
  EXPECT_FALSE(has(m, va::ApsMsts::VM) || has(m, va::ApsMsts::DEC) || has(m, va::ApsMsts::MDN) ||
               has(m, va::ApsMsts::CSTP));
  EXPECT_TRUE(has(m, va::ApsMsts::DIR));
  EXPECT_FALSE(has(va::aps_motion_io_status(c, 0), va::ApsMio::INP));  // moving: not in position
  c.run(800);
  m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::VM));
  EXPECT_FALSE(has(m, va::ApsMsts::ACC) || has(m, va::ApsMsts::DEC));
  c.run(1200);  // tick 2100: decelerating
  m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::DEC));
  c.run(1000);
  m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::MDN) && has(m, va::ApsMsts::CSTP) && has(m, va::ApsMsts::DIR));
  EXPECT_FALSE(has(m, va::ApsMsts::ASTP));
  EXPECT_EQ(c.profile_pos(0), 20000);
  // a negative move: DIR 0, kept after the stop
  va::adlink(c).move_ptp(0, ptp(10000));
  c.run(3000);
  m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::MDN));
  EXPECT_FALSE(has(m, va::ApsMsts::DIR));
}

TEST(ApsStatus, StopCodesOfEachCause) {
  // L3922-4023: EMG 1, ALM 2, PEL 4, MEL 5, SPEL 6, SMEL 7, ERR_POS_LEVEL 13 (V41), with ASTP and MDN.
  mc::AxisConfig cfg = aps_axis();
  cfg.switches.pos_limit_rad = 3000 * kRadPerPulse;
  cfg.switches.neg_limit_rad = -3000 * kRadPerPulse;
  mc::Card c(4, cfg);
  for (std::size_t i = 0; i < 4; ++i) c.axis_on(i);
  va::adlink(c).move_ptp(0, ptp(10000));
  va::adlink(c).move_ptp(1, ptp(-10000));
  mc::LimitConfig soft;
  soft.soft_pos_enabled = soft.soft_neg_enabled = true;
  soft.soft_pos_pulse = 2000;
  soft.soft_neg_pulse = -2000;
  c.set_limits(2, soft);
  va::adlink(c).move_ptp(2, ptp(5000));
  c.set_limits(3, soft);
  va::adlink(c).move_ptp(3, ptp(-5000));
  c.run(3000);
  const int expect[4] = {4, 5, 6, 7};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto m = va::aps_motion_status(c, i);
    EXPECT_EQ(va::aps_stop_code(c, i), expect[i]) << "axis " << i;
    EXPECT_TRUE(has(m, va::ApsMsts::ASTP) && has(m, va::ApsMsts::MDN)) << "axis " << i;
  }
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 0), va::ApsMio::PEL));
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 1), va::ApsMio::MEL));
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 2), va::ApsMio::SPEL));
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 3), va::ApsMio::SMEL));
  // while the limit is active a move toward it is ignored, a move away is accepted and clears ASTP (L3971-3973)
  EXPECT_THROW(va::adlink(c).move_ptp(0, ptp(9000)), mc::CardCommandRefused);
  EXPECT_EQ(va::aps_stop_code(c, 0), 4);
  va::adlink(c).move_ptp(0, ptp(0));
  EXPECT_FALSE(has(va::aps_motion_status(c, 0), va::ApsMsts::ASTP));
  EXPECT_EQ(va::aps_stop_code(c, 0), 0);
  // EMG: moving axes stop at once (code 1); idle axes ignore motion and get code 1 (L3931-3936)
  c.run(10);
  c.set_emergency_stop(true);
  c.run(1);
  EXPECT_EQ(va::aps_stop_code(c, 0), 1);
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 0), va::ApsMio::EMG));
  EXPECT_THROW(va::adlink(c).move_ptp(1, ptp(0)), mc::CardCommandRefused);
  EXPECT_EQ(va::aps_stop_code(c, 1), 1);
  c.set_emergency_stop(false);
  // ALM input: motion ignored with code 2 (L3950-3953); ALM bit in the I/O word
  c.set_alarm_input(2, true);
  c.run(1);
  EXPECT_TRUE(has(va::aps_motion_io_status(c, 2), va::ApsMio::ALM));
  EXPECT_FALSE(has(va::aps_motion_io_status(c, 2), va::ApsMio::SVON));
  EXPECT_EQ(va::aps_stop_code(c, 2), 2);
  EXPECT_THROW(va::adlink(c).move_ptp(2, ptp(0)), mc::CardCommandRefused);
  // ERR_POS_LEVEL: servo off, code 13, ASTP (L4012-4023)
  mc::Card d(4, aps_axis());
  d.axis_on(0);
  va::adlink(d).set_error_level(0, 3);
  sm::AdlinkPtpParams fast = ptp(50000);
  fast.vm = 400000;
  fast.acc = fast.dec = 4e8;
  va::adlink(d).move_ptp(0, fast);
  d.run(200);
  EXPECT_FALSE(d.servo_on(0));
  EXPECT_EQ(va::aps_stop_code(d, 0), 13);
  EXPECT_TRUE(has(va::aps_motion_status(d, 0), va::ApsMsts::ASTP));
  EXPECT_FALSE(has(va::aps_motion_io_status(d, 0), va::ApsMio::SVON));
}

TEST(ApsStatus, StopCodeTable) {
  EXPECT_EQ(va::aps_stop_code(mc::StopCause::None), 0);
  EXPECT_EQ(va::aps_stop_code(mc::StopCause::EmergencyStop), 1);
  EXPECT_EQ(va::aps_stop_code(mc::StopCause::DriveAlarm), 2);
  EXPECT_EQ(va::aps_stop_code(mc::StopCause::FollowingError), 3);
  EXPECT_EQ(va::aps_stop_code(mc::StopCause::ErrorLevel), 13);
}

TEST(ApsStatus, StopMoveDeceleratesAtSdDecAsANormalStop) {
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  sm::AdlinkPtpParams p = ptp(0);
  p.sd_dec = 2e5;  // half the DEC: the stop takes 0.2 s from 40000 pulse/s (800 ticks)
  va::adlink(c).move_velocity(0, 40000, p);
  c.run(1000);
  EXPECT_TRUE(has(va::aps_motion_status(c, 0), va::ApsMsts::VM));
  va::adlink(c).stop_move(0, p);
  c.run(790);
  EXPECT_TRUE(has(va::aps_motion_status(c, 0), va::ApsMsts::DEC));
  c.run(20);
  const auto m = va::aps_motion_status(c, 0);
  EXPECT_TRUE(has(m, va::ApsMsts::MDN));
  EXPECT_FALSE(has(m, va::ApsMsts::ASTP));  // a user stop is a normal stop (V45)
}
