#include "servobench/tuning/relay_autotune.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {
constexpr const char* kOwner = "RelayTune";
constexpr const char* kManual = "ADLINK auto-tuning, L1842-1847";
constexpr double kCountsPerVolt = 32767.0 / 10.0;
constexpr double kDeg = 180.0 / M_PI;

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
double rel_std(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  s = v.size() > 1 ? std::sqrt(s / static_cast<double>(v.size() - 1)) : 0.0;
  return m != 0 ? s / std::fabs(m) : 0.0;
}
}  // namespace

void RelayTuneOptions::validate() const {
  if (!(amplitude_v > 0) || !(amplitude_v <= 10))
    throw_invalid(kOwner, "amplitude_v", amplitude_v, "is outside the allowed range 0 < d <= 10 V (" +
                                                          std::string(kManual) + ")");
  check_positive(kOwner, "hysteresis_pulse", hysteresis_pulse);
  check_integer(kOwner, "data_length", data_length, 1, 100000, kManual);
  check_range(kOwner, "sampling_time_s", sampling_time_s, 100e-6, 1000e-6, kManual);
  check_nonnegative(kOwner, "deviation_limit_pulse", deviation_limit_pulse);
  if (!(max_spread > 0) || !(max_spread <= 1))
    throw_invalid(kOwner, "max_spread", max_spread, "is outside the allowed range 0 < spread <= 1 (L1794: 0.1)");
  check_range(kOwner, "phase_margin_deg", phase_margin_deg, 10.0, 89.0);
  check_range(kOwner, "alpha", alpha, 1.0, 100.0);
  check_integer(kOwner, "settle_cycles", settle_cycles, 0, 1000);
  check_positive(kOwner, "max_cycle_s", max_cycle_s);
}

PidDesign design_pid_for_phase_margin(std::complex<double> g, double freq_hz, double ts, double pm_deg,
                                      double alpha, double extra_delay_s) {
  using C = std::complex<double>;
  const double w = 2.0 * M_PI * freq_hz;
  const double th = w * ts;
  if (!(th > 0) || th >= M_PI) throw_invalid("design_pid", "freq_hz", freq_hz, "must be > 0 and below Nyquist");
  // Wanted controller value: C* = 1 at (-180 + PM) divided by the loop's plant part.
  const C target = std::polar(1.0, (-180.0 + pm_deg) / kDeg) / (g * std::exp(C(0.0, -w * extra_delay_s)));
  const double phi = std::arg(target);
  // The law's z-transfer with ki = kp/(alpha x), kd = kp x, x = Td/Ts: C = kp Q(x).
  const C a = C(0.5, -0.5 / std::tan(th / 2));              // 1/(1 - z^-1)
  const C b = C(2 * std::pow(std::sin(th / 2), 2), std::sin(th));  // 1 - z^-1
  auto q = [&](double x) { return 1.0 + a / (alpha * x) + b * x; };
  double lo = std::log(1e-9), hi = std::log(1e9);
  auto f = [&](double lx) {
    double d = std::arg(q(std::exp(lx))) - phi;
    return std::remainder(d, 2 * M_PI);
  };
  if (!(f(lo) < 0 && f(hi) > 0))
    throw std::invalid_argument("design_pid: no PID with Ti = " + format_value(alpha) + " Td reaches the phase " +
                                format_value(phi * kDeg) + " deg needed at " + format_value(freq_hz) +
                                " Hz (the plant point's phase leaves no room for a " + format_value(pm_deg) +
                                " deg margin)");
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  const double x = std::exp(0.5 * (lo + hi));
  PidDesign d;
  d.kp = std::abs(target) / std::abs(q(x)) * kCountsPerVolt;  // V/pulse -> counts/pulse
  d.ki = d.kp / (alpha * x);
  d.kd = d.kp * x;
  d.kc = d.kp;
  d.td_s = x * ts;
  d.ti_s = alpha * d.td_s;
  return d;
}

namespace {
PidDesign from_continuous(double kc, double ti, double td, double ts) {
  PidDesign d;
  d.kc = kc;
  d.ti_s = ti;
  d.td_s = td;
  d.kp = kc;
  d.ki = kc * ts / ti;
  d.kd = kc * td / ts;
  return d;
}
}  // namespace

PidDesign ziegler_nichols(double ku, double tu, double ts) { return from_continuous(0.6 * ku, tu / 2, tu / 8, ts); }
PidDesign tyreus_luyben(double ku, double tu, double ts) {
  return from_continuous(ku / 2.2, 2.2 * tu, tu / 6.3, ts);
}

control::GtServoLawParams to_gt_law(const PidDesign& d, const control::GtServoLawParams& base) {
  control::GtServoLawParams p = base;
  auto fit = [](const char* name, double v) {
    const double r = std::round(v);
    if (!(r >= 0 && r <= 32767))
      throw_invalid("to_gt_law", name, r, "does not fit the GT gain range 0..32767 (GT manual Table 3-4)");
    return r;
  };
  p.kp = fit("kp", d.kp);
  p.ki = fit("ki", d.ki * 256.0);
  p.kd = fit("kd", d.kd);
  p.kvff = 0;
  p.kaff = 0;
  return p;
}

control::ApsServoLawParams to_aps_law(const PidDesign& d, const control::ApsServoLawParams& base) {
  control::ApsServoLawParams p = base;
  p.pid_shift = -5;
  auto fit = [&](double g, double& k, double& shift, const char* name) {
    if (g == 0) {
      k = 0;
      shift = 0;
      return;
    }
    // g = K 2^(shift + pid): the smallest exponent that keeps K <= 65535.
    int e = static_cast<int>(std::ceil(std::log2(g / 65535.0)));
    double kk = std::round(std::ldexp(g, -e));
    if (kk > 65535) kk = std::round(std::ldexp(g, -(++e)));
    const int s = e - static_cast<int>(p.pid_shift);
    if (s < -31 || s > 31)
      throw_invalid("to_aps_law", name, g, "cannot be represented with a shift in -31..31 (ADLINK L1753-1758)");
    k = kk;
    shift = s;
  };
  fit(d.kp, p.kp, p.kp_shift, "kp");
  fit(d.ki, p.ki, p.ki_shift, "ki");
  fit(d.kd, p.kd, p.kd_shift, "kd");
  p.kvff = 0;
  p.kaff = 0;
  return p;
}

RelayTuneResult relay_autotune(machine::Axis& axis, const RelayTuneOptions& o, const TuneProgress& progress) {
  o.validate();
  if (axis.power_train().pulse_input())
    throw std::invalid_argument("RelayTune: a pulse-output axis (stepper or servo in position mode) has no analog "
                                "output to drive the relay with");
  const double ts = axis.servo_period_s();
  // The relay decides at the first tick at or after each multiple of its sampling time, exactly (no rounding to
  // whole ticks: 250 us on a 100 us axis decides after 2, 3, 2, 3, ... ticks; decisions Q8); never more often than
  // every tick.
  const double per_tick = ts / o.sampling_time_s;  // relay samples per tick
  auto decides = [per_tick](long long k) {
    return k == 0 || std::floor(static_cast<double>(k) * per_tick + 1e-9) !=
                         std::floor(static_cast<double>(k - 1) * per_tick + 1e-9);
  };
  RelayTuneResult res;
  res.sampling_time_s = std::max(o.sampling_time_s, ts);
  const double sign = std::visit(
      [](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, control::ApsServoLawParams>) return p.v_inverse ? -1.0 : 1.0;
        return 1.0;
      },
      axis.config().law);
  const double d = o.amplitude_v, eps = o.hysteresis_pulse;
  const double r = axis.feedback_pulse();
  double u = d;  // the kick: the relay starts on +d
  long long tick = 0;
  std::vector<long long> rising;  // ticks at which u switched from -d to +d (decision ticks)
  std::vector<double> e_hist, u_hist;
  const std::function<double(std::size_t, double, double)> relay = [&](std::size_t, double cmd, double fb) {
    const double e = cmd - fb;
    if (decides(tick)) {
      if (e > eps) {
        if (u < 0) rising.push_back(tick);
        u = d;
      } else if (e < -eps) {
        u = -d;
      }
    }
    e_hist.push_back(e);
    u_hist.push_back(u);
    return sign * u;
  };
  machine::CommandInput in;
  in.pos = &r;
  in.n = 1;
  in.external = &relay;
  double pos_lim = 0, neg_lim = 0, alarm = 0;
  machine::Trace tr;
  tr.pos_limit_sw = &pos_lim;
  tr.neg_limit_sw = &neg_lim;
  tr.alarm = &alarm;
  machine::RunGuard guard;
  guard.error_limit_pulse = o.deviation_limit_pulse;
  guard.stop_on_alarm = true;

  const auto max_ticks = static_cast<long long>(std::ceil(o.max_cycle_s / ts));
  std::size_t analysed = 0;  // cycles analysed so far (index into `rising`)
  auto stop = [&](TuneStatus s, const std::string& msg) {
    res.status = s;
    res.message = msg;
    axis.set_servo_on(false);
  };
  bool done = false;
  while (!done) {
    const machine::RunOutcome out = axis.run(in, tr, guard);
    ++tick;
    if (out.stop == machine::RunStop::kErrorLimit) {
      stop(TuneStatus::kDeviationExceeded, "position deviation |e| = " + format_value(std::fabs(out.error_pulse)) +
                                               " pulse exceeded the deviation limit " +
                                               format_value(o.deviation_limit_pulse) + " pulse; servo off");
      break;
    }
    if (out.stop == machine::RunStop::kDriveAlarm || alarm != 0) {
      stop(TuneStatus::kLimitOrAlarm, "drive alarm (ALM); servo off");
      break;
    }
    if (pos_lim != 0 || neg_lim != 0) {
      stop(TuneStatus::kLimitOrAlarm,
           std::string(pos_lim != 0 ? "positive" : "negative") + " limit switch (" + (pos_lim != 0 ? "PEL" : "MEL") +
               ") reached; servo off");
      break;
    }
    // A new complete cycle: analyse rising[i] .. rising[i+1].
    while (analysed + 1 < rising.size()) {
      const long long t0 = rising[analysed], t1 = rising[analysed + 1];
      ++analysed;
      if (static_cast<int>(analysed) <= o.settle_cycles) continue;
      const auto n = static_cast<std::size_t>(t1 - t0);
      const double tu = static_cast<double>(n) * ts;
      const double w = 2.0 * M_PI / static_cast<double>(n);
      std::complex<double> acc = 0.0;
      double mx = -1e300, mn = 1e300, c = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        const double e = e_hist[static_cast<std::size_t>(t0) + k];
        acc += e * std::exp(std::complex<double>(0.0, -w * static_cast<double>(k)));
        mx = std::max(mx, e);
        mn = std::min(mn, e);
        c += e;
      }
      const double a = 2.0 * std::abs(acc) / static_cast<double>(n);
      if (!(a > eps)) {
        stop(TuneStatus::kNoOscillation, "the limit cycle's amplitude " + format_value(a) +
                                             " pulse is not above the hysteresis " + format_value(eps) +
                                             " pulse: raise the amplitude or lower the hysteresis");
        done = true;
        break;
      }
      const double gain = M_PI * a / (4.0 * d);
      const double phase = -M_PI + std::asin(eps / a);
      const double fu = 1.0 / tu;
      PidDesign pid;
      try {
        pid = design_pid_for_phase_margin(std::polar(gain, phase), fu, ts, o.phase_margin_deg, o.alpha,
                                          0.5 * (ts - res.sampling_time_s));
      } catch (const std::invalid_argument& ex) {
        stop(TuneStatus::kNoOscillation, ex.what());
        done = true;
        break;
      }
      res.period_s.push_back(tu);
      res.amplitude_pulse.push_back(a);
      res.peak_pulse.push_back(0.5 * (mx - mn));
      res.center_pulse.push_back(c / static_cast<double>(n));
      res.gain_pulse_per_v.push_back(gain);
      res.phase_deg.push_back(phase * kDeg);
      res.kp.push_back(pid.kp);
      res.ki.push_back(pid.ki);
      res.kd.push_back(pid.kd);
      if (progress && !progress(static_cast<int>(res.kp.size()), o.data_length)) {
        stop(TuneStatus::kUserStop, "stopped by the user after " + std::to_string(res.kp.size()) + " gain sets");
        done = true;
        break;
      }
      if (static_cast<int>(res.kp.size()) >= o.data_length) {
        done = true;
        break;
      }
    }
    const long long last = rising.empty() ? 0 : rising.back();
    if (!done && tick - last >= max_ticks) {
      stop(TuneStatus::kNoOscillation, "no limit cycle completed within " + format_value(o.max_cycle_s) +
                                           " s (after " + std::to_string(res.kp.size()) + " of " +
                                           std::to_string(o.data_length) +
                                           " gain sets): raise the amplitude or lower the hysteresis");
      break;
    }
  }
  res.ticks = tick;
  res.error_pulse = std::move(e_hist);
  res.output_v = std::move(u_hist);
  if (!res.kp.empty()) {
    res.mean.kp = mean(res.kp);
    res.mean.ki = mean(res.ki);
    res.mean.kd = mean(res.kd);
    res.mean.kc = res.mean.kp;
    res.mean.td_s = res.mean.kd / res.mean.kp * ts;
    res.mean.ti_s = res.mean.kp / res.mean.ki * ts;
    res.kp_spread = rel_std(res.kp);
    res.ki_spread = rel_std(res.ki);
    res.kd_spread = rel_std(res.kd);
    double f = 0, k = 0;
    for (std::size_t i = 0; i < res.period_s.size(); ++i) {
      f += 1.0 / res.period_s[i];
      k += 1.0 / res.gain_pulse_per_v[i];
    }
    res.ultimate_freq_hz = f / static_cast<double>(res.period_s.size());
    res.ultimate_gain_v_per_pulse = k / static_cast<double>(res.period_s.size());
  }
  if (res.status == TuneStatus::kCompleted) {
    const double worst = std::max({res.kp_spread, res.ki_spread, res.kd_spread});
    if (worst > o.max_spread) {
      stop(TuneStatus::kSpreadTooLarge, "gain fluctuation (relative standard deviation) KP " +
                                            format_value(100 * res.kp_spread) + " %, KI " +
                                            format_value(100 * res.ki_spread) + " %, KD " +
                                            format_value(100 * res.kd_spread) + " % exceeds " +
                                            format_value(100 * o.max_spread) + " %; servo off");
    } else {
      axis.set_servo_on(false);
      res.message = "completed: " + std::to_string(res.kp.size()) + " gain sets, fluctuation KP " +
                    format_value(100 * res.kp_spread) + " %, KI " + format_value(100 * res.ki_spread) + " %, KD " +
                    format_value(100 * res.kd_spread) + " %";
    }
  }
  return res;
}

}  // namespace servobench::tuning
