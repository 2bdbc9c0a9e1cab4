// The card kernel and its vendor modules (issue 24 points 1-2, decisions VK1-VK5): the ADLINK state lives in the
// ADLINK module, created on first use and owned by the card; a card that never runs an ADLINK command has none; the
// status words read the power-on values without it; a card reset clears the module; the scope reads vendor words
// only through the functions it is given.
#include <gtest/gtest.h>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/vendor/scope_words.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace sm = servobench::motion;
namespace va = servobench::vendor::adlink;
using servobench::test::aps_axis;

namespace {

sm::AdlinkPtpParams ptp(double pos) {
  sm::AdlinkPtpParams p;
  p.pos = pos;
  p.vm = 40000;
  p.acc = p.dec = 4e5;
  return p;
}

}  // namespace

TEST(VendorModules, AdlinkModuleIsCreatedOnFirstUseAndOwnedByTheCard) {
  mc::Card c(4, aps_axis());
  EXPECT_EQ(va::adlink_if_any(c), nullptr);
  c.axis_on(0);
  c.run(10);
  EXPECT_EQ(va::adlink_if_any(c), nullptr);  // running, status reads: no module
  EXPECT_TRUE(va::in_position(c, 0));         // the power-on INP band (10 pulse)
  EXPECT_EQ(va::adlink_state(c, 0).error_level_pulse, 0.0);
  va::AdlinkAxes& m = va::adlink(c);
  EXPECT_EQ(va::adlink_if_any(c), &m);
  EXPECT_EQ(&va::adlink(c), &m);  // one module per card
  m.set_move_event_distances(0, 2000, 1000);
  m.move_ptp(0, ptp(10000));
  c.run(3000);
  EXPECT_TRUE(va::adlink_state(c, 0).pre_event && va::adlink_state(c, 0).post_event);
  c.reset();  // GT_Reset / APS_initial: the module's state back to power-on, the module stays attached
  EXPECT_EQ(va::adlink_if_any(c), &m);
  EXPECT_FALSE(va::adlink_state(c, 0).pre_event || va::adlink_state(c, 0).post_event);
  EXPECT_EQ(va::adlink_state(c, 0).pre_event_dist, 0.0);
  EXPECT_THROW(va::adlink_state(c, 4), std::invalid_argument);  // the kernel's one axis check
}

TEST(VendorModules, ScopeReadsVendorWordsOnlyThroughTheGivenFunctions) {
  mc::Card c(4, aps_axis());
  c.axis_on(0);
  mc::CardScope& s = c.scope();
  EXPECT_EQ(s.words().msts, nullptr);
  s.set_watch(0, 0, 1u << static_cast<int>(va::ApsMsts::MDN), 0);
  va::adlink(c).move_ptp(0, ptp(2000));
  c.run(1);
  c.run_until_event(4000);
  EXPECT_TRUE(s.fired().empty());  // no words given: MSTS reads 0, nothing fires
  s.set_words(servobench::vendor::scope_words());
  va::adlink(c).move_ptp(0, ptp(0));
  c.run(1);
  const std::size_t ran = c.run_until_event(4000);
  ASSERT_FALSE(s.fired().empty());  // motion done fires from the ADLINK word
  EXPECT_LT(ran, 4000u);
  EXPECT_FALSE(c.moving(0));
}
