// The H1 frequency-response estimate of a broadband closed-loop run (servobench.frequency.broadband_response): the
// indirect method with the command R as the reference, read at chosen DFT lines.
//
// The run's signals R (command, pulse), E (following error, pulse), U (the second biquad's output, DAC counts) and
// Y (encoder, pulse) are cut into `records` records of N samples after `skip` samples (the multisine's settling
// period). Per record r and line k the DFT X_r(k) = sum_n x_r[n] exp(-2 pi j k n / N) (numpy.fft.rfft's
// convention; with remove_offset each record's first sample is subtracted first, the chirp's records starting at
// rest) is computed directly at the lines only -- exact for a periodic multisine's lines (no leakage), and no FFT
// library is needed: each line's twiddle runs as a phasor re-anchored every 256 samples on the exact table value
// (k n mod N indexes a table of cos/sin 2 pi m/N), all signals and lines in one pass over the data. Then
//   S_ab = sum_r conj(A_r) B_r,   Y/R = S_RY / S_RR,  Y/E = S_RY / S_RE,  Y/U = S_RY / S_RU,
//   coherence = |S_RY|^2 / (S_RR S_YY) clipped to 0..1 (1 with a single record),
// where a periodic reference (every record of R the same sample for sample) is transformed once and the cross
// spectra taken as conj(R) times the spectra of the summed records of E, U, Y (the DFT is linear). The estimate is
// unbiased by anything that enters the loop after R. Frequencies k / (N Ts), Hz.
#pragma once

#include <complex>
#include <vector>

namespace servobench::tuning {

struct H1Estimate {
  std::vector<double> freq_hz;                  // the lines, Hz
  std::vector<std::complex<double>> plant;      // Y/U, pulse per DAC count
  std::vector<std::complex<double>> open_loop;  // Y/E, pulse/pulse
  std::vector<std::complex<double>> closed_loop;  // Y/R, pulse/pulse
  std::vector<double> coherence;                // magnitude-squared, R to Y, 0..1
};

// DFT of x[0..n-1] at the given lines (each 0..n-1).
std::vector<std::complex<double>> dft_lines(const double* x, int n, const std::vector<int>& lines);

// The estimate from equally long signals r, e, u, y (at least skip + records N samples). Throws
// std::invalid_argument naming the argument and its range.
H1Estimate h1_estimate(const std::vector<double>& r, const std::vector<double>& e, const std::vector<double>& u,
                       const std::vector<double>& y, int record_ticks, int records, int skip_ticks,
                       const std::vector<int>& lines, double servo_period_s, bool remove_offset);

}  // namespace servobench::tuning
