// The analytic frequency response of a simulated axis's position loop, computed from the same parameter objects
// the simulator runs (docs/bode.md, "the analytic loop"):
//
//   R --(+)--E--> C(z) --(+)--> F0(z) F1(z) --U--> P(z) --Y-->
//        ^-                ^ Cff(z) R
//        '----------------------------------------------Y
//
//   C(z)   the servo law's feedback part, counts/pulse:
//            GT:     Kp + (Ki/256)/(1 - z^-1) + Kd (1 - z^-1)                         (GT L801-803)
//            ADLINK: KP_eff + KI_eff/(1 - z^-1) + KD_eff (1 - z^-1)                  (ADLINK L1723-1731)
//          (the integral term is 0 when the integral limit is 0: the sum is held at 0)
//   Cff(z) the feed-forward part on the command: Kvff (1 - z^-1) + Kaff (1 - z^-1)^2 (the command's backward
//          differences, what both laws see when only positions are given)
//   F(z)   the two biquads, from their coefficients (integer ones from the integers)
//   P(z)   U (DAC input, counts) -> Y (encoder, pulse): the output stage's 10 V/32767 counts (sign -1 with
//          ADLINK V_INVERSE), the one-tick output delay z^-1, the drive (current loop; velocity mode: its discrete
//          speed loop at its own rate) and the mechanics held over the tick, lifted exactly to the servo rate, and
//          the encoder's counts per radian on the motor or the load.
//
// Loop gain L = F C P. Responses to R: Y/R = F (C + Cff) P / (1 + L), E/R = (1 - F Cff P) / (1 + L), and the
// ratio Y/E a closed-loop sweep measures = (Y/R) / (E/R), which equals L when the feed-forward is off.
// Exact for a linear configuration: no friction, no saturation, no quantisation, no noise.
#pragma once

#include <complex>
#include <vector>

#include "servobench/machine/axis.hpp"

namespace servobench::tuning {

using Complex = std::complex<double>;

// What is in the loop during a measurement (the ADLINK manual contradicts itself, L1984 vs L2003; docs/decisions.md
// B1-B2 give the defaults and the reasons).
struct LoopOptions {
  bool feedforward = false;  // Kvff/Kaff act on the command; false: zeroed for the measurement
  bool filters = true;       // the two biquads stay in the loop; false: bypassed (pass-through)
  void validate() const {}   // both choices are valid

  // The option table (decision OP3): the one place the Python API (analytic_response, broadband_response,
  // linear_model, analytic_margins, closed_loop_poles) reads these defaults and docs from.
  template <class V>
  static void describe(V&& v) {
    using O = LoopOptions;
    v("feedforward", &O::feedforward, "", "Kvff/Kaff act on the command; False: zeroed, so Y/E is the loop gain L (decision B1)");
    v("filters", &O::filters, "", "the two biquads stay in the loop; False: bypassed, pass-through (decision B2)");
  }
};

struct LoopResponse {
  std::vector<double> freq_hz;
  std::vector<Complex> controller;   // C: E -> law output, counts/pulse
  std::vector<Complex> feedforward;  // Cff: R -> law output, counts/pulse (0 when options.feedforward is false)
  std::vector<Complex> filters;      // F0 F1 (1 when bypassed)
  std::vector<Complex> plant;        // P: U (counts) -> Y (pulse), with the one-tick output delay
  std::vector<Complex> loop_gain;    // L = F C P, pulse/pulse
  std::vector<Complex> open_loop;    // Y/E as a closed-loop sweep measures it (= L without feed-forward)
  std::vector<Complex> closed_loop;  // Y/R
  std::vector<Complex> sensitivity;  // E/R
};

// The loop's responses at freq_hz (Hz, each > 0 and below the Nyquist frequency 1/(2 Ts)). Throws
// std::invalid_argument for a pulse-output drive (no position loop on the card) or a bad frequency.
LoopResponse loop_response(const machine::AxisConfig& config, const std::vector<double>& freq_hz,
                           const LoopOptions& options = {});

// The law's parts alone at z = exp(j 2 pi f Ts): feedback C(z) and feed-forward Cff(z), counts/pulse.
Complex law_feedback_response(const machine::LawParams& law, double freq_hz, double servo_period_s);
Complex law_feedforward_response(const machine::LawParams& law, double freq_hz, double servo_period_s);

// The configuration a measurement runs with: feed-forward gains zeroed unless options.feedforward, biquads set to
// pass-through unless options.filters.
machine::LawParams law_for_measurement(const machine::LawParams& law, const LoopOptions& options);
std::array<control::BiquadParams, 2> filters_for_measurement(const std::array<control::BiquadParams, 2>& filters,
                                                             const LoopOptions& options);

}  // namespace servobench::tuning
