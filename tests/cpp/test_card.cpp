// The virtual card: staged/active registers with Update/MltiUpdt, the GT status words, safety.
// Manual lines: GT seed 000 (digest gt.md).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "card_fixtures.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
namespace va = servobench::vendor::adlink;
namespace sm = servobench::motion;

namespace {

using servobench::test::tuned_axis;
using servobench::test::t_move;

constexpr double kRadPerPulse = 2 * M_PI / 10000;

std::uint32_t ev(mc::CardEvent e) { return mc::event_bit(e); }

}  // namespace

TEST(Card, ConstructionAndCyclesAreValidated) {
  EXPECT_THROW(mc::Card(5, tuned_axis()), std::invalid_argument);
  mc::CardCycles bad;
  bad.motion_cycle_ticks = 4;
  bad.host_cycle_ticks = 6;  // not a multiple
  EXPECT_THROW(mc::Card(4, tuned_axis(), bad), std::invalid_argument);
  mc::Card eight(8, tuned_axis());
  EXPECT_EQ(eight.axis_count(), 8u);
  EXPECT_EQ(eight.servo_period_s(), 200e-6);
  // given axes must share one servo clock
  mc::AxisConfig other = tuned_axis();
  other.servo_period_s = 400e-6;
  mc::Axis a(tuned_axis()), b(tuned_axis()), c(tuned_axis()), d(other);
  EXPECT_THROW(mc::Card({&a, &b, &c, &d}), std::invalid_argument);
  EXPECT_THROW(mc::Card({&a, &b, &c, &c}), std::invalid_argument);
}

TEST(Card, StagedRegistersWaitForUpdateAndCommitAtTheNextTick) {
  // GT L1156: after the update the controller copies the staged registers at the next sample time.
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  c.stage_acc(0, 0.1);
  c.stage_vel(0, 2);
  c.stage_pos(0, 1000);
  EXPECT_EQ(c.state(0).staged.pos, 1000);
  EXPECT_EQ(c.state(0).active.pos, 0);
  c.run(10);
  EXPECT_FALSE(c.moving(0));  // nothing happens without an update
  EXPECT_EQ(c.profile_pos(0), 0);
  c.update(1);
  EXPECT_TRUE(c.state(0).commit_pending);
  EXPECT_EQ(c.state(0).active.pos, 0);  // not yet
  c.run(1);
  EXPECT_EQ(c.state(0).active.pos, 1000);
  EXPECT_TRUE(c.moving(0));
  EXPECT_NEAR(c.profile_vel(0), 0.1, 1e-12);  // the first tick of the ramp ran in the commit tick
  c.run(2000);
  EXPECT_FALSE(c.moving(0));
  EXPECT_EQ(c.profile_pos(0), 1000);
  EXPECT_TRUE(c.events(0) & ev(mc::CardEvent::MotionComplete));
  EXPECT_NEAR(c.actual_pos(0), 1000, 2);
}

TEST(Card, MultiUpdateStartsTheMaskedAxesInTheSameTick) {
  // GT TV16/TV43 (L1200-1229, L4276-4310): MltiUpdt(0x6) starts axes 2 and 3 in the same sample.
  mc::Card c(4, tuned_axis());
  for (std::size_t i = 0; i < 4; ++i) c.axis_on(i);
  for (std::size_t i : {0u, 1u, 2u}) {
    c.stage_acc(i, 0.01);
    c.stage_vel(i, 1);
    c.stage_pos(i, 20000);
  }
  c.update(0x6);
  for (int k = 0; k < 150; ++k) {
    c.run(1);
    EXPECT_EQ(c.profile_pos(1), c.profile_pos(2));
    EXPECT_EQ(c.profile_vel(1), c.profile_vel(2));
  }
  EXPECT_FALSE(c.moving(0));  // staged but not in the mask
  EXPECT_EQ(c.state(0).active.pos, 0);
  // a kp change on axes 1 and 3 takes effect in one sample (TV17, L4300-4308)
  auto law = std::get<servobench::control::GtServoLawParams>(c.state(0).staged.law);
  law.kp = 10;
  c.stage_law(0, law);
  law.kp = 15;
  c.stage_law(2, law);
  c.update(0x5);
  EXPECT_NE(std::get<servobench::control::GtServoLawParams>(c.axis(0).config().law).kp, 10);
  c.run(1);
  EXPECT_EQ(std::get<servobench::control::GtServoLawParams>(c.axis(0).config().law).kp, 10);
  EXPECT_EQ(std::get<servobench::control::GtServoLawParams>(c.axis(2).config().law).kp, 15);
}

TEST(Card, RefusedUpdateCommitsNothingAndRecordsTheCause) {
  // GT L474, TV46: S-curve + SetVel + Update while moving -> rtn 1, command status bit 11.
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  c.set_mode(0, mc::AxisMode::SCurve);
  c.stage_vel(0, 2);
  c.stage_macc(0, 0.01);
  c.stage_jerk(0, 0.001);
  c.stage_pos(0, 5000);
  c.update(1);
  c.run(100);
  ASSERT_TRUE(c.moving(0));
  // axis 2 staged too: the refused MltiUpdt must not commit it either
  t_move(c, 1, 100, 1, 0.1);
  c.run(1);
  c.stage_pos(1, 300);
  c.stage_vel(0, 3);
  try {
    c.update(0x3);
    FAIL() << "expected a refusal";
  } catch (const mc::CardCommandRefused& e) {
    EXPECT_EQ(e.fault(), mc::CommandFault::ChangeInMotion);
    EXPECT_EQ(e.axis(), 0);
  }
  EXPECT_EQ(vg::gt_command_status(c), 1u << 11);
  EXPECT_TRUE(vg::gt_axis_status(c, 0) & 0x80);  // bit 7: command error
  EXPECT_EQ(c.state(0).active.vel, 2);
  EXPECT_EQ(c.state(0).staged.vel, 3);
  EXPECT_FALSE(c.state(1).commit_pending);
  EXPECT_EQ(c.state(1).active.pos, 100);
  // only the target may change during an S-curve move (GT L909)
  c.stage_vel(0, 2);
  c.stage_pos(0, 8000);
  c.update(1);
  c.run(1);
  EXPECT_EQ(c.state(0).active.pos, 8000);
  // mode change while moving: bit 6 (L464)
  EXPECT_THROW(c.set_mode(0, mc::AxisMode::TCurve), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 6);
  EXPECT_EQ(c.state(0).mode, mc::AxisMode::SCurve);
  // MltiUpdt(0): bit 2 (L460)
  EXPECT_THROW(c.update(0), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 2);
  // ZeroPos while moving: bit 11 (L1421)
  EXPECT_THROW(c.zero_pos(0), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 11);
}

TEST(GtStatus, StateBitsOfTable4_14AndTheModeRegister) {
  // GT Table 4-14 (L1439-1464) and 4-15 (L1493-1511).
  mc::Card c(4, tuned_axis());
  // axis 3 after power-on: closed loop (8), limits on (11), axis number 10b (12-13), nothing else
  EXPECT_EQ(vg::gt_axis_status(c, 2), 0x0100 | 0x0800 | 0x2000);
  EXPECT_EQ(vg::gt_axis_status(c, 3) & 0x3000, 0x3000);
  c.axis_on(2);  // bit 9, and AxisOn sets motion complete (L1481)
  EXPECT_EQ(vg::gt_axis_status(c, 2) & 0x0201, 0x0201);
  c.set_closed_loop(2, false);
  EXPECT_FALSE(vg::gt_axis_status(c, 2) & 0x0100);
  c.set_closed_loop(2, true);
  c.arm_capture(2, mc::CaptureTrigger::Home);
  EXPECT_TRUE(vg::gt_axis_status(c, 2) & 0x4000);
  EXPECT_THROW(c.arm_capture(2, mc::CaptureTrigger::Home), mc::CardCommandRefused);  // L465-471: bit 8
  EXPECT_EQ(vg::gt_command_status(c), 1u << 8);
  c.arm_capture(2, mc::CaptureTrigger::None);
  c.arm_capture(2, mc::CaptureTrigger::Index);
  EXPECT_EQ(vg::gt_axis_status(c, 2) & 0xC000, 0x8000);
  EXPECT_THROW(c.arm_capture(2, mc::CaptureTrigger::Index), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 7);
  mc::LimitConfig lim;
  lim.enabled = false;
  c.set_limits(2, lim);
  EXPECT_FALSE(vg::gt_axis_status(c, 2) & 0x0800);
  // bit 10 while the profile moves
  c.set_mode(2, mc::AxisMode::Jog);
  c.stage_acc(2, 0.1);
  c.stage_vel(2, 1);
  c.update(1u << 2);
  c.run(2);
  EXPECT_TRUE(vg::gt_axis_status(c, 2) & 0x0400);
  // mode register: jog = 001 in bits 11-13; AuStp bit 7; AuUpdt bit 10
  EXPECT_EQ(vg::gt_mode_register(c, 2), 1u << 11);
  c.set_auto_stop(2, true);
  c.set_auto_update(2, true);
  EXPECT_EQ(vg::gt_mode_register(c, 2), (1u << 11) | (1u << 7) | (1u << 10));
  // RstSts(0xff7f) clears bit 7 only; the state bits stay (L1468, L4557-4569)
  const auto before = vg::gt_axis_status(c, 2);
  ASSERT_TRUE(before & 0x80);
  c.clear_events(2, vg::gt_events_to_clear(0xff7f));
  EXPECT_EQ(vg::gt_axis_status(c, 2), before & ~0x80);
}

TEST(CardSafety, HardLimitStopsLatchesAndInhibitsTheDirection) {
  // GT L2196-2213: stop at once, bit 5, only the opposite direction until ClrSts after leaving.
  mc::AxisConfig cfg = tuned_axis();
  cfg.switches.pos_limit_rad = 3000 * kRadPerPulse;
  mc::Card c(4, cfg);
  c.axis_on(0);
  c.clear_events(0, mc::kAllEvents);
  t_move(c, 0, 10000, 4, 0.1);
  c.run(3000);
  EXPECT_FALSE(c.moving(0));
  const auto sts = vg::gt_axis_status(c, 0);
  EXPECT_TRUE(sts & 0x20);
  EXPECT_TRUE(sts & 0x01);  // the limit sets motion complete (L1478)
  EXPECT_EQ(c.state(0).stop_cause, mc::StopCause::PosLimit);
  EXPECT_LT(c.profile_pos(0), 3100);
  EXPECT_GE(c.actual_pos(0), 3000);
  // further + motion refused, and nothing committed
  c.stage_pos(0, 6000);
  EXPECT_THROW(c.update(1), mc::CardCommandRefused);
  EXPECT_EQ(c.state(0).active.pos, 10000);
  // clearing while still on the switch: it latches again at the next tick
  c.clear_events(0, vg::gt_events_to_clear(0xffdf));
  c.run(1);
  EXPECT_TRUE(vg::gt_axis_status(c, 0) & 0x20);
  // moving away is allowed (TV27, L2866-2880)
  c.stage_pos(0, 0);
  c.update(1);
  c.run(3000);
  EXPECT_LT(c.actual_pos(0), 2990);
  c.clear_events(0, vg::gt_events_to_clear(0xff9f));  // TV4 mask: clears bits 5 and 6
  c.run(1);
  EXPECT_FALSE(vg::gt_axis_status(c, 0) & 0x60);
  // limits off: the switch is ignored (GT_LmtsOff), its level still readable
  mc::LimitConfig off;
  off.enabled = false;
  c.set_limits(0, off);
  t_move(c, 0, 5000, 4, 0.1);
  c.run(3000);
  EXPECT_EQ(c.profile_pos(0), 5000);
  EXPECT_TRUE(c.pos_limit_input(0));
  EXPECT_FALSE(vg::gt_axis_status(c, 0) & 0x20);
}

TEST(CardSafety, WrongLimitSenseFlagsTheAxisAndSoftLimitsStopToo) {
  // GT L4219: a wrong LmtSns sets the limit flags; here no switch is fitted, so active-low reads "hit".
  mc::Card c(4, tuned_axis());
  mc::LimitConfig lim;
  lim.neg_active_low = true;
  c.set_limits(1, lim);
  c.run(1);
  EXPECT_TRUE(vg::gt_axis_status(c, 1) & 0x40);
  EXPECT_FALSE(vg::gt_axis_status(c, 1) & 0x20);
  // soft limit (ADLINK PRA_SPEL_*, L3983-4010) on axis 3
  mc::LimitConfig soft;
  soft.soft_pos_enabled = true;
  soft.soft_pos_pulse = 2000;
  c.set_limits(2, soft);
  c.axis_on(2);
  t_move(c, 2, 8000, 4, 0.1);
  c.run(3000);
  EXPECT_EQ(c.state(2).stop_cause, mc::StopCause::SoftPosLimit);
  EXPECT_TRUE(c.events(2) & ev(mc::CardEvent::SoftPosLimit));
  EXPECT_TRUE(vg::gt_axis_status(c, 2) & 0x20);
  EXPECT_LT(c.profile_pos(2), 2100);
}

TEST(CardSafety, FollowingErrorFlagsEveryTickAndAutoStopDisables) {
  // GT L2154-2178: compared every sample; AuStp: stop, bit 0, drive disabled. The flag clears only out of error.
  mc::AxisConfig cfg = tuned_axis();
  auto law = std::get<servobench::control::GtServoLawParams>(cfg.law);
  law.kaff = 0;
  law.kd = 0;
  law.ki = 0;
  law.kp = 2;  // a soft loop: a large lag on a fast move
  cfg.law = law;
  auto plant = std::get<servobench::plant::RigidPlantParams>(cfg.plant);
  plant.coulomb_nm = 0.05;  // so that the axis coasts to rest once disabled
  cfg.plant = plant;
  mc::Card c(4, cfg);
  c.axis_on(0);
  c.stage_pos_err(0, 50);
  c.update(1);
  c.run(1);
  c.clear_events(0, mc::kAllEvents);
  t_move(c, 0, 20000, 10, 0.5);
  std::vector<double> err(400), events(400);
  std::vector<mc::CardTrace> tr(4);
  tr[0].axis.error = err.data();
  tr[0].events = events.data();
  c.run(400, tr);
  std::size_t first = 0;
  while (first < err.size() && std::fabs(err[first]) <= 50) ++first;
  ASSERT_LT(first, err.size());
  EXPECT_FALSE(static_cast<unsigned>(events[first - 1]) & ev(mc::CardEvent::FollowingError));
  EXPECT_TRUE(static_cast<unsigned>(events[first]) & ev(mc::CardEvent::FollowingError));
  EXPECT_TRUE(c.servo_on(0));  // flag only by default (L2167)
  EXPECT_TRUE(c.moving(0));
  c.clear_events(0, ev(mc::CardEvent::FollowingError));
  EXPECT_TRUE(c.events(0) & ev(mc::CardEvent::FollowingError));  // still in error: stays (L1453)
  // auto-stop on
  c.set_auto_stop(0, true);
  c.clear_events(0, ev(mc::CardEvent::MotionComplete));
  c.run(1);
  EXPECT_FALSE(c.servo_on(0));
  EXPECT_FALSE(c.moving(0));
  EXPECT_TRUE(c.events(0) & ev(mc::CardEvent::MotionComplete));
  EXPECT_EQ(c.state(0).stop_cause, mc::StopCause::FollowingError);
  // recovery (L2171-2178): clear bit 4, SynchPos, AxisOn
  c.clear_events(0, ev(mc::CardEvent::FollowingError));
  EXPECT_FALSE(c.events(0) & ev(mc::CardEvent::FollowingError));
  c.run(2000);  // let the axis coast to rest
  EXPECT_NEAR(c.axis(0).speed_rad_s(), 0.0, 1e-9);
  c.stage_synch_pos(0);
  c.update(1);
  c.run(1);
  EXPECT_EQ(c.profile_pos(0), std::nearbyint(c.actual_pos(0)));
  EXPECT_EQ(c.state(0).staged.pos, c.profile_pos(0));
  c.axis_on(0);
  c.run(50);
  EXPECT_LT(std::fabs(c.following_error(0)), 50);
  EXPECT_FALSE(c.events(0) & ev(mc::CardEvent::FollowingError));
}

TEST(CardSafety, DriveAlarmDisablesAndTheResetSequenceRecovers) {
  // GT L2180-2194: bits 1 and 0, disabled; DrvRst only disabled (cmd bit 3); AxisOn refused with bit 1 (cmd bit 9).
  mc::Card c(4, tuned_axis());
  c.axis_on(1);
  EXPECT_THROW(c.drive_reset(1), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 3);
  c.clear_events(1, mc::kAllEvents);
  t_move(c, 1, 5000, 2, 0.1);
  c.run(100);
  c.set_alarm_input(1, true);
  c.run(1);
  EXPECT_EQ(vg::gt_axis_status(c, 1) & 0x0203, 0x0003);
  EXPECT_FALSE(c.moving(1));
  EXPECT_THROW(c.axis_on(1), mc::CardCommandRefused);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 9);
  c.set_alarm_input(1, false);  // the cause fixed
  c.drive_reset(1);
  c.clear_events(1, vg::gt_events_to_clear(0xfffd));  // TV26: clears bit 1 only
  EXPECT_FALSE(c.events(1) & ev(mc::CardEvent::DriveAlarm));
  c.run(300);
  c.stage_synch_pos(1);
  c.update(2);
  c.run(1);
  c.axis_on(1);
  EXPECT_TRUE(c.servo_on(1));
  // the drive's own alarm (TorqueDrive alarm_at_s) and its reset through DrvRst
  mc::AxisConfig cfg = tuned_axis();
  servobench::drive::TorqueDriveParams drive;
  drive.alarm_at_s = 0.01;
  cfg.drive = drive;
  mc::Card d(4, cfg);
  d.axis_on(0);
  d.run(100);
  EXPECT_TRUE(d.events(0) & ev(mc::CardEvent::DriveAlarm));
  EXPECT_FALSE(d.servo_on(0));
  d.drive_reset(0);
  d.clear_events(0, mc::kAllEvents);
  d.run(10);
  EXPECT_FALSE(d.events(0) & ev(mc::CardEvent::DriveAlarm));
  EXPECT_FALSE(d.axis(0).alarm());
}

TEST(CardSafety, EmergencyStopAndErrorLevelServoOff) {
  mc::Card c(4, tuned_axis());
  for (std::size_t i = 0; i < 4; ++i) c.axis_on(i);
  t_move(c, 0, 20000, 5, 0.1);
  t_move(c, 1, -20000, 5, 0.1);
  c.run(200);
  c.set_emergency_stop(true);
  c.run(1);
  EXPECT_FALSE(c.moving(0));
  EXPECT_FALSE(c.moving(1));
  EXPECT_EQ(c.state(0).stop_cause, mc::StopCause::EmergencyStop);
  EXPECT_TRUE(c.events(1) & ev(mc::CardEvent::EmergencyStop));
  c.stage_pos(2, 100);
  c.stage_vel(2, 1);
  c.stage_acc(2, 0.1);
  EXPECT_THROW(c.update(4), mc::CardCommandRefused);  // ignored while active (ADLINK L3924-3938)
  c.set_emergency_stop(false);
  c.update(4);
  // ADLINK ERR_POS_LEVEL: servo off when |E| exceeds the level (L4012-4023)
  va::adlink(c).set_error_level(3, 5);
  c.set_mtr_cmd(3, 0);
  t_move(c, 3, 20000, 20, 1);
  c.run(100);
  EXPECT_FALSE(c.servo_on(3));
  EXPECT_EQ(c.state(3).stop_cause, mc::StopCause::ErrorLevel);
  EXPECT_TRUE(c.events(3) & ev(mc::CardEvent::ErrorLevel));
}

TEST(Card, BreakpointAutoUpdateCommitsTheStagedRegisters) {
  // GT TV18 (L1265-1295): at actual >= BrkCn, bit 2 and the staged velocity takes effect.
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  c.stage_vel(0, 1);
  c.stage_acc(0, 0.1);
  c.stage_pos(0, 50000);
  c.set_auto_update(0, true);
  c.stage_brk_cn(0, 20000);
  c.update(1);
  c.run(1);
  c.arm_breakpoint(0, sm::BreakKind::PositionAbove);
  c.stage_vel(0, 4);
  c.run(19000);
  EXPECT_FALSE(c.events(0) & ev(mc::CardEvent::Breakpoint));
  EXPECT_NEAR(c.profile_vel(0), 1, 1e-12);
  c.run(2000);
  EXPECT_TRUE(c.events(0) & ev(mc::CardEvent::Breakpoint));
  EXPECT_EQ(c.state(0).active.vel, 4);
  EXPECT_NEAR(c.profile_vel(0), 4, 1e-12);
}

TEST(Card, OpenLoopOutputsTheHostCommand) {
  // GT L778, L4960-4966: open loop, the output is GT_SetMtrCmd; the law is not evaluated.
  mc::Card c(4, tuned_axis());
  c.set_closed_loop(0, false);
  c.set_mtr_cmd(0, 3276.7);
  c.axis_on(0);
  std::vector<double> volts(5);
  std::vector<mc::CardTrace> tr(4);
  tr[0].axis.volts = volts.data();
  c.run(5, tr);
  EXPECT_NEAR(volts[4], 1.0, 1e-3);
  EXPECT_THROW(c.set_mtr_cmd(0, 40000), std::invalid_argument);
  EXPECT_EQ(vg::gt_command_status(c), 1u << 1);
}
