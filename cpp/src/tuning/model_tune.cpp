#include "servobench/tuning/model_tune.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include <Eigen/Dense>

#include "servobench/common/validate.hpp"
#include "servobench/control/filter_design.hpp"

namespace servobench::tuning {

namespace {

constexpr const char* kOwner = "ModelTune";
constexpr double kCountsPerVolt = 32767.0 / 10.0;

std::string fmt(double v, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}
std::string fixed(double v, int decimals = 1) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// Linear interpolation in log frequency is what margins() does; here the log-spaced grid.
std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> f(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    f[static_cast<std::size_t>(i)] = lo * std::pow(hi / lo, static_cast<double>(i) / static_cast<double>(n - 1));
  return f;
}

double db(Complex h) { return 20.0 * std::log10(std::abs(h)); }

// margins() over the points where L is not exactly zero (a floating-point notch's null can fall on a grid point);
// `crossovers`, when given, receives every gain crossover of the same points.
Margins margins_nonzero(const std::vector<double>& f, const std::vector<Complex>& l, const std::vector<Complex>& t,
                        const Stability& stability, std::vector<GainCrossover>* crossovers = nullptr) {
  std::vector<double> f2;
  std::vector<Complex> l2, t2;
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (l[k] == 0.0) continue;
    f2.push_back(f[k]);
    l2.push_back(l[k]);
    if (!t.empty()) t2.push_back(t[k]);
  }
  if (crossovers != nullptr) *crossovers = gain_crossovers(f2, l2);
  MarginsOptions o;
  o.stability = stability;
  return margins(f2, l2, t2, o);
}

// Everything a candidate evaluation needs, computed once.
struct Problem {
  machine::AxisConfig config;  // law = the base law of the requested kind, filters pass-through
  double ts = 0;
  std::vector<double> grid;
  std::vector<Complex> plant;  // P on the grid
  ModelTuneOptions o;
};

Complex plant_at(const Problem& pb, double f) {
  return loop_response(pb.config, {f}, LoopOptions{false, false}).plant[0];
}

machine::LawParams law_from(const PidDesign& pid, const machine::LawParams& base) {
  if (const auto* gt = std::get_if<control::GtServoLawParams>(&base)) return to_gt_law(pid, *gt);
  return to_aps_law(pid, std::get<control::ApsServoLawParams>(base));
}

// One filter option: biquad 0 = `filter` (pass-through when empty).
struct Option {
  std::optional<control::BiquadParams> filter;
  double q = 0, center_hz = 0;
  std::vector<Complex> f_grid;  // its response on the grid
};

CrossoverCandidate evaluate(const Problem& pb, const Option& opt, double fc) {
  CrossoverCandidate c;
  c.freq_hz = fc;
  const Complex ff = opt.filter ? std::visit([&](const auto& q) { return control::frequency_response(q, fc, pb.ts); },
                                             *opt.filter)
                                : Complex(1.0);
  const Complex g = plant_at(pb, fc) * ff * kCountsPerVolt;  // pulse per volt
  try {
    c.pid = design_pid_for_phase_margin(g, fc, pb.ts, pb.o.phase_margin_deg, pb.o.alpha);
  } catch (const std::invalid_argument&) {
    c.reason = "no PID with Ti = " + fmt(pb.o.alpha) + " Td reaches the phase needed";
    return c;
  }
  {
    const double th = 2.0 * M_PI * fc * pb.ts, x = c.pid.td_s / pb.ts;
    const Complex q = 1.0 + Complex(0.5, -0.5 / std::tan(th / 2)) / (pb.o.alpha * x) +
                      Complex(2 * std::pow(std::sin(th / 2), 2), std::sin(th)) * x;
    c.pid_lead_deg = std::arg(q) * 180.0 / M_PI;
  }
  if (c.pid_lead_deg > pb.o.max_pid_lead_deg) {
    c.reason = "the PID would need " + fixed(c.pid_lead_deg) + " deg of phase lead (max_pid_lead_deg = " +
               fmt(pb.o.max_pid_lead_deg) + ")";
    return c;
  }
  machine::AxisConfig cfg = pb.config;
  try {
    cfg.law = law_from(c.pid, pb.config.law);
  } catch (const std::invalid_argument& e) {
    c.reason = std::string("the gains do not fit the card law (") + e.what() + ")";
    return c;
  }
  if (opt.filter) cfg.filters[0] = *opt.filter;
  std::vector<Complex> l(pb.grid.size());
  for (std::size_t k = 0; k < pb.grid.size(); ++k)
    l[k] = opt.f_grid[k] * law_feedback_response(cfg.law, pb.grid[k], pb.ts) * pb.plant[k];
  std::vector<GainCrossover> crossovers;
  const LoopPoles poles = loop_poles(cfg);
  c.margins = margins_nonzero(pb.grid, l, {}, pole_stability(poles), &crossovers);
  c.max_pole_radius = poles.max_radius;
  const Margins& m = c.margins;
  // Every gain crossover must have the target margin (R11): a resonance lifted above 0 dB is gain-stabilised by
  // the notch, never left phase-stabilised (its phase moves with the load; decision R15).
  const GainCrossover* worst = nullptr;
  for (const GainCrossover& x : crossovers)
    if (worst == nullptr || std::fabs(x.phase_margin_deg - pb.o.phase_margin_deg) >
                                std::fabs(worst->phase_margin_deg - pb.o.phase_margin_deg))
      worst = &x;
  if (!(c.max_pole_radius < 1.0)) {
    c.reason = "the closed loop is unstable (pole |z| = " + fixed(c.max_pole_radius, 4) + ")";
  } else if (worst == nullptr) {
    c.reason = "the loop gain does not cross 0 dB in the band";
  } else if (std::fabs(worst->phase_margin_deg - pb.o.phase_margin_deg) > pb.o.pm_tolerance_deg) {
    c.reason = "PM " + fixed(worst->phase_margin_deg, 2) + " deg at " + fmt(worst->freq_hz, 4) + " Hz is outside " +
               fmt(pb.o.phase_margin_deg) + " +- " + fmt(pb.o.pm_tolerance_deg) + " deg" +
               (crossovers.size() > 1 ? " (" + std::to_string(crossovers.size()) + " gain crossovers)" : "");
  } else if (m.gain_margin_db < pb.o.min_gain_margin_db) {
    c.reason = "GM " + fixed(m.gain_margin_db, 2) + " dB at " + fmt(m.gm_freq_hz, 4) + " Hz is below " +
               fmt(pb.o.min_gain_margin_db) + " dB";
  } else if (m.ms > pb.o.max_ms) {
    c.reason = "Ms " + fixed(m.ms, 3) + " at " + fmt(m.ms_freq_hz, 4) + " Hz is above " + fmt(pb.o.max_ms);
  } else {
    c.feasible = true;
  }
  return c;
}

struct OptionOutcome {
  std::vector<CrossoverCandidate> scan;  // by frequency, refinements included
  int best = -1;                         // index into scan of the highest feasible candidate
  int limit = -1;                        // the first failure above it (-1: none, the range's end)
};

OptionOutcome scan_option(const Problem& pb, const Option& opt, double f_lo, double f_hi) {
  OptionOutcome out;
  const std::vector<double> fcs = log_grid(f_lo, f_hi, pb.o.candidates);
  for (double fc : fcs) out.scan.push_back(evaluate(pb, opt, fc));
  // The highest feasible candidate (integer gains can make the feasible set ragged), and the one just above it.
  for (std::size_t i = out.scan.size(); i-- > 0;) {
    if (out.scan[i].feasible) {
      out.best = static_cast<int>(i);
      if (i + 1 < out.scan.size()) out.limit = static_cast<int>(i + 1);
      break;
    }
  }
  if (out.best >= 0 && out.limit >= 0) {
    // Bisection (in log frequency) between the last feasible and the first failing candidate.
    CrossoverCandidate good = out.scan[static_cast<std::size_t>(out.best)];
    CrossoverCandidate bad = out.scan[static_cast<std::size_t>(out.limit)];
    for (int it = 0; it < 12; ++it) {
      const double mid = std::sqrt(good.freq_hz * bad.freq_hz);
      CrossoverCandidate c = evaluate(pb, opt, mid);
      (c.feasible ? good : bad) = c;
      out.scan.push_back(std::move(c));
    }
    std::sort(out.scan.begin(), out.scan.end(),
              [](const CrossoverCandidate& a, const CrossoverCandidate& b) { return a.freq_hz < b.freq_hz; });
    for (std::size_t i = 0; i < out.scan.size(); ++i) {
      if (out.scan[i].freq_hz == good.freq_hz) out.best = static_cast<int>(i);
      if (out.scan[i].freq_hz == bad.freq_hz) out.limit = static_cast<int>(i);
    }
  }
  return out;
}

// A lightly damped resonance is narrower than the log grid's step can resolve to a hundredth of a dB: a peak
// between two points would hide a gain crossover of the loop. 64 more points between the neighbours of every
// local extreme of |P| (peaks and dips) put the grid's miss of a peak below 0.01 dB for damping down to 0.1 %.
void refine_at_peaks(Problem& pb) {
  const std::vector<double>& f = pb.grid;
  std::vector<double> extra;
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    const double a = std::abs(pb.plant[k - 1]), b = std::abs(pb.plant[k]), c = std::abs(pb.plant[k + 1]);
    if (!((b > a && b >= c) || (b < a && b <= c))) continue;
    const std::vector<double> fine = log_grid(f[k - 1], f[k + 1], 66);
    extra.insert(extra.end(), fine.begin() + 1, fine.end() - 1);
  }
  if (extra.empty()) return;
  std::vector<double> grid = f;
  grid.insert(grid.end(), extra.begin(), extra.end());
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  pb.grid = std::move(grid);
  pb.plant = loop_response(pb.config, pb.grid, LoopOptions{false, false}).plant;
}

machine::LawParams base_law(const machine::AxisConfig& config, TuneLaw kind) {
  switch (kind) {
    case TuneLaw::kAxis: return config.law;
    case TuneLaw::kGt:
      if (std::holds_alternative<control::GtServoLawParams>(config.law)) return config.law;
      return control::GtServoLawParams{};
    case TuneLaw::kAps:
      if (std::holds_alternative<control::ApsServoLawParams>(config.law)) return config.law;
      return control::ApsServoLawParams{};
  }
  return config.law;
}

}  // namespace

namespace {
// The ranges that do not depend on the servo period, in the order of the option table.
void check_scalar_ranges(const ModelTuneOptions& o) {
  check_range(kOwner, "phase_margin_deg", o.phase_margin_deg, 10.0, 89.0);
  check_range(kOwner, "alpha", o.alpha, 1.0, 100.0);
  check_range(kOwner, "pm_tolerance_deg", o.pm_tolerance_deg, 0.1, 20.0);
  check_range(kOwner, "min_gain_margin_db", o.min_gain_margin_db, 0.0, 60.0);
  check_range(kOwner, "max_ms", o.max_ms, 1.05, 10.0);
  check_range(kOwner, "max_pid_lead_deg", o.max_pid_lead_deg, 5.0, 89.0);
  check_range(kOwner, "min_resonance_prominence_db", o.min_resonance_prominence_db, 0.1, 60.0);
}
}  // namespace

void ModelTuneOptions::validate() const {
  check_scalar_ranges(*this);
  if (resonance_hz != 0.0) check_positive(kOwner, "resonance_hz", resonance_hz);
  if (notch_q_set.empty() && notch)
    throw std::invalid_argument("ModelTune.notch_q_set is empty; give at least one q (0.1..100) or notch = false");
  for (double q : notch_q_set) check_range(kOwner, "notch_q_set[i]", q, 0.1, 100.0);
  check_positive(kOwner, "min_crossover_hz", min_crossover_hz);
  if (max_crossover_hz != 0.0) check_positive(kOwner, "max_crossover_hz", max_crossover_hz);
  check_integer(kOwner, "candidates", candidates, 4, 10000);
  check_integer(kOwner, "points", points, 100, 200000);
}

void ModelTuneOptions::validate(double ts) const {
  check_scalar_ranges(*this);
  const double nyq = 0.5 / ts;
  if (resonance_hz != 0.0 && !(resonance_hz > 0 && resonance_hz < nyq))
    throw_invalid(kOwner, "resonance_hz", resonance_hz,
                  "is outside the allowed range 0 < f < " + format_value(nyq) + " Hz (Nyquist); 0 = find it");
  if (notch_q_set.empty() && notch)
    throw std::invalid_argument("ModelTune.notch_q_set is empty; give at least one q (0.1..100) or notch = false");
  for (double q : notch_q_set) check_range(kOwner, "notch_q_set[i]", q, 0.1, 100.0);
  if (!(min_crossover_hz > 0 && min_crossover_hz < 0.45 / ts))
    throw_invalid(kOwner, "min_crossover_hz", min_crossover_hz,
                  "is outside the allowed range 0 < f < " + format_value(0.45 / ts) + " Hz (0.45 / Ts)");
  if (max_crossover_hz != 0.0 && !(max_crossover_hz > min_crossover_hz && max_crossover_hz < nyq))
    throw_invalid(kOwner, "max_crossover_hz", max_crossover_hz,
                  "is outside the allowed range min_crossover_hz < f < " + format_value(nyq) +
                      " Hz (Nyquist); 0 = 0.45 / Ts");
  check_integer(kOwner, "candidates", candidates, 4, 10000);
  check_integer(kOwner, "points", points, 100, 200000);
}

std::vector<ResonancePeak> plant_resonances(const std::vector<double>& f, const std::vector<Complex>& h,
                                            double min_prominence_db, double max_width_decades) {
  const std::size_t n = f.size();
  std::vector<ResonancePeak> out;
  if (n < 3 || h.size() != n) return out;
  std::vector<double> x(n), y(n);
  for (std::size_t k = 0; k < n; ++k) {
    x[k] = std::log10(f[k]);
    y[k] = db(h[k]) + 40.0 * x[k];
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (!(y[i] > y[i - 1] && y[i] >= y[i + 1])) continue;
    double left_min = y[i], right_min = y[i];
    for (std::size_t j = i + 1; j-- > 0;) {
      if (y[j] > y[i]) break;
      left_min = std::min(left_min, y[j]);
    }
    for (std::size_t j = i; j < n; ++j) {
      if (y[j] > y[i]) break;
      right_min = std::min(right_min, y[j]);
    }
    const double prom = y[i] - std::max(left_min, right_min);
    if (prom < min_prominence_db) continue;
    const double level = y[i] - 0.5 * prom;
    std::size_t lo = i, hi = i;
    while (lo > 0 && y[lo] > level) --lo;
    while (hi + 1 < n && y[hi] > level) ++hi;
    const double width = x[hi] - x[lo];
    if (width > max_width_decades) continue;
    out.push_back({f[i], prom, width});
  }
  std::sort(out.begin(), out.end(),
            [](const ResonancePeak& a, const ResonancePeak& b) { return a.prominence_db > b.prominence_db; });
  return out;
}

ModelTuneResult model_tune(const machine::AxisConfig& config_in, const ModelTuneOptions& o) {
  machine::AxisConfig config = config_in;
  config.validate_and_complete();
  {
    const machine::Axis probe(config);
    if (probe.power_train().pulse_input())
      throw std::invalid_argument(
          "ModelTune.drive: a pulse-input drive (stepper or servo in position mode) closes its position loop itself; "
          "there is no card PID to design. Use a torque- or velocity-mode drive (voltage output).");
  }
  const double ts = *config.servo_period_s;
  o.validate(ts);
  Problem pb;
  pb.o = o;
  pb.ts = ts;
  pb.config = config;
  pb.config.law = base_law(config, o.law);
  pb.config.filters = {control::AdlinkBiquadParams{}, control::AdlinkBiquadParams{}};
  pb.config.validate_and_complete();
  const double nyq = 0.5 / ts;
  const double f_lo = o.min_crossover_hz;
  const double f_hi = o.max_crossover_hz > 0 ? o.max_crossover_hz : 0.45 / ts;
  pb.grid = log_grid(std::min(0.1, f_lo / 10.0), 0.999 * nyq, o.points);
  pb.plant = loop_response(pb.config, pb.grid, LoopOptions{false, false}).plant;
  refine_at_peaks(pb);
  const bool aps = std::holds_alternative<control::ApsServoLawParams>(pb.config.law);

  ModelTuneResult res;
  // 1. Resonances.
  std::vector<double> centers;
  if (o.resonance_hz > 0) {
    res.resonance_hz = o.resonance_hz;
    res.resonance_given = true;
    centers.push_back(o.resonance_hz);
  } else {
    res.resonances = plant_resonances(pb.grid, pb.plant, o.min_resonance_prominence_db);
    for (std::size_t i = 0; i < res.resonances.size() && i < 3; ++i) centers.push_back(res.resonances[i].freq_hz);
    if (!res.resonances.empty()) {
      res.resonance_hz = res.resonances[0].freq_hz;
      res.resonance_prominence_db = res.resonances[0].prominence_db;
    }
  }
  // 2. Filter options: none, then a notch at each centre with each q.
  std::vector<Option> options(1);
  options[0].f_grid.assign(pb.grid.size(), Complex(1.0));
  std::vector<std::string> notch_notes;
  if (o.notch) {
    for (double center : centers) {
      for (double q : o.notch_q_set) {
        Option opt;
        opt.q = q;
        opt.center_hz = center;
        control::FloatBiquadParams fl;
        try {
          fl = control::notch(center, q, ts, true);
        } catch (const std::invalid_argument& e) {
          notch_notes.push_back(fmt(center, 4) + " Hz q " + fmt(q) + ": " + e.what());
          continue;
        }
        if (aps) {
          try {
            opt.filter = control::quantize_adlink(fl);
          } catch (const std::invalid_argument& e) {
            notch_notes.push_back(fmt(center, 4) + " Hz q " + fmt(q) + ": the card's integers fail (" + e.what() + ")");
            continue;
          }
        } else {
          opt.filter = fl;
        }
        opt.f_grid.resize(pb.grid.size());
        for (std::size_t k = 0; k < pb.grid.size(); ++k)
          opt.f_grid[k] = std::visit([&](const auto& p) { return control::frequency_response(p, pb.grid[k], ts); },
                                     *opt.filter);
        options.push_back(std::move(opt));
      }
    }
  }
  // 3. Scan every option; the highest feasible crossover wins (ties: the earlier option, i.e. no notch first).
  std::vector<OptionOutcome> outcomes;
  int win = -1;
  double win_f = 0;
  for (std::size_t i = 0; i < options.size(); ++i) {
    outcomes.push_back(scan_option(pb, options[i], f_lo, f_hi));
    const auto& oc = outcomes.back();
    if (oc.best >= 0) {
      const double f = oc.scan[static_cast<std::size_t>(oc.best)].freq_hz;
      if (f > win_f) {
        win_f = f;
        win = static_cast<int>(i);
      }
    }
  }
  if (outcomes[0].best >= 0)
    res.crossover_without_notch_hz = outcomes[0].scan[static_cast<std::size_t>(outcomes[0].best)].freq_hz;

  const std::string target = "PM " + fmt(o.phase_margin_deg) + " +- " + fmt(o.pm_tolerance_deg) + " deg, GM >= " +
                             fmt(o.min_gain_margin_db) + " dB, Ms <= " + fmt(o.max_ms);
  if (win < 0) {
    // The nearest miss: the candidate with the smallest PM error among those with a PID.
    const CrossoverCandidate* near = nullptr;
    for (const auto& oc : outcomes)
      for (const auto& c : oc.scan)
        if (std::isfinite(c.margins.phase_margin_deg) &&
            (!near || std::fabs(c.margins.phase_margin_deg - o.phase_margin_deg) <
                          std::fabs(near->margins.phase_margin_deg - o.phase_margin_deg)))
          near = &c;
    std::string msg = "ModelTune: no crossover in " + fmt(f_lo) + ".." + fmt(f_hi) + " Hz (min_crossover_hz.." +
                      "max_crossover_hz) meets " + target + " (phase_margin_deg, pm_tolerance_deg, " +
                      "min_gain_margin_db, max_ms)";
    if (near) msg += "; nearest: " + fmt(near->freq_hz, 4) + " Hz, where " + near->reason;
    msg += ". Relax min_gain_margin_db (0..60) or max_ms (1.05..10), lower phase_margin_deg (10..89), or widen the "
           "crossover range";
    throw std::invalid_argument(msg);
  }

  const Option& opt = options[static_cast<std::size_t>(win)];
  OptionOutcome& oc = outcomes[static_cast<std::size_t>(win)];
  const CrossoverCandidate& best = oc.scan[static_cast<std::size_t>(oc.best)];
  res.pid = best.pid;
  res.crossover_hz = best.freq_hz;
  res.law = law_from(best.pid, pb.config.law);
  res.filters = {control::AdlinkBiquadParams{}, control::AdlinkBiquadParams{}};
  if (opt.filter) res.filters[0] = *opt.filter;
  res.limited_by = oc.limit >= 0 ? oc.scan[static_cast<std::size_t>(oc.limit)].reason
                                 : "the end of the scanned range " + fmt(f_hi) + " Hz (max_crossover_hz)";
  const std::string limit_at =
      oc.limit >= 0 ? " at " + fmt(oc.scan[static_cast<std::size_t>(oc.limit)].freq_hz, 4) + " Hz" : "";
  // Predicted figures from the analytic loop of the configuration apply() writes.
  machine::AxisConfig fin = pb.config;
  fin.law = res.law;
  fin.filters = res.filters;
  const LoopResponse lr = loop_response(fin, pb.grid, LoopOptions{false, true});
  const LoopPoles poles = loop_poles(fin);
  res.margins = margins_nonzero(pb.grid, lr.loop_gain, lr.closed_loop, pole_stability(poles));
  res.max_pole_radius = poles.max_radius;
  if (opt.filter) {
    NotchDesign& nd = res.notch;
    nd.used = true;
    nd.center_hz = opt.center_hz;
    nd.q = opt.q;
    res.resonance_hz = opt.center_hz;
    for (const auto& p : res.resonances)
      if (p.freq_hz == opt.center_hz) res.resonance_prominence_db = p.prominence_db;
    const double r = std::sqrt(1.0 + 1.0 / (4.0 * opt.q * opt.q));
    nd.low_hz = nd.center_hz * (r - 1.0 / (2.0 * opt.q));
    nd.high_hz = nd.center_hz * (r + 1.0 / (2.0 * opt.q));
    nd.float_biquad = control::notch(nd.center_hz, opt.q, ts, true);
    try {
      nd.adlink_biquad = control::quantize_adlink(nd.float_biquad);
      nd.adlink_ok = true;
    } catch (const std::invalid_argument&) {
      nd.adlink_ok = false;
    }
    const auto resp = [&](double f) {
      return std::visit([&](const auto& p) { return control::frequency_response(p, f, ts); }, *opt.filter);
    };
    nd.depth_db = -db(resp(nd.center_hz));
    nd.phase_at_crossover_deg = std::arg(resp(res.crossover_hz)) * 180.0 / M_PI;
  }
  res.scan = oc.scan;

  // Summary.
  const Margins& m = res.margins;
  std::string s = "Model-based tuning: " + target + ", Ti = " + fmt(o.alpha) + " Td, law " +
                  (aps ? "ADLINK" : "GT") + ", servo period " + fmt(ts * 1e6) + " us\n";
  if (res.resonance_given) {
    s += "  resonance: " + fmt(res.resonance_hz, 4) + " Hz (given)\n";
  } else if (!res.resonances.empty()) {
    s += "  resonances (plant gain above a -40 dB/decade line, found in the analytic plant response):";
    for (const auto& p : res.resonances)
      s += " " + fmt(p.freq_hz, 4) + " Hz (+" + fixed(p.prominence_db) + " dB, " + fixed(p.width_decades, 2) + " dec)";
    s += "\n";
  } else {
    s += "  resonance: none stands out of a -40 dB/decade line by " + fmt(o.min_resonance_prominence_db) +
         " dB within 1 decade: no notch\n";
  }
  if (o.notch && !centers.empty()) {
    s += "  crossover without notch: " +
         (res.crossover_without_notch_hz > 0 ? fmt(res.crossover_without_notch_hz, 4) + " Hz" : std::string("none")) +
         (outcomes[0].limit >= 0 ? " (above it: " + outcomes[0].scan[static_cast<std::size_t>(outcomes[0].limit)].reason + ")"
                                 : std::string()) + "\n";
    for (double center : centers) {
      s += "  notch at " + fmt(center, 4) + " Hz, crossover per q:";
      for (std::size_t i = 1; i < options.size(); ++i) {
        if (options[i].center_hz != center) continue;
        const auto& oi = outcomes[i];
        s += " " + fmt(options[i].q) + ": " +
             (oi.best >= 0 ? fmt(oi.scan[static_cast<std::size_t>(oi.best)].freq_hz, 4) + " Hz" : std::string("none"));
        s += i + 1 < options.size() && options[i + 1].center_hz == center ? "," : "";
      }
      s += "\n";
    }
    for (const auto& n : notch_notes) s += "  notch " + n + "\n";
  } else if (!o.notch && !centers.empty()) {
    s += "  notch: off (notch = false)\n";
  }
  if (res.notch.used) {
    const NotchDesign& nd = res.notch;
    s += "  notch chosen: " + fmt(nd.center_hz, 4) + " Hz, q " + fmt(nd.q) + " (-3 dB " + fmt(nd.low_hz, 4) + ".." +
         fmt(nd.high_hz, 4) + " Hz), depth " + (nd.depth_db > 100 ? std::string("a null (> 100 dB)") : fixed(nd.depth_db) + " dB") + " at the resonance, " +
         fixed(nd.phase_at_crossover_deg) + " deg at the crossover; biquad 0 " +
         (aps ? "as the card's integers" : "in floating point") + "\n";
  } else if (o.notch && !centers.empty()) {
    s += "  notch: not used (no q raised the crossover above the loop without one)\n";
  }
  s += "  crossover: raised from " + fmt(f_lo) + " Hz to " + fmt(res.crossover_hz, 4) + " Hz; limited by " +
       res.limited_by + limit_at + "\n";
  s += "  PID: kc " + fmt(res.pid.kc, 4) + " counts/pulse, Ti " + fmt(res.pid.ti_s * 1e3, 4) + " ms, Td " +
       fmt(res.pid.td_s * 1e3, 4) + " ms; per tick kp " + fmt(res.pid.kp, 4) + ", ki " + fmt(res.pid.ki, 4) +
       ", kd " + fmt(res.pid.kd, 4) + "; PID phase lead " + fixed(best.pid_lead_deg) + " deg at the crossover\n";
  s += "  predicted (analytic loop, card integers): PM " + fixed(m.phase_margin_deg) + " deg at " +
       fmt(m.pm_freq_hz, 4) + " Hz, GM " + fixed(m.gain_margin_db) + " dB at " + fmt(m.gm_freq_hz, 4) + " Hz, Ms " +
       fixed(m.ms, 2) + ", bandwidth " + fmt(m.bandwidth_hz, 4) + " Hz, closed-loop poles |z| <= " +
       fixed(res.max_pole_radius, 4);
  res.summary = s;
  return res;
}

}  // namespace servobench::tuning
