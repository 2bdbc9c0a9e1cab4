// The shooting-segment cost by forward sensitivity: see segment_sensitivity.hpp.
#include "segment_sensitivity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace servobench::identify::detail {

namespace {

// The sizes of a model with NB bodies (1: rigid, 2: two-mass), as plant_model.hpp orders its parameter vector.
template <int NB>
struct Shape {
  static constexpr int kStates = 2 * NB;              // angle, speed per body
  static constexpr int kParams = NB == 1 ? 6 : 11;    // internal parameters
  static constexpr int kLinear = NB == 1 ? 2 : 6;     // the first ones: they enter Phi, Gamma
  static constexpr int kLoad = kParams - 1;           // the constant load torque, last
  static constexpr int kMasks = 1 << NB;              // discretisations: the bodies locked by stiction
};

// Where each derivative goes: one lane per free parameter, in the parameter vector's order (so the free linear
// parameters, which come first, are lanes 0..free_linear-1), then one per start state. A held parameter has no
// lane (-1): its Jacobian column is 0 and nothing is carried for it (decision FV2).
struct LaneMap {
  std::array<int, 11> of{};  // lane of parameter i, or -1
  int free = 0;              // free parameters: the start states' lanes begin here
  int free_linear = 0;       // free linear parameters
  std::array<int, 6> linear{};  // the free linear parameters, in lane order
};

inline LaneMap lane_map(int np, int nlin, const std::vector<int>& free) {
  LaneMap m;
  m.of.fill(-1);
  for (int i = 0; i < np; ++i) {
    const bool moves = free.empty() || std::find(free.begin(), free.end(), i) != free.end();
    if (!moves) continue;
    if (i < nlin) m.linear[static_cast<std::size_t>(m.free_linear++)] = i;
    m.of[static_cast<std::size_t>(i)] = m.free++;
  }
  return m;
}

// A body's dry friction: its levels and where their derivatives go. The motor (rigid: the body) has a Stribeck
// peak (Coulomb, excess, Stribeck speed); the two-mass load has Coulomb friction only (breakaway = Coulomb, the
// excess identically 0: lanes < 0).
struct BodyFriction {
  double fc = 0.0, fs = 0.0, ws = 1.0;
  bool peak = true;                              // false: Fs = Fc, no Stribeck term
  int lane_fc = -1, lane_excess = -1, lane_ws = -1;  // -1: held (or, without a peak, absent)
  int angle = 0, speed = 1, input = 1;  // mechanical state indices and input column
  bool active() const { return fs > 0.0; }  // DryFriction::active (the fit's friction is symmetric)
};

// No lanes at all: a Simulation<NB, 0> computes the residuals alone.
inline const LaneMap& no_lanes() {
  static const LaneMap m = [] {
    LaneMap l;
    l.of.fill(-1);
    return l;
  }();
  return m;
}

// ND: the lanes carried (at least the free parameters and the start states; the rest stay 0). The loops over the
// linear parameters' lanes run over all kLinear of them, of compile-time length: a held linear parameter's
// dPhi/dp, dGamma/dp are 0 in Step, so its iterations add exact zeros to lanes that are not its own (decision FV6).
template <int NB, int ND>
class Simulation {
 public:
  using S_ = Shape<NB>;
  static constexpr int n = S_::kStates, nd = ND, nlin = S_::kLinear;
  // The linear parameters' lanes (0..kLinear-1); none without lanes (ND = 0: the residuals alone).
  static constexpr int nlin_lanes = nd > 0 ? nlin : 0;
  static_assert(nd == 0 || nd >= nlin, "the linear parameters' loops run over lanes 0..kLinear-1");
  using Lanes = std::array<double, nd>;  // d(value) / d[free p, x0]

  // One discretisation (a stiction mask) on the mechanical state, with its derivatives along the linear
  // parameters. Input columns: command, torque on the motor body, torque on the load body (the load torque; rigid:
  // the same body), the current loop's torque (the lag state's column of phi; 0 without a current loop).
  // The derivatives are those of the free linear parameters only, in lane order (dphi[t]: lane t).
  struct Step {
    double phi[n][n], gam[n][4];
    double dphi[nlin][n][n], dgam[nlin][n][4];  // [lane][row][column]
  };

  Simulation(const FitContext& ctx, const double* p, const LaneMap& lanes)
      : ctx_(ctx), p_(p), lane_load_(lanes.of[S_::kLoad]) {
    const int nl = ctx.layout.lag_states();
    const auto disc = ctx.cache->get(p, nd > 0);
    for (int m = 0; m < S_::kMasks; ++m) steps_[m] = mechanical_step(*disc, static_cast<unsigned>(m), nl, lanes);
    expo_ = ctx.layout.stribeck_exponent;
    const auto& of = lanes.of;
    if constexpr (NB == 1) {
      body_[0] = BodyFriction{p[2], p[2] + p[3], p[4], true, of[2], of[3], of[4], 0, 1, 1};
    } else {
      body_[0] = BodyFriction{p[6], p[6] + p[7], p[8], true, of[6], of[7], of[8], 0, 1, 1};
      body_[1] = BodyFriction{p[9], p[9], 1.0, false, of[9], -1, -1, 2, 3, 2};
    }
    for (int b = 0; b < NB; ++b) {
      inv_ws_[b] = 1.0 / body_[b].ws;
      unit_fc_[b] = unit(body_[b].lane_fc);
      unit_excess_[b] = unit(body_[b].lane_excess);
      unit_ws_[b] = unit(body_[b].lane_ws);
    }
    unit_load_ = unit(lane_load_);
  }

  // One sub-step (plant::advance_with_dry_friction): x, S advanced in place; stuck[b] carried between sub-steps.
  void substep(double x[n], Lanes S[n], char stuck[NB], double u, double lag) const {
    double xf[n];
    Lanes dxf[n];
    free_motion(steps_[0], x, S, u, lag, xf, dxf);
    bool any_dry = false;
    for (int b = 0; b < NB; ++b) any_dry = any_dry || body_[b].active();
    if (!any_dry) {
      commit(x, S, xf, dxf);
      return;
    }
    double f[NB] = {};
    Lanes df[NB];           // set where known[b]; a body not known has f = 0 and no lanes
    bool known[NB] = {};
    bool stick[NB] = {};
    solve(x, S, xf, dxf, steps_[0], 0u, f, df, known, stick);
    unsigned locked = 0;  // bodies at rest that static friction keeps at rest: integrated locked
    for (int b = 0; b < NB; ++b)
      if (stick[b] && stuck[b] && x[body_[b].speed] == 0.0) locked |= 1u << b;
    const Step* g = &steps_[0];
    if (locked != 0) {
      g = &steps_[locked];
      free_motion(*g, x, S, u, lag, xf, dxf);
      solve(x, S, xf, dxf, *g, locked, f, df, known, stick);
    }
    for (int b = 0; b < NB; ++b) {
      if ((locked & (1u << b)) || f[b] == 0.0 || !known[b]) continue;
      const int c = body_[b].input;
      for (int i = 0; i < n; ++i) {
        xf[i] += g->gam[i][c] * f[b];
        for (int j = 0; j < nd; ++j) dxf[i][j] += g->gam[i][c] * df[b][j];
        for (int k = 0; k < nlin_lanes; ++k) dxf[i][k] += g->dgam[k][i][c] * f[b];
      }
    }
    for (int b = 0; b < NB; ++b) {
      if (locked & (1u << b)) {
        stuck[b] = 1;
        continue;
      }
      if (stick[b]) {  // stopped inside the sub-step
        xf[body_[b].speed] = 0.0;
        dxf[body_[b].speed].fill(0.0);
      }
      stuck[b] = stick[b] ? 1 : 0;
    }
    commit(x, S, xf, dxf);
  }

  const BodyFriction& body(int b) const { return body_[b]; }

 private:
  static Step mechanical_step(const Discretisation& d, unsigned mask, int nl, const LaneMap& lanes) {
    Step s{};
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) s.phi[r][c] = d.phi[mask](nl + r, nl + c);
      for (int c = 0; c < 3; ++c) s.gam[r][c] = d.gamma[mask](nl + r, c);
      s.gam[r][3] = nl ? d.phi[mask](nl + r, 0) : 0.0;
      for (int k = 0; k < lanes.free_linear; ++k) {
        const auto kk = static_cast<std::size_t>(lanes.linear[static_cast<std::size_t>(k)]);
        for (int c = 0; c < n; ++c) s.dphi[k][r][c] = d.dphi[mask][kk](nl + r, nl + c);
        for (int c = 0; c < 3; ++c) s.dgam[k][r][c] = d.dgamma[mask][kk](nl + r, c);
        s.dgam[k][r][3] = nl ? d.dphi[mask][kk](nl + r, 0) : 0.0;
      }
    }
    return s;
  }

  // The lane vector of a parameter: 1 in its lane (none: lane < 0), 0 elsewhere. The lanes of a parameter's own
  // term are added as whole vectors, never written one element at a time: a scalar store into an array the next
  // operation loads as vectors stalls store-to-load forwarding (measured: a fifth of the evaluation's time).
  static Lanes unit(int lane) {
    Lanes u{};
    if (lane >= 0 && lane < nd) u[static_cast<std::size_t>(lane)] = 1.0;
    return u;
  }

  static void commit(double x[n], Lanes S[n], const double xf[n], const Lanes dxf[n]) {
    for (int i = 0; i < n; ++i) {
      x[i] = xf[i];
      S[i] = dxf[i];
    }
  }

  // xf = Phi x + Gamma [u, 0, t_load, lag] and its lanes (a zero command or current-loop torque is skipped as
  // add_input skips it; the load is a parameter and always enters).
  void free_motion(const Step& s, const double x[n], const Lanes S[n], double u, double lag, double xf[n],
                   Lanes dxf[n]) const {
    const double t_load = -p_[S_::kLoad];
    for (int i = 0; i < n; ++i) {
      double v = s.phi[i][0] * x[0];
      for (int c = 1; c < n; ++c) v += s.phi[i][c] * x[c];
      xf[i] = v;
      Lanes& d = dxf[i];
      for (int j = 0; j < nd; ++j) {
        double a = s.phi[i][0] * S[0][j];
        for (int c = 1; c < n; ++c) a += s.phi[i][c] * S[c][j];
        d[j] = a;
      }
      for (int k = 0; k < nlin_lanes; ++k)
        for (int c = 0; c < n; ++c) d[k] += s.dphi[k][i][c] * x[c];
      if (u != 0.0) {
        xf[i] += s.gam[i][0] * u;
        for (int k = 0; k < nlin_lanes; ++k) d[k] += s.dgam[k][i][0] * u;
      }
      if (ctx_.has_load) {
        xf[i] += s.gam[i][2] * t_load;
        for (int k = 0; k < nlin_lanes; ++k) d[k] += s.dgam[k][i][2] * t_load;
        if constexpr (nd > 0)
          if (lane_load_ >= 0)
            for (int j = 0; j < nd; ++j) d[j] -= s.gam[i][2] * unit_load_[j];
      }
      if (lag != 0.0) {
        xf[i] += s.gam[i][3] * lag;
        for (int k = 0; k < nlin_lanes; ++k) d[k] += s.dgam[k][i][3] * lag;
      }
    }
  }

  // The sliding level Fc + (Fs - Fc) exp(-(|v|/ws)^delta) at the sub-step's start speed v and its lanes.
  double sliding(int b, double v, const Lanes& dv, Lanes& out) const {
    const BodyFriction& bf = body_[b];
    if (!bf.peak) {  // the level is Fc (the Jets' (Fs - Fc) term is exactly 0 with its lanes)
      if constexpr (nd > 0) out = unit_fc_[b];
      return bf.fc;
    }
    const double r = std::fabs(v) / bf.ws;
    double shape, slope;
    if (expo_ == 2.0) {
      shape = r * r;
      slope = 2.0 * r;
    } else {
      shape = std::pow(r, expo_);
      slope = expo_ * std::pow(r, expo_ - 1.0);
    }
    const double e = std::exp(-shape);
    const double excess = bf.fs - bf.fc;
    if constexpr (nd > 0) {  // d(|v|/ws) = (d|v| - r dws) (1/ws), as Ceres' Jet division
      const double sg = std::copysign(1.0, v), c = -excess * e * slope, iw = inv_ws_[b];
      const Lanes &uw = unit_ws_[b], &uf = unit_fc_[b], &ue = unit_excess_[b];
      for (int j = 0; j < nd; ++j) out[j] = c * ((sg * dv[j] - r * uw[j]) * iw) + uf[j] + e * ue[j];
    }
    return bf.fc + excess * e;
  }

  // plant::solve_dry_friction with lanes: the held friction f[b] of every body for the sub-step from x whose
  // friction-free end is xf (step g; bodies in `locked` get f = 0, stick). f, df carry the previous solve's forces
  // in (the Gauss-Seidel start of a second, locked solve), as the plant's f[] does; known[b]: df[b] is set (a body
  // not known has f[b] = 0 and lanes 0, which are not stored).
  void solve(const double x[n], const Lanes S[n], const double xf[n], const Lanes dxf[n], const Step& g,
             unsigned locked, double f[NB], Lanes df[NB], bool known[NB], bool stick[NB]) const {
    constexpr int sweeps = NB > 1 ? 3 : 1;
    double slip[NB] = {};
    Lanes dslip[NB];
    for (int b = 0; b < NB; ++b) {
      if (locked & (1u << b)) {
        f[b] = 0.0;
        known[b] = false;
        stick[b] = true;
      } else if (body_[b].active() && x[body_[b].speed] != 0.0) {
        slip[b] = sliding(b, x[body_[b].speed], S[body_[b].speed], dslip[b]);
      }
    }
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      for (int b = 0; b < NB; ++b) {
        if (locked & (1u << b)) continue;
        const BodyFriction& bf = body_[b];
        stick[b] = false;
        if (!bf.active()) {
          f[b] = 0.0;
          known[b] = false;
          continue;
        }
        const int sp = bf.speed, an = bf.angle, in = bf.input;
        // End speed and displacement of this body without its own friction (the others' included). Their lanes
        // are needed on the sticking and the capped branches only, and are formed there (the sliding branch, the
        // common one in motion, carries the sliding level's lanes alone).
        double v_free = xf[sp], d = xf[an] - x[an];
        for (int o = 0; o < NB; ++o) {
          if (o == b) continue;
          v_free += g.gam[sp][body_[o].input] * f[o];
          d += g.gam[an][body_[o].input] * f[o];
        }
        // d(row's free end value) = dxf[row] - base[row] + the others' friction lanes.
        const auto free_lanes = [&](int row, const Lanes* base, Lanes& out) {
          for (int j = 0; j < nd; ++j) out[j] = base ? dxf[row][j] - (*base)[j] : dxf[row][j];
          for (int o = 0; o < NB; ++o) {
            if (o == b || !known[o]) continue;
            const int oc = body_[o].input;
            for (int j = 0; j < nd; ++j) out[j] += g.gam[row][oc] * df[o][j];
            for (int k = 0; k < nlin_lanes; ++k) out[k] += g.dgam[k][row][oc] * f[o];
          }
        };
        const double gv = g.gam[sp][in], gth = g.gam[an][in];
        const double v0 = x[sp];
        const double dir = v0 > 0.0 ? 1.0 : -1.0;
        double fb = 0.0;
        Lanes& dfb = df[b];  // every branch below sets all of its lanes (free_lanes reads the others' only)
        bool st = false, sliding_branch = false;
        if (v0 != 0.0) {
          const double f_slip = -dir * slip[b];
          if ((v_free + gv * f_slip) * dir > 0.0) {  // keeps sliding the same way
            fb = f_slip;
            for (int j = 0; j < nd; ++j) dfb[j] = -dir * dslip[b][j];
            sliding_branch = true;
          }
        }
        if (!sliding_branch) {
          const double q = v_free / gv;
          const double f_stick = -q;  // holds the body at rest at the sub-step's end
          if (f_stick <= bf.fs && f_stick >= -bf.fs) {
            fb = f_stick;
            Lanes dv;
            free_lanes(sp, nullptr, dv);
            for (int j = 0; j < nd; ++j) dfb[j] = -dv[j] / gv;
            for (int k = 0; k < nlin_lanes; ++k) dfb[k] += q * g.dgam[k][sp][in] / gv;
            st = true;
          } else {  // breaks away, or passes zero: -Fs or +Fs, dFs = dFc + d(excess)
            const double sgn = v_free > 0.0 ? -1.0 : 1.0;
            fb = sgn * bf.fs;
            if constexpr (nd > 0)
              for (int j = 0; j < nd; ++j) dfb[j] = sgn * unit_fc_[b][j] + sgn * unit_excess_[b][j];
          }
        }
        // Sliding friction may only oppose the net displacement over the sub-step.
        if (!(st && v0 == 0.0) && fb * (d + gth * fb) > 0.0) {
          st = false;
          double cap = 0.0;
          Lanes dcap{};
          if (gth > 0.0) {
            cap = std::fabs(d) / gth;
            const double sd = std::copysign(1.0, d);
            Lanes dd;
            free_lanes(an, &S[an], dd);
            for (int j = 0; j < nd; ++j) dcap[j] = sd * dd[j] / gth;
            for (int k = 0; k < nlin_lanes; ++k) dcap[k] -= cap * g.dgam[k][an][in] / gth;
          }
          const double sf = std::copysign(1.0, fb);
          double mag;
          Lanes dmag;
          if (std::fabs(fb) < cap) {
            mag = std::fabs(fb);
            for (int j = 0; j < nd; ++j) dmag[j] = sf * dfb[j];
          } else {
            mag = cap;
            dmag = dcap;
          }
          if (d == 0.0) {
            fb = 0.0;
            dfb.fill(0.0);
          } else {
            const double s = d > 0.0 ? -1.0 : 1.0;
            fb = s * mag;
            for (int j = 0; j < nd; ++j) dfb[j] = s * dmag[j];
          }
        }
        f[b] = fb;
        known[b] = true;
        stick[b] = st;
      }
    }
  }

  const FitContext& ctx_;
  const double* p_;
  int lane_load_;  // the load's lane, or -1
  Step steps_[S_::kMasks];
  BodyFriction body_[NB];
  double inv_ws_[NB];
  Lanes unit_fc_[NB], unit_excess_[NB], unit_ws_[NB], unit_load_;  // unit(lane) of those parameters
  double expo_ = 2.0;
};

// The segment's residuals and Jacobian rows (the loop of SensitivityCost::Evaluate), one function with everything
// it calls inlined (flatten). An AVX2 + FMA copy chosen at run time was measured and left out (decision FV3).
template <int NB, int ND>
__attribute__((always_inline)) inline void segment_lanes(const Simulation<NB, ND>& sim, const FitContext& ctx,
                                                         const LaneMap& lanes, bool free_block, const double* x0,
                                                         int start, int count, double* residuals,
                                                         double** jacobians) {
  using Sim = Simulation<NB, ND>;
  constexpr int n = Sim::n, np = Shape<NB>::kParams;
  using Lanes = typename Sim::Lanes;
  const int nl = ctx.layout.lag_states();
  const int nf = lanes.free;
  double x[n];
  Lanes S[n];
  char stuck[NB];
  for (int i = 0; i < n; ++i) {
    x[i] = x0[i];
    if constexpr (ND > 0) {
      S[i].fill(0.0);
      S[i][static_cast<std::size_t>(nf + i)] = 1.0;
    }
  }
  for (int b = 0; b < NB; ++b) stuck[b] = x[sim.body(b).speed] == 0.0 ? 1 : 0;
  const int oi = ctx.output_index - nl;
  const std::vector<double>& u = ctx.log->torque_nm;
  const std::vector<double>& y = ctx.log->measured;
  double lag = nl ? ctx.lag[static_cast<std::size_t>(start)] : 0.0;
  for (int k = 0; k < count; ++k) {
    const std::size_t s = static_cast<std::size_t>(start + k);
    residuals[k] = (x[oi] - y[s]) * ctx.inv_scale;
    if constexpr (ND == 0) {
      // the residuals alone
    } else if (jacobians[0] && free_block) {  // a column per free parameter: the lanes in order
      double* row = jacobians[0] + static_cast<std::ptrdiff_t>(k) * nf;
      for (int j = 0; j < nf; ++j) row[j] = S[oi][static_cast<std::size_t>(j)] * ctx.inv_scale;
    } else if (jacobians[0]) {
      double* row = jacobians[0] + static_cast<std::ptrdiff_t>(k) * np;
      for (int j = 0; j < np; ++j) {
        const int l = lanes.of[static_cast<std::size_t>(j)];
        row[j] = l >= 0 ? S[oi][static_cast<std::size_t>(l)] * ctx.inv_scale : 0.0;
      }
    }
    if constexpr (ND > 0)
      if (jacobians[1])
        for (int i = 0; i < n; ++i)
          jacobians[1][static_cast<std::ptrdiff_t>(k) * n + i] =
              S[oi][static_cast<std::size_t>(nf + i)] * ctx.inv_scale;
    if (k + 1 == count) break;
    for (int sub = 0; sub < ctx.substeps; ++sub) {
      sim.substep(x, S, stuck, u[s], lag);
      if (nl) lag = ctx.lag_decay * lag + (1.0 - ctx.lag_decay) * u[s];
    }
  }
}

template <int NB, int ND>
__attribute__((flatten)) void segment_lanes_flat(const Simulation<NB, ND>& sim, const FitContext& ctx,
                                                 const LaneMap& lanes, bool free_block, const double* x0, int start,
                                                 int count, double* residuals, double** jacobians) {
  segment_lanes(sim, ctx, lanes, free_block, x0, start, count, residuals, jacobians);
}


template <int NB, int ND>
class SensitivityCost final : public ceres::CostFunction {
 public:
  using S_ = Shape<NB>;
  static constexpr int n = S_::kStates, np = S_::kParams;

  SensitivityCost(const FitContext* ctx, int start, int count, const LaneMap& lanes, const double* base)
      : ctx_(ctx), start_(start), count_(count), lanes_(lanes), base_(base) {
    set_num_residuals(count);
    mutable_parameter_block_sizes()->push_back(base ? lanes.free : np);
    mutable_parameter_block_sizes()->push_back(n);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    double full[np];
    const double* p = parameters[0];
    if (base_) {  // the block holds the free parameters (lane order): the held ones from base
      std::copy(base_, base_ + np, full);
      for (int i = 0; i < np; ++i) {
        const int l = lanes_.of[static_cast<std::size_t>(i)];
        if (l >= 0) full[i] = parameters[0][l];
      }
      p = full;
    }
    if (!jacobians || (!jacobians[0] && !jacobians[1])) {  // the same simulation without lanes
      const Simulation<NB, 0> sim(*ctx_, p, no_lanes());
      segment_lanes_flat(sim, *ctx_, no_lanes(), false, parameters[1], start_, count_, residuals, nullptr);
      return true;
    }
    const Simulation<NB, ND> sim(*ctx_, p, lanes_);
    segment_lanes_flat(sim, *ctx_, lanes_, base_ != nullptr, parameters[1], start_, count_, residuals, jacobians);
    return true;
  }

 private:
  const FitContext* ctx_;
  int start_, count_;
  LaneMap lanes_;
  const double* base_;  // nullptr: parameter block 0 is the whole vector
};

}  // namespace

ceres::CostFunction* sensitivity_cost(const FitContext* ctx, int start, int count, std::vector<int> free,
                                      const double* base) {
  // The lanes carried: the free parameters and the start states, rounded up to one of a few widths.
  if (ctx->layout.model == PlantModel::kRigid) {
    const LaneMap lanes = lane_map(6, 2, free);
    if (lanes.free + 2 <= 6) return new SensitivityCost<1, 6>(ctx, start, count, lanes, base);
    return new SensitivityCost<1, 8>(ctx, start, count, lanes, base);
  }
  const LaneMap lanes = lane_map(11, 6, free);
  if (lanes.free + 4 <= 10) return new SensitivityCost<2, 10>(ctx, start, count, lanes, base);
  if (lanes.free + 4 <= 12) return new SensitivityCost<2, 12>(ctx, start, count, lanes, base);
  return new SensitivityCost<2, 15>(ctx, start, count, lanes, base);
}

}  // namespace servobench::identify::detail
