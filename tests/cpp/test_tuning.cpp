// Tuning layer: the lifted servo-rate model of the power train, the analytic loop response against a simulated
// stepped sine, and the margins against closed-form values.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/machine/powertrain.hpp"
#include "servobench/plant/rigid.hpp"
#include "servobench/plant/two_mass.hpp"
#include "servobench/tuning/loop_response.hpp"
#include "servobench/tuning/margins.hpp"
#include "servobench/tuning/sine_sweep.hpp"

using namespace servobench;
using Complex = std::complex<double>;

namespace {

// Simulates the lifted model x+ = A x + B v and compares its angles with the PowerTrain's, tick by tick.
double max_model_error(const machine::DriveParams& drive, const plant::Mechanics& mech, double ts, int substeps) {
  machine::PowerTrain pt(drive, mech, ts, substeps);
  const machine::TickModel m = pt.linear_tick_model();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.a.rows());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> volts(-1.0, 1.0);
  double worst = 0.0, scale = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double v = volts(rng);
    pt.set_input(v);
    pt.advance_tick();
    x = m.a * x + m.b * v;
    worst = std::max({worst, std::fabs((m.c_motor * x)(0) - pt.motor_angle_rad()),
                      std::fabs((m.c_load * x)(0) - pt.load_angle_rad())});
    scale = std::max(scale, std::fabs(pt.motor_angle_rad()));
  }
  return worst / scale;
}

drive::TorqueDriveParams linear_torque_drive() {
  drive::TorqueDriveParams d;
  d.current_limit_a = drive::kInf;
  return d;
}

drive::VelocityDriveParams linear_velocity_drive() {
  drive::VelocityDriveParams d;
  d.current_limit_a = drive::kInf;
  d.torque_limit_nm = 1e9;  // the speed loop needs a finite limit; this one is never reached
  return d;
}

machine::AxisConfig linear_axis(const machine::LawParams& law, const machine::PlantParams& plant, double ts) {
  machine::AxisConfig c;
  c.law = law;
  c.drive = linear_torque_drive();
  c.plant = plant;
  c.encoder.quantize = false;
  c.dac.quantize = false;
  c.servo_period_s = ts;
  return c;
}

}  // namespace

TEST(TickModel, MatchesThePowerTrainTickByTick) {
  plant::RigidPlantParams rigid;
  rigid.inertia_kgm2 = 1e-4;
  rigid.viscous_nms = 1e-4;
  const plant::TwoMassPlantParams two;
  // Torque mode, ideal and first-order current loop, several sub-steps.
  EXPECT_LT(max_model_error(linear_torque_drive(), plant::rigid_mechanics(rigid), 200e-6, 1), 1e-10);
  EXPECT_LT(max_model_error(linear_torque_drive(), plant::two_mass_mechanics(two), 100e-6, 4), 1e-10);
  // Velocity mode: the drive's PI speed loop runs twice per tick at 20 kHz (multi-rate, lifted exactly).
  EXPECT_LT(max_model_error(linear_velocity_drive(), plant::rigid_mechanics(rigid), 100e-6, 1), 1e-10);
  EXPECT_LT(max_model_error(linear_velocity_drive(), plant::two_mass_mechanics(two), 100e-6, 3), 1e-10);
}

TEST(TickModel, RefusesPulseInputDrives) {
  machine::PowerTrain pt(drive::StepperDriveParams{}, plant::rigid_mechanics({}), 200e-6, 1);
  EXPECT_THROW(pt.linear_tick_model(), std::invalid_argument);
}

TEST(LoopResponse, AgreesWithASimulatedSteppedSine) {
  // GT law at 10 kHz on the rigid reference plant: the C++ sweep and the analytic response within 0.1 dB / 1 deg
  // from 10 Hz to 0.4 fs, the bound of the Bode issue.
  control::GtServoLawParams law;
  law.kp = 38;
  law.ki = 30;
  law.kd = 1660;
  plant::RigidPlantParams rigid;
  rigid.inertia_kgm2 = 1e-4;
  rigid.viscous_nms = 1e-4;
  machine::Axis axis(linear_axis(law, rigid, 100e-6));
  tuning::SineSweepOptions o;
  o.start_hz = 10;
  o.end_hz = 4000;
  o.points = 15;
  o.amplitude_pulse = 2;
  o.update_s = 0.2;
  const tuning::SineSweepResult r = tuning::sine_sweep(axis, o);
  ASSERT_EQ(r.status, tuning::SweepStatus::kCompleted) << r.message;
  ASSERT_EQ(r.freq_hz.size(), 15u);
  const tuning::LoopResponse a = tuning::loop_response(axis.config(), r.freq_hz);
  for (std::size_t k = 0; k < r.freq_hz.size(); ++k) {
    const Complex meas[3] = {r.y[k] / r.u[k], r.y[k] / r.e[k], r.y[k] / r.r[k]};
    const Complex ana[3] = {a.plant[k], a.open_loop[k], a.closed_loop[k]};
    for (int t = 0; t < 3; ++t) {
      const Complex q = meas[t] / ana[t];
      EXPECT_LT(std::fabs(20 * std::log10(std::abs(q))), 0.1) << "f = " << r.freq_hz[k] << " type " << t;
      EXPECT_LT(std::fabs(std::arg(q) * 180 / M_PI), 1.0) << "f = " << r.freq_hz[k] << " type " << t;
    }
    EXPECT_GT(r.coherence[k], 0.999);
  }
  EXPECT_EQ(r.ticks, 15 * 2000);
}

TEST(LoopResponse, LawTransferFunctions) {
  // GT: C(z) = Kp + (Ki/256)/(1 - z^-1) + Kd (1 - z^-1); at z = -1 (Nyquist) 1 - z^-1 = 2.
  control::GtServoLawParams gt;
  gt.kp = 10;
  gt.ki = 256;
  gt.kd = 3;
  gt.kvff = 5;
  gt.kaff = 7;
  const double ts = 1e-3, f = 0.5 / ts;
  EXPECT_NEAR(std::abs(tuning::law_feedback_response(gt, f * (1 - 1e-12), ts) - Complex(10 + 0.5 + 6, 0)), 0, 1e-6);
  EXPECT_NEAR(std::abs(tuning::law_feedforward_response(gt, f * (1 - 1e-12), ts) - Complex(10 + 28, 0)), 0, 1e-6);
  gt.ilmt = 0;  // the sum is held at 0: no integral action
  EXPECT_NEAR(std::abs(tuning::law_feedback_response(gt, f * (1 - 1e-12), ts) - Complex(16, 0)), 0, 1e-6);
  // ADLINK: the worked example's gain 100 * 2^(2+3) = 3200 (L1733) is the proportional part.
  control::ApsServoLawParams aps;
  aps.kp = 100;
  aps.kp_shift = 2;
  aps.pid_shift = 3;
  EXPECT_NEAR(std::abs(tuning::law_feedback_response(aps, 10.0, ts)), 3200.0, 1e-9);
}

TEST(Margins, ThirdOrderLoopClosedForm) {
  // L(s) = 2 / (s (s+1) (s+2)): phase crossover at w = sqrt(2) rad/s with |L| = 1/3 (GM = 20 log10 3 dB).
  std::vector<double> f;
  std::vector<Complex> l;
  for (int k = 0; k < 4000; ++k) {
    const double hz = 0.01 * std::pow(10.0, 3.0 * k / 3999.0);
    const Complex s(0, 2 * M_PI * hz);
    f.push_back(hz);
    l.push_back(2.0 / (s * (s + 1.0) * (s + 2.0)));
  }
  const tuning::Margins m = tuning::margins(f, l);
  EXPECT_NEAR(m.gain_margin_db, 20 * std::log10(3.0), 1e-3);
  EXPECT_NEAR(m.gm_freq_hz, std::sqrt(2.0) / (2 * M_PI), 1e-4);
  // Gain crossover: w^2 (w^2+1)(w^2+4) = 4 -> w^2 = 0.5616 (root of x^3 + 5x^2 + 4x - 4 = 0).
  double x = 0.5;
  for (int i = 0; i < 50; ++i) x -= (x * x * x + 5 * x * x + 4 * x - 4) / (3 * x * x + 10 * x + 4);
  const double wc = std::sqrt(x);
  const double pm = 180.0 - 90.0 - std::atan(wc) * 180 / M_PI - std::atan(wc / 2) * 180 / M_PI;
  EXPECT_NEAR(m.pm_freq_hz, wc / (2 * M_PI), 1e-4);
  EXPECT_NEAR(m.phase_margin_deg, pm, 1e-2);
  EXPECT_NEAR(m.delay_margin_s, pm / (360 * m.pm_freq_hz), 1e-6);
  EXPECT_FALSE(std::isfinite(m.lower_gain_margin_db));
  // Peak sensitivity: max |1/(1+L)| on the grid, compared with a direct scan.
  double ms = 0;
  for (const auto& v : l) ms = std::max(ms, 1.0 / std::abs(1.0 + v));
  EXPECT_DOUBLE_EQ(m.ms, ms);
}

TEST(Margins, APhaseStabilisedResonanceIsNotTheWorstCrossover) {
  // A loop crossing 0 dB at 60 deg, then (a collocated resonance) rising above 0 dB again with L near +1: those two
  // crossovers (PM -177.5 and +177.5 deg) are the farthest from -1. The phase margin is the crossover nearest to -1
  // (python-control's choice); the delay margin is the smallest dead time that turns any crossover onto -1.
  auto polar = [](double mag, double deg) { return std::polar(mag, deg * M_PI / 180.0); };
  const std::vector<double> f = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<Complex> l = {polar(10, -120), polar(0.1, -120), polar(0.5, -200), polar(0.5, -290),
                                  polar(0.5, -355), polar(2.0, -360), polar(0.5, -365), polar(0.1, -370)};
  const tuning::Margins m = tuning::margins(f, l);
  EXPECT_NEAR(m.phase_margin_deg, 60.0, 1e-9);
  EXPECT_NEAR(m.pm_freq_hz, std::sqrt(1.0 * 2.0), 1e-9);  // 20 dB -> -20 dB: the middle in log f
  const double f2 = std::sqrt(5.0 * 6.0), f3 = std::sqrt(6.0 * 7.0);
  const double dm = std::min({60.0 / (360 * std::sqrt(2.0)), (360.0 - 177.5) / (360 * f2), 177.5 / (360 * f3)});
  EXPECT_NEAR(m.delay_margin_s, dm, 1e-12);
  EXPECT_NEAR(m.delay_margin_s, 177.5 / (360 * f3), 1e-12);  // the resonance crossover sets it here
  // the phase crossover at -180 deg between 2 and 3 Hz: |L| from 0.1 to 0.5
  EXPECT_GT(m.gain_margin_db, 6.0);
  EXPECT_LT(m.gain_margin_db, 20.0);
  // only the resonance crossovers left: the nearest to -1 of the two
  const std::vector<double> f_hi(f.begin() + 3, f.end());
  const std::vector<Complex> l_hi(l.begin() + 3, l.end());
  EXPECT_NEAR(std::fabs(tuning::margins(f_hi, l_hi).phase_margin_deg), 177.5, 1e-9);
}

TEST(Margins, RejectsBadData) {
  EXPECT_THROW(tuning::margins({1.0}, {Complex(1, 0)}), std::invalid_argument);
  EXPECT_THROW(tuning::margins({1.0, 2.0}, {Complex(1, 0)}), std::invalid_argument);
  EXPECT_THROW(tuning::margins({2.0, 1.0}, {Complex(1, 0), Complex(2, 0)}), std::invalid_argument);
  EXPECT_THROW(tuning::margins({1.0, 2.0}, {Complex(1, 0), Complex(NAN, 0)}), std::invalid_argument);
}

TEST(SineSweep, DeviationLimitTurnsTheServoOff) {
  control::GtServoLawParams law;
  law.kp = 38;
  law.ki = 30;
  law.kd = 1660;
  machine::Axis axis(linear_axis(law, plant::RigidPlantParams{}, 100e-6));
  tuning::SineSweepOptions o;  // the manual's example: 10-100 Hz, 100 points, 300 pulse, 0.1 s (L2035)
  o.deviation_limit_pulse = 50;
  const tuning::SineSweepResult r = tuning::sine_sweep(axis, o);
  EXPECT_EQ(r.status, tuning::SweepStatus::kDeviationExceeded);
  EXPECT_GT(std::fabs(r.stop_error_pulse), 50.0);
  EXPECT_LT(r.freq_hz.size(), 100u);
  EXPECT_FALSE(axis.servo_on());
}
