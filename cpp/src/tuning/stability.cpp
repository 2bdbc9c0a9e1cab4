#include "servobench/tuning/stability.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {

// Effective per-tick feedback gains of a card law, counts/pulse, and its volts per count (sign: V_INVERSE).
struct Gains {
  double kp, ki, kd, volts_per_count;
};
Gains gains_of(const machine::LawParams& law) {
  if (const auto* gt = std::get_if<control::GtServoLawParams>(&law))
    return {gt->kp, gt->ilmt == 0 ? 0.0 : gt->ki / 256.0, gt->kd, 10.0 / 32767.0};
  const auto& a = std::get<control::ApsServoLawParams>(law);
  return {a.kp_eff(), a.integral_limit == 0 ? 0.0 : a.ki_eff(), a.kd_eff(),
          (a.v_inverse ? -1.0 : 1.0) * 10.0 / 32767.0};
}

struct StateSpace {
  Eigen::MatrixXd a, b, c, d;
};

// Series connection: first s1, then s2 (single input, single output).
StateSpace series(const StateSpace& s1, const StateSpace& s2) {
  const Eigen::Index n1 = s1.a.rows(), n2 = s2.a.rows();
  StateSpace s;
  s.a = Eigen::MatrixXd::Zero(n1 + n2, n1 + n2);
  s.a.topLeftCorner(n1, n1) = s1.a;
  s.a.bottomLeftCorner(n2, n1) = s2.b * s1.c;
  s.a.bottomRightCorner(n2, n2) = s2.a;
  s.b = Eigen::MatrixXd(n1 + n2, 1);
  s.b.topRows(n1) = s1.b;
  s.b.bottomRows(n2) = s2.b * s1.d;
  s.c = Eigen::MatrixXd(1, n1 + n2);
  s.c.leftCols(n1) = s2.d * s1.c;
  s.c.rightCols(n2) = s2.c;
  s.d = s2.d * s1.d;
  return s;
}

StateSpace biquad_ss(const control::BiquadParams& p) {
  const control::FloatBiquadParams f =
      std::visit([](const auto& q) -> control::FloatBiquadParams {
        if constexpr (std::is_same_v<std::decay_t<decltype(q)>, control::AdlinkBiquadParams>) return q.to_float();
        else return q;
      }, p);
  // Transposed direct form II: y = b0 x + s1; s1' = -a1 y + b1 x + s2; s2' = -a2 y + b2 x.
  StateSpace s;
  s.a = (Eigen::MatrixXd(2, 2) << -f.a1, 1.0, -f.a2, 0.0).finished();
  s.b = (Eigen::MatrixXd(2, 1) << f.b1 - f.a1 * f.b0, f.b2 - f.a2 * f.b0).finished();
  s.c = (Eigen::MatrixXd(1, 2) << 1.0, 0.0).finished();
  s.d = Eigen::MatrixXd::Constant(1, 1, f.b0);
  return s;
}

struct Loop {
  StateSpace k, p;  // controller E -> V, plant V -> Y (pulse) with the one-tick delay
  double ts = 0;
};

Loop loop_of(const machine::AxisConfig& config_in, const LoopOptions& options) {
  machine::AxisConfig config = config_in;
  config.validate_and_complete();
  const machine::Axis axis(config);
  if (axis.power_train().pulse_input())
    throw std::invalid_argument("loop_poles: a pulse-output axis (stepper or servo in position mode) has no "
                                "position loop on the card");
  const machine::TickModel tm = axis.power_train().linear_tick_model();
  const Gains g = gains_of(config.law);
  Loop lp;
  lp.ts = *config.servo_period_s;
  // PID: states Sum(k-1) (only when the integral acts) and E(k-1).
  StateSpace pid;
  if (g.ki != 0.0) {
    pid.a = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 0.0, 0.0).finished();
    pid.b = (Eigen::MatrixXd(2, 1) << 1.0, 1.0).finished();
    pid.c = (Eigen::MatrixXd(1, 2) << g.ki, -g.kd).finished();
  } else {
    pid.a = Eigen::MatrixXd::Zero(1, 1);
    pid.b = Eigen::MatrixXd::Ones(1, 1);
    pid.c = Eigen::MatrixXd::Constant(1, 1, -g.kd);
  }
  pid.d = Eigen::MatrixXd::Constant(1, 1, g.kp + g.ki + g.kd);
  const auto filters = filters_for_measurement(config.filters, options);
  lp.k = series(series(pid, biquad_ss(filters[0])), biquad_ss(filters[1]));
  lp.k.c *= g.volts_per_count;
  lp.k.d *= g.volts_per_count;
  // Plant V -> Y (pulse) with the one-tick output delay: x' = A x + B d, d' = v, y = cpr C x.
  const Eigen::Index n = tm.a.rows();
  const double cpr = config.encoder.counts_per_rev / (2.0 * M_PI);
  StateSpace& p = lp.p;
  p.a = Eigen::MatrixXd::Zero(n + 1, n + 1);
  p.a.topLeftCorner(n, n) = tm.a;
  p.a.topRightCorner(n, 1) = tm.b.col(0);
  p.b = Eigen::MatrixXd::Zero(n + 1, 1);
  p.b(n, 0) = 1.0;
  p.c = Eigen::MatrixXd::Zero(1, n + 1);
  p.c.leftCols(n) = cpr * (config.encoder.on_load ? tm.c_load : tm.c_motor);
  p.d = Eigen::MatrixXd::Zero(1, 1);
  return lp;
}

Complex evaluate(const StateSpace& s, Complex z) {
  const Eigen::Index n = s.a.rows();
  const Eigen::MatrixXcd m = z * Eigen::MatrixXcd::Identity(n, n) - s.a.cast<Complex>();
  const Eigen::VectorXcd x = m.partialPivLu().solve(s.b.cast<Complex>());
  return (s.c.cast<Complex>() * x)(0, 0) + s.d(0, 0);
}

}  // namespace

LoopPoles loop_poles(const machine::AxisConfig& config, const LoopOptions& options) {
  const Loop lp = loop_of(config, options);
  const StateSpace &k = lp.k, &p = lp.p;
  // e = -y: x_p' = (Ap - Bp Dk Cp) x_p + Bp Ck x_k, x_k' = -Bk Cp x_p + Ak x_k.
  const Eigen::Index np = p.a.rows(), nk = k.a.rows();
  Eigen::MatrixXd a(np + nk, np + nk);
  a.topLeftCorner(np, np) = p.a - p.b * k.d * p.c;
  a.topRightCorner(np, nk) = p.b * k.c;
  a.bottomLeftCorner(nk, np) = -k.b * p.c;
  a.bottomRightCorner(nk, nk) = k.a;
  LoopPoles out;
  const Eigen::VectorXcd ev = a.eigenvalues();
  for (Eigen::Index i = 0; i < ev.size(); ++i) {
    out.closed_loop.push_back(ev(i));
    out.max_radius = std::max(out.max_radius, std::abs(ev(i)));
  }
  for (const Eigen::MatrixXd* m : {&k.a, &p.a}) {
    const Eigen::VectorXcd e = m->eigenvalues();
    for (Eigen::Index i = 0; i < e.size(); ++i) {
      out.open_loop.push_back(e(i));
      if (std::abs(e(i) - 1.0) < 1e-6) ++out.integrators;
      else if (std::abs(e(i)) > 1.0 + 1e-9) ++out.open_loop_unstable;
    }
  }
  return out;
}

Stability pole_stability(const LoopPoles& poles) {
  Stability s;
  s.decided = true;
  s.method = "closed-loop poles";
  s.max_pole_radius = poles.max_radius;
  s.integrators = poles.integrators;
  s.open_loop_unstable_poles = poles.open_loop_unstable;
  s.unstable_poles = 0;
  for (const Complex& z : poles.closed_loop)
    if (!(std::abs(z) < 1.0)) ++s.unstable_poles;
  s.stable = s.unstable_poles == 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", poles.max_radius);
  s.reason = std::string(s.stable ? "stable" : "UNSTABLE") + ": the linear model's largest closed-loop pole |z| = " +
             buf + (s.stable ? " < 1" : " >= 1 (" + std::to_string(s.unstable_poles) +
                                            " pole(s) on or outside the unit circle)");
  return s;
}

double closed_loop_pole_radius(const machine::AxisConfig& config) { return loop_poles(config).max_radius; }

Margins analytic_margins(const machine::AxisConfig& config, const std::vector<double>& freq_hz,
                         const LoopOptions& options) {
  const Loop lp = loop_of(config, options);
  const double ts = lp.ts, nyq = 0.5 / ts;
  std::vector<double> f = freq_hz;
  if (f.empty()) {
    const int n = 4000;
    const double lo = 1e-5 / ts, hi = nyq * (1.0 - 1e-9);
    for (int i = 0; i < n; ++i) f.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
  }
  for (double x : f)
    if (!(x > 0) || !(x < nyq))
      throw_invalid("analytic_margins", "freq_hz", x,
                    "must be > 0 and below the Nyquist frequency 1/(2 Ts) = " + format_value(nyq) + " Hz");
  const StateSpace ol = series(lp.k, lp.p);
  auto at = [&](double hz) { return evaluate(ol, std::exp(Complex(0.0, 2.0 * M_PI * hz * ts))); };
  std::vector<Complex> l(f.size());
  std::vector<double> f2;
  std::vector<Complex> l2;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Complex v = at(f[i]);
    if (v == 0.0 || !std::isfinite(v.real()) || !std::isfinite(v.imag())) continue;  // a notch's null on the grid
    f2.push_back(f[i]);
    l2.push_back(v);
  }
  const Stability verdict = pole_stability(loop_poles(config, options));
  if (f2.size() < 2) {  // no loop gain at all (every gain 0): stability only
    Margins m;
    m.stability = verdict;
    return m;
  }
  MarginsOptions o;
  o.stability = verdict;
  o.loop_gain_at = at;
  if (f2.back() > 0.45 / ts) o.nyquist_hz = nyq;
  return margins(f2, l2, {}, o);
}

}  // namespace servobench::tuning
