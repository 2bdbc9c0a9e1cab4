// FollowEx (electronic cam): the iDEABOX examples and the segment-type rules. Manual: ../shared/seeds/
// 003_2c62cffc310de7fb.txt (iDEABOX advanced manual; digest ideabox.md §2.1 and §6 items 1-2).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "servobench/motion/follow_ex.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/jog.hpp"

namespace sm = servobench::motion;
using V = std::vector<double>;
using T = sm::FollowSegmentType;

namespace {
// The examples' master: axis 1 jogging at 50 pulse/ms with acc 1 pulse/ms^2 (003 L716-740), 1 ms tick;
// element k is the master position after k ticks.
V jog_master(long ticks) {
  sm::ProfileGenerator g(0.0, 1e-3);
  g.command(sm::GeJogParams{50, 1});
  V m{g.state().pos};
  for (long k = 0; k < ticks; ++k) m.push_back(g.step().pos);
  return m;
}
}  // namespace

// iDEABOX Ex 4-1 (003 L554-742): NORMAL (20000, 10000) 60 %, 1000 x EVEN (20, 20), STOP (20000, 10000) 60 %,
// cumulative values; memory 2 with max 5000; PASS at 50000 going positive; infinite loop.
TEST(FollowExVectors, IdeaboxEx4_1_PercentCamStartsOnPass) {
  sm::FollowExSetup s;
  s.max_segment = 5000;
  s.memory = 2;
  s.event = 2;
  s.master_dir = 1;
  s.event_pos = 50000;
  s.loop = 0;
  sm::FollowEx f(s);
  EXPECT_EQ(f.space(0), 5000);
  double m = 20000, sl = 10000;
  f.data_percent(m, sl, T::Normal, 60);
  for (int i = 2; i <= 1001; ++i) f.data_percent(m += 20, sl += 20, T::Even, 0);
  f.data_percent(m + 20000, sl + 10000, T::Stop, 60);
  EXPECT_EQ(f.size(0), 1002);
  const V master = jog_master(3000);
  f.start(master[0], 0);
  V pos, ratio;
  for (std::size_t k = 1; k < master.size(); ++k) {
    pos.push_back(f.step(master[k]).pos);
    ratio.push_back(f.ratio());
  }
  auto at = [&](const V& v, int ms) { return v[static_cast<std::size_t>(ms - 1)]; };
  // The master reaches 50 pulse/ms after 50 ms and 1250 pulses, and passes 50000 at 1025 ms.
  EXPECT_DOUBLE_EQ(master[1025], 50000.0);
  EXPECT_EQ(at(pos, 1024), 0.0);
  EXPECT_EQ(at(pos, 1025), 0.0);
  EXPECT_GT(at(pos, 1026), 0.0);
  // Ratio 0 -> 1 over 20000 master pulses (400 ms), 1 for 20000, 1 -> 0 over 20000.
  EXPECT_NEAR(at(ratio, 1025 + 200), 0.5, 1e-12);  // the S ramp is point-symmetric
  EXPECT_NEAR(at(pos, 1025 + 400), 10000.0, 1e-9);
  EXPECT_NEAR(at(ratio, 1025 + 600), 1.0, 1e-12);
  EXPECT_NEAR(at(pos, 1025 + 600) - at(pos, 1025 + 599), 50.0, 1e-9);  // slave at the master's speed
  EXPECT_NEAR(at(pos, 1025 + 800), 30000.0, 1e-9);
  EXPECT_NEAR(at(pos, 1025 + 1200), 40000.0, 1e-9);  // 40000 per 60000 master pulses per loop
  EXPECT_NEAR(at(pos, 1025 + 1600), 50000.0, 1e-9);  // the next pass starts at ratio 0 again
  EXPECT_NEAR(at(ratio, 1025 + 1201), 0.0, 1e-3);
  EXPECT_EQ(f.loop_count(), 1);
  EXPECT_TRUE(f.moving());
  // The ratio is continuous over the whole pass (NORMAL -> EVEN -> STOP -> NORMAL all meet).
  double worst = 0;
  for (std::size_t k = 1027; k < ratio.size(); ++k) worst = std::max(worst, std::fabs(ratio[k] - ratio[k - 1]));
  EXPECT_LT(worst, 0.01);
}

// iDEABOX Ex 4-2 (003 L744-929): Complete, 15 knots, ratio 1.0 at both ends, memory 1 (512), event START.
TEST(FollowExVectors, IdeaboxEx4_2_CompleteCam) {
  const V mpos{80413.3639047272, 157154.737891984, 234538.731662469, 312552.345216181, 391204.578553119,
               470496.431673285, 550428.904576678, 630986.997263298, 712186.709733145, 794025.041986219,
               876494.994022521, 959612.56584205,  1043352.7574448,  1127738.56883079, 1212761};
  V spos;
  for (int k = 0; k < 15; ++k) spos.push_back(40000.0 + 80000.0 * k);
  const auto segs = sm::follow_complete_segments(mpos, spos, 1.0, 1.0);
  ASSERT_EQ(segs.size(), 14u);
  const auto cam = sm::plan_follow_cam(segs, 0.0);
  // Node ratios of the clamped C2 spline (digest ideabox.md §6 item 2, DERIVED).
  const V expect{1.0, 1.0507, 1.0262, 1.0222, 1.0128, 1.0049, 0.9969, 0.9892, 0.9814, 0.9737, 0.9666, 0.9577,
                 0.9562, 0.9277, 1.0};
  for (std::size_t i = 0; i < 14; ++i) EXPECT_NEAR(cam.ratio_begin[i], expect[i], 5e-5) << i;
  EXPECT_NEAR(cam.ratio_end.back(), 1.0, 1e-12);
  EXPECT_NEAR(cam.slave_length, 1120000.0, 1e-6);
  EXPECT_NEAR(cam.length, 1212761 - 80413.3639047272, 1e-6);
  sm::FollowExSetup s;
  s.memory = 1;
  s.loop = 0;
  sm::FollowEx f(s);
  f.data_complete(mpos, spos, 1.0, 1.0, 0);
  EXPECT_EQ(f.space(0), 512 - 14);
  const V master = jog_master(30000);
  f.start(master[0], 0);
  V pos;
  for (std::size_t k = 1; k < master.size(); ++k) pos.push_back(f.step(master[k]).pos);
  // The slave passes each knot when the master has travelled the knot's master distance from the start.
  for (std::size_t i = 1; i < 15; ++i) {
    const double x = mpos[i] - mpos[0];
    EXPECT_NEAR(cam.slave_at(x), spos[i] - spos[0], 1e-6) << i;
  }
  // One pass is 1132347.6 master pulses = 22672 ms at 50 pulse/ms (after the 50 ms ramp).
  EXPECT_EQ(f.loop_count(), 1);
  EXPECT_NEAR(pos.back(), 1120000.0 + cam.slave_at(master.back() - cam.length), 1e-6);
}

// The four segment types' ratio rules (003 L516-530, L4718-4726), and CONTINUE across a FIFO switch.
TEST(FollowExTypes, RatioRules) {
  std::vector<sm::FollowSegmentData> s{{1000, 500, T::Normal, 0}, {1000, 1000, T::Normal, 0},
                                       {1000, 2000, T::Even, 0},  {1000, 1000, T::Stop, 50},
                                       {1000, 500, T::Normal, 0}};
  const auto cam = sm::plan_follow_cam(s, 0.7);
  EXPECT_EQ(cam.ratio_begin, (V{0.0, 1.0, 2.0, 2.0, 0.0}));
  EXPECT_EQ(cam.ratio_end, (V{1.0, 1.0, 2.0, 0.0, 1.0}));
  s[0].type = T::Continue;
  const auto c2 = sm::plan_follow_cam(s, 0.7);
  EXPECT_DOUBLE_EQ(c2.ratio_begin[0], 0.7);  // the previous FIFO's end ratio
  EXPECT_DOUBLE_EQ(c2.ratio_end[0], 1.0 - 0.7);
  EXPECT_NEAR(c2.slave_at(1000), 500.0, 1e-9);
  // Negative master displacements: the ratio keeps its sign convention dS/dM.
  std::vector<sm::FollowSegmentData> neg{{-1000, 500, T::Normal, 0}, {-1000, -500, T::Even, 0}};
  const auto cn = sm::plan_follow_cam(neg, 0.0);
  EXPECT_DOUBLE_EQ(cn.ratio_end[0], -1.0);
  EXPECT_DOUBLE_EQ(cn.ratio_begin[1], 0.5);
  EXPECT_NEAR(cn.slave_at(1000), 500.0, 1e-9);
  EXPECT_NEAR(cn.ratio_at(500), -0.5, 1e-12);
}

TEST(FollowExFifo, SwitchContinueLoopsAndDirection) {
  sm::FollowExSetup s;
  s.loop = 2;
  sm::FollowEx f(s);
  f.data_percent(1000, 1000, T::Even, 0, 0);
  f.data_percent(1000, 500, T::Continue, 0, 1);  // r 1 -> 0 in FIFO 1
  EXPECT_THROW(f.switch_fifo(), sm::MotionCommandRefused);  // only while moving (L5291-5293)
  f.start(0.0, 0);
  f.step(500);
  EXPECT_NEAR(f.state().pos, 500.0, 1e-12);
  EXPECT_THROW(f.clear(0), sm::MotionCommandRefused);  // in use (L4619)
  f.switch_fifo();
  f.step(1500);  // pass of FIFO 0 ends at 1000; FIFO 1 from there, starting at ratio 1 (CONTINUE)
  EXPECT_EQ(f.active_fifo(), 1);
  EXPECT_NEAR(f.ratio(), 0.5, 1e-12);
  EXPECT_NEAR(f.state().pos, 1000.0 + 375.0, 1e-9);
  f.step(2000);
  EXPECT_NEAR(f.state().pos, 1500.0, 1e-9);
  f.step(3000);  // loop 2 of FIFO 1 ends the motion
  EXPECT_NEAR(f.state().pos, 2000.0, 1e-9);
  EXPECT_FALSE(f.moving());
  EXPECT_EQ(f.loop_count(), 2);
  f.step(5000);
  EXPECT_NEAR(f.state().pos, 2000.0, 1e-9);
  // dir = 1: negative master motion is ignored (L6185).
  sm::FollowExSetup d;
  d.dir = 1;
  d.loop = 0;
  sm::FollowEx g(d);
  g.data_percent(100, 100, T::Even, 0);
  g.start(0.0);
  g.step(50);
  g.step(20);
  EXPECT_NEAR(g.state().pos, 50.0, 1e-12);
  g.step(40);
  EXPECT_NEAR(g.state().pos, 70.0, 1e-12);
  // dir = 0: the slave goes back with the master, across a pass boundary too.
  sm::FollowExSetup b;
  b.loop = 0;
  sm::FollowEx h(b);
  h.data_percent(100, 200, T::Even, 0);
  h.start(0.0);
  h.step(150);
  EXPECT_NEAR(h.state().pos, 300.0, 1e-12);
  h.step(80);
  EXPECT_NEAR(h.state().pos, 160.0, 1e-12);
  // PASS going negative at -500 (L7224-7240).
  sm::FollowExSetup p;
  p.event = 2;
  p.master_dir = -1;
  p.event_pos = -500;
  sm::FollowEx q(p);
  q.data_percent(-1000, 1000, T::Even, 0);
  q.start(0.0);
  q.step(-400);
  EXPECT_TRUE(q.waiting());
  q.step(-600);
  EXPECT_FALSE(q.waiting());
  EXPECT_NEAR(q.state().pos, 100.0, 1e-12);
}

TEST(FollowExFifo, SizesAndRefusals) {
  sm::FollowEx f;  // memory 0: 16 segments per FIFO (L489-493)
  EXPECT_EQ(f.space(0), 16);
  for (int i = 1; i <= 16; ++i) f.data_percent(100.0 * i, 50.0 * i, T::Even, 0, 0);
  EXPECT_EQ(f.space(0), 0);
  EXPECT_THROW(f.data_percent(1700, 850, T::Even, 0, 0), sm::MotionCommandRefused);  // full: data lost
  EXPECT_EQ(f.size(0), 16);
  V m, s;
  for (int i = 0; i < 18; ++i) m.push_back(100.0 * i), s.push_back(10.0 * i);
  EXPECT_THROW(f.data_complete(m, s, 0, 0, 1), sm::MotionCommandRefused);  // 17 segments > 16
  EXPECT_EQ(f.size(1), 0);
  m.pop_back();
  s.pop_back();
  f.data_complete(m, s, 0, 0, 1);
  EXPECT_EQ(f.space(1), 0);
  sm::FollowEx e;
  EXPECT_THROW(e.start(0.0, 0), sm::MotionCommandRefused);  // empty FIFO (L4997-5003)
  EXPECT_THROW(e.data_percent(0, 10, T::Normal, 0), std::invalid_argument);  // no master displacement
  EXPECT_THROW(e.data_percent(10, 10, T::Normal, 101), std::invalid_argument);
  EXPECT_THROW(e.data_percent(10, 10, T::Normal, 0, 2), std::invalid_argument);
  e.data_percent(10, 10, T::Normal, 0);
  EXPECT_THROW(e.data_percent(5, 10, T::Normal, 0), std::invalid_argument);  // reverses the cam direction
  sm::FollowExSetup bad;
  bad.memory = 2;  // max_segment not set
  EXPECT_THROW(sm::FollowEx{bad}, std::invalid_argument);
}
