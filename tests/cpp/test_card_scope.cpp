// The card's scope (sampler), event watch, position compare and probe (issue 10 point 3).
// Manual lines: ADLINK seed 004 (digest adlink.md §6.10, §7.5, §8), GT seed 000 (gt.md §5, §7).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "servobench/machine/card.hpp"
#include "card_fixtures.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;

namespace {

using servobench::test::tuned_axis;
using servobench::test::t_move;

mc::SampleChannel ch(double axis, mc::SampleSignal s) {
  mc::SampleChannel c;
  c.axis = axis;
  c.signal = s;
  return c;
}

}  // namespace

TEST(CardScope, SamplerReadsWhatTheTraceRecordsEveryNTicks) {
  mc::Card a(4, tuned_axis()), b(4, tuned_axis());
  for (mc::Card* c : {&a, &b}) {
    c->axis_on(1);
    t_move(*c, 1, 3000, 5, 0.1);
  }
  mc::SamplerConfig cfg;
  cfg.channels = {ch(1, mc::SampleSignal::loop_pos), ch(1, mc::SampleSignal::u), ch(1, mc::SampleSignal::volts),
                  ch(1, mc::SampleSignal::card_fbk_vel), ch(1, mc::SampleSignal::card_error_diff),
                  ch(1, mc::SampleSignal::error)};
  cfg.every_ticks = 3;
  cfg.depth = 200;
  a.scope().start_sampler(cfg);
  // b records the same signals tick by tick (the run is deterministic and the sampler does not perturb it)
  const std::size_t n = 800;
  std::vector<double> pos(n), u(n), volts(n), act(n), err(n);
  std::vector<mc::CardTrace> tr(4);
  tr[1].loop.pos = pos.data();
  tr[1].axis.u = u.data();
  tr[1].axis.volts = volts.data();
  tr[1].loop.actual_pos = act.data();
  tr[1].axis.error = err.data();
  b.run(n, tr);
  a.run(n);
  const mc::Sampler& s = a.scope().sampler();
  ASSERT_EQ(s.state(), mc::SamplerState::Done);
  const mc::SampleBlock& blk = s.blocks().front();
  ASSERT_EQ(blk.ticks.size(), 200u);
  for (std::size_t j = 0; j < 200; ++j) {
    const auto k = static_cast<std::size_t>(blk.ticks[j]);
    EXPECT_EQ(k, 3 * j);
    EXPECT_EQ(blk.values[j * 6 + 0], pos[k]);
    EXPECT_EQ(blk.values[j * 6 + 1], u[k]);
    EXPECT_EQ(blk.values[j * 6 + 2], volts[k]);
    EXPECT_EQ(blk.values[j * 6 + 5], err[k]);
    if (k > 0) {
      EXPECT_DOUBLE_EQ(blk.values[j * 6 + 3], act[k] - act[k - 1]);
      EXPECT_DOUBLE_EQ(blk.values[j * 6 + 4], err[k] - err[k - 1]);
    }
  }
  EXPECT_EQ(a.actual_pos(1), b.actual_pos(1));
}

TEST(CardScope, RisingTriggerKeepsThePretriggerSamples) {
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  t_move(c, 0, 5000, 10, 0.2);
  mc::SamplerConfig cfg;
  cfg.channels = {ch(0, mc::SampleSignal::loop_actual_pos)};
  cfg.depth = 100;
  cfg.pretrigger = 20;
  cfg.trigger = mc::SampleTrigger::Rising;
  cfg.level = 2500;
  c.scope().start_sampler(cfg);
  c.run(2000);
  const mc::SampleBlock& blk = c.scope().sampler().blocks().front();
  ASSERT_EQ(blk.ticks.size(), 100u);
  EXPECT_LT(blk.values[19], 2500.0);
  EXPECT_GE(blk.values[20], 2500.0);
  EXPECT_EQ(blk.trigger_tick, blk.ticks[20]);
  for (std::size_t j = 1; j < 100; ++j) EXPECT_EQ(blk.ticks[j], blk.ticks[j - 1] + 1);
}

TEST(CardScope, EventTriggerAndValidation) {
  mc::Card c(4, tuned_axis());
  mc::SamplerConfig bad;
  EXPECT_THROW(c.scope().start_sampler(bad), std::invalid_argument);  // no channel
  bad.channels = {ch(4, mc::SampleSignal::volts)};
  EXPECT_THROW(c.scope().start_sampler(bad), std::invalid_argument);  // no axis 4 on a 4-axis card
  bad.channels = {ch(0, mc::SampleSignal::volts)};
  bad.pretrigger = 5;
  EXPECT_THROW(c.scope().start_sampler(bad), std::invalid_argument);  // pretrigger needs a trigger
  c.axis_on(2);
  t_move(c, 2, 400, 4, 0.2);
  mc::SamplerConfig cfg;
  cfg.channels = {ch(2, mc::SampleSignal::card_moving)};
  cfg.depth = 10;
  cfg.pretrigger = 3;
  cfg.trigger = mc::SampleTrigger::Event;
  cfg.event_axis = 2;
  cfg.event_bits = mc::event_bit(mc::CardEvent::MotionComplete);
  c.clear_events(2, mc::kAllEvents);
  c.scope().start_sampler(cfg);
  c.run(1000);
  const mc::SampleBlock& blk = c.scope().sampler().blocks().front();
  EXPECT_EQ(blk.values[2], 1.0);  // still moving just before
  EXPECT_EQ(blk.values[3], 0.0);  // the trigger sample: motion complete latched
}

TEST(CardScope, RunUntilEventStopsAtTheTickTheEventLatches) {
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  c.clear_events(0, mc::kAllEvents);
  t_move(c, 0, 1000, 5, 0.1);
  c.scope().set_watch(0, mc::event_bit(mc::CardEvent::MotionComplete), 0, 0);
  const std::size_t ran = c.run_until_event(100000);
  ASSERT_EQ(c.scope().fired().size(), 1u);
  const mc::FiredEvent& f = c.scope().fired()[0];
  EXPECT_EQ(f.axis, 0);
  EXPECT_EQ(f.word, mc::WatchWord::Events);
  EXPECT_EQ(static_cast<std::size_t>(f.tick) + 1, ran);
  EXPECT_FALSE(c.moving(0));
  EXPECT_TRUE(c.events(0) & mc::event_bit(mc::CardEvent::MotionComplete));
  // the profile of a T-curve 0 -> 1000 at vel 5, acc 0.1: 50 ticks ramp each way, 150 at cruise (+ commit tick)
  EXPECT_NEAR(static_cast<double>(ran), 251.0, 2.0);
  // nothing more fires: the run goes to its end
  EXPECT_EQ(c.run_until_event(500), 500u);
  // a timer fires every 10 ticks
  c.scope().set_watch(0, 0, 0, 0);
  c.scope().set_timer(10);
  EXPECT_EQ(c.run_until_event(1000), 10u);
  EXPECT_EQ(c.run_until_event(1000), 10u);
}

TEST(CardScope, LinearCompareEmitsAtTheManualsPoints) {
  // ADLINK L3393-3395 (adlink.md T23): start P1, repeat 4, interval L -> P1, P1+L, P1+2L, P1+3L.
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  mc::PositionCompare& pc = c.scope().compare();
  mc::CompareSource src;
  src.axis = 0;
  src.command = true;
  pc.set_source(0, src, 4);
  pc.set_linear(0, 1000, 4, 500);
  mc::TriggerOutputConfig out;
  out.sources = mc::kTrgSrcLcmp0;
  out.pulse_width_s = 1e-6;
  pc.set_output(0, out);
  pc.set_enabled_mask(0x1);
  t_move(c, 0, 5000, 7, 0.1);
  c.scope().set_system_watch(mc::kSysLcf0);
  std::vector<double> pulses(3000), cmd(3000);
  std::vector<mc::CardTrace> tr(4);
  tr[0].loop.pos = cmd.data();
  c.run(3000, tr);
  EXPECT_EQ(pc.count(0), 4);
  ASSERT_EQ(pc.log().size(), 4u);
  for (int j = 0; j < 4; ++j) {
    const mc::TriggerEvent& e = pc.log()[static_cast<std::size_t>(j)];
    EXPECT_EQ(e.point, 1000.0 + 500.0 * j);
    EXPECT_EQ(e.comparator, 0);
    // the command position reached the point during that tick
    const auto k = static_cast<std::size_t>(e.tick);
    EXPECT_GE(cmd[k], e.point);
    EXPECT_LT(cmd[k - 1], e.point);
    EXPECT_GE(e.time_s, static_cast<double>(k) * c.servo_period_s());
    EXPECT_LE(e.time_s, static_cast<double>(k + 1) * c.servo_period_s());
  }
  EXPECT_EQ(pc.remaining(0), 0u);
  // the linear compare's end is the system event ILCF0 (L4166); a positive interval ignores the way back
  c.scope().set_system_watch(mc::kSysLcf0);
  pc.set_linear(0, 4000, 2, 1000);
  c.scope().set_watch(0, 0, 0, 0);
  t_move(c, 0, 0, 7, 0.1);
  c.run(2000);
  EXPECT_EQ(pc.count(0), 4);
  // negative interval: compared going down
  pc.set_linear(0, 4000, 3, -1000);
  t_move(c, 0, 5000, 7, 0.1);
  c.run(2000);
  t_move(c, 0, 0, 7, 0.1);
  const std::size_t ran = c.run_until_event(3000);
  EXPECT_EQ(pc.count(0), 7);
  ASSERT_FALSE(c.scope().fired().empty());
  EXPECT_EQ(c.scope().fired()[0].word, mc::WatchWord::System);
  EXPECT_EQ(c.scope().fired()[0].bits, mc::kSysLcf0);
  EXPECT_LT(ran, 3000u);
  EXPECT_THROW(pc.set_linear(0, 0, 3, 0), std::invalid_argument);
  EXPECT_THROW(pc.set_linear(2, 0, 3, 1), std::invalid_argument);
}

TEST(CardScope, TableCompareDirectionsToggleAndLogic) {
  mc::Card c(4, tuned_axis());
  c.axis_on(1);
  mc::PositionCompare& pc = c.scope().compare();
  mc::CompareSource src;
  src.axis = 1;
  pc.set_source(2, src, 4);  // TCMP0 on axis 1's feedback
  pc.set_table(0, {300, 900, 950, 2000});
  pc.set_table_direction(0, 1);
  mc::TriggerOutputConfig out;
  out.sources = mc::kTrgSrcTcmp0;
  out.toggle = true;
  out.active_low = true;
  pc.set_output(2, out);
  pc.set_enabled_mask(0x4);
  EXPECT_TRUE(pc.level(2));  // active low idles high
  t_move(c, 1, 1000, 5, 0.1);
  c.run(1500);
  EXPECT_EQ(pc.count(2), 3);
  EXPECT_FALSE(pc.level(2));  // toggled three times from idle high
  EXPECT_EQ(pc.next_point(2), 2000.0);
  EXPECT_EQ(pc.count(0), 0);  // TRG0 not fed by TCMP0
  // a disabled output does not count
  pc.set_enabled_mask(0);
  t_move(c, 1, 2500, 5, 0.1);
  c.run(1500);
  EXPECT_EQ(pc.count(2), 3);
  EXPECT_EQ(pc.remaining(2), 0u);
}

TEST(CardScope, ProbeAtATimeAndAtAPositionLatchesEveryArmedAxis) {
  // GT_CaptProb (GT L3008-3049): EXI0 captures the actual position of every axis armed for it, sets bit 3.
  mc::Card c(4, tuned_axis());
  for (std::size_t i = 0; i < 2; ++i) {
    c.axis_on(i);
    c.clear_events(i, mc::kAllEvents);
    t_move(c, i, 4000.0 * static_cast<double>(i + 1), 4.0 * static_cast<double>(i + 1), 0.1);
    c.arm_capture(i, mc::CaptureTrigger::Probe);
  }
  std::vector<double> act0(1000), act1(1000);
  std::vector<mc::CardTrace> tr(4);
  tr[0].loop.actual_pos = act0.data();
  tr[1].loop.actual_pos = act1.data();
  c.set_probe_time(0.1);  // tick 500 at 200 us
  c.run(1000, tr);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(c.events(i) & mc::event_bit(mc::CardEvent::Captured));
    EXPECT_TRUE(vg::gt_axis_status(c, i) & 0x8);
    const std::vector<double>& act = i == 0 ? act0 : act1;
    const double v = c.loop(i).capture().value();
    EXPECT_GE(v, std::min(act[498], act[499]) - 1.0);
    EXPECT_LE(v, std::max(act[498], act[499]) + 1.0);
  }
  EXPECT_FALSE(c.events(2) & mc::event_bit(mc::CardEvent::Captured));  // not armed
  // at a position of axis 1: the probe axis latches the point itself, axis 0 its position at that instant
  for (std::size_t i = 0; i < 2; ++i) {
    c.clear_events(i, mc::kAllEvents);
    c.arm_capture(i, mc::CaptureTrigger::Probe);
  }
  c.set_probe_time(std::nan(""));
  t_move(c, 0, 6000, 4, 0.1);
  t_move(c, 1, 12000, 8, 0.1);
  c.scope().set_probe_position(1, 10000);
  std::vector<double> b0(2000), b1(2000);
  tr[0].loop.actual_pos = b0.data();
  tr[1].loop.actual_pos = b1.data();
  c.run(2000, tr);
  EXPECT_EQ(c.loop(1).capture().value(), 10000.0);
  std::size_t k = 1;
  while (k < 2000 && !(b1[k - 1] < 10000 && b1[k] >= 10000)) ++k;
  ASSERT_LT(k, 2000u);
  const double f = (10000 - b1[k - 1]) / (b1[k] - b1[k - 1]);
  EXPECT_DOUBLE_EQ(c.loop(0).capture().value(), b0[k - 1] + f * (b0[k] - b0[k - 1]));
  EXPECT_TRUE(c.events(0) & mc::event_bit(mc::CardEvent::Captured));
}

TEST(CardScope, ResetStopsTheSamplerAndTheCompareButKeepsTheHostsWatch) {
  // GT_Reset / GT_HardRst (GT L4124-4142) return the card to its power-on state; the sampler and the compare are
  // card registers, the event watch is the host's subscription (V126).
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  mc::SamplerConfig cfg;
  cfg.channels = {ch(0, mc::SampleSignal::error)};
  cfg.depth = 100;
  c.scope().start_sampler(cfg);
  mc::PositionCompare& pc = c.scope().compare();
  mc::CompareSource src;
  src.axis = 0;
  src.command = true;
  pc.set_source(0, src, 4);
  pc.set_linear(0, 1000, 4, 500);
  pc.set_enabled_mask(0x1);
  c.scope().set_watch(0, mc::event_bit(mc::CardEvent::MotionComplete), 0, 0);
  c.scope().set_probe_position(0, 500);
  c.run(10);
  ASSERT_TRUE(c.scope().sampler().active());
  ASSERT_TRUE(pc.active());
  c.reset();
  EXPECT_EQ(c.scope().sampler().state(), mc::SamplerState::Idle);
  EXPECT_EQ(c.scope().sampler().filled(), 0u);
  EXPECT_FALSE(c.scope().compare().active());
  EXPECT_EQ(c.scope().compare().enabled_mask(), 0u);
  EXPECT_EQ(c.scope().probe_axis(), -1);
  EXPECT_TRUE(c.scope().watching());
  // the kept watch still fires: a move after the reset ends with motion complete
  c.axis_on(0);
  c.clear_events(0, mc::kAllEvents);
  t_move(c, 0, 1000, 5, 0.1);
  c.run_until_event(100000);
  ASSERT_EQ(c.scope().fired().size(), 1u);
  EXPECT_EQ(c.scope().fired()[0].word, mc::WatchWord::Events);
}
