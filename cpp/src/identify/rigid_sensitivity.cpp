// The rigid segment cost by forward sensitivity: see rigid_sensitivity.hpp.
#include "rigid_sensitivity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace servobench::identify::detail {

namespace {

constexpr int kParams = 6;               // inertia, viscous, Coulomb, Stribeck excess, Stribeck speed, load
constexpr int kDirs = kParams + 2;       // then the segment's start angle and speed
using Lanes = std::array<double, kDirs>;  // d(value) / d[p, x0]

// One discretisation (a stiction mask) on the mechanical state, with its derivatives along the two linear
// parameters (inertia: 0, viscous: 1). Input columns: command, torque on the body (its friction), load torque,
// the current loop's torque (the lag state's column of phi; 0 without a current loop).
struct RigidStep {
  double phi[2][2], gam[2][4];
  double dphi[2][2][2], dgam[2][2][4];  // [linear parameter][row][column]
};

RigidStep mechanical_step(const Discretisation& d, unsigned mask, int nl) {
  RigidStep s{};
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) s.phi[r][c] = d.phi[mask](nl + r, nl + c);
    for (int c = 0; c < 3; ++c) s.gam[r][c] = d.gamma[mask](nl + r, c);
    s.gam[r][3] = nl ? d.phi[mask](nl + r, 0) : 0.0;
    for (int k = 0; k < 2; ++k) {
      for (int c = 0; c < 2; ++c) s.dphi[k][r][c] = d.dphi[mask][static_cast<std::size_t>(k)](nl + r, nl + c);
      for (int c = 0; c < 3; ++c) s.dgam[k][r][c] = d.dgamma[mask][static_cast<std::size_t>(k)](nl + r, c);
      s.dgam[k][r][3] = nl ? d.dphi[mask][static_cast<std::size_t>(k)](nl + r, 0) : 0.0;
    }
  }
  return s;
}

// The segment's simulation with its sensitivities (the friction's parameters read once).
struct RigidSimulation {
  const FitContext& ctx;
  const double* p;
  RigidStep free_step, locked_step;
  double fc, fs, ws, expo;  // Coulomb, breakaway (Fc + excess, as DryFriction holds it), Stribeck speed, exponent

  // xf = Phi x + Gamma [u, 0, t_load, lag] and its lanes (plant::advance_with_dry_friction's free motion; a zero
  // command or current-loop torque is skipped as add_input skips it, the load is a parameter and always enters).
  void free_motion(const RigidStep& s, const double x[2], const Lanes S[2], double u, double lag, double xf[2],
                   Lanes dxf[2]) const {
    const double t_load = -p[5];
    for (int i = 0; i < 2; ++i) {
      xf[i] = s.phi[i][0] * x[0] + s.phi[i][1] * x[1];
      for (int j = 0; j < kDirs; ++j) dxf[i][j] = s.phi[i][0] * S[0][j] + s.phi[i][1] * S[1][j];
      for (int k = 0; k < 2; ++k) dxf[i][k] += s.dphi[k][i][0] * x[0] + s.dphi[k][i][1] * x[1];
      if (u != 0.0) {
        xf[i] += s.gam[i][0] * u;
        for (int k = 0; k < 2; ++k) dxf[i][k] += s.dgam[k][i][0] * u;
      }
      if (ctx.has_load) {
        xf[i] += s.gam[i][2] * t_load;
        for (int k = 0; k < 2; ++k) dxf[i][k] += s.dgam[k][i][2] * t_load;
        dxf[i][5] -= s.gam[i][2];
      }
      if (lag != 0.0) {
        xf[i] += s.gam[i][3] * lag;
        for (int k = 0; k < 2; ++k) dxf[i][k] += s.dgam[k][i][3] * lag;
      }
    }
  }

  // The sliding level Fc + (Fs - Fc) exp(-(|v|/ws)^delta) at the sub-step's start speed v and its lanes.
  double sliding(double v, const Lanes& dv, Lanes& out) const {
    const double sg = std::copysign(1.0, v);
    const double r = std::fabs(v) / ws;
    Lanes dr;
    for (int j = 0; j < kDirs; ++j) dr[j] = sg * dv[j];
    dr[4] -= r;  // d|v|/ws = (d|v| - r dws) / ws
    for (int j = 0; j < kDirs; ++j) dr[j] /= ws;
    double shape, slope;
    if (expo == 2.0) {
      shape = r * r;
      slope = 2.0 * r;
    } else {
      shape = std::pow(r, expo);
      slope = expo * std::pow(r, expo - 1.0);
    }
    const double e = std::exp(-shape);
    const double excess = fs - fc;
    for (int j = 0; j < kDirs; ++j) out[j] = -excess * e * slope * dr[j];
    out[2] += 1.0;  // dFc
    out[3] += e;    // d(Fs - Fc) = d(excess)
    return fc + excess * e;
  }

  // One sub-step (advance_with_dry_friction, one body, one sweep): x, S advanced in place.
  void substep(double x[2], Lanes S[2], char& stuck, double u, double lag) const {
    double xf[2];
    Lanes dxf[2];
    free_motion(free_step, x, S, u, lag, xf, dxf);
    if (!(fs > 0.0)) {  // no dry friction (DryFriction::active)
      for (int i = 0; i < 2; ++i) {
        x[i] = xf[i];
        S[i] = dxf[i];
      }
      return;
    }
    const RigidStep& g0 = free_step;
    const double v0 = x[1];
    const double dir = v0 > 0.0 ? 1.0 : -1.0;
    const double v_free = xf[1];
    const double d = xf[0] - x[0];
    Lanes dd, dg, dgth;
    for (int j = 0; j < kDirs; ++j) {
      dd[j] = dxf[0][j] - S[0][j];
      dg[j] = dgth[j] = 0.0;
    }
    for (int k = 0; k < 2; ++k) {
      dg[k] = g0.dgam[k][1][1];
      dgth[k] = g0.dgam[k][0][1];
    }
    const double g = g0.gam[1][1], gth = g0.gam[0][1];
    double fb;
    Lanes dfb{};
    bool st = false;
    bool sliding_branch = false;
    if (v0 != 0.0) {
      Lanes dslip;
      const double f_slip = -dir * sliding(v0, S[1], dslip);
      if ((v_free + g * f_slip) * dir > 0.0) {
        fb = f_slip;
        for (int j = 0; j < kDirs; ++j) dfb[j] = -dir * dslip[j];
        sliding_branch = true;
      }
    }
    if (!sliding_branch) {
      const double q = v_free / g;
      const double f_stick = -q;
      if (f_stick <= fs && f_stick >= -fs) {
        fb = f_stick;
        for (int j = 0; j < kDirs; ++j) dfb[j] = -(dxf[1][j] - q * dg[j]) / g;
        st = true;
      } else {  // breaks away, or passes zero: -Fs or +Fs, dFs = dFc + d(excess)
        const double sgn = v_free > 0.0 ? -1.0 : 1.0;
        fb = sgn * fs;
        dfb[2] = sgn;
        dfb[3] = sgn;
      }
    }
    // Sliding friction may only oppose the net displacement over the sub-step.
    if (!(st && v0 == 0.0) && fb * (d + gth * fb) > 0.0) {
      st = false;
      Lanes dcap{};
      double cap = 0.0;
      if (gth > 0.0) {
        cap = std::fabs(d) / gth;
        const double sd = std::copysign(1.0, d);
        for (int j = 0; j < kDirs; ++j) dcap[j] = (sd * dd[j] - cap * dgth[j]) / gth;
      }
      const double sf = std::copysign(1.0, fb);
      const double afb = std::fabs(fb);
      Lanes dmag;
      double mag;
      if (afb < cap) {
        mag = afb;
        for (int j = 0; j < kDirs; ++j) dmag[j] = sf * dfb[j];
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
        for (int j = 0; j < kDirs; ++j) dfb[j] = s * dmag[j];
      }
    }
    if (st && stuck && v0 == 0.0) {  // held by static friction: the locked discretisation, no friction torque
      free_motion(locked_step, x, S, u, lag, xf, dxf);
      stuck = 1;
      for (int i = 0; i < 2; ++i) {
        x[i] = xf[i];
        S[i] = dxf[i];
      }
      return;
    }
    if (fb != 0.0)
      for (int i = 0; i < 2; ++i) {
        xf[i] += g0.gam[i][1] * fb;
        for (int j = 0; j < kDirs; ++j) dxf[i][j] += g0.gam[i][1] * dfb[j];
        for (int k = 0; k < 2; ++k) dxf[i][k] += g0.dgam[k][i][1] * fb;
      }
    if (st) {  // stopped inside the sub-step
      xf[1] = 0.0;
      dxf[1].fill(0.0);
    }
    stuck = st ? 1 : 0;
    for (int i = 0; i < 2; ++i) {
      x[i] = xf[i];
      S[i] = dxf[i];
    }
  }
};

class RigidSensitivityCost final : public ceres::CostFunction {
 public:
  RigidSensitivityCost(const FitContext* ctx, int start, int count, std::vector<int> free)
      : ctx_(ctx), start_(start), count_(count) {
    set_num_residuals(count);
    mutable_parameter_block_sizes()->push_back(kParams);
    mutable_parameter_block_sizes()->push_back(2);
    if (free.empty())
      moves_.fill(true);
    else
      for (int i : free) moves_[static_cast<std::size_t>(i)] = true;
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!jacobians || (!jacobians[0] && !jacobians[1])) {
      segment_residual(*ctx_, parameters[0], parameters[1], start_, count_, residuals);
      return true;
    }
    const FitContext& ctx = *ctx_;
    const double* p = parameters[0];
    const int nl = ctx.layout.lag_states();
    const auto disc = ctx.cache->get(p, true);
    RigidSimulation sim{ctx, p, mechanical_step(*disc, 0, nl), mechanical_step(*disc, 1, nl), p[2], p[2] + p[3],
                        p[4], ctx.layout.stribeck_exponent};
    double x[2] = {parameters[1][0], parameters[1][1]};
    Lanes S[2];
    S[0].fill(0.0);
    S[1].fill(0.0);
    S[0][kParams] = 1.0;
    S[1][kParams + 1] = 1.0;
    char stuck = x[1] == 0.0 ? 1 : 0;
    const int oi = ctx.output_index - nl;
    const std::vector<double>& u = ctx.log->torque_nm;
    const std::vector<double>& y = ctx.log->measured;
    double lag = nl ? ctx.lag[static_cast<std::size_t>(start_)] : 0.0;
    for (int k = 0; k < count_; ++k) {
      const std::size_t s = static_cast<std::size_t>(start_ + k);
      residuals[k] = (x[oi] - y[s]) * ctx.inv_scale;
      if (jacobians[0]) {
        double* row = jacobians[0] + static_cast<std::ptrdiff_t>(k) * kParams;
        for (int j = 0; j < kParams; ++j) row[j] = moves_[static_cast<std::size_t>(j)] ? S[oi][j] * ctx.inv_scale : 0.0;
      }
      if (jacobians[1])
        for (int i = 0; i < 2; ++i)
          jacobians[1][static_cast<std::ptrdiff_t>(k) * 2 + i] = S[oi][kParams + i] * ctx.inv_scale;
      if (k + 1 == count_) break;
      for (int sub = 0; sub < ctx.substeps; ++sub) {
        sim.substep(x, S, stuck, u[s], lag);
        if (nl) lag = ctx.lag_decay * lag + (1.0 - ctx.lag_decay) * u[s];
      }
    }
    return true;
  }

 private:
  const FitContext* ctx_;
  int start_, count_;
  std::array<bool, kParams> moves_{};
};

}  // namespace

ceres::CostFunction* rigid_sensitivity_cost(const FitContext* ctx, int start, int count, std::vector<int> free) {
  return new RigidSensitivityCost(ctx, start, count, std::move(free));
}

}  // namespace servobench::identify::detail
