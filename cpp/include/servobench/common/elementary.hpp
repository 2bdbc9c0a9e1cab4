// sin and exp without a library call, for the tick (decision FV22): the plant's disturbance torques (cogging and
// unbalance, sin) and the Stribeck curve of its dry friction (exp), in machine/powertrain.cpp, plant/dry_friction.hpp
// and the fused tick's machine/powertrain_local.hpp.
//
// libm's functions are calls: inside the fused tick each costs its own instructions plus the spill of every live
// vector register around the call (the x86-64 System V ABI saves none of them), and issue 22 asks for a hot loop
// free of library calls. These are the classic fdlibm algorithms in FreeBSD msun's form, whose error is below 1 ulp:
//   sin: Cody-Waite reduction by pi/2 in up to three 33-bit pieces (e_rem_pio2.c's medium range), then the degree-13
//        sine and degree-14 cosine kernels on the reduced pair (k_sin.c, k_cos.c);
//   exp: reduction by ln 2 in two pieces, a degree-5 rational remainder, the power of two put into the exponent
//        (e_exp.c).
// Constants are hexadecimal doubles (their fdlibm hex words; tests/cpp/test_elementary.cpp checks the splits of pi/2
// and ln 2 and the results against long double). Plain double arithmetic in a fixed order (no FMA contraction: the
// build is ISO C++, and axis_fused.cpp adds -ffp-contract=off; CMakeLists.txt), so every kernel gives the same double.
// Beyond |x| >= 2^20 pi/2 (about 1.65e6 rad) and for inf/NaN it returns std::sin(x).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "servobench/common/rounding.hpp"

namespace servobench {

namespace elementary_detail {
// pi/2 = kPio2_1 + kPio2_2 + kPio2_3 + kPio2_3t, each piece 33 significant bits (kPio2_it: the rest after piece i).
constexpr double kInvPio2 = 0x1.45f306dc9c883p-1;  // 2/pi
constexpr double kPio2_1 = 0x1.921fb544p+0, kPio2_1t = 0x1.0b4611a626331p-34;
constexpr double kPio2_2 = 0x1.0b4611a6p-34, kPio2_2t = 0x1.3198a2e037073p-69;
constexpr double kPio2_3 = 0x1.3198a2ep-69, kPio2_3t = 0x1.b839a252049c1p-104;
// sin(x) ~ x + S1 x^3 + ... + S6 x^13 and cos(x) ~ 1 - x^2/2 + C1 x^4 + ... + C6 x^14 on |x| <= pi/4.
constexpr double kS1 = -0x1.5555555555549p-3, kS2 = 0x1.111111110f8a6p-7, kS3 = -0x1.a01a019c161d5p-13,
                 kS4 = 0x1.71de357b1fe7dp-19, kS5 = -0x1.ae5e68a2b9cebp-26, kS6 = 0x1.5d93a5acfd57cp-33;
constexpr double kC1 = 0x1.555555555554cp-5, kC2 = -0x1.6c16c16c15177p-10, kC3 = 0x1.a01a019cb1590p-16,
                 kC4 = -0x1.27e4f809c52adp-22, kC5 = 0x1.1ee9ebdb4b1c4p-29, kC6 = -0x1.8fae9be8838d4p-37;

inline std::uint32_t high_word(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return static_cast<std::uint32_t>(b >> 32);
}

// sin(x + y) for |x + y| <= pi/4, y the tail of the reduced argument (tail0: y = 0).
inline double kernel_sin(double x, double y, bool tail0) {
  const double z = x * x, w = z * z;
  const double r = kS2 + z * (kS3 + z * kS4) + z * w * (kS5 + z * kS6);
  const double v = z * x;
  if (tail0) return x + v * (kS1 + z * r);
  return x - ((z * (0.5 * y - v * r) - y) - v * kS1);
}

// cos(x + y) for |x + y| <= pi/4.
inline double kernel_cos(double x, double y) {
  const double z = x * x, w = z * z;
  const double r = z * (kC1 + z * (kC2 + z * kC3)) + w * w * (kC4 + z * (kC5 + z * kC6));
  const double hz = 0.5 * z;
  const double c = 1.0 - hz;
  return c + (((1.0 - c) - hz) + (z * r - x * y));
}
// exp: ln 2 = kLn2Hi + kLn2Lo (kLn2Hi with 32 significant bits: k kLn2Hi is exact for |k| < 2^21); on the reduced
// r, c = r - r^2 (P1 + r^2 (P2 + ... + r^2 P5)) and exp(r) = 1 + r + r c / (2 - c), as e_exp.c writes it.
constexpr double kInvLn2 = 0x1.71547652b82fep+0, kLn2Hi = 0x1.62e42feep-1, kLn2Lo = 0x1.a39ef35793c76p-33;
constexpr double kP1 = 0x1.555555555553ep-3, kP2 = -0x1.6c16c16bebd93p-9, kP3 = 0x1.1566aaf25de2cp-14,
                 kP4 = -0x1.bbd41c5d26bf1p-20, kP5 = 0x1.6376972bea4d0p-25;
}  // namespace elementary_detail

// sin(x), x in rad; error below 1 ulp. No library call for |x| < 2^20 pi/2.
inline double sin_inline(double x) {
  using namespace elementary_detail;
  const std::uint32_t ix = high_word(x) & 0x7fffffffu;
  if (ix <= 0x3fe921fbu) {                 // |x| <~ pi/4: no reduction
    if (ix < 0x3e500000u) return x;        // |x| < 2^-26: sin x = x to the last bit
    return kernel_sin(x, 0.0, true);
  }
  if (ix >= 0x413921fbu) return std::sin(x);  // |x| >~ 2^20 pi/2, inf, NaN: libm (never in a realistic tick)
  // x = n pi/2 + (y0 + y1): n the nearest whole number to x 2/pi (ties to even), the pieces of pi/2 times n exact
  // (n < 2^20, 33-bit pieces), further pieces while the reduction cancels.
  const double fn = nearbyint_inline(x * kInvPio2);
  const int n = static_cast<int>(fn);
  double r = x - fn * kPio2_1;
  double w = fn * kPio2_1t;  // good to 85 bits
  double y0 = r - w;
  const int j = static_cast<int>(ix >> 20);
  if (j - static_cast<int>((high_word(y0) >> 20) & 0x7ff) > 16) {  // cancelled more than 16 bits: 118 bits
    double t = r;
    w = fn * kPio2_2;
    r = t - w;
    w = fn * kPio2_2t - ((t - r) - w);
    y0 = r - w;
    if (j - static_cast<int>((high_word(y0) >> 20) & 0x7ff) > 49) {  // 151 bits: covers every double
      t = r;
      w = fn * kPio2_3;
      r = t - w;
      w = fn * kPio2_3t - ((t - r) - w);
      y0 = r - w;
    }
  }
  const double y1 = (r - y0) - w;
  switch (n & 3) {
    case 0: return kernel_sin(y0, y1, false);
    case 1: return kernel_cos(y0, y1);
    case 2: return -kernel_sin(y0, y1, false);
    default: return -kernel_cos(y0, y1);
  }
}

// e^x; error below 1 ulp. No library call for |x| <= 708 (results 3.3e-308 .. 3.0e307, all normal).
inline double exp_inline(double x) {
  using namespace elementary_detail;
  if (!(std::fabs(x) <= 708.0)) return std::exp(x);  // overflow, subnormal results, inf, NaN: libm
  const std::uint32_t hx = high_word(x) & 0x7fffffffu;
  const bool neg = x < 0.0;
  double hi = 0.0, lo = 0.0;
  int k = 0;
  if (hx > 0x3fd62e42u) {    // |x| > ln2 / 2: x = k ln2 + (hi - lo)
    if (hx < 0x3ff0a2b2u) {  // |x| < 1.5 ln2: k = +-1
      hi = neg ? x + kLn2Hi : x - kLn2Hi;
      lo = neg ? -kLn2Lo : kLn2Lo;
      k = neg ? -1 : 1;
    } else {
      k = static_cast<int>(kInvLn2 * x + (neg ? -0.5 : 0.5));
      const double t = k;
      hi = x - t * kLn2Hi;  // exact
      lo = t * kLn2Lo;
    }
    x = hi - lo;
  } else if (hx < 0x3e300000u) {  // |x| < 2^-28: 1 + x to the last bit
    return 1.0 + x;
  }
  const double t = x * x;
  const double c = x - t * (kP1 + t * (kP2 + t * (kP3 + t * (kP4 + t * kP5))));
  if (k == 0) return 1.0 - ((x * c) / (c - 2.0) - x);
  const double y = 1.0 - ((lo - (x * c) / (2.0 - c)) - hi);
  // y 2^k: k added to y's exponent (|k| <= 1021 here, so the result is a normal double).
  std::uint64_t b;
  std::memcpy(&b, &y, sizeof b);
  b += static_cast<std::uint64_t>(static_cast<std::int64_t>(k)) << 52;
  double r;
  std::memcpy(&r, &b, sizeof r);
  return r;
}

}  // namespace servobench
