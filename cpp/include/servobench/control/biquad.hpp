// Biquad filters: the two second-order sections the ADLINK PCI-8254/8258 runs after its servo law
// (seed 004 L1869-1911; adlink.md §3), in the card's integer form and in a floating-point form.
//
// ADLINK integer form (L1873-1887; feedback terms are ADDED, DIV divides the whole bracket):
//   R(k) = ( B0*X(k) + B1*X(k-1) + B2*X(k-2) + A1*R(k-1) + A2*R(k-2) ) / DIV
//   H(z) = (B0 + B1 z^-1 + B2 z^-2) / (DIV - A1 z^-1 - A2 z^-2)
// with int16 coefficients (-32768..32767, parameters 132h..13Dh) and defaults B0 = DIV = 1, others 0 (pass-through).
//
// Floating-point form (the usual sign convention, as scipy.signal and MATLAB write it):
//   y(k) = b0*x(k) + b1*x(k-1) + b2*x(k-2) - a1*y(k-1) - a2*y(k-2)
//   H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2)
// so the integer form corresponds to b_i = B_i/DIV, a1 = -A1/DIV, a2 = -A2/DIV.
//
// Arithmetic (docs/decisions.md F1): the card's DSP is a floating-point DSP (L322, "TI 375MHz floating DSP"), so the
// integer form is evaluated exactly as printed, in double precision, with no truncation of R(k): the integers
// only quantise the coefficients. The filter state is kept in double.
#pragma once

#include <complex>
#include <utility>
#include <variant>

namespace servobench::control {

// Floating-point biquad, usual sign convention (feedback subtracted). sample_time_s is the period the filter was
// designed for (s); 0 means "not bound to a period" (then frequency responses need an explicit period).
struct FloatBiquadParams {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;  // numerator, z^0, z^-1, z^-2
  double a1 = 0.0, a2 = 0.0;            // denominator 1 + a1 z^-1 + a2 z^-2
  double sample_time_s = 0.0;           // s, 0..1; 0 = not bound to a period

  void validate() const;  // every coefficient finite; sample_time_s in 0..1 s
};

// The ADLINK card's integer biquad (PRA_BIQUADn_A1, A2, B0, B1, B2, DIV). Whole numbers stored as doubles.
struct AdlinkBiquadParams {
  double a1 = 0, a2 = 0, b0 = 1, b1 = 0, b2 = 0, div = 1;
  double sample_time_s = 0.0;  // s, 0..1; 0 = not bound to a period (not a card parameter; a design record)

  static constexpr double kMin = -32768.0, kMax = 32767.0;
  void validate() const;  // int16 ranges (L1897-1911), DIV != 0

  // The same filter in the floating-point convention: b_i = B_i/DIV, a1 = -A1/DIV, a2 = -A2/DIV.
  FloatBiquadParams to_float() const;
};

using BiquadParams = std::variant<FloatBiquadParams, AdlinkBiquadParams>;

// Complex response H(e^{j 2 pi f Ts}) at frequency f (Hz) for sample time ts (s).
std::complex<double> frequency_response(const FloatBiquadParams& p, double freq_hz, double ts);
// The integer form's response, evaluated from the integers themselves (no division by DIV first).
std::complex<double> frequency_response(const AdlinkBiquadParams& p, double freq_hz, double ts);

// The two poles (roots of z^2 + a1 z + a2, resp. DIV z^2 - A1 z - A2).
std::pair<std::complex<double>, std::complex<double>> poles(const FloatBiquadParams& p);
std::pair<std::complex<double>, std::complex<double>> poles(const AdlinkBiquadParams& p);

// Both poles strictly inside the unit circle (Jury: |a2| < 1 and |a1| < 1 + a2). For the integer form the test is
// done in exact integer arithmetic, so a pole ON the unit circle is detected exactly.
bool is_stable(const FloatBiquadParams& p);
bool is_stable(const AdlinkBiquadParams& p);

// Throws std::invalid_argument "<owner>: poles |z| = r1, r2 are on or outside the unit circle ..." unless stable.
void require_stable(const BiquadParams& p, const char* owner);

// The running filter: five coefficients, a divisor and two samples of history, evaluated as
//   y = (n0*x + n1*x1 + n2*x2 + f1*y1 + f2*y2) / div
// For the integer form (n, f, div) are the card's integers; for the float form n = b, f = -a, div = 1 (exact in
// IEEE arithmetic: adding -a*y equals subtracting a*y, dividing by 1 is exact). One code path, no virtual call.
class Biquad {
 public:
  Biquad() = default;
  explicit Biquad(const BiquadParams& params) { set_params(params); }

  // New coefficients; the history is kept (the card changes parameters between ticks).
  void set_params(const BiquadParams& params);
  void reset() { x1_ = x2_ = y1_ = y2_ = 0.0; }
  // True for the pass-through coefficients (B0 = DIV = 1, all else 0): step(x) returns x.
  bool bypass() const { return bypass_; }

  __attribute__((always_inline)) double step(double x) {  // always inlined into the fused tick (TK3)
    // Pass-through (B0 = DIV = 1, all else 0: the card's default): y = x, which is exactly what the full expression
    // gives (1*x + 0*... = x, /1 exact); skips the division on the tick's critical path. The history is kept current,
    // so coefficients set later see the same past as if the expression had been evaluated.
    // Dividing by DIV = 1 (every float-form filter) is exact, so it is skipped too.
    double y = x;
    if (!bypass_) {
      y = n0_ * x + n1_ * x1_ + n2_ * x2_ + f1_ * y1_ + f2_ * y2_;
      if (div_ != 1.0) y /= div_;
    }
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
  }

 private:
  double n0_ = 1, n1_ = 0, n2_ = 0, f1_ = 0, f2_ = 0, div_ = 1;
  bool bypass_ = true;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

}  // namespace servobench::control
