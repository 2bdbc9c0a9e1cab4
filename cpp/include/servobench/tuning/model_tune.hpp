// Model-based PID design from the axis's analytic plant (issue 6: "a model-based design from a given or identified
// plant: crossover for the target margin, notch at the resonance"; docs/decisions.md R8-R14).
//
// The plant P (DAC counts -> encoder pulse: output stage, one-tick delay, drive and mechanics lifted exactly to the
// servo rate) comes from the axis configuration through tuning::loop_response, so any plant the axis runs, given
// or identified, is designed for. Then:
//   1. resonances: peaks of |P| above a double integrator's -40 dB/decade line by min_resonance_prominence_db (or the
//      one given); notch candidates (pre-warped, centred on each of the up to 3 most prominent, q from notch_q_set)
//      go in biquad 0;
//   2. for each filter option (no notch, each notch) crossover candidates fc are scanned upward, log-spaced from
//      min_crossover_hz; at each, design_pid_for_phase_margin puts the loop point F(fc) C(fc) P(fc) at -180 deg +
//      phase_margin_deg (with at most max_pid_lead_deg of PID phase lead), the gains are written to the card law
//      (integers), and the whole loop is checked over the band: phase margin within target +- pm_tolerance_deg (all crossovers), gain margin >= min_gain_margin_db,
//      peak sensitivity <= max_ms, closed-loop poles strictly inside the unit circle;
//   3. the highest feasible candidate is taken and the boundary to the (failing) candidate above it refined by
//      bisection; the highest feasible crossover over all filter options wins (a notch is kept only when it raises
//      the crossover).
// The result explains itself: what was found, what limited the crossover, what was chosen (summary).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "servobench/control/biquad.hpp"
#include "servobench/machine/axis.hpp"
#include "servobench/tuning/loop_response.hpp"
#include "servobench/tuning/margins.hpp"
#include "servobench/tuning/relay_autotune.hpp"
#include "servobench/tuning/stability.hpp"

namespace servobench::tuning {

enum class TuneLaw { kAxis, kGt, kAps };  // the card law the gains are written to (kAxis: the axis's own)

struct ModelTuneOptions {
  double phase_margin_deg = 60.0;      // target at the crossover, 10..89 deg
  double alpha = 4.0;                  // Ti = alpha * Td, 1..100
  double pm_tolerance_deg = 2.0;       // accepted |PM - target| over all crossovers, 0.1..20 deg
  double min_gain_margin_db = 10.0;    // upper gain margin bound, 0..60 dB
  double max_ms = 2.0;                 // peak sensitivity bound, 1.05..10
  double max_pid_lead_deg = 70.0;      // phase the PID may add at the crossover, 5..89 deg (bounds Td: zeros not
                                       // too far below the crossover, a loop without a slow creeping mode)
  bool notch = true;                   // try a notch at the plant's resonance
  double resonance_hz = 0.0;           // the resonance to notch, Hz (0 < f < Nyquist); 0: found in the plant response
  double min_resonance_prominence_db = 6.0;  // a peak this far above the trend is a resonance worth a notch, 0.1..60 dB
  std::vector<double> notch_q_set = {0.5, 0.7, 1.0, 1.4, 2.0, 3.0, 5.0};  // notch quality factors tried, each 0.1..100
  double min_crossover_hz = 1.0;       // lowest crossover candidate, Hz, > 0
  double max_crossover_hz = 0.0;       // highest, Hz (< Nyquist); 0: 0.45 / Ts
  int candidates = 60;                 // log-spaced crossover candidates, 4..10000
  int points = 4000;                   // log-spaced frequencies of the band the loop is checked over, 100..200000
  TuneLaw law = TuneLaw::kAxis;
  // Throws std::invalid_argument naming the field and its range: validate() the ranges that hold at any servo
  // period, validate(servo_period_s) also the frequencies below Nyquist.
  void validate() const;
  void validate(double servo_period_s) const;

  // The option table (name, member, unit, meaning with range): the one place the Python API reads each option's
  // default, unit and doc from (decision OP3). `law` is chosen by name in Python (None, "gt", "aps"); the list
  // notch_q_set is passed beside the struct (its default is bound as MODEL_TUNE_NOTCH_Q).
  template <class V>
  static void describe(V&& v) {
    using O = ModelTuneOptions;
    v("phase_margin_deg", &O::phase_margin_deg, "deg", "target phase margin at the crossover, 10..89");
    v("alpha", &O::alpha, "", "Ti = alpha * Td, 1..100");
    v("notch", &O::notch, "", "try a notch (pre-warped, in biquad 0; the card's integers on an ADLINK law) at the plant's resonance; kept only when it raises the crossover");
    v("min_gain_margin_db", &O::min_gain_margin_db, "dB", "bound on the loop's upper gain margin, 0..60");
    v("max_ms", &O::max_ms, "", "bound on the peak sensitivity max |1/(1 + L)|, 1.05..10");
    v("max_pid_lead_deg", &O::max_pid_lead_deg, "deg", "largest phase the PID may add at the crossover, 5..89; bounds Td so the PID's zeros stay within a factor tan((lead + 90)/2) below the crossover (5.7 at 70 deg): no slowly creeping closed-loop mode");
    v("pm_tolerance_deg", &O::pm_tolerance_deg, "deg", "accepted |phase margin - target| over all gain crossovers of the loop, 0.1..20");
    v("resonance_hz", &O::resonance_hz, "Hz", "the resonance to notch, 0 < f < Nyquist; 0: each of the up to 3 most prominent peaks of the plant's gain found above a -40 dB/decade line");
    v("min_resonance_prominence_db", &O::min_resonance_prominence_db, "dB", "a peak this far above the -40 dB/decade line is a resonance worth a notch, 0.1..60");
    v("min_crossover_hz", &O::min_crossover_hz, "Hz", "lowest crossover candidate, 0 < f < 0.45 / Ts");
    v("max_crossover_hz", &O::max_crossover_hz, "Hz", "highest crossover candidate, min_crossover_hz < f < Nyquist; 0: 0.45 / Ts");
    v("candidates", &O::candidates, "", "log-spaced crossover candidates from min to max, 4..10000; the highest feasible one is taken and the boundary to the one above it bisected");
    v("points", &O::points, "", "log-spaced frequencies of the band the loop is checked over (0.1 Hz or lower .. Nyquist), 100..200000");
  }
};

// A resonance peak of the plant (plant_resonances): frequency, height above the -40 dB/decade line, width at half
// that height in decades.
struct ResonancePeak {
  double freq_hz = 0, prominence_db = 0, width_decades = 0;

  // Its fields (name, member, unit, meaning): the keys of each of ModelTuneResult.resonances in Python (OR1).
  template <class V>
  static void describe(V&& v) {
    using P = ResonancePeak;
    v("freq_hz", &P::freq_hz, "Hz", "the peak's frequency");
    v("prominence_db", &P::prominence_db, "dB", "its height above the -40 dB/decade line");
    v("width_decades", &P::width_decades, "decades", "its width at half that height");
  }
};

// One crossover candidate of the scan.
struct CrossoverCandidate {
  double freq_hz = 0;             // the design frequency
  bool feasible = false;
  std::string reason;             // why not ("" when feasible)
  PidDesign pid;                  // as designed (before the law's integers)
  double pid_lead_deg = 0;        // the PID's phase at the design frequency, deg
  Margins margins;                // of the whole loop with the card law's integers (when a PID was found)
  double max_pole_radius = 0;     // largest closed-loop pole |z| (0 when no PID)

  // The columns of the scan (name, member, unit, meaning): ModelTuneResult.scan's keys in Python (OR1).
  template <class V>
  static void describe(V&& v) {
    using C = CrossoverCandidate;
    v("freq_hz", &C::freq_hz, "Hz", "the design frequency of the candidate");
    v("phase_margin_deg", &C::margins, &Margins::phase_margin_deg, "deg", "phase margin of the whole loop with the card law's integers");
    v("pm_freq_hz", &C::margins, &Margins::pm_freq_hz, "Hz", "its gain crossover");
    v("gain_margin_db", &C::margins, &Margins::gain_margin_db, "dB", "gain margin of the whole loop");
    v("ms", &C::margins, &Margins::ms, "", "peak sensitivity max |1/(1 + L)|");
    v("max_pole_radius", &C::max_pole_radius, "", "largest closed-loop pole |z| (0 when no PID)");
    v("pid_lead_deg", &C::pid_lead_deg, "deg", "the PID's phase at the design frequency");
    v("feasible", &C::feasible, "", "the candidate meets every bound");
    v("reason", &C::reason, "", "why not (\"\" when feasible)");
  }
};

struct NotchDesign {
  bool used = false;
  double center_hz = 0, q = 0;
  double low_hz = 0, high_hz = 0;   // -3 dB edges (analogue prototype): center (sqrt(1 + 1/(4q^2)) -+ 1/(2q))
  double depth_db = 0;              // attenuation of the biquad actually run at the resonance, dB (> 0)
  double phase_at_crossover_deg = 0;  // the notch's phase at the chosen crossover, deg (< 0: lag)
  control::FloatBiquadParams float_biquad;  // pre-warped bilinear design
  control::AdlinkBiquadParams adlink_biquad;  // the card's integers (quantize_adlink)
  bool adlink_ok = false;           // the integers exist (quantisation kept the poles inside)

  // Its figures (name, member, unit, meaning): the keys of ModelTuneResult.notch in Python, beside float_biquad
  // and adlink_biquad (the biquads themselves, None for integers that do not exist; decision OR1).
  template <class V>
  static void describe(V&& v) {
    using N = NotchDesign;
    v("used", &N::used, "", "the notch is in the design (it raised the crossover)");
    v("center_hz", &N::center_hz, "Hz", "notch centre");
    v("q", &N::q, "", "quality factor");
    v("low_hz", &N::low_hz, "Hz", "lower -3 dB edge (analogue prototype)");
    v("high_hz", &N::high_hz, "Hz", "upper -3 dB edge");
    v("depth_db", &N::depth_db, "dB", "attenuation of the biquad actually run at the resonance (> 0)");
    v("phase_at_crossover_deg", &N::phase_at_crossover_deg, "deg", "the notch's phase at the chosen crossover (< 0: lag)");
  }
};

struct ModelTuneResult {
  PidDesign pid;
  machine::LawParams law;                            // the gains as the card law (integers), feed-forward 0
  std::array<control::BiquadParams, 2> filters;      // biquad 0: the notch or pass-through; biquad 1: pass-through
  double crossover_hz = 0;                           // the design frequency chosen
  Margins margins;                                   // predicted from the analytic loop with law and filters
  double max_pole_radius = 0;                        // closed-loop poles, largest |z|
  // The plant's resonances found (empty when given or none stands out); the one notched (or the most prominent).
  std::vector<ResonancePeak> resonances;
  double resonance_hz = 0, resonance_prominence_db = 0;
  bool resonance_given = false;
  NotchDesign notch;
  double crossover_without_notch_hz = 0;             // best crossover with biquad 0 pass-through (0: none)
  std::string limited_by;                            // what failed just above the chosen crossover
  std::vector<CrossoverCandidate> scan;              // the chosen filter option's scan, by frequency
  std::string summary;

  // The single figures (name, member, unit, meaning): the one place the Python result (servobench.autotune.
  // ModelTuneResult) reads their names, units and docs from (decision OR1).
  template <class V>
  static void describe(V&& v) {
    using R = ModelTuneResult;
    v("kp", &R::pid, &PidDesign::kp, "counts/pulse", "proportional gain per tick, as designed (before the card's integers)");
    v("ki", &R::pid, &PidDesign::ki, "counts/(pulse*tick)", "integral gain per tick");
    v("kd", &R::pid, &PidDesign::kd, "counts*tick/pulse", "derivative gain per tick");
    v("kc", &R::pid, &PidDesign::kc, "counts/pulse", "the same PID in continuous form kc (1 + 1/(ti s) + td s): its gain");
    v("ti_s", &R::pid, &PidDesign::ti_s, "s", "its integral time (ti = alpha td)");
    v("td_s", &R::pid, &PidDesign::td_s, "s", "its derivative time");
    v("crossover_hz", &R::crossover_hz, "Hz", "the design crossover chosen");
    v("max_pole_radius", &R::max_pole_radius, "", "the closed loop's largest pole magnitude |z| (< 1: stable)");
    v("resonance_hz", &R::resonance_hz, "Hz", "the resonance notched (or the most prominent one found; 0 when none)");
    v("resonance_prominence_db", &R::resonance_prominence_db, "dB", "its height above the -40 dB/decade line (0 when none)");
    v("crossover_without_notch_hz", &R::crossover_without_notch_hz, "Hz", "the best crossover with no notch (0: none meets the bounds)");
    v("limited_by", &R::limited_by, "", "what failed just above the chosen crossover");
  }
};

// Designs the PID (and notch) for the axis described by `config`. Throws std::invalid_argument for a pulse-input
// axis, bad options (naming the option and its range), or when no crossover in the scanned range meets the margins
// (naming the bounds to relax, with the best candidate's figures).
ModelTuneResult model_tune(const machine::AxisConfig& config, const ModelTuneOptions& options = {});

// Resonance peaks of a plant response h (frequencies increasing): local maxima of |h| in dB plus 40 dB/decade (the
// plant's gain above a double integrator's line, the shape a position loop sees above the drive's bandwidth) whose
// prominence (as scipy.signal.peak_prominences) is >= min_prominence_db and whose width at half prominence is at
// most max_width_decades (broader humps are loops or bends, not modes). Sorted by prominence, largest first.
std::vector<ResonancePeak> plant_resonances(const std::vector<double>& freq_hz, const std::vector<Complex>& h,
                                            double min_prominence_db, double max_width_decades = 1.0);

}  // namespace servobench::tuning
