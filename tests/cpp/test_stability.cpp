// Issue 20: stability before margins. The closed-loop pole verdict, the Nyquist count on data, the crossing lists
// and their refinement on the exact loop, the judged sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/tuning/margins.hpp"
#include "servobench/tuning/sine_sweep.hpp"
#include "servobench/tuning/stability.hpp"

using namespace servobench;
using Complex = std::complex<double>;

namespace {

machine::AxisConfig gt_rigid(double kp, double ki, double kd) {
  machine::AxisConfig c;
  control::GtServoLawParams law;
  law.kp = kp;
  law.ki = ki;
  law.kd = kd;
  c.law = law;
  plant::RigidPlantParams p;
  p.inertia_kgm2 = 1e-4;
  p.viscous_nms = 1e-4;
  c.plant = p;
  c.encoder.quantize = false;
  c.dac.quantize = false;
  c.servo_period_s = 200e-6;
  return c;
}

}  // namespace

TEST(Stability, PolesDecideAndTheDivergingLoopReadsUnstable) {
  const tuning::Margins ok = tuning::analytic_margins(gt_rigid(38, 60, 830));
  EXPECT_TRUE(ok.stability.decided);
  EXPECT_TRUE(ok.stability.stable);
  EXPECT_EQ(ok.stability.method, "closed-loop poles");
  EXPECT_LT(ok.stability.max_pole_radius, 1.0);
  EXPECT_EQ(ok.stability.integrators, 2);  // the rigid plant's position and the law's integral
  // The same loop with 30x the proportional gain diverges: the verdict says so, whatever the crossings read.
  const tuning::Margins bad = tuning::analytic_margins(gt_rigid(38 * 30, 60, 830 * 4));
  EXPECT_TRUE(bad.stability.decided);
  EXPECT_FALSE(bad.stability.stable);
  EXPECT_GT(bad.stability.max_pole_radius, 1.0);
  EXPECT_GT(bad.stability.unstable_poles, 0);
  EXPECT_NE(bad.stability.reason.find("UNSTABLE"), std::string::npos);
}

TEST(Stability, AllCrossingsListedAndLabelledLikeAllmargin) {
  // A PID on a rigid axis: conditionally stable (a lower gain margin at low frequency), an upper one above the
  // crossover. Each crossing is refined on the exact loop: |L| = 1 and Im L = 0 there.
  const machine::AxisConfig c = gt_rigid(38, 60, 830);
  const tuning::Margins m = tuning::analytic_margins(c);
  ASSERT_GE(m.phase_crossovers.size(), 2u);
  EXPECT_TRUE(m.phase_crossovers.front().lower());
  EXPECT_NEAR(m.lower_gain_margin_db, m.phase_crossovers.front().gain_margin_db, 1e-12);
  EXPECT_GT(m.gain_margin_db, 0.0);
  ASSERT_EQ(m.gain_crossovers.size(), 1u);
  const tuning::LoopResponse at = tuning::loop_response(c, {m.pm_freq_hz, m.gm_freq_hz, m.lower_gm_freq_hz});
  EXPECT_NEAR(std::abs(at.loop_gain[0]), 1.0, 1e-8);
  EXPECT_NEAR(std::fabs(std::arg(at.loop_gain[1])) * 180 / M_PI, 180.0, 1e-6);
  EXPECT_NEAR(-20 * std::log10(std::abs(at.loop_gain[1])), m.gain_margin_db, 1e-8);
  EXPECT_NEAR(-20 * std::log10(std::abs(at.loop_gain[2])), m.lower_gain_margin_db, 1e-8);
}

TEST(Stability, NyquistCountOnDataWithIntegrators) {
  // L(s) = K (1 + s/3) / s^2 on a grid: stable for K > 0, one pair outside for K < 0; undecided when the data
  // stop above 0 dB.
  std::vector<double> f;
  std::vector<Complex> lp, ln;
  for (int k = 0; k < 2000; ++k) {
    const double hz = 0.01 * std::pow(10.0, 4.0 * k / 1999.0);
    const Complex s(0, 2 * M_PI * hz);
    f.push_back(hz);
    lp.push_back(10.0 * (1.0 + s / 3.0) / (s * s));
    ln.push_back(-lp.back());
  }
  const tuning::Stability a = tuning::nyquist_stability(f, lp);
  EXPECT_TRUE(a.decided && a.stable);
  EXPECT_EQ(a.integrators, 2);
  const tuning::Stability b = tuning::nyquist_stability(f, ln, 0, 2);
  EXPECT_TRUE(b.decided);
  EXPECT_FALSE(b.stable);
  EXPECT_GT(b.unstable_poles, 0);
  const std::vector<double> f_cut(f.begin(), f.begin() + 600);
  const std::vector<Complex> l_cut(lp.begin(), lp.begin() + 600);
  const tuning::Stability u = tuning::nyquist_stability(f_cut, l_cut);
  EXPECT_FALSE(u.decided);
  EXPECT_FALSE(u.stable);
  EXPECT_THROW(tuning::nyquist_stability(f, lp, -1), std::invalid_argument);
}

TEST(SineSweep, SaturatedPointsAreFlagged) {
  machine::AxisConfig c = gt_rigid(38, 60, 830);
  machine::Axis axis(c);
  tuning::SineSweepOptions o;
  o.start_hz = 20;
  o.end_hz = 200;
  o.points = 5;
  o.amplitude_pulse = 1e6;
  const tuning::SineSweepResult r = tuning::sine_sweep(axis, o);
  ASSERT_EQ(r.flag.size(), 5u);
  for (std::size_t i = 0; i < r.flag.size(); ++i) {
    EXPECT_GT(r.dac_saturated_ticks[i], 0);
    EXPECT_NE(r.flag[i].find("DAC saturated"), std::string::npos);
  }
  // The automatic amplitude: no saturated tick, every point passes.
  machine::Axis fresh(c);
  o.amplitude_pulse = 0;
  const tuning::SineSweepResult a = tuning::sine_sweep(fresh, o);
  for (std::size_t i = 0; i < a.flag.size(); ++i) {
    EXPECT_EQ(a.dac_saturated_ticks[i], 0);
    EXPECT_TRUE(a.flag[i].empty()) << a.flag[i];
    EXPECT_GT(a.amplitude_pulse[i], 0);
  }
}
