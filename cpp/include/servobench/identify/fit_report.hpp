// What a fit reports, Ceres-style: the estimates with their standard errors, and a summary that explains itself.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace servobench::identify {

// One parameter of a fit (SI units).
struct ParameterEstimate {
  std::string name;
  std::string unit;
  double value = 0.0;      // the estimate
  double initial = 0.0;    // the starting guess
  double std_error = 0.0;  // standard error from the covariance (0 for a fixed parameter; inf if not identifiable)
  double lower = 0.0;      // bounds in force
  double upper = 0.0;
  bool fixed = false;      // held at its initial value
  bool at_bound = false;   // ended on a bound (its standard error then describes the unconstrained curvature only)

  // The fields a Python estimate carries (name, member, unit, meaning): servobench.identify.Estimate reads them from
  // here, in its constructor's order (decision OR1). The bounds are the binding's too (the fit's setup).
  template <class V>
  static void describe(V&& v) {
    using E = ParameterEstimate;
    v("name", &E::name, "", "the parameter's name");
    v("value", &E::value, "", "the estimate, in `unit`");
    v("std_error", &E::std_error, "", "its standard error, in `unit`, from the covariance (0 for a fixed parameter; inf if not identifiable)");
    v("unit", &E::unit, "", "the parameter's SI unit");
    v("initial", &E::initial, "", "the starting guess, in `unit`");
    v("fixed", &E::fixed, "", "held at its initial value");
    v("at_bound", &E::at_bound, "", "ended on a bound (its standard error then describes the unconstrained curvature only)");
  }
};

struct FitSummary {
  bool converged = false;     // Ceres reported convergence (not a cap on iterations or time)
  std::string termination;    // Ceres's message
  int iterations = 0;
  double initial_cost = 0.0;  // 1/2 sum of squared scaled residuals
  double final_cost = 0.0;
  double seconds = 0.0;       // wall time of the solve
  std::size_t residuals = 0;
  std::size_t free_parameters = 0;  // plant parameters estimated
  std::size_t nuisance_parameters = 0;  // e.g. segment initial states of the multiple shooting
  double residual_rms = 0.0;  // RMS of the unscaled residuals (the measurement's unit)
  double nrmse = 0.0;         // residual RMS / standard deviation of the measurement
  // Free parameters the data cannot determine: each entry names them and why ("not excited", "not separable from").
  std::vector<std::string> not_identifiable;
  std::string report;         // a few lines for a person

  // The single figures a Python fit result shows (servobench.identify.IdentifiedPlant reads their names, units and
  // docs from here; decision OQ6).
  template <class V>
  static void describe(V&& v) {
    using S = FitSummary;
    v("nrmse", &S::nrmse, "", "residual RMS over the measurement's standard deviation (time fit) or the relative complex error (frequency fit); 0: a perfect fit");
    v("residual_rms", &S::residual_rms, "measured unit", "RMS of the unscaled residuals, in the measurement's unit (rad or rad/s for a time fit; nepers and radians of the log-ratio for a frequency fit)");
    v("converged", &S::converged, "", "Ceres reported convergence (not a cap on iterations or time)");
    v("iterations", &S::iterations, "", "solver iterations, over all stages");
    v("seconds", &S::seconds, "s", "wall time of the solve");
  }
};

// Covariance of the plant parameters from the Jacobian at the solution, with the nuisance parameters (blocks of
// `nuisance_block` columns after the first `global` columns, each touching its own rows) eliminated by the Schur
// complement: cov = s^2 (J^T J)^-1 restricted to the plant parameters, s^2 = 2 cost / (m - n). `free_mask` selects
// the plant parameters that were estimated (the others are held fixed and get no column). Also diagnoses
// identifiability: on the correlation form of the reduced information, an eigenvalue below 1e-10 marks a direction
// the data cannot see; a free parameter whose relative standard error exceeds max_relative_error is named too.
struct CovarianceResult {
  Eigen::MatrixXd covariance;         // over all plant parameters (zero rows/columns for fixed ones)
  std::vector<double> std_error;      // sqrt of the diagonal
  std::vector<std::string> not_identifiable;
};

}  // namespace servobench::identify
