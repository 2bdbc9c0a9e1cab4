#include "servobench/tuning/margins.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {
double db(std::complex<double> h) { return 20.0 * std::log10(std::abs(h)); }

// Linear interpolation in log frequency: the frequency where y (given at f0, f1) reaches target.
double crossing(double f0, double f1, double y0, double y1, double target, double* t_out) {
  const double t = (y1 == y0) ? 0.0 : (target - y0) / (y1 - y0);
  if (t_out) *t_out = t;
  return std::exp(std::log(f0) + t * (std::log(f1) - std::log(f0)));
}
}  // namespace

std::vector<double> unwrapped_phase_deg(const std::vector<std::complex<double>>& h) {
  std::vector<double> p(h.size());
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (k == 0) {
      p[k] = std::arg(h[k]) * 180.0 / M_PI;
    } else {
      p[k] = p[k - 1] + std::arg(h[k] / h[k - 1]) * 180.0 / M_PI;
    }
  }
  return p;
}

namespace {
void check_data(const std::vector<double>& f, const std::vector<std::complex<double>>& l,
                const std::vector<std::complex<double>>& t_in) {
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

// The crossovers with the loop's unwrapped phase (shared by gain_crossovers and margins).
std::vector<GainCrossover> crossovers_of(const std::vector<double>& f, const std::vector<std::complex<double>>& l,
                                         const std::vector<double>& ph) {
  std::vector<GainCrossover> out;
  for (std::size_t k = 0; k + 1 < f.size(); ++k) {
    const double g0 = db(l[k]), g1 = db(l[k + 1]);
    if ((g0 >= 0) == (g1 >= 0) && g1 != 0.0) continue;
    double t = 0;
    const double fc = crossing(f[k], f[k + 1], g0, g1, 0.0, &t);
    const double phase = ph[k] + t * (ph[k + 1] - ph[k]);
    double pm = std::fmod(phase + 180.0, 360.0);  // wrapped to (-180, 180]
    if (pm > 180.0) pm -= 360.0;
    if (pm <= -180.0) pm += 360.0;
    out.push_back(GainCrossover{fc, pm});
  }
  return out;
}
}  // namespace

std::vector<GainCrossover> gain_crossovers(const std::vector<double>& freq_hz,
                                           const std::vector<std::complex<double>>& loop_gain) {
  check_data(freq_hz, loop_gain, {});
  return crossovers_of(freq_hz, loop_gain, unwrapped_phase_deg(loop_gain));
}

Margins margins(const std::vector<double>& f, const std::vector<std::complex<double>>& l,
                const std::vector<std::complex<double>>& t_in) {
  check_data(f, l, t_in);
  const std::size_t n = f.size();
  Margins m;
  const std::vector<double> ph = unwrapped_phase_deg(l);
  // Gain crossovers: |L| through 0 dB. The phase margin is the crossover nearest to -1 (smallest |PM|, as
  // python-control's stability_margins); a crossover where L is near +1 (a phase-stabilised resonance, PM near
  // +-180) is the farthest from -1, not the worst. The delay margin is the smallest extra dead time that turns any
  // crossover onto -1: min over crossovers of (PM mod 360) / (360 fc).
  double delay = Margins::kNone;
  for (const GainCrossover& c : crossovers_of(f, l, ph)) {
    const double rotation = c.phase_margin_deg >= 0.0 ? c.phase_margin_deg : c.phase_margin_deg + 360.0;
    delay = std::min(delay, rotation / (360.0 * c.freq_hz));
    if (std::isinf(m.phase_margin_deg) || std::fabs(c.phase_margin_deg) < std::fabs(m.phase_margin_deg)) {
      m.phase_margin_deg = c.phase_margin_deg;
      m.pm_freq_hz = c.freq_hz;
    }
  }
  if (!std::isinf(m.phase_margin_deg)) m.delay_margin_s = m.phase_margin_deg > 0.0 ? delay : 0.0;
  // Phase crossovers: the unwrapped phase through an odd multiple of 180 deg.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double lo = std::min(ph[k], ph[k + 1]), hi = std::max(ph[k], ph[k + 1]);
    // odd multiples of 180 in [lo, hi]
    for (double c = std::ceil((lo - 180.0) / 360.0) * 360.0 + 180.0; c <= hi; c += 360.0) {
      if (ph[k + 1] == ph[k]) continue;
      double t = 0;
      const double fp = crossing(f[k], f[k + 1], ph[k], ph[k + 1], c, &t);
      const double gain = db(l[k]) + t * (db(l[k + 1]) - db(l[k]));
      const double gm = -gain;
      if (gm >= 0 && gm < m.gain_margin_db) {
        m.gain_margin_db = gm;
        m.gm_freq_hz = fp;
      } else if (gm < 0 && gm > m.lower_gain_margin_db) {
        m.lower_gain_margin_db = gm;
        m.lower_gm_freq_hz = fp;
      }
    }
  }
  // Closed-loop bandwidth.
  std::vector<std::complex<double>> t = t_in;
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
  for (std::size_t k = 0; k < n; ++k) {
    const double s = 1.0 / std::abs(1.0 + l[k]);
    if (s > m.ms) {
      m.ms = s;
      m.ms_freq_hz = f[k];
    }
  }
  return m;
}

}  // namespace servobench::tuning
