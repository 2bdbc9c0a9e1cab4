// The path interpolator at the motion cycle: the manuals' programs as test vectors, buffers, stops and
// resumes. Manual files in ../shared/seeds/: GT = 000_0c49d4aa9b235bd5.txt, GE = 001_b26ef06a365efe59.txt,
// GUC = 002_b2237d67fd2eb602.txt (digest guc-ecat.md §6.2-6.5), iDEABOX = 003_2c62cffc310de7fb.txt (ideabox.md
// §6 items 4-9). Units: pulse, ms, pulse/ms, pulse/ms^2; 1 ms motion cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "servobench/motion/generator.hpp"
#include "servobench/motion/path_generator.hpp"

namespace sm = servobench::motion;
using G = sm::PathSegmentGeometry;
using P = sm::CrdPoint;

namespace {
constexpr double kPi = 3.14159265358979323846;

struct Tick {
  double t, x, y, speed, acc, gpo;
  long long seg;
  double aux4;
};

std::vector<Tick> run(sm::PathGenerator& g, long max_ticks = 200000) {
  std::vector<Tick> out;
  for (long k = 0; k < max_ticks && !g.done(); ++k) {
    const auto& s = g.step();
    out.push_back({s.t_ms, s.pos[0], s.pos[1], s.speed, s.acc, static_cast<double>(s.do_words[0]), s.segments_done,
                   g.aux_position(4)});
  }
  return out;
}

// First tick time at which pred holds.
template <class F>
double first(const std::vector<Tick>& r, F pred) {
  for (const auto& k : r)
    if (pred(k)) return k.t;
  return -1;
}

sm::PathGenerator guc(int dim = 2, sm::PathSetup setup = {}) {
  return sm::PathGenerator(sm::CoordSystem::identity(dim), setup);
}
}  // namespace

TEST(PathVectors, GucHexagonWithBufferedIoEndsAt21500ms) {
  // GUC L802-843 (Fig 4-5), iDEABOX Ex 4-4 L1219-1370: seven 200000-pulse lines at 100 pulse/ms, 0.1 pulse/ms^2,
  // velEnd 0; BufIO 0x55 after line 2, 0xAA after line 3, BufDelay 400 after line 4, BufIO 0x55 and BufDelay 100
  // after line 5. Each line is 3000 ms: DO 0x55 at 6000, 0xAA at 9000, dwell 12000-12400, 0x55 at 15400, dwell
  // until 15500, end at 21500 ms (guc-ecat.md §6.2; +-1 cycle per buffered operation).
  auto g = guc();
  g.line({200000, 0}, 100, 0.1);
  g.line({100000, 173205}, 100, 0.1);
  g.buf_io(0, 0xffff, 0x55);
  g.line({-100000, 173205}, 100, 0.1);
  g.buf_io(0, 0xffff, 0xaa);
  g.line({-200000, 0}, 100, 0.1);
  g.buf_delay(400);
  g.line({-100000, -173205}, 100, 0.1);
  g.buf_io(0, 0xffff, 0x55);
  g.buf_delay(100);
  g.line({100000, -173205}, 100, 0.1);
  g.line({200000, 0}, 100, 0.1);
  EXPECT_EQ(g.fifo_space(), 4096 - 12);
  EXPECT_EQ(g.remaining_segments(), 7);
  g.start();
  const auto r = run(g);
  EXPECT_NEAR(r.back().t, 21500, 1);
  EXPECT_EQ(r.back().x, 200000);
  EXPECT_EQ(r.back().y, 0);
  EXPECT_EQ(r.back().seg, 7);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.gpo == 0x55; }), 6000, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.gpo == 0xaa; }), 9000, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.t > 9000 && k.gpo == 0x55; }), 15400, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 4; }), 12000, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 4 && k.speed > 0; }), 12401, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 5 && k.speed > 0; }), 15501, 1);
  for (const auto& k : r)
    if (k.t >= 12001 && k.t <= 12399) {
      EXPECT_EQ(k.speed, 0.0);
    }
  // Segment counter: cumulative completed segments (GUC L697-699); the speed never exceeds 100.
  for (const auto& k : r) EXPECT_LE(k.speed, 100.0);
}

TEST(PathVectors, GucCircleProgramTakes17424ms) {
  // GUC L857-875 (Fig 4-6), iDEABOX Ex 4-5 L1448-1592: line to (200000, 0); full CW circle (centre offset
  // (-100000, 0)); R = +200000 CCW to (0, 200000); line back to (0, 0). 3000 + 7283.19 + 4141.59 + 3000 ms.
  auto g = guc();
  g.line({200000, 0}, 100, 0.1);
  g.push_segment(G::arc_center_offset(g.tail(), {200000, 0}, 2, sm::ArcPlane::XY, -100000, 0, false), 100, 0.1);
  g.push_segment(G::arc_end_radius(g.tail(), {0, 200000}, 2, sm::ArcPlane::XY, 200000, true), 100, 0.1);
  g.line({0, 0}, 100, 0.1);
  g.start();
  const auto r = run(g);
  EXPECT_NEAR(r.back().t, 17424.78, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 2; }), 10283.19, 1);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 3; }), 14424.78, 1);
  // On the circle every sample is R = 100000 from (100000, 0).
  for (const auto& k : r)
    if (k.seg == 1) {
      EXPECT_NEAR(std::hypot(k.x - 100000, k.y), 100000, 1e-6);
    }
  EXPECT_EQ(r.back().x, 0);
  EXPECT_EQ(r.back().y, 0);
}

TEST(PathVectors, GucLookAheadExampleHoldsSpeed100) {
  // GUC L933-961 (Figs 4-12..4-14), iDEABOX Ex 4-7 L2016-2075: T = 5 ms, accMax = 1, n = 200; 300 LnXY to
  // (8000 + 1600k, 9000 + 1852k) at 100 pulse/ms, 0.8 pulse/ms^2, then GT_CrdData flush. With look-ahead the
  // path speed stays at 100 between one acceleration and one deceleration (L987-989): about 7563 ms. Without
  // it, every 2447-pulse segment is a triangle peaking at 44.25 pulse/ms: about 33.3 s.
  auto program = [](sm::PathGenerator& g) {
    for (int k = 0; k < 300; ++k) g.line({8000.0 + 1600 * k, 9000.0 + 1852 * k}, 100, 0.8);
  };
  auto g = guc();
  g.init_lookahead({5, 1, 200});
  program(g);
  EXPECT_EQ(g.fifo_size(), 100u);  // the window keeps 200 (iDEABOX L1983-2008)
  EXPECT_EQ(g.window_size(), 200u);
  EXPECT_TRUE(g.flush());
  g.start();
  const auto r = run(g);
  const double total = std::hypot(8000, 9000) + 299 * std::hypot(1600, 1852);
  EXPECT_NEAR(r.back().t, total / 100 + 100 / 0.8, 1);
  EXPECT_NEAR(r.back().t, 7563, 1);
  double vmin = 1e9;
  for (const auto& k : r)
    if (k.t > 126 && k.t < 7437) vmin = std::min(vmin, k.speed);
  EXPECT_NEAR(vmin, 100, 1e-9);
  EXPECT_EQ(r.back().x, 486400);
  EXPECT_EQ(r.back().y, 562748);

  auto off = guc();
  program(off);
  off.start();
  const auto r0 = run(off);
  double vmax = 0;
  for (const auto& k : r0) vmax = std::max(vmax, k.t > 300 ? k.speed : 0.0);
  EXPECT_NEAR(vmax, std::sqrt(0.8 * std::hypot(1600, 1852)), 0.01);  // 44.25
  EXPECT_NEAR(r0.back().t, 2 * std::sqrt(std::hypot(8000, 9000) / 0.8) + 299 * 2 * std::sqrt(std::hypot(1600, 1852) / 0.8), 2);
  EXPECT_NEAR(r0.back().t, 33300, 100);
}

TEST(PathBuffers, LookAheadAndFifoFullAt4297) {
  // iDEABOX L2000-2004: with N = 200 the 4297th push fails (200 + 4096 = 4296); the push returns 1 and the
  // segment must be sent again after GT_CrdSpace shows room (L2115-2119).
  auto g = guc();
  g.init_lookahead({5, 1, 200});
  for (int k = 1; k <= 4296; ++k) g.line({10.0 * k, 0}, 100, 1);
  EXPECT_EQ(g.fifo_space(), 0);
  EXPECT_THROW(g.line({10.0 * 4297, 0}, 100, 1), sm::MotionCommandRefused);
  EXPECT_EQ(g.remaining_segments(), 4296);
  g.start();
  while (g.fifo_space() == 0) g.step();
  g.line({10.0 * 4297, 0}, 100, 1);  // accepted once the FIFO drained
  EXPECT_FALSE(g.flush() && g.fifo_space() < 0);
  // Without look-ahead the FIFO alone refuses the 4097th entry (GUC L798, L979).
  auto h = guc();
  for (int k = 1; k <= 4096; ++k) h.line({10.0 * k, 0}, 100, 1);
  EXPECT_THROW(h.buf_delay(5), sm::MotionCommandRefused);
  EXPECT_THROW(h.line({1e6, 0}, 100, 1), sm::MotionCommandRefused);
  EXPECT_EQ(h.tail()[0], 40960);  // a refused command changes nothing
}

TEST(PathVectors, GucBufMoveModalAndNonModal) {
  // GUC L1021-1043 (Fig 4-15), iDEABOX Ex 4-8 L2163-2324: line to (200000, 200000) [3828.43 ms]; BufMove axis 4
  // to 50000 at 30 pulse/ms, 0.1 (non-modal: 1966.7 ms during the next line); line to (200000, 0) [3000 ms];
  // BufMove axis 4 to 100000 (modal: blocks the arc 6828.4..8795.1); CW semicircle about (0, 0) to
  // (-200000, 0) [7283.19 ms] ending at 16078.3 ms.
  auto g = guc();
  g.line({200000, 200000}, 100, 0.1);
  g.buf_move(4, 50000, 30, 0.1, false);
  g.line({200000, 0}, 100, 0.1);
  g.buf_move(4, 100000, 30, 0.1, true);
  g.push_segment(G::arc_center_offset(g.tail(), {-200000, 0}, 2, sm::ArcPlane::XY, -200000, 0, false), 100, 0.1);
  g.start();
  const auto r = run(g);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.aux4 > 0; }), 3828.43, 2);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.aux4 >= 50000; }), 3828.43 + 1966.67, 2);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.aux4 > 50000; }), 6828.43, 2);
  EXPECT_NEAR(first(r, [](const Tick& k) { return k.seg == 2 && k.speed > 0; }), 8795.1, 2);
  for (const auto& k : r)
    if (k.seg == 2 && k.t < 8794) {  // the modal move blocks the FIFO
      EXPECT_EQ(k.speed, 0.0);
    }
  EXPECT_NEAR(r.back().t, 16078.3, 2);
  EXPECT_EQ(r.back().aux4, 100000);
  EXPECT_NEAR(r.back().x, -200000, 1e-6);
  // Through (0, -200000): CW from angle 0 about the origin.
  double ymin = 0;
  for (const auto& k : r) ymin = std::min(ymin, k.y);
  EXPECT_NEAR(ymin, -200000, 1);
}

TEST(PathVectors, GucBufGearFollowsThePath) {
  // GUC L1080-1104 (Fig 4-16), iDEABOX Ex 4-9 L2369-2510: BufGear(4, +50000) before line 2 and before the arc:
  // axis 4 travels in proportion to the path (ratio 0.25 on the line, 0.0796 on the arc) and ends at 100000.
  auto g = guc();
  g.line({200000, 200000}, 100, 0.1);
  g.buf_gear(4, 50000);
  g.line({200000, 0}, 100, 0.1);
  g.buf_gear(4, 50000);
  g.push_segment(G::arc_center_offset(g.tail(), {-200000, 0}, 2, sm::ArcPlane::XY, -200000, 0, false), 100, 0.1);
  g.start();
  const auto r = run(g);
  EXPECT_EQ(r.back().aux4, 100000);
  double peak_line = 0, peak_arc = 0;
  for (std::size_t i = 1; i < r.size(); ++i) {
    const double v = r[i].aux4 - r[i - 1].aux4;
    if (r[i].seg == 1 && r[i - 1].seg == 1) peak_line = std::max(peak_line, v);
    if (r[i].seg == 2 && r[i - 1].seg == 2) peak_arc = std::max(peak_arc, v);
    if (r[i].seg == 0) {  // not before its segment
      EXPECT_EQ(r[i].aux4, 0.0);
    }
  }
  EXPECT_NEAR(peak_line, 25, 1e-6);
  EXPECT_NEAR(peak_arc, 100 * 50000 / (kPi * 200000), 1e-6);
}

TEST(PathStops, SmoothStopResumeAndSegmentCounter) {
  auto g = guc();
  g.line({200000, 0}, 100, 0.1);
  g.line({200000, 100000}, 100, 0.1);
  g.start();
  for (int k = 0; k < 1200; ++k) g.step();  // cruising at 100, x = 70000
  EXPECT_NEAR(g.state().pos[0], 70000, 1e-6);
  g.stop(false);  // decelerates at the segment's 0.1: 50000 further, 1000 ms
  std::vector<Tick> r = run(g, 5000);
  EXPECT_TRUE(g.stopped());
  EXPECT_NEAR(g.breakpoint()[0], 120000, 1e-6);
  EXPECT_NEAR(r.back().t, 2200, 1);
  EXPECT_EQ(g.state().segments_done, 0);  // the counter holds at a stop
  EXPECT_EQ(g.remaining_segments(), 2);
  for (int k = 0; k < 100; ++k) EXPECT_EQ(g.step().pos[0], 120000);  // it stays there
  g.start();  // resume from the breakpoint, from rest
  r = run(g);
  EXPECT_EQ(r.back().x, 200000);
  EXPECT_EQ(r.back().y, 100000);
  EXPECT_EQ(r.back().seg, 2);
  for (std::size_t i = 1; i < r.size(); ++i) EXPECT_LE(std::fabs(r[i].speed - r[i - 1].speed), 0.1 + 1e-9);
}

TEST(PathStops, AbruptStopAndReturnToTheStopPoint) {
  // GT L3336: EStpMtn sets the vector speed to 0 at once and keeps the state; GT L1940 / GE L1660: the resume
  // returns from wherever the axes are to the breakpoint along a line, stops, then continues.
  auto g = guc();
  g.line({200000, 0}, 100, 0.1);
  g.start();
  for (int k = 0; k < 1500; ++k) g.step();
  g.stop(true);
  const double x = g.state().pos[0];
  EXPECT_EQ(g.step().pos[0], x);
  EXPECT_EQ(g.state().speed, 0.0);
  EXPECT_TRUE(g.has_breakpoint());
  g.move_immediate({x, 50000}, 50, 0.5);  // leave the path (immediate mode while stopped, GT L1938)
  EXPECT_THROW(g.move_immediate({0, 0}, 50, 0.5), sm::MotionCommandRefused);  // one at a time (GE L1492)
  run(g, 10000);
  EXPECT_EQ(g.state().pos[1], 50000);
  g.start();
  bool back_on_path = false;
  for (int k = 0; k < 100000 && !g.done(); ++k) {
    const auto& s = g.step();
    if (s.pos[1] == 0 && s.pos[0] == x) back_on_path = true;
    if (back_on_path) {
      EXPECT_EQ(s.pos[1], 0);
    }
  }
  EXPECT_TRUE(back_on_path);
  EXPECT_EQ(g.state().pos[0], 200000);

  // GUC/iDEABOX: FIFO0 resumes only at its breakpoint (GUC L1005, iDEABOX L1648-1653, return code 1).
  sm::PathSetup s;
  s.return_to_stop_point = false;
  auto h = guc(2, s);
  h.line({200000, 0}, 100, 0.1);
  h.start();
  for (int k = 0; k < 1500; ++k) h.step();
  h.stop(true);
  const double hx = h.state().pos[0];
  h.move_immediate({hx, 1000}, 50, 0.5);
  run(h, 10000);
  EXPECT_THROW(h.start(), sm::MotionCommandRefused);
  h.move_immediate({hx, 0}, 50, 0.5);
  run(h, 10000);
  h.start();
  run(h);
  EXPECT_EQ(h.state().pos[0], 200000);
}

TEST(PathStops, SmoothStopAcrossSegmentsKeepsItsDeceleration) {
  // Short segments with look-ahead at full speed; a gentle stop ramp runs through several segments.
  auto g = guc();
  g.init_lookahead({5, 1, 200});
  for (int k = 1; k <= 100; ++k) g.line({1000.0 * k, 0}, 50, 1);
  g.flush();
  g.set_stop_dec(0.05, 0);
  g.start();
  for (int k = 0; k < 300; ++k) g.step();
  const long long seg_at_stop = g.state().segments_done;
  EXPECT_NEAR(g.state().speed, 50, 1e-9);
  g.stop(false);
  const auto r = run(g, 5000);
  EXPECT_TRUE(g.stopped());
  EXPECT_GT(r.back().seg, seg_at_stop + 10);  // 50^2 / 0.1 = 25000 pulse: about 25 segments
  EXPECT_NEAR(g.breakpoint()[0], g.state().pos[0], 0);
  double prev = 50;
  for (const auto& k : r) {
    EXPECT_LE(k.speed, prev + 1e-12);
    EXPECT_LE(prev - k.speed, 0.05 * (1 + 1e-9) + 1e-12);
    prev = k.speed;
  }
  g.start();
  run(g);
  EXPECT_EQ(g.state().pos[0], 100000);
  EXPECT_EQ(g.state().segments_done, 100);
}

TEST(PathFeedRules, OverrideClampAndG0) {
  // synVel above synVelMax is clamped (GUC L771); the override scales the running segment (GE L1952-1958);
  // a G0 line ends at rest even under look-ahead (GUC L322-327, L981-983) and follows the G0 override.
  sm::PathSetup s;
  s.syn_vel_max = 40;
  auto g = guc(2, s);
  g.line({100000, 0}, 100, 1);
  g.start();
  for (int k = 0; k < 200; ++k) g.step();
  EXPECT_NEAR(g.state().speed, 40, 1e-12);
  g.set_override(0.5);  // 100 x 0.5 = 50 is still clamped to 40 (GE L1958)
  g.step();
  EXPECT_NEAR(g.state().speed, 40, 1e-12);
  g.set_override(0.3);
  for (int k = 0; k < 30; ++k) g.step();
  EXPECT_NEAR(g.state().speed, 30, 1e-12);
  run(g);
  EXPECT_EQ(g.state().pos[0], 100000);

  auto h = guc();
  h.init_lookahead({5, 1, 200});
  h.line({10000, 0}, 50, 1);
  h.push_segment(G::line(h.tail(), {20000, 0}, 2), 50, 1, 0, true);  // G0
  h.line({30000, 0}, 50, 1);
  h.flush();
  h.set_g0_override(0.5);
  h.start();
  const auto r = run(h);
  double vmax_g0 = 0;
  for (const auto& k : r)
    if (k.seg == 1) vmax_g0 = std::max(vmax_g0, k.speed);
  EXPECT_NEAR(vmax_g0, 25, 1e-9);
  EXPECT_EQ(first(r, [](const Tick& k) { return k.seg == 1; }), first(r, [](const Tick& k) { return k.x >= 10000; }));
  for (const auto& k : r)
    if (k.x == 10000 || k.x == 20000) {
      EXPECT_EQ(k.speed, 0.0);
    }
}

TEST(PathFeedRules, GtOneJointRuleWithAxisAccelerationLimit) {
  // GT L1956-1963 (Strategy Two): at a corner the speed is lowered until no motor axis's velocity jump exceeds
  // its AccLmt within one cycle. A 90 deg corner changes each axis by the full speed: v_c = AccLmt * cycle.
  sm::PathSetup s;
  s.corner_axis_acc = 2;
  sm::PathGenerator g(sm::CoordSystem::identity(2), s);
  g.push_segment(G::line({0, 0}, {50000, 0}, 2), 100, 1, 0, false, true);
  g.push_segment(G::line({50000, 0}, {50000, 50000}, 2), 100, 1, 0, false, true);
  g.start();
  const auto r = run(g);
  double at_corner = -1;
  for (std::size_t i = 1; i < r.size(); ++i)
    if (r[i - 1].seg == 0 && r[i].seg == 1) at_corner = std::min(r[i - 1].speed, r[i].speed);
  EXPECT_NEAR(at_corner, 2, 1.0 + 1e-9);  // within one cycle of acceleration (1 pulse/ms^2 x 1 ms)
  EXPECT_GT(at_corner, 0);
  // Collinear: Strategy One, no slow-down at the joint.
  sm::PathGenerator h(sm::CoordSystem::identity(2), s);
  h.push_segment(G::line({0, 0}, {50000, 0}, 2), 100, 1, 0, false, true);
  h.push_segment(G::line({50000, 0}, {100000, 0}, 2), 100, 1, 0, false, true);
  h.start();
  const auto q = run(h);
  double vmin = 1e9;
  for (const auto& k : q)
    if (k.t > 100 && k.t < 900) vmin = std::min(vmin, k.speed);
  EXPECT_EQ(vmin, 100);
}

TEST(PathFeedRules, SetAxisAccOnALiveGeneratorIsTheSetupsLimit) {
  // GT_SetAccLmt (GT L1956, decision GF10): set_axis_acc(k, a) on a built generator acts as PathSetup.axis_acc_k
  sm::PathSetup s;
  s.axis_acc_1 = 2;
  s.axis_acc_2 = 2;
  sm::PathGenerator a(sm::CoordSystem::identity(2), s);
  sm::PathGenerator b(sm::CoordSystem::identity(2));
  b.set_axis_acc(1, 2);
  b.set_axis_acc(2, 2);
  EXPECT_EQ(b.setup().axis_acc_1, 2);
  EXPECT_EQ(b.setup().axis_acc_2, 2);
  for (auto* g : {&a, &b}) {
    g->push_segment(G::line({0, 0}, {50000, 0}, 2), 100, 1, 0, false, true);
    g->push_segment(G::line({50000, 0}, {50000, 50000}, 2), 100, 1, 0, false, true);
    g->start();
  }
  const auto ra = run(a);
  const auto rb = run(b);
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) EXPECT_EQ(ra[i].speed, rb[i].speed);
  EXPECT_THROW(b.set_axis_acc(0, 1), std::invalid_argument);
  EXPECT_THROW(b.set_axis_acc(5, 1), std::invalid_argument);
  EXPECT_THROW(b.set_axis_acc(1, -1), std::invalid_argument);
}

TEST(PathGenerator, MapsToMotorAxesAndRefusesBadCommands) {
  // TV34 on the generator: 2000 pulse/mm; the motor positions follow the coordinate path.
  sm::PathGenerator g(sm::CoordSystem::gt_map({{1, 2000, 0, 0, 0, 0}, {2, 0, 2000, 0, 0, 0}}));
  g.line({10, 10, 0, 0}, 0.01, 1e-5);
  g.start();
  while (!g.done()) g.step();
  const auto ax = g.coords().to_axes(g.state().pos);
  EXPECT_EQ(ax[0], 20000);
  EXPECT_EQ(ax[1], 20000);
  auto h = guc();
  EXPECT_THROW(h.line({1, 0}, 0, 1), std::invalid_argument);
  EXPECT_THROW(h.line({1, 0}, 10, -1), std::invalid_argument);
  EXPECT_THROW(h.buf_delay(16384), std::invalid_argument);
  EXPECT_THROW(h.buf_da(9, 0), std::invalid_argument);
  EXPECT_THROW(h.buf_move(1, 0, 1, 1, true), std::invalid_argument);  // a crd axis
  EXPECT_THROW(h.push_segment(G::line({5, 5}, {6, 6}, 2), 1, 1), std::invalid_argument);  // not at the tail
  auto four = sm::PathGenerator(sm::CoordSystem::identity(4));
  EXPECT_THROW(four.init_lookahead({5, 1, 200}), std::invalid_argument);  // <= 3 axes (GUC L985)
}
