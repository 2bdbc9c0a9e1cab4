// The ADLINK vendor module's register tables (session 11, decisions AV2-AV9): the scope registers (ApsScope), the
// interrupt table (ApsInterrupts), the PRA_* axis parameters (ApsParameters) and the board outputs (ApsOutputs)
// answer with the APS codes of the manual and keep their power-on values until a command changes them.
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/aps_interrupts.hpp"
#include "servobench/vendor/adlink/aps_outputs.hpp"
#include "servobench/vendor/adlink/aps_parameters.hpp"
#include "servobench/vendor/adlink/aps_scope.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace va = servobench::vendor::adlink;
using servobench::test::aps_axis;
using va::AdlinkCode;

TEST(ApsScope, SamplingRegistersStartAtThePowerOnValuesAndCheckTheirRanges) {
  mc::Card card(4, aps_axis());
  va::ApsScope& s = va::aps_scope(card);
  int v = -1;
  EXPECT_EQ(s.sampling_param(va::kSampRate, v), AdlinkCode::NoError);
  EXPECT_EQ(v, 4);  // the ticks of 1 ms at 250 us (L3548)
  EXPECT_EQ(s.set_sampling_param(va::kSampRate, 0), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(s.set_sampling_param(va::kSampSrcCh0, 0x21), AdlinkCode::FunctionNotAvailable);  // gantry deviation
  EXPECT_EQ(s.set_sampling_param(va::kSampSrcCh0, 0x400), AdlinkCode::ParametersInvalid);     // axis 4 of 4
  EXPECT_EQ(s.set_sampling_param(va::kSampSrcCh0, 0x300 | 0x01), AdlinkCode::NoError);
  EXPECT_EQ(s.sampling_param(va::kSampSrcCh0, v), AdlinkCode::NoError);
  EXPECT_EQ(v, 0x301);
  EXPECT_EQ(s.start_sampling(10, 10, 50), AdlinkCode::ParametersInvalid);  // pretrigger must be < length
  EXPECT_EQ(s.start_sampling(10, 0, 1000), AdlinkCode::NoError);
  card.run(60);
  EXPECT_TRUE(s.sampling_block_ready());
  EXPECT_EQ(s.sampling_count(), 10);
  EXPECT_EQ((*s.sampling_buffer())[1].tick - (*s.sampling_buffer())[0].tick, 4);
}

TEST(ApsScope, TriggerParametersAndTheTimer) {
  mc::Card card(4, aps_axis());
  va::ApsScope& s = va::aps_scope(card);
  EXPECT_EQ(s.set_trigger_param(0x16, 5), AdlinkCode::ParametersInvalid);  // TGR_TRG2_PWD: a PCI-8254 has TRG0-1
  EXPECT_EQ(s.set_trigger_param(0x14, 25), AdlinkCode::NoError);
  EXPECT_DOUBLE_EQ(card.scope().compare().output(0).pulse_width_s, 25 * 100e-9);
  EXPECT_EQ(s.set_trigger_param(0x20, 2), AdlinkCode::NoError);  // TIMR_ITV: a count every 2 ticks
  EXPECT_EQ(s.set_trigger_param(0x23, 1), AdlinkCode::NoError);  // TIMR_EN
  card.run(10);
  EXPECT_EQ(s.timer_counter(), 5);
  EXPECT_EQ(s.set_timer_counter(2147483647.0), AdlinkCode::NoError);
  card.run(4);
  EXPECT_EQ(s.timer_counter(), 2147483647);  // held at the I32 limit without TIMR_RING_EN
}

TEST(ApsInterrupts, FactorsNumberSignalAndWait) {
  mc::Card card(4, aps_axis());
  va::ApsInterrupts& m = va::aps_interrupts(card);
  EXPECT_EQ(m.set_factor(1, 12, 1), 1 * 32 + 12);           // IMDN of axis 1
  EXPECT_EQ(m.set_factor(0, 1 << 12, 1), 12);                // a one-bit mask is read as its bit (V82)
  EXPECT_EQ(m.set_factor(0, 18, 1), static_cast<int>(AdlinkCode::FunctionNotAvailable));  // IPRED
  EXPECT_EQ(m.set_factor(9, 0, 1), static_cast<int>(AdlinkCode::FunctionNotAvailable));   // DI edges
  EXPECT_EQ(m.msts_mask(1), 1u << 5);                        // MDN
  long long ticks = 0;
  EXPECT_EQ(m.begin_wait(1, {44}, 1, 100, ticks), AdlinkCode::InterruptNotEnable);  // main switch off
  m.fired(1, "msts", 1u << 5);
  EXPECT_EQ(m.set_main(1), AdlinkCode::NoError);
  EXPECT_EQ(m.begin_wait(1, {44}, 1, 100, ticks), AdlinkCode::NoError);
  EXPECT_EQ(ticks, 400);
  EXPECT_FALSE(m.wait_done());  // the event while the switch was off signaled nothing
  m.fired(1, "msts", 1u << 5);
  EXPECT_TRUE(m.wait_done());
  EXPECT_EQ(m.set_signaled(44, false), AdlinkCode::NoError);
  EXPECT_EQ(m.set_signaled(45, true), AdlinkCode::ParametersInvalid);  // never enabled
}

TEST(ApsParameters, StoredValuesRangesAndTheRefusalCodes) {
  mc::Card card(4, aps_axis());
  va::ApsParameters& p = va::aps_parameters(card);
  double v = 0;
  EXPECT_EQ(p.get(0, 0x24, v), AdlinkCode::NoError);
  EXPECT_DOUBLE_EQ(v, 1e5);  // PRA_VM default (V48)
  EXPECT_EQ(p.set(0, 0x24, 2e9), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(p.set(0, 0x24, 3e4), AdlinkCode::NoError);
  EXPECT_DOUBLE_EQ(p.axis(0).motion.vm, 3e4);
  EXPECT_EQ(p.set(0, 0x90, 1.5), AdlinkCode::ParametersInvalid);  // PRA_KP_GAIN is whole
  EXPECT_EQ(p.set(0, 0x90, 1000), AdlinkCode::NoError);
  EXPECT_EQ(p.get(0, 0x90, v), AdlinkCode::NoError);
  EXPECT_DOUBLE_EQ(v, 1000);
  EXPECT_EQ(p.set(0, 0x49, 1), AdlinkCode::FunctionNotAvailable);  // DI-linked jog (V30)
  EXPECT_EQ(p.set(0, 0x0A, 5000), AdlinkCode::NoError);            // PRA_SPEL_POS -> the card's limits
  EXPECT_DOUBLE_EQ(card.state(0).limits.soft_pos_pulse, 5000);
  EXPECT_EQ(p.set(0, 0x999, 1), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::code_of(mc::CommandFault::EmergencyStopActive), AdlinkCode::NoError);  // ignored (V47)
  EXPECT_EQ(va::code_of(mc::CommandFault::DistanceTooShort), AdlinkCode::DistantNotEnough);
  EXPECT_EQ(va::code_of(mc::CommandFault::ChangeInMotion), AdlinkCode::FunctionNotAvailable);
}

TEST(ApsOutputs, BoardParametersAndTheVaoPower) {
  mc::Card card(4, aps_axis());
  va::ApsOutputs& o = va::aps_outputs(card);
  EXPECT_EQ(o.set_board_param(0x00, 1), AdlinkCode::FunctionNotAvailable);  // EMG logic inverted (AF17)
  EXPECT_EQ(o.set_board_param(0x110, 0x103), AdlinkCode::NoError);          // PWM0 enabled by DO3 on
  EXPECT_EQ(o.start_vao(0, 1), AdlinkCode::FunctionNotAvailable);           // no table yet
  EXPECT_EQ(o.set_vao_param(0x01, 1), AdlinkCode::NoError);                 // table 0 on the command speed
  EXPECT_EQ(o.set_vao_table(0, 0, 1000, 2, {100, 300}), AdlinkCode::NoError);
  EXPECT_EQ(o.start_vao(0, 1), AdlinkCode::NoError);
  EXPECT_FALSE(o.vao_output(0).on);  // DO3 off
  o.set_do_bit(3, true);
  const va::VaoOutput out = o.vao_output(0);
  EXPECT_TRUE(out.on);
  EXPECT_DOUBLE_EQ(out.power, 100);  // at rest: the first point
  EXPECT_EQ(out.unit, "0.05 %");
}
