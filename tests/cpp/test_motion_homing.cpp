// Homing, capture, breakpoints, the ADLINK jog step and on-the-fly PTP at the motion and machine levels.
// Manual lines: ADLINK seed 004 (adlink.md), GT seed 000 (gt.md).
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/machine/capture.hpp"
#include "servobench/machine/motion_loop.hpp"
#include "servobench/machine/sensing.hpp"
#include "servobench/motion/adlink_jog.hpp"
#include "servobench/motion/adlink_replan.hpp"
#include "servobench/motion/breakpoint.hpp"
#include "servobench/motion/home_sequence.hpp"
#include "servobench/motion/stop.hpp"

namespace sm = servobench::motion;
namespace mc = servobench::machine;

namespace {
// An ideal mechanism: the actual position is the profile position; ORG [lo, hi], limits +-el, index marks
// every `pitch` pulses at `idx`.
struct Ideal {
  double lo = 10000, hi = 14000, el = 50000, idx = 2500, pitch = 10000;
  sm::HomeInputs sense(double a, double b) const {
    sm::HomeInputs in;
    auto edge = [&](sm::SignalEvent& e, bool was, bool is, double at) {
      e.level = is;
      e.rose = is && !was;
      e.fell = was && !is;
      if (was != is) e.edge_pos = at;
    };
    const auto org = [&](double x) { return x >= lo && x <= hi; };
    edge(in.org, org(a), org(b), (a < lo) != (b < lo) ? lo : hi);
    edge(in.pel, a >= el, b >= el, el);
    edge(in.mel, a <= -el, b <= -el, -el);
    const double ka = std::floor((a - idx) / pitch), kb = std::floor((b - idx) / pitch);
    if (ka != kb) {
      in.ez.rose = true;
      in.ez.edge_pos = idx + pitch * std::max(ka, kb);
    }
    in.actual_pos = b;
    return in;
  }
};

// Runs a sequence against the ideal mechanism; returns the final position (after the reset) and the ticks.
double run_home(sm::HomeSequence& seq, sm::ProfileGenerator& gen, const Ideal& m, int max_ticks = 1000000) {
  sm::HomeInputs in = m.sense(gen.state().pos, gen.state().pos);
  double offset = 0.0;
  for (int k = 0; k < max_ticks && !seq.finished(); ++k) {
    const sm::HomeAction act = seq.step(in, gen);
    if (act.set_position) {
      offset += gen.state().pos - act.pos;
      gen.set_position(act.pos);
    }
    const double before = gen.state().pos + offset;
    gen.step();
    in = m.sense(before, gen.state().pos + offset);
    in.actual_pos -= offset;
    for (sm::SignalEvent* e : {&in.org, &in.pel, &in.mel, &in.ez}) e->edge_pos -= offset;
  }
  return offset;
}
}  // namespace

// adlink.md §10 T37, seed L2295-2303, L2372: MODE 0, DIR 1 ends at the PEL-side (right) edge of ORG, and the
// position is reset to HOME_POS there (L2252).
TEST(AdlinkHome, T37ManualExampleEndsAtTheRightEdgeOfOrg) {
  sm::ProfileGenerator gen(0.0, 250e-6);
  sm::HomeSequence seq(sm::AdlinkHomeParams{}, 250e-6);
  const double offset = run_home(seq, gen, Ideal{});
  ASSERT_TRUE(seq.done());
  EXPECT_EQ(seq.reference_pos(), 14000.0);
  EXPECT_EQ(offset, 14000.0);
  EXPECT_EQ(gen.state().pos, 0.0);
}

// ADLINK L2370 (DIR 0 -> MEL-side edge), L2391 (EZA: first EZ in the home direction), L2436-2449 (shift),
// L2459-2508 (mode 1: limit edge), L2510-2556 (mode 2: single EZ).
TEST(AdlinkHome, ModesDirectionsEzaShift) {
  struct Case {
    double mode, dir;
    bool eza;
    double shift, start, ref;
  };
  const Case cases[] = {{0, 0, false, 0, -30000, 10000}, {0, 0, true, 0, -30000, 12500}, {0, 1, false, 0, 30000, 14000},
                        {0, 0, false, 0, 12000, 10000},  {0, 0, false, 0, 30000, 10000}, {1, 0, false, 0, 0, 50000},
                        {1, 1, false, 0, 0, -50000},     {1, 0, true, 0, 0, 42500},      {2, 0, false, 0, 0, 2500},
                        {2, 1, true, 0, 0, -7500},       {0, 0, false, -300, -30000, 10000}};
  for (const Case& c : cases) {
    sm::AdlinkHomeParams p;
    p.mode = c.mode;
    p.dir = c.dir;
    p.eza = c.eza;
    p.shift = c.shift;
    p.pos = 7;
    sm::ProfileGenerator gen(c.start, 250e-6);
    sm::HomeSequence seq(p, 250e-6);
    const double offset = run_home(seq, gen, Ideal{});
    ASSERT_TRUE(seq.done()) << c.mode << " " << c.dir << " " << c.start;
    EXPECT_EQ(seq.reference_pos(), c.ref) << c.mode << " " << c.dir << " " << c.start;
    EXPECT_EQ(gen.state().pos, 7.0);                // HOME_POS
    EXPECT_EQ(offset + 7.0, c.ref + c.shift);        // rests at the reference + HOME_SHIFT
  }
}

// GT L4152-4213, Example 6-1 (L2021-2099): GT_Index(1); GT_Home(200000) ends at the index after the home
// switch, zeroed (gt.md §9 TV40, TV42).
TEST(GtHome, HomeAndIndex) {
  sm::GtHomeParams p;
  p.pos = 200000;
  p.index = true;
  sm::ProfileGenerator gen(0.0, 200e-6);
  sm::HomeSequence seq(p);
  const double offset = run_home(seq, gen, Ideal{});
  ASSERT_TRUE(seq.done());
  EXPECT_EQ(seq.reference_pos(), 12500.0);
  EXPECT_EQ(offset, 12500.0);
}

// gt.md §3.7: one-shot breakpoints on the actual position, motion complete (an edge) and home capture.
TEST(Breakpoint, OneShotConditions) {
  sm::Breakpoint b;
  EXPECT_THROW(b.set_compare(1073741824.0), std::invalid_argument);  // L4721-4727
  b.set_compare(20000);
  b.arm(sm::BreakKind::PositionAbove);
  EXPECT_FALSE(b.check(19999, true, false));
  EXPECT_TRUE(b.check(20000, true, false));  // actual >= BrkCn (L1263)
  EXPECT_EQ(b.armed(), sm::BreakKind::None);  // cleared on trigger (L1257)
  EXPECT_FALSE(b.check(30000, true, false));
  b.arm(sm::BreakKind::PositionBelow);
  EXPECT_FALSE(b.check(20001, true, false));
  EXPECT_TRUE(b.check(20000, true, false));
  b.arm(sm::BreakKind::MotionComplete);  // armed at rest: fires at the end of the next move (TV21)
  EXPECT_FALSE(b.check(0, true, false));
  EXPECT_FALSE(b.check(0, false, false));
  EXPECT_TRUE(b.check(0, true, false));
  b.arm(sm::BreakKind::Home);
  EXPECT_FALSE(b.check(0, true, false));
  EXPECT_TRUE(b.check(0, true, true));
}

// gt.md §9 TV18 (L1265-1295) with ideal tracking: Vel 1, Acc 0.1, Pos 50000, BrkCn 20000, SetVel(4) staged and
// committed by the breakpoint: 27 536.25 ST in total.
TEST(Breakpoint, Tv18IdealTiming) {
  sm::ProfileGenerator gen(0.0, 200e-6);
  gen.move_t_curve(50000, {1, 0.1});
  sm::Breakpoint b;
  b.set_compare(20000);
  b.arm(sm::BreakKind::PositionAbove);
  int k = 0;
  while (gen.moving() && k < 100000) {
    gen.step();
    ++k;
    if (b.check(gen.state().pos, !gen.moving(), false)) gen.move_t_curve(50000, {4, 0.1});
  }
  EXPECT_NEAR(k, 27536.25, 1.0);
  EXPECT_EQ(gen.state().pos, 50000.0);
}

// adlink.md §10 T36, seed L2657: the step jog's total displacement is ceil(n) * offset, n = the plain stop's
// displacement in offsets.
TEST(AdlinkJog, T36StepRoundsUpToWholeOffsets) {
  for (double sf : {0.0, 0.5}) {
    for (int on : {1, 700, 1234, 4000}) {
      sm::AdlinkJogParams p;
      p.mode = 1;
      p.offset = 1000;
      p.delay_us = 25000;
      p.sf = sf;
      sm::ProfileGenerator gen(0.0, 250e-6);
      sm::AdlinkJog jog(p, 250e-6);
      double natural = 1000.0;
      for (int k = 0; k < 200000; ++k) {
        const bool on_now = k < on;
        if (!on_now && jog.phase() == sm::JogPhase::Continuous && gen.state().acc == 0.0)
          natural = sm::plan_adlink_stop(gen.state(), 1e6 * 250e-6 * 250e-6, sf).end().pos;
        jog.step(on_now, gen);
        gen.step();
        if (k > on && jog.phase() == sm::JogPhase::Idle && !gen.moving()) break;
      }
      const double total = gen.state().pos;
      EXPECT_EQ(std::fmod(total, 1000.0), 0.0) << on;
      EXPECT_EQ(total, 1000.0 * std::ceil(natural / 1000.0 - 1e-9)) << on << " sf " << sf;
    }
  }
}

// ADLINK L2757-2767: on-the-fly PTP replans from a moving state; the end is exact and rates stay within limits.
TEST(AdlinkOnTheFly, ReplanFromCruiseAndReverse) {
  const sm::AdlinkLimits lim{0, 20, 0, 0.04, 0.02, 0.5};
  for (double target : {60000.0, 30000.0, 12000.0, -5000.0}) {
    const sm::Profile p = sm::plan_adlink_ptp_from({10000, 20, 0, 0}, target, lim);
    EXPECT_EQ(p.end().pos, target);
    double prev_v = 20;
    for (double t = 1; t <= p.duration(); t += 1) {
      const sm::MotionState s = p.at(t);
      EXPECT_LE(std::fabs(s.vel), 20 + 1e-9);
      EXPECT_LE(std::fabs(s.vel - prev_v), 0.04 + 1e-9);
      prev_v = s.vel;
    }
    EXPECT_NEAR(p.at(p.duration()).pos, target, 1e-6);
  }
  EXPECT_THROW(sm::plan_adlink_ptp_from({0, 1, 0.1, 0}, 100, lim), std::invalid_argument);
}

// The Hermite crossing inside a tick: exact for constant acceleration.
TEST(Sensing, HermiteCrossingIsExactForConstantAcceleration) {
  const double h = 1e-3, x0 = 1.0, v0 = 2.0, a = 50.0;
  const double x1 = x0 + v0 * h + 0.5 * a * h * h, v1 = v0 + a * h;
  const double tau = mc::crossing_fraction(x0, v0, x1, v1, h, x0 + v0 * 0.3 * h + 0.5 * a * 0.09 * h * h);
  EXPECT_NEAR(tau, 0.3, 1e-12);
}

// GT L465-471, L2017: one capture per arm; re-arming while armed or while captured is refused.
TEST(Capture, OneShotArmRules) {
  mc::CaptureUnit c;
  c.arm(mc::CaptureTrigger::Home);
  EXPECT_THROW(c.arm(mc::CaptureTrigger::Index), sm::MotionCommandRefused);
  sm::SignalEvent home, idx;
  home.rose = true;
  home.edge_pos = 123;
  EXPECT_TRUE(c.update(home, idx, false, 0));
  EXPECT_TRUE(c.captured());
  EXPECT_EQ(c.value(), 123);
  EXPECT_THROW(c.arm(mc::CaptureTrigger::Home), sm::MotionCommandRefused);
  c.clear();
  c.arm(mc::CaptureTrigger::Probe);
  EXPECT_TRUE(c.update(home, idx, true, 77));
  EXPECT_EQ(c.value(), 77);
}

// The closed loop against a simulated axis: ADLINK T37 with a switch window on a rigid axis.
TEST(MotionLoop, HomesASimulatedAxis) {
  mc::AxisConfig cfg;
  servobench::control::GtServoLawParams law;
  law.kp = 38;
  law.ki = 60;
  law.kd = 830;
  law.kaff = 12870;
  cfg.law = law;
  servobench::plant::RigidPlantParams plant;
  plant.inertia_kgm2 = 1e-4;
  plant.viscous_nms = 1e-4;
  cfg.plant = plant;
  servobench::drive::TorqueDriveParams drive;
  drive.amps_per_volt = 0.8;
  drive.kt = 0.5;
  drive.current_limit_a = 8;
  drive.current_bw_hz = 1500;
  cfg.drive = drive;
  const double rad = 2 * M_PI / 10000;
  cfg.switches.home_min_rad = 10000 * rad;
  cfg.switches.home_max_rad = 14000 * rad;
  // No limit switches on this axis: start on the PEL side of ORG so that DIR 1 finds it directly (case A).
  mc::Axis axis2(cfg);
  axis2.reset(20000 * rad);
  mc::MotionLoop loop2(axis2);
  loop2.home(sm::AdlinkHomeParams{});
  const std::size_t ticks = loop2.run_until_done(100000, {}, {});
  ASSERT_TRUE(loop2.homing()->done());
  EXPECT_LT(ticks, 100000u);
  EXPECT_EQ(loop2.homing()->reference_pos(), 14000.0);
  EXPECT_NEAR(axis2.feedback_pulse(), 14000.0, 1.0);
  EXPECT_EQ(loop2.offset(), 14000.0);
}
