// The GT and GTS vendor modules (vendor/googol/gt_card.hpp, gts_card.hpp; issue 24 point 2, decisions GT1-GT13):
// the registers are the card's, every command returns a GtCode (never throws), the list state machine refuses with
// the manual's command status bits, the interrupt machine raises at the lowest axis with an enabled status bit.
#include <gtest/gtest.h>

#include <cmath>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gt_card.hpp"
#include "servobench/vendor/googol/gt_status.hpp"
#include "servobench/vendor/googol/gts_card.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
using vg::GtCode;

TEST(GtCard, CreatedOnFirstUseAndOwnedByTheCard) {
  mc::Card card(4, servobench::test::tuned_axis());
  EXPECT_EQ(card.module_if_any<vg::GtCard>(), nullptr);
  vg::GtCard& g = vg::gt(card);
  EXPECT_EQ(&vg::gt(card), &g);
  EXPECT_EQ(g.axis(), 0u);  // axis 1 after power-on (GT L754)
}

TEST(GtCard, AxisSelectionAndRangeChecksReturnTheManualsCodes) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  EXPECT_EQ(g.select_axis(3), GtCode::Success);
  EXPECT_EQ(g.axis(), 2u);
  for (double bad : {0.0, 5.0, 1.5, std::nan("")}) EXPECT_EQ(g.select_axis(bad), GtCode::ParameterError) << bad;
  EXPECT_EQ(g.axis(), 2u);  // unchanged by a refused selection
  EXPECT_EQ(card.last_fault(), mc::CommandFault::IllegalControlParam);
  EXPECT_EQ(g.check(0.25, 0, 0.5, vg::GtArg::RealHalfOpen), GtCode::Success);
  EXPECT_EQ(g.check(0.5, 0, 0.5, vg::GtArg::RealHalfOpen), GtCode::ParameterError);
}

TEST(GtCard, LimitSenseSetsEveryAxisPolarity) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  ASSERT_EQ(g.set_limit_sense(0b10000001), GtCode::Success);  // axis 1 positive, axis 4 negative low-active
  EXPECT_TRUE(card.state(0).limits.pos_active_low);
  EXPECT_FALSE(card.state(0).limits.neg_active_low);
  EXPECT_TRUE(card.state(3).limits.neg_active_low);
  EXPECT_EQ(g.limit_sense(), 0b10000001);
  EXPECT_EQ(g.set_limit_sense(0x10000), GtCode::ParameterError);
}

TEST(GtCrdList, ListStateMachineRefusesWithTheCommandStatusBit) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  for (std::size_t i = 0; i < 4; ++i) card.axis_on(i);
  EXPECT_EQ(g.crd().set_syn_vel(0), GtCode::SynParamError);  // zero: 4 (L401)
  EXPECT_EQ(g.crd().end_list(), GtCode::CommandError);        // not open: bit 12
  EXPECT_EQ(g.command_status(), 1u << 12);
  EXPECT_EQ(g.crd().move_start_point({1, 1}, 1, 0.1), GtCode::CommandError);  // Mv* without StrtList: bit 13
  EXPECT_EQ(g.command_status(), 1u << 13);
  ASSERT_EQ(g.crd().map_axis(1, {1, 0, 0, 0, 0}), GtCode::Success);
  ASSERT_EQ(g.crd().map_axis(2, {0, 1, 0, 0, 0}), GtCode::Success);
  ASSERT_EQ(g.crd().start_list(), GtCode::Success);
  EXPECT_EQ(g.crd().line({100, 0}), GtCode::CommandError);    // a path command before Mv* (L1843)
  ASSERT_EQ(g.crd().move_start_point({0, 0}, 2, 0.1), GtCode::Success);
  ASSERT_EQ(g.crd().line({100, 0}), GtCode::Success);
  ASSERT_EQ(g.crd().line({100, 100}), GtCode::Success);
  EXPECT_EQ(g.crd().regs().pushed, 2);
  ASSERT_EQ(g.crd().end_list(), GtCode::Success);
  ASSERT_EQ(g.crd().start_motion(), GtCode::Success);
  EXPECT_EQ(g.crd().start_motion(), GtCode::CommandError);    // while it executes: bit 12
  card.run(20000);
  EXPECT_EQ(g.crd().motion_number(), 2);
  EXPECT_NEAR(card.actual_pos(1), 100.0, 1.0);
  // the list registers are the card's: a reset brings the HardRst values back, the current axis stays
  ASSERT_EQ(g.select_axis(2), GtCode::Success);
  ASSERT_EQ(g.hard_reset(), GtCode::Success);
  EXPECT_EQ(g.crd().regs().vel, 0.0);
  EXPECT_FALSE(g.crd().regs().buffer);
  EXPECT_EQ(g.axis(), 1u);
}

TEST(GtInterrupts, RaisesAtTheLowestAxisAndCallsTheHostOnce) {
  mc::Card card(4, servobench::test::tuned_axis());
  vg::GtCard& g = vg::gt(card);
  int calls = 0;
  g.interrupts().isr = [&] { ++calls; };
  for (std::size_t i : {1u, 3u}) card.axis_on(i);  // motion complete latched on axes 2 and 4
  ASSERT_EQ(g.select_axis(4), GtCode::Success);
  ASSERT_EQ(g.interrupts().set_mask(0x1), GtCode::Success);  // axis 4: motion complete interrupts at once
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(g.interrupts().pending_axis(), std::optional<std::size_t>(3));
  ASSERT_EQ(g.select_axis(2), GtCode::Success);
  EXPECT_EQ(g.interrupts().set_mask(0x1), GtCode::Success);  // pending: no second request
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(g.select_interrupting_axis(), GtCode::Success);
  EXPECT_EQ(g.axis(), 3u);
  ASSERT_EQ(g.interrupts().reset_request(0), GtCode::Success);  // served: axis 2 requests next (its bit is set)
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(g.interrupts().pending_axis(), std::optional<std::size_t>(1));
  ASSERT_EQ(g.select_interrupting_axis(), GtCode::Success);
  ASSERT_EQ(g.interrupts().reset_request(0), GtCode::Success);
  EXPECT_FALSE(g.interrupts().pending_axis());
  EXPECT_EQ(g.interrupts().reset_request(0), GtCode::CommandError);  // nothing pending: cmd bit 4
  EXPECT_EQ(card.last_fault(), mc::CommandFault::NoInterruptPending);
}

// The GUC-ECAT / iDEABOX module (vendor/googol/gts_card.hpp, decisions GT11-GT13): look-ahead windows per
// (crd, fifo), stop decelerations, the velocity history recorded at the end of every tick.
TEST(GtsCard, LookAheadWindowsStopDecelerationsAndTheVelocityHistory) {
  mc::Card card(8, servobench::test::tuned_axis());  // 200 us: 1 pulse/tick = 5 pulse/ms
  vg::GtsCard& g = vg::gts(card);
  EXPECT_EQ(g.check_push(1, 0), vg::GucCode::CommandError);  // crd 1 not set up: the card refuses it
  g.set_lookahead(1, 0, 200);
  g.set_lookahead(2, 1, 50);
  EXPECT_EQ(g.lookahead(1, 0), 200);
  g.drop_lookahead(1);
  EXPECT_EQ(g.lookahead(1, 0), 0);
  EXPECT_EQ(g.lookahead(2, 1), 50);
  card.reset();  // GT_Reset: the windows go with the card's FIFOs
  EXPECT_EQ(g.lookahead(2, 1), 0);

  EXPECT_EQ(g.set_stop_dec(1, 0.0, 1.0), vg::GucCode::ParameterError);  // (0, 32767]
  EXPECT_EQ(g.set_stop_dec(9, 1.0, 1.0), vg::GucCode::ParameterError);  // profile 1..8
  ASSERT_EQ(g.set_stop_dec(2, 0.5, 4.0), vg::GucCode::Success);
  EXPECT_EQ(g.stop_dec(1), std::make_pair(0.5, 4.0));
  EXPECT_EQ(g.stop_dec(0), std::make_pair(0.0, 0.0));
  EXPECT_EQ(g.set_stop_io(1, 0, 3, 1), vg::GucCode::CommandError);  // MC_HOME is not wired (GS6)

  mc::Card jog(8, servobench::test::tuned_axis());  // a tuned card (the reset above zeroed the gains)
  vg::GtsCard& h = vg::gts(jog);
  jog.axis_on(0);
  ASSERT_EQ(h.set_enc_vel_filter(1, 2), vg::GucCode::Success);  // window 4 ticks; the history starts now
  jog.set_mode(0, mc::AxisMode::Jog);
  jog.stage_acc(0, 0.1);
  jog.stage_vel(0, 2.0);  // pulse/tick = 10 pulse/ms
  jog.update(1u);
  jog.run(20000);
  EXPECT_NEAR(h.filtered_enc_vel(0), 10.0, 0.5);  // pulse/ms, the actual-position change over 4 ticks
  EXPECT_NEAR(h.filtered_prf_vel(0), 10.0, 1e-9);  // the mean of the last 1 profile velocity (exp 0)
}
