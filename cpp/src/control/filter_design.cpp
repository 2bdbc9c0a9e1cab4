#include "servobench/control/filter_design.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::control {

namespace {

constexpr double kPi = 3.14159265358979323846;

void check_sample_time(const char* owner, double ts) {
  if (!std::isfinite(ts)) throw_invalid(owner, "sample_time_s", ts, "is not a finite number; it must be > 0 s and <= 1 s");
  if (!(ts > 0.0) || ts > 1.0) throw_invalid(owner, "sample_time_s", ts, "must be > 0 s and <= 1 s");
}

// 0 < f < Nyquist = 1/(2 ts).
void check_frequency(const char* owner, const char* field, double f, double ts) {
  const double nyquist = 0.5 / ts;
  const std::string range =
      "0 < f < " + format_value(nyquist) + " Hz (the Nyquist frequency 1/(2*sample_time_s))";
  if (!std::isfinite(f)) throw_invalid(owner, field, f, "is not a finite number; the allowed range is " + range);
  if (!(f > 0.0) || !(f < nyquist)) throw_invalid(owner, field, f, "is outside the allowed range " + range);
}

// Bilinear constant c: s = c (z-1)/(z+1); c = 2/ts, or w/tan(w ts/2) pre-warped at w = 2 pi prewarp_hz.
double bilinear_c(double ts, double prewarp_hz) {
  if (prewarp_hz == 0.0) return 2.0 / ts;
  const double w = 2.0 * kPi * prewarp_hz;
  return w / std::tan(0.5 * w * ts);
}

int degree(const std::array<double, 3>& p) {
  if (p[0] != 0.0) return 2;
  if (p[1] != 0.0) return 1;
  if (p[2] != 0.0) return 0;
  return -1;
}

double clean(double v) { return v + 0.0; }  // -0 -> +0

}  // namespace

FloatBiquadParams from_s(const std::array<double, 3>& num, const std::array<double, 3>& den, double ts,
                         double prewarp_hz) {
  const char* o = "from_s";
  check_sample_time(o, ts);
  static const char* const num_names[3] = {"num[0]", "num[1]", "num[2]"};
  static const char* const den_names[3] = {"den[0]", "den[1]", "den[2]"};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(num[i])) throw_invalid(o, num_names[i], num[i], "is not a finite number");
    if (!std::isfinite(den[i])) throw_invalid(o, den_names[i], den[i], "is not a finite number");
  }
  if (!std::isfinite(prewarp_hz)) throw_invalid(o, "prewarp_hz", prewarp_hz, "is not a finite number; 0 = no pre-warping");
  if (prewarp_hz != 0.0) check_frequency(o, "prewarp_hz", prewarp_hz, ts);
  const int dn = degree(den), nn = degree(num);
  if (dn < 0) throw std::invalid_argument("from_s.den = [0, 0, 0]: the denominator is identically zero");
  if (nn > dn)
    throw std::invalid_argument("from_s.num: numerator degree " + std::to_string(nn) + " > denominator degree " +
                                std::to_string(dn) +
                                " (improper transfer function: the bilinear transform would put a pole at z = -1)");
  const double c = bilinear_c(ts, prewarp_hz);
  FloatBiquadParams f;
  f.sample_time_s = ts;
  // Multiply N(s) and D(s), with s = c (z-1)/(z+1), by (z+1)^dn and write in powers of z^-1.
  double nz[3] = {0, 0, 0}, dz[3] = {0, 0, 0};
  if (dn == 2) {
    const double c2 = c * c;
    nz[0] = num[0] * c2 + num[1] * c + num[2];
    nz[1] = 2.0 * (num[2] - num[0] * c2);
    nz[2] = num[0] * c2 - num[1] * c + num[2];
    dz[0] = den[0] * c2 + den[1] * c + den[2];
    dz[1] = 2.0 * (den[2] - den[0] * c2);
    dz[2] = den[0] * c2 - den[1] * c + den[2];
  } else if (dn == 1) {
    nz[0] = num[1] * c + num[2];
    nz[1] = num[2] - num[1] * c;
    dz[0] = den[1] * c + den[2];
    dz[1] = den[2] - den[1] * c;
  } else {
    nz[0] = num[2];
    dz[0] = den[2];
  }
  if (dz[0] == 0.0)
    throw std::invalid_argument("from_s.den: D(s) has a root at s = c = " + format_value(c) +
                                " rad/s (right half plane), which the bilinear transform maps to z = infinity");
  f.b0 = clean(nz[0] / dz[0]);
  f.b1 = clean(nz[1] / dz[0]);
  f.b2 = clean(nz[2] / dz[0]);
  f.a1 = clean(dz[1] / dz[0]);
  f.a2 = clean(dz[2] / dz[0]);
  f.validate();
  require_stable(f, "from_s.den");
  return f;
}

FloatBiquadParams lowpass(double cutoff_hz, double ts, double zeta, bool prewarp) {
  const char* o = "lowpass";
  check_sample_time(o, ts);
  check_frequency(o, "cutoff_hz", cutoff_hz, ts);
  check_positive(o, "zeta", zeta);
  const double w = 2.0 * kPi * cutoff_hz;
  return from_s({0.0, 0.0, w * w}, {1.0, 2.0 * zeta * w, w * w}, ts, prewarp ? cutoff_hz : 0.0);
}

FloatBiquadParams notch(double center_hz, double q, double ts, bool prewarp) {
  const char* o = "notch";
  check_sample_time(o, ts);
  check_frequency(o, "center_hz", center_hz, ts);
  check_positive(o, "q", q);
  const double w = 2.0 * kPi * center_hz;
  return from_s({1.0, 0.0, w * w}, {1.0, w / q, w * w}, ts, prewarp ? center_hz : 0.0);
}

double notch_band_q(double center_hz, double low_hz, double high_hz, double ts) {
  const char* o = "notch";
  check_sample_time(o, ts);
  check_frequency(o, "center_hz", center_hz, ts);
  check_frequency(o, "low_hz", low_hz, ts);
  check_frequency(o, "high_hz", high_hz, ts);
  if (!(low_hz < center_hz))
    throw_invalid(o, "low_hz", low_hz, "must be below center_hz = " + format_value(center_hz) + " Hz");
  if (!(high_hz > center_hz))
    throw_invalid(o, "high_hz", high_hz, "must be above center_hz = " + format_value(center_hz) + " Hz");
  return center_hz / (high_hz - low_hz);
}

FloatBiquadParams notch_band(double center_hz, double low_hz, double high_hz, double ts, bool prewarp) {
  return notch(center_hz, notch_band_q(center_hz, low_hz, high_hz, ts), ts, prewarp);
}

FloatBiquadParams lead_lag(double zero_hz, double pole_hz, double ts, double gain, bool prewarp) {
  const char* o = "lead_lag";
  check_sample_time(o, ts);
  check_frequency(o, "zero_hz", zero_hz, ts);
  check_frequency(o, "pole_hz", pole_hz, ts);
  check_positive(o, "gain", gain);
  const double wz = 2.0 * kPi * zero_hz, wp = 2.0 * kPi * pole_hz;
  return from_s({0.0, gain / wz, gain}, {0.0, 1.0 / wp, 1.0}, ts, prewarp ? std::sqrt(zero_hz * pole_hz) : 0.0);
}

AdlinkBiquadParams quantize_adlink(const FloatBiquadParams& f) {
  f.validate();
  require_stable(f, "to_adlink: the floating-point biquad");
  const double v[5] = {f.b0, f.b1, f.b2, -f.a1, -f.a2};  // B0, B1, B2, A1, A2 (manual sign: feedback added)
  const double original[5] = {f.b0, f.b1, f.b2, f.a1, f.a2};
  static const char* const names[5] = {"b0", "b1", "b2", "a1", "a2"};
  double m = 0.0;
  int imax = 0;
  for (int i = 0; i < 5; ++i) {
    if (std::fabs(v[i]) > m) {
      m = std::fabs(v[i]);
      imax = i;
    }
  }
  if (m > 32767.0)
    throw_invalid("to_adlink", names[imax], original[imax],
                  "is too large to quantise: the largest |coefficient| must be <= 32767 so that "
                  "DIV = trunc(32767/max|coef|) >= 1");
  const double ratio = 32767.0 / m;
  const bool capped = ratio > 32767.0;  // m < 1: DIV cannot exceed the int16 maximum
  const double div = capped ? 32767.0 : std::trunc(ratio);
  double q[5];
  for (int i = 0; i < 5; ++i) {
    q[i] = (!capped && std::fabs(v[i]) == m) ? std::copysign(32767.0, v[i]) : std::trunc(v[i] * div);
    q[i] = clean(q[i]);
  }
  AdlinkBiquadParams p;
  p.b0 = q[0];
  p.b1 = q[1];
  p.b2 = q[2];
  p.a1 = q[3];
  p.a2 = q[4];
  p.div = div;
  p.sample_time_s = f.sample_time_s;
  p.validate();
  if (p.b0 == 0.0 && p.b1 == 0.0 && p.b2 == 0.0)
    throw std::invalid_argument(
        "to_adlink: b0, b1, b2 = " + format_value(f.b0) + ", " + format_value(f.b1) + ", " + format_value(f.b2) +
        " all truncate to 0 with DIV = " + format_value(div) +
        ": the numerator is too small next to the largest coefficient for 16-bit integers (for a low-pass: "
        "cutoff_hz too far below the sample rate)");
  if (!is_stable(p)) {
    const auto r = poles(p);
    throw std::invalid_argument(
        "to_adlink: the quantised poles (A1 = " + format_value(p.a1) + ", A2 = " + format_value(p.a2) +
        ", DIV = " + format_value(div) + ") have |z| = " + format_value(std::abs(r.first)) + " and " +
        format_value(std::abs(r.second)) +
        ", on or outside the unit circle: 16-bit coefficients cannot hold poles this close to |z| = 1 "
        "(raise cutoff_hz/center_hz, lower q, or lengthen sample_time_s)");
  }
  return p;
}

}  // namespace servobench::control
