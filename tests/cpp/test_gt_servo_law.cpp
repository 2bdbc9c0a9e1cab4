// GT servo filter against hand-computed vectors.
// Law: seed 000 (GT manual) L801-803; variables Table 3-5 L807-817; ranges/defaults Table 3-4 L784-793;
// ILmt = 0 clears the sum L819; output +-2^15 <-> +-10 V and MtrLmt default 32767 L829.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "servobench/control/gt_servo_law.hpp"

using servobench::control::GtServoLaw;
using servobench::control::GtServoLawParams;

TEST(GtServoLaw, DefaultsAreTheManuals) {  // Table 3-4, L784-793; MtrLmt L829
  GtServoLawParams p;
  EXPECT_EQ(p.kp, 0);
  EXPECT_EQ(p.ki, 0);
  EXPECT_EQ(p.kd, 0);
  EXPECT_EQ(p.kvff, 0);
  EXPECT_EQ(p.kaff, 0);
  EXPECT_EQ(p.ilmt, 32767);
  EXPECT_EQ(p.bias, 0);
  EXPECT_EQ(p.mtr_lmt, 32767);
  EXPECT_DOUBLE_EQ(GtServoLawParams::kDefaultPeriodS, 200e-6);  // L578-580
  EXPECT_DOUBLE_EQ(GtServoLawParams::kMinPeriodS, 48e-6);
  EXPECT_DOUBLE_EQ(GtServoLawParams::kMaxPeriodS, 1966.08e-6);
}

TEST(GtServoLaw, EachTermByHand) {  // U_n = Kp*E + Kd*(E-E_prev) + Ki*SumE/256 + Kvff*V + Kaff*A + B, L801-803
  GtServoLawParams p;
  p.kp = 10;
  p.ki = 512;
  p.kd = 100;
  p.kvff = 3;
  p.kaff = 7;
  p.bias = -20;
  GtServoLaw law(p);
  // tick 0: target 5, actual 0 -> E = 5; SumE = 5; V = 2, A = 1
  auto t = law.step(5, 0, 2, 1);
  EXPECT_DOUBLE_EQ(t.p, 50);              // 10*5
  EXPECT_DOUBLE_EQ(t.d, 500);             // 100*(5-0)
  EXPECT_DOUBLE_EQ(t.i, 10);              // 512*5/256
  EXPECT_DOUBLE_EQ(t.vff, 6);             // 3*2
  EXPECT_DOUBLE_EQ(t.aff, 7);             // 7*1
  EXPECT_DOUBLE_EQ(t.bias, -20);
  EXPECT_DOUBLE_EQ(t.total, 50 + 500 + 10 + 6 + 7 - 20);
  // tick 1: target 8, actual 6 -> E = 2; SumE = 7
  t = law.step(8, 6, 3, 1);
  EXPECT_DOUBLE_EQ(t.p, 20);
  EXPECT_DOUBLE_EQ(t.d, 100 * (2 - 5));   // backward difference of the error
  EXPECT_DOUBLE_EQ(t.i, 512.0 * 7 / 256);  // the sum includes E_n
  EXPECT_DOUBLE_EQ(t.vff, 9);
  EXPECT_DOUBLE_EQ(t.total, 20 - 300 + 14 + 9 + 7 - 20);
  EXPECT_DOUBLE_EQ(law.error_sum(), 7);
}

TEST(GtServoLaw, IntegralLimitClampsTheSumAndZeroClearsIt) {  // L819, Table 3-4 "Lim"
  GtServoLawParams p;
  p.ki = 256;
  p.ilmt = 100;
  GtServoLaw law(p);
  for (int k = 0; k < 30; ++k) law.step(10, 0, 0, 0);
  EXPECT_DOUBLE_EQ(law.error_sum(), 100);               // clamped at +ILmt
  EXPECT_DOUBLE_EQ(law.step(10, 0, 0, 0).i, 100);        // Ki*SumE/256 = 256*100/256
  for (int k = 0; k < 30; ++k) law.step(-10, 0, 0, 0);
  EXPECT_DOUBLE_EQ(law.error_sum(), -100);              // and at -ILmt
  // The manual's bumpless recipe: ILmt = 0 clears the accumulated value, then Ki and ILmt are set again.
  p.ilmt = 0;
  law.set_params(p);
  EXPECT_DOUBLE_EQ(law.error_sum(), 0);
  EXPECT_DOUBLE_EQ(law.step(10, 0, 0, 0).i, 0);          // stays cleared while ILmt = 0
  p.ilmt = 32767;
  law.set_params(p);
  EXPECT_DOUBLE_EQ(law.step(3, 0, 0, 0).i, 3);           // restarts from zero: 256*3/256
}

TEST(GtServoLaw, OutputClampedToMtrLmt) {  // L829: the valid output scope is +-MtrLmt
  GtServoLawParams p;
  p.kp = 1000;
  p.mtr_lmt = 20000;
  GtServoLaw law(p);
  auto t = law.step(100, 0, 0, 0);
  EXPECT_DOUBLE_EQ(t.p, 100000);
  EXPECT_DOUBLE_EQ(t.total, 20000);
  t = law.step(-100, 0, 0, 0);
  EXPECT_DOUBLE_EQ(t.total, -20000);
  EXPECT_DOUBLE_EQ(GtServoLaw::counts_to_volts(32767), 10.0);  // full scale
}

TEST(GtServoLaw, RejectsOutOfRangeParameters) {  // Table 3-4 ranges
  auto bad = [](auto mutate) {
    GtServoLawParams p;
    mutate(p);
    EXPECT_THROW(GtServoLaw{p}, std::invalid_argument);
  };
  bad([](GtServoLawParams& p) { p.kp = 32768; });
  bad([](GtServoLawParams& p) { p.kp = -1; });
  bad([](GtServoLawParams& p) { p.ki = 1.5; });
  bad([](GtServoLawParams& p) { p.kd = 40000; });
  bad([](GtServoLawParams& p) { p.kvff = -3; });
  bad([](GtServoLawParams& p) { p.kaff = 1e9; });
  bad([](GtServoLawParams& p) { p.ilmt = 32768; });
  bad([](GtServoLawParams& p) { p.bias = -32769; });
  bad([](GtServoLawParams& p) { p.bias = 32768; });
  bad([](GtServoLawParams& p) { p.mtr_lmt = 32768; });
  try {
    GtServoLawParams p;
    p.kp = 40000;
    GtServoLaw law(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "GtServoLaw.kp = 40000 is outside the allowed range 0..32767 (GT manual Table 3-4)");
  }
}

// Decision FV26: step() forms the integral term as (Ki/256)*SumE, which must be the manual's Ki*SumE/256 to the last
// bit: for integer and fractional gains, gains whose Ki/256 is not exact (below 2^-1014), sums of every magnitude
// down to the subnormals and the results near the smallest normal double where the folded form is not taken.
TEST(GtServoLaw, IntegralTermIsKiTimesSumOver256ToTheLastBit) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mant(1.0, 2.0), exp2(-1080.0, 14.0);
  std::vector<double> sums{0.0, -0.0, 1.0, -3.0, 32767.0, 0x1p-1074, 0x1p-1060, 0x1.fffffffffffffp-1022};
  for (int k = 0; k < 4000; ++k) sums.push_back((k % 2 ? -1 : 1) * std::ldexp(mant(rng), static_cast<int>(exp2(rng))));
  for (double ki : {0.0, 1.0, 40.0, 32767.0, 0.3, 1234.5678, 1e-310, 3 * 0x1p-1016, 0x1.23456789abcdep-1013}) {
    GtServoLawParams p;
    p.fractional_gains = true;
    p.ki = ki;
    for (double e : sums) {
      GtServoLaw law(p);  // the first tick's sum is its error (0.0 + e)
      const double got = law.step(e, 0.0, 0.0, 0.0).i;
      volatile double kv = ki, ev = law.error_sum();  // the manual's form, evaluated at run time
      const double want = kv * ev * (1.0 / 256.0);
      EXPECT_EQ(0, std::memcmp(&got, &want, sizeof got))
          << "ki " << ki << " sum " << e << ": " << got << " vs " << want;
    }
  }
}
