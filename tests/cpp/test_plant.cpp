// Plant, drive, DAC and encoder first versions: exactness of the ZOH integration, stiction, quantisation.
#include <gtest/gtest.h>

#include <cmath>

#include "servobench/drive/dac.hpp"
#include "servobench/machine/powertrain.hpp"
#include "servobench/plant/encoder.hpp"
#include "servobench/plant/zoh.hpp"

using namespace servobench;

TEST(Zoh, DoubleIntegratorIsExact) {
  Eigen::MatrixXd a(2, 2), b(2, 1);
  a << 0, 1, 0, 0;
  b << 0, 1;
  const double h = 1e-3;
  const auto z = plant::discretize_zoh(a, b, h);
  EXPECT_NEAR(z.phi(0, 1), h, 1e-18);
  EXPECT_NEAR(z.gamma(0, 0), h * h / 2, 1e-18);
  EXPECT_NEAR(z.gamma(1, 0), h, 1e-18);
}

TEST(PowerTrain, ViscousSpinUpMatchesAnalyticSolution) {
  // J w' = kt*i - b w with an ideal drive: w(t) = (kt i / b)(1 - e^{-b t / J}), theta = integral of w.
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.kt = 0.5;
  d.current_limit_a = INFINITY;
  d.current_bw_hz = INFINITY;
  plant::RigidPlantParams p;
  p.inertia_kgm2 = 2e-4;
  p.viscous_nms = 1e-3;
  const double h = 250e-6;
  machine::PowerTrain pt(d, p, h);
  const double volts = 2.0, tau = d.kt * volts, a = p.viscous_nms / p.inertia_kgm2;
  for (int k = 1; k <= 4000; ++k) {
    pt.step(volts);
    const double t = k * h;
    const double w = tau / p.viscous_nms * (1 - std::exp(-a * t));
    const double th = tau / p.viscous_nms * (t - (1 - std::exp(-a * t)) / a);
    ASSERT_NEAR(pt.speed_rad_s(), w, 1e-9 * std::fabs(w) + 1e-15);
    ASSERT_NEAR(pt.angle_rad(), th, 1e-9 * std::fabs(th) + 1e-15);
  }
}

TEST(PowerTrain, CurrentLoopIsAFirstOrderLag) {
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.current_limit_a = 3.0;
  d.current_bw_hz = 1000.0;
  plant::RigidPlantParams p;
  const double h = 50e-6;
  machine::PowerTrain pt(d, p, h);
  for (int k = 1; k <= 20; ++k) {
    pt.step(5.0);  // 5 A asked, limited to 3 A
    EXPECT_NEAR(pt.current_a(), 3.0 * (1 - std::exp(-2 * M_PI * 1000.0 * k * h)), 1e-12);
  }
}

TEST(PowerTrain, StictionHoldsBelowTheStaticLevelAndBreaksAwayAbove) {
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.kt = 0.1;
  d.current_bw_hz = 2000.0;
  plant::RigidPlantParams p;
  p.coulomb_nm = 0.05;
  machine::PowerTrain pt(d, p, 200e-6);
  for (int k = 0; k < 100000; ++k) pt.step(0.49);  // 0.049 N*m < 0.05 N*m
  EXPECT_EQ(pt.angle_rad(), 0.0);
  EXPECT_EQ(pt.speed_rad_s(), 0.0);
  for (int k = 0; k < 100; ++k) pt.step(0.6);  // 0.06 N*m > 0.05 N*m
  EXPECT_GT(pt.speed_rad_s(), 0.0);
  // Torque removed: Coulomb friction stops it and it stays stopped, no chatter.
  for (int k = 0; k < 20000; ++k) pt.step(0.0);
  const double stopped_at = pt.angle_rad();
  for (int k = 0; k < 1000; ++k) pt.step(0.0);
  EXPECT_EQ(pt.speed_rad_s(), 0.0);
  EXPECT_EQ(pt.angle_rad(), stopped_at);
}

TEST(Dac, SaturatesAndQuantisesToSymmetric16BitCodes) {
  drive::Dac dac;
  EXPECT_DOUBLE_EQ(dac.convert(12.0), 10.0);
  EXPECT_DOUBLE_EQ(dac.convert(-12.0), -10.0);
  EXPECT_DOUBLE_EQ(dac.max_code(), 32767);
  EXPECT_DOUBLE_EQ(dac.convert(1.0 / 3276.7 * 0.4), 0.0);          // less than half a code
  EXPECT_DOUBLE_EQ(dac.convert(1.0 / 3276.7 * 0.6), 10.0 / 32767);  // rounds to one code
  drive::DacParams ideal;
  ideal.quantize = false;
  EXPECT_DOUBLE_EQ(drive::Dac(ideal).convert(0.123456789), 0.123456789);
}

TEST(Encoder, QuantisesToTheNearestCount) {
  plant::Encoder enc;  // 10000 counts/rev
  const double rad_per_count = 2 * M_PI / 10000;
  EXPECT_EQ(enc.read(0.0), 0.0);
  EXPECT_EQ(enc.read(0.49 * rad_per_count), 0.0);
  EXPECT_EQ(enc.read(0.51 * rad_per_count), 1.0);
  EXPECT_EQ(enc.read(-0.51 * rad_per_count), -1.0);
  EXPECT_EQ(enc.read(2 * M_PI), 10000.0);
}
