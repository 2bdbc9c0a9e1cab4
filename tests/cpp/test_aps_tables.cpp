// The ADLINK tables the dialect is written from (session 13, decisions AX1-AX2): the header constants
// (aps_constants.hpp) hold each name once and the module's own values, the command descriptions (aps_command_table.hpp)
// each APS_* function once, with a manual line or a decision and a non-empty description.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

#include "servobench/vendor/adlink/aps_command_table.hpp"
#include "servobench/vendor/adlink/aps_constants.hpp"
#include "servobench/vendor/adlink/aps_parameters.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace va = servobench::vendor::adlink;

namespace {

long long value_of(const char* name) {
  for (const va::ApsConstant& c : va::aps_constants())
    if (std::strcmp(c.name, name) == 0) return c.value;
  ADD_FAILURE() << name << " is not in the table";
  return -9999;
}

}  // namespace

TEST(ApsTables, ConstantsAreUniqueAndDocumented) {
  std::set<std::string> names;
  for (const va::ApsConstant& c : va::aps_constants()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
    EXPECT_GT(std::strlen(c.doc), 0u) << c.name;
    EXPECT_FALSE(c.hex && c.value < 0) << c.name << ": a negative value written in hex";
  }
  EXPECT_GE(names.size(), 245u);
}

TEST(ApsTables, ConstantsAreTheModuleValues) {
  EXPECT_EQ(value_of("ERR_NoError"), static_cast<int>(va::AdlinkCode::NoError));
  EXPECT_EQ(value_of("ERR_TimeOut"), static_cast<int>(va::AdlinkCode::TimeOut));
  EXPECT_EQ(value_of("ERR_DistantNotEnough"), -22);  // ErrorCodeDef.h (V49)
  EXPECT_EQ(value_of("PRA_VM"), va::pra::VM);
  EXPECT_EQ(value_of("PRA_VM"), 0x24);               // L2749
  EXPECT_EQ(value_of("PRA_STP_DEC"), value_of("PRA_SD_DEC"));
  EXPECT_EQ(value_of("PRA_INTEGRAL_LIMIT"), 0x12B);  // L1746-1762
  EXPECT_EQ(value_of("MTS_NSTP"), static_cast<int>(va::ApsMsts::NSTP));
  EXPECT_EQ(value_of("MIO_SMEL"), 12);               // L3611-3631
  EXPECT_EQ(value_of("STOP_ERROR_LEVEL"), va::kApsStopErrorLevel);
  EXPECT_EQ(value_of("STOP_ERROR_LEVEL"), 13);       // APS_define.h (V41)
}

TEST(ApsTables, EachFunctionIsDescribedOnce) {
  std::set<std::string> names;
  for (const auto* table : {&va::aps_commands(), &va::pt_commands()})
    for (const va::ApsCommandDoc& d : *table) {
      EXPECT_EQ(std::string(d.name).rfind("APS_", 0), 0u) << d.name;
      EXPECT_TRUE(names.insert(d.name).second) << d.name << " twice";
      EXPECT_GT(std::strlen(d.doc), 10u) << d.name;
    }
  EXPECT_GE(va::aps_commands().size(), 78u);
  EXPECT_EQ(va::pt_commands().size(), 26u);
}
