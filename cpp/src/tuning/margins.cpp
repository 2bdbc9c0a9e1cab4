#include "servobench/tuning/margins.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {
using C = std::complex<double>;
double db(C h) { return 20.0 * std::log10(std::abs(h)); }
double deg(double rad) { return rad * 180.0 / M_PI; }

// Linear interpolation in log frequency: the frequency where y (given at f0, f1) reaches target.
double crossing(double f0, double f1, double y0, double y1, double target, double* t_out) {
  const double t = (y1 == y0) ? 0.0 : (target - y0) / (y1 - y0);
  if (t_out) *t_out = t;
  return std::exp(std::log(f0) + t * (std::log(f1) - std::log(f0)));
}

double wrap180(double d) {  // to (-180, 180]
  double w = std::fmod(d, 360.0);
  if (w > 180.0) w -= 360.0;
  if (w <= -180.0) w += 360.0;
  return w;
}

// Bisection in log frequency on a sign change of g between f0 and f1 (g(f0), g(f1) of opposite signs).
template <class G>
double bisect(double f0, double f1, G g) {
  double lo = std::log(f0), hi = std::log(f1);
  const bool s0 = g(f0) >= 0.0;
  for (int i = 0; i < 200 && hi - lo > 1e-11; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((g(std::exp(mid)) >= 0.0) == s0) lo = mid; else hi = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

std::string fmt(double v) { return format_value(v); }
}  // namespace

std::vector<double> unwrapped_phase_deg(const std::vector<C>& h) {
  std::vector<double> p(h.size());
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (k == 0) {
      p[k] = deg(std::arg(h[k]));
    } else {
      p[k] = p[k - 1] + deg(std::arg(h[k] / h[k - 1]));
    }
  }
  return p;
}

namespace {
void check_data(const std::vector<double>& f, const std::vector<C>& l, const std::vector<C>& t_in) {
  const std::size_t n = f.size();
  if (n < 2) throw std::invalid_argument("margins: freq_hz needs at least 2 points, got " + std::to_string(n));
  if (l.size() != n)
    throw std::invalid_argument("margins: loop_gain has " + std::to_string(l.size()) + " points, freq_hz " +
                                std::to_string(n));
  if (!t_in.empty() && t_in.size() != n)
    throw std::invalid_argument("margins: closed_loop has " + std::to_string(t_in.size()) + " points, freq_hz " +
                                std::to_string(n));
  for (std::size_t k = 0; k < n; ++k) {
    if (!(f[k] > 0) || !std::isfinite(f[k])) throw_invalid("margins", "freq_hz", f[k], "must be finite and > 0");
    if (k > 0 && !(f[k] > f[k - 1]))
      throw std::invalid_argument("margins: freq_hz must increase; freq_hz[" + std::to_string(k) +
                                  "] = " + format_value(f[k]) + " <= " + format_value(f[k - 1]));
    if (!std::isfinite(l[k].real()) || !std::isfinite(l[k].imag()) || l[k] == 0.0)
      throw std::invalid_argument("margins: loop_gain[" + std::to_string(k) + "] is zero or not finite");
  }
}

// The gain crossovers of the data, refined with `at` when given.
std::vector<GainCrossover> crossovers_of(const std::vector<double>& f, const std::vector<C>& l,
                                         const std::function<C(double)>& at) {
  std::vector<GainCrossover> out;
  for (std::size_t k = 0; k + 1 < f.size(); ++k) {
    const double g0 = db(l[k]), g1 = db(l[k + 1]);
    if ((g0 >= 0) == (g1 >= 0) && g1 != 0.0) continue;
    if (at) {
      const double fc = (g1 == 0.0) ? f[k + 1] : bisect(f[k], f[k + 1], [&](double x) { return db(at(x)); });
      out.push_back(GainCrossover{fc, wrap180(deg(std::arg(at(fc))) + 180.0)});
      continue;
    }
    double t = 0;
    const double fc = crossing(f[k], f[k + 1], g0, g1, 0.0, &t);
    const double p0 = deg(std::arg(l[k]));
    const double phase = p0 + t * deg(std::arg(l[k + 1] / l[k]));
    out.push_back(GainCrossover{fc, wrap180(phase + 180.0)});
  }
  return out;
}

// The phase crossovers of the data (angle L through an odd multiple of 180 deg between neighbours, the phase
// unwrapped locally), refined with `at` (a sign change of Im L) when given.
std::vector<PhaseCrossover> phase_crossovers_of(const std::vector<double>& f, const std::vector<C>& l,
                                                const std::function<C(double)>& at) {
  std::vector<PhaseCrossover> out;
  for (std::size_t k = 0; k + 1 < f.size(); ++k) {
    const double p0 = deg(std::arg(l[k]));
    const double p1 = p0 + deg(std::arg(l[k + 1] / l[k]));
    if (p1 == p0) continue;
    const double lo = std::min(p0, p1), hi = std::max(p0, p1);
    for (double c = std::ceil((lo - 180.0) / 360.0) * 360.0 + 180.0; c <= hi; c += 360.0) {
      if (c == p0 && k > 0) continue;  // counted as the previous interval's end
      double t = 0;
      double fp = crossing(f[k], f[k + 1], p0, p1, c, &t);
      double gain = db(l[k]) + t * (db(l[k + 1]) - db(l[k]));
      if (at) {
        if (l[k].imag() == 0.0) {
          fp = f[k];
        } else if (l[k + 1].imag() == 0.0) {
          fp = f[k + 1];
        } else if ((l[k].imag() > 0) != (l[k + 1].imag() > 0)) {
          fp = bisect(f[k], f[k + 1], [&](double x) { return at(x).imag(); });
        }
        gain = db(at(fp));
      }
      out.push_back(PhaseCrossover{fp, -gain});
    }
  }
  return out;
}

int infer_integrators(const std::vector<double>& f, const std::vector<C>& l) {
  const double slope = (db(l[1]) - db(l[0])) / (std::log10(f[1]) - std::log10(f[0]));
  return static_cast<int>(std::clamp(std::round(-slope / 20.0), 0.0, 4.0));
}
}  // namespace

Stability nyquist_stability(const std::vector<double>& f, const std::vector<C>& l, int p, int k) {
  check_data(f, l, {});
  if (p < 0) throw_invalid("margins", "open_loop_unstable_poles", p, "must be >= 0");
  Stability s;
  s.method = "Nyquist";
  s.open_loop_unstable_poles = p;
  const bool inferred = k < 0;
  s.integrators = inferred ? infer_integrators(f, l) : k;
  k = s.integrators;
  const std::string counts = std::to_string(p) + " open-loop unstable pole(s), " + std::to_string(k) +
                             " integrator(s)" + (inferred ? " (inferred from the low-frequency slope)" : "");
  const double l0 = std::abs(l.front()), l1 = std::abs(l.back());
  if (k > 0 && l0 < 2.0) {
    s.reason = "undecided: the data start at |L| = " + fmt(l0) + " (< 2) at " + fmt(f.front()) +
               " Hz, above the integrators' region; the Nyquist count needs a lower start frequency (" + counts + ")";
    return s;
  }
  if (l1 >= 1.0) {
    s.reason = "undecided: the data end at |L| = " + fmt(l1) + " (>= 1) at " + fmt(f.back()) +
               " Hz; the Nyquist count needs the response up to where |L| < 1 (" + counts + ")";
    return s;
  }
  // Start: angle L on the branch nearest the integrators' asymptote -k 90 deg, angle (1 + L) on the branch nearest
  // that (|L| >= 2: within 30 deg). k = 0: no winding below the first point.
  double theta;
  {
    const double asym = -90.0 * k;
    double phi = deg(std::arg(l.front()));
    phi += 360.0 * std::round((asym - phi) / 360.0);
    double th = deg(std::arg(1.0 + l.front()));
    if (k > 0) th += 360.0 * std::round((phi - th) / 360.0);
    theta = th;
  }
  double closest = std::abs(1.0 + l.front());
  for (std::size_t i = 1; i < l.size(); ++i) {
    theta += deg(std::arg((1.0 + l[i]) / (1.0 + l[i - 1])));
    closest = std::min(closest, std::abs(1.0 + l[i]));
  }
  const double theta_end = 360.0 * std::round(theta / 360.0);  // |L| < 1: 1 + L in the right half-plane
  const double z = p - theta_end / 180.0;
  s.unstable_poles = static_cast<int>(std::lround(z));
  s.decided = true;
  const double n_cw = -theta_end / 360.0;
  s.stable = s.unstable_poles == 0 && closest > 0.0;
  s.reason = std::string(s.stable ? "stable" : "UNSTABLE") + " by the Nyquist criterion: L encircles -1 " +
             fmt(n_cw) + " time(s) clockwise over the whole contour with " + counts + ": " +
             std::to_string(s.unstable_poles) + " closed-loop pole(s) outside the unit circle (closest approach " +
             "|1 + L| = " + fmt(closest) + ")";
  if (s.unstable_poles < 0) {
    s.stable = false;
    s.decided = false;
    s.reason = "undecided: the Nyquist count gives a negative number of closed-loop poles (" +
               std::to_string(s.unstable_poles) + "): the grid is too coarse near -1 or " + counts + " is wrong";
  }
  return s;
}

std::vector<GainCrossover> gain_crossovers(const std::vector<double>& freq_hz, const std::vector<C>& loop_gain) {
  check_data(freq_hz, loop_gain, {});
  return crossovers_of(freq_hz, loop_gain, {});
}

Margins margins(const std::vector<double>& f, const std::vector<C>& l, const std::vector<C>& t_in,
                const MarginsOptions& o) {
  check_data(f, l, t_in);
  const std::size_t n = f.size();
  Margins m;
  m.stability = o.stability ? *o.stability : nyquist_stability(f, l, o.open_loop_unstable_poles, o.integrators);
  // Gain crossovers. The phase margin is the crossover nearest to -1 (smallest |PM|, as python-control's
  // stability_margins); a crossover where L is near +1 (a phase-stabilised resonance, PM near +-180) is the
  // farthest from -1, not the worst. The delay margin is the smallest extra dead time that turns any crossover
  // onto -1: min over crossovers of (PM mod 360) / (360 fc).
  m.gain_crossovers = crossovers_of(f, l, o.loop_gain_at);
  double delay = Margins::kNone;
  for (const GainCrossover& c : m.gain_crossovers) {
    const double rotation = c.phase_margin_deg >= 0.0 ? c.phase_margin_deg : c.phase_margin_deg + 360.0;
    delay = std::min(delay, rotation / (360.0 * c.freq_hz));
    if (std::isinf(m.phase_margin_deg) || std::fabs(c.phase_margin_deg) < std::fabs(m.phase_margin_deg)) {
      m.phase_margin_deg = c.phase_margin_deg;
      m.pm_freq_hz = c.freq_hz;
    }
  }
  if (!std::isinf(m.phase_margin_deg)) m.delay_margin_s = m.phase_margin_deg > 0.0 ? delay : 0.0;
  // Phase crossovers.
  m.phase_crossovers = phase_crossovers_of(f, l, o.loop_gain_at);
  if (o.loop_gain_at && o.nyquist_hz > 0.0) {
    const C ln = o.loop_gain_at(o.nyquist_hz);
    if (ln.real() < 0.0 && (m.phase_crossovers.empty() || m.phase_crossovers.back().freq_hz < o.nyquist_hz * (1 - 1e-9)))
      m.phase_crossovers.push_back(PhaseCrossover{o.nyquist_hz, -db(ln)});
  }
  for (const PhaseCrossover& c : m.phase_crossovers) {
    if (c.gain_margin_db >= 0 && c.gain_margin_db < m.gain_margin_db) {
      m.gain_margin_db = c.gain_margin_db;
      m.gm_freq_hz = c.freq_hz;
    } else if (c.gain_margin_db < 0 && c.gain_margin_db > m.lower_gain_margin_db) {
      m.lower_gain_margin_db = c.gain_margin_db;
      m.lower_gm_freq_hz = c.freq_hz;
    }
  }
  // Closed-loop bandwidth.
  std::vector<C> t = t_in;
  if (t.empty()) {
    t.resize(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = l[k] / (1.0 + l[k]);
  }
  const double ref = db(t[0]) - 3.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double g0 = db(t[k]), g1 = db(t[k + 1]);
    if (g0 >= ref && g1 < ref) {
      m.bandwidth_hz = crossing(f[k], f[k + 1], g0, g1, ref, nullptr);
      break;
    }
  }
  // Peak sensitivity.
  m.ms = 0.0;
  std::size_t kmax = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = 1.0 / std::abs(1.0 + l[k]);
    if (s > m.ms) {
      m.ms = s;
      m.ms_freq_hz = f[k];
      kmax = k;
    }
  }
  if (o.loop_gain_at) {  // golden-section search for the minimum of |1 + L| between the neighbours
    double a = std::log(f[kmax > 0 ? kmax - 1 : 0]), b = std::log(f[std::min(kmax + 1, n - 1)]);
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    auto dist = [&](double x) { return std::abs(1.0 + o.loop_gain_at(std::exp(x))); };
    double x1 = b - r * (b - a), x2 = a + r * (b - a), d1 = dist(x1), d2 = dist(x2);
    for (int i = 0; i < 100 && b - a > 1e-10; ++i) {
      if (d1 < d2) { b = x2; x2 = x1; d2 = d1; x1 = b - r * (b - a); d1 = dist(x1); }
      else { a = x1; x1 = x2; d1 = d2; x2 = a + r * (b - a); d2 = dist(x2); }
    }
    const double x = 0.5 * (a + b), s = 1.0 / dist(x);
    if (s > m.ms) {
      m.ms = s;
      m.ms_freq_hz = std::exp(x);
    }
  }
  return m;
}

void MarginsOptions::validate() const {
  check_integer("MarginsOptions", "open_loop_unstable_poles", open_loop_unstable_poles, 0, 1000);
  check_integer("MarginsOptions", "integrators", integrators, -1, 10);
}

}  // namespace servobench::tuning
