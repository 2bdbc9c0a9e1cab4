// The rigid segment cost by forward sensitivity (identify/rigid_sensitivity.cpp, decision FU1) against Ceres'
// automatic differentiation of the same simulation (TimeFitOptions::analytic_jacobian = false), on random
// parameters and random segment states -- sliding, sticking, breaking away, held by stiction -- with and without a
// current loop, sub-steps, a load, a speed log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "servobench/identify/time_fit.hpp"

using namespace servobench;

namespace {

struct Case {
  double current_bw_hz;
  int substeps;
  bool speed;
  double stribeck_exponent;
};

// The largest difference of the two Jacobians, each entry over its column's largest magnitude (a column: one
// parameter or one segment state).
double worst_relative_difference(const identify::SparseJacobian& a, const identify::SparseJacobian& b) {
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.col_index, b.col_index);
  std::vector<double> scale(static_cast<std::size_t>(b.cols), 0.0);
  for (std::size_t i = 0; i < b.values.size(); ++i)
    scale[static_cast<std::size_t>(b.col_index[i])] =
        std::max(scale[static_cast<std::size_t>(b.col_index[i])], std::fabs(b.values[i]));
  double worst = 0.0;
  for (std::size_t i = 0; i < b.values.size(); ++i) {
    const double s = scale[static_cast<std::size_t>(b.col_index[i])];
    if (s > 0.0) worst = std::max(worst, std::fabs(a.values[i] - b.values[i]) / s);
  }
  return worst;
}

}  // namespace

TEST(RigidSensitivity, JacobianIsTheAutoDiffOnesOnRandomPoints) {
  const Case cases[] = {{std::numeric_limits<double>::infinity(), 1, false, 2.0},
                        {1500.0, 1, false, 2.0},
                        {800.0, 3, false, 1.3},
                        {std::numeric_limits<double>::infinity(), 2, true, 0.7}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int points = 0, stuck_states = 0;
  for (const Case& c : cases) {
    // A log: torque levels held 300 samples (moves, stops, reversals) through the model itself, quantised.
    identify::TimeFitOptions o;
    o.current_bw_hz = c.current_bw_hz;
    o.substeps = c.substeps;
    o.stribeck_exponent = c.stribeck_exponent;
    o.measurement_scale = c.speed ? 0.05 : 2.0 * M_PI / 10000.0;
    o.segment_samples = 200;
    o.min_segment_samples = 20;
    identify::TimeLog log;
    log.sample_period_s = 200e-6;
    log.measured_is_speed = c.speed;
    std::uniform_real_distribution<double> level(-0.15, 0.15);
    double u = 0.0;
    for (int k = 0; k < 6000; ++k) {
      if (k % 300 == 0) u = k == 0 ? 0.0 : level(rng);
      log.torque_nm.push_back(u);
    }
    const std::vector<double> truth = {2e-4, 3e-4, 0.03, 0.05, 2.0, 0.004};
    std::vector<double> y = identify::simulate_model(log, truth, {0.0, 0.0}, o);
    if (c.speed) {  // speeds: the angle's difference per sample
      std::vector<double> v(y.size(), 0.0);
      for (std::size_t k = 1; k < y.size(); ++k) v[k] = (y[k] - y[k - 1]) / log.sample_period_s;
      y = v;
    }
    for (double& v : y) v = std::round(v / o.measurement_scale) * o.measurement_scale;
    log.measured = y;
    const identify::ShootingProblem sp = identify::shooting_problem(log, o);
    ASSERT_GE(sp.starts.size(), 4u);
    for (int trial = 0; trial < 6; ++trial) {
      // Internal parameters (the breakaway entry is the Stribeck excess): 0.3x..3x the truth, the load either sign;
      // the last trial without a Stribeck peak (excess 0) and without dry friction at all.
      std::vector<double> p(truth.size());
      for (std::size_t i = 0; i < p.size(); ++i) p[i] = truth[i] * std::exp(std::log(10.0) * (unit(rng) - 0.5));
      p[3] = trial == 4 ? 0.0 : p[3] - std::min(p[3], p[2]) * 0.5;
      p[5] *= unit(rng) < 0.5 ? -1.0 : 1.0;
      if (trial == 5) p[2] = p[3] = 0.0;
      // Segment states: the data's, perturbed; one in three speeds exactly 0 (stuck at the segment's start).
      std::vector<double> states = sp.states;
      for (std::size_t s = 0; s < states.size(); s += 2) {
        states[s] += (unit(rng) - 0.5) * 20.0 * o.measurement_scale;
        states[s + 1] *= 0.5 + unit(rng);
        if (unit(rng) < 1.0 / 3.0) {
          states[s + 1] = 0.0;
          ++stuck_states;
        }
      }
      identify::TimeFitOptions autodiff = o;
      autodiff.analytic_jacobian = false;
      identify::SparseJacobian ja, jb;
      const std::vector<double> ra = identify::shooting_residual(log, o, sp, p, states, &ja);
      const std::vector<double> rb = identify::shooting_residual(log, autodiff, sp, p, states, &jb);
      ASSERT_EQ(ra.size(), rb.size());
      double worst_r = 0.0, scale_r = 0.0;
      for (std::size_t k = 0; k < ra.size(); ++k) {
        worst_r = std::max(worst_r, std::fabs(ra[k] - rb[k]));
        scale_r = std::max(scale_r, std::fabs(rb[k]));
      }
      EXPECT_LE(worst_r, 1e-12 * std::max(1.0, scale_r)) << "case bw " << c.current_bw_hz << " trial " << trial;
      EXPECT_LE(worst_relative_difference(ja, jb), 1e-12)
          << "case bw " << c.current_bw_hz << " substeps " << c.substeps << " trial " << trial;
      ++points;
    }
  }
  EXPECT_EQ(points, 24);
  EXPECT_GT(stuck_states, 0);
}

TEST(RigidSensitivity, FitIsTheAutoDiffFitsToRounding) {
  // The whole fit with either Jacobian: the same estimates (the derivatives differ by rounding only).
  identify::TimeFitOptions o;
  o.current_bw_hz = 1500.0;
  o.measurement_scale = 2.0 * M_PI / 10000.0;
  identify::TimeLog log;
  log.sample_period_s = 200e-6;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> level(-0.15, 0.15);
  double u = 0.0;
  for (int k = 0; k < 10000; ++k) {
    if (k % 400 == 0) u = k == 0 ? 0.0 : level(rng);
    log.torque_nm.push_back(u);
  }
  const std::vector<double> truth = {2e-4, 3e-4, 0.03, 0.05, 2.0, 0.004};
  log.measured = identify::simulate_model(log, truth, {0.0, 0.0}, o);
  for (double& v : log.measured) v = std::round(v / o.measurement_scale) * o.measurement_scale;
  identify::ParameterSetup setup;
  setup.initial = {3e-4, 2e-4, 0.02, 0.06, 3.0, 0.0};
  identify::TimeFitOptions ad = o;
  ad.analytic_jacobian = false;
  const identify::TimeFitResult a = identify::fit_time_domain(log, setup, o);
  const identify::TimeFitResult b = identify::fit_time_domain(log, setup, ad);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& ea = a.parameters[i];
    const auto& eb = b.parameters[i];
    EXPECT_NEAR(ea.value, eb.value, 1e-6 * std::max(std::fabs(eb.value), eb.std_error)) << ea.name;
    EXPECT_NEAR(ea.std_error, eb.std_error, 1e-6 * eb.std_error) << ea.name;
  }
  EXPECT_EQ(a.summary.converged, b.summary.converged);
}
