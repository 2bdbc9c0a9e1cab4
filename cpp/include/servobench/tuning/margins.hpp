// Figures of merit of a position loop from its frequency response (measured or analytic), python-control's
// stability margins in a servo engineer's units:
//
//   phase margin     180 deg + angle L at the gain crossover |L| = 1, wrapped to (-180, 180]; with several
//                    crossovers the one nearest to -1 (smallest |PM|, python-control's choice): a crossover with
//                    L near +1 (a phase-stabilised resonance) is the safest, not the worst
//   gain margin      -|L| in dB where angle L = -180 deg (mod 360) and |L| < 1: how far the gain may rise (the
//                    smallest over those phase crossovers)
//   lower gain margin  the same where |L| > 1 (a PID on an integrating plant has one at low frequency): how far
//                    the gain may fall, a negative number of dB (the one closest to 0)
//   delay margin     the extra dead time the loop tolerates, s: the smallest over all crossovers of
//                    (PM mod 360) / (360 deg * crossover frequency); 0 when the phase margin is <= 0
//   bandwidth        first frequency where |Y/R| falls 3 dB below its value at the lowest frequency given
//   Ms               peak sensitivity max |1/(1 + L)| and where it occurs (1/Ms is the distance to -1)
//
// Crossings are interpolated between the given points (dB and unwrapped phase linear in log frequency), so the
// figures are as accurate as the frequency grid is dense around them. The phase is unwrapped from the lowest
// frequency on, point to point: a grid too coarse for a resonance can unwrap wrongly.
#pragma once

#include <complex>
#include <limits>
#include <vector>

namespace servobench::tuning {

struct Margins {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  double gain_margin_db = kNone;        // dB; inf: no phase crossover with |L| < 1 in the data
  double gm_freq_hz = std::numeric_limits<double>::quiet_NaN();  // its phase crossover, Hz
  double lower_gain_margin_db = -kNone;  // dB (< 0); -inf: no phase crossover with |L| > 1 in the data
  double lower_gm_freq_hz = std::numeric_limits<double>::quiet_NaN();
  double phase_margin_deg = kNone;      // deg; inf: |L| never crosses 1 in the data
  double pm_freq_hz = std::numeric_limits<double>::quiet_NaN();  // gain crossover, Hz
  double delay_margin_s = kNone;        // s
  double bandwidth_hz = std::numeric_limits<double>::quiet_NaN();  // closed-loop -3 dB, Hz (NaN: not reached)
  double ms = std::numeric_limits<double>::quiet_NaN();            // peak |S|
  double ms_freq_hz = std::numeric_limits<double>::quiet_NaN();    // Hz
};

// One gain crossover |L| = 1: where (Hz, interpolated in log frequency) and its phase margin 180 + angle L
// (deg, wrapped to (-180, 180]).
struct GainCrossover {
  double freq_hz = 0.0;
  double phase_margin_deg = 0.0;
};

// Every gain crossover of L, by frequency (the same interpolation and checks as margins()).
std::vector<GainCrossover> gain_crossovers(const std::vector<double>& freq_hz,
                                           const std::vector<std::complex<double>>& loop_gain);

// Phase of h in degrees, unwrapped point to point from the first (which lies in (-180, 180]).
std::vector<double> unwrapped_phase_deg(const std::vector<std::complex<double>>& h);

// Margins of the loop gain L (pulse/pulse) at freq_hz (increasing, > 0); closed_loop (Y/R) for the bandwidth, may
// be empty (then Y/R = L/(1+L) is used). Throws std::invalid_argument on mismatched sizes, fewer than 2 points,
// non-increasing or non-positive frequencies, non-finite data.
Margins margins(const std::vector<double>& freq_hz, const std::vector<std::complex<double>>& loop_gain,
                const std::vector<std::complex<double>>& closed_loop = {});

}  // namespace servobench::tuning
