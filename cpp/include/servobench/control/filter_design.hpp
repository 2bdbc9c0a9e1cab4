// Filter design: analogue prototypes mapped by the bilinear transform to a floating-point biquad, and the
// quantisation of a biquad to the ADLINK card's int16 integers (adlink.md §3.3-3.6; seed 004 L1913-1968).
//
// The manual's worked integers (low-pass L1919, notch L1948) are reproduced exactly by: the analogue prototype,
// the bilinear transform s = (2/Ts)(z-1)/(z+1) WITHOUT pre-warping, and `quantize_adlink` (docs/decisions.md F2-F5).
// Every function validates its arguments (std::invalid_argument naming the function, the parameter, the value and
// the allowed range) and refuses designs whose poles are not strictly inside the unit circle.
#pragma once

#include <array>

#include "servobench/control/biquad.hpp"

namespace servobench::control {

// H(s) = (num[0] s^2 + num[1] s + num[2]) / (den[0] s^2 + den[1] s + den[2]) -> bilinear transform at sample time
// ts (s). prewarp_hz > 0 pre-warps so that the response at prewarp_hz is exact (c = w/tan(w ts/2) instead of 2/ts);
// 0 = no pre-warping. The denominator must not be identically zero, its degree must be >= the numerator's, and the
// digital poles must lie strictly inside the unit circle.
FloatBiquadParams from_s(const std::array<double, 3>& num, const std::array<double, 3>& den, double ts,
                         double prewarp_hz = 0.0);

// Second-order low-pass H(s) = wc^2 / (s^2 + 2 zeta wc s + wc^2), wc = 2 pi cutoff_hz. zeta > 0 (default 0.707, the
// value that reproduces the manual's integers; exactly 1/sqrt(2) is 1 LSB off). prewarp: pre-warp at cutoff_hz.
FloatBiquadParams lowpass(double cutoff_hz, double ts, double zeta = 0.707, bool prewarp = false);

// Notch H(s) = (s^2 + w0^2) / (s^2 + (w0/q) s + w0^2), w0 = 2 pi center_hz, q > 0 (q = centre / -3 dB bandwidth).
FloatBiquadParams notch(double center_hz, double q, double ts, bool prewarp = false);

// Notch from its -3 dB edges: q = center_hz / (high_hz - low_hz) (the standard definition; docs/decisions.md F4 notes
// that the manual's example band 95..105 Hz does NOT produce its printed integers, which imply q ~ 30).
// Requires 0 < low_hz < center_hz < high_hz < Nyquist.
FloatBiquadParams notch_band(double center_hz, double low_hz, double high_hz, double ts, bool prewarp = false);
double notch_band_q(double center_hz, double low_hz, double high_hz, double ts);

// First-order lead/lag H(s) = gain * (1 + s/wz) / (1 + s/wp), wz = 2 pi zero_hz, wp = 2 pi pole_hz; DC gain `gain`
// (> 0). zero_hz < pole_hz is a lead (phase advance, max at sqrt(zero_hz*pole_hz)), zero_hz > pole_hz a lag.
// prewarp: pre-warp at sqrt(zero_hz*pole_hz).
FloatBiquadParams lead_lag(double zero_hz, double pole_hz, double ts, double gain = 1.0, bool prewarp = false);

// Quantisation to the card's integers (adlink.md §3.6): with v = (b0, b1, b2, A1 = -a1, A2 = -a2) and
// m = max |v|: DIV = trunc(32767 / m) (capped at 32767 when m < 1), every v with |v| == m becomes +-32767 (when not
// capped), the others trunc(v * DIV) (toward zero). Refuses m > 32767 (DIV would be 0), non-finite input, an
// all-zero quantised numerator, and quantised poles on or outside the unit circle.
AdlinkBiquadParams quantize_adlink(const FloatBiquadParams& f);

}  // namespace servobench::control
