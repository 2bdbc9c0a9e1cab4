#include "servobench/control/biquad.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::control {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kAdlinkSource = "ADLINK manual L1897-1911, int16";

void check_finite(const char* owner, const char* field, double value) {
  if (!std::isfinite(value)) throw_invalid(owner, field, value, "is not a finite number");
}

void check_period(const char* owner, double ts) {
  check_range(owner, "sample_time_s", ts, 0.0, 1.0, "s; 0 = not bound to a period");
}

std::complex<double> unit(double freq_hz, double ts) {
  if (!(ts > 0) || !std::isfinite(ts))
    throw std::invalid_argument("sample_time_s = " + format_value(ts) +
                                " s: a frequency response needs a sample time > 0 s (the filter is not bound to a "
                                "period; pass sample_time_s)");
  if (!std::isfinite(freq_hz)) throw_invalid("frequency_response", "freq_hz", freq_hz, "is not a finite number");
  return std::polar(1.0, -2.0 * kPi * freq_hz * ts);  // z^-1 on the unit circle
}

std::pair<std::complex<double>, std::complex<double>> quadratic_roots(double a, double b, double c) {
  // roots of a z^2 + b z + c, a != 0
  const std::complex<double> s = std::sqrt(std::complex<double>(b * b - 4.0 * a * c, 0.0));
  return {(-b + s) / (2.0 * a), (-b - s) / (2.0 * a)};
}

}  // namespace

void FloatBiquadParams::validate() const {
  const char* o = "FloatBiquad";
  check_finite(o, "b0", b0);
  check_finite(o, "b1", b1);
  check_finite(o, "b2", b2);
  check_finite(o, "a1", a1);
  check_finite(o, "a2", a2);
  check_period(o, sample_time_s);
}

void AdlinkBiquadParams::validate() const {
  const char* o = "AdlinkBiquad";
  check_integer(o, "a1", a1, kMin, kMax, kAdlinkSource);
  check_integer(o, "a2", a2, kMin, kMax, kAdlinkSource);
  check_integer(o, "b0", b0, kMin, kMax, kAdlinkSource);
  check_integer(o, "b1", b1, kMin, kMax, kAdlinkSource);
  check_integer(o, "b2", b2, kMin, kMax, kAdlinkSource);
  check_integer(o, "div", div, kMin, kMax, kAdlinkSource);
  if (div == 0.0)
    throw_invalid(o, "div", div,
                  "is not allowed: DIV divides the whole difference equation (L1873-1887); the allowed range is "
                  "-32768..-1 or 1..32767");
  check_period(o, sample_time_s);
}

FloatBiquadParams AdlinkBiquadParams::to_float() const {
  FloatBiquadParams f;
  f.b0 = b0 / div;
  f.b1 = b1 / div;
  f.b2 = b2 / div;
  f.a1 = -a1 / div;
  f.a2 = -a2 / div;
  f.sample_time_s = sample_time_s;
  return f;
}

std::complex<double> frequency_response(const FloatBiquadParams& p, double freq_hz, double ts) {
  const std::complex<double> zi = unit(freq_hz, ts);
  return (p.b0 + zi * (p.b1 + zi * p.b2)) / (1.0 + zi * (p.a1 + zi * p.a2));
}

std::complex<double> frequency_response(const AdlinkBiquadParams& p, double freq_hz, double ts) {
  const std::complex<double> zi = unit(freq_hz, ts);
  return (p.b0 + zi * (p.b1 + zi * p.b2)) / (p.div - zi * (p.a1 + zi * p.a2));
}

std::pair<std::complex<double>, std::complex<double>> poles(const FloatBiquadParams& p) {
  return quadratic_roots(1.0, p.a1, p.a2);
}

std::pair<std::complex<double>, std::complex<double>> poles(const AdlinkBiquadParams& p) {
  return quadratic_roots(p.div, -p.a1, -p.a2);
}

bool is_stable(const FloatBiquadParams& p) {
  return std::fabs(p.a2) < 1.0 && std::fabs(p.a1) < 1.0 + p.a2;
}

bool is_stable(const AdlinkBiquadParams& p) {
  // DIV z^2 - A1 z - A2 = DIV (z^2 + c1 z + c0), c1 = -A1/DIV, c0 = -A2/DIV. Jury: |c0| < 1 and |c1| < 1 + c0,
  // multiplied through by |DIV| so that everything stays in integers.
  const long long d = std::llabs(static_cast<long long>(p.div));
  const long long s = p.div > 0 ? 1 : -1;
  const long long a1 = static_cast<long long>(p.a1), a2 = static_cast<long long>(p.a2);
  return std::llabs(a2) < d && std::llabs(a1) < d - s * a2;
}

void require_stable(const BiquadParams& params, const char* owner) {
  const bool stable = std::visit([](const auto& p) { return is_stable(p); }, params);
  if (stable) return;
  const auto r = std::visit([](const auto& p) { return poles(p); }, params);
  throw std::invalid_argument(std::string(owner) + ": the poles have |z| = " + format_value(std::abs(r.first)) +
                              " and " + format_value(std::abs(r.second)) +
                              "; a biquad needs both strictly inside the unit circle (|z| < 1), otherwise it is "
                              "unstable or marginally stable");
}

void Biquad::set_params(const BiquadParams& params) {
  if (const auto* q = std::get_if<AdlinkBiquadParams>(&params)) {
    n0_ = q->b0;
    n1_ = q->b1;
    n2_ = q->b2;
    f1_ = q->a1;
    f2_ = q->a2;
    div_ = q->div;
  } else {
    const auto& f = std::get<FloatBiquadParams>(params);
    n0_ = f.b0;
    n1_ = f.b1;
    n2_ = f.b2;
    f1_ = -f.a1;
    f2_ = -f.a2;
    div_ = 1.0;
  }
  bypass_ = n0_ == 1.0 && div_ == 1.0 && n1_ == 0.0 && n2_ == 0.0 && f1_ == 0.0 && f2_ == 0.0;
}

}  // namespace servobench::control
