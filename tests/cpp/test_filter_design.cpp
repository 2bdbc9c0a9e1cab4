// Filter design against the ADLINK manual's worked integers: low-pass seed 004 L1919, notch seed 004 L1948
// (adlink.md §3.3-3.6; docs/decisions.md F2-F5).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/control/filter_design.hpp"

using namespace servobench::control;

namespace {
void expect_ints(const AdlinkBiquadParams& p, double a1, double a2, double b0, double b1, double b2, double div) {
  EXPECT_EQ(p.a1, a1);
  EXPECT_EQ(p.a2, a2);
  EXPECT_EQ(p.b0, b0);
  EXPECT_EQ(p.b1, b1);
  EXPECT_EQ(p.b2, b2);
  EXPECT_EQ(p.div, div);
}
std::string message_of(void (*f)()) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FilterDesign, ManualLowpassIntegersL1919) {
  // "1000 Hz cutoff frequency, 100 microseconds sampling time ... A1 at 32767, A2 at -11896, B0 at 1794, B1 at
  // 3588, B2 at 1794, and DIV at 28046" (seed 004 L1919).
  const AdlinkBiquadParams p = quantize_adlink(lowpass(1000.0, 100e-6));
  expect_ints(p, 32767, -11896, 1794, 3588, 1794, 28046);
  EXPECT_DOUBLE_EQ(p.sample_time_s, 100e-6);
  // zeta exactly 1/sqrt(2) is one LSB off (adlink.md §3.3): the manual used 0.707.
  const AdlinkBiquadParams q = quantize_adlink(lowpass(1000.0, 100e-6, 1.0 / std::sqrt(2.0)));
  EXPECT_EQ(q.div, 28047);
  EXPECT_EQ(q.a2, -11895);
  // Pre-warping is clearly not what the manual did.
  EXPECT_NE(quantize_adlink(lowpass(1000.0, 100e-6, 0.707, true)).div, 28046);
}

TEST(FilterDesign, ManualNotchIntegersL1948) {
  // "cutoff frequency at 100Hz, low ... 95Hz, high ... 105Hz, sampling time at 100 microseconds ... A1 at 32767,
  // A2 at -16398, B0 at 16415, B1 at -32767, B2 at 16415 and DIV at 16433" (seed 004 L1948): reproduced by Q = 30.
  expect_ints(quantize_adlink(notch(100.0, 30.0, 100e-6)), 32767, -16398, 16415, -32767, 16415, 16433);
  // The stated band 95..105 Hz (Q = 100/10 = 10, the -3 dB definition) gives other integers (decision F4).
  EXPECT_DOUBLE_EQ(notch_band_q(100.0, 95.0, 105.0, 100e-6), 10.0);
  expect_ints(quantize_adlink(notch_band(100.0, 95.0, 105.0, 100e-6)), 32767, -16363, 16415, -32767, 16415, 16467);
}

TEST(FilterDesign, NotchQRangeThatReproducesTheIntegers) {
  // adlink.md §3.4 scans f0 and the bandwidth together (Q ~ 29.5..30.3). At f0 = 100 Hz exactly, a scan of Q in steps
  // of 0.001 finds the printed integers for Q = 29.440..30.079 only: Q = 30 sits inside, Q = 10 (95..105 Hz) far out.
  for (double q : {29.45, 30.0, 30.07})
    expect_ints(quantize_adlink(notch(100.0, q, 100e-6)), 32767, -16398, 16415, -32767, 16415, 16433);
  auto same = [](double q) {
    const AdlinkBiquadParams p = quantize_adlink(notch(100.0, q, 100e-6));
    return p.a1 == 32767 && p.a2 == -16398 && p.b0 == 16415 && p.b1 == -32767 && p.b2 == 16415 && p.div == 16433;
  };
  EXPECT_FALSE(same(29.4));
  EXPECT_FALSE(same(30.1));
}

TEST(FilterDesign, BilinearMatchesTheAnalogueResponse) {
  const double ts = 100e-6;
  // Without pre-warping the digital response at f equals the analogue one at fa = tan(pi f ts)/(pi ts).
  const FloatBiquadParams lp = lowpass(1000.0, ts);
  for (double f : {10.0, 500.0, 1000.0, 3000.0}) {
    const double fa = std::tan(M_PI * f * ts) / (M_PI * ts);
    const std::complex<double> s(0, 2 * M_PI * fa);
    const double w = 2 * M_PI * 1000.0;
    const std::complex<double> h = w * w / (s * s + 2 * 0.707 * w * s + w * w);
    EXPECT_NEAR(std::abs(frequency_response(lp, f, ts) - h), 0.0, 1e-12);
  }
  // With pre-warping the response at the cutoff equals the analogue one there: 1/(2 zeta j).
  const FloatBiquadParams pw = lowpass(1000.0, ts, 0.5, true);
  EXPECT_NEAR(std::abs(frequency_response(pw, 1000.0, ts) - std::complex<double>(0, -1.0)), 0.0, 1e-12);
  // Notch: exact zero at the (warped) centre with pre-warping.
  EXPECT_LT(std::abs(frequency_response(notch(100.0, 30.0, ts, true), 100.0, ts)), 1e-12);
}

TEST(FilterDesign, LeadLagIsFirstOrder) {
  const double ts = 250e-6;
  const FloatBiquadParams ll = lead_lag(50.0, 200.0, ts, 2.0);
  EXPECT_EQ(ll.b2, 0.0);
  EXPECT_EQ(ll.a2, 0.0);
  EXPECT_NEAR(std::abs(frequency_response(ll, 0.0, ts)), 2.0, 1e-12);
  // Phase lead at the geometric mean: asin((p-z)/(p+z)) = asin(0.6) = 36.87 deg (analogue; bilinear shifts it a bit).
  const double ph = std::arg(frequency_response(ll, 100.0, ts)) * 180 / M_PI;
  EXPECT_NEAR(ph, 36.87, 0.5);
  const FloatBiquadParams pw = lead_lag(50.0, 200.0, ts, 2.0, true);
  EXPECT_NEAR(std::arg(frequency_response(pw, 100.0, ts)) * 180 / M_PI, 36.8699, 1e-3);
  EXPECT_LT(std::arg(frequency_response(lead_lag(200.0, 50.0, ts), 100.0, ts)), 0.0);  // lag
}

TEST(FilterDesign, FromSGeneralSection) {
  const double ts = 1e-3;
  // A pure gain.
  const FloatBiquadParams g = from_s({0, 0, 3}, {0, 0, 2}, ts);
  EXPECT_DOUBLE_EQ(g.b0, 1.5);
  EXPECT_EQ(g.a1, 0.0);
  // First order low-pass 1/(s/w + 1): the textbook bilinear coefficients.
  const double w = 2 * M_PI * 20, c = 2 / ts;
  const FloatBiquadParams f1 = from_s({0, 0, 1}, {0, 1 / w, 1}, ts);
  EXPECT_NEAR(f1.b0, w / (c + w), 1e-15);
  EXPECT_NEAR(f1.a1, (w - c) / (c + w), 1e-15);
  EXPECT_THROW(from_s({1, 0, 0}, {0, 1, 1}, ts), std::invalid_argument);    // improper
  EXPECT_THROW(from_s({0, 0, 1}, {0, 0, 0}, ts), std::invalid_argument);    // zero denominator
  EXPECT_THROW(from_s({0, 0, 1}, {1, -10, 100}, ts), std::invalid_argument);  // unstable analogue poles
  EXPECT_THROW(from_s({0, 0, 1}, {1, 0, 100}, ts), std::invalid_argument);    // poles on the jw axis -> |z| = 1
}

TEST(FilterDesign, BadArgumentsNameTheParameter) {
  EXPECT_NE(message_of([] { lowpass(5000.0, 100e-6); }).find("lowpass.cutoff_hz = 5000 is outside"), std::string::npos);
  EXPECT_NE(message_of([] { lowpass(0.0, 100e-6); }).find("lowpass.cutoff_hz = 0"), std::string::npos);
  EXPECT_NE(message_of([] { lowpass(NAN, 100e-6); }).find("cutoff_hz = nan is not a finite"), std::string::npos);
  EXPECT_NE(message_of([] { lowpass(100.0, 100e-6, 0.0); }).find("lowpass.zeta = 0 must be > 0"), std::string::npos);
  EXPECT_NE(message_of([] { lowpass(100.0, 0.0); }).find("lowpass.sample_time_s = 0"), std::string::npos);
  EXPECT_NE(message_of([] { notch(100.0, -1.0, 1e-4); }).find("notch.q = -1 must be > 0"), std::string::npos);
  EXPECT_NE(message_of([] { notch(100.0, INFINITY, 1e-4); }).find("notch.q = inf"), std::string::npos);
  EXPECT_NE(message_of([] { notch_band(100.0, 105.0, 110.0, 1e-4); }).find("notch.low_hz = 105 must be below"),
            std::string::npos);
  EXPECT_NE(message_of([] { lead_lag(10.0, 6000.0, 1e-4); }).find("lead_lag.pole_hz = 6000"), std::string::npos);
}

TEST(FilterDesign, QuantisationRefusesWhatSixteenBitsCannotHold) {
  // 2 Hz low-pass at 10 kHz: b0 ~ 4e-6 truncates to 0 -> refused, naming the cause.
  const std::string m1 = message_of([] { quantize_adlink(lowpass(2.0, 100e-6)); });
  EXPECT_NE(m1.find("all truncate to 0"), std::string::npos) << m1;
  // Very sharp notch: quantised poles land on the unit circle (A2 = -DIV).
  const std::string m2 = message_of([] { quantize_adlink(notch(5.0, 1000.0, 100e-6)); });
  EXPECT_NE(m2.find("on or outside the unit circle"), std::string::npos) << m2;
  // Coefficients beyond the int16 range.
  FloatBiquadParams big;
  big.b0 = 40000;
  EXPECT_THROW(quantize_adlink(big), std::invalid_argument);
  // All coefficients below 1: DIV is capped at 32767.
  FloatBiquadParams small;
  small.b0 = 0.5;
  small.a1 = 0.25;
  const AdlinkBiquadParams s = quantize_adlink(small);
  EXPECT_EQ(s.div, 32767);
  EXPECT_EQ(s.b0, 16383);
  EXPECT_EQ(s.a1, -8191);
}
