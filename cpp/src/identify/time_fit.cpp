#include "servobench/identify/time_fit.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <ceres/ceres.h>

#include "servobench/common/validate.hpp"
#include "servobench/identify/covariance.hpp"
#include "servobench/identify/solver_progress.hpp"

#include "shooting_model.hpp"

namespace servobench::identify {

void TimeFitOptions::validate() const {
  check_integer("TimeFitOptions", "segment_samples", segment_samples, 10, 100000);
  check_integer("TimeFitOptions", "min_segment_samples", min_segment_samples, 3, segment_samples);
  check_integer("TimeFitOptions", "initial_segment_samples", initial_segment_samples, 10, 100000);
  check_integer("TimeFitOptions", "edge_samples", edge_samples, 0, 1000);
  check_integer("TimeFitOptions", "direction_window", direction_window, 2, 1000);
  check_nonnegative("TimeFitOptions", "rest_threshold", rest_threshold);
  check_integer("TimeFitOptions", "substeps", substeps, 1, 1000);
  if (!(current_bw_hz > 0.0)) throw_invalid("TimeFitOptions", "current_bw_hz", current_bw_hz, "must be > 0 (inf: none)");
  check_range("TimeFitOptions", "stribeck_exponent", stribeck_exponent, 0.5, 4.0);
  check_positive("TimeFitOptions", "measurement_scale", measurement_scale);
  check_nonnegative("TimeFitOptions", "continuity_weight", continuity_weight);
  check_positive("TimeFitOptions", "loss_scale", loss_scale);
  check_integer("TimeFitOptions", "max_iterations", max_iterations, 1, 10000);
  check_integer("TimeFitOptions", "num_threads", num_threads, 1, 64);
  check_positive("TimeFitOptions", "max_relative_std_error", max_relative_std_error);
}

namespace {

using detail::add_segment_blocks;
using detail::check_log;
using detail::FitContext;
using detail::init_context;
using detail::run_segment;
using detail::state_at;

struct Stage {
  ShootingProblem shooting;
  std::unique_ptr<ceres::Problem> problem;
  std::vector<int> free;       // the parameters this stage moves
  std::vector<double> block;   // their values: the problem's parameter block when `reduced`
  bool reduced = false;        // false: p itself is the block, its held entries under a SubsetManifold
  ceres::Solver::Summary summary;
  double seconds = 0.0;
};

std::string loss_name(Loss l) {
  switch (l) {
    case Loss::kHuber: return "Huber";
    case Loss::kSoftLOne: return "soft L1";
    case Loss::kCauchy: return "Cauchy";
    default: return "none";
  }
}

}  // namespace

TimeFitResult fit_time_domain(const TimeLog& log, const ParameterSetup& setup, const TimeFitOptions& options,
                              const StageJoin* join) {
  options.validate();
  if (join != nullptr && !(join->rtol > 0.0 && join->rtol < 1.0))
    throw_invalid("StageJoin", "rtol", join->rtol, "must be in (0, 1)");
  check_log(log, options);
  const PlantModel model = options.model;
  const auto& info = model_parameters(model);
  const int np = parameter_count(model);
  const int ns = mechanical_states(model);
  if (static_cast<int>(setup.initial.size()) != np)
    throw std::invalid_argument(std::string("ParameterSetup.initial: the ") + model_name(model) + " model has " +
                                std::to_string(np) + " parameters, got " + std::to_string(setup.initial.size()));
  std::vector<bool> fixed = setup.fixed.empty() ? std::vector<bool>(static_cast<std::size_t>(np), false) : setup.fixed;
  std::vector<double> lower = setup.lower, upper = setup.upper;
  if (lower.empty())
    for (const auto& pi : info) lower.push_back(pi.lower);
  if (upper.empty()) upper.assign(static_cast<std::size_t>(np), std::numeric_limits<double>::infinity());
  if (fixed.size() != static_cast<std::size_t>(np) || lower.size() != static_cast<std::size_t>(np) ||
      upper.size() != static_cast<std::size_t>(np))
    throw std::invalid_argument("ParameterSetup: fixed, lower and upper must have one entry per parameter");
  for (int i = 0; i < np; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    const double v = setup.initial[u];
    if (!std::isfinite(v)) throw_invalid("ParameterSetup", info[u].name, v, "is not a finite number");
    if (!fixed[u] && (v < lower[u] || v > upper[u] || !(lower[u] < upper[u])))
      throw_invalid("ParameterSetup", info[u].name, v,
                    "(initial value) is outside its bounds " + format_value(lower[u]) + ".." + format_value(upper[u]));
  }

  FitContext ctx;
  init_context(ctx, log, options);
  {  // a load held at 0 needs no input column (load_nm is the last parameter of both models)
    const std::size_t li = static_cast<std::size_t>(np - 1);
    ctx.has_load = !(fixed[li] && setup.initial[li] == 0.0);
  }
  const std::size_t n = log.measured.size();

  // Internally the breakaway entry is the Stribeck excess Fs - Fc >= 0 (plant_model.hpp).
  const std::size_t si = static_cast<std::size_t>(static_index(model));
  std::vector<double> p = to_internal(model, setup.initial);
  lower[si] = 0.0;
  upper[si] = std::numeric_limits<double>::infinity();
  const auto& y = log.measured;
  std::vector<int> free_index;
  for (int i = 0; i < np; ++i)
    if (!fixed[static_cast<std::size_t>(i)]) free_index.push_back(i);
  if (free_index.empty()) throw std::invalid_argument("ParameterSetup: every parameter is fixed; nothing to fit");
  // A later stage starts its segments where the previous stage's model is at their first sample (decision LK3): the
  // previous segment that holds the sample, simulated to it with the present parameters. A sample no previous
  // segment holds keeps the state read from the data.
  auto warm_start = [&](const ShootingProblem& prev, ShootingProblem& sp) {
    const std::size_t nsu = static_cast<std::size_t>(ns);
    std::size_t j = 0;
    for (std::size_t s = 0; s < sp.starts.size(); ++s) {
      const int k = sp.starts[s];
      while (j < prev.starts.size() && prev.starts[j] + prev.counts[j] <= k) ++j;
      if (j == prev.starts.size()) break;
      if (prev.starts[j] > k) continue;
      const double* x0 = prev.states.data() + j * nsu;
      double* x = sp.states.data() + s * nsu;
      if (prev.starts[j] == k)
        std::copy(x0, x0 + ns, x);
      else
        state_at(ctx, p.data(), x0, prev.starts[j], k - prev.starts[j], x);
    }
  };
  // One stage of the continuation: segments of about `len` samples, their start states from the previous stage (the
  // first stage: from the data), solved from the present parameters p.
  auto run_stage = [&](int len, bool hold_stribeck, bool last, const ShootingProblem* prev, Stage& st) {
    TimeFitOptions so = options;
    so.segment_samples = len;
    so.min_segment_samples = std::min(options.min_segment_samples, len);
    st.shooting = shooting_problem(log, so);
    if (prev) warm_start(*prev, st.shooting);
    st.problem = std::make_unique<ceres::Problem>();
    ceres::Problem& problem = *st.problem;
    std::vector<int> constant;
    std::vector<bool> held(static_cast<std::size_t>(np), false);
    for (int i = 0; i < np; ++i)
      if (fixed[static_cast<std::size_t>(i)] || (hold_stribeck && (i == static_index(model) || i == stribeck_index(model)))) {
        constant.push_back(i);
        held[static_cast<std::size_t>(i)] = true;
      }
    for (int i = 0; i < np; ++i)
      if (!held[static_cast<std::size_t>(i)]) {
        st.free.push_back(i);
        st.block.push_back(p[static_cast<std::size_t>(i)]);
      }
    st.reduced = add_segment_blocks(problem, ctx, st.shooting, p.data(), options, true, &held, st.block.data());
    if (!st.reduced && !constant.empty()) problem.SetManifold(p.data(), new ceres::SubsetManifold(np, constant));
    for (std::size_t j = 0; j < st.free.size(); ++j) {
      const std::size_t u = static_cast<std::size_t>(st.free[j]);
      double* block = st.reduced ? st.block.data() : p.data();
      const int at = st.reduced ? static_cast<int>(j) : st.free[j];
      if (std::isfinite(lower[u])) problem.SetParameterLowerBound(block, at, lower[u]);
      if (std::isfinite(upper[u])) problem.SetParameterUpperBound(block, at, upper[u]);
    }
    // A speed log does not see the absolute angle: hold the motor angle of each segment (the twist stays free).
    if (log.measured_is_speed)
      for (std::size_t i = 0; i < st.shooting.starts.size(); ++i)
        problem.SetManifold(st.shooting.states.data() + i * static_cast<std::size_t>(ns),
                            new ceres::SubsetManifold(ns, {0}));

    ceres::Solver::Options sopt;
    sopt.linear_solver_type = ceres::DENSE_SCHUR;
    // The held-Stribeck stage only brings J, b and Fc near: a few iterations do; the later stages converge. Its own
    // minimum (the peak held at its guess) is not the fit's, so iterating it further refines a wrong model (decision
    // FV7: 8 iterations, where 20 cost rigid B 12 more Jacobians per start and the same later stages).
    sopt.max_num_iterations = hold_stribeck ? std::min(options.max_iterations, 8) : options.max_iterations;
    sopt.num_threads = options.num_threads;
    // Stop when the relative cost change per iteration is below 1e-4 / samples in the last stage (decision J48): the
    // Gauss-Newton iterations converge linearly here (the dry friction's switching makes the residual non-smooth),
    // at a rate r ~ 0.65, so the cost left above the minimum is about r / (1 - r) times the last change, and the
    // parameters stand within about 0.03 standard errors of the minimum; the earlier stages only bring the next one
    // near (Ceres' default 1e-6).
    sopt.function_tolerance =
        last ? std::min(1e-8, std::max(1e-12, 1e-4 / static_cast<double>(log.measured.size()))) : 1e-6;
    sopt.parameter_tolerance = 1e-12;
    sopt.gradient_tolerance = 1e-14;
    sopt.logging_type = ceres::SILENT;
    std::unique_ptr<SolverProgress> cb;
    if (options.progress) {
      cb = std::make_unique<SolverProgress>(options.progress);
      sopt.callbacks.push_back(cb.get());
    }
    const auto t0 = std::chrono::steady_clock::now();
    ceres::Solve(sopt, &problem, &st.summary);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (st.reduced)
      for (std::size_t j = 0; j < st.free.size(); ++j) p[static_cast<std::size_t>(st.free[j])] = st.block[j];

  };

  // Segment-length continuation: short segments first (a wide basin of attraction from poor guesses), then doubled
  // up to segment_samples (more information per segment state, hence smaller standard errors).
  std::vector<int> lengths;
  for (int l = std::min(options.initial_segment_samples, options.segment_samples); l < options.segment_samples; l *= 2)
    lengths.push_back(l);
  lengths.push_back(options.segment_samples);
  // With the Stribeck peak free, a first stage holds its level and speed at their guesses: with inertia, viscous and
  // Coulomb friction far off, the peak's parameters drift to where the peak vanishes (ws -> 0), and stay there.
  const bool stribeck_free = options.hold_stribeck_first &&
                             (!fixed[si] || !fixed[static_cast<std::size_t>(stribeck_index(model))]);
  if (stribeck_free) lengths.insert(lengths.begin(), lengths.front());
  Stage st;
  ShootingProblem prev;
  int total_iterations = 0;
  double seconds = 0.0, initial_cost = 0.0;
  // Where the time goes (decision FT4): per stage its segment length and iterations; over all stages Ceres' own
  // split into residual evaluations, Jacobian evaluations (the model on Jets) and the linear solver.
  std::ostringstream stages;
  double t_residual = 0.0, t_jacobian = 0.0, t_linear = 0.0;
  TimeFitResult result;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    if (i) prev = st.shooting;
    st = Stage();
    run_stage(lengths[i], stribeck_free && i == 0, i + 1 == lengths.size(), i ? &prev : nullptr, st);
    const int it = static_cast<int>(st.summary.iterations.size()) - 1;
    total_iterations += it;
    seconds += st.seconds;
    if (i == 0) initial_cost = st.summary.initial_cost;
    stages << (i ? ", " : "") << lengths[i] << (stribeck_free && i == 0 ? " (Stribeck held)" : "") << ": " << it;
    t_residual += st.summary.residual_evaluation_time_in_seconds;
    t_jacobian += st.summary.jacobian_evaluation_time_in_seconds;
    t_linear += st.summary.linear_solver_time_in_seconds;
    result.stage_parameters.push_back(to_external(model, p));
    if (join != nullptr && i + 1 < lengths.size() && i < join->points.size() &&
        join->points[i].size() == static_cast<std::size_t>(np)) {
      const std::vector<double>& q = join->points[i];
      const std::vector<double>& here = result.stage_parameters.back();
      bool same = true;
      for (int k : free_index) {
        const double a = here[static_cast<std::size_t>(k)], b = q[static_cast<std::size_t>(k)];
        if (!(std::fabs(a - b) <= join->rtol * std::max(std::fabs(a), std::fabs(b)) ||
              std::max(std::fabs(a), std::fabs(b)) < 1e-300))
          same = false;
      }
      if (same) {
        result.joined_stage = static_cast<int>(i);
        FitSummary& fs = result.summary;
        fs.iterations = total_iterations;
        fs.initial_cost = initial_cost;
        fs.final_cost = st.summary.final_cost;
        fs.seconds = seconds;
        std::ostringstream os;
        os << "Stages (segment samples: iterations): " << stages.str() << "; joined after stage " << i + 1 << " of "
           << lengths.size() << ": every free parameter within " << join->rtol
           << " (relative) of the other start's at that stage.";
        fs.report = os.str();
        return result;
      }
    }
  }
  ceres::Solver::Summary& summary = st.summary;
  ceres::Problem& problem = *st.problem;
  const std::vector<int>& starts = st.shooting.starts;
  const std::vector<int>& counts = st.shooting.counts;
  const auto x0 = [&](int s) { return st.shooting.states.data() + s * ns; };
  const int nseg = static_cast<int>(starts.size());
  const int len = options.segment_samples;

  // The model's output and the residuals at the solution.
  result.predicted.assign(n, std::numeric_limits<double>::quiet_NaN());
  result.residual.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (int s = 0; s < nseg; ++s) {
    const std::size_t a = static_cast<std::size_t>(starts[static_cast<std::size_t>(s)]);
    run_segment(ctx, p.data(), x0(s), static_cast<int>(a),
                counts[static_cast<std::size_t>(s)], result.predicted.data() + a);
  }
  double ss = 0.0, mean = 0.0;
  std::size_t used = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (std::isnan(result.predicted[k])) continue;
    result.residual[k] = y[k] - result.predicted[k];
    ss += result.residual[k] * result.residual[k];
    mean += y[k];
    ++used;
  }
  mean /= static_cast<double>(used);
  double var = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isnan(result.predicted[k])) var += (y[k] - mean) * (y[k] - mean);
  result.segment_start = starts;
  result.segment_count = counts;
  result.segment_states = st.shooting.states;

  // Standard errors: the Jacobian at the solution, segment states eliminated.
  ceres::Problem::EvaluateOptions eopt;
  eopt.parameter_blocks.push_back(st.reduced ? st.block.data() : p.data());
  for (int s = 0; s < nseg; ++s) eopt.parameter_blocks.push_back(x0(s));
  eopt.apply_loss_function = false;
  eopt.num_threads = options.num_threads;
  double cost_at = 0.0;
  ceres::CRSMatrix jac;
  problem.Evaluate(eopt, &cost_at, nullptr, nullptr, &jac);
  std::vector<std::string> names;
  for (const auto& pi : info) names.push_back(pi.name);
  const int nuisance = log.measured_is_speed ? ns - 1 : ns;
  CovarianceResult cov = reduced_covariance(jac, free_index, np, nuisance, cost_at, p, to_internal(model, setup.initial),
                                            names, options.max_relative_std_error);
  {  // back to the breakaway level: var(Fs) = var(Fc) + var(e) + 2 cov(Fc, e)
    const Eigen::Index a = static_cast<Eigen::Index>(coulomb_index(model)), b = static_cast<Eigen::Index>(si);
    const double v = cov.covariance(a, a) + cov.covariance(b, b) + 2.0 * cov.covariance(a, b);
    if (std::isfinite(cov.std_error[si])) cov.std_error[si] = std::sqrt(std::max(v, 0.0));
  }
  p = to_external(model, p);

  for (int i = 0; i < np; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    ParameterEstimate e;
    e.name = info[u].name;
    e.unit = info[u].unit;
    e.value = p[u];
    e.initial = setup.initial[u];
    e.std_error = cov.std_error[u];
    e.lower = lower[u];
    e.upper = upper[u];
    e.fixed = fixed[u];
    const double tol = 1e-9 * std::max(1.0, std::fabs(p[u]));
    e.at_bound = !e.fixed && ((std::isfinite(lower[u]) && p[u] - lower[u] <= tol && lower[u] > info[u].lower) ||
                              (std::isfinite(upper[u]) && upper[u] - p[u] <= tol));
    result.parameters.push_back(e);
  }
  FitSummary& fs = result.summary;
  fs.converged = summary.termination_type == ceres::CONVERGENCE;
  fs.termination = summary.message;
  fs.iterations = total_iterations;
  fs.initial_cost = initial_cost;
  fs.final_cost = summary.final_cost;
  fs.seconds = seconds;
  fs.residuals = used;
  fs.free_parameters = free_index.size();
  fs.nuisance_parameters = static_cast<std::size_t>(nseg * nuisance);
  fs.residual_rms = std::sqrt(ss / static_cast<double>(used));
  fs.nrmse = var > 0 ? std::sqrt(ss / var) : std::numeric_limits<double>::infinity();
  fs.not_identifiable = cov.not_identifiable;
  std::ostringstream os;
  os << "Time-domain fit of a " << model_name(model) << " plant: " << free_index.size() << " parameters, " << nseg
     << " shooting segments of about " << len << " samples (" << fs.nuisance_parameters << " segment states), "
     << used << " of " << n << " samples in one-way motion, loss " << loss_name(options.loss) << ".\n"
     << "Ceres: " << (fs.converged ? "converged" : "did not converge") << " after " << fs.iterations
     << " iterations in " << seconds << " s (" << summary.message << "); cost " << summary.initial_cost << " -> "
     << summary.final_cost << ".\n"
     << "Stages (segment samples: iterations): " << stages.str() << "; residuals " << t_residual << " s, Jacobians "
     << t_jacobian << " s, linear solver " << t_linear << " s.\n"
     << "Residual RMS " << fs.residual_rms << " (" << fs.residual_rms * ctx.inv_scale
     << " x measurement_scale), NRMSE " << fs.nrmse << ".";
  if (!fs.not_identifiable.empty()) {
    os << "\nNot identifiable from these data:";
    for (const auto& s : fs.not_identifiable) os << "\n  - " << s;
  }
  fs.report = os.str();
  return result;
}

}  // namespace servobench::identify
