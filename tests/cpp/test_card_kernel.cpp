// The card kernel's module interface (machine/card_hooks.hpp) and its tick (docs/architecture.md "The tick"):
// hooks called at their points, the law's error read from what the loop step returns.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/adlink/return_code.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace mc = servobench::machine;

namespace {

using servobench::test::t_move;
using servobench::test::tuned_axis;

// Counts the hook calls; optionally hides the positive limit of every axis.
struct CountingModule : mc::CardHooks {
  bool on = true;
  bool hide_pos_limit = false;
  long long begins = 0, last_tick = -1;
  std::vector<int> fed;
  int leaves = 0, resets = 0, aborts = 0;
  bool active() const override { return on; }
  void begin_tick(long long tick) override {
    ++begins;
    last_tick = tick;
  }
  void feed(std::size_t i) override { fed.push_back(static_cast<int>(i)); }
  bool limit_enabled(std::size_t, bool positive) const override { return !(positive && hide_pos_limit); }
  void leave(std::size_t) override { ++leaves; }
  void reset() override { ++resets; }
  void on_abrupt_stop(std::size_t) override { ++aborts; }
};

}  // namespace

TEST(CardKernel, HooksRunAtTheirPointsOfTheTick) {
  mc::Card c(4, tuned_axis());
  CountingModule m;
  c.attach(m);
  c.attach(m);  // attaching twice keeps one registration
  c.run(3);
  EXPECT_EQ(m.begins, 3);
  EXPECT_EQ(m.last_tick, 2);
  ASSERT_EQ(m.fed.size(), 12u);  // every axis, in ascending order, every tick
  for (std::size_t k = 0; k < m.fed.size(); ++k) EXPECT_EQ(m.fed[k], static_cast<int>(k % 4));
  m.on = false;  // an inactive module costs nothing: no tick hooks
  c.run(2);
  EXPECT_EQ(m.begins, 3);
  EXPECT_EQ(m.fed.size(), 12u);
  c.set_mode(1, mc::AxisMode::Jog);
  EXPECT_EQ(m.leaves, 1);
  c.abrupt_stop(2);
  EXPECT_EQ(m.aborts, 1);
  c.reset();
  EXPECT_EQ(m.resets, 1);
  c.detach(m);
  c.reset();
  EXPECT_EQ(m.resets, 1);
}

TEST(CardKernel, AModuleCanHideALimit) {
  mc::AxisConfig cfg = tuned_axis();
  cfg.switches.pos_limit_rad = 0.0;  // the positive limit switch is hit where the axis stands
  mc::Card c(4, cfg);
  c.run(1);
  EXPECT_TRUE(c.events(0) & mc::event_bit(mc::CardEvent::PosLimit));
  c.clear_events(0, mc::kAllEvents);
  CountingModule m;
  m.hide_pos_limit = true;
  c.attach(m);
  c.run(1);
  EXPECT_FALSE(c.events(0) & mc::event_bit(mc::CardEvent::PosLimit));
}

TEST(CardKernel, KernelServicesCheckTheAxisOnce) {
  mc::Card c(4, tuned_axis());
  EXPECT_NO_THROW(c.check_axis(3));
  EXPECT_THROW(c.check_axis(4), std::invalid_argument);
  EXPECT_THROW(mc::Card(6, tuned_axis()), std::invalid_argument);
  c.set_stop_cause(1, mc::StopCause::DriveAlarm);
  EXPECT_EQ(c.state(1).stop_cause, mc::StopCause::DriveAlarm);
  try {
    c.refuse(2, mc::CommandFault::InvalidInMode, "a test refusal");
    FAIL() << "refuse must throw";
  } catch (const mc::CardCommandRefused& e) {
    EXPECT_EQ(e.fault(), mc::CommandFault::InvalidInMode);
    EXPECT_EQ(e.axis(), 2);
  }
  EXPECT_EQ(c.last_fault(), mc::CommandFault::InvalidInMode);
  EXPECT_TRUE(c.events(2) & mc::event_bit(mc::CardEvent::CommandError));
}

TEST(CardKernel, TheRecordedErrorIsTheOneTheChecksUse) {
  // The tick reads the law's error from the loop step's return value; a recorded trace shows the same number.
  mc::Card c(4, tuned_axis());
  c.axis_on(0);
  t_move(c, 0, 2000, 2.0, 0.05);
  const std::size_t n = 400;
  std::vector<double> err(n, NAN), pos(n, NAN);
  std::vector<mc::CardTrace> tr(4);
  tr[0].axis.error = err.data();
  tr[0].loop.actual_pos = pos.data();
  c.run(n, tr);
  double peak = 0.0;
  for (double e : err) {
    ASSERT_TRUE(std::isfinite(e));
    peak = std::max(peak, std::fabs(e));
  }
  EXPECT_GT(peak, 0.0);  // the axis moved with a following error
  EXPECT_DOUBLE_EQ(c.following_error(0), err[n - 1]);
}

TEST(VendorCodes, TheManualsValues) {
  namespace g = servobench::vendor::googol;
  namespace a = servobench::vendor::adlink;
  EXPECT_EQ(static_cast<int>(g::GtCode::MapAxisError), 6);      // GT Table 2-1 L408
  EXPECT_EQ(static_cast<int>(g::GtCode::SynParamError), 4);     // GT L401
  EXPECT_EQ(static_cast<int>(g::GeCode::Reentered), -3);        // GE L266
  EXPECT_EQ(static_cast<int>(g::GucCode::LicenseError), 2);     // GUC Tab 2-1
  EXPECT_EQ(static_cast<int>(g::GucCode::OpenFailed), -6);
  EXPECT_EQ(static_cast<int>(a::AdlinkCode::FunctionNotAvailable), -13);  // V49
  EXPECT_EQ(g::ge_geometry_code(3), g::GeCode::CommandError);  // a zero-length look-ahead line: duplicate point
  EXPECT_EQ(g::ge_geometry_code(5), g::GeCode::ArcChordError);
  EXPECT_EQ(g::guc_geometry_code(2), g::GucCode::ParameterError);
  EXPECT_STREQ(g::to_string(g::GtCode::ArcRadiusError), "arc radius error");
  EXPECT_STREQ(a::to_string(a::AdlinkCode::DistantNotEnough), "ERR_DistantNotEnough");
}
