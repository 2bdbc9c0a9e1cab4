// Figures of merit of a position loop from its frequency response (measured or analytic), python-control's
// stability margins (and MATLAB's allmargin lists) in a servo engineer's units. Stability comes first: margins of
// an unstable loop mean nothing, so every Margins carries the verdict and its reason (issue 20).
//
//   stability        the closed loop's poles when the linear model is known (tuning/stability.hpp), otherwise the
//                    Nyquist criterion on the data: Z = P - theta_end / pi closed-loop poles outside the unit
//                    circle, where P is the open loop's count of poles outside the unit circle (0 for the card
//                    loops), and theta_end the phase of 1 + L unwrapped from the low-frequency asymptote of the k
//                    open-loop integrators (angle L -> -k 90 deg, the contour indented around z = 1) to the
//                    Nyquist frequency. Decided only when the data start where |L| >= 2 (k >= 1) and end where
//                    |L| < 1 (assumed to stay below 1 up to Nyquist); otherwise "undecided" with the reason.
//   gain crossovers  every |L| = 1, each with its phase margin 180 deg + angle L wrapped to (-180, 180]
//   phase margin     the crossover nearest to -1 (smallest |PM|, python-control's choice): a crossover with L near
//                    +1 (a phase-stabilised resonance) is the safest, not the worst
//   phase crossovers every angle L = -180 deg (mod 360), i.e. Im L = 0 with Re L < 0, each with -20 log10 |L| dB:
//                    > 0 the gain that may be added before this point reaches -1 ("upper"), < 0 the gain that may
//                    be removed ("lower", a conditionally stable loop). Labels are directions; they are margins
//                    only when the loop is stable.
//   gain margin      the smallest upper one (dB, > 0); lower gain margin the lower one closest to 0 dB
//   delay margin     the extra dead time the loop tolerates, s: the smallest over all crossovers of
//                    (PM mod 360) / (360 deg * crossover frequency); 0 when the phase margin is <= 0
//   bandwidth        first frequency where |Y/R| falls 3 dB below its value at the lowest frequency given
//   Ms               peak sensitivity max |1/(1 + L)| and where it occurs (1/Ms is the distance to -1)
//
// From data alone crossings are interpolated between the given points (dB and phase linear in log frequency, the
// phase unwrapped between neighbours), so the figures are as accurate as the grid is dense around them. With an
// evaluator of L (the analytic loop) each crossing found on the grid is refined by bisection to 1e-10 in log
// frequency and Ms by golden-section search.
#pragma once

#include <complex>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace servobench::tuning {

// The stability verdict a Margins carries.
struct Stability {
  bool decided = false;           // false: the data cannot tell (reason says why); `stable` is then false
  bool stable = false;
  std::string method;             // "closed-loop poles" or "Nyquist"
  std::string reason;             // one sentence with the figures
  double max_pole_radius = std::numeric_limits<double>::quiet_NaN();  // largest closed-loop |z| (poles only)
  int unstable_poles = -1;        // closed-loop poles outside the unit circle (-1: undecided)
  int open_loop_unstable_poles = 0;  // P of the Nyquist criterion
  int integrators = 0;            // open-loop poles at z = 1 (Nyquist: given or inferred)

  // The verdict's fields (name, member, unit, meaning): the keys of Margins.stability in Python (decision OR1).
  template <class V>
  static void describe(V&& v) {
    using S = Stability;
    v("decided", &S::decided, "", "the data (or the model) tell stable from unstable; false: `reason` says why not, and `stable` is false");
    v("stable", &S::stable, "", "the closed loop is stable");
    v("method", &S::method, "", "how it was decided: \"closed-loop poles\" or \"Nyquist\"");
    v("reason", &S::reason, "", "one sentence with the figures");
    v("max_pole_radius", &S::max_pole_radius, "", "largest closed-loop pole |z| (poles only; NaN for Nyquist)");
    v("unstable_poles", &S::unstable_poles, "", "closed-loop poles outside the unit circle (-1: undecided)");
    v("open_loop_unstable_poles", &S::open_loop_unstable_poles, "", "open-loop poles outside the unit circle (the Nyquist criterion's P)");
    v("integrators", &S::integrators, "", "open-loop poles at z = 1 (Nyquist: given or inferred)");
  }
};

// One gain crossover |L| = 1: where (Hz) and its phase margin 180 + angle L (deg, wrapped to (-180, 180]).
struct GainCrossover {
  double freq_hz = 0.0;
  double phase_margin_deg = 0.0;
};

// One phase crossover angle L = -180 deg: where (Hz) and -20 log10 |L| (dB): > 0 upper (the gain may rise by
// this much before the point reaches -1), < 0 lower (it may fall by this much).
struct PhaseCrossover {
  double freq_hz = 0.0;
  double gain_margin_db = 0.0;
  bool lower() const { return gain_margin_db < 0.0; }
};

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
  Stability stability;
  std::vector<GainCrossover> gain_crossovers;    // all, by frequency
  std::vector<PhaseCrossover> phase_crossovers;  // all, by frequency

  // The single-figure results (name, member, unit, meaning): the one place the Python result (servobench.margins.
  // Margins) reads its field names, units and docs from (decision OP6).
  template <class V>
  static void describe(V&& v) {
    using M = Margins;
    v("gain_margin_db", &M::gain_margin_db, "dB", "how far the loop gain may rise before a phase crossover reaches -1: the smallest -20 log10|L| > 0 over the phase crossovers (angle L = -180 deg); inf if there is none");
    v("gm_freq_hz", &M::gm_freq_hz, "Hz", "the phase crossover of the gain margin; NaN if there is none");
    v("lower_gain_margin_db", &M::lower_gain_margin_db, "dB", "how far the gain may fall (negative) for a conditionally stable loop (a PID on an integrating plant has one at low frequency): the phase crossover with |L| > 1 closest to 0 dB; -inf if none");
    v("lower_gm_freq_hz", &M::lower_gm_freq_hz, "Hz", "the phase crossover of the lower gain margin; NaN if none");
    v("phase_margin_deg", &M::phase_margin_deg, "deg", "180 deg + angle L at the gain crossover |L| = 1 nearest to -1; inf if |L| never crosses 1 in the data");
    v("pm_freq_hz", &M::pm_freq_hz, "Hz", "that gain crossover; NaN if none");
    v("delay_margin_s", &M::delay_margin_s, "s", "extra dead time the loop tolerates, phase margin / (360 deg * crossover), the smallest over the crossovers");
    v("bandwidth_hz", &M::bandwidth_hz, "Hz", "closed-loop -3 dB bandwidth: the first frequency where |Y/R| is 3 dB below its value at the lowest frequency; NaN if not reached in the data");
    v("ms", &M::ms, "", "peak sensitivity max |1/(1 + L)| (1/Ms is the distance of L from -1; Ms < 2 is the usual robustness goal)");
    v("ms_freq_hz", &M::ms_freq_hz, "Hz", "where the peak sensitivity occurs");
  }
};

struct MarginsOptions {
  // Nyquist criterion on the data (used when `stability` is empty): P and k (k < 0: inferred from the slope of
  // |L| over the two lowest points, round(-slope / 20 dB/decade), 0..4).
  int open_loop_unstable_poles = 0;
  int integrators = -1;
  std::optional<Stability> stability;  // a verdict from the model's closed-loop poles, used as given
  // L(f) for any f in (0, Nyquist]: refines the crossings and Ms found on the grid (the analytic loop).
  std::function<std::complex<double>(double)> loop_gain_at;
  double nyquist_hz = 0.0;  // > 0 with loop_gain_at: also report a phase crossover at Nyquist (L real < 0 there)
  // Throws std::invalid_argument naming the field and its range.
  void validate() const;

  // The option table of the Nyquist criterion on data (decision OP3): the one place the Python API (margins())
  // reads the defaults, units and docs from. The verdict and the evaluator come from the model, not the user.
  template <class V>
  static void describe(V&& v) {
    using O = MarginsOptions;
    v("open_loop_unstable_poles", &O::open_loop_unstable_poles, "", "the Nyquist criterion's P: open-loop poles outside the unit circle, 0..1000 (0 for the card loops)");
    v("integrators", &O::integrators, "", "open-loop poles at z = 1, 0..10; -1: inferred from the slope of |L| over the two lowest points, round(-slope / 20 dB/decade). The verdict is \"undecided\" when the data do not start where |L| >= 2 or do not end where |L| < 1");
  }
};

// Every gain crossover of L, by frequency (the same interpolation and checks as margins()).
std::vector<GainCrossover> gain_crossovers(const std::vector<double>& freq_hz,
                                           const std::vector<std::complex<double>>& loop_gain);

// Phase of h in degrees, unwrapped point to point from the first (which lies in (-180, 180]).
std::vector<double> unwrapped_phase_deg(const std::vector<std::complex<double>>& h);

// The Nyquist verdict on data (see the top of this file). Same data checks as margins().
Stability nyquist_stability(const std::vector<double>& freq_hz, const std::vector<std::complex<double>>& loop_gain,
                            int open_loop_unstable_poles = 0, int integrators = -1);

// Margins of the loop gain L (pulse/pulse) at freq_hz (increasing, > 0); closed_loop (Y/R) for the bandwidth, may
// be empty (then Y/R = L/(1+L) is used). Throws std::invalid_argument on mismatched sizes, fewer than 2 points,
// non-increasing or non-positive frequencies, non-finite or zero data, a negative open_loop_unstable_poles.
Margins margins(const std::vector<double>& freq_hz, const std::vector<std::complex<double>>& loop_gain,
                const std::vector<std::complex<double>>& closed_loop = {}, const MarginsOptions& options = {});

}  // namespace servobench::tuning
