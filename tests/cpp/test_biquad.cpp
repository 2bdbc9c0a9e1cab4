// Biquads: the ADLINK integer difference equation (seed 004 L1873-1887), parameters and defaults (L1897-1911),
// the float form, responses, stability, and the arithmetic decision (docs/decisions.md F1: evaluated in double).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

#include "servobench/control/biquad.hpp"

using namespace servobench::control;

namespace {
AdlinkBiquadParams manual_lowpass() {  // L1919
  AdlinkBiquadParams p;
  p.a1 = 32767; p.a2 = -11896; p.b0 = 1794; p.b1 = 3588; p.b2 = 1794; p.div = 28046;
  return p;
}
}  // namespace

TEST(Biquad, DefaultsArePassThrough) {  // L1897-1911, adlink.md T5
  AdlinkBiquadParams p;
  EXPECT_EQ(p.b0, 1);
  EXPECT_EQ(p.div, 1);
  EXPECT_EQ(p.a1, 0);
  EXPECT_EQ(p.a2, 0);
  EXPECT_EQ(p.b1, 0);
  EXPECT_EQ(p.b2, 0);
  Biquad b(p);
  for (double x : {0.0, 1.5, -32767.0, 1e9, 3.25}) EXPECT_EQ(b.step(x), x);
  Biquad f(FloatBiquadParams{});
  for (double x : {0.0, 1.5, -32767.0, 1e9, 3.25}) EXPECT_EQ(f.step(x), x);
}

TEST(Biquad, IntegerFormIsTheManualsEquationInDouble) {
  // R(k) = (B0 X(k) + B1 X(k-1) + B2 X(k-2) + A1 R(k-1) + A2 R(k-2)) / DIV, feedback ADDED, no truncation.
  const AdlinkBiquadParams p = manual_lowpass();
  Biquad b(p);
  std::vector<double> x = {1000, -250, 37, 0, 5, 5, 5, -1, 12345, 0, 0, 0};
  double x1 = 0, x2 = 0, r1 = 0, r2 = 0;
  bool saw_fraction = false;
  for (double xk : x) {
    const double expected = (p.b0 * xk + p.b1 * x1 + p.b2 * x2 + p.a1 * r1 + p.a2 * r2) / p.div;
    const double got = b.step(xk);
    EXPECT_EQ(got, expected);  // bit for bit: the same expression in the same order
    if (got != std::trunc(got)) saw_fraction = true;
    x2 = x1; x1 = xk; r2 = r1; r1 = expected;
  }
  EXPECT_TRUE(saw_fraction);  // the state is not truncated to integers (decision F1)
  // Hand value of the first step: 1794*1000/28046.
  Biquad c(p);
  EXPECT_DOUBLE_EQ(c.step(1000.0), 1794000.0 / 28046.0);
}

TEST(Biquad, FloatFormSubtractsFeedback) {
  FloatBiquadParams f;
  f.b0 = 0.5; f.b1 = 0.25; f.b2 = 0.125; f.a1 = -0.5; f.a2 = 0.25;
  Biquad b(f);
  EXPECT_DOUBLE_EQ(b.step(1.0), 0.5);
  EXPECT_DOUBLE_EQ(b.step(0.0), 0.25 + 0.5 * 0.5);                        // b1 - a1*y1
  EXPECT_DOUBLE_EQ(b.step(0.0), 0.125 + 0.5 * 0.5 - 0.25 * 0.5);          // b2 - a1*y1 - a2*y2
}

TEST(Biquad, IntegerAndFloatFormsAgree) {
  const AdlinkBiquadParams p = manual_lowpass();
  Biquad bi(p), bf(p.to_float());
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double x = 1000.0 * std::sin(0.01 * k) + (k % 7 == 0 ? 300.0 : 0.0);
    worst = std::max(worst, std::fabs(bi.step(x) - bf.step(x)));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(worst, 0.0);  // different rounding, same filter
}

TEST(Biquad, ResetClearsHistorySetParamsKeepsIt) {
  Biquad b(manual_lowpass());
  const double y0 = b.step(100.0);
  b.step(50.0);
  b.reset();
  EXPECT_EQ(b.step(100.0), y0);
  b.set_params(AdlinkBiquadParams{});  // pass-through from now on, history kept but unused by b0 = div = 1
  EXPECT_EQ(b.step(7.0), 7.0);
}

TEST(Biquad, ValidationNamesFieldAndRange) {
  AdlinkBiquadParams p;
  p.div = 0;
  try {
    p.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("AdlinkBiquad.div = 0 is not allowed"), std::string::npos) << e.what();
  }
  p = AdlinkBiquadParams{};
  p.a1 = 32768;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.a1 = -32768;
  EXPECT_NO_THROW(p.validate());
  p.b2 = 0.5;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  FloatBiquadParams f;
  f.a2 = NAN;
  EXPECT_THROW(f.validate(), std::invalid_argument);
}

TEST(Biquad, ResponseOfTheManualsIntegers) {  // adlink.md §3.5, T7 and T9 (derived)
  const double ts = 100e-6;
  const AdlinkBiquadParams lp = manual_lowpass();
  EXPECT_NEAR(std::abs(frequency_response(lp, 0.0, ts)), 7176.0 / 7175.0, 1e-12);  // DC gain (B0+B1+B2)/(DIV-A1-A2)
  EXPECT_NEAR(std::abs(frequency_response(lp, 1200.0, ts)), 0.5328, 5e-5);
  EXPECT_NEAR(std::arg(frequency_response(lp, 1200.0, ts)) * 180 / M_PI, -108.3, 0.05);
  AdlinkBiquadParams nt;
  nt.a1 = 32767; nt.a2 = -16398; nt.b0 = 16415; nt.b1 = -32767; nt.b2 = 16415; nt.div = 16433;
  EXPECT_DOUBLE_EQ(std::abs(frequency_response(nt, 0.0, ts)), 63.0 / 64.0);  // 63/4032... = 63/64
  EXPECT_NEAR(20 * std::log10(std::abs(frequency_response(nt, 100.0, ts))), -2.34, 0.005);
  // Zeros at cos(theta) = 32767/(2*16415): 98.61 Hz, where the integer filter has its null.
  const double f_null = std::acos(32767.0 / (2 * 16415.0)) / (2 * M_PI * ts);
  EXPECT_NEAR(f_null, 98.61, 0.005);
  EXPECT_LT(std::abs(frequency_response(nt, f_null, ts)), 1e-9);
  // Same response from the float form. to_float rounds each of five ratios (relative 1e-16); near the poles
  // (|p| = 0.99893) the denominator is ~1e-3 of its coefficients, so agreement to ~1e-13 relative is what double
  // precision gives; 1e-10 relative leaves margin and still catches any real difference (a 1-LSB change is ~1e-4).
  for (double f : {0.0, 50.0, 99.4, 100.0, 200.0, 4999.0}) {
    const std::complex<double> hi = frequency_response(nt, f, ts), hf = frequency_response(nt.to_float(), f, ts);
    EXPECT_LT(std::abs(hi - hf), 1e-10 * std::abs(hi)) << f;
  }
}

TEST(Biquad, StabilityIsExactForIntegers) {
  AdlinkBiquadParams p;
  p.div = 16384; p.a2 = -16384; p.a1 = 0;  // poles at +-j: on the unit circle
  EXPECT_FALSE(is_stable(p));
  p.a2 = -16383;
  EXPECT_TRUE(is_stable(p));
  p = AdlinkBiquadParams{};
  p.div = 100; p.a1 = 100; p.a2 = 0;  // pole at z = 1
  EXPECT_FALSE(is_stable(p));
  p.a1 = 99;
  EXPECT_TRUE(is_stable(p));
  p.div = -100; p.a1 = -99;  // same filter, negative DIV
  EXPECT_TRUE(is_stable(p));
  p.a1 = -100;
  EXPECT_FALSE(is_stable(p));
  AdlinkBiquadParams nt;
  nt.a1 = 32767; nt.a2 = -16398; nt.b0 = 16415; nt.b1 = -32767; nt.b2 = 16415; nt.div = 16433;
  EXPECT_TRUE(is_stable(nt));
  EXPECT_NEAR(std::abs(poles(nt).first), 0.99893, 5e-6);  // adlink.md §3.5
  EXPECT_NEAR(std::abs(poles(manual_lowpass()).first), 0.6513, 5e-5);
  EXPECT_THROW(require_stable(p, "x"), std::invalid_argument);
}

TEST(Biquad, PassThroughBypassKeepsTheSameHistory) {
  // The default pass-through skips the arithmetic; B0 = DIV = 2 is the same filter evaluated in full (exact for
  // these inputs: multiplying and dividing by 2 are exact). After switching both to the manual's low-pass (the
  // card's parameter update keeps the history), they must agree bit for bit.
  AdlinkBiquadParams two;
  two.b0 = 2;
  two.div = 2;
  Biquad bypass{AdlinkBiquadParams{}}, full(two);
  for (double x : {3.0, -7.5, 12.25, 100.0}) EXPECT_EQ(bypass.step(x), full.step(x));
  bypass.set_params(manual_lowpass());
  full.set_params(manual_lowpass());
  for (double x : {0.0, 5.0, -2.0, 1000.0, 0.0, 0.0}) EXPECT_EQ(bypass.step(x), full.step(x));
}
