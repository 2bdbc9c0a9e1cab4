// GT servo filter against hand-computed vectors.
// Law: seed 000 (GT manual) L801-803; variables Table 3-5 L807-817; ranges/defaults Table 3-4 L784-793;
// ILmt = 0 clears the sum L819; output +-2^15 <-> +-10 V and MtrLmt default 32767 L829.
#include <gtest/gtest.h>

#include <stdexcept>

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
