// The ADLINK point tables, the watchdog and the vendor-owned event watch (session 12, decisions AW1-AW5): the point
// table's buffer bookkeeping and instruction commands (ApsPointTables, L3794-3911), the watchdog's time-out and
// actions (ApsWatchdog, L4025-4084) and the interrupt module watching the card itself without touching the host's
// watch (ApsInterrupts on CardScope::set_vendor_watch, L4090-4330).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <string>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_interrupts.hpp"
#include "servobench/vendor/adlink/aps_outputs.hpp"
#include "servobench/vendor/adlink/aps_point_table.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/vendor/adlink/aps_watchdog.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace sm = servobench::motion;
namespace va = servobench::vendor::adlink;
using servobench::test::aps_axis;
using va::AdlinkCode;

namespace {

constexpr long long kTicksPerS = 4000;  // 250 us servo period

void servo_on(mc::Card& c) {
  for (std::size_t i = 0; i < c.axis_count(); ++i) c.axis_on(i);
}

va::PtMove line(double x, double y) {
  va::PtMove m;
  m.dim = 2;
  m.pos = {x, y};
  return m;
}

}  // namespace

TEST(ApsPointTables, PointsWaitForStartThenRunInOrderCountingTheMovesStarted) {
  mc::Card c(4, aps_axis());
  servo_on(c);
  va::ApsPointTables& pt = va::aps_point_tables(c);
  ASSERT_EQ(pt.enable(0, 0, 2, {0, 1}), AdlinkCode::NoError);
  ASSERT_EQ(pt.set_speed(0, 0, va::ApsPointTables::Speed::Vm, 20000), AdlinkCode::NoError);
  va::PtStatus st;
  for (double x : {1000.0, 2000.0, 3000.0}) ASSERT_EQ(pt.push(0, 0, line(x, 0), st), AdlinkCode::NoError);
  EXPECT_EQ(st.usage_space, 3);
  EXPECT_EQ(st.free_space, va::kPtBufferPoints - 3);
  EXPECT_EQ(st.bit_sts, 0);  // waiting for APS_pt_start: not working, not empty
  c.run(400);
  EXPECT_EQ(c.profile_pos(0), 0);  // held (MF_WAIT) until the start
  ASSERT_EQ(pt.start(0, 0, 0), AdlinkCode::NoError);
  c.run(40);
  ASSERT_EQ(pt.status(0, 0, st), AdlinkCode::NoError);
  EXPECT_EQ(st.bit_sts & va::kPtbWorking, va::kPtbWorking);
  EXPECT_GE(st.running_cnt, 1);
  c.run(2 * kTicksPerS);
  ASSERT_EQ(pt.status(0, 0, st), AdlinkCode::NoError);
  EXPECT_EQ(st.bit_sts, va::kPtbEmpty);
  EXPECT_EQ(st.running_cnt, 3);
  EXPECT_EQ(c.profile_pos(0), 3000);
  EXPECT_EQ(va::aps_motion_status(c, 0) >> static_cast<int>(va::ApsMsts::PTB) & 1u, 0u);
}

TEST(ApsPointTables, InstructionCommandsTakeEffectWhenTheirMoveStarts) {
  mc::Card c(4, aps_axis());
  servo_on(c);
  va::ApsPointTables& pt = va::aps_point_tables(c);
  ASSERT_EQ(pt.enable(0, 0, 2, {0, 1}), AdlinkCode::NoError);
  va::PtStatus st;
  ASSERT_EQ(pt.push(0, 0, line(20000, 0), st), AdlinkCode::NoError);
  ASSERT_EQ(pt.ext_set_do(0, 0, 2, 1), AdlinkCode::NoError);  // rides on the second line
  ASSERT_EQ(pt.push(0, 0, line(20000, 1000), st), AdlinkCode::NoError);
  ASSERT_EQ(pt.start(0, 0, 0), AdlinkCode::NoError);
  int d = -1;
  c.run(40);
  pt.sync();
  ASSERT_EQ(va::aps_outputs(c).read_do(0, d), AdlinkCode::NoError);
  EXPECT_EQ(d, 0);  // the first line runs
  c.run(4 * kTicksPerS);
  pt.sync();
  ASSERT_EQ(va::aps_outputs(c).read_do(0, d), AdlinkCode::NoError);
  EXPECT_EQ(d, 1 << 2);
}

TEST(ApsPointTables, CodesOfTheManual) {
  mc::Card c(4, aps_axis());
  servo_on(c);
  va::ApsPointTables& pt = va::aps_point_tables(c);
  va::PtStatus st;
  EXPECT_EQ(pt.enable(0, 2, 2, {0, 1}), AdlinkCode::ParametersInvalid);   // tables 0..1
  EXPECT_EQ(pt.enable(0, 0, 1, {0}), AdlinkCode::ParametersInvalid);      // 2..6 axes
  EXPECT_EQ(pt.enable(0, 0, 2, {0, 0}), AdlinkCode::ParametersInvalid);   // distinct axes
  EXPECT_EQ(pt.enable(0, 0, 2, {0, NAN}), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(pt.enable(1, 0, 2, {0, 1}), AdlinkCode::ParametersInvalid);   // board 0
  EXPECT_EQ(pt.status(0, 0, st), AdlinkCode::FunctionNotAvailable);       // not enabled
  ASSERT_EQ(pt.enable(0, 0, 2, {0, 1}), AdlinkCode::NoError);
  EXPECT_EQ(pt.enable(0, 1, 2, {2, 3}), AdlinkCode::FunctionNotAvailable);  // one group on the card (AF5)
  EXPECT_EQ(pt.set_speed(0, 0, va::ApsPointTables::Speed::Vm, 0), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(pt.set_speed(0, 0, va::ApsPointTables::Speed::Sf, 1.5), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(pt.set_transition(0, 0, va::ApsPointTables::Transition::InPosition), AdlinkCode::FunctionNotAvailable);
  EXPECT_EQ(pt.set_transition(0, 0, va::ApsPointTables::Transition::BlendPcnt, 100), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(pt.ext_set_do(0, 0, 8, 1), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(pt.start(0, 0, 1), AdlinkCode::ParametersInvalid);
  va::PtMove bad = line(1, 2);
  bad.dim = 3;
  EXPECT_EQ(pt.push(0, 0, bad, st), AdlinkCode::ParametersInvalid);
  va::PtMove arc;
  arc.kind = va::PtMove::Kind::Arc2Ca;
  arc.index = {1, 0};
  arc.center = {0, 0};
  arc.angle_deg = 90;
  EXPECT_EQ(pt.push(0, 0, arc, st), AdlinkCode::FunctionNotAvailable);   // Index 0, 1 in order (AF10)
  va::PtMove dwell;
  dwell.kind = va::PtMove::Kind::Dwell;
  dwell.dw_time_ms = 0;
  EXPECT_EQ(pt.push(0, 0, dwell, st), AdlinkCode::ParametersInvalid);
  for (int k = 0; k < va::kPtBufferPoints; ++k)
    ASSERT_EQ(pt.push(0, 0, line(100.0 * (k + 1), 0), st), AdlinkCode::NoError) << k;
  EXPECT_EQ(st.bit_sts & va::kPtbFull, va::kPtbFull);
  EXPECT_EQ(pt.push(0, 0, line(99999, 0), st), AdlinkCode::FunctionNotAvailable);  // full (L3880)
  EXPECT_EQ(pt.disable(0, 0), AdlinkCode::NoError);  // waiting: dropped, the axes back to single-axis motion
  const va::AdlinkGroup* g = va::adlink_group(c);
  EXPECT_TRUE(g == nullptr || !g->busy());
  EXPECT_EQ(pt.status(0, 0, st), AdlinkCode::FunctionNotAvailable);
}

TEST(ApsWatchdog, FiresOnceAfterTheTimeOutUnlessResetAndCarriesOutItsActions) {
  mc::Card c(4, aps_axis());
  servo_on(c);
  va::ApsWatchdog& w = va::aps_watchdog(c);
  ASSERT_EQ(va::aps_outputs(c).write_do(0, 0xA5), AdlinkCode::NoError);
  ASSERT_EQ(w.set_action(0, 0, va::kWdtServoOff | va::kWdtDoOff), AdlinkCode::NoError);
  EXPECT_EQ(w.set_action(0, 0, 8), AdlinkCode::ParametersInvalid);
  EXPECT_EQ(w.start(0, 1, 10), AdlinkCode::ParametersInvalid);  // only timer 0 (L4069)
  ASSERT_EQ(w.start(0, 0, 10), AdlinkCode::NoError);            // 10 x 100 ms = 1 s (L4070)
  for (int k = 0; k < 3; ++k) {
    c.run(kTicksPerS / 2);
    ASSERT_EQ(w.reset_counter(0, 0), AdlinkCode::NoError);
  }
  c.run(kTicksPerS - 8);
  EXPECT_TRUE(c.servo_on(0));
  c.run(8);  // 1 s after the last reset, to within one motion cycle (AF16)
  for (std::size_t i = 0; i < 4; ++i) EXPECT_FALSE(c.servo_on(i)) << i;
  int d = -1;
  ASSERT_EQ(va::aps_outputs(c).read_do(0, d), AdlinkCode::NoError);
  EXPECT_EQ(d, 0);
  EXPECT_TRUE(w.fired());
  EXPECT_EQ(w.reset_counter(0, 0), AdlinkCode::FunctionNotAvailable);  // one shot
  EXPECT_FALSE(c.scope().watching());                                  // the host's watch untouched
}

TEST(CardScopeVendorWatch, TheModulesWatchIsApartFromTheHostsAndEndsAWaitingRun) {
  mc::Card c(4, aps_axis());
  servo_on(c);
  va::ApsInterrupts& ints = va::aps_interrupts(c);
  ASSERT_EQ(ints.set_main(1), AdlinkCode::NoError);
  constexpr int kImdn = 12;
  ASSERT_EQ(ints.set_factor(0, kImdn, 1), kImdn);  // axis 0 motion done (MSTS MDN)
  EXPECT_FALSE(c.scope().watching());               // a vendor watch is not the host's
  sm::AdlinkPtpParams p;
  p.pos = 2000;
  p.vm = 40000;
  p.acc = p.dec = 4e5;
  va::adlink(c).move_ptp(0, p);
  long long ticks = 0;
  ASSERT_EQ(ints.begin_wait(1, {static_cast<double>(kImdn)}, 1, 5000, ticks), AdlinkCode::NoError);
  const std::size_t ran = c.run_until_event(static_cast<std::size_t>(ticks));
  EXPECT_LT(ran, static_cast<std::size_t>(ticks));  // the wait ended the run at the interrupt
  EXPECT_TRUE(ints.wait_done());
  EXPECT_TRUE(c.scope().fired().empty());           // nothing for the host
  EXPECT_EQ(c.profile_pos(0), 2000);
  // A host watch on the same bit gets its own event; the module's watch goes on.
  c.scope().set_watch(0, 0, 1u << static_cast<int>(va::ApsMsts::MDN), 0);
  ASSERT_EQ(ints.set_signaled(kImdn, false), AdlinkCode::NoError);
  p.pos = 0;
  va::adlink(c).move_ptp(0, p);
  c.run_until_event(static_cast<std::size_t>(ticks));
  ASSERT_EQ(c.scope().fired().size(), 1u);
  EXPECT_EQ(c.scope().fired()[0].word, mc::WatchWord::Msts);
  EXPECT_TRUE(ints.wait_done());
  ints.power_on();                                  // APS_close: the module's watch ends
  c.scope().set_watch(0, 0, 0, 0);
  EXPECT_FALSE(c.scope().watching());
}

TEST(ApsPointTables, TheCommandTableDescribesEveryFunctionOnceWithItsManualLine) {
  const auto& rows = va::pt_commands();
  EXPECT_EQ(rows.size(), 26u);  // APS_pt_* and APS_get_pt_status of manual §4.10.6
  const auto cites_a_line = [](const std::string& d) {  // "L" and four digits: a line of seed 004
    for (std::size_t i = 0; i + 4 < d.size(); ++i)
      if (d[i] == 'L' && std::isdigit(static_cast<unsigned char>(d[i + 1])) &&
          std::isdigit(static_cast<unsigned char>(d[i + 4])))
        return true;
    return false;
  };
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_TRUE(cites_a_line(rows[k].doc)) << rows[k].name;
    for (std::size_t j = 0; j < k; ++j) EXPECT_STRNE(rows[j].name, rows[k].name);
  }
}
