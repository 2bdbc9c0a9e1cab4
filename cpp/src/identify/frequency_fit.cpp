#include "servobench/identify/frequency_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <ceres/ceres.h>

#include "servobench/common/validate.hpp"
#include "servobench/identify/covariance.hpp"
#include "servobench/identify/solver_progress.hpp"
#include "servobench/tuning/loop_response.hpp"

namespace servobench::identify {

void FrequencyFitOptions::validate() const {
  check_nonnegative("FrequencyFitOptions", "delay_initial_s", delay_initial_s);
  check_integer("FrequencyFitOptions", "max_iterations", max_iterations, 1, 10000);
  check_positive("FrequencyFitOptions", "max_relative_std_error", max_relative_std_error);
}

void MechanicsIO::validate() const {
  check_nonnegative("MechanicsIO", "sample_period_s", sample_period_s);
  check_integer("MechanicsIO", "delay_samples", delay_samples, 0, 1000);
  if (delay_samples != 0 && sample_period_s == 0.0)
    throw std::invalid_argument("MechanicsIO.delay_samples = " + std::to_string(delay_samples) +
                                " needs a sample_period_s > 0 (a continuous-time response has no samples)");
  if (!(std::isfinite(torque_per_input) && torque_per_input != 0.0))
    throw_invalid("MechanicsIO", "torque_per_input", torque_per_input, "must be a finite non-zero number (N*m per unit)");
  if (!(std::isfinite(output_per_rad) && output_per_rad != 0.0))
    throw_invalid("MechanicsIO", "output_per_rad", output_per_rad, "must be a finite non-zero number (units per rad)");
  if (!(current_bw_hz > 0.0))
    throw_invalid("MechanicsIO", "current_bw_hz", current_bw_hz, "must be > 0 Hz (inf: no current loop)");
}

std::vector<std::complex<double>> mechanics_response(const MechanicsIO& io, PlantModel model,
                                                     const std::vector<double>& parameters, double delay_s,
                                                     const std::vector<double>& freq_hz) {
  using Complex = std::complex<double>;
  ModelLayout layout;
  layout.model = model;
  layout.current_bw_hz = io.current_bw_hz;
  const int n = layout.states();
  const int nlin = linear_parameter_count(model);
  const std::vector<double> lin(parameters.begin(), parameters.begin() + nlin);
  // The plant objects validate the parameters (an out-of-range trial point throws, as with an Axis).
  if (model == PlantModel::kRigid)
    rigid_plant(parameters, 2.0).validate();
  else
    two_mass_plant(parameters, 2.0).validate();
  Eigen::MatrixXd a, b;
  if (io.sample_period_s > 0.0) {
    const Discretisation d = discretise(layout, lin, io.sample_period_s, false);
    a = d.phi[0];
    b = d.gamma[0];
  } else {
    model_linear(layout, lin.data(), a, b);
  }
  const int row = io.speed_output ? (io.on_load ? layout.load_speed() : layout.motor_speed())
                                  : (io.on_load ? layout.load_angle() : layout.motor_angle());
  const Eigen::MatrixXcd ac = a.cast<Complex>();
  const Eigen::VectorXcd bc = b.col(0).cast<Complex>();
  std::vector<Complex> g(freq_hz.size());
  for (std::size_t k = 0; k < freq_hz.size(); ++k) {
    const Complex s(0.0, 2.0 * M_PI * freq_hz[k]);
    const Complex z = io.sample_period_s > 0.0 ? std::exp(s * io.sample_period_s) : s;
    const Eigen::VectorXcd x = (z * Eigen::MatrixXcd::Identity(n, n) - ac).partialPivLu().solve(bc);
    Complex y = io.output_per_rad * io.torque_per_input * x(row);
    if (io.delay_samples > 0) y *= std::pow(z, -io.delay_samples);
    if (delay_s != 0.0) y *= std::exp(-s * delay_s);
    g[k] = y;
  }
  return g;
}

std::vector<std::complex<double>> model_plant_response(const machine::AxisConfig& config, PlantModel model,
                                                       const std::vector<double>& parameters, double delay_s,
                                                       const std::vector<double>& freq_hz) {
  machine::AxisConfig c = config;
  if (model == PlantModel::kRigid)
    c.plant = rigid_plant(parameters, 2.0);
  else
    c.plant = two_mass_plant(parameters, 2.0);
  std::vector<std::complex<double>> g = tuning::loop_response(c, freq_hz).plant;
  if (delay_s != 0.0)
    for (std::size_t k = 0; k < g.size(); ++k) g[k] *= std::polar(1.0, -2.0 * M_PI * freq_hz[k] * delay_s);
  return g;
}

namespace {

using Evaluate = std::function<std::vector<std::complex<double>>(const std::vector<double>&, double)>;

struct ResponseCost {
  const Evaluate* evaluate;
  const FrequencyData* data;
  PlantModel model;
  int np;
  bool operator()(const double* p, const double* delay, double* r) const {
    // Central differences step around the point; a held friction parameter at 0 would step below its physical
    // bound, which the plant refuses: evaluate at the bound instead (those parameters do not enter the response).
    std::vector<double> v(p, p + np);
    const auto& info = model_parameters(model);
    for (int i = 0; i < np; ++i)
      v[static_cast<std::size_t>(i)] = std::max(v[static_cast<std::size_t>(i)], info[static_cast<std::size_t>(i)].lower);
    std::vector<std::complex<double>> g;
    try {
      g = (*evaluate)(v, delay[0]);
    } catch (const std::exception&) {
      return false;  // a trial point outside the plant's valid range: Ceres shrinks the step
    }
    for (std::size_t k = 0; k < g.size(); ++k) {
      const std::complex<double> e = std::log(data->response[k] / g[k]);
      const double w = data->weight.empty() ? 1.0 : data->weight[k];
      r[2 * k] = w * e.real();
      r[2 * k + 1] = w * e.imag();
    }
    return true;
  }
};

FrequencyFitResult fit_with(const Evaluate& evaluate, double nyquist, const FrequencyData& data,
                            const ParameterSetup& setup, const FrequencyFitOptions& options) {
  options.validate();
  const PlantModel model = options.model;
  const auto& info = model_parameters(model);
  const int np = parameter_count(model);
  const int nlin = linear_parameter_count(model);
  const std::size_t nf = data.freq_hz.size();
  if (data.response.size() != nf)
    throw std::invalid_argument("FrequencyData: freq_hz has " + std::to_string(nf) + " points but response has " +
                                std::to_string(data.response.size()) + "; they must have the same length");
  if (!data.weight.empty() && data.weight.size() != nf)
    throw std::invalid_argument("FrequencyData: weight must be empty or have one entry per frequency");
  for (std::size_t k = 0; k < nf; ++k) {
    if (!(data.freq_hz[k] > 0.0 && data.freq_hz[k] < nyquist))
      throw std::invalid_argument("FrequencyData.freq_hz[" + std::to_string(k) + "] = " +
                                  format_value(data.freq_hz[k]) + " Hz is outside 0.." + format_value(nyquist) +
                                  " Hz (above zero, below the Nyquist frequency)");
    if (!std::isfinite(data.response[k].real()) || !std::isfinite(data.response[k].imag()) ||
        data.response[k] == 0.0)
      throw std::invalid_argument("FrequencyData.response[" + std::to_string(k) + "] is not a finite non-zero number");
    if (!data.weight.empty() && !(data.weight[k] >= 0.0 && std::isfinite(data.weight[k])))
      throw std::invalid_argument("FrequencyData.weight[" + std::to_string(k) + "] = " +
                                  format_value(data.weight[k]) + " must be a finite number >= 0");
  }
  if (static_cast<int>(setup.initial.size()) != np)
    throw std::invalid_argument(std::string("ParameterSetup.initial: the ") + model_name(model) + " model has " +
                                std::to_string(np) + " parameters, got " + std::to_string(setup.initial.size()));
  std::vector<bool> fixed = setup.fixed.empty() ? std::vector<bool>(static_cast<std::size_t>(np), false) : setup.fixed;
  for (int i = nlin; i < np; ++i) fixed[static_cast<std::size_t>(i)] = true;  // friction: not in a linear response
  std::vector<double> lower = setup.lower, upper = setup.upper;
  if (lower.empty())
    for (const auto& pi : info) lower.push_back(pi.lower);
  if (upper.empty()) upper.assign(static_cast<std::size_t>(np), std::numeric_limits<double>::infinity());
  int nfree = 0;
  for (int i = 0; i < np; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    if (!std::isfinite(setup.initial[u])) throw_invalid("ParameterSetup", info[u].name, setup.initial[u], "is not finite");
    if (fixed[u]) continue;
    ++nfree;
    if (setup.initial[u] < lower[u] || setup.initial[u] > upper[u])
      throw_invalid("ParameterSetup", info[u].name, setup.initial[u],
                    "(initial value) is outside its bounds " + format_value(lower[u]) + ".." + format_value(upper[u]));
  }
  nfree += options.fit_delay ? 1 : 0;
  if (2 * nf < static_cast<std::size_t>(nfree) + 1)
    throw std::invalid_argument("FrequencyData: " + std::to_string(nf) + " frequencies cannot determine " +
                                std::to_string(nfree) + " parameters");

  std::vector<double> p = setup.initial;
  double delay = options.delay_initial_s;
  ceres::Problem problem;
  auto* f = new ResponseCost{&evaluate, &data, model, np};
  ceres::CostFunction* cost = nullptr;
  const int nr = static_cast<int>(2 * nf);
  if (model == PlantModel::kRigid)
    cost = new ceres::NumericDiffCostFunction<ResponseCost, ceres::CENTRAL, ceres::DYNAMIC, 6, 1>(
        f, ceres::TAKE_OWNERSHIP, nr);
  else
    cost = new ceres::NumericDiffCostFunction<ResponseCost, ceres::CENTRAL, ceres::DYNAMIC, 11, 1>(
        f, ceres::TAKE_OWNERSHIP, nr);
  problem.AddResidualBlock(cost, nullptr, p.data(), &delay);
  std::vector<int> constant;
  for (int i = 0; i < np; ++i)
    if (fixed[static_cast<std::size_t>(i)]) constant.push_back(i);
  problem.SetManifold(p.data(), new ceres::SubsetManifold(np, constant));
  for (int i = 0; i < np; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    if (fixed[u]) continue;
    if (std::isfinite(lower[u])) problem.SetParameterLowerBound(p.data(), i, lower[u]);
    if (std::isfinite(upper[u])) problem.SetParameterUpperBound(p.data(), i, upper[u]);
  }
  if (options.fit_delay)
    problem.SetParameterLowerBound(&delay, 0, 0.0);
  else
    problem.SetParameterBlockConstant(&delay);

  ceres::Solver::Options sopt;
  sopt.linear_solver_type = ceres::DENSE_QR;
  sopt.max_num_iterations = options.max_iterations;
  sopt.function_tolerance = 1e-12;
  sopt.parameter_tolerance = 1e-12;
  sopt.logging_type = ceres::SILENT;
  std::unique_ptr<SolverProgress> cb;
  if (options.progress) {
    cb = std::make_unique<SolverProgress>(options.progress);
    sopt.callbacks.push_back(cb.get());
  }
  ceres::Solver::Summary summary;
  const auto t0 = std::chrono::steady_clock::now();
  ceres::Solve(sopt, &problem, &summary);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Covariance over the model parameters and the delay (one extra column when fitted).
  ceres::Problem::EvaluateOptions eopt;
  eopt.parameter_blocks = {p.data()};
  if (options.fit_delay) eopt.parameter_blocks.push_back(&delay);
  double cost_at = 0.0;
  ceres::CRSMatrix jac;
  problem.Evaluate(eopt, &cost_at, nullptr, nullptr, &jac);
  std::vector<int> free_index;
  for (int i = 0; i < np; ++i)
    if (!fixed[static_cast<std::size_t>(i)]) free_index.push_back(i);
  std::vector<std::string> names;
  for (const auto& pi : info) names.push_back(pi.name);
  names.push_back("delay_s");
  std::vector<double> values = p, initial = setup.initial;
  values.push_back(delay);
  initial.push_back(options.delay_initial_s);
  if (options.fit_delay) free_index.push_back(np);
  const CovarianceResult cov = reduced_covariance(jac, free_index, np + 1, 0, cost_at, values, initial, names,
                                                  options.max_relative_std_error);

  FrequencyFitResult result;
  for (int i = 0; i <= np; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    ParameterEstimate e;
    e.name = names[u];
    e.unit = i < np ? info[u].unit : "s";
    e.value = values[u];
    e.initial = initial[u];
    e.std_error = cov.std_error[u];
    e.lower = i < np ? lower[u] : 0.0;
    e.upper = i < np ? upper[u] : std::numeric_limits<double>::infinity();
    e.fixed = i < np ? bool(fixed[u]) : !options.fit_delay;
    result.parameters.push_back(e);
  }
  result.predicted = evaluate(p, delay);
  FitSummary& fs = result.summary;
  fs.converged = summary.termination_type == ceres::CONVERGENCE;
  fs.termination = summary.message;
  fs.iterations = static_cast<int>(summary.iterations.size()) - 1;
  fs.initial_cost = summary.initial_cost;
  fs.final_cost = summary.final_cost;
  fs.seconds = seconds;
  fs.residuals = 2 * nf;
  fs.free_parameters = free_index.size();
  fs.residual_rms = std::sqrt(2.0 * summary.final_cost / static_cast<double>(2 * nf));
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k < nf; ++k) {
    num += std::norm(data.response[k] - result.predicted[k]);
    den += std::norm(data.response[k]);
  }
  fs.nrmse = std::sqrt(num / den);
  fs.not_identifiable = cov.not_identifiable;
  std::ostringstream os;
  os << "Frequency-domain fit of a " << model_name(model) << " plant: " << free_index.size() << " parameters, " << nf
     << " frequencies" << (options.fit_delay ? ", extra delay fitted" : "") << ".\n"
     << "Ceres: " << (fs.converged ? "converged" : "did not converge") << " after " << fs.iterations
     << " iterations in " << seconds << " s (" << summary.message << "); cost " << summary.initial_cost << " -> "
     << summary.final_cost << ".\n"
     << "RMS log-ratio error " << fs.residual_rms << " (nepers/radians), relative complex error " << fs.nrmse << ".";
  if (!fs.not_identifiable.empty()) {
    os << "\nNot identifiable from these data:";
    for (const auto& s : fs.not_identifiable) os << "\n  - " << s;
  }
  fs.report = os.str();
  return result;
}

}  // namespace

FrequencyFitResult fit_frequency_response(const machine::AxisConfig& config, const FrequencyData& data,
                                          const ParameterSetup& setup, const FrequencyFitOptions& options) {
  machine::AxisConfig cfg = config;
  cfg.validate_and_complete();
  const PlantModel model = options.model;
  const Evaluate evaluate = [&](const std::vector<double>& p, double delay) {
    return model_plant_response(cfg, model, p, delay, data.freq_hz);
  };
  return fit_with(evaluate, 0.5 / *cfg.servo_period_s, data, setup, options);
}

FrequencyFitResult fit_frequency_response(const MechanicsIO& io, const FrequencyData& data,
                                          const ParameterSetup& setup, const FrequencyFitOptions& options) {
  io.validate();
  const PlantModel model = options.model;
  const Evaluate evaluate = [&](const std::vector<double>& p, double delay) {
    return mechanics_response(io, model, p, delay, data.freq_hz);
  };
  const double nyquist =
      io.sample_period_s > 0.0 ? 0.5 / io.sample_period_s : std::numeric_limits<double>::infinity();
  return fit_with(evaluate, nyquist, data, setup, options);
}

}  // namespace servobench::identify
