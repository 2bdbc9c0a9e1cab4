// Periodic multisine excitations: the Schroeder multisine of the broadband measurement
// (servobench.frequency.multisine, broadband_response with excitation="multisine") and the random-phase multisine of
// the identification experiment (servobench.experiment.excitation("multisine"), phases drawn by the caller).
//
// One period has N = period_ticks samples at Ts; its lines are the DFT bins k (frequency k / (N Ts)) from
// ceil(start_hz N Ts) (at least 1) to floor(end_hz N Ts) (at most N/2 - 1): all of them, or `lines` of them at
// round(geomspace(k_lo, k_hi, lines)) (distinct). Schroeder phases (low crest factor, M lines, i = 0..M-1):
//   phi_i = -pi i (i + 1) / M,     x_n = sum_i cos(2 pi k_i n / N + phi_i),
// scaled to a peak of `amplitude` (numpy.fft.irfft of unit lines, up to that scale). Summed directly, no FFT
// library: each line a phasor re-anchored every 256 samples on the exact twiddle (k n mod N indexes a table of
// cos/sin 2 pi m / N), equal to the inverse FFT within 1e-13 of the peak.
#pragma once

#include <vector>

namespace servobench::tuning {

struct Multisine {
  std::vector<double> period;  // one period, N samples, the amplitude's unit
  std::vector<int> lines;      // the excited DFT bins k, increasing
};

// The excited bins of an N-tick period (see above). Throws std::invalid_argument naming the field and its range
// (band outside (0, Nyquist), end <= start, N < 8, lines < 0, no bin in the band).
std::vector<int> multisine_lines(double start_hz, double end_hz, int period_ticks, double servo_period_s, int lines);

// The Schroeder multisine of one period; lines = 0: every bin in the band.
Multisine schroeder_multisine(double start_hz, double end_hz, int period_ticks, double servo_period_s,
                              double amplitude, int lines);

// x_n = sum_i cos(2 pi k_i df t_n + phase_i), t_n = n Ts, df = 1 / (n_samples Ts), n = 0..n_samples-1, scaled
// to a peak of `amplitude` (the random-phase multisine: one period of n_samples, whole periods of every line).
std::vector<double> multisine_sum(int n_samples, double servo_period_s, const std::vector<int>& lines,
                                  const std::vector<double>& phases_rad, double amplitude);

}  // namespace servobench::tuning
