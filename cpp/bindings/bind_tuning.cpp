// Bindings of the tuning layer: analytic loop response, stepped-sine sweep, margins. Thin: arrays in and out.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "flag.hpp"
#include "object_lock.hpp"
#include "param_class.hpp"
#include "result_table.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/tuning/loop_response.hpp"
#include "servobench/tuning/margins.hpp"
#include "servobench/tuning/model_tune.hpp"
#include "servobench/tuning/relay_autotune.hpp"
#include "servobench/tuning/sine_sweep.hpp"
#include "servobench/tuning/stability.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {

py::dict margins_dict(const tuning::Margins& mg) {
  py::dict d;
  put_described(d, mg);  // the single figures, named as tuning::Margins::describe() names them
  py::dict stability;
  put_described(stability, mg.stability);  // as tuning::Stability::describe() names them (OR1)
  d["stability"] = stability;
  std::vector<double> gf, gp, pf, pg;
  for (const auto& c : mg.gain_crossovers) {
    gf.push_back(c.freq_hz);
    gp.push_back(c.phase_margin_deg);
  }
  for (const auto& c : mg.phase_crossovers) {
    pf.push_back(c.freq_hz);
    pg.push_back(c.gain_margin_db);
  }
  d["gain_crossovers"] = py::dict(py::arg("freq_hz") = to_array(gf), py::arg("phase_margin_deg") = to_array(gp));
  d["phase_crossovers"] = py::dict(py::arg("freq_hz") = to_array(pf), py::arg("gain_margin_db") = to_array(pg));
  return d;
}

py::dict pid_dict(const tuning::PidDesign& p) {
  py::dict d;
  put_described(d, p);  // kc ... kd, as tuning::PidDesign::describe() names them (OR1)
  return d;
}

const char* status_name(tuning::SweepStatus s) {
  switch (s) {
    case tuning::SweepStatus::kCompleted: return "completed";
    case tuning::SweepStatus::kDeviationExceeded: return "deviation_exceeded";
    case tuning::SweepStatus::kDriveAlarm: return "drive_alarm";
    case tuning::SweepStatus::kStopped: return "stopped";
  }
  return "?";
}
}  // namespace

void bind_tuning(py::module_& m) {
  // The options, each described once in its C++ struct (describe(): name, default, unit, doc; decision OP3).
  ParamClass<tuning::SineSweepOptions>(m, "SineSweepOptions",
                                       "Options of the stepped-sine sweep (tuning/sine_sweep.hpp; ADLINK Bode tool, "
                                       "L1978-2045).")
      .described()
      .finish();
  ParamClass<tuning::RelayTuneOptions>(m, "RelayTuneOptions",
                                       "Options of the relay auto-tuning (tuning/relay_autotune.hpp; ADLINK L1764-1847).")
      .described()
      .finish();
  ParamClass<tuning::MarginsOptions>(m, "MarginsOptions",
                                     "Options of the Nyquist criterion on frequency-response data (tuning/margins.hpp).")
      .described()
      .finish();
  ParamClass<tuning::LoopOptions>(m, "LoopOptions",
                                  "What is in the loop during a measurement or an analytic response "
                                  "(tuning/loop_response.hpp; decisions B1-B2).")
      .described()
      .finish();
  m.attr("MARGINS_FIELDS") = described_fields<tuning::Margins>();
  m.attr("RELAY_TUNE_FIELDS") = described_fields<tuning::RelayTuneResult>();  // servobench.autotune.RelayTuneResult  // servobench.margins.Margins reads it
  // The results' fields described once (decision OR1): servobench.autotune.ModelTuneResult and its parts, the
  // stability verdict of a Margins, and the stepped sine's arrays (servobench.frequency.FrequencyResponse).
  m.attr("MODEL_TUNE_FIELDS") = described_fields<tuning::ModelTuneResult>();
  m.attr("PID_DESIGN_FIELDS") = described_fields<tuning::PidDesign>();
  m.attr("NOTCH_DESIGN_FIELDS") = described_fields<tuning::NotchDesign>();
  m.attr("RESONANCE_PEAK_FIELDS") = described_fields<tuning::ResonancePeak>();
  m.attr("CROSSOVER_CANDIDATE_FIELDS") = described_fields<tuning::CrossoverCandidate>();
  m.attr("STABILITY_FIELDS") = described_fields<tuning::Stability>();
  m.attr("SINE_SWEEP_FIELDS") = described_fields<tuning::SineSweepResult>();
  m.attr("MODEL_TUNE_NOTCH_Q") = py::tuple(py::cast(tuning::ModelTuneOptions{}.notch_q_set));  // its default
  ParamClass<tuning::ModelTuneOptions>(m, "ModelTuneOptions",
                                       "Options of the model-based PID and notch design (tuning/model_tune.hpp).")
      .described()
      .finish();
  m.def(
      "loop_response",
      [](const machine::Axis& axis, const py::object& freq, Flag feedforward, Flag filters) {
        const std::vector<double> f = real_vector(freq, "freq_hz");
        tuning::LoopOptions o;
        o.feedforward = feedforward;
        o.filters = filters;
        tuning::LoopResponse r;
        {
          py::gil_scoped_release release;
          r = tuning::loop_response(axis.config(), f, o);
        }
        py::dict d;
        d["freq_hz"] = to_array(r.freq_hz);
        d["controller"] = to_array(r.controller);
        d["feedforward"] = to_array(r.feedforward);
        d["filters"] = to_array(r.filters);
        d["plant"] = to_array(r.plant);
        d["loop_gain"] = to_array(r.loop_gain);
        d["open_loop"] = to_array(r.open_loop);
        d["closed_loop"] = to_array(r.closed_loop);
        d["sensitivity"] = to_array(r.sensitivity);
        return d;
      },
      py::arg("axis"), py::arg("freq_hz"), py::arg("feedforward") = false, py::arg("filters") = true,
      "Analytic responses of the axis's loop at freq_hz (Hz); returns {name: complex array}.");

  m.def(
      "sine_sweep",
      [](machine::Axis& axis, const tuning::SineSweepOptions& o, const py::object& progress) {
        o.validate(axis.servo_period_s());
        std::shared_ptr<py::error_already_set> interrupt;
        const tuning::SweepProgress cb = progress_callback(progress, &interrupt);
        tuning::SineSweepResult r;
        {
          RunLock lock({&axis});  // one run at a time on the axis; its other calls wait for the sweep
          py::gil_scoped_release release;
          auto held = lock.chunk();
          r = tuning::sine_sweep(axis, o, cb);
        }
        raise_pending(interrupt);
        py::dict d;
        d["status"] = status_name(r.status);
        d["message"] = r.message;
        put_described(d, r);  // freq_hz ... tries, as tuning::SineSweepResult::describe() names them (OR1)
        const tuning::LoopPoles poles = tuning::loop_poles(axis.config(), o.loop);
        d["integrators"] = poles.integrators;
        d["open_loop_unstable_poles"] = poles.open_loop_unstable;
        return d;
      },
      py::arg("axis"), py::arg("options"), py::arg("progress") = py::none(),
      "Stepped-sine sweep on the axis (ADLINK Bode tool). Releases the GIL.");

  m.def(
      "analytic_margins",
      [](const machine::Axis& axis, const py::object& freq, Flag filters) {
        std::vector<double> f;
        if (!freq.is_none()) f = real_vector(freq, "freq_hz");
        tuning::LoopOptions o;
        o.filters = filters;
        tuning::Margins mg;
        {
          py::gil_scoped_release release;
          mg = tuning::analytic_margins(axis.config(), f, o);
        }
        return margins_dict(mg);
      },
      py::arg("axis"), py::arg("freq_hz") = py::none(), py::arg("filters") = true,
      "Margins of the axis's analytic loop: stability from the closed-loop poles, crossings refined on the exact L.");
  m.def(
      "loop_poles",
      [](const machine::Axis& axis, Flag filters) {
        tuning::LoopOptions o;
        o.filters = filters;
        const tuning::LoopPoles p = tuning::loop_poles(axis.config(), o);
        return py::dict(py::arg("closed_loop") = to_array(p.closed_loop), py::arg("open_loop") = to_array(p.open_loop),
                        py::arg("max_radius") = p.max_radius, py::arg("integrators") = p.integrators,
                        py::arg("open_loop_unstable") = p.open_loop_unstable);
      },
      py::arg("axis"), py::arg("filters") = true, "Closed- and open-loop poles of the axis's linear loop (z).");

  m.def(
      "margins",
      [](const py::object& freq, const py::object& loop_gain, const py::object& closed_loop,
         const tuning::MarginsOptions& o) {
        const auto f = real_vector(freq, "freq_hz");
        const auto l = complex_vector(loop_gain, "loop_gain");
        std::vector<std::complex<double>> t;
        if (!closed_loop.is_none()) t = complex_vector(closed_loop, "closed_loop");
        o.validate();
        return margins_dict(tuning::margins(f, l, t, o));
      },
      py::arg("freq_hz"), py::arg("loop_gain"), py::arg("closed_loop") = py::none(), py::kw_only(), py::arg("options"),
      "Gain/phase/delay margins, closed-loop bandwidth and peak sensitivity from frequency-response data.");

  m.def(
      "relay_autotune",
      [](machine::Axis& axis, const tuning::RelayTuneOptions& o, const py::object& progress) {
        o.validate();
        std::shared_ptr<py::error_already_set> interrupt;
        const tuning::TuneProgress cb = progress_callback(progress, &interrupt);
        tuning::RelayTuneResult r;
        {
          RunLock lock({&axis});
          py::gil_scoped_release release;
          auto held = lock.chunk();
          r = tuning::relay_autotune(axis, o, cb);
        }
        raise_pending(interrupt);
        static const char* names[] = {"completed", "user_stop", "limit_or_alarm", "deviation_exceeded",
                                      "spread_too_large", "no_oscillation"};
        py::dict d;
        d["status"] = names[static_cast<int>(r.status)];
        d["message"] = r.message;
        d["period_s"] = to_array(r.period_s);
        d["amplitude_pulse"] = to_array(r.amplitude_pulse);
        d["peak_pulse"] = to_array(r.peak_pulse);
        d["center_pulse"] = to_array(r.center_pulse);
        d["gain_pulse_per_v"] = to_array(r.gain_pulse_per_v);
        d["phase_deg"] = to_array(r.phase_deg);
        d["kp"] = to_array(r.kp);
        d["ki"] = to_array(r.ki);
        d["kd"] = to_array(r.kd);
        d["error_pulse"] = to_array(r.error_pulse);
        d["output_v"] = to_array(r.output_v);
        d["mean"] = pid_dict(r.mean);
        py::dict figures;
        put_described(figures, r);  // kp ... sampling_time_s, as RelayTuneResult::describe() names them (OQ6)
        d["figures"] = figures;     // the one place of the single figures (no top-level copies: GZ8)
        d["ticks"] = r.ticks;
        return d;
      },
      py::arg("axis"), py::arg("options"), py::arg("progress") = py::none(), "Relay auto-tuning (ADLINK L1764-1847). Releases the GIL. The dict: status, message, the per-set arrays, the\n"
      "record, mean (the PidDesign), ticks, and figures: the single figures RELAY_TUNE_FIELDS describes.");

  m.def(
      "model_tune",
      [](const machine::Axis& axis, const tuning::ModelTuneOptions& options, const std::vector<double>& notch_q_set,
         const std::string& law) {
        tuning::ModelTuneOptions o = options;
        o.notch_q_set = notch_q_set;
        if (law == "axis") {
          o.law = tuning::TuneLaw::kAxis;
        } else if (law == "gt") {
          o.law = tuning::TuneLaw::kGt;
        } else if (law == "aps") {
          o.law = tuning::TuneLaw::kAps;
        } else {
          throw py::value_error("ModelTune.law = '" + law + "' must be None (the axis's law), 'gt' or 'aps'");
        }
        tuning::ModelTuneResult r;
        {
          py::gil_scoped_release release;
          r = tuning::model_tune(axis.config(), o);
        }
        py::dict d;
        d["pid"] = pid_dict(r.pid);
        d["law"] = py::cast(r.law);
        d["filters"] = py::make_tuple(py::cast(r.filters[0]), py::cast(r.filters[1]));
        put_described(d, r);  // kp ... limited_by, as tuning::ModelTuneResult::describe() names them (OR1)
        d["margins"] = margins_dict(r.margins);
        d["resonance_given"] = r.resonance_given;
        d["resonances"] = described_rows(r.resonances);  // each as tuning::ResonancePeak::describe() names it
        py::dict notch;
        put_described(notch, r.notch);  // used ... phase_at_crossover_deg (NotchDesign::describe()); the biquads:
        notch["float_biquad"] = py::cast(r.notch.float_biquad);
        notch["adlink_biquad"] = r.notch.adlink_ok ? py::cast(r.notch.adlink_biquad) : py::none();
        d["notch"] = notch;
        d["scan"] = described_columns(r.scan);  // the columns of CrossoverCandidate::describe()
        d["summary"] = r.summary;
        return d;
      },
      py::arg("axis"), py::arg("options"), py::arg("notch_q_set"), py::arg("law") = "axis",
      "Model-based PID (and notch) design from the axis's analytic plant (tuning/model_tune). Releases the GIL.");

  m.def(
      "closed_loop_pole_radius",
      [](const machine::Axis& axis) { return tuning::closed_loop_pole_radius(axis.config()); }, py::arg("axis"),
      "Largest |pole| of the axis's closed position loop (law, biquads, plant tick model); < 1: stable.");

  m.def(
      "pid_to_law",
      [](double kp, double ki, double kd, const py::object& base) -> py::object {
        tuning::PidDesign d;
        d.kp = kp;
        d.ki = ki;
        d.kd = kd;
        if (py::isinstance<control::GtServoLawParams>(base))
          return py::cast(tuning::to_gt_law(d, base.cast<control::GtServoLawParams>()));
        return py::cast(tuning::to_aps_law(d, base.cast<control::ApsServoLawParams>()));
      },
      py::arg("kp"), py::arg("ki"), py::arg("kd"), py::arg("base"),
      "Per-tick PID gains (counts/pulse) as the card law of `base`'s type (GT integers; ADLINK integers with shifts).");

  m.def(
      "classic_rule",
      [](const std::string& rule, double ku, double tu_s, double ts_s) {
        if (!(ku > 0) || !std::isfinite(ku)) throw_invalid("classic_rule", "ku", ku, "must be finite and > 0");
        if (!(tu_s > 0) || !std::isfinite(tu_s)) throw_invalid("classic_rule", "tu_s", tu_s, "must be finite and > 0");
        if (!(ts_s > 0) || !std::isfinite(ts_s)) throw_invalid("classic_rule", "ts_s", ts_s, "must be finite and > 0");
        tuning::PidDesign d;
        if (rule == "ziegler_nichols") {
          d = tuning::ziegler_nichols(ku, tu_s, ts_s);
        } else if (rule == "tyreus_luyben") {
          d = tuning::tyreus_luyben(ku, tu_s, ts_s);
        } else {
          throw py::value_error("rule = '" + rule + "' must be 'ziegler_nichols' or 'tyreus_luyben'");
        }
        return pid_dict(d);
      },
      py::arg("rule"), py::arg("ku"), py::arg("tu_s"), py::arg("ts_s"),
      "Classic PID rule from an ultimate point (ku counts/pulse, tu s) as per-tick gains at ts_s.");

  m.def(
      "tick_model",
      [](const machine::Axis& axis) {
        const machine::TickModel tm = axis.power_train().linear_tick_model();
        return py::make_tuple(tm.a, tm.b, tm.c_motor, tm.c_load);
      },
      py::arg("axis"),
      "The power train's linear model at the servo rate: (A, B, C_motor, C_load), volts held over a tick in, "
      "angles (rad) out.");

  m.def(
      "unwrapped_phase_deg",
      [](const py::object& h) { return to_array(tuning::unwrapped_phase_deg(complex_vector(h, "response"))); },
      py::arg("response"), "Phase in degrees, unwrapped point to point from the first point.");
}

}  // namespace servobench::bindings
