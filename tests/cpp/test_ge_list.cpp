// The GE SX path list as a card module (vendor/googol/ge_list.hpp; GE seed 001 §6, ge.md §4; decisions V100-V112,
// GV1-GV4): the buffer sequence StrtList, MvXY, lines, EndList, StrtMtn with the segment number; refusals return
// the manual's code and leave the state unchanged, with the SX command-error bit of their cause.
#include <gtest/gtest.h>

#include "card_fixtures.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/ge_list.hpp"
#include "servobench/vendor/googol/ge_registers.hpp"
#include "servobench/vendor/googol/ge_status.hpp"
#include "servobench/vendor/googol/ge_watch.hpp"

namespace mc = servobench::machine;
namespace gg = servobench::vendor::googol;

TEST(GeList, BufferRunsMvThenTwoLinesAndCountsSegments) {
  mc::Card c(4, servobench::test::tuned_axis(1e-3));  // 1 ms servo period: pulse/ms = pulse/tick
  for (std::size_t i = 0; i < 4; ++i) c.axis_on(i);
  gg::GeList& l = gg::ge_list(c);
  EXPECT_EQ(l.strt_mtn(), gg::GeCode::CommandError);  // no buffer yet: bit 9
  EXPECT_EQ(gg::ge_command_status(gg::GeVariant::SX, c), 1u << 9);
  EXPECT_EQ(l.strt_list(), gg::GeCode::Success);
  EXPECT_EQ(l.line({100, 0}, false), gg::GeCode::CommandError);  // no Mv after StrtList: bit 8
  EXPECT_EQ(gg::ge_command_status(gg::GeVariant::SX, c), 1u << 8);
  EXPECT_EQ(l.mv({0, 0}, 0, 1), gg::GeCode::SynParamError);       // feed 0: 4
  EXPECT_EQ(l.mv({0, 0}, 20, 1), gg::GeCode::Success);
  EXPECT_EQ(l.line({1000, 0}, false), gg::GeCode::Success);
  EXPECT_EQ(l.line({1000, 1000}, false), gg::GeCode::Success);
  EXPECT_EQ(l.line({2e9, 0}, false), gg::GeCode::LineLengthError);  // beyond 2^30: 3
  EXPECT_EQ(l.end_list(), gg::GeCode::Success);
  EXPECT_EQ(l.mtn_nm(), 0);
  EXPECT_EQ(l.strt_mtn(), gg::GeCode::Success);
  c.run(20);
  EXPECT_EQ(l.mtn_nm(), 1);  // the first line runs (no Mv line: the start point is where the axes are)
  c.run(400);
  EXPECT_EQ(l.mtn_nm(), 2);
  EXPECT_EQ(c.profile_pos(0), 1000);
  EXPECT_EQ(c.profile_pos(1), 1000);
  EXPECT_EQ(l.strt_list(), gg::GeCode::Success);  // stopped: a new list
  EXPECT_EQ(l.mtn_nm(), 0);
}

TEST(GeList, FeedAndOverrideRangesAndReset) {
  mc::Card c(4, servobench::test::tuned_axis(200e-6));
  gg::GeList& l = gg::ge_list(c);
  EXPECT_EQ(l.set_syn_vel(-1), gg::GeCode::SynParamError);
  EXPECT_EQ(l.set_override(2.5, false), gg::GeCode::ParameterError);  // (0, 2] (V105)
  EXPECT_EQ(l.map_cnt(5, 0), gg::GeCode::ParameterError);            // axis 1..4
  EXPECT_EQ(l.map_cnt(1, 250), gg::GeCode::Success);
  EXPECT_DOUBLE_EQ(l.state().offsets[0], 250.0);
  l.set_outputs(0x12);
  EXPECT_EQ(l.outputs(), 0x12u);
  c.reset();  // GT_Reset: the module's power-on values
  EXPECT_DOUBLE_EQ(l.state().offsets[0], 0.0);
  EXPECT_EQ(l.outputs(), 0u);
}

TEST(GeRegisters, SenseWordsCtrlModeAndReadBack) {
  mc::Card c(4, servobench::test::tuned_axis(200e-6));
  gg::GeRegisters& r = gg::ge_registers(c);
  EXPECT_EQ(r.set_sense(gg::GeSense::Limit, 0b10), gg::GeCode::Success);
  EXPECT_TRUE(c.state(0).limits.neg_active_low);
  EXPECT_EQ(r.set_sense(gg::GeSense::Home, 1), gg::GeCode::CommandError);  // a rising edge is not simulated (V93)
  EXPECT_EQ(r.set_ctrl_mode(1, 1), gg::GeCode::CommandError);              // a torque drive takes no pulses (V94)
  EXPECT_EQ(r.set_ctrl_mode(9, 0), gg::GeCode::ParameterError);            // no axis 9
  r.stage_motion(0, gg::GeMotionRegister::Vel, 3.7, 0.2);
  EXPECT_DOUBLE_EQ(c.state(0).staged.vel, 3.7 * 0.2);
  EXPECT_DOUBLE_EQ(r.read_motion(0, gg::GeMotionRegister::Vel, 0.2), 3.7);  // exactly as written
  gg::GeWatch& w = gg::ge_watch(c);  // the watch's selection: vendor/googol/ge_watch.hpp (GW4)
  EXPECT_EQ(w.set_watch({0x41, 0x2}, 100), gg::GeCode::Success);
  EXPECT_EQ(w.channels().size(), 3u);
  EXPECT_EQ(w.set_watch({0x10}, 100), gg::GeCode::ParameterError);  // bit 4 reserved
  EXPECT_EQ(w.set_watch({0x1}, 40000), gg::GeCode::ParameterError); // beyond the watch memory (V75)
}
