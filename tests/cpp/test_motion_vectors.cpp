// Manual test vectors for the single-axis motion generators. Each test names the manual file (in
// ../shared/seeds/) and the lines it reproduces; the digest row (gt.md §9, ge.md §8, adlink.md §10) is given too.
// GT = 000_0c49d4aa9b235bd5.txt (units per ST), GE = 001_b26ef06a365efe59.txt (pulse/ms),
// ADLINK = 004_b417b1b5a6e5a740.txt (pulse/s).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "motion_check.hpp"
#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/s_curve.hpp"
#include "servobench/motion/stop.hpp"
#include "servobench/motion/t_curve.hpp"

namespace sm = servobench::motion;
using sm::MotionState;
using sm::testing::profile_peaks;

namespace {
// Steps until the generator stops moving (or max ticks); returns the number of ticks stepped.
long run_to_end(sm::ProfileGenerator& g, long max_ticks = 100000000) {
  long k = 0;
  while (g.moving() && k < max_ticks) {
    g.step();
    ++k;
  }
  return k;
}
}  // namespace

// GT TV7, 000_0c49d4aa9b235bd5.txt L872-880: S-curve Jerk 2e-8, MAcc 0.004, Vel 4, Pos 80000.
// MAcc and Vel are never reached: a_pk = (d J^2/2)^(1/3) = 2.520e-4, v_pk = 3.1748, T = 4 a_pk/J = 50397 ST.
TEST(MotionVectors, GtTV7_SCurveJerkLimitedDeformed) {
  sm::GtSCurveParams p{80000, 4, 0.004, 2e-8};
  p.validate();
  const auto prof = sm::plan_s_curve_rest_to_rest(0, p.pos, p.limits());
  const double a_pk = std::cbrt(80000.0 * 2e-8 * 2e-8 / 2.0);
  EXPECT_NEAR(a_pk, 2.520e-4, 1e-7);
  const auto k = profile_peaks(prof);
  EXPECT_NEAR(k.acc, a_pk, 1e-12);
  EXPECT_NEAR(k.vel, 3.1748, 1e-4);
  EXPECT_NEAR(prof.duration(), 4 * a_pk / 2e-8, 1e-6);
  EXPECT_NEAR(prof.duration(), 50397, 1.0);
  sm::ProfileGenerator g;
  g.move_s_curve(p.pos, p.limits());
  const long ticks = run_to_end(g);
  EXPECT_EQ(ticks, static_cast<long>(std::ceil(prof.duration())));
  EXPECT_EQ(g.reported_pos(), 80000);
  EXPECT_EQ(g.state().pos, 80000.0);
}

// GT TV8, 000 L942-951: T-curve Acc 0.01, Vel 1, Pos 80000: 100 ST ramps of 50 pulses, total 80100 ST.
TEST(MotionVectors, GtTV8_TCurve) {
  sm::GtTCurveParams p{80000, 1, 0.01};
  p.validate();
  const auto prof = sm::plan_t_curve({0, 0, 0, 0}, p.pos, p.limits());
  EXPECT_NEAR(prof.duration(), 80100.0, 1e-6);
  EXPECT_NEAR(prof.at(100).pos, 50.0, 1e-9);
  EXPECT_NEAR(prof.at(100).vel, 1.0, 1e-12);
  sm::ProfileGenerator g;
  g.move_t_curve(p.pos, p.limits());
  EXPECT_EQ(run_to_end(g), 80100);
  EXPECT_EQ(g.reported_pos(), 80000);
}

// GT TV9, 000 L1006-1010: jog Acc 0.01, Vel 1 reaches 1 pulse/ST after 100 ST.
// GT TV16, 000 L1200-1229: 1 s (5000 ST at 200 us) later SmthStp decelerates at 0.01 over 100 ST.
TEST(MotionVectors, GtTV9_TV16_JogThenSmoothStop) {
  sm::GtJogParams p{1, 0.01};
  p.validate();
  sm::ProfileGenerator g;
  g.jog(p.vel, p.acc);
  for (int k = 0; k < 99; ++k) g.step();
  EXPECT_LT(g.state().vel, 1.0);
  g.step();
  EXPECT_NEAR(g.state().vel, 1.0, 1e-12);
  while (g.time_in_profile() < 5000) g.step();
  EXPECT_TRUE(g.moving());
  const double pos_at_stop = g.state().pos;  // 50 + 4900
  EXPECT_NEAR(pos_at_stop, 4950.0, 1e-9);
  g.smooth_stop();
  EXPECT_EQ(run_to_end(g), 100);
  EXPECT_NEAR(g.state().pos, pos_at_stop + 50.0, 1e-9);
  EXPECT_EQ(g.state().vel, 0.0);
}

// GT TV16 second half, 000 L1200-1229: axes 2 and 3 Acc 0.01, Vel 1, Pos 20000 finish at 20100 ST.
TEST(MotionVectors, GtTV16_TwoAxesFinishTogether) {
  sm::ProfileGenerator a2, a3;
  a2.move_t_curve(20000, {1, 0.01});
  a3.move_t_curve(20000, {1, 0.01});
  EXPECT_EQ(run_to_end(a2), 20100);
  EXPECT_EQ(run_to_end(a3), 20100);
}

// GT TV12, 000 L4452-4462: S-curve Pos 12345, Vel 3.21, MAcc 0.345, Jerk 0.087 (valid ranges) reaches 12345.
TEST(MotionVectors, GtTV12_SCurveReaches) {
  sm::GtSCurveParams p{12345, 3.21, 0.345, 0.087};
  p.validate();
  sm::ProfileGenerator g;
  g.move_s_curve(p.pos, p.limits());
  run_to_end(g);
  EXPECT_EQ(g.reported_pos(), 12345);
  const auto k = profile_peaks(g.profile());
  EXPECT_NEAR(k.vel, 3.21, 1e-12);
  EXPECT_NEAR(k.acc, 0.345, 1e-12);
}

// GT TV13, 000 L4480-4488: T-curve Pos 100000, Vel 5.7, Acc 0.67: t_acc 8.507 ST, total 17552.4 ST.
TEST(MotionVectors, GtTV13_TCurve) {
  const auto prof = sm::plan_t_curve({0, 0, 0, 0}, 100000, sm::GtTCurveParams{100000, 5.7, 0.67}.limits());
  EXPECT_NEAR(5.7 / 0.67, 8.507, 1e-3);
  EXPECT_NEAR(prof.duration(), 17552.4, 0.05);
  EXPECT_NEAR(prof.duration(), 100000 / 5.7 + 5.7 / 0.67, 1e-7);
}

// GT TV14, 000 L4507-4517: jog Vel 17, Acc 1.1 reaches speed after 15.45 ST.
TEST(MotionVectors, GtTV14_Jog) {
  const auto prof = sm::plan_jog({0, 0, 0, 0}, 17, 1.1);
  EXPECT_NEAR(prof.segment(0).duration, 15.45, 5e-3);
  EXPECT_NEAR(prof.at(15.46).vel, 17.0, 1e-12);
  EXPECT_TRUE(prof.open_ended());
}

// GT TV15, 000 L1110-1120 / L2716-2726 (and GE T15, 001 L3317-3335): AbptStp sets the profile velocity to 0
// at once; the position holds.
TEST(MotionVectors, GtTV15_GeT15_AbruptStop) {
  sm::ProfileGenerator g;
  g.move_t_curve(1000000, {1, 0.1});
  for (int k = 0; k < 500; ++k) g.step();
  const double pos = g.state().pos;
  g.abrupt_stop();
  EXPECT_FALSE(g.moving());
  EXPECT_EQ(g.state().vel, 0.0);
  EXPECT_EQ(g.state().acc, 0.0);
  g.step();
  EXPECT_EQ(g.state().pos, pos);
}

// GT TV18 / TV19, 000 L1265-1295 / L1301-1327: Vel 1, Acc 0.1, Pos +-50000; at +-20000 the velocity changes to 4
// (the breakpoint's auto-update; here the profile position stands for the actual position, ideal tracking):
// 30 ST to ramp 1 -> 4, total 27536.25 ST.
TEST(MotionVectors, GtTV18_TV19_VelocityChangeOnTheFly) {
  for (double sgn : {1.0, -1.0}) {
    sm::ProfileGenerator g;
    g.move_t_curve(sgn * 50000, {1, 0.1});
    long k = 0;
    while (sgn * g.state().pos < 20000) {
      g.step();
      ++k;
    }
    EXPECT_EQ(k, 20005);
    g.move_t_curve(sgn * 50000, {4, 0.1});
    for (int i = 0; i < 30; ++i) g.step();
    EXPECT_NEAR(sgn * g.state().vel, 4.0, 1e-9);
    k += 30 + run_to_end(g);
    EXPECT_NEAR(static_cast<double>(k), 27536.25, 1.0);
    EXPECT_EQ(k, 27537);
    EXPECT_EQ(g.reported_pos(), static_cast<long long>(sgn * 50000));
  }
}

// GT TV21, 000 L4322-4337: Pos 10000, Vel 7, Acc 0.347, then (on motion complete) Pos 0: goes and comes back.
TEST(MotionVectors, GtTV21_ThereAndBack) {
  sm::ProfileGenerator g;
  g.move_t_curve(10000, {7, 0.347});
  run_to_end(g);
  EXPECT_EQ(g.reported_pos(), 10000);
  g.move_t_curve(0, {7, 0.347});
  run_to_end(g);
  EXPECT_EQ(g.reported_pos(), 0);
  EXPECT_EQ(g.state().pos, 0.0);
}

// GT TV46, 000 L474 (and L909): SetVel + Update in S-curve while moving is refused (command status bit 11);
// the target alone may change.
TEST(MotionVectors, GtTV46_SCurveOnlyTargetChanges) {
  sm::ProfileGenerator g;
  const sm::SCurveLimits lim{3, 0.01, 1e-3};
  g.move_s_curve(50000, lim);
  for (int k = 0; k < 100; ++k) g.step();
  EXPECT_THROW(g.move_s_curve(50000, {4, 0.01, 1e-3}), sm::MotionCommandRefused);
  EXPECT_THROW(g.move_s_curve(50000, {3, 0.02, 1e-3}), sm::MotionCommandRefused);
  EXPECT_THROW(g.move_t_curve(50000, {3, 0.01}), sm::MotionCommandRefused);  // mode change in motion (L837)
  EXPECT_NO_THROW(g.move_s_curve(60000, lim));
  run_to_end(g);
  EXPECT_EQ(g.reported_pos(), 60000);
}

// GE T1, 001 L998-1050: T-curve acc 4 pulse/ms^2, vel 166.7 pulse/ms, pos 200000: t_acc 41.675 ms,
// d_acc 3473.6 pulse, total 1241.4 ms. Run at a 250 us tick (4 ticks per ms).
TEST(MotionVectors, GeT1_TCurvePulsePerMs) {
  sm::GeTCurveParams p{200000, 166.7, 4};
  p.validate();
  const double period = 250e-6;
  const auto lim = p.limits(period);
  EXPECT_DOUBLE_EQ(lim.vel, 166.7 / 4);
  const auto prof = sm::plan_t_curve({0, 0, 0, 0}, p.pos, lim);
  const double ms = prof.duration() / 4.0;
  EXPECT_NEAR(ms, 1241.4, 0.05);
  EXPECT_NEAR(prof.at(41.675 * 4).pos, 3473.6, 0.05);
}

// GE T2, 001 L1103-1158: S-curve jerk 0.001 pulse/ms^3, acc 4, vel 166.7, pos 200000. MAcc is never reached:
// peak acc sqrt(v j) = 0.408, jerk phases 408.3 ms, acceleration 816.6 ms over 68062 pulse, cruise 383 ms,
// total 2016 ms.
TEST(MotionVectors, GeT2_SCurveNoConstantAcc) {
  sm::GeSCurveParams p{200000, 166.7, 4, 0.001};
  p.validate();
  const double period = 1e-3;  // tick = 1 ms
  const auto prof = sm::plan_s_curve_rest_to_rest(0, p.pos, p.limits(period));
  const auto k = profile_peaks(prof);
  EXPECT_NEAR(k.acc, 0.408, 5e-4);
  EXPECT_NEAR(prof.segment(0).duration, 408.3, 0.05);
  EXPECT_NEAR(prof.at(2 * prof.segment(0).duration).pos, 68062, 1.0);
  EXPECT_NEAR(2 * prof.segment(0).duration, 816.6, 0.05);
  EXPECT_NEAR(prof.duration(), 2016, 0.5);
  EXPECT_NEAR(k.vel, 166.7, 1e-9);
}

// GE T3, 001 L1208-1257 and T28, L5207-5228: velocity mode 166.7 pulse/ms at 4 pulse/ms^2 reaches speed after
// 41.675 ms; 10 pulse/ms at 0.1 pulse/ms^2 after 100 ms and 500 pulse.
TEST(MotionVectors, GeT3_T28_Jog) {
  sm::GeJogParams p{166.7, 4};
  p.validate();
  const double period = 200e-6;
  auto prof = sm::plan_jog({0, 0, 0, 0}, p.vel_per_tick(period), p.acc_per_tick(period));
  EXPECT_NEAR(prof.segment(0).duration * 0.2, 41.675, 1e-9);
  sm::GeJogParams q{10, 0.1};
  prof = sm::plan_jog({0, 0, 0, 0}, q.vel_per_tick(1e-3), q.acc_per_tick(1e-3));
  EXPECT_NEAR(prof.segment(0).duration, 100, 1e-9);
  EXPECT_NEAR(prof.at(100).pos, 500, 1e-9);
}

// GE T10, 001 L2484-2600: pos 100000, vel 10, acc 1: t_acc 10 ms, d_acc 50, total 10010 ms.
// GE T23, 001 L4155-4230: pos 10000, vel 10, acc 1: total 1010 ms, then PrfPos = 10000, PrfVel = 0.
// GE T30, 001 L5474-5488: pos 10000, vel 1, acc 0.1: 10010 ms; SetAtlPos(0) makes the profile position 0.
TEST(MotionVectors, GeT10_T23_T30_TCurves) {
  const double period = 1e-3;
  sm::ProfileGenerator g;
  g.move_t_curve(100000, sm::GeTCurveParams{100000, 10, 1}.limits(period));
  EXPECT_NEAR(g.profile().at(10).pos, 50, 1e-9);
  EXPECT_EQ(run_to_end(g), 10010);
  g.set_position(0);
  g.move_t_curve(10000, sm::GeTCurveParams{10000, 10, 1}.limits(period));
  EXPECT_EQ(run_to_end(g), 1010);
  EXPECT_EQ(g.reported_pos(), 10000);
  EXPECT_EQ(g.state().vel, 0.0);
  g.set_position(0);
  g.move_t_curve(10000, sm::GeTCurveParams{10000, 1, 0.1}.limits(period));
  EXPECT_EQ(run_to_end(g), 10010);
  g.set_position(0);
  EXPECT_EQ(g.reported_pos(), 0);
}

// GE §3.1, 001 L1067-1071 (Fig. 5-2, 5-3): a target decreased behind the braking point decelerates to 0 and
// reverses; in front of it the deceleration simply starts earlier. The acceleration may not change (L315).
TEST(MotionVectors, GeTargetChangeRules) {
  sm::ProfileGenerator g;
  g.move_t_curve(100000, {10, 0.1});
  while (g.state().vel < 10) g.step();  // pos = 500, braking distance 500
  EXPECT_THROW(g.move_t_curve(100000, {10, 0.2}), sm::MotionCommandRefused);
  g.move_t_curve(1000, {10, 0.1});  // exactly the braking point: just decelerate
  EXPECT_EQ(run_to_end(g), 100);
  EXPECT_EQ(g.reported_pos(), 1000);
  g.set_position(0);
  g.move_t_curve(100000, {10, 0.1});
  while (g.state().vel < 10) g.step();
  const double p = g.state().pos;
  g.move_t_curve(p + 200, {10, 0.1});  // behind the braking point (p + 500): overshoot and reverse
  double max_pos = p;
  while (g.moving()) max_pos = std::max(max_pos, g.step().pos);
  EXPECT_NEAR(max_pos, p + 500, 1e-9);
  EXPECT_NEAR(g.state().pos, p + 200, 1e-12);
}

// ADLINK T18, 004 L2211-2219: S = 0 is the T-curve; S = 1 a triangular acceleration (pure S).
TEST(MotionVectors, AdlinkT18_SFactorExtremes) {
  sm::AdlinkLimits lim{0, 100, 0, 2, 2, 0.0};
  auto t = sm::plan_adlink_ptp(0, 100000, lim);
  auto tc = sm::plan_t_curve({0, 0, 0, 0}, 100000, {100, 2});
  EXPECT_NEAR(t.duration(), tc.duration(), 1e-9);
  lim.sf = 1.0;
  auto s = sm::plan_adlink_ptp(0, 100000, lim);
  // A-T triangle: two jerk phases of dV/ACC each, no constant-acceleration phase.
  EXPECT_NEAR(s.segment(0).duration, 50, 1e-9);
  EXPECT_NEAR(s.segment(1).duration, 50, 1e-9);
  EXPECT_NEAR(profile_peaks(s).acc, 2, 1e-12);
  EXPECT_NEAR(s.at(50).acc, 2, 1e-12);
}

// ADLINK T38, 004 L2613-2630: velocity move 500 -> 1000 -> 600 -> stop, ACC = DEC = STP_DEC = 10000 pulse/s^2,
// S = 0.5. With ACC as the peak acceleration (decision M8), 0 -> 500 takes (1+S)*dV/ACC = 0.075 s
// (0.05 s as a T-curve).
TEST(MotionVectors, AdlinkT38_VelocityMoveExample) {
  const double period = 1e-3;  // 1 ms motion cycle
  sm::AdlinkPtpParams p{0, 0, 1000, 0, 10000, 10000, 0.5, 10000};
  p.validate();
  const auto lim = p.limits(period);
  sm::ProfileGenerator g;
  g.move_adlink_velocity(0.5, lim);  // 500 pulse/s = 0.5 pulse/ms
  EXPECT_NEAR(g.profile().segment(0).duration + g.profile().segment(1).duration + g.profile().segment(2).duration,
              75.0, 1e-9);
  for (int k = 0; k < 2000; ++k) g.step();
  EXPECT_NEAR(g.state().vel, 0.5, 1e-12);
  g.move_adlink_velocity(1.0, lim);
  for (int k = 0; k < 2000; ++k) g.step();
  EXPECT_NEAR(g.state().vel, 1.0, 1e-12);
  g.move_adlink_velocity(0.6, lim);
  for (int k = 0; k < 2000; ++k) g.step();
  EXPECT_NEAR(g.state().vel, 0.6, 1e-12);
  g.smooth_stop_with(p.sd_dec_per_tick(period), sm::adlink_ramp_jerk(0.6, p.sd_dec_per_tick(period), 0.5));
  EXPECT_EQ(run_to_end(g), 90);  // (1 + 0.5) * 600 / 10000 s
  EXPECT_EQ(g.state().vel, 0.0);
  // without the analog example: with S = 0 the first ramp takes 0.05 s
  p.sf = 0;
  EXPECT_NEAR(sm::plan_adlink_velocity({0, 0, 0, 0}, 0.5, p.limits(period)).segment(0).duration, 50.0, 1e-9);
}

// ADLINK short-move rule, 004 L2191-2197 (T) and L2223 (S): ACC, DEC and S are kept, the peak drops to VM'.
TEST(MotionVectors, AdlinkShortMoveRule) {
  sm::AdlinkLimits lim{1, 100, 2, 0.5, 0.25, 0.4};
  const double D = 3000;
  const auto prof = sm::plan_adlink_ptp(0, D, lim);
  const double k = 1.4;
  const double vm = std::sqrt((2 * 0.5 * 0.25 * D / k + 0.25 * 1 + 0.5 * 4) / 0.75);
  const auto pk = profile_peaks(prof);
  EXPECT_NEAR(pk.vel, vm, 1e-9);
  EXPECT_NEAR(pk.acc, 0.5, 1e-12);  // ACC kept
  EXPECT_NEAR(sm::testing::integrated_end(prof), D, 1e-8);
  EXPECT_NEAR(prof.start().vel, 1.0, 0);  // starts at VS
  // the jerk of the acceleration ramp is ACC^2 / (S dV)
  EXPECT_NEAR(prof.segment(0).j, 0.25 / (0.4 * (vm - 1)), 1e-12);
  EXPECT_THROW(sm::plan_adlink_ptp(0, 1, {50, 100, 0, 0.5, 0.5, 0}), std::invalid_argument);
}
