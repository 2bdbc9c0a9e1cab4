// The GE series' status words (PX/SX axis status, PX mode register, command-error registers) as functions of
// the Card state, one test per documented condition. Manual lines: GE seed 001 (digest ge.md §1.5, §3.4, §5.7).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "servobench/machine/card.hpp"
#include "card_fixtures.hpp"
#include "servobench/vendor/googol/ge_status.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;

namespace {

inline mc::AxisConfig ge_axis() { return servobench::test::tuned_axis(); }
using servobench::test::t_move;

constexpr double kRadPerPulse = 2 * M_PI / 10000;

constexpr std::uint32_t bit(int b) { return 1u << b; }

}  // namespace

TEST(GeStatus, PowerOnWordsPxAndSx) {
  // Table 4-3 L902-932 / Table 4-2 L879-900: closed loop (8) and limits on (11) by default; servo off, idle.
  mc::Card c(8, ge_axis());
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(vg::ge_px_axis_status(c, i), bit(8) | bit(11) | (static_cast<std::uint32_t>(i) << 28)) << i;
  }
  mc::Card s(4, ge_axis());
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(vg::ge_sx_axis_status(s, i), bit(11) | (i << 12)) << i;  // SX bit 8 reserved
  }
  EXPECT_EQ(vg::ge_mode_register(c, 0), 0u);  // Table 4-4: trapezoid 000, auto-stop off
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), 0u);
}

TEST(GeStatus, AxisNumberFieldsL928AndL896) {
  // PX bits 30:28 = axis - 1 (000 axis 1 ... 111 axis 8); SX bits 13:12 (00 axis 1, 01 axis 2, 10 axis 3).
  mc::Card c(8, ge_axis());
  EXPECT_EQ(vg::ge_px_axis_status(c, 7) >> 28 & 7u, 7u);
  EXPECT_EQ(vg::ge_px_axis_status(c, 4) >> 28 & 7u, 4u);
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & 0x80000000u, 0u);  // bit 31 reserved
  EXPECT_EQ(vg::ge_sx_axis_status(c, 2) >> 12 & 3u, 2u);
  EXPECT_EQ(vg::ge_sx_axis_status(c, 3) >> 12 & 3u, 3u);
}

TEST(GeStatus, ServoEnabledMotionAndReservedBit0) {
  mc::Card c(4, ge_axis());
  c.axis_on(0);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(9));  // bit 9 servo enabled
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & bit(0), 0u);  // bit 0 reserved even though the card latched motion complete
  t_move(c, 0, 2000, 2, 0.02);
  c.run(2);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(10));  // bit 10 motion
  EXPECT_TRUE(vg::ge_sx_axis_status(c, 0) & bit(10));
  c.run(1200);
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & bit(10), 0u);
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & (bit(0) | bit(2)), 0u);
  c.axis_off(0);
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & bit(9), 0u);
}

TEST(GeStatus, OpenLoopClearsBit8) {
  mc::Card c(4, ge_axis());
  c.set_closed_loop(1, false);  // GT_OpenLp (L5325): bit 8 = 0 open loop
  EXPECT_EQ(vg::ge_px_axis_status(c, 1) & bit(8), 0u);
  c.set_closed_loop(1, true);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 1) & bit(8));
}

TEST(GeStatus, LimitsEnabledAndTriggered) {
  mc::AxisConfig cfg = ge_axis();
  cfg.switches.pos_limit_rad = 1000 * kRadPerPulse;
  cfg.switches.neg_limit_rad = -1000 * kRadPerPulse;
  mc::Card c(4, cfg);
  c.axis_on(0);
  c.axis_on(1);
  t_move(c, 0, 5000, 2, 0.02);
  t_move(c, 1, -5000, 2, 0.02);
  c.run(1500);
  const auto px0 = vg::ge_px_axis_status(c, 0), px1 = vg::ge_px_axis_status(c, 1);
  EXPECT_TRUE(px0 & bit(5));  // bit 5 positive limit triggered (L2381-2388)
  EXPECT_FALSE(px0 & bit(6));
  EXPECT_TRUE(px1 & bit(6));  // bit 6 negative limit triggered
  EXPECT_FALSE(px1 & bit(5));
  EXPECT_TRUE(vg::ge_sx_axis_status(c, 0) & bit(5));
  // bit 11: limits enabled (GT_LmtsOn default; LmtsOff clears it, L4921-4944)
  mc::LimitConfig off = c.state(2).limits;
  off.enabled = false;
  c.set_limits(2, off);
  EXPECT_EQ(vg::ge_px_axis_status(c, 2) & bit(11), 0u);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 3) & bit(11));
}

TEST(GeStatus, DriveAlarmBit1) {
  mc::Card c(4, ge_axis());
  c.axis_on(0);
  c.set_alarm_input(0, true);
  c.run(1);
  const auto w = vg::ge_px_axis_status(c, 0);
  EXPECT_TRUE(w & bit(1));             // drive alarm (L2390-2398)
  EXPECT_EQ(w & bit(9), 0u);           // servo switched off
  EXPECT_TRUE(vg::ge_sx_axis_status(c, 0) & bit(1));
}

TEST(GeStatus, FollowingErrorBit4) {
  mc::AxisConfig cfg = ge_axis();
  mc::Card c(4, cfg);
  c.axis_on(0);
  c.stage_pos_err(0, 5);  // a 5-pulse limit: the move's lag exceeds it (L2344-2364)
  t_move(c, 0, 20000, 10, 0.5);
  c.run(100);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(4));
  EXPECT_TRUE(vg::ge_sx_axis_status(c, 0) & bit(4));
}

TEST(GeStatus, CaptureArmedAndTriggeredBits3_14_15) {
  mc::AxisConfig cfg = ge_axis();
  cfg.switches.home_min_rad = 500 * kRadPerPulse;
  cfg.switches.home_max_rad = 800 * kRadPerPulse;
  mc::Card c(4, cfg);
  c.axis_on(0);
  c.arm_capture(0, mc::CaptureTrigger::Home);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(14));  // Home capture armed (L3802-3826)
  EXPECT_FALSE(vg::ge_px_axis_status(c, 0) & bit(15));
  t_move(c, 0, 2000, 2, 0.05);
  c.run(1300);
  auto w = vg::ge_px_axis_status(c, 0);
  EXPECT_TRUE(w & bit(3));               // captured
  EXPECT_EQ(w & (bit(14) | bit(15)), 0u);  // one shot: armed bit cleared
  c.clear_events(0, vg::ge_events_to_clear(0));
  c.arm_capture(0, mc::CaptureTrigger::Index);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(15));
  EXPECT_TRUE(vg::ge_sx_axis_status(c, 0) & bit(15));
}

TEST(GeStatus, ProbeCaptureSetsBit3OnEveryAxis) {
  mc::Card c(4, ge_axis());
  c.arm_probe();  // GT_CaptProb (L3828-3862): all axes latch, bit 3 of all axes
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & (bit(14) | bit(15)), 0u);
  EXPECT_THROW(c.arm_probe(), mc::CardCommandRefused);  // armed and not triggered: cmd bit 5
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), bit(5));
  c.set_probe_time(10 * c.servo_period_s() + 1e-6);
  c.run(20);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(vg::ge_px_axis_status(c, i) & bit(3)) << i;
}

TEST(GeStatus, CommandErrorBit7PxOnlyAndEncoderAbnormalBit27) {
  mc::Card c(4, ge_axis());
  EXPECT_THROW(c.update(0), mc::CardCommandRefused);  // MltiUpdt(0): cmd bit 2, no axis
  c.axis_on(0);
  EXPECT_THROW(c.drive_reset(0), mc::CardCommandRefused);  // DrvRst with the servo on: cmd bit 3
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(7));     // axis command error (L917)
  EXPECT_EQ(vg::ge_sx_axis_status(c, 0) & bit(7), 0u);   // SX bit 7 reserved
  c.set_encoder_fault(1, true);
  EXPECT_TRUE(vg::ge_px_axis_status(c, 1) & bit(27));    // encoder abnormal (L920-921)
  EXPECT_EQ(vg::ge_px_axis_status(c, 0) & bit(27), 0u);
}

TEST(GeStatus, ModeRegisterCodesAndAutoStop) {
  // Table 4-4 L938-945: bits 13..11 000 trapezoid, 001 velocity, 010 S-curve; bit 7 auto-stop.
  mc::Card c(4, ge_axis());
  c.set_mode(0, mc::AxisMode::Jog);
  EXPECT_EQ(vg::ge_mode_register(c, 0), 0x0800u);
  c.set_mode(0, mc::AxisMode::SCurve);
  EXPECT_EQ(vg::ge_mode_register(c, 0), 0x1000u);
  c.set_mode(0, mc::AxisMode::TCurve);
  c.set_auto_stop(0, true);
  EXPECT_EQ(vg::ge_mode_register(c, 0), 0x0080u);
  c.set_auto_update(0, true);  // a GT feature: GE bit 10 is reserved
  EXPECT_EQ(vg::ge_mode_register(c, 0), 0x0080u);
}

TEST(GeStatus, CommandErrorBitsPxTable2_3) {
  using F = mc::CommandFault;
  const auto px = [](F f) { return vg::ge_command_status_bit(vg::GeVariant::PX, f); };
  EXPECT_EQ(px(F::MotionParamOverflow), bit(0));
  EXPECT_EQ(px(F::IllegalControlParam), bit(1));
  EXPECT_EQ(px(F::NoAxisInMask), bit(2));
  EXPECT_EQ(px(F::DriveResetWhileEnabled), bit(3));
  EXPECT_EQ(px(F::HomeCaptureArmed), bit(5));
  EXPECT_EQ(px(F::IndexCaptureArmed), bit(5));
  EXPECT_EQ(px(F::ModeChangeInMotion), bit(6));
  EXPECT_EQ(px(F::AxisOnWhileAlarm), bit(9));
  EXPECT_EQ(px(F::ChangeInMotion), bit(11));
  for (F f : {F::None, F::DirectionInhibited, F::NotInCommandSet, F::AxisStateError, F::MotorStateWhileEnabled,
              F::NotSimulated})
    EXPECT_EQ(px(f), 0u);
}

TEST(GeStatus, CommandErrorBitsSxTable2_4) {
  using F = mc::CommandFault;
  const auto sx = [](F f) { return vg::ge_command_status_bit(vg::GeVariant::SX, f); };
  EXPECT_EQ(sx(F::MotionParamOverflow), bit(1));  // SX bit 0 reserved: "illegal axis parameter" (bit 1)
  EXPECT_EQ(sx(F::IllegalControlParam), bit(1));
  EXPECT_EQ(sx(F::NoAxisInMask), bit(2));
  EXPECT_EQ(sx(F::DriveResetWhileEnabled), bit(3));
  EXPECT_EQ(sx(F::MotorStateWhileEnabled), bit(3));
  EXPECT_EQ(sx(F::AxisOnWhileAlarm), bit(3));
  EXPECT_EQ(sx(F::HomeCaptureArmed), bit(5));
  EXPECT_EQ(sx(F::AxisStateError), bit(6));
  EXPECT_EQ(sx(F::ChangeInMotion), bit(11));
  EXPECT_EQ(sx(F::NotInCommandSet), bit(14));
  EXPECT_EQ(sx(F::ModeChangeInMotion), 0u);
}

TEST(GeStatus, CardRefusalsReadOnTheRegister) {
  mc::Card c(4, ge_axis());
  c.axis_on(0);
  t_move(c, 0, 20000, 2, 0.02);
  c.run(5);
  EXPECT_THROW(c.set_mode(0, mc::AxisMode::SCurve), mc::CardCommandRefused);  // L310, L5368
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), bit(6));
  EXPECT_THROW(c.zero_pos(0), mc::CardCommandRefused);  // L721-729
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), bit(11));
  c.stage_acc(0, 0.05);  // Acc of a T move in motion (L315)
  EXPECT_THROW(c.update(1), mc::CardCommandRefused);
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), bit(11));
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::SX, c), bit(11));
}

TEST(GeStatus, RstStsMaskRule) {
  // L5423-5431: a mask bit 1 keeps, 0 clears; only bits 0-7. RstSts(1, 0xFE) clears bit 0 only (L5487).
  EXPECT_EQ(vg::ge_events_to_clear(0xFE), 0x1u);
  EXPECT_EQ(vg::ge_events_to_clear(0xFFFF), 0u);
  const std::uint32_t all = vg::ge_events_to_clear(0);
  EXPECT_EQ(all & 0xFFu, 0xFFu);
  EXPECT_TRUE(all & mc::event_bit(mc::CardEvent::SoftPosLimit));
  EXPECT_EQ(all & mc::event_bit(mc::CardEvent::EmergencyStop), 0u);
}

TEST(GeStatus, ImmediateSmoothStop) {
  mc::Card c(4, ge_axis());
  c.axis_on(0);
  t_move(c, 0, 100000, 2, 0.02);
  c.run(200);  // cruising at 2 pulse/tick
  c.smooth_stop(0);  // GE L1310-1312: decelerates at Acc: 100 ticks
  c.run(99);
  EXPECT_TRUE(c.moving(0));
  c.run(2);
  EXPECT_FALSE(c.moving(0));
  EXPECT_NO_THROW(c.smooth_stop(0));  // at rest: nothing
  EXPECT_THROW(c.set_probe_time(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(GeStatus, Bit10SetFromTheUpdateOfAMotion) {
  // L871: bit 10 is the planner's state; a host polling right after GT_Update (Example 7-2 L2236-2244) sees it.
  mc::Card c(4, ge_axis());
  c.axis_on(0);
  t_move(c, 0, 1000, 2, 0.05);
  EXPECT_FALSE(c.moving(0));                          // the commit is at the next tick
  EXPECT_TRUE(vg::ge_px_axis_status(c, 0) & bit(10));
  c.stage_pos_err(1, 100);
  c.update(2);                                        // an update without motion registers: no bit 10
  EXPECT_EQ(vg::ge_px_axis_status(c, 1) & bit(10), 0u);
  c.synch_pos_now(1);                                 // AxisOn's synchronisation at rest
  c.run(2);
  EXPECT_THROW(c.synch_pos_now(0), mc::CardCommandRefused);  // in motion: refused (cmd bit 11)
  EXPECT_EQ(vg::ge_command_status(vg::GeVariant::PX, c), bit(11));
}
