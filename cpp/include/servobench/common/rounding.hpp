// Rounding to whole numbers without a library call, bit-identical to std::floor and std::nearbyint.
//
// The baseline x86-64 build (SSE2, no SSE4.1 roundsd) turns std::floor / std::nearbyint into calls into libm;
// these inline forms give the same double for every input -- signed zeros, halves, |x| >= 2^52 (already whole),
// infinities and NaN included -- in the default rounding mode (round to nearest, ties to even), which the
// simulator never changes:
//   nearbyint(x) = sign(x) * ((|x| + 2^52) - 2^52)    for |x| < 2^52 (the addition rounds to a whole number)
//   floor(x)     = r - 1 if r > x else r,  r = nearbyint(x)
//
// The fused tick also has an SSE4.1 kernel (machine/axis_fused.cpp, decision SP1): the same loop compiled with
// __attribute__((target("sse4.1"))) and chosen at run time when the CPU has SSE4.1, where `roundsd` rounds in one
// instruction. Its rounding policy is Sse41Rounding; everything else stays on PortableRounding. Both give the same
// double for every input (roundsd is exact, as is the inline form above), so the kernel changes the speed only.
#pragma once

#include <cmath>

// Whether the build has the fused tick's SSE4.1 kernel: x86 with GCC or Clang (function target attributes and
// __builtin_cpu_supports); -DSERVOBENCH_NO_SSE41_KERNEL leaves it out.
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(SERVOBENCH_NO_SSE41_KERNEL)
#define SERVOBENCH_SSE41_KERNEL 1
#else
#define SERVOBENCH_SSE41_KERNEL 0
#endif

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

// Rounding policies for code compiled once per kernel (Encoder::read, Dac::convert take one as a template
// argument; the default is the portable one).
struct PortableRounding {
  static double floor(double x) { return floor_inline(x); }
  static double nearbyint(double x) { return nearbyint_inline(x); }
};

// __builtin_floor / __builtin_nearbyint: one `roundsd` once inlined into a function compiled for SSE4.1 (the fused
// tick's SSE4.1 kernel); anywhere else they are the libm calls, with the same results.
struct Sse41Rounding {
  static double floor(double x) { return __builtin_floor(x); }
  static double nearbyint(double x) { return __builtin_nearbyint(x); }
};

}  // namespace servobench
