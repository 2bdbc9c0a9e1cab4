// sin_inline and exp_inline (common/elementary.hpp, decision FV22): the tick's sine (disturbance torques) and
// exponential (Stribeck curve) without a library call. Checked against long double (64-bit significand: 11 bits
// beyond a double) on random and on hard arguments: the error stays below 1 ulp, sin is odd bit for bit, and outside
// their ranges both are libm's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "servobench/common/elementary.hpp"

namespace {

using servobench::exp_inline;
using servobench::sin_inline;

// |got - exact| in units of the last place of the double nearest to exact.
double ulps(double got, long double exact) {
  const double e = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(e), std::numeric_limits<double>::infinity()) - std::fabs(e);
  return static_cast<double>(std::fabs(static_cast<long double>(got) - exact) / ulp);
}

// Low bits of a double's significand that are zero.
int zero_low_bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b &= (std::uint64_t{1} << 52) - 1;
  int n = 0;
  while (n < 52 && !(b & (std::uint64_t{1} << n))) ++n;
  return n;
}

TEST(Sine, PiOverTwoPiecesAreExactAndSumToPiOverTwo) {
  using namespace servobench::elementary_detail;
  // 33 significant bits each (20 low bits zero), so n * piece is exact for |n| < 2^20.
  EXPECT_GE(zero_low_bits(kPio2_1), 20);
  EXPECT_GE(zero_low_bits(kPio2_2), 20);
  EXPECT_GE(zero_low_bits(kPio2_3), 20);
  // Each tail is the rest after its pieces: to long double precision the sums are pi/2.
  const long double half_pi = 1.570796326794896619231321691639751442L;
  EXPECT_NEAR(static_cast<double>((static_cast<long double>(kPio2_1) + kPio2_1t - half_pi) / half_pi), 0.0, 1e-19);
  EXPECT_NEAR(static_cast<double>((static_cast<long double>(kPio2_1) + kPio2_2 + kPio2_2t - half_pi) / half_pi), 0.0,
              1e-19);
  EXPECT_NEAR(static_cast<double>(1.0L / half_pi / kInvPio2 - 1.0L), 0.0, 1.2e-16);  // 2/pi
}

TEST(Sine, BelowOneUlpOnRandomArguments) {
  std::mt19937_64 rng(20261128);
  for (double range : {0.7, 4.0, 100.0, 1e4, 1.6e6}) {
    std::uniform_real_distribution<double> u(-range, range);
    double worst = 0.0;
    constexpr int kN = 200000;
    for (int i = 0; i < kN; ++i) {
      const double x = u(rng);
      const long double ref = sinl(static_cast<long double>(x));
      const double got = sin_inline(x);
      worst = std::max(worst, ulps(got, ref));
    }
    EXPECT_LT(worst, 1.0) << "range " << range;
  }
}

TEST(Sine, BelowOneUlpNearMultiplesOfHalfPi) {
  // The doubles nearest to k pi/2 (the reduction cancels most of their bits: its second and third pieces run) and
  // their neighbours; sin is near 0 or +-1 there.
  const long double half_pi = 1.570796326794896619231321691639751442L;
  double worst = 0.0;
  for (long k = -1048575; k <= 1048575; k += 997) {
    const double x0 = static_cast<double>(half_pi * static_cast<long double>(k));
    double x = x0;
    for (int s = 0; s < 3; ++s, x = std::nextafter(x, DBL_MAX)) {
      if (!(std::fabs(x) < 0x1.921fb54442d18p20)) continue;
      worst = std::max(worst, ulps(sin_inline(x), sinl(static_cast<long double>(x))));
    }
  }
  EXPECT_LT(worst, 1.0);
}

TEST(Sine, OddSmallAndOutsideItsRange) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e5, 1e5);
  for (int i = 0; i < 10000; ++i) {
    const double x = u(rng);
    EXPECT_EQ(sin_inline(-x), -sin_inline(x));
  }
  EXPECT_EQ(sin_inline(1e-9), 1e-9);  // |x| < 2^-26: x itself
  EXPECT_EQ(sin_inline(-0.0), -0.0);
  EXPECT_TRUE(std::signbit(sin_inline(-0.0)));
  for (double x : {2e6, -3.5e9, 1e300}) EXPECT_EQ(sin_inline(x), std::sin(x));
  EXPECT_TRUE(std::isnan(sin_inline(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(sin_inline(std::numeric_limits<double>::quiet_NaN())));
}

TEST(Exp, LnTwoPiecesAreExactAndSumToLnTwo) {
  using namespace servobench::elementary_detail;
  EXPECT_GE(zero_low_bits(kLn2Hi), 21);  // k kLn2Hi exact for |k| <= 1021
  const long double ln2 = 0.693147180559945309417232121458176568L;
  EXPECT_NEAR(static_cast<double>((static_cast<long double>(kLn2Hi) + kLn2Lo - ln2) / ln2), 0.0, 1e-19);
  EXPECT_NEAR(static_cast<double>(1.0L / ln2 / kInvLn2 - 1.0L), 0.0, 1.2e-16);
}

TEST(Exp, BelowOneUlpOnRandomArguments) {
  std::mt19937_64 rng(20261128);
  // The Stribeck curve's exp(-(w/ws)^2) takes -708..0; both signs and every reduction branch are checked.
  for (double range : {1e-6, 0.5, 1.0, 30.0, 708.0}) {
    std::uniform_real_distribution<double> u(-range, range);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
      const double x = u(rng);
      worst = std::max(worst, ulps(exp_inline(x), expl(static_cast<long double>(x))));
    }
    EXPECT_LT(worst, 1.0) << "range " << range;
  }
}

TEST(Exp, EdgesAndOutsideItsRange) {
  EXPECT_EQ(exp_inline(0.0), 1.0);
  EXPECT_EQ(exp_inline(-0.0), 1.0);
  EXPECT_EQ(exp_inline(1e-10), 1.0 + 1e-10);  // |x| < 2^-28: 1 + x
  for (double x : {-708.0, 708.0, 0.5 * 0.6931471805599453, 1.5 * 0.6931471805599453})
    EXPECT_LT(ulps(exp_inline(x), expl(static_cast<long double>(x))), 1.0) << x;
  EXPECT_TRUE(std::isnormal(exp_inline(-708.0)));
  for (double x : {-708.5, -745.0, -800.0, 709.0, 710.0}) EXPECT_EQ(exp_inline(x), std::exp(x)) << x;
  EXPECT_EQ(exp_inline(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isinf(exp_inline(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(exp_inline(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
