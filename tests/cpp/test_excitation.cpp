// Issue 24 point 4: the broadband excitations and their estimate in C++ (tuning/chirp, multisine, spectral_lines).
// The equality with the former NumPy implementation is tested from Python (tests/python/test_excitation_cpp.py);
// here the properties that make them right: the DFT at the lines is the DFT, a multisine puts its power on its
// lines only, the H1 estimate of a known filter is that filter, the option tables list what the structs hold.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "servobench/tuning/chirp.hpp"
#include "servobench/tuning/margins.hpp"
#include "servobench/tuning/multisine.hpp"
#include "servobench/tuning/sine_sweep.hpp"
#include "servobench/tuning/spectral_lines.hpp"

using namespace servobench::tuning;
using Complex = std::complex<double>;

namespace {
constexpr double kPi = 3.141592653589793;

Complex naive_dft(const std::vector<double>& x, int k) {
  Complex s;
  const int n = static_cast<int>(x.size());
  for (int j = 0; j < n; ++j) s += x[j] * std::polar(1.0, -2 * kPi * static_cast<double>(k) * j / n);
  return s;
}
}  // namespace

TEST(Excitation, DftAtLinesIsTheDft) {
  const int n = 1237;  // prime: no FFT factorisation to lean on
  std::vector<double> x(n);
  for (int j = 0; j < n; ++j) x[j] = std::sin(0.37 * j) + 0.2 * std::cos(0.011 * j * j) + 1.5;
  const std::vector<int> lines = {0, 1, 7, 300, 617, 618, 1236};
  const auto X = dft_lines(x.data(), n, lines);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Complex want = naive_dft(x, lines[i]);
    EXPECT_LT(std::abs(X[i] - want), 1e-10 * (1 + std::abs(want))) << "line " << lines[i];
  }
  EXPECT_THROW(dft_lines(x.data(), n, {n}), std::invalid_argument);
}

TEST(Excitation, SchroederMultisineHasPowerOnItsLinesOnly) {
  const int n = 1000;
  const Multisine ms = schroeder_multisine(10, 400, n, 1e-3, 2.0, 0);
  ASSERT_EQ(ms.lines.front(), 10);
  ASSERT_EQ(ms.lines.back(), 400);
  double peak = 0;
  for (double v : ms.period) peak = std::max(peak, std::fabs(v));
  EXPECT_NEAR(peak, 2.0, 1e-12);
  std::vector<int> all(n / 2);
  for (int k = 0; k < n / 2; ++k) all[k] = k;
  const auto X = dft_lines(ms.period.data(), n, all);
  const double on = std::abs(X[10]);
  for (int k = 0; k < n / 2; ++k) {
    const bool excited = k >= 10 && k <= 400;
    if (excited) {
      EXPECT_NEAR(std::abs(X[k]), on, 1e-9 * on) << k;  // flat amplitude spectrum
    } else {
      EXPECT_LT(std::abs(X[k]), 1e-9 * on) << k;
    }
  }
  EXPECT_THROW(schroeder_multisine(10.2, 10.4, 100, 1e-3, 1.0, 0), std::invalid_argument);
}

TEST(Excitation, H1OfAKnownFilterIsThatFilter) {
  // y = 0.5 r[n-1] + 0.25 r[n-2], e = r - y, u = 2 r: a periodic multisine gives the exact responses at its lines.
  const int n = 512, records = 3;
  const Multisine ms = schroeder_multisine(5, 200, n, 1e-3, 1.0, 40);
  std::vector<double> r, e, u, y;
  for (int rec = 0; rec < records + 1; ++rec)
    for (int j = 0; j < n; ++j) r.push_back(ms.period[j]);
  for (std::size_t j = 0; j < r.size(); ++j) {
    const double yj = 0.5 * (j >= 1 ? r[j - 1] : 0.0) + 0.25 * (j >= 2 ? r[j - 2] : 0.0);
    y.push_back(yj);
    e.push_back(r[j] - yj);
    u.push_back(2 * r[j]);
  }
  const H1Estimate h = h1_estimate(r, e, u, y, n, records, n, ms.lines, 1e-3, false);
  for (std::size_t i = 0; i < ms.lines.size(); ++i) {
    const double w = 2 * kPi * ms.lines[i] / n;
    const Complex g = 0.5 * std::polar(1.0, -w) + 0.25 * std::polar(1.0, -2 * w);
    EXPECT_LT(std::abs(h.closed_loop[i] - g), 1e-12);
    EXPECT_LT(std::abs(h.open_loop[i] - g / (1.0 - g)), 1e-10 * std::abs(g / (1.0 - g)));
    EXPECT_LT(std::abs(h.plant[i] - g / 2.0), 1e-12);
    EXPECT_NEAR(h.coherence[i], 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(h.freq_hz[i], ms.lines[i] / (n * 1e-3));
  }
  EXPECT_THROW(h1_estimate(r, e, u, y, n, records + 1, n, ms.lines, 1e-3, false), std::invalid_argument);
}

TEST(Excitation, ChirpStartsAtRestAndSweepsItsBand) {
  ChirpOptions o;
  o.start_hz = 5;
  o.end_hz = 200;
  o.duration_s = 2.0;
  o.servo_period_s = 1e-3;
  o.amplitude = 3;
  const auto x = chirp(o);
  ASSERT_EQ(x.size(), 2000u);
  EXPECT_EQ(x[0], 0.0);
  const auto rec = chirp_record(o, 500);
  ASSERT_EQ(rec.size(), 2500u);
  EXPECT_EQ(rec[0], 0.0);
  EXPECT_EQ(rec[2000], 0.0);
  EXPECT_LT(std::fabs(rec[1999]), 0.05);
  const auto lines = chirp_lines(2500, 1e-3, 5, 200, 50);
  ASSERT_FALSE(lines.empty());
  EXPECT_GE(lines.front() / 2.5, 5.0 - 1e-9);
  EXPECT_LE(lines.back() / 2.5, 200.0 + 1e-9);
  for (std::size_t i = 1; i < lines.size(); ++i) EXPECT_GT(lines[i], lines[i - 1]);
  o.end_hz = 600;  // above Nyquist
  EXPECT_THROW(chirp(o), std::invalid_argument);
}

TEST(Excitation, OptionTablesListTheFields) {
  std::vector<std::string> names;
  SineSweepOptions::describe([&](const char* name, auto...) { names.push_back(name); });
  EXPECT_EQ(names.size(), 15u);
  EXPECT_EQ(names.front(), "start_hz");
  names.clear();
  Margins::describe([&](const char* name, auto...) { names.push_back(name); });
  EXPECT_EQ(names.size(), 10u);
  MarginsOptions mo;
  mo.integrators = 11;
  EXPECT_THROW(mo.validate(), std::invalid_argument);
}
