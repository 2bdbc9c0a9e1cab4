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
};

struct FrequencyFitResult {
  std::vector<ParameterEstimate> parameters;  // the model's parameters (friction ones held), then "delay_s"
  FitSummary summary;
  std::vector<std::complex<double>> predicted;  // the model's response at freq_hz
};

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
