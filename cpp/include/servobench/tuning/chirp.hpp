// The swept-sine (chirp) excitation of the broadband measurement (servobench.frequency.chirp, broadband_response
// with excitation="chirp") and of the identification experiment (servobench.experiment.excitation("chirp")).
//
// Sampled every Ts = servo_period_s for N = round(duration_s / Ts) samples, t_n = n Ts, it starts at phase 0:
//   log (exponential, equal time per decade):  x_n = A sin(2 pi f0 (exp(k t_n) - 1) / k),  k = ln(f1 / f0) / T
//   linear:                                     x_n = A sin(2 pi (f0 t_n + (f1 - f0) t_n^2 / (2 T)))
// with f0 = start_hz, f1 = end_hz, T = duration_s, A = amplitude (any unit: pulse for a command, V for an injection).
//
// The broadband record (chirp_record): the chirp tapered by half-cosine ramps of one start-frequency period at the
// start and 20 end-frequency periods at the end (each at most a quarter of the chirp), so the command starts and
// ends at rest, followed by `rest_ticks` zeros for the loop to settle. Its response is read at the record's DFT
// lines k / (N Ts) between f0 and f1 (chirp_lines), thinned to `lines` log-spaced ones.
#pragma once

#include <vector>

namespace servobench::tuning {

enum class ChirpKind { kLog, kLinear };

struct ChirpOptions {
  double start_hz = 10.0;           // f0, Hz, 0 < f0 < Nyquist
  double end_hz = 100.0;            // f1, Hz, f0 < f1 < Nyquist
  double duration_s = 1.0;          // T, s, > 0 (at least one sample)
  double servo_period_s = 200e-6;   // Ts, s, > 0
  double amplitude = 1.0;           // A, the signal's unit, finite, >= 0
  ChirpKind kind = ChirpKind::kLog;
  // Throws std::invalid_argument naming the field and its range.
  void validate() const;
};

// The chirp, N = round(duration_s / servo_period_s) samples.
std::vector<double> chirp(const ChirpOptions& options);

// The tapered chirp followed by rest_ticks (>= 0) zeros (see the top of this file).
std::vector<double> chirp_record(const ChirpOptions& options, int rest_ticks);

// DFT lines k (0 <= k <= n/2) of an n-sample record at Ts whose frequency k / (n Ts) lies in [start_hz, end_hz];
// when lines > 0 and fewer than those, thinned to the distinct lines nearest above `lines` log-spaced frequencies
// from the first to the last in-band line (numpy.geomspace, searchsorted).
std::vector<int> chirp_lines(int n, double servo_period_s, double start_hz, double end_hz, int lines);

// numpy.geomspace(start, stop, num): num >= 1 values log-spaced from start to stop, both ends exact.
std::vector<double> geomspace(double start, double stop, int num);

}  // namespace servobench::tuning
