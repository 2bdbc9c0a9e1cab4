// The GE commands C++ runs with their argument checks (vendor/googol/ge_commands.hpp, GW1-GW3) and the GE data watch
// (vendor/googol/ge_watch.hpp, GW4).
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/ge_commands.hpp"
#include "servobench/vendor/googol/ge_watch.hpp"

namespace mc = servobench::machine;
namespace gg = servobench::vendor::googol;

TEST(GeCommands, ArgumentChecksReturnTheManualsCodes) {
  mc::Card c(4, servobench::test::tuned_axis(200e-6));
  const auto px = gg::GeVariant::PX;
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetPos", {5, 100}).code, gg::GeCode::ParameterError);  // no axis 5
  EXPECT_EQ(c.last_fault(), mc::CommandFault::IllegalControlParam);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetPos", {1, 2e9}).code, gg::GeCode::ParameterError);  // beyond 2^30 - 1
  EXPECT_EQ(c.last_fault(), mc::CommandFault::MotionParamOverflow);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetPos", {1, 0.5}).code, gg::GeCode::ParameterError);  // whole pulses
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetPos", {1, 1000}).code, gg::GeCode::Success);
  const gg::GeReply pos = gg::ge_command(c, px, "GT_GetPos", {1});
  EXPECT_TRUE(pos.read && pos.integer);
  EXPECT_EQ(pos.value, 1000);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetKp", {1, 40000}).code, gg::GeCode::ParameterError);  // 0..32767
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetKp", {1, 12.5}).code, gg::GeCode::Success);         // a double (V87)
  EXPECT_EQ(gg::ge_command(c, px, "GT_GetKp", {1}).value, 12.5);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetVel", {1, -1}).code, gg::GeCode::ParameterError);  // < 0: velocity mode only
  EXPECT_EQ(gg::ge_command(c, px, "GT_PrflV", {1}).code, gg::GeCode::Success);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetVel", {1, -1}).code, gg::GeCode::Success);
  EXPECT_EQ(gg::ge_command(c, px, "GT_GetVel", {1}).value, -1);                           // exactly as written
  EXPECT_EQ(gg::ge_command(c, px, "GT_MltiUpdt", {0x10000}).code, gg::GeCode::ParameterError);
  EXPECT_EQ(gg::ge_command(c, px, "GT_SetMtrCmd", {1, 0}).code, gg::GeCode::Success);
  // a card refusal is 1: CloseLp with the servo on
  EXPECT_EQ(gg::ge_command(c, px, "GT_AxisOn", {1}).code, gg::GeCode::Success);
  EXPECT_EQ(gg::ge_command(c, px, "GT_CloseLp", {1}).code, gg::GeCode::CommandError);
  EXPECT_EQ(c.last_fault(), mc::CommandFault::AxisStateError);
  // SX: the drive-alarm input may not change with the servo on (cmd bit 3); PX may
  EXPECT_EQ(gg::ge_command(c, gg::GeVariant::SX, "GT_AlarmOff", {1}).code, gg::GeCode::CommandError);
  EXPECT_EQ(gg::ge_command(c, px, "GT_AlarmOff", {1}).code, gg::GeCode::Success);
  EXPECT_THROW(gg::ge_command(c, px, "GT_NoSuchCommand", {}), std::invalid_argument);
}

TEST(GeCommands, EveryCommandRunIsARowOfTheTable) {
  std::set<std::string> rows;
  for (const gg::GeCommandRow& r : gg::ge_command_table()) {
    EXPECT_TRUE(rows.insert(r.name).second) << r.name;  // described once
    EXPECT_GT(std::string(r.doc).size(), 10u) << r.name;
  }
  for (const std::string& name : gg::ge_axis_command_names()) {
    if (name == "GT_GetPrfVel") continue;  // the PX form of a class method (its doc is the method's)
    EXPECT_EQ(rows.count(name), 1u) << name;
  }
}

TEST(GeWatch, BlocksInGeUnits) {
  mc::Card c(4, servobench::test::tuned_axis(200e-6));
  gg::GeWatch& w = gg::ge_watch(c);
  std::vector<std::vector<double>> block;
  EXPECT_EQ(w.start(0), gg::GeCode::CommandError);       // before SetWatch
  EXPECT_EQ(w.next_block(block), gg::GeCode::CommandError);
  ASSERT_EQ(w.set_watch({0x5}, 10), gg::GeCode::Success);  // axis 1: profile position and velocity
  EXPECT_EQ(w.start(70000), gg::GeCode::ParameterError);   // n 0..65535
  ASSERT_EQ(w.start(1), gg::GeCode::Success);              // every 2 ticks
  c.stage_vel(0, 2.0);                                     // 2 pulse/tick = 10 pulse/ms at 200 us
  c.stage_acc(0, 1e6);
  c.stage_pos(0, 1e6);
  c.set_mode(0, mc::AxisMode::Jog);
  c.axis_on(0);
  c.update(1u);
  c.run(10);
  EXPECT_EQ(w.next_block(block), gg::GeCode::Success);
  EXPECT_TRUE(block.empty());                              // 5 of 10 samples
  c.run(30);
  EXPECT_EQ(w.next_block(block), gg::GeCode::Success);
  ASSERT_EQ(block.size(), 2u);
  ASSERT_EQ(block[0].size(), 10u);
  EXPECT_DOUBLE_EQ(block[1].back(), 10.0);                 // pulse/ms
  EXPECT_EQ(block[0][9] - block[0][8], 4.0);               // whole pulses, 2 ticks apart
  w.stop();
  EXPECT_EQ(w.next_block(block), gg::GeCode::Success);
  EXPECT_TRUE(block.empty());                              // unread blocks dropped
}
