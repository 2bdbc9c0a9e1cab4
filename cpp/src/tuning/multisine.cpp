#include "servobench/tuning/multisine.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/tuning/chirp.hpp"
#include "vector_clones.hpp"

namespace servobench::tuning {

namespace {
constexpr const char* kOwner = "multisine";
constexpr double kPi = 3.141592653589793;

// x_n = sum_i cos(2 pi k_i n / N + phase_i), n = 0..N-1. Each line runs as a phasor z <- z w (w = exp(2 pi j k/N))
// started on exp(j phase) and re-anchored every kBlock samples on the exact value (k n mod N indexes a table of
// cos/sin 2 pi m / N; the rotation's rounding stays below 1e-13); four lines at a time, so their chains overlap.
SERVOBENCH_VECTOR_CLONES
std::vector<double> cosine_sum(int n, const std::vector<int>& lines, const std::vector<double>& phases) {
  constexpr int kBlock = 256;
  std::vector<double> c(n), s(n), x(n, 0.0);
  for (int m = 0; m < n; ++m) {
    c[m] = std::cos(2 * kPi * m / n);
    s[m] = std::sin(2 * kPi * m / n);
  }
  const std::size_t count = lines.size();
  std::vector<long long> k(count);
  std::vector<double> cp(count), sp(count);
  for (std::size_t i = 0; i < count; ++i) {
    k[i] = ((lines[i] % n) + n) % n;
    cp[i] = std::cos(phases[i]);
    sp[i] = std::sin(phases[i]);
  }
  for (std::size_t i0 = 0; i0 < count; i0 += 4) {
    const std::size_t g = std::min<std::size_t>(4, count - i0);
    double wr[4] = {1, 1, 1, 1}, wi[4] = {0, 0, 0, 0};
    for (std::size_t q = 0; q < g; ++q) {
      wr[q] = c[k[i0 + q]];
      wi[q] = s[k[i0 + q]];
    }
    for (int j0 = 0; j0 < n; j0 += kBlock) {
      const int j1 = std::min(n, j0 + kBlock);
      double zr[4] = {0, 0, 0, 0}, zi[4] = {0, 0, 0, 0};  // exp(j (2 pi k n / N + phase))
      for (std::size_t q = 0; q < g; ++q) {
        const long long idx = (k[i0 + q] * j0) % n;
        zr[q] = c[idx] * cp[i0 + q] - s[idx] * sp[i0 + q];
        zi[q] = s[idx] * cp[i0 + q] + c[idx] * sp[i0 + q];
      }
      for (int j = j0; j < j1; ++j) {
        x[j] += (zr[0] + zr[1]) + (zr[2] + zr[3]);
        for (int q = 0; q < 4; ++q) {
          const double re = zr[q] * wr[q] - zi[q] * wi[q];
          zi[q] = zr[q] * wi[q] + zi[q] * wr[q];
          zr[q] = re;
        }
      }
    }
  }
  return x;
}

void scale_to_peak(std::vector<double>& x, double amplitude) {
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::fabs(v));
  if (!(peak > 0)) throw_invalid(kOwner, "lines", 0, "give a signal that is zero everywhere");
  for (double& v : x) v = amplitude * v / peak;
}
}  // namespace

std::vector<int> multisine_lines(double start_hz, double end_hz, int period_ticks, double ts, int lines) {
  check_positive(kOwner, "servo_period_s", ts, 1.0);
  const double nyquist = 0.5 / ts;
  if (!(start_hz > 0 && start_hz < nyquist))
    throw_invalid(kOwner, "start_hz", start_hz, "must be > 0 and below the Nyquist frequency " + format_value(nyquist) + " Hz");
  if (!(end_hz > 0 && end_hz < nyquist))
    throw_invalid(kOwner, "end_hz", end_hz, "must be > 0 and below the Nyquist frequency " + format_value(nyquist) + " Hz");
  if (!(end_hz > start_hz))
    throw_invalid(kOwner, "end_hz", end_hz, "must be above start_hz = " + format_value(start_hz));
  if (period_ticks < 8) throw_invalid(kOwner, "period_ticks", period_ticks, "must be >= 8");
  if (lines < 0) throw_invalid(kOwner, "lines", lines, "must be >= 1 (or None: every line in the band)");
  const int n = period_ticks;
  const double df = 1.0 / (n * ts);
  const int k_lo = std::max(1, static_cast<int>(std::ceil(start_hz / df - 1e-9)));
  const int k_hi = std::min(n / 2 - 1, static_cast<int>(std::floor(end_hz / df + 1e-9)));
  if (k_hi < k_lo)
    throw_invalid(kOwner, "period_ticks", n, "has no DFT line (spacing " + format_value(df) + " Hz) in " +
                                              format_value(start_hz) + ".." + format_value(end_hz) +
                                              " Hz: lengthen period_ticks");
  std::vector<int> bins;
  if (lines == 0) {
    for (int k = k_lo; k <= k_hi; ++k) bins.push_back(k);
    return bins;
  }
  for (double v : geomspace(k_lo, k_hi, lines)) bins.push_back(static_cast<int>(std::nearbyint(v)));
  std::sort(bins.begin(), bins.end());
  bins.erase(std::unique(bins.begin(), bins.end()), bins.end());
  return bins;
}

Multisine schroeder_multisine(double start_hz, double end_hz, int period_ticks, double ts, double amplitude,
                              int lines) {
  check_nonnegative(kOwner, "amplitude", amplitude);
  Multisine out;
  out.lines = multisine_lines(start_hz, end_hz, period_ticks, ts, lines);
  const int m = static_cast<int>(out.lines.size());
  std::vector<double> phases(m);
  for (int i = 0; i < m; ++i) phases[i] = -kPi * i * (i + 1.0) / m;  // Schroeder
  out.period = cosine_sum(period_ticks, out.lines, phases);
  scale_to_peak(out.period, amplitude);
  return out;
}

std::vector<double> multisine_sum(int n_samples, double ts, const std::vector<int>& lines,
                                  const std::vector<double>& phases_rad, double amplitude) {
  check_positive(kOwner, "servo_period_s", ts, 1.0);
  check_nonnegative(kOwner, "amplitude", amplitude);
  if (n_samples < 1) throw_invalid(kOwner, "n_samples", n_samples, "must be >= 1");
  if (phases_rad.size() != lines.size())
    throw_invalid(kOwner, "phases_rad", static_cast<double>(phases_rad.size()), "must have one phase per line");
  if (lines.empty()) throw_invalid(kOwner, "lines", 0, "must hold at least one DFT line");
  std::vector<double> x = cosine_sum(n_samples, lines, phases_rad);
  scale_to_peak(x, amplitude);
  return x;
}

}  // namespace servobench::tuning
