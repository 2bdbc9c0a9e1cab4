#include "servobench/tuning/chirp.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {
constexpr const char* kOwner = "chirp";
constexpr double kPi = 3.141592653589793;
}  // namespace

void ChirpOptions::validate() const {
  check_positive(kOwner, "servo_period_s", servo_period_s, 1.0);
  const double nyquist = 0.5 / servo_period_s;
  if (!(start_hz > 0 && start_hz < nyquist))
    throw_invalid(kOwner, "start_hz", start_hz, "must be > 0 and below the Nyquist frequency " + format_value(nyquist) + " Hz");
  if (!(end_hz > start_hz && end_hz <= nyquist))
    throw_invalid(kOwner, "end_hz", end_hz, "must be above start_hz = " + format_value(start_hz) +
                                                " and at most the Nyquist frequency " + format_value(nyquist) + " Hz");
  check_positive(kOwner, "duration_s", duration_s, 1e7);
  check_nonnegative(kOwner, "amplitude", amplitude);
}

std::vector<double> chirp(const ChirpOptions& o) {
  o.validate();
  const double ts = o.servo_period_s;
  const long long n = std::llround(std::nearbyint(o.duration_s / ts));  // round half to even, as Python's round()
  if (n > 100000000LL) throw_invalid(kOwner, "duration_s", o.duration_s, "is more than 1e8 samples");
  std::vector<double> x(static_cast<std::size_t>(n));
  if (o.kind == ChirpKind::kLog) {
    const double k = std::log(o.end_hz / o.start_hz) / o.duration_s;
    const double w0 = 2 * kPi * o.start_hz;
    for (long long i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) * ts;
      x[i] = o.amplitude * std::sin(w0 * std::expm1(k * t) / k);
    }
  } else {
    const double rate = 0.5 * (o.end_hz - o.start_hz) / o.duration_s;
    for (long long i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) * ts;
      x[i] = o.amplitude * std::sin(2 * kPi * (o.start_hz * t + rate * t * t));
    }
  }
  return x;
}

std::vector<double> chirp_record(const ChirpOptions& o, int rest_ticks) {
  if (rest_ticks < 0) throw_invalid(kOwner, "rest_ticks", rest_ticks, "must be >= 0");
  std::vector<double> x = chirp(o);
  const int n = static_cast<int>(x.size());
  const double fs = 1.0 / o.servo_period_s;
  const int ramp_in = std::min(n / 4, static_cast<int>(std::nearbyint(fs / o.start_hz)));
  const int ramp_out = std::min(n / 4, static_cast<int>(std::nearbyint(20 * fs / o.end_hz)));
  std::vector<double> taper(n, 1.0);
  for (int i = 0; i < ramp_in; ++i) taper[i] = 0.5 - 0.5 * std::cos(kPi * i / ramp_in);
  for (int i = 1; i <= ramp_out; ++i) taper[n - ramp_out + i - 1] = 0.5 + 0.5 * std::cos(kPi * i / ramp_out);
  for (int i = 0; i < n; ++i) x[i] *= taper[i];
  x.resize(static_cast<std::size_t>(n) + rest_ticks, 0.0);
  return x;
}

std::vector<double> geomspace(double start, double stop, int num) {
  std::vector<double> out(std::max(num, 0));
  if (num <= 0) return out;
  const double a = std::log10(start), b = std::log10(stop);
  const double step = num > 1 ? (b - a) / (num - 1) : 0.0;
  for (int i = 0; i < num; ++i) out[i] = std::pow(10.0, (num > 1 && i == num - 1) ? b : i * step + a);
  out[0] = start;
  if (num > 1) out[num - 1] = stop;
  return out;
}

std::vector<int> chirp_lines(int n, double ts, double start_hz, double end_hz, int lines) {
  if (n < 1) throw_invalid(kOwner, "record_ticks", n, "must be >= 1");
  const double df = 1.0 / (n * ts);
  std::vector<double> freq(n / 2 + 1);
  for (int i = 0; i <= n / 2; ++i) freq[i] = i * df;  // numpy.fft.rfftfreq
  std::vector<int> band;
  for (int i = 0; i <= n / 2; ++i)
    if (freq[i] >= start_hz && freq[i] <= end_hz) band.push_back(i);
  if (lines < 0 || lines >= static_cast<int>(band.size())) return band;
  const std::vector<double> want = geomspace(freq[band.front()], freq[band.back()], lines);
  std::vector<int> picked;
  for (double w : want) {
    int i = static_cast<int>(std::lower_bound(freq.begin(), freq.end(), w) - freq.begin());
    i = std::clamp(i, band.front(), band.back());
    picked.push_back(i);
  }
  std::sort(picked.begin(), picked.end());
  picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  return picked;
}

}  // namespace servobench::tuning
