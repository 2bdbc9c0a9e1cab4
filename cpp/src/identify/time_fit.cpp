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

constexpr int kMaxStates = 5;
template <class T>
using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
template <class T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxStates>;
template <class T>
using InMat = Eigen::Matrix<T, Eigen::Dynamic, 4, 0, kMaxStates, 4>;

inline double value_of(double x) { return x; }
template <int N>
double value_of(const ceres::Jet<double, N>& x) {
  return x.a;
}

// A discretisation matrix on T: the value, and for Jets the derivatives along the first directions (the linear
// parameters come first in the parameter block, so Jet direction k is linear parameter k).
template <class M>
void lift(const Eigen::MatrixXd& v, const std::vector<Eigen::MatrixXd>&, M& out, std::true_type /*double*/) {
  out = v;
}
template <class M>
void lift(const Eigen::MatrixXd& v, const std::vector<Eigen::MatrixXd>& d, M& out, std::false_type /*jet*/) {
  using T = typename M::Scalar;
  out.resize(v.rows(), v.cols());
  for (Eigen::Index r = 0; r < v.rows(); ++r)
    for (Eigen::Index c = 0; c < v.cols(); ++c) {
      T x(v(r, c));
      for (std::size_t k = 0; k < d.size(); ++k) x.v[static_cast<Eigen::Index>(k)] = d[k](r, c);
      out(r, c) = x;
    }
}

// Everything the segments share.
struct FitContext {
  ModelLayout layout;
  const TimeLog* log = nullptr;
  std::vector<double> lag;  // current-loop torque at every sample (parameter-free: the loop is known)
  double lag_decay = 0.0;   // exp(-wc h) over one sub-step h
  bool has_load = true;     // false: the constant load is held at 0 (no input column for it)
  int substeps = 1;
  int output_index = 0;
  double inv_scale = 1.0;
  double continuity_weight = 1.0;
  mutable std::unique_ptr<DiscretisationCache> cache;
};

// The mechanical part of a discretisation (value or derivative): the current-loop torque is data (ctx.lag), so the
// state is mechanical only and the lag's column of phi becomes a fourth input column:
// x_mech' = phi_mm x_mech + [gamma_m | phi_m,lag] [u, t_motor, t_load, lag].
Eigen::MatrixXd mechanical_phi(const Eigen::MatrixXd& phi, int nl) {
  return phi.bottomRightCorner(phi.rows() - nl, phi.cols() - nl);
}
Eigen::MatrixXd mechanical_gamma(const Eigen::MatrixXd& phi, const Eigen::MatrixXd& gamma, int nl) {
  const Eigen::Index nm = gamma.rows() - nl;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(nm, 4);
  g.leftCols(3) = gamma.bottomRows(nm);
  if (nl) g.col(3) = phi.block(nl, 0, nm, 1);
  return g;
}

// Simulates samples [start, start + count) from the mechanical state x0 with parameters p, writing the output per
// sample to out (scaled residuals when y is given). T = double or a Ceres Jet.
template <PlantModel M, class T>
void simulate_segment(const FitContext& ctx, const T* p, const T* x0, int start, int count, T* out, bool residual,
                      const T* x_next = nullptr, T* continuity = nullptr) {
  constexpr bool is_double = std::is_same<T, double>::value;
  const ModelLayout& layout = ctx.layout;
  const int nlin = linear_parameter_count(layout.model);
  const int nl = layout.lag_states();
  double lin[6];
  for (int k = 0; k < nlin; ++k) lin[k] = value_of(p[k]);
  const auto disc = ctx.cache->get(lin, !is_double);
  const std::size_t masks = disc->phi.size();
  std::array<Mat<T>, 4> phis;
  std::array<InMat<T>, 4> gammas;
  for (std::size_t m = 0; m < masks; ++m) {
    std::vector<Eigen::MatrixXd> dphi, dgamma;
    for (std::size_t k = 0; k < disc->dphi[m].size(); ++k) {
      dphi.push_back(mechanical_phi(disc->dphi[m][k], nl));
      dgamma.push_back(mechanical_gamma(disc->dphi[m][k], disc->dgamma[m][k], nl));
    }
    lift(mechanical_phi(disc->phi[m], nl), dphi, phis[m], std::integral_constant<bool, is_double>());
    lift(mechanical_gamma(disc->phi[m], disc->gamma[m], nl), dgamma, gammas[m],
         std::integral_constant<bool, is_double>());
  }
  plant::DryFriction<T> dry[2];
  T load_nm;
  model_friction<M>(layout, p, dry, &load_nm);
  const int nb = body_count(layout.model);
  plant::BodyIndex idx[2] = {layout.body(0), layout.body(1)};
  for (auto& b : idx) {  // mechanical state indices
    b.angle -= nl;
    b.speed -= nl;
  }
  const int n = mechanical_states(layout.model);
  const int out_index = ctx.output_index - nl;
  Vec<T> x(n), xf(n);
  for (int i = 0; i < n; ++i) x[i] = x0[i];
  char stuck[2] = {0, 0};
  for (int b = 0; b < nb; ++b) stuck[b] = value_of(x[idx[b].speed]) == 0.0 ? 1 : 0;
  const T t_load = -load_nm;
  const std::vector<double>& u = ctx.log->torque_nm;
  const std::vector<double>& y = ctx.log->measured;
  double lag = nl ? ctx.lag[static_cast<std::size_t>(start)] : 0.0;
  for (int k = 0; k < count; ++k) {
    const std::size_t s = static_cast<std::size_t>(start + k);
    out[k] = residual ? T((x[out_index] - T(y[s])) * ctx.inv_scale) : T(x[out_index]);
    if (k + 1 == count && !continuity) break;
    // The logged command and the current loop's torque are data (double): no Jet products for them.
    for (int sub = 0; sub < ctx.substeps; ++sub) {
      if (ctx.has_load)
        plant::advance_with_dry_friction(static_cast<std::size_t>(nb), idx, dry, phis, gammas, u[s], 0.0, t_load, x,
                                         xf, stuck, lag);
      else
        plant::advance_with_dry_friction(static_cast<std::size_t>(nb), idx, dry, phis, gammas, u[s], 0.0, 0.0, x, xf,
                                         stuck, lag);
      if (nl) lag = ctx.lag_decay * lag + (1.0 - ctx.lag_decay) * u[s];
    }
  }
  if (continuity) {  // the next segment must start where this one ends (angles in counts, speeds in counts/sample)
    for (int i = 0; i < n; ++i) {
      const bool angle = i % 2 == 0;
      const double w = ctx.continuity_weight * ctx.inv_scale * (angle ? 1.0 : ctx.log->sample_period_s);
      continuity[i] = (x[i] - x_next[i]) * w;
    }
  }
}

template <PlantModel M>
struct SegmentCost {
  const FitContext* ctx;
  int start, count;
  template <class T>
  bool operator()(const T* p, const T* x0, T* r) const {
    simulate_segment<M>(*ctx, p, x0, start, count, r, true);
    return true;
  }
};

// A segment and the continuity of its end state with the next segment's start (multiple shooting).
template <PlantModel M>
struct LinkedSegmentCost {
  const FitContext* ctx;
  int start, count;
  template <class T>
  bool operator()(const T* p, const T* x0, const T* x_next, T* r) const {
    simulate_segment<M>(*ctx, p, x0, start, count, r, true, x_next, r + count);
    return true;
  }
};

// The layout, the output, the discretisation cache and the known current loop's torque at every sample
// (i' = wc (u - i), u held over each sample, exactly; it starts at the first torque sample).
void init_context(FitContext& ctx, const TimeLog& log, const TimeFitOptions& options) {
  ctx.layout.model = options.model;
  ctx.layout.current_bw_hz = options.current_bw_hz;
  ctx.layout.stribeck_exponent = options.stribeck_exponent;
  ctx.log = &log;
  ctx.substeps = options.substeps;
  ctx.inv_scale = 1.0 / options.measurement_scale;
  ctx.continuity_weight = options.continuity_weight;
  const ModelLayout& l = ctx.layout;
  ctx.output_index = log.measured_is_speed ? (log.measured_on_load ? l.load_speed() : l.motor_speed())
                                           : (log.measured_on_load ? l.load_angle() : l.motor_angle());
  ctx.cache = std::make_unique<DiscretisationCache>(ctx.layout, log.sample_period_s / options.substeps);
  ctx.lag_decay = std::exp(-2.0 * M_PI * options.current_bw_hz * log.sample_period_s / options.substeps);
  const std::size_t n = log.torque_nm.size();
  ctx.lag.clear();
  if (!l.lag_states() || n == 0) return;
  const double e = std::exp(-2.0 * M_PI * options.current_bw_hz * log.sample_period_s);
  ctx.lag.resize(n);
  double i = log.torque_nm[0];
  for (std::size_t k = 0; k < n; ++k) {
    ctx.lag[k] = i;
    i = e * i + (1.0 - e) * log.torque_nm[k];
  }
}

void run_segment(const FitContext& ctx, const double* p, const double* x0, int start, int count, double* out) {
  if (ctx.layout.model == PlantModel::kRigid)
    simulate_segment<PlantModel::kRigid>(ctx, p, x0, start, count, out, false);
  else
    simulate_segment<PlantModel::kTwoMass>(ctx, p, x0, start, count, out, false);
}

struct Stage {
  ShootingProblem shooting;
  std::unique_ptr<ceres::Problem> problem;
  ceres::Solver::Summary summary;
  double seconds = 0.0;
};


void check_log(const TimeLog& log, const TimeFitOptions& o) {
  check_positive("TimeLog", "sample_period_s", log.sample_period_s);
  if (log.torque_nm.size() != log.measured.size())
    throw std::invalid_argument("TimeLog: torque_nm has " + std::to_string(log.torque_nm.size()) +
                                " samples but measured has " + std::to_string(log.measured.size()) +
                                "; they must have the same length");
  for (std::size_t k = 0; k < log.measured.size(); ++k) {
    if (!std::isfinite(log.torque_nm[k]))
      throw std::invalid_argument("TimeLog.torque_nm[" + std::to_string(k) + "] = " + format_value(log.torque_nm[k]) +
                                  " is not a finite number");
    if (!std::isfinite(log.measured[k]))
      throw std::invalid_argument("TimeLog.measured[" + std::to_string(k) + "] = " + format_value(log.measured[k]) +
                                  " is not a finite number");
  }
  const std::size_t need = 2 * static_cast<std::size_t>(o.min_segment_samples);
  if (log.measured.size() < need)
    throw std::invalid_argument("TimeLog: " + std::to_string(log.measured.size()) +
                                " samples is too short a log: at least " + std::to_string(need) + " are needed");
  if (log.measured_on_load && o.model == PlantModel::kRigid) {
    // the same body: allowed, nothing to do
  }
}

// Where the shooting segments go. A segment simulated through a stick phase or a reversal can be trapped: once the
// model body sticks at a different moment than the real one, the residuals stop depending on the segment's state and
// on the friction parameters. The data are therefore cut into runs of one-way motion -- the measured direction,
// sign(y[k+h] - y[k-h]), constant and the change over 2h samples at least `rest_threshold` -- with `edge_samples`
// trimmed at both ends; runs shorter than min_segment_samples are left out, longer ones are split into pieces of
// about segment_samples. Rest phases and reversals carry no residual (the friction's low-speed branch is still seen
// on the way into and out of them).
void shooting_segments(const TimeLog& log, const TimeFitOptions& o, std::vector<int>* starts, std::vector<int>* counts) {
  const std::vector<double>& y = log.measured;
  const int n = static_cast<int>(y.size());
  const int h = o.direction_window / 2;
  const double thr = o.rest_threshold * o.measurement_scale;
  std::vector<int> dir(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k) {
    double d;
    if (log.measured_is_speed) {
      d = y[static_cast<std::size_t>(k)];
    } else {
      const int a = std::max(0, k - h), b = std::min(n - 1, k + h);
      d = y[static_cast<std::size_t>(b)] - y[static_cast<std::size_t>(a)];
    }
    dir[static_cast<std::size_t>(k)] = d >= thr ? 1 : (d <= -thr ? -1 : 0);
  }
  int k = 0;
  while (k < n) {
    if (dir[static_cast<std::size_t>(k)] == 0) {
      ++k;
      continue;
    }
    int e = k;
    while (e < n && dir[static_cast<std::size_t>(e)] == dir[static_cast<std::size_t>(k)]) ++e;
    const int a = k + o.edge_samples, b = e - o.edge_samples;  // [a, b)
    k = e;
    if (b - a < o.min_segment_samples) continue;
    const int pieces = std::max(1, (b - a + o.segment_samples / 2) / o.segment_samples);
    for (int i = 0; i < pieces; ++i) {
      const int s0 = a + (b - a) * i / pieces, s1 = a + (b - a) * (i + 1) / pieces;
      starts->push_back(s0);
      counts->push_back(s1 - s0);
    }
  }
}

// Where the segments start: a line through each segment's first samples (angle and speed; a two-mass load starts
// with the motor).
void initial_states(const TimeLog& log, ShootingProblem& sp) {
  const auto& y = log.measured;
  const double ts = log.sample_period_s;
  const int ns = sp.state_size;
  sp.states.assign(sp.starts.size() * static_cast<std::size_t>(ns), 0.0);
  for (std::size_t s = 0; s < sp.starts.size(); ++s) {
    const std::size_t a = static_cast<std::size_t>(sp.starts[s]);
    const std::size_t m = std::min<std::size_t>(8, static_cast<std::size_t>(sp.counts[s]));
    double angle = 0.0, speed = 0.0;
    if (log.measured_is_speed) {
      speed = y[a];
    } else {
      double s_t = 0, sy = 0, stt = 0, sty = 0;
      for (std::size_t j = 0; j < m; ++j) {
        const double tj = static_cast<double>(j) * ts;
        s_t += tj;
        sy += y[a + j];
        stt += tj * tj;
        sty += tj * y[a + j];
      }
      const double md = static_cast<double>(m);
      speed = (md * sty - s_t * sy) / (md * stt - s_t * s_t);
      angle = (sy - speed * s_t) / md;
    }
    double* v = sp.states.data() + s * static_cast<std::size_t>(ns);
    v[0] = angle;
    v[1] = speed;
    if (ns == 4) {
      v[2] = angle;
      v[3] = speed;
    }
  }
}

ceres::LossFunction* make_loss(const TimeFitOptions& options) {
  switch (options.loss) {
    case Loss::kHuber: return new ceres::HuberLoss(options.loss_scale);
    case Loss::kSoftLOne: return new ceres::SoftLOneLoss(options.loss_scale);
    case Loss::kCauchy: return new ceres::CauchyLoss(options.loss_scale);
    default: return nullptr;
  }
}

// One residual block per segment: the model simulated from the segment's state (the AutoDiff cost); with
// continuity_weight > 0, adjacent segments are linked. with_loss: the robust loss of the options.
void add_segment_blocks(ceres::Problem& problem, const FitContext& ctx, ShootingProblem& sp, double* p,
                        const TimeFitOptions& options, bool with_loss = true) {
  const int nseg = static_cast<int>(sp.starts.size());
  const std::size_t ns = static_cast<std::size_t>(sp.state_size);
  for (int s = 0; s < nseg; ++s) {
    const std::size_t u = static_cast<std::size_t>(s);
    const int a = sp.starts[u], c = sp.counts[u];
    const bool linked = options.continuity_weight > 0.0 && s + 1 < nseg && sp.starts[u + 1] == a + c;
    using ceres::AutoDiffCostFunction;
    using ceres::DYNAMIC;
    constexpr PlantModel R = PlantModel::kRigid, W = PlantModel::kTwoMass;
    ceres::CostFunction* cost = nullptr;
    if (options.model == R && linked)
      cost = new AutoDiffCostFunction<LinkedSegmentCost<R>, DYNAMIC, 6, 2, 2>(new LinkedSegmentCost<R>{&ctx, a, c}, c + 2);
    else if (options.model == R)
      cost = new AutoDiffCostFunction<SegmentCost<R>, DYNAMIC, 6, 2>(new SegmentCost<R>{&ctx, a, c}, c);
    else if (linked)
      cost = new AutoDiffCostFunction<LinkedSegmentCost<W>, DYNAMIC, 11, 4, 4>(new LinkedSegmentCost<W>{&ctx, a, c}, c + 4);
    else
      cost = new AutoDiffCostFunction<SegmentCost<W>, DYNAMIC, 11, 4>(new SegmentCost<W>{&ctx, a, c}, c);
    ceres::LossFunction* loss = with_loss ? make_loss(options) : nullptr;
    double* x = sp.states.data() + u * ns;
    if (linked)
      problem.AddResidualBlock(cost, loss, p, x, x + ns);
    else
      problem.AddResidualBlock(cost, loss, p, x);
  }
}

std::string loss_name(Loss l) {
  switch (l) {
    case Loss::kHuber: return "Huber";
    case Loss::kSoftLOne: return "soft L1";
    case Loss::kCauchy: return "Cauchy";
    default: return "none";
  }
}

}  // namespace

TimeFitResult fit_time_domain(const TimeLog& log, const ParameterSetup& setup, const TimeFitOptions& options) {
  options.validate();
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
  // One stage of the continuation: segments of about `len` samples, their start states from the data, solved from the
  // present parameters p.
  auto run_stage = [&](int len, bool hold_stribeck, bool last, Stage& st) {
    TimeFitOptions so = options;
    so.segment_samples = len;
    so.min_segment_samples = std::min(options.min_segment_samples, len);
    st.shooting = shooting_problem(log, so);
    st.problem = std::make_unique<ceres::Problem>();
    ceres::Problem& problem = *st.problem;
    add_segment_blocks(problem, ctx, st.shooting, p.data(), options);
    std::vector<int> constant;
    for (int i = 0; i < np; ++i)
      if (fixed[static_cast<std::size_t>(i)] || (hold_stribeck && (i == static_index(model) || i == stribeck_index(model))))
        constant.push_back(i);
    if (!constant.empty()) problem.SetManifold(p.data(), new ceres::SubsetManifold(np, constant));
    for (int i = 0; i < np; ++i) {
      const std::size_t u = static_cast<std::size_t>(i);
      if (fixed[u]) continue;
      if (std::isfinite(lower[u])) problem.SetParameterLowerBound(p.data(), i, lower[u]);
      if (std::isfinite(upper[u])) problem.SetParameterUpperBound(p.data(), i, upper[u]);
    }
    // A speed log does not see the absolute angle: hold the motor angle of each segment (the twist stays free).
    if (log.measured_is_speed)
      for (std::size_t i = 0; i < st.shooting.starts.size(); ++i)
        problem.SetManifold(st.shooting.states.data() + i * static_cast<std::size_t>(ns),
                            new ceres::SubsetManifold(ns, {0}));

    ceres::Solver::Options sopt;
    sopt.linear_solver_type = ceres::DENSE_SCHUR;
    // The held-Stribeck stage only brings J, b and Fc near: a few iterations do; the later stages converge.
    sopt.max_num_iterations = hold_stribeck ? std::min(options.max_iterations, 20) : options.max_iterations;
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
  int total_iterations = 0;
  double seconds = 0.0, initial_cost = 0.0;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    st = Stage();
    run_stage(lengths[i], stribeck_free && i == 0, i + 1 == lengths.size(), st);
    total_iterations += static_cast<int>(st.summary.iterations.size()) - 1;
    seconds += st.seconds;
    if (i == 0) initial_cost = st.summary.initial_cost;
  }
  ceres::Solver::Summary& summary = st.summary;
  ceres::Problem& problem = *st.problem;
  const std::vector<int>& starts = st.shooting.starts;
  const std::vector<int>& counts = st.shooting.counts;
  const auto x0 = [&](int s) { return st.shooting.states.data() + s * ns; };
  const int nseg = static_cast<int>(starts.size());
  const int len = options.segment_samples;

  TimeFitResult result;
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
  eopt.parameter_blocks.push_back(p.data());
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
     << "Residual RMS " << fs.residual_rms << " (" << fs.residual_rms * ctx.inv_scale
     << " x measurement_scale), NRMSE " << fs.nrmse << ".";
  if (!fs.not_identifiable.empty()) {
    os << "\nNot identifiable from these data:";
    for (const auto& s : fs.not_identifiable) os << "\n  - " << s;
  }
  fs.report = os.str();
  return result;
}

ShootingProblem shooting_problem(const TimeLog& log, const TimeFitOptions& options) {
  options.validate();
  check_log(log, options);
  ShootingProblem sp;
  sp.state_size = mechanical_states(options.model);
  shooting_segments(log, options, &sp.starts, &sp.counts);
  const int nseg = static_cast<int>(sp.starts.size());
  if (nseg < 2)
    throw std::invalid_argument("TimeLog: only " + std::to_string(nseg) +
                                " stretch(es) of one-way motion long enough to fit (at least 2 of " +
                                std::to_string(options.min_segment_samples) +
                                " samples are needed): the log is too short or the axis hardly moves");
  initial_states(log, sp);
  return sp;
}

std::vector<double> shooting_residual(const TimeLog& log, const TimeFitOptions& options,
                                      const ShootingProblem& problem, const std::vector<double>& p,
                                      const std::vector<double>& states, SparseJacobian* jacobian) {
  options.validate();
  check_log(log, options);
  if (static_cast<int>(p.size()) != parameter_count(options.model))
    throw std::invalid_argument("shooting_residual: the " + std::string(model_name(options.model)) + " model has " +
                                std::to_string(parameter_count(options.model)) + " parameters, got " +
                                std::to_string(p.size()));
  if (states.size() != problem.states.size() || problem.state_size != mechanical_states(options.model))
    throw std::invalid_argument("shooting_residual: states must hold " + std::to_string(problem.states.size()) +
                                " values (the problem's segments times its state size), got " +
                                std::to_string(states.size()));
  for (std::size_t s = 0; s < problem.starts.size(); ++s)
    if (problem.starts[s] < 0 || problem.counts[s] < 1 ||
        static_cast<std::size_t>(problem.starts[s] + problem.counts[s]) > log.measured.size())
      throw std::invalid_argument("shooting_residual: segment " + std::to_string(s) + " lies outside the log");
  FitContext ctx;
  init_context(ctx, log, options);
  ShootingProblem sp = problem;
  sp.states = states;
  std::vector<double> pv = p;
  ceres::Problem::Options po;
  ceres::Problem cp(po);
  add_segment_blocks(cp, ctx, sp, pv.data(), options, false);
  ceres::Problem::EvaluateOptions eopt;
  eopt.parameter_blocks.push_back(pv.data());
  for (std::size_t s = 0; s < sp.starts.size(); ++s)
    eopt.parameter_blocks.push_back(sp.states.data() + s * static_cast<std::size_t>(sp.state_size));
  eopt.apply_loss_function = false;
  eopt.num_threads = options.num_threads;
  double cost = 0.0;
  std::vector<double> residual;
  ceres::CRSMatrix crs;
  cp.Evaluate(eopt, &cost, &residual, nullptr, jacobian ? &crs : nullptr);
  if (jacobian) {
    jacobian->rows = crs.num_rows;
    jacobian->cols = crs.num_cols;
    jacobian->row_ptr = crs.rows;
    jacobian->col_index = crs.cols;
    jacobian->values = crs.values;
  }
  return residual;
}

std::vector<double> simulate_model(const TimeLog& log, const std::vector<double>& parameters,
                                   const std::vector<double>& initial_state, const TimeFitOptions& options) {
  options.validate();
  check_positive("TimeLog", "sample_period_s", log.sample_period_s);
  if (static_cast<int>(parameters.size()) != parameter_count(options.model))
    throw std::invalid_argument("simulate_model: wrong number of parameters");
  if (static_cast<int>(initial_state.size()) != mechanical_states(options.model))
    throw std::invalid_argument("simulate_model: wrong number of initial states");
  FitContext ctx;
  init_context(ctx, log, options);
  const std::size_t n = log.torque_nm.size();
  TimeLog padded = log;
  padded.measured.assign(n, 0.0);
  ctx.log = &padded;
  std::vector<double> out(n);
  const std::vector<double> internal = to_internal(options.model, parameters);
  if (n) run_segment(ctx, internal.data(), initial_state.data(), 0, static_cast<int>(n), out.data());
  return out;
}

}  // namespace servobench::identify
