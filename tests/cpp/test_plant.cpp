// Plant, drive, DAC and encoder: exactness of the ZOH integration, two-mass dynamics, friction with stiction,
// passivity, sub-step convergence, quantisation.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "servobench/drive/dac.hpp"
#include "servobench/machine/powertrain.hpp"
#include "servobench/plant/encoder.hpp"
#include "servobench/plant/rigid.hpp"
#include "servobench/plant/two_mass.hpp"
#include "servobench/plant/zoh.hpp"

using namespace servobench;

namespace {
// An ideal torque source: 1 V -> 1 A -> kt N*m.
drive::TorqueDriveParams ideal_drive(double kt = 1.0) {
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.kt = kt;
  d.current_limit_a = drive::kInf;
  d.current_bw_hz = drive::kInf;
  return d;
}
}  // namespace

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
  // J w' = kt*i - b w with an ideal drive: w(t) = (tau/b)(1 - e^{-b t / J}), theta = integral of w.
  plant::RigidPlantParams p;
  p.inertia_kgm2 = 2e-4;
  p.viscous_nms = 1e-3;
  const double ts = 250e-6;
  machine::PowerTrain pt(ideal_drive(0.5), plant::rigid_mechanics(p), ts, 1);
  const double volts = 2.0, tau = 0.5 * volts, a = p.viscous_nms / p.inertia_kgm2;
  pt.set_input(volts);
  for (int k = 1; k <= 4000; ++k) {
    pt.advance_tick();
    const double t = k * ts;
    const double w = tau / p.viscous_nms * (1 - std::exp(-a * t));
    const double th = tau / p.viscous_nms * (t - (1 - std::exp(-a * t)) / a);
    ASSERT_NEAR(pt.motor_speed_rad_s(), w, 1e-9 * std::fabs(w) + 1e-15);
    ASSERT_NEAR(pt.motor_angle_rad(), th, 1e-9 * std::fabs(th) + 1e-15);
  }
}

TEST(PowerTrain, CurrentLoopIsAFirstOrderLagAndLimits) {
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.current_limit_a = 3.0;
  d.torque_limit_nm = 1.0;  // with kt 0.5: 2 A
  d.kt = 0.5;
  d.current_bw_hz = 1000.0;
  const double ts = 50e-6;
  machine::PowerTrain pt(d, plant::rigid_mechanics({}), ts, 1);
  pt.set_input(5.0);  // 5 A asked, limited to min(3 A, 1 N*m / 0.5) = 2 A
  for (int k = 1; k <= 20; ++k) {
    pt.advance_tick();
    EXPECT_NEAR(pt.current_a(), 2.0 * (1 - std::exp(-2 * M_PI * 1000.0 * k * ts)), 1e-12);
  }
}

TEST(TwoMass, ResonanceFrequencies) {
  plant::TwoMassPlantParams p;  // jm 2e-5, jl 6e-5, k 400
  EXPECT_NEAR(p.antiresonance_hz(), std::sqrt(400.0 / 6e-5) / (2 * M_PI), 1e-9);
  EXPECT_NEAR(p.resonance_hz(), std::sqrt(400.0 * 8e-5 / (2e-5 * 6e-5)) / (2 * M_PI), 1e-9);
  EXPECT_NEAR(p.resonance_hz(), 821.873, 0.001);      // 5163.98 rad/s
  EXPECT_NEAR(p.antiresonance_hz(), 410.936, 0.001);  // 2581.99 rad/s
}

TEST(TwoMass, FreeResponseMatchesAnalyticSolution) {
  // No friction: the twist phi = thm - thl is a damped oscillator with w_r^2 = k(Jm+Jl)/(Jm Jl) and
  // 2 zeta w_r = c (Jm+Jl)/(Jm Jl); the momentum-weighted mean angle stays put.
  plant::TwoMassPlantParams p;
  p.motor_viscous_nms = 0.0;
  p.load_viscous_nms = 0.0;
  p.c_nms_per_rad = 0.004;
  const double jm = p.jm_kgm2, jl = p.jl_kgm2, jt = jm + jl;
  const double wr2 = p.k_nm_per_rad * jt / (jm * jl);
  const double sigma = 0.5 * p.c_nms_per_rad * jt / (jm * jl);
  const double wd = std::sqrt(wr2 - sigma * sigma);
  const double ts = 200e-6;
  machine::PowerTrain pt(ideal_drive(), plant::two_mass_mechanics(p), ts, 1);
  const double phi0 = 1e-3;  // initial twist, rad
  const double mean0 = 0.3;  // (Jm thm + Jl thl)/(Jm+Jl)
  pt.set_state(mean0 + jl / jt * phi0, 0.0, mean0 - jm / jt * phi0, 0.0);
  pt.set_input(0.0);
  double worst = 0.0;
  for (int k = 1; k <= 5000; ++k) {
    pt.advance_tick();
    const double t = k * ts;
    const double phi = phi0 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
    const double thm = mean0 + jl / jt * phi;
    const double thl = mean0 - jm / jt * phi;
    worst = std::max({worst, std::fabs(pt.motor_angle_rad() - thm), std::fabs(pt.load_angle_rad() - thl)});
  }
  EXPECT_LT(worst / mean0, 1e-9);
  EXPECT_LT(worst, 1e-9 * phi0 * 10);  // also tight against the oscillation itself
}

namespace {
// Steady-state response of the sampled angle to a held sinusoidal torque, by a single-bin DFT over whole periods.
std::complex<double> measured_response(const plant::Mechanics& m, bool load_side, double ts, int cycles_per_record,
                                       int record, int settle) {
  machine::PowerTrain pt(ideal_drive(), m, ts, 1);
  const double w = 2 * M_PI * cycles_per_record / (record * ts);
  std::complex<double> y_sum = 0, u_sum = 0;
  for (int k = 0; k < settle + record; ++k) {
    const double u = std::sin(w * k * ts);
    pt.set_input(u);
    const double y = load_side ? pt.load_angle_rad() : pt.motor_angle_rad();
    if (k >= settle) {
      const std::complex<double> e = std::exp(std::complex<double>(0, -w * k * ts));
      y_sum += y * e;
      u_sum += u * e;
    }
    pt.advance_tick();
  }
  return y_sum / u_sum;
}
}  // namespace

TEST(FrequencyResponse, ZohResponseMatchesSimulation) {
  const double ts = 250e-6;
  plant::TwoMassPlantParams p;
  p.motor_viscous_nms = 2e-3;  // the free integrator's transient decays (J/b ~ 40 ms)
  p.load_viscous_nms = 2e-3;
  p.c_nms_per_rad = 0.01;
  const plant::Mechanics two = plant::two_mass_mechanics(p);
  plant::RigidPlantParams r;
  r.viscous_nms = 5e-3;
  const plant::Mechanics rigid = plant::rigid_mechanics(r);
  const int record = 4000;  // 1 s
  for (int cycles : {20, 300, 410, 800, 1300}) {
    const double f = cycles / (record * ts);
    for (bool load : {false, true}) {
      const auto h = plant::frequency_response(two, {f}, load, ts)[0];
      const auto hm = measured_response(two, load, ts, cycles, record, 8000);
      EXPECT_LT(std::abs(hm - h) / std::abs(h), 1e-6) << "two-mass f = " << f << " load " << load;
    }
    const auto h = plant::frequency_response(rigid, {f}, false, ts)[0];
    const auto hm = measured_response(rigid, false, ts, cycles, record, 8000);
    EXPECT_LT(std::abs(hm - h) / std::abs(h), 1e-6) << "rigid f = " << f;
  }
}

TEST(FrequencyResponse, ContinuousTwoMassMatchesTransferFunction) {
  // G_m(s) = (Jl s^2 + (c+bl) s + k) / D(s), D = (Jm s^2 + (c+bm) s + k)(Jl s^2 + (c+bl) s + k) - (c s + k)^2
  plant::TwoMassPlantParams p;
  const double jm = p.jm_kgm2, jl = p.jl_kgm2, k = p.k_nm_per_rad, c = p.c_nms_per_rad;
  const double bm = p.motor_viscous_nms, bl = p.load_viscous_nms;
  const std::vector<double> f = {1.0, 50.0, 410.0, 822.0, 3000.0};
  const auto hm = plant::frequency_response(plant::two_mass_mechanics(p), f, false, 0.0);
  const auto hl = plant::frequency_response(plant::two_mass_mechanics(p), f, true, 0.0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::complex<double> s(0, 2 * M_PI * f[i]);
    const auto mm = jm * s * s + (c + bm) * s + k, ll = jl * s * s + (c + bl) * s + k, cs = c * s + k;
    const auto d = mm * ll - cs * cs;
    EXPECT_LT(std::abs(hm[i] - ll / d) / std::abs(ll / d), 1e-9);
    EXPECT_LT(std::abs(hl[i] - cs / d) / std::abs(cs / d), 1e-9);
  }
}

TEST(Friction, StictionHoldsFor1e7TicksAndBreaksAway) {
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.kt = 0.1;
  d.current_bw_hz = 2000.0;
  plant::RigidPlantParams p;
  p.coulomb_nm = 0.04;
  p.static_nm = 0.05;
  machine::PowerTrain pt(d, plant::rigid_mechanics(p), 200e-6, 1);
  pt.set_input(0.499);  // 0.0499 N*m < Fs = 0.05 N*m
  for (int k = 0; k < 10000000; ++k) pt.advance_tick();
  EXPECT_EQ(pt.motor_angle_rad(), 0.0);  // no creep, not even one ulp
  EXPECT_EQ(pt.motor_speed_rad_s(), 0.0);
  EXPECT_TRUE(pt.stuck(0));
  pt.set_input(0.51);  // 0.051 N*m > Fs: breaks away
  for (int k = 0; k < 100; ++k) pt.advance_tick();
  EXPECT_GT(pt.motor_speed_rad_s(), 0.0);
  // Stribeck: once sliding, 0.045 N*m (between Fc and Fs) keeps it sliding and accelerating slowly.
  pt.set_input(0.45);
  for (int k = 0; k < 2000; ++k) pt.advance_tick();
  EXPECT_GT(pt.motor_speed_rad_s(), 0.0);
  EXPECT_FALSE(pt.stuck(0));
  // Torque removed: friction stops it, and it then stays stopped without chatter.
  pt.set_input(0.0);
  for (int k = 0; k < 20000; ++k) pt.advance_tick();
  const double at = pt.motor_angle_rad();
  for (int k = 0; k < 100000; ++k) {
    pt.advance_tick();
    ASSERT_EQ(pt.motor_speed_rad_s(), 0.0);
  }
  EXPECT_EQ(pt.motor_angle_rad(), at);
}

TEST(Friction, AsymmetricLevelsPerDirection) {
  // issue 19: Fc+/- = Fc +/- a, b+/- = b +/- bv; steady speeds (tau - Fc+/-) / b+/- in each direction, and an
  // effort between the two breakaway levels holds the body in one direction only.
  plant::RigidPlantParams p;
  p.inertia_kgm2 = 1e-3;
  p.viscous_nms = 5e-3;
  p.viscous_asym_nms = -1e-3;  // b+ = 4e-3, b- = 6e-3
  p.coulomb_nm = 0.02;
  p.coulomb_asym_nm = 0.005;   // Fc+ = 0.025, Fc- = 0.015
  for (double tau : {0.05, -0.05}) {
    machine::PowerTrain pt(ideal_drive(), plant::rigid_mechanics(p), 1e-3, 4);
    pt.set_input(tau);
    for (int k = 0; k < 5000; ++k) pt.advance_tick();
    const double expected = tau > 0 ? (tau - 0.025) / 4e-3 : (tau + 0.015) / 6e-3;
    EXPECT_NEAR(pt.motor_speed_rad_s(), expected, 1e-6 * std::fabs(expected));
  }
  machine::PowerTrain hold(ideal_drive(), plant::rigid_mechanics(p), 1e-3, 4);
  hold.set_input(0.02);  // below Fs+ = 0.025: held
  for (int k = 0; k < 1000; ++k) hold.advance_tick();
  EXPECT_EQ(hold.motor_speed_rad_s(), 0.0);
  hold.set_input(-0.02);  // beyond Fs- = 0.015: moves
  for (int k = 0; k < 1000; ++k) hold.advance_tick();
  EXPECT_LT(hold.motor_speed_rad_s(), 0.0);
  plant::RigidPlantParams bad = p;
  bad.coulomb_asym_nm = 0.03;  // |a| > Fc
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(Friction, PassivePlantNeverGainsEnergy) {
  plant::TwoMassPlantParams p;
  p.motor_coulomb_nm = 0.01;
  p.motor_static_nm = 0.015;
  p.load_coulomb_nm = 0.02;
  p.load_static_nm = 0.03;
  p.c_nms_per_rad = 0.001;
  p.cogging_nm = 0.0;
  machine::PowerTrain pt(ideal_drive(), plant::two_mass_mechanics(p), 250e-6, 1);
  pt.set_state(0.0, 50.0, 0.002, -20.0);
  pt.set_input(0.0);
  double e_prev = pt.mechanical_energy_j();
  const double e0 = e_prev;
  for (int k = 0; k < 200000; ++k) {
    pt.advance_tick();
    const double e = pt.mechanical_energy_j();
    ASSERT_LE(e, e_prev + 1e-12 * e0) << "tick " << k;
    e_prev = e;
  }
  EXPECT_LT(e_prev, 1e-3 * e0);  // friction and damping took the energy out
}

TEST(Friction, SubstepsConverge) {
  // A step of torque into a Stribeck-friction axis that sticks, slips and stops: the position after the
  // episode converges as the sub-steps grow.
  drive::TorqueDriveParams d;
  d.amps_per_volt = 1.0;
  d.kt = 0.1;
  d.current_bw_hz = 800.0;
  plant::RigidPlantParams p;
  p.coulomb_nm = 0.02;
  p.static_nm = 0.03;
  p.stribeck_speed_rad_s = 0.5;
  p.viscous_nms = 1e-4;
  auto final_angle = [&](int substeps) {
    machine::PowerTrain pt(d, plant::rigid_mechanics(p), 1e-3, substeps);
    pt.set_input(0.5);
    for (int k = 0; k < 30; ++k) pt.advance_tick();
    pt.set_input(0.0);
    for (int k = 0; k < 200; ++k) pt.advance_tick();
    return pt.motor_angle_rad();
  };
  const double ref = final_angle(1000);
  double prev_err = 1e9;
  for (int n : {1, 4, 16, 64}) {
    const double err = std::fabs(final_angle(n) - ref);
    EXPECT_LT(err, prev_err) << n << " sub-steps";
    prev_err = err;
  }
  EXPECT_LT(prev_err, 1e-3 * std::fabs(ref));
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

TEST(Encoder, QuantisesToTheNearestCountAndMarksTheIndex) {
  plant::Encoder enc;  // 10000 counts/rev
  const double rad_per_count = 2 * M_PI / 10000;
  EXPECT_EQ(enc.read(0.0), 0.0);
  EXPECT_EQ(enc.read(0.49 * rad_per_count), 0.0);
  EXPECT_EQ(enc.read(0.51 * rad_per_count), 1.0);
  EXPECT_EQ(enc.read(-0.51 * rad_per_count), -1.0);
  EXPECT_EQ(enc.read(2 * M_PI), 10000.0);
  plant::EncoderParams ep;
  ep.index_angle_rad = 1.0;
  plant::Encoder idx(ep);
  EXPECT_TRUE(idx.index_between(0.9, 1.1));
  EXPECT_FALSE(idx.index_between(1.1, 2.0));
  EXPECT_TRUE(idx.index_between(1.1 + 2 * M_PI, 0.9 + 2 * M_PI));  // backwards too
  EXPECT_TRUE(idx.index_between(-5.0, -5.4));                        // 1 - 2 pi = -5.28
}
