// Frequency-domain fit of a parametric plant to a measured plant response Y/U, solved with Ceres.
//
// The model is the axis's own analytic plant response (tuning/loop_response.hpp: the output stage, the one-tick
// output delay, the drive, the mechanics lifted exactly to the servo rate by the simulator's zero-order hold, and the
// encoder scale), with the mechanics' parameters free, times an optional extra pure delay exp(-j w tau) for the lags
// a real machine adds. Residual per frequency: the complex log of the ratio, [ln|G_meas/G_model|, arg(G_meas/G_model)]
// in nepers and radians, times a weight (e.g. the coherence) -- a relative error, so a resonance peak and a -60 dB
// roll-off count alike. Derivatives: central differences of that double-precision model (the analytic response
// contains a matrix exponential, which Jets do not go through). Friction is invisible to a linear response: only the
// linear parameters (inertias, stiffness, damping, viscous friction) are fitted, the others held.
#pragma once

#include <complex>
#include <functional>
#include <limits>
#include <vector>

#include "servobench/identify/fit_report.hpp"
#include "servobench/identify/plant_model.hpp"
#include "servobench/identify/time_fit.hpp"
#include "servobench/machine/axis.hpp"

namespace servobench::identify {

struct FrequencyData {
  std::vector<double> freq_hz;                    // > 0, below the Nyquist frequency
  std::vector<std::complex<double>> response;     // measured Y/U: U in DAC counts, Y in pulse (a sweep's "plant")
  std::vector<double> weight;                     // per frequency, >= 0 (empty: all 1)
};

struct FrequencyFitOptions {
  PlantModel model = PlantModel::kRigid;
  bool fit_delay = false;         // estimate an extra pure delay tau (s) besides the axis's own one-tick delay
  double delay_initial_s = 0.0;   // its starting value (or its fixed value when not fitted), s, >= 0
  int max_iterations = 200;       // 1..10000
  double max_relative_std_error = 0.2;
  std::function<bool(int, double)> progress;
  void validate() const;

  // The option table (decision OP3): the one place the Python API (fit_frequency) reads each option's default,
  // unit and doc from. The model is chosen by name in Python; the progress callback is not an option.
  template <class V>
  static void describe(V&& v) {
    using O = FrequencyFitOptions;
    v("fit_delay", &O::fit_delay, "", "also fit an extra pure delay exp(-j w tau) for lags the description leaves out (besides the axis's own one-tick delay)");
    v("delay_s", &O::delay_initial_s, "s", "the extra delay's starting value (its fixed value when not fitted), >= 0");
    v("max_iterations", &O::max_iterations, "", "solver iterations at most, 1..10000");
    v("max_relative_std_error", &O::max_relative_std_error, "", "a parameter whose standard error exceeds this fraction of its own value is not identifiable, > 0");
  }
};

struct FrequencyFitResult {
  std::vector<ParameterEstimate> parameters;  // the model's parameters (friction ones held), then "delay_s"
  FitSummary summary;
  std::vector<std::complex<double>> predicted;  // the model's response at freq_hz
};

// What surrounds the mechanics in a measured response when there is no servobench Axis (a drive's analyser, a Bode
// CSV, an FRD from elsewhere): the response is
//   G(f) = output_per_rad * C (s I - A)^-1 B * torque_per_input                    (continuous: s = j 2 pi f)
//   G(f) = output_per_rad * C (z I - Phi)^-1 Gamma * z^-delay_samples * torque_per_input   (sampled, z = e^{s Ts})
// with (A, B) the model's linear part (current loop at current_bw_hz in series with the mechanics, plant_model.hpp),
// (Phi, Gamma) its exact zero-order hold over the sample period, C the motor or load angle (or speed) row.
struct MechanicsIO {
  double sample_period_s = 0.0;   // s; 0: a continuous-time response, > 0: sampled, torque held over each sample
  int delay_samples = 0;          // whole samples of delay between the input and the output (sampled only), 0..1000
  double torque_per_input = 1.0;  // N*m per unit of the response's input (1: the input is the torque command), != 0
  double output_per_rad = 1.0;    // output units per rad (speed output: per rad/s), != 0 (counts_per_rev / 2 pi)
  bool speed_output = false;      // the output is a speed (rad/s x output_per_rad), else an angle
  bool on_load = false;           // the output is the load side's (two-mass), else the motor's
  double current_bw_hz = std::numeric_limits<double>::infinity();  // the known current loop, Hz (inf: none)
  void validate() const;

  // The field table (decision OQ3): the one place servobench.frequency_fit.MechanicsIO reads its fields' defaults,
  // units and docs from (Python writes None for a continuous-time sample_period_s and counts_per_rev for
  // output_per_rad).
  template <class V>
  static void describe(V&& v) {
    using O = MechanicsIO;
    v("sample_period_s", &O::sample_period_s, "s", "0: a continuous-time response (an analyser that removed its sampling, a model); > 0: the response of a sampled loop whose torque is held over each sample");
    v("delay_samples", &O::delay_samples, "samples", "whole samples between the input and the output, 0..1000, sampled responses only (a servobench axis has 1: the output delay); a further non-integer delay is fitted with fit_delay=True");
    v("torque_per_input", &O::torque_per_input, "N*m per input unit", "1 for a torque command in N*m, kt x A/V for DAC volts (servobench.torque_per_volt), x 10/32767 more for DAC counts; finite and non-zero (negative: an inverted output)");
    v("output_per_rad", &O::output_per_rad, "output units per rad", "the output's units per rad (speed output: per rad/s), finite and non-zero: counts_per_rev / (2 pi) for encoder counts, 1 for rad");
    v("speed_output", &O::speed_output, "", "the output is a speed (rad/s x output_per_rad), not an angle");
    v("on_load", &O::on_load, "", "the output is measured on the load side (two-mass), not the motor");
    v("current_bw_hz", &O::current_bw_hz, "Hz", "the drive's current-loop bandwidth, > 0 (inf: ideal)");
  }
};

// The response of the mechanics described by `io` for a parameter vector (full model vector, friction ignored).
std::vector<std::complex<double>> mechanics_response(const MechanicsIO& io, PlantModel model,
                                                     const std::vector<double>& parameters, double delay_s,
                                                     const std::vector<double>& freq_hz);

// The same fit without an Axis: the model is mechanics_response(io, ...). Frequencies must be > 0 (and below the
// Nyquist frequency when sampled).
FrequencyFitResult fit_frequency_response(const MechanicsIO& io, const FrequencyData& data,
                                          const ParameterSetup& setup, const FrequencyFitOptions& options);

// `config`: the axis the response was measured on (drive, output stage, encoder, servo period, sub-steps); its
// plant is replaced by the model. Throws std::invalid_argument for bad data (lengths, non-finite values,
// frequencies out of range, fewer frequencies than parameters) or a pulse-input drive.
FrequencyFitResult fit_frequency_response(const machine::AxisConfig& config, const FrequencyData& data,
                                          const ParameterSetup& setup, const FrequencyFitOptions& options);

// The model's response (U counts -> Y pulse) for a parameter vector, as the fit evaluates it.
std::vector<std::complex<double>> model_plant_response(const machine::AxisConfig& config, PlantModel model,
                                                       const std::vector<double>& parameters, double delay_s,
                                                       const std::vector<double>& freq_hz);

}  // namespace servobench::identify
