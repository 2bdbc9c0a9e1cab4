// The GUC-ECAT / iDEABOX set-up commands as C++ vendor functions (vendor/googol/gts_commands.hpp; issue 24 point 2,
// decisions GU1-): every bad argument returns the manual's 7 (never a throw), a command the card refuses in its
// state returns 1 with nothing changed, and a valid one does what the Python dialect did (units per ms).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/googol/gts_card.hpp"
#include "servobench/vendor/googol/gts_commands.hpp"
#include "servobench/vendor/googol/gts_config.hpp"

namespace mc = servobench::machine;
namespace vg = servobench::vendor::googol;
using vg::GucCode;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

vg::GtsCrdPrm xy() {
  vg::GtsCrdPrm p;
  p.dimension = 2;
  p.profile = {1, 2, 0, 0, 0, 0, 0, 0};
  p.syn_vel_max = 500;
  p.syn_acc_max = 1;
  return p;
}
}  // namespace

TEST(GtsCommands, TrapAndJogParametersInPulsePerMsSquared) {
  mc::Card card(8, servobench::test::tuned_axis(1e-3));  // 1 ms tick: pulse/ms^2 = pulse/tick^2
  EXPECT_EQ(vg::gts_set_trap_prm(card, 2, 0.5, 0.5, 0, 0), GucCode::Success);
  EXPECT_DOUBLE_EQ(card.state(1).staged.acc, 0.5);
  for (double bad : {0.0, -1.0, kNaN, std::numeric_limits<double>::infinity()})
    EXPECT_EQ(vg::gts_set_trap_prm(card, 2, bad, 0.5, 0, 0), GucCode::ParameterError) << bad;
  EXPECT_EQ(vg::gts_set_trap_prm(card, 9, 0.5, 0.5, 0, 0), GucCode::ParameterError);   // 8 profiles
  EXPECT_EQ(vg::gts_set_trap_prm(card, 1.5, 0.5, 0.5, 0, 0), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_set_trap_prm(card, 2, 0.5, 0.5, 1, 0), GucCode::ParameterError);   // velStart not simulated
  EXPECT_DOUBLE_EQ(card.state(1).staged.acc, 0.5);                                     // unchanged
  EXPECT_EQ(vg::gts_set_jog_prm(card, 3, 0.25, 0.25, 0.5), GucCode::Success);
  EXPECT_DOUBLE_EQ(vg::gts(card).jog_smooth(2), 0.5);
  EXPECT_EQ(vg::gts_set_jog_prm(card, 3, 0.25, 0.25, 1.5), GucCode::ParameterError);
  EXPECT_DOUBLE_EQ(vg::gts(card).jog_smooth(2), 0.5);
}

TEST(GtsCommands, CrdPrmChecksTheManualsRulesAndDropsTheLookAhead) {
  mc::Card card(4, servobench::test::tuned_axis(1e-3));
  EXPECT_EQ(vg::gts_get_crd_prm(card, 1).first, GucCode::CommandError);  // not set up
  EXPECT_EQ(vg::gts_get_crd_prm(card, 3).first, GucCode::ParameterError);
  vg::GtsCrdPrm p = xy();
  p.profile = {1, 1, 0, 0};  // a coordinate mapped twice (L785)
  EXPECT_EQ(vg::gts_set_crd_prm(card, 1, p), GucCode::ParameterError);
  p = xy();
  p.profile = {0, 0, 0, 0, 1, 2};  // profiles 5, 6 on a 4-axis card
  EXPECT_EQ(vg::gts_set_crd_prm(card, 1, p), GucCode::ParameterError);
  p = xy();
  p.dimension = 3;  // a dimension the profiles do not fill
  EXPECT_EQ(vg::gts_set_crd_prm(card, 1, p), GucCode::ParameterError);
  p = xy();
  p.syn_vel_max = 32767;  // (0, 32767)
  EXPECT_EQ(vg::gts_set_crd_prm(card, 1, p), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_set_crd_prm(card, kNaN, xy()), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_init_lookahead(card, 1, 0, 5, 1, 200), GucCode::CommandError);  // no crd yet
  ASSERT_EQ(vg::gts_set_crd_prm(card, 1, xy()), GucCode::Success);
  const auto [code, prm] = vg::gts_get_crd_prm(card, 1);
  EXPECT_EQ(code, GucCode::Success);
  EXPECT_EQ(prm.dimension, 2);
  EXPECT_DOUBLE_EQ(prm.syn_vel_max, 500);
  EXPECT_EQ(vg::gts_init_lookahead(card, 1, 0, 0, 1, 200), GucCode::ParameterError);  // T in (0, 1000]
  EXPECT_EQ(vg::gts_init_lookahead(card, 1, 2, 5, 1, 200), GucCode::ParameterError);  // fifo 0..1
  ASSERT_EQ(vg::gts_init_lookahead(card, 1, 0, 5, 1, 200), GucCode::Success);
  EXPECT_EQ(vg::gts(card).lookahead(1, 0), 200);
  EXPECT_EQ(vg::gts_crd_data(card, 1, true, 0), GucCode::Success);
  EXPECT_EQ(vg::gts_crd_data(card, 1, false, 0), GucCode::ParameterError);  // raw records: not simulated
  ASSERT_EQ(vg::gts_set_crd_prm(card, 1, xy()), GucCode::Success);
  EXPECT_EQ(vg::gts(card).lookahead(1, 0), 0);  // a new GT_SetCrdPrm drops the window
}

TEST(GtsCommands, StopChecksTheMaskAndStopsAMovingAxis) {
  mc::Card card(4, servobench::test::tuned_axis(1e-3));
  EXPECT_EQ(vg::gts_stop(card, -1, 0), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_stop(card, 1, 0.5), GucCode::ParameterError);
  card.axis_on(0);
  servobench::test::t_move(card, 0, 100000, 10, 0.1);
  card.run(200);
  ASSERT_TRUE(card.moving(0));
  EXPECT_EQ(vg::gts_stop(card, 1, 1), GucCode::Success);  // abrupt
  card.run(2);
  EXPECT_FALSE(card.moving(0));
}

TEST(GtsCommands, PvtTablesUseTheFirstCountPointsAndReturnCodes) {
  mc::Card card(4, servobench::test::tuned_axis(1e-3));
  const std::vector<double> t{0, 100, 200, 999}, p{0, 500, 1000, 7}, v{0, 5, 0, 0};
  EXPECT_EQ(vg::gts_pvt_table(card, 1, 3, t, p, v), GucCode::Success);
  ASSERT_NE(card.modes().pvt_tables().table(1), nullptr);
  EXPECT_EQ(card.modes().pvt_tables().table(1)->time_ms.size(), 3u);
  EXPECT_EQ(vg::gts_pvt_table(card, 33, 3, t, p, v), GucCode::ParameterError);  // table 1..32
  EXPECT_EQ(vg::gts_pvt_table(card, 2, 5, t, p, v), GucCode::ParameterError);   // count > the arrays
  EXPECT_EQ(vg::gts_pvt_table(card, 2, 2.5, t, p, v), GucCode::ParameterError);
  const std::vector<double> back{0, 100, 50};
  EXPECT_EQ(vg::gts_pvt_table(card, 2, 3, back, p, v), GucCode::ParameterError);  // times must increase
  EXPECT_EQ(vg::gts_pvt_table_complete(card, 3, 3, t, p, 0, 0), GucCode::Success);
  const auto [c, vel] = vg::gts_pvt_percent_calculate(3, t, p, {0, 0, 0}, 0);
  EXPECT_EQ(c, GucCode::Success);
  ASSERT_EQ(vel.size(), 3u);
  EXPECT_DOUBLE_EQ(vel[1], 2 * 500.0 / 100 - 0);  // v[i+1] = 2 (p[i+1] - p[i]) / (t[i+1] - t[i]) - v[i]
  EXPECT_EQ(vg::gts_pvt_percent_calculate(4, t, p, {0, 0, 0}, 0).first, GucCode::ParameterError);
}

TEST(GtsConfig, SystemCallsCheckTheirRangesAndReadBack) {
  mc::Card card(4, servobench::test::tuned_axis(1e-3));
  EXPECT_EQ(vg::gts_limits(card, 1, 0, false), GucCode::CommandError);  // one enable per axis (GS3)
  EXPECT_EQ(vg::gts_limits(card, 1, -1, false), GucCode::Success);
  EXPECT_FALSE(card.state(0).limits.enabled);
  EXPECT_EQ(vg::gts_limits(card, 1, 2, true), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_limit_sense(card, 0b10), GucCode::Success);
  EXPECT_TRUE(card.state(0).limits.neg_active_low);
  EXPECT_EQ(vg::gts_limit_sense(card, 0x10000), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_enc_sense(card, 1), GucCode::CommandError);  // reversed count: not simulated (GS4)
  EXPECT_EQ(vg::gts_scale(card, 1, 3, 3), GucCode::Success);
  EXPECT_EQ(vg::gts_scale(card, 1, 3, 0), GucCode::ParameterError);
  EXPECT_EQ(vg::gts_get_di(card, 3).first, GucCode::CommandError);  // MC_HOME not wired (GS6)
  EXPECT_EQ(vg::gts_get_di(card, kNaN).first, GucCode::ParameterError);
  EXPECT_EQ(vg::gts_set_adc_filter(card, 1, 10), GucCode::CommandError);
  EXPECT_EQ(vg::gts_get_stop_dec(card, 5), std::make_tuple(GucCode::ParameterError, 0.0, 0.0));
  ASSERT_EQ(vg::gts(card).set_stop_dec(2, 0.5, 4), GucCode::Success);
  EXPECT_EQ(vg::gts_get_stop_dec(card, 2), std::make_tuple(GucCode::Success, 0.5, 4.0));
  ASSERT_EQ(vg::gts_set_jog_prm(card, 1, 0.25, 0.25, 0.5), GucCode::Success);
  EXPECT_EQ(vg::gts_get_acc(card, 1), std::make_tuple(GucCode::Success, 0.25, 0.5));
  EXPECT_EQ(vg::gts_get_vel_filter(card, 1, true), std::make_pair(GucCode::Success, 0));
  EXPECT_EQ(vg::gts_set_stop_io(card, 0, 0, 4, 1), GucCode::ParameterError);
}

// The command runner (gts_command, decision GX1): each name of gts_command_names() is a row of the table, a NaN in
// every position returns 7 (never a throw), a valid call does what the dialect's row did and a read says its values.
TEST(GtsCommands, RunnerChecksEveryArgumentAndReadsInTheManualsUnits) {
  mc::Card card(4, servobench::test::tuned_axis(1e-3));
  std::set<std::string> rows;
  for (const auto& r : vg::gts_command_table()) rows.insert(r.name);
  for (const auto& name : vg::gts_command_names()) {
    EXPECT_TRUE(rows.count(name)) << name;
    const vg::GtsReply r = vg::gts_command(card, name, std::vector<double>(10, kNaN));
    EXPECT_EQ(r.code, GucCode::ParameterError) << name;
    EXPECT_TRUE(r.values.empty()) << name;
  }
  EXPECT_THROW(vg::gts_command(card, "GT_NoSuchCommand", {}), std::invalid_argument);
  EXPECT_EQ(vg::gts_command(card, "GT_AxisOn", {5}).code, GucCode::ParameterError);  // 4 axes
  EXPECT_EQ(vg::gts_command(card, "GT_AxisOn", {1}).code, GucCode::Success);
  EXPECT_EQ(vg::gts_command(card, "GT_PrfJog", {1}).code, GucCode::Success);
  EXPECT_EQ(vg::gts_command(card, "GT_SetVel", {1, 2.0}).code, GucCode::Success);  // pulse/ms
  EXPECT_DOUBLE_EQ(card.state(0).staged.vel, 2.0);  // 1 ms tick: pulse/ms = pulse/tick
  EXPECT_EQ(vg::gts_command(card, "GT_Update", {16}).code, GucCode::ParameterError);  // mask 1..15
  const vg::GtsReply sts = vg::gts_command(card, "GT_GetSts", {1, 1});
  EXPECT_EQ(sts.code, GucCode::Success);
  EXPECT_EQ(sts.kinds, "i");
  EXPECT_EQ(sts.values.size(), 1u);
  // a crd command before GT_SetCrdPrm: the card refuses it (1); a bad crd is 7
  EXPECT_EQ(vg::gts_command(card, "GT_LnXY", {1, 100, 0, 10, 1, 0, 0}).code, GucCode::CommandError);
  EXPECT_EQ(vg::gts_command(card, "GT_LnXY", {3, 100, 0, 10, 1, 0, 0}).code, GucCode::ParameterError);
  EXPECT_EQ(vg::gts_command(card, "GT_CrdSpace", {1, 0}).code, GucCode::CommandError);
}
