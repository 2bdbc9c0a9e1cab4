// Relay auto-tuning with hysteresis, the procedure of the ADLINK card's auto servo tuning (seed 004 L1764-1847,
// adlink.md §4), identified with the describing function of a relay with hysteresis and designed for a phase margin.
//
// The experiment: the servo law is off; every sampling time the relay reads the position error e = r - y (r: the
// position at the start) and sets the DAC output to +d when e > +eps, -d when e < -eps, else keeps it (d =
// amplitude_v, eps = hysteresis_pulse). The axis settles into a limit cycle ("the motor starts vibrating", L1816).
//
// Per limit cycle (rising switch to rising switch): the period Tu, the fundamental amplitude a of e over the cycle
// (single-bin DFT; the peak is reported too), and the describing-function point of the plant (volts -> pulses)
//   |G(j wu)| = pi a / (4 d),   angle G(j wu) = -180 deg + asin(eps / a),   wu = 2 pi / Tu.
// Each cycle gives one gain set: a PID with Ti = alpha Td that puts the loop at the target phase margin at wu,
// designed on the card's discrete law (exact z-transfer of the PID, the relay's and the servo loop's delays
// accounted for: docs/decisions.md R1-R6). "Data length" sets are collected; the result is their mean, accepted
// when each gain's relative standard deviation is below max_spread (10 %, L1794).
//
// Stop reasons (L1826-1831): user stop, a limit switch (PEL/MEL) or the drive alarm, the deviation limit,
// spread above 10 %; each turns the servo off. A cycle that never appears (no oscillation within max_time_s)
// (no cycle completed within max_cycle_s) also ends the tuning.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "servobench/machine/axis.hpp"

namespace servobench::tuning {

struct RelayTuneOptions {
  double amplitude_v = 1.0;             // relay output +-d, V, 0 < d <= 10 (L1843)
  double hysteresis_pulse = 50.0;       // eps, pulse, > 0 (L1846)
  int data_length = 200;                // gain sets to compute, 1..100000 (L1845)
  double sampling_time_s = 500e-6;      // relay sampling time, 100e-6..1000e-6 s (L1847); exact: the relay decides
                                        // at the first tick at or after each multiple of it (at most every tick)
  double deviation_limit_pulse = 2000;  // |e| above this stops the tuning, pulse; 0 = off (L1842)
  double max_spread = 0.10;             // accepted relative standard deviation of each gain (L1794), 0 < . <= 1
  double phase_margin_deg = 60.0;       // design target (L1796), 10..89 deg
  double alpha = 4.0;                   // Ti = alpha * Td, 1..100
  int settle_cycles = 3;                // first limit cycles discarded (start-up), 0..1000
  double max_cycle_s = 10.0;            // give up when no new limit cycle completes within this time, s, > 0
  void validate() const;

  // The option table (name, member, unit, meaning with range and manual line): the one place the Python API reads
  // each option's default, unit and doc from (decision OP3).
  template <class V>
  static void describe(V&& v) {
    using O = RelayTuneOptions;
    v("amplitude_v", &O::amplitude_v, "V", "relay output +-d, 0 < d <= 10 (L1843)");
    v("hysteresis_pulse", &O::hysteresis_pulse, "pulse", "relay hysteresis eps on the position error, > 0 (L1846)");
    v("data_length", &O::data_length, "", "gain sets (limit cycles) to compute, 1..100000 (L1845)");
    v("sampling_time_s", &O::sampling_time_s, "s", "relay sampling time, 100e-6..1000e-6 (L1847); exact: the relay decides at the first servo tick at or after each multiple of it (250 us on a 100 us axis: after 2, 3, 2, 3 ... ticks), at most every tick");
    v("deviation_limit_pulse", &O::deviation_limit_pulse, "pulse", "|position error| above this stops the tuning, servo off, >= 0; 0 = off (L1842)");
    v("max_spread", &O::max_spread, "", "accepted relative standard deviation of each gain over the sets, 0 < . <= 1 (the manual's 10 %, L1794)");
    v("phase_margin_deg", &O::phase_margin_deg, "deg", "design target phase margin, 10..89 (L1796)");
    v("alpha", &O::alpha, "", "Ti = alpha * Td, 1..100");
    v("settle_cycles", &O::settle_cycles, "", "first limit cycles discarded (start-up), 0..1000");
    v("max_cycle_s", &O::max_cycle_s, "s", "give up when no new limit cycle completes within this time, > 0");
  }
};

enum class TuneStatus { kCompleted, kUserStop, kLimitOrAlarm, kDeviationExceeded, kSpreadTooLarge, kNoOscillation };

// A continuous PID C(s) = kc (1 + 1/(ti s) + td s), kc in DAC counts per pulse (32767 counts = 10 V), and its
// per-tick form for the cards' laws: U = kp E + ki Sum(E) + kd (E - E_prev), counts per pulse.
struct PidDesign {
  double kc = 0, ti_s = 0, td_s = 0;
  double kp = 0, ki = 0, kd = 0;  // per tick, counts/pulse (ki per pulse*tick)

  // Its figures (name, member, unit, meaning): the keys of a PID design in Python (classic_rule, model_tune's pid;
  // decision OR1).
  template <class V>
  static void describe(V&& v) {
    using P = PidDesign;
    v("kc", &P::kc, "counts/pulse", "gain of the continuous PID kc (1 + 1/(ti s) + td s)");
    v("ti_s", &P::ti_s, "s", "its integral time");
    v("td_s", &P::td_s, "s", "its derivative time");
    v("kp", &P::kp, "counts/pulse", "proportional gain per tick (the card law's unit)");
    v("ki", &P::ki, "counts/(pulse*tick)", "integral gain per tick");
    v("kd", &P::kd, "counts*tick/pulse", "derivative gain per tick");
  }
};

struct RelayTuneResult {
  TuneStatus status = TuneStatus::kCompleted;
  std::string message;
  double sampling_time_s = 0;        // the sampling time actually used: max(option, servo period), s
  // Per identified cycle (after the settling cycles):
  std::vector<double> period_s, amplitude_pulse, peak_pulse, center_pulse;
  std::vector<double> gain_pulse_per_v, phase_deg;  // describing-function point of G at wu
  std::vector<double> kp, ki, kd;                   // per-tick gains of each set
  // Means and relative standard deviations of the sets:
  PidDesign mean;
  double kp_spread = 0, ki_spread = 0, kd_spread = 0;
  double ultimate_freq_hz = 0;      // mean 1/Tu
  double ultimate_gain_v_per_pulse = 0;  // mean 4 d / (pi a)
  long long ticks = 0;
  // The experiment's record, one sample per servo tick: position error (pulse) and relay output (V).
  std::vector<double> error_pulse, output_v;

  // The single figures (name, member, unit, meaning): the one place the Python result (servobench.autotune.
  // RelayTuneResult) reads their names, units and docs from (decision OQ6).
  template <class V>
  static void describe(V&& v) {
    using R = RelayTuneResult;
    v("kp", &R::mean, &PidDesign::kp, "counts/pulse", "mean proportional gain of the sets, per tick (the card law's unit)");
    v("ki", &R::mean, &PidDesign::ki, "counts/(pulse*tick)", "mean integral gain of the sets, per tick");
    v("kd", &R::mean, &PidDesign::kd, "counts*tick/pulse", "mean derivative gain of the sets, per tick");
    v("kc", &R::mean, &PidDesign::kc, "counts/pulse", "the same PID in continuous form kc (1 + 1/(ti s) + td s): its gain");
    v("ti_s", &R::mean, &PidDesign::ti_s, "s", "its integral time");
    v("td_s", &R::mean, &PidDesign::td_s, "s", "its derivative time");
    v("kp_spread", &R::kp_spread, "", "relative standard deviation of kp over the sets (the manual's \"fluctuation\", L1794)");
    v("ki_spread", &R::ki_spread, "", "relative standard deviation of ki over the sets");
    v("kd_spread", &R::kd_spread, "", "relative standard deviation of kd over the sets");
    v("ultimate_freq_hz", &R::ultimate_freq_hz, "Hz", "mean identified ultimate frequency 1/Tu");
    v("ultimate_gain_v_per_pulse", &R::ultimate_gain_v_per_pulse, "V/pulse", "mean identified ultimate gain 4 d / (pi a)");
    v("sampling_time_s", &R::sampling_time_s, "s", "the relay's sampling time actually used: max(option, servo period)");
  }
};

// Called after each identified set with (sets done, sets wanted); false stops the tuning (the user's Stop).
using TuneProgress = std::function<bool(int, int)>;

// Runs the relay experiment on `axis` from its present state (voltage-output axes only). The servo is turned off
// for the experiment and left off when it ends (the card's behaviour); the caller applies the result.
RelayTuneResult relay_autotune(machine::Axis& axis, const RelayTuneOptions& options,
                               const TuneProgress& progress = {});

// The PID (Ti = alpha Td) that puts the discrete loop at `phase_margin_deg` at w = 2 pi freq_hz, given the plant's
// point g (pulse per volt, complex) there, for a card law at servo period ts_s: the law's z-transfer is exact;
// extra_delay_s is a delay to add to g (the servo loop's minus the experiment's). Throws std::invalid_argument if no
// PID with that structure reaches the phase.
PidDesign design_pid_for_phase_margin(std::complex<double> g, double freq_hz, double ts_s, double phase_margin_deg,
                                      double alpha, double extra_delay_s = 0.0);

// Classic rules from an ultimate point (ku in counts per pulse, tu in s), converted to per-tick gains at ts_s:
// Ziegler-Nichols PID (0.6 Ku, Tu/2, Tu/8) and Tyreus-Luyben (Ku/2.2, 2.2 Tu, Tu/6.3).
PidDesign ziegler_nichols(double ku, double tu_s, double ts_s);
PidDesign tyreus_luyben(double ku, double tu_s, double ts_s);

// The card laws carrying a design: GT (integers, Ki/256; throws std::invalid_argument naming the gain when it does
// not fit 0..32767) and ADLINK (integers 0..65535 with per-term shifts chosen to keep the most digits, PID_SHIFT
// kept at its default -5). Feed-forward zero (the manual's "Set final", L1820).
control::GtServoLawParams to_gt_law(const PidDesign& d, const control::GtServoLawParams& base = {});
control::ApsServoLawParams to_aps_law(const PidDesign& d, const control::ApsServoLawParams& base = {});

}  // namespace servobench::tuning
