// The ADLINK APS runner (vendor/adlink/aps_commands.hpp, session 14, decisions AY1-AY5): every function checks its
// arguments and returns the manual's code, never throws; a refusal of the card comes back as the code of the fault
// the card recorded (EMG / ALM / a limit toward the move: ignored, ERR_NoError).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_commands.hpp"
#include "card_fixtures.hpp"

namespace mc = servobench::machine;
namespace va = servobench::vendor::adlink;
using servobench::test::aps_axis;
using va::AdlinkCode;
using va::ApsArgs;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Valid-looking arguments of a shape: 0 for a number, {0, 1} for an array.
ApsArgs plain(const std::string& kinds) {
  ApsArgs a;
  for (char k : kinds) a.push_back(k == 'a' ? std::vector<double>{0.0, 1.0} : std::vector<double>{0.0});
  return a;
}

}  // namespace

TEST(ApsCommands, NotANumberInAnyArgumentOfAnyFunctionIsParametersInvalid) {
  mc::Card card(4, aps_axis());
  for (const va::ApsCommandShape& s : va::aps_command_shapes()) {
    for (std::size_t k = 0; k < s.args.size(); ++k) {
      ApsArgs a = plain(s.args);
      a[k] = {kNaN};
      va::ApsReply r;
      ASSERT_NO_THROW(r = va::aps_command(&card, s.name, a)) << s.name << " argument " << k;
      const double code = s.reply == "w" ? r.values.at(0) : static_cast<double>(r.code);
      EXPECT_EQ(code, static_cast<double>(AdlinkCode::ParametersInvalid)) << s.name << " argument " << k;
      EXPECT_EQ(r.kinds, s.reply) << s.name;
      if (!s.reply.empty() && s.reply != "w") {
        EXPECT_EQ(r.values.size(), s.reply.size()) << s.name;
      }
      ASSERT_NO_THROW(r = va::aps_command(nullptr, s.name, a)) << s.name;  // no card open
      EXPECT_TRUE(r.code == AdlinkCode::DeviceNotInitial || r.code == AdlinkCode::ParametersInvalid ||
                  (s.reply == "w" && r.values.at(0) == static_cast<double>(AdlinkCode::DeviceNotInitial)))
          << s.name;
    }
  }
  EXPECT_THROW(va::aps_command(&card, "APS_no_such_function", {}), std::invalid_argument);
}

TEST(ApsCommands, PointToPointChecksInTheManualsOrderThenMoves) {
  mc::Card card(4, aps_axis());
  EXPECT_EQ(va::aps_command(&card, "APS_set_servo_on", {{0}, {1}}).code, AdlinkCode::NoError);
  // an axis outside the card, a position that is not whole, a buffer mode (bits 12-15, V32), Wait not None/0
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{4}, {0}, {1000}, {}}).code, AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{0}, {0}, {1000.5}, {}}).code, AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{0}, {0x1000}, {1000}, {}}).code, AdlinkCode::FunctionNotAvailable);
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{0}, {0}, {1000}, {1}}).code, AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_ptp_v", {{0}, {0}, {1000}, {0}, {}}).code, AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{0}, {0}, {1000}, {}}).code, AdlinkCode::NoError);
  card.run(20000);
  const va::ApsReply pos = va::aps_command(&card, "APS_get_command", {{0}});
  EXPECT_EQ(pos.code, AdlinkCode::NoError);
  EXPECT_EQ(pos.values.at(0), 1000.0);
  EXPECT_EQ(pos.kinds, "i");
  // relative (Option bit 0) from the command position
  EXPECT_EQ(va::aps_command(&card, "APS_ptp", {{0}, {1}, {500}, {0}}).code, AdlinkCode::NoError);
  card.run(20000);
  EXPECT_EQ(va::aps_command(&card, "APS_get_command_f", {{0}}).values.at(0), 1500.0);
}

TEST(ApsCommands, ALineHostsTheGroupAndAnArcChecksItsArrays) {
  mc::Card card(4, aps_axis());
  for (double i : {0.0, 1.0})
    EXPECT_EQ(va::aps_command(&card, "APS_set_servo_on", {{i}, {1}}).code, AdlinkCode::NoError);
  // a repeated axis, one axis only, a mode field beyond 6
  EXPECT_EQ(va::aps_command(&card, "APS_line", {{2}, {0, 0}, {0}, {10, 10}, {0}, {}}).code,
            AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_line", {{1}, {0}, {0}, {10}, {0}, {}}).code, AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_line", {{2}, {0, 1}, {0x7000}, {10, 10}, {0}, {}}).code,
            AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_line", {{2}, {0, 1}, {0}, {3000, 4000}, {0}, {}}).code, AdlinkCode::NoError);
  ASSERT_NE(va::adlink_group(card), nullptr);
  EXPECT_EQ(va::adlink_group(card)->array(), (std::vector<std::size_t>{0, 1}));
  card.run(40000);
  EXPECT_EQ(va::aps_command(&card, "APS_get_command", {{1}}).values.at(0), 4000.0);
  // APS_arc2_ca(Axis_ID_Array, Option, CenterArray, Angle, TransPara, Wait): a centre of 3 values on 2 axes
  EXPECT_EQ(va::aps_command(&card, "APS_arc2_ca", {{0, 1}, {0}, {0, 0, 0}, {90}, {0}, {}}).code,
            AdlinkCode::ParametersInvalid);
  EXPECT_EQ(va::aps_command(&card, "APS_arc2_ca", {{0, 1}, {0}, {0, 4000}, {90}, {0}, {}}).code, AdlinkCode::NoError);
}
