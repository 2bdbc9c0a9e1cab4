// The output-error model of the time-domain fit and the multiple-shooting problem (shooting_problem,
// shooting_residual, simulate_model): see shooting_model.hpp. The solve is in time_fit.cpp.
#include "shooting_model.hpp"
#include "segment_sensitivity.hpp"

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

namespace {

using detail::FitContext;

// The mechanical state of model M: 2 (rigid) or 4 (two-mass) entries. The vectors and matrices keep run-time sizes
// (at most kMaxStates): fixed-size ones made the Jet evaluation slower, not faster (decision FT1: two-mass one start
// 0.51 -> 0.79 s CPU, rigid 0.40 -> 0.47 s, paired on a loaded machine).
template <PlantModel M>
constexpr int kStates = M == PlantModel::kRigid ? 2 : 4;
constexpr int kMaxStates = 5;
template <PlantModel M, class T>
using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
template <PlantModel M, class T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxStates>;
template <PlantModel M, class T>
using InMat = Eigen::Matrix<T, Eigen::Dynamic, 4, 0, kMaxStates, 4>;

inline double value_of(double x) { return x; }
template <int N>
double value_of(const ceres::Jet<double, N>& x) {
  return x.a;
}

// A discretisation matrix on T: the value, and for Jets the derivative with respect to linear parameter k along
// Jet direction dir[k] (none when dir[k] < 0: a held parameter). Without dir, direction k is linear parameter k
// (the linear parameters come first in the parameter block).
template <class M>
void lift(const Eigen::MatrixXd& v, const std::vector<Eigen::MatrixXd>&, M& out, const int*, std::true_type /*double*/) {
  out = v;
}
template <class M>
void lift(const Eigen::MatrixXd& v, const std::vector<Eigen::MatrixXd>& d, M& out, const int* dir,
          std::false_type /*jet*/) {
  using T = typename M::Scalar;
  out.resize(v.rows(), v.cols());
  for (Eigen::Index r = 0; r < v.rows(); ++r)
    for (Eigen::Index c = 0; c < v.cols(); ++c) {
      T x(v(r, c));
      for (std::size_t k = 0; k < d.size(); ++k) {
        const int j = dir ? dir[k] : static_cast<int>(k);
        if (j >= 0) x.v[j] = d[k](r, c);
      }
      out(r, c) = x;
    }
}


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
// lin_dir: the Jet direction of each linear parameter (see lift; nullptr: direction k is parameter k).
template <PlantModel M, class T>
void simulate_segment(const FitContext& ctx, const T* p, const T* x0, int start, int count, T* out, bool residual,
                      const T* x_next = nullptr, T* continuity = nullptr, T* x_end = nullptr,
                      const int* lin_dir = nullptr) {
  constexpr bool is_double = std::is_same<T, double>::value;
  const ModelLayout& layout = ctx.layout;
  const int nlin = linear_parameter_count(layout.model);
  const int nl = layout.lag_states();
  double lin[6];
  for (int k = 0; k < nlin; ++k) lin[k] = value_of(p[k]);
  const auto disc = ctx.cache->get(lin, !is_double);
  const std::size_t masks = disc->phi.size();
  std::array<Mat<M, T>, 4> phis;
  std::array<InMat<M, T>, 4> gammas;
  for (std::size_t m = 0; m < masks; ++m) {
    std::vector<Eigen::MatrixXd> dphi, dgamma;
    for (std::size_t k = 0; k < disc->dphi[m].size(); ++k) {
      dphi.push_back(mechanical_phi(disc->dphi[m][k], nl));
      dgamma.push_back(mechanical_gamma(disc->dphi[m][k], disc->dgamma[m][k], nl));
    }
    lift(mechanical_phi(disc->phi[m], nl), dphi, phis[m], lin_dir, std::integral_constant<bool, is_double>());
    lift(mechanical_gamma(disc->phi[m], disc->gamma[m], nl), dgamma, gammas[m], lin_dir,
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
  constexpr int n = kStates<M>;
  const int out_index = ctx.output_index - nl;
  static_assert(kStates<M> <= 4, "two bodies at most");
  Vec<M, T> x(n), xf(n);
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
  if (x_end)  // the state at the last sample written (start + count - 1; start + count with continuity)
    for (int i = 0; i < n; ++i) x_end[i] = x[i];
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

// A segment's cost with derivatives along the free parameters only (decision FT5): Jets of K directions, the free
// parameters first, then the segment's state, where the AutoDiff cost above carries one direction per parameter,
// held or not. The Jet arithmetic is element by element, so every derivative is the AutoDiff cost's to the bit; the
// Jacobian columns of held parameters are zero, or absent when the block holds the free parameters only (decision
// FV4; otherwise a SubsetManifold projects them out). K: the smallest of the instantiated widths that holds free +
// state directions.
template <PlantModel M, int K>
class FreeSegmentCost final : public ceres::CostFunction {
 public:
  FreeSegmentCost(const FitContext* ctx, int start, int count, std::vector<int> free, const double* base)
      : ctx_(ctx), start_(start), count_(count), free_(std::move(free)), base_(base) {
    set_num_residuals(count);
    mutable_parameter_block_sizes()->push_back(base ? static_cast<int>(free_.size()) : parameter_count(M));
    mutable_parameter_block_sizes()->push_back(kStates<M>);
    lin_dir_.fill(-1);
    for (std::size_t j = 0; j < free_.size(); ++j)
      if (free_[j] < linear_parameter_count(M)) lin_dir_[static_cast<std::size_t>(free_[j])] = static_cast<int>(j);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    constexpr int np = M == PlantModel::kRigid ? 6 : 11;
    const int nf = static_cast<int>(free_.size());
    double full[np];
    const double* pv = parameters[0];
    if (base_) {  // the block holds the free parameters: the held ones from base
      std::copy(base_, base_ + np, full);
      for (int j = 0; j < nf; ++j) full[free_[static_cast<std::size_t>(j)]] = parameters[0][j];
      pv = full;
    }
    if (!jacobians || (!jacobians[0] && !jacobians[1])) {
      simulate_segment<M>(*ctx_, pv, parameters[1], start_, count_, residuals, true);
      return true;
    }
    using J = ceres::Jet<double, K>;
    constexpr int ns = kStates<M>;
    std::array<J, np> p;
    std::array<J, ns> x0;
    for (int i = 0; i < np; ++i) p[static_cast<std::size_t>(i)] = J(pv[i]);
    for (int j = 0; j < nf; ++j) p[static_cast<std::size_t>(free_[static_cast<std::size_t>(j)])].v[j] = 1.0;
    for (int i = 0; i < ns; ++i) x0[static_cast<std::size_t>(i)] = J(parameters[1][i], nf + i);
    std::vector<J> out(static_cast<std::size_t>(count_));
    simulate_segment<M>(*ctx_, p.data(), x0.data(), start_, count_, out.data(), true, static_cast<const J*>(nullptr),
                        static_cast<J*>(nullptr), static_cast<J*>(nullptr), lin_dir_.data());
    for (int k = 0; k < count_; ++k) {
      const J& r = out[static_cast<std::size_t>(k)];
      residuals[k] = r.a;
      if (jacobians[0] && base_) {
        double* row = jacobians[0] + static_cast<std::ptrdiff_t>(k) * nf;
        for (int j = 0; j < nf; ++j) row[j] = r.v[j];
      } else if (jacobians[0]) {
        double* row = jacobians[0] + static_cast<std::ptrdiff_t>(k) * np;
        std::fill(row, row + np, 0.0);
        for (int j = 0; j < nf; ++j) row[free_[static_cast<std::size_t>(j)]] = r.v[j];
      }
      if (jacobians[1])
        for (int i = 0; i < ns; ++i) jacobians[1][static_cast<std::ptrdiff_t>(k) * ns + i] = r.v[nf + i];
    }
    return true;
  }

 private:
  const FitContext* ctx_;
  int start_, count_;
  std::vector<int> free_;           // the free parameters, in Jet-direction order
  const double* base_;              // nullptr: parameter block 0 is the whole vector; else its held values
  std::array<int, 6> lin_dir_{};    // Jet direction of each linear parameter (-1: held)
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

}  // namespace

namespace detail {

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

void state_at(const FitContext& ctx, const double* p, const double* x0, int start, int steps, double* x_end) {
  std::vector<double> out(static_cast<std::size_t>(steps) + 1);
  if (ctx.layout.model == PlantModel::kRigid)
    simulate_segment<PlantModel::kRigid>(ctx, p, x0, start, steps + 1, out.data(), false,
                                            static_cast<const double*>(nullptr), static_cast<double*>(nullptr), x_end);
  else
    simulate_segment<PlantModel::kTwoMass>(ctx, p, x0, start, steps + 1, out.data(), false,
                                            static_cast<const double*>(nullptr), static_cast<double*>(nullptr), x_end);
}

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

// One residual block per segment: the model simulated from the segment's state (the AutoDiff cost); with
// continuity_weight > 0, adjacent segments are linked. with_loss: the robust loss of the options.
bool add_segment_blocks(ceres::Problem& problem, const FitContext& ctx, ShootingProblem& sp, double* p,
                        const TimeFitOptions& options, bool with_loss, const std::vector<bool>* held,
                        double* free_block) {
  const int nseg = static_cast<int>(sp.starts.size());
  const std::size_t ns = static_cast<std::size_t>(sp.state_size);
  std::vector<int> free;
  if (held)
    for (int i = 0; i < parameter_count(options.model); ++i)
      if (!(*held)[static_cast<std::size_t>(i)]) free.push_back(i);
  const int width = static_cast<int>(free.size()) + sp.state_size;
  bool any_link = false;
  for (int s = 0; s + 1 < nseg; ++s) {
    const std::size_t u = static_cast<std::size_t>(s);
    any_link = any_link || (options.continuity_weight > 0.0 && sp.starts[u + 1] == sp.starts[u] + sp.counts[u]);
  }
  // The free parameters as a block of their own (every cost then reads the held ones from p): no SubsetManifold,
  // whose projection Ceres computes as a dense product per residual block and evaluation (decision FV4).
  const bool reduced = held && free_block && !any_link && !free.empty();
  const double* base = reduced ? p : nullptr;
  double* block = reduced ? free_block : p;
  for (int s = 0; s < nseg; ++s) {
    const std::size_t u = static_cast<std::size_t>(s);
    const int a = sp.starts[u], c = sp.counts[u];
    const bool linked = options.continuity_weight > 0.0 && s + 1 < nseg && sp.starts[u + 1] == a + c;
    using ceres::AutoDiffCostFunction;
    using ceres::DYNAMIC;
    constexpr PlantModel R = PlantModel::kRigid, W = PlantModel::kTwoMass;
    ceres::CostFunction* cost = nullptr;
    if (held && !linked && options.analytic_jacobian)
      cost = sensitivity_cost(&ctx, a, c, free, base);
    else if (held && !linked && options.model == R && width <= 6)
      cost = new FreeSegmentCost<R, 6>(&ctx, a, c, free, base);
    else if (held && !linked && options.model == R)
      cost = new FreeSegmentCost<R, 8>(&ctx, a, c, free, base);
    else if (held && !linked && options.model == W && width <= 10)
      cost = new FreeSegmentCost<W, 10>(&ctx, a, c, free, base);
    else if (held && !linked && options.model == W)
      cost = new FreeSegmentCost<W, 15>(&ctx, a, c, free, base);
    else if (options.model == R && linked)
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
      problem.AddResidualBlock(cost, loss, block, x, x + ns);
    else
      problem.AddResidualBlock(cost, loss, block, x);
  }
  return reduced;
}

}  // namespace detail

using detail::add_segment_blocks;
using detail::check_log;
using detail::FitContext;
using detail::init_context;
using detail::run_segment;

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
  // Every parameter free: the fit's own cost function (FreeSegmentCost), which the tests check against central
  // differences.
  const std::vector<bool> none_held(p.size(), false);
  add_segment_blocks(cp, ctx, sp, pv.data(), options, false, &none_held);
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
