#include "servobench/tuning/sine_sweep.hpp"

#include <algorithm>
#include <limits>
#include <cmath>

#include <Eigen/Dense>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {
constexpr const char* kOwner = "SineSweep";
constexpr const char* kManual = "ADLINK Bode tool, L2038-2045";

// Number of whole periods m (<= m_max) whose length m*P samples comes closest to a whole number, preferring long
// windows: searched over the upper half of 1..m_max.
int best_periods(double samples_per_period, int m_max) {
  int best = m_max;
  double best_err = 1e300;
  for (int m = m_max; m >= std::max(1, m_max / 2); --m) {
    const double len = m * samples_per_period;
    const double err = std::fabs(len - std::round(len)) / len;
    if (err < best_err - 1e-15) {
      best_err = err;
      best = m;
    }
  }
  return best;
}

// cos(w k) and sin(w k) for k = 0..n-1 by rotation, re-anchored on the exact values every 256 samples (the
// rotation's rounding error stays below 1e-13; a sin/cos call per sample would dominate the sweep's cost).
void unit_phasors(double w, int n, double* c, double* s) {
  const double cw = std::cos(w), sw = std::sin(w);
  double a = 1.0, b = 0.0;
  for (int k = 0; k < n; ++k) {
    if ((k & 255) == 0) {
      a = std::cos(w * k);
      b = std::sin(w * k);
    }
    c[k] = a;
    s[k] = b;
    const double a2 = a * cw - b * sw;
    b = b * cw + a * sw;
    a = a2;
  }
}

// Least-squares fit of x[n] = re*cos(w n) + im*(-sin(w n)) + c on the window, returned as the phasor re + j im
// (x = Re(X e^{j w n}) + c). Over whole periods this is the single-bin DFT 2/N sum x e^{-j w n}.
struct SineFit {
  Eigen::Matrix3d gram_inv;
  std::vector<double> cs, sn;
  SineFit(double w, int n) : cs(n), sn(n) {
    unit_phasors(w, n, cs.data(), sn.data());
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    for (int k = 0; k < n; ++k) {
      sn[k] = -sn[k];
      const Eigen::Vector3d b(cs[k], sn[k], 1.0);
      g += b * b.transpose();
    }
    gram_inv = g.inverse();
  }
  // Returns the phasor and sets `residual_share` = residual variance / variance about the mean.
  std::complex<double> fit(const double* x, double* residual_share = nullptr) const {
    const int n = static_cast<int>(cs.size());
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    double mean = 0.0;
    for (int k = 0; k < n; ++k) {
      rhs += Eigen::Vector3d(cs[k], sn[k], 1.0) * x[k];
      mean += x[k];
    }
    mean /= n;
    const Eigen::Vector3d c = gram_inv * rhs;
    if (residual_share) {
      double res = 0.0, var = 0.0;
      for (int k = 0; k < n; ++k) {
        const double e = x[k] - (c[0] * cs[k] + c[1] * sn[k] + c[2]);
        res += e * e;
        var += (x[k] - mean) * (x[k] - mean);
      }
      *residual_share = var > 0 ? res / var : 0.0;
    }
    return {c[0], c[1]};
  }
};

// Amplitude of the h-th harmonic over the window (whole periods of the fundamental, so whole periods of each
// harmonic): single-bin DFT by the Goertzel recursion.
// Amplitude of the component at w (rad/tick) of x[0..n) about `offset` (the window's mean): the window holds whole
// periods of the fundamental only to the nearest tick, so an uncentred signal (an axis standing at 10000 pulse)
// would leak its mean into every harmonic bin and read as distortion.
double harmonic_amplitude(const double* x, int n, double w, double offset) {
  const double coeff = 2.0 * std::cos(w);
  double s1 = 0.0, s2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double s0 = (x[k] - offset) + coeff * s1 - s2;
    s2 = s1;
    s1 = s0;
  }
  const double power = s1 * s1 + s2 * s2 - coeff * s1 * s2;  // |sum x e^{-j w k}|^2
  return 2.0 * std::sqrt(std::max(power, 0.0)) / n;
}
}  // namespace

void SineSweepOptions::validate() const {
  check_positive(kOwner, "start_hz", start_hz);
  check_positive(kOwner, "end_hz", end_hz);
  check_nonnegative(kOwner, "amplitude_pulse", amplitude_pulse);
  check_range(kOwner, "min_coherence", min_coherence, 0.0, 1.0);
  check_nonnegative(kOwner, "max_distortion", max_distortion);
  check_nonnegative(kOwner, "min_response_pulse", min_response_pulse);
  check_nonnegative(kOwner, "min_dac_counts", min_dac_counts);
  check_range(kOwner, "dac_fraction", dac_fraction, 1e-6, 1.0);
  check_nonnegative(kOwner, "max_amplitude_pulse", max_amplitude_pulse);
  check_integer(kOwner, "points", points, 2, 100000, kManual);
  check_positive(kOwner, "update_s", update_s);
  check_nonnegative(kOwner, "deviation_limit_pulse", deviation_limit_pulse);
  check_range(kOwner, "settle_fraction", settle_fraction, 0.0, 0.9);
}

void SineSweepOptions::validate(double ts) const {
  const double nyquist = 0.5 / ts;
  const std::string nyq = "must be > 0 and below the Nyquist frequency 1/(2 Ts) = " + format_value(nyquist) + " Hz";
  if (!(start_hz > 0) || !(start_hz < nyquist)) throw_invalid(kOwner, "start_hz", start_hz, nyq);
  if (!(end_hz > 0) || !(end_hz < nyquist)) throw_invalid(kOwner, "end_hz", end_hz, nyq);
  validate();
  const double f_low = std::min(start_hz, end_hz);
  const double ticks = std::round(update_s / ts);
  if (ticks * ts * f_low < 1.0 - 1e-9)
    throw_invalid(kOwner, "update_s", update_s,
                  "is too short: each point must hold at least one whole period of the lowest frequency " +
                      format_value(f_low) + " Hz, i.e. update_s >= " + format_value(1.0 / f_low) + " s");
}

std::vector<double> SineSweepOptions::frequencies_hz() const {
  std::vector<double> f(points);
  for (int i = 0; i < points; ++i)
    f[i] = start_hz * std::pow(end_hz / start_hz, static_cast<double>(i) / (points - 1));
  f.back() = end_hz;
  return f;
}

namespace {
// Output-stage and drive limits the point judge checks.
struct Limits {
  double dac_v = 10.0;            // DAC full scale, V
  double amps_per_volt = 0.0;     // torque drive (0: none)
  double max_current_a = kInfinity;
  double max_torque_nm = kInfinity;  // velocity drive
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
};
Limits limits_of(const machine::AxisConfig& c) {
  Limits l;
  l.dac_v = c.dac.full_scale_v;
  if (const auto* t = std::get_if<drive::TorqueDriveParams>(&c.drive)) {
    l.amps_per_volt = t->amps_per_volt;
    l.max_current_a = t->max_current_a();
  } else if (const auto* v = std::get_if<drive::VelocityDriveParams>(&c.drive)) {
    l.max_torque_nm = v->max_torque_nm();
  }
  return l;
}
void append(std::string& s, const std::string& what) { s += (s.empty() ? "" : "; ") + what; }
}  // namespace

SineSweepResult sine_sweep(machine::Axis& axis, const SineSweepOptions& options, const SweepProgress& progress) {
  const double ts = axis.servo_period_s();
  options.validate(ts);
  if (axis.power_train().pulse_input())
    throw std::invalid_argument("SineSweep: a pulse-output axis (stepper or servo in position mode) has no position "
                                "loop on the card to measure");
  const machine::AxisConfig saved = axis.config();
  const Limits lim = limits_of(saved);
  const std::vector<double> freqs = options.frequencies_hz();
  // Automatic amplitude: the linear model's DAC counts per pulse of command, U/R = F C / (1 + L).
  std::vector<double> auto_amp;
  if (options.amplitude_pulse == 0.0) {
    const LoopResponse lr = loop_response(saved, freqs, options.loop);
    const double cap = options.max_amplitude_pulse > 0 ? options.max_amplitude_pulse : saved.encoder.counts_per_rev;
    const double u_max = options.dac_fraction * 32767.0 *
                         std::min(1.0, lim.amps_per_volt > 0 && std::isfinite(lim.max_current_a)
                                           ? lim.max_current_a / (lim.amps_per_volt * lim.dac_v)
                                           : 1.0);
    for (std::size_t i = 0; i < freqs.size(); ++i) {
      const double u_per_r = std::abs(lr.filters[i] * (lr.controller[i] + lr.feedforward[i]) / (1.0 + lr.loop_gain[i]));
      auto_amp.push_back(std::min(cap, u_per_r > 0 ? u_max / u_per_r : cap));
    }
  }
  axis.set_law(law_for_measurement(saved.law, options.loop));
  axis.set_filters(filters_for_measurement(saved.filters, options.loop));

  const auto n_tick = static_cast<std::size_t>(std::llround(options.update_s / ts));
  const auto settle = static_cast<std::size_t>(std::floor(options.settle_fraction * static_cast<double>(n_tick)));
  std::vector<double> cmd(n_tick), y(n_tick), e(n_tick), u(n_tick), volts(n_tick), torque(n_tick), law_u(n_tick);
  machine::Trace trace;
  trace.fb_pos = y.data();
  trace.error = e.data();
  trace.biquad1 = u.data();
  trace.u = law_u.data();
  trace.volts = volts.data();
  trace.torque_nm = torque.data();
  machine::RunGuard guard;
  guard.error_limit_pulse = options.deviation_limit_pulse;
  guard.stop_on_alarm = true;

  SineSweepResult res;
  const double base = axis.last_command_pulse();
  double phase = 0.0;  // of the command sine, continuous across points
  double prev_amp = 0.0;  // amplitude at the end of the previous point (0: the sweep starts from rest)
  bool ended = false;
  for (std::size_t i = 0; i < freqs.size() && !ended; ++i) {
    const double f = freqs[i];
    const double w = 2.0 * M_PI * f * ts;  // rad per tick
    double amp = options.amplitude_pulse > 0 ? options.amplitude_pulse : auto_amp[i];
    int tries = 0, dac_sat = 0, cur_sat = 0, trq_sat = 0;
    // Analysis window (known before the run): the last whole periods after the settling share.
    const double per = 1.0 / (f * ts);  // samples per period
    // The settling share is cut short where it would leave less than one whole period (decisions B4).
    const double usable = std::max(static_cast<double>(n_tick - settle), std::min(per, static_cast<double>(n_tick)));
    const int m_max = static_cast<int>(std::floor(usable / per + 1e-9));
    const int m = best_periods(per, std::max(m_max, 1));
    const int len = std::min(static_cast<int>(n_tick), std::max(3, static_cast<int>(std::lround(m * per))));
    const std::size_t start = n_tick - static_cast<std::size_t>(len);
    // Over the first quarter of the settling share the amplitude moves from the previous point's to this one's on
    // a raised cosine: no step of command velocity between points (decisions Q6).
    // With the automatic amplitude the first point is preceded by a lead-in of the same length whose amplitude
    // rises from 0 on a raised cosine (discarded): the loop is in its periodic steady state when the first window
    // starts, even where the window is the whole point (decisions Q6).
    bool lead_in = (i == 0 && options.amplitude_pulse == 0.0);  // automatic amplitude only: a given one keeps the
                                                                  // manual's timing (points x update_s)
    for (;;) {
      ++tries;
      const double phase0 = phase;
      {
        // sin(phase0 + w k) = sin(phase0) cos(w k) + cos(phase0) sin(w k)
        unit_phasors(w, static_cast<int>(n_tick), y.data(), e.data());  // scratch, overwritten by the run
        const double s0 = std::sin(phase0), c0 = std::cos(phase0);
        const std::size_t ramp = lead_in ? n_tick : start / 4;  // the rest of the settling lets the transient die out
        for (std::size_t k = 0; k < n_tick; ++k) {
          const double blend = k < ramp ? 0.5 - 0.5 * std::cos(M_PI * static_cast<double>(k) / ramp) : 1.0;
          const double a = prev_amp + (amp - prev_amp) * blend;
          cmd[k] = base + a * (s0 * y[k] + c0 * e[k]);
        }
      }
      phase = std::fmod(phase0 + w * static_cast<double>(n_tick), 2.0 * M_PI);
      machine::CommandInput in;
      in.pos = cmd.data();
      in.n = n_tick;
      const machine::RunOutcome out = axis.run(in, trace, guard);
      res.ticks += static_cast<long long>(out.ticks);
      if (out.stop != machine::RunStop::kCompleted) {
        res.stop_time_s = static_cast<double>(res.ticks) * ts;
        if (out.stop == machine::RunStop::kErrorLimit) {
          res.status = SweepStatus::kDeviationExceeded;
          res.stop_error_pulse = out.error_pulse;
          res.message = "deviation limit exceeded at " + format_value(f) + " Hz (amplitude " + format_value(amp) +
                        " pulse): |E| = " + format_value(std::fabs(out.error_pulse)) + " pulse > " +
                        format_value(options.deviation_limit_pulse) + " pulse; servo turned off";
        } else {
          res.status = SweepStatus::kDriveAlarm;
          res.message = "drive alarm at " + format_value(f) + " Hz; servo turned off";
        }
        ended = true;
        break;
      }
      if (lead_in) {
        lead_in = false;
        prev_amp = amp;
        --tries;
        continue;
      }
      dac_sat = cur_sat = trq_sat = 0;
      for (std::size_t k = start; k < n_tick; ++k) {  // over the analysed window
        if (std::fabs(volts[k]) >= lim.dac_v * (1 - 1e-9) || std::fabs(law_u[k]) >= 32767.0 ||
            std::fabs(u[k]) >= 32767.0)
          ++dac_sat;
        if (lim.amps_per_volt > 0 && std::fabs(lim.amps_per_volt * volts[k]) >= lim.max_current_a * (1 - 1e-9))
          ++cur_sat;
        if (std::fabs(torque[k]) >= lim.max_torque_nm * (1 - 1e-9)) ++trq_sat;
      }
      if (options.amplitude_pulse > 0 || (dac_sat + cur_sat + trq_sat) == 0 || tries >= 7) break;
      prev_amp = amp;
      amp *= 0.5;
    }
    if (ended) break;
    prev_amp = amp;
    const SineFit fit(w, len);
    for (int k = 0; k < len; ++k) cmd[static_cast<std::size_t>(k)] = cmd[start + static_cast<std::size_t>(k)] - base;
    double resid = 0.0;
    res.freq_hz.push_back(f);
    res.r.push_back(fit.fit(cmd.data()));
    res.e.push_back(fit.fit(e.data() + start));
    res.u.push_back(fit.fit(u.data() + start));
    res.y.push_back(fit.fit(y.data() + start, &resid));
    res.coherence.push_back(std::clamp(1.0 - resid, 0.0, 1.0));
    double harm = 0.0, y_mean = 0.0;
    for (int k = 0; k < len; ++k) y_mean += y[start + static_cast<std::size_t>(k)];
    y_mean /= len;
    for (int h = 2; h <= 5 && h * f < 0.5 / ts; ++h) {
      const double a = harmonic_amplitude(y.data() + start, len, h * w, y_mean);
      harm += a * a;
    }
    const double fund = std::abs(res.y.back());
    res.distortion.push_back(fund > 0 ? std::sqrt(harm) / fund : 0.0);
    res.periods.push_back(m);
    res.window.push_back(len);
    res.amplitude_pulse.push_back(amp);
    res.torque_amplitude_nm.push_back(std::abs(fit.fit(torque.data() + start)));
    res.dac_saturated_ticks.push_back(dac_sat);
    res.current_saturated_ticks.push_back(cur_sat);
    res.torque_saturated_ticks.push_back(trq_sat);
    res.tries.push_back(tries);
    std::string flag;
    if (dac_sat > 0) append(flag, "DAC saturated " + std::to_string(dac_sat) + " ticks");
    if (cur_sat > 0) append(flag, "current command clamped " + std::to_string(cur_sat) + " ticks");
    if (trq_sat > 0) append(flag, "torque at the drive limit " + std::to_string(trq_sat) + " ticks");
    if (res.coherence.back() < options.min_coherence)
      append(flag, "coherence " + format_value(res.coherence.back()) + " < " + format_value(options.min_coherence));
    if (res.distortion.back() > options.max_distortion)
      append(flag, "distortion " + format_value(res.distortion.back()) + " > " + format_value(options.max_distortion));
    if (saved.encoder.quantize && std::abs(res.y.back()) < options.min_response_pulse)
      append(flag, "|Y| " + format_value(std::abs(res.y.back())) + " pulse < " +
                       format_value(options.min_response_pulse) + " (encoder quantisation)");
    if (saved.dac.quantize && std::abs(res.u.back()) < options.min_dac_counts)
      append(flag, "|U| " + format_value(std::abs(res.u.back())) + " counts < " +
                       format_value(options.min_dac_counts) + " (DAC quantisation)");
    res.flag.push_back(flag);
    if (progress && !progress(static_cast<int>(i + 1), static_cast<int>(freqs.size()))) {
      if (i + 1 < freqs.size()) {
        res.status = SweepStatus::kStopped;
        res.message = "stopped by the user after " + std::to_string(i + 1) + " of " + std::to_string(freqs.size()) +
                      " points";
        res.stop_time_s = static_cast<double>(res.ticks) * ts;
        break;
      }
    }
  }
  if (res.status == SweepStatus::kCompleted) {
    res.stop_time_s = static_cast<double>(res.ticks) * ts;
    std::size_t bad = 0;
    for (const auto& fl : res.flag) bad += fl.empty() ? 0 : 1;
    res.message = "completed " + std::to_string(res.freq_hz.size()) + " points in " + format_value(res.stop_time_s) +
                  " s of card time" +
                  (bad ? "; " + std::to_string(bad) + " flagged (saturation, coherence, distortion or quantisation)"
                       : "; every point passed the checks");
  }
  axis.set_law(saved.law);
  axis.set_filters(saved.filters);
  return res;
}

}  // namespace servobench::tuning
