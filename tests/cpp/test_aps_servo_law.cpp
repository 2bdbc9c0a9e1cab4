// ADLINK servo law against hand-computed vectors.
// Law: seed 004 (ADLINK manual) L1723-1731; gain shift text and worked example L1733; parameter table
// L1746-1762.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "servobench/control/aps_servo_law.hpp"

using servobench::control::ApsServoLaw;
using servobench::control::ApsServoLawParams;

TEST(ApsServoLaw, DefaultsAreTheManuals) {  // L1746-1762
  ApsServoLawParams p;
  EXPECT_EQ(p.kp_shift, -5);
  EXPECT_EQ(p.ki_shift, -15);
  EXPECT_EQ(p.kd_shift, 0);
  EXPECT_EQ(p.kvff_shift, 0);
  EXPECT_EQ(p.kaff_shift, 0);
  EXPECT_EQ(p.pid_shift, -5);
  EXPECT_EQ(p.integral_limit, 2147483647.0);
  EXPECT_EQ(p.v_bias, 0.0);
  EXPECT_EQ(p.v_limit, 10.0);
  EXPECT_FALSE(p.v_inverse);
  EXPECT_DOUBLE_EQ(ApsServoLawParams::kDefaultPeriodS, 250e-6);  // L1733
}

// L1733: "KP gain to 100, KP shift to 2, and PID shift to 3 to get a equivalent KP of 100 x 2^2 x 3 = 3200".
// 100 x 2^2 x 3 is 1200; only 100 x 2^2 x 2^3 is 3200, and the shifts are "2^n folds" (L1753-1758), so the
// printed "x 3" is read as x 2^3: K_eff = K * 2^(K_SHIFT + PID_SHIFT).
TEST(ApsServoLaw, GainShiftWorkedExampleGives3200) {
  ApsServoLawParams p;
  p.kp = 100;
  p.kp_shift = 2;
  p.pid_shift = 3;
  EXPECT_DOUBLE_EQ(p.kp_eff(), 3200.0);
  ApsServoLaw law(p);
  EXPECT_DOUBLE_EQ(law.step(1, 0, 0, 0).p, 3200.0);  // E = 1 pulse -> 3200 counts
}

TEST(ApsServoLaw, EachTermByHand) {  // U = 2^PID*(KP*2^KPS*E + KI*2^KIS*Sum + KD*2^KDS*dE + KVFF*.. + KAFF*..)
  ApsServoLawParams p;
  p.kp = 64;    p.kp_shift = 0;
  p.ki = 1024;  p.ki_shift = -8;
  p.kd = 3;     p.kd_shift = 2;
  p.kvff = 5;   p.kvff_shift = 1;
  p.kaff = 9;   p.kaff_shift = 0;
  p.pid_shift = -1;
  ApsServoLaw law(p);
  // CmdPos 10 -> 13 -> 19, FbkPos 10 -> 11 -> 15. First tick primes the command history (at rest).
  auto t = law.step(10, 10, 0, 0);
  EXPECT_DOUBLE_EQ(t.total, 0.0);
  t = law.step(13, 11, 0, 0);  // E = 2, Sum = 2, dE = 2, CmdVel = 3, CmdAcc = 3
  EXPECT_DOUBLE_EQ(t.p, 0.5 * 64 * 2);
  EXPECT_DOUBLE_EQ(t.i, 0.5 * 1024 / 256.0 * 2);
  EXPECT_DOUBLE_EQ(t.d, 0.5 * 3 * 4 * 2);
  EXPECT_DOUBLE_EQ(t.vff, 0.5 * 5 * 2 * 3);
  EXPECT_DOUBLE_EQ(t.aff, 0.5 * 9 * 3);
  EXPECT_DOUBLE_EQ(t.total, t.p + t.i + t.d + t.vff + t.aff);
  t = law.step(19, 15, 99, 99);  // E = 4, Sum = 6, dE = 2, CmdVel = 6, CmdAcc = 3 (profile args ignored)
  EXPECT_DOUBLE_EQ(t.p, 0.5 * 64 * 4);
  EXPECT_DOUBLE_EQ(t.i, 0.5 * 4 * 6);
  EXPECT_DOUBLE_EQ(t.d, 0.5 * 12 * 2);
  EXPECT_DOUBLE_EQ(t.vff, 0.5 * 10 * 6);
  EXPECT_DOUBLE_EQ(t.aff, 0.5 * 9 * 3);
}

TEST(ApsServoLaw, IntegralLimitClampsTheErrorSum) {  // PRA_INTEGRAL_LIMIT, L1762
  ApsServoLawParams p;
  p.ki = 1;
  p.ki_shift = 0;
  p.pid_shift = 0;
  p.integral_limit = 50;
  ApsServoLaw law(p);
  for (int k = 0; k < 20; ++k) law.step(7, 0, 0, 0);
  EXPECT_DOUBLE_EQ(law.error_sum(), 50);
  for (int k = 0; k < 40; ++k) law.step(-7, 0, 0, 0);
  EXPECT_DOUBLE_EQ(law.error_sum(), -50);
}

TEST(ApsServoLaw, OutputStageBiasLimitInverse) {  // PRA_SERVO_V_BIAS/LIMIT/INVERSE, L1735, L1759-1761
  ApsServoLawParams p;
  p.v_bias = 0.5;
  p.v_limit = 3.0;
  ApsServoLaw law(p);
  EXPECT_NEAR(law.counts_to_volts(3276.7), 1.0 + 0.5, 1e-12);   // 32767 counts = 10 V
  EXPECT_DOUBLE_EQ(law.counts_to_volts(32767), 3.0);            // clamped to +V_LIMIT
  EXPECT_DOUBLE_EQ(law.counts_to_volts(-32767), -3.0);
  p.v_inverse = true;
  law.set_params(p);
  EXPECT_NEAR(law.counts_to_volts(3276.7), -1.5, 1e-12);
}

TEST(ApsServoLaw, RejectsOutOfRangeParameters) {
  auto bad = [](auto mutate) {
    ApsServoLawParams p;
    mutate(p);
    EXPECT_THROW(ApsServoLaw{p}, std::invalid_argument);
  };
  bad([](ApsServoLawParams& p) { p.kp = 65536; });
  bad([](ApsServoLawParams& p) { p.ki = -1; });
  bad([](ApsServoLawParams& p) { p.kd = 0.5; });
  bad([](ApsServoLawParams& p) { p.kvff = 70000; });
  bad([](ApsServoLawParams& p) { p.kaff = NAN; });
  bad([](ApsServoLawParams& p) { p.kp_shift = 32; });
  bad([](ApsServoLawParams& p) { p.ki_shift = -32; });
  bad([](ApsServoLawParams& p) { p.kd_shift = 1.5; });
  bad([](ApsServoLawParams& p) { p.kvff_shift = INFINITY; });
  bad([](ApsServoLawParams& p) { p.kaff_shift = 40; });
  bad([](ApsServoLawParams& p) { p.pid_shift = -40; });
  bad([](ApsServoLawParams& p) { p.integral_limit = 2147483648.0; });
  bad([](ApsServoLawParams& p) { p.v_bias = -0.1; });
  bad([](ApsServoLawParams& p) { p.v_limit = 10.5; });
}
