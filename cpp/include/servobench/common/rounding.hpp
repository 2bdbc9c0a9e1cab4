// Rounding to whole numbers without a library call, bit-identical to std::floor and std::nearbyint.
//
// The baseline x86-64 build (SSE2, no SSE4.1 roundsd) turns std::floor / std::nearbyint into calls into libm;
// these inline forms give the same double for every input -- signed zeros, halves, |x| >= 2^52 (already whole),
// infinities and NaN included -- in the default rounding mode (round to nearest, ties to even), which the
// simulator never changes:
//   nearbyint(x) = sign(x) * ((|x| + 2^52) - 2^52)    for |x| < 2^52 (the addition rounds to a whole number)
//   floor(x)     = r - 1 if r > x else r,  r = nearbyint(x)
#pragma once

#include <cmath>

namespace servobench {

inline double nearbyint_inline(double x) {
  constexpr double kTwo52 = 4503599627370496.0;  // 2^52: above it every double is whole
  const double a = std::fabs(x);                 // fabs/copysign are bit operations, inlined
  if (!(a < kTwo52)) return x;                   // whole already, inf or NaN
  return std::copysign((a + kTwo52) - kTwo52, x);  // IEEE order kept: no -ffast-math in this build
}

inline double floor_inline(double x) {
  const double r = nearbyint_inline(x);
  return r > x ? std::copysign(r - 1.0, x) : r;
}

}  // namespace servobench
