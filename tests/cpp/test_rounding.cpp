// The inline rounding of the servo tick (common/rounding.hpp) gives the same double as libm for every input class:
// signed zeros, halves (ties to even), the 2^52 boundary, huge values, infinities, NaN and random values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "servobench/common/rounding.hpp"

namespace {

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST(Rounding, EdgeCasesMatchLibm) {
  const double inf = std::numeric_limits<double>::infinity();
  const double two52 = 4503599627370496.0;
  const std::vector<double> xs = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                                  1.0, -1.0, 0.3, -0.3, 0.7, -0.7, two52 - 0.5, -(two52 - 0.5), two52, -two52,
                                  two52 + 1, 1e300, -1e300, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                                  4503599627370495.5, -4503599627370495.5, 2251799813685248.5};
  for (double x : xs) {
    EXPECT_TRUE(same_bits(servobench::nearbyint_inline(x), std::nearbyint(x))) << x;
    EXPECT_TRUE(same_bits(servobench::floor_inline(x), std::floor(x))) << x;
  }
}

TEST(Rounding, RandomValuesMatchLibm) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200000; ++k) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 120) - 20);
    const double x = u(rng) * scale;
    ASSERT_TRUE(same_bits(servobench::nearbyint_inline(x), std::nearbyint(x))) << x;
    ASSERT_TRUE(same_bits(servobench::floor_inline(x), std::floor(x))) << x;
    const double h = std::floor(x) + 0.5;  // exact halves
    ASSERT_TRUE(same_bits(servobench::nearbyint_inline(h), std::nearbyint(h))) << h;
    ASSERT_TRUE(same_bits(servobench::floor_inline(h), std::floor(h))) << h;
  }
}
