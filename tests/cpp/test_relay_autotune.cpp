// Relay auto-tuning (ADLINK L1764-1847): the phase-margin design on the card's discrete law, the conversions to the
// cards' integer gains, and the stop reasons of the experiment.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "servobench/machine/axis.hpp"
#include "servobench/tuning/loop_response.hpp"
#include "servobench/tuning/relay_autotune.hpp"

using namespace servobench;
using Complex = std::complex<double>;

namespace {
machine::AxisConfig velocity_axis(double ts) {
  machine::AxisConfig c;
  c.law = control::ApsServoLawParams{};
  drive::VelocityDriveParams d;
  d.speed_per_volt_rad_s = 31.4;
  d.current_limit_a = drive::kInf;
  d.torque_limit_nm = 1e9;
  c.drive = d;
  plant::RigidPlantParams p;
  p.inertia_kgm2 = 1e-4;
  p.viscous_nms = 1e-4;
  c.plant = p;
  c.encoder.quantize = false;
  c.dac.quantize = false;
  c.servo_period_s = ts;
  return c;
}
}  // namespace

TEST(RelayDesign, PutsTheDiscreteLoopAtTheTargetMargin) {
  // Any plant point: the designed law's exact z-transfer times the point is 1 at -180 + PM.
  const double ts = 250e-6;
  for (double pm : {30.0, 45.0, 60.0, 75.0}) {
    for (double beta : {0.0, 10.0, 25.0}) {
      const Complex g = std::polar(0.02, (-180.0 + beta) * M_PI / 180.0);  // pulse per volt
      const double f = 40.0;
      const tuning::PidDesign d = tuning::design_pid_for_phase_margin(g, f, ts, pm, 4.0);
      control::GtServoLawParams law;  // carry the design in double precision through the GT form
      law.kp = d.kp;
      law.ki = d.ki * 256.0;
      law.kd = d.kd;
      const Complex c = tuning::law_feedback_response(law, f, ts) * (10.0 / 32767.0);  // V per pulse
      const Complex l = c * g;
      EXPECT_NEAR(std::abs(l), 1.0, 1e-9);
      EXPECT_NEAR(std::arg(l) * 180 / M_PI, -180.0 + pm, 1e-7);
      EXPECT_NEAR(d.ti_s, 4.0 * d.td_s, 1e-15);
      EXPECT_NEAR(d.ki, d.kp * ts / d.ti_s, 1e-12 * d.ki);
    }
  }
  // A point that would need 130 deg of controller lead (plant at -250 deg) is refused: a PID gives at most 90.
  EXPECT_THROW(tuning::design_pid_for_phase_margin(std::polar(0.02, -250.0 * M_PI / 180), 40.0, ts, 60, 4.0),
               std::invalid_argument);
}

TEST(RelayDesign, CardGainConversions) {
  tuning::PidDesign d;
  d.kp = 38.4;
  d.ki = 0.117;
  d.kd = 1660.2;
  const auto gt = tuning::to_gt_law(d);
  EXPECT_EQ(gt.kp, 38);
  EXPECT_EQ(gt.ki, 30);  // 0.117 * 256 = 29.95
  EXPECT_EQ(gt.kd, 1660);
  EXPECT_EQ(gt.kvff, 0);
  const auto aps = tuning::to_aps_law(d);
  // Effective gains within the integer rounding (16 significant bits).
  EXPECT_NEAR(aps.kp_eff(), 38.4, 38.4 / 32768);
  EXPECT_NEAR(aps.ki_eff(), 0.117, 0.117 / 32768);
  EXPECT_NEAR(aps.kd_eff(), 1660.2, 1660.2 / 32768);
  EXPECT_LE(aps.kp, 65535);
  EXPECT_GT(aps.kp, 32767);  // the most digits kept
  EXPECT_EQ(aps.pid_shift, -5);
  d.kd = 40000;
  EXPECT_THROW(tuning::to_gt_law(d), std::invalid_argument);
}

TEST(RelayTune, VelocityDriveAxisGivesSixtyDegrees) {
  machine::Axis axis(velocity_axis(100e-6));
  tuning::RelayTuneOptions o;
  o.sampling_time_s = 100e-6;
  o.hysteresis_pulse = 150;
  o.data_length = 50;
  const tuning::RelayTuneResult r = tuning::relay_autotune(axis, o);
  ASSERT_EQ(r.status, tuning::TuneStatus::kCompleted) << r.message;
  EXPECT_EQ(r.kp.size(), 50u);
  EXPECT_FALSE(axis.servo_on());
  // Apply ("Set final") and read the margin off the analytic loop.
  machine::AxisConfig c = axis.config();
  c.law = tuning::to_aps_law(r.mean);
  std::vector<double> f;
  for (int k = 0; k < 4000; ++k) f.push_back(std::pow(10.0, 0.0 + 3.6 * k / 3999.0));
  const auto resp = tuning::loop_response(c, f);
  std::vector<Complex> l = resp.loop_gain;
  double pm = 0;
  for (std::size_t k = 0; k + 1 < f.size(); ++k)
    if (std::abs(l[k]) >= 1 && std::abs(l[k + 1]) < 1) pm = 180.0 + std::arg(l[k]) * 180 / M_PI;
  EXPECT_NEAR(pm, 60.0, 5.0);
}

TEST(RelayTune, StopReasons) {
  tuning::RelayTuneOptions o;
  o.sampling_time_s = 250e-6;
  {  // deviation limit
    machine::Axis axis(velocity_axis(250e-6));
    o.deviation_limit_pulse = 100;
    const auto r = tuning::relay_autotune(axis, o);
    EXPECT_EQ(r.status, tuning::TuneStatus::kDeviationExceeded);
    EXPECT_FALSE(axis.servo_on());
  }
  o.deviation_limit_pulse = 2000;
  {  // user stop
    machine::Axis axis(velocity_axis(250e-6));
    const auto r = tuning::relay_autotune(axis, o, [](int done, int) { return done < 5; });
    EXPECT_EQ(r.status, tuning::TuneStatus::kUserStop);
    EXPECT_EQ(r.kp.size(), 5u);
  }
  {  // drive alarm
    machine::AxisConfig c = velocity_axis(250e-6);
    std::get<drive::VelocityDriveParams>(c.drive).alarm_at_s = 0.2;
    machine::Axis axis(c);
    const auto r = tuning::relay_autotune(axis, o);
    EXPECT_EQ(r.status, tuning::TuneStatus::kLimitOrAlarm);
  }
  {  // positive limit switch inside the oscillation
    machine::AxisConfig c = velocity_axis(250e-6);
    c.switches.pos_limit_rad = 2 * M_PI * 100 / 10000.0;  // 100 pulses ahead
    machine::Axis axis(c);
    const auto r = tuning::relay_autotune(axis, o);
    EXPECT_EQ(r.status, tuning::TuneStatus::kLimitOrAlarm);
    EXPECT_NE(r.message.find("PEL"), std::string::npos);
  }
  {  // bad options
    tuning::RelayTuneOptions b;
    b.sampling_time_s = 50e-6;
    machine::Axis axis(velocity_axis(250e-6));
    EXPECT_THROW(tuning::relay_autotune(axis, b), std::invalid_argument);
    b = {};
    b.amplitude_v = 11;
    EXPECT_THROW(tuning::relay_autotune(axis, b), std::invalid_argument);
  }
}
