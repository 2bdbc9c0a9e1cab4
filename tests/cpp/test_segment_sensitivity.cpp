// The shooting-segment cost by forward sensitivity (identify/segment_sensitivity.cpp, decisions FU1, FV1 and FV6)
// against Ceres' automatic differentiation of the same simulation (TimeFitOptions::analytic_jacobian = false), on
// random parameters and random segment states -- sliding, sticking, breaking away, held by stiction, on either body
// of a two-mass plant -- with and without a current loop, sub-steps, a load, a speed log, a load-side output.
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

// Compares the two Jacobians of `model` on six random points around `truth` for each case; returns the points
// checked and counts the segment speeds that start exactly at rest.
// A torque command of random levels in [-amplitude, amplitude] N*m, each held `hold` samples (0 first).
std::vector<double> torque_levels(std::mt19937& rng, int samples, int hold, double amplitude) {
  std::uniform_real_distribution<double> level(-amplitude, amplitude);
  std::vector<double> torque;
  double u = 0.0;
  for (int k = 0; k < samples; ++k) {
    if (k % hold == 0) u = k == 0 ? 0.0 : level(rng);
    torque.push_back(u);
  }
  return torque;
}

// tolerance: of a Jacobian entry, relative to its column's largest.
int compare_on_random_points(identify::PlantModel model, const std::vector<Case>& cases,
                             const std::vector<double>& truth, double tolerance, std::mt19937& rng,
                             int* stuck_states, bool on_load = false) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool two = model == identify::PlantModel::kTwoMass;
  const std::size_t ns = two ? 4 : 2;
  const int coulomb = identify::coulomb_index(model), excess = identify::static_index(model);
  int points = 0;
  for (const Case& c : cases) {
    // A log: torque levels held 300 samples (moves, stops, reversals) through the model itself, quantised.
    identify::TimeFitOptions o;
    o.model = model;
    o.current_bw_hz = c.current_bw_hz;
    o.substeps = c.substeps;
    o.stribeck_exponent = c.stribeck_exponent;
    o.measurement_scale = c.speed ? 0.05 : 2.0 * M_PI / 10000.0;
    o.segment_samples = 200;
    o.min_segment_samples = 20;
    identify::TimeLog log;
    log.sample_period_s = 200e-6;
    log.measured_is_speed = c.speed;
    log.measured_on_load = on_load;
    log.torque_nm = torque_levels(rng, 6000, 300, 0.15);
    std::vector<double> y = identify::simulate_model(log, truth, std::vector<double>(ns, 0.0), o);
    if (c.speed) {  // speeds: the angle's difference per sample
      std::vector<double> v(y.size(), 0.0);
      for (std::size_t k = 1; k < y.size(); ++k) v[k] = (y[k] - y[k - 1]) / log.sample_period_s;
      y = v;
    }
    for (double& v : y) v = std::round(v / o.measurement_scale) * o.measurement_scale;
    log.measured = y;
    const identify::ShootingProblem sp = identify::shooting_problem(log, o);
    EXPECT_GE(sp.starts.size(), 4u);
    for (int trial = 0; trial < 6; ++trial) {
      // Internal parameters (the breakaway entry is the Stribeck excess): 0.3x..3x the truth, the load either sign;
      // trial 4 without a Stribeck peak (excess 0), trial 5 without dry friction at all.
      std::vector<double> p(truth.size());
      for (std::size_t i = 0; i < p.size(); ++i) p[i] = truth[i] * std::exp(std::log(10.0) * (unit(rng) - 0.5));
      p[excess] = trial == 4 ? 0.0 : p[excess] - std::min(p[excess], p[coulomb]) * 0.5;
      p.back() *= unit(rng) < 0.5 ? -1.0 : 1.0;
      if (trial == 5) {
        p[coulomb] = p[excess] = 0.0;
        if (two) p[9] = 0.0;  // the load's Coulomb friction
      }
      // Segment states: the data's, perturbed; one in three speeds exactly 0 (stuck at the segment's start).
      std::vector<double> states = sp.states;
      for (std::size_t s = 0; s < states.size(); s += 2) {
        states[s] += (unit(rng) - 0.5) * 20.0 * o.measurement_scale;
        states[s + 1] *= 0.5 + unit(rng);
        if (unit(rng) < 1.0 / 3.0) {
          states[s + 1] = 0.0;
          ++*stuck_states;
        }
      }
      identify::TimeFitOptions autodiff = o;
      autodiff.analytic_jacobian = false;
      identify::SparseJacobian ja, jb;
      const std::vector<double> ra = identify::shooting_residual(log, o, sp, p, states, &ja);
      const std::vector<double> rb = identify::shooting_residual(log, autodiff, sp, p, states, &jb);
      EXPECT_EQ(ra.size(), rb.size());
      double worst_r = 0.0, scale_r = 0.0;
      for (std::size_t k = 0; k < ra.size() && k < rb.size(); ++k) {
        worst_r = std::max(worst_r, std::fabs(ra[k] - rb[k]));
        scale_r = std::max(scale_r, std::fabs(rb[k]));
      }
      EXPECT_LE(worst_r, 1e-12 * std::max(1.0, scale_r)) << "case bw " << c.current_bw_hz << " trial " << trial;
      // Without a Jacobian the forward-sensitivity cost runs its simulation without lanes (decision FV6): the same
      // residuals, to rounding, as the simulator's code on doubles.
      const std::vector<double> rc = identify::shooting_residual(log, o, sp, p, states, nullptr);
      double worst_c = 0.0;
      for (std::size_t k = 0; k < rc.size() && k < rb.size(); ++k) worst_c = std::max(worst_c, std::fabs(rc[k] - rb[k]));
      EXPECT_EQ(rc.size(), rb.size());
      EXPECT_LE(worst_c, 1e-12 * std::max(1.0, scale_r)) << "no Jacobian: case bw " << c.current_bw_hz << " trial " << trial;
      EXPECT_LE(worst_relative_difference(ja, jb), tolerance)
          << "case bw " << c.current_bw_hz << " substeps " << c.substeps << " trial " << trial;
      ++points;
    }
  }
  return points;
}

// The whole fit with either Jacobian: the same estimates and standard errors (the derivatives differ by rounding
// only), the same iterations and convergence.
void expect_the_same_fit(const identify::TimeLog& log, const identify::ParameterSetup& setup,
                         const identify::TimeFitOptions& o) {
  identify::TimeFitOptions ad = o;
  ad.analytic_jacobian = false;
  const identify::TimeFitResult a = identify::fit_time_domain(log, setup, o);
  const identify::TimeFitResult b = identify::fit_time_domain(log, setup, ad);
  ASSERT_EQ(a.parameters.size(), b.parameters.size());
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const auto& ea = a.parameters[i];
    const auto& eb = b.parameters[i];
    EXPECT_NEAR(ea.value, eb.value, 1e-6 * std::max(std::fabs(eb.value), eb.std_error)) << ea.name;
    if (std::isinf(eb.std_error))  // not identified by either (e.g. no Stribeck speed visited in the log)
      EXPECT_TRUE(std::isinf(ea.std_error)) << ea.name;
    else
      EXPECT_NEAR(ea.std_error, eb.std_error, 1e-6 * eb.std_error) << ea.name;
  }
  EXPECT_EQ(a.summary.converged, b.summary.converged);
  EXPECT_EQ(a.summary.iterations, b.summary.iterations);
}

}  // namespace

TEST(SegmentSensitivity, RigidJacobianIsTheAutoDiffOnesOnRandomPoints) {
  const std::vector<Case> cases = {{std::numeric_limits<double>::infinity(), 1, false, 2.0},
                                   {1500.0, 1, false, 2.0},
                                   {800.0, 3, false, 1.3},
                                   {std::numeric_limits<double>::infinity(), 2, true, 0.7}};
  std::mt19937 rng(11);
  int stuck_states = 0;
  const std::vector<double> truth = {2e-4, 3e-4, 0.03, 0.05, 2.0, 0.004};
  EXPECT_EQ(compare_on_random_points(identify::PlantModel::kRigid, cases, truth, 1e-12, rng, &stuck_states), 24);
  EXPECT_GT(stuck_states, 0);
}

TEST(SegmentSensitivity, TwoMassJacobianIsTheAutoDiffOnesOnRandomPoints) {
  // jm, jl, k, c, motor viscous, load viscous, motor Coulomb, Stribeck excess, Stribeck speed, load Coulomb, load:
  // a 200-450 Hz resonance, both bodies with dry friction (each sticks and slips on its own).
  const std::vector<Case> cases = {{std::numeric_limits<double>::infinity(), 1, false, 2.0},
                                   {1500.0, 1, false, 2.0},
                                   {800.0, 3, false, 1.3},
                                   {std::numeric_limits<double>::infinity(), 2, true, 0.7}};
  const std::vector<double> truth = {1e-4, 2e-4, 300.0, 0.01, 2e-4, 1e-4, 0.03, 0.02, 2.0, 0.01, 0.004};
  // The tolerance is rounding: the 4-state segments carry a lightly damped resonance over 200 samples, and the two
  // codes sum the same products in different orders (the Jets add each lane's two products element by element).
  // Without any friction (trial 5) the two differ by up to 1.3e-11 of a column's largest entry; a wrong term shows
  // at 1e-6 or more (the central differences of test_identify.py check the same Jacobian independently).
  constexpr double tolerance = 1e-10;
  std::mt19937 rng(13);
  int stuck_states = 0;
  EXPECT_EQ(compare_on_random_points(identify::PlantModel::kTwoMass, cases, truth, tolerance, rng, &stuck_states), 24);
  // The output on the load body (an encoder on the load).
  EXPECT_EQ(compare_on_random_points(identify::PlantModel::kTwoMass, {{1500.0, 2, false, 2.0}}, truth, tolerance, rng,
                                     &stuck_states, true),
            6);
  EXPECT_GT(stuck_states, 0);
}

TEST(SegmentSensitivity, RigidFitIsTheAutoDiffFitsToRounding) {
  identify::TimeFitOptions o;
  o.current_bw_hz = 1500.0;
  o.measurement_scale = 2.0 * M_PI / 10000.0;
  identify::TimeLog log;
  log.sample_period_s = 200e-6;
  std::mt19937 rng(5);
  log.torque_nm = torque_levels(rng, 10000, 400, 0.15);
  const std::vector<double> truth = {2e-4, 3e-4, 0.03, 0.05, 2.0, 0.004};
  log.measured = identify::simulate_model(log, truth, {0.0, 0.0}, o);
  for (double& v : log.measured) v = std::round(v / o.measurement_scale) * o.measurement_scale;
  identify::ParameterSetup setup;
  setup.initial = {3e-4, 2e-4, 0.02, 0.06, 3.0, 0.0};
  expect_the_same_fit(log, setup, o);
}

TEST(SegmentSensitivity, TwoMassFitIsTheAutoDiffFitsToRounding) {
  // A two-mass fit with either Jacobian, from 30 % off: the same estimates and standard errors.
  identify::TimeFitOptions o;
  o.model = identify::PlantModel::kTwoMass;
  o.current_bw_hz = 1500.0;
  o.measurement_scale = 2.0 * M_PI / 10000.0;
  o.segment_samples = 400;
  identify::TimeLog log;
  log.sample_period_s = 200e-6;
  std::mt19937 rng(7);
  log.torque_nm = torque_levels(rng, 10000, 40, 0.3);  // a rich input: steps every 8 ms excite the resonance
  const std::vector<double> truth = {1e-4, 2e-4, 300.0, 0.01, 2e-4, 0.0, 0.03, 0.02, 2.0, 0.0, 0.0};
  log.measured = identify::simulate_model(log, truth, {0.0, 0.0, 0.0, 0.0}, o);
  for (double& v : log.measured) v = std::round(v / o.measurement_scale) * o.measurement_scale;
  identify::ParameterSetup setup;
  setup.initial = {1.3e-4, 1.5e-4, 380.0, 0.013, 1.5e-4, 0.0, 0.04, 0.015, 2.5, 0.0, 0.0};
  setup.fixed = {false, false, false, false, false, true, false, false, false, true, true};
  expect_the_same_fit(log, setup, o);
}
