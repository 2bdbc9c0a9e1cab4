// Homing, capture, breakpoints and the ADLINK jog: the machine::MotionLoop and its parameter sets.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "flag.hpp"
#include "object_lock.hpp"
#include "param_class.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/motion_loop.hpp"
#include "servobench/motion/adlink_jog.hpp"
#include "servobench/motion/home_sequence.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::MotionLoop;

namespace {

const std::vector<std::string>& axis_signal_names() {
  static const std::vector<std::string> names = {
#define SERVOBENCH_NAME(name, unit, doc) #name,
      SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_NAME)
#undef SERVOBENCH_NAME
  };
  return names;
}
const std::vector<std::string>& loop_signal_names() {
  static const std::vector<std::string> names = {
#define SERVOBENCH_NAME(name, unit, doc) #name,
      SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_NAME)
#undef SERVOBENCH_NAME
  };
  return names;
}

// Runs the loop in chunks, recording the wanted signals; until_done stops when the sequence/motion ends.
py::dict run_loop(MotionLoop& loop, double ticks, Flag until_done, const py::object& signals) {
  check_integer("MotionLoop.run", until_done ? "max_ticks" : "ticks", ticks, 0, 1e9);
  std::vector<std::string> wanted;
  if (signals.is_none()) {
    wanted = axis_signal_names();
    for (const auto& s : loop_signal_names()) wanted.push_back(s);
  } else {
    for (const auto& s : signals) wanted.push_back(py::str(s));
  }
  std::map<std::string, std::vector<double>> buf;
  for (const auto& name : wanted) {
    bool known = false;
    for (const auto& s : axis_signal_names()) known = known || s == name;
    for (const auto& s : loop_signal_names()) known = known || s == name;
    if (!known) {
      std::string all;
      for (const auto& s : axis_signal_names()) all += (all.empty() ? "" : ", ") + s;
      for (const auto& s : loop_signal_names()) all += ", " + s;
      throw py::value_error("signals: unknown signal '" + name + "'; the signals are: " + all);
    }
    buf[name];
  }
  const auto total_max = static_cast<std::size_t>(ticks);
  // A fixed run is checked before it starts; a run until done (which usually ends long before max_ticks) before
  // each growth of its buffers.
  const auto too_big = [&](std::size_t n) { return static_cast<double>(n) * static_cast<double>(buf.size()) * 8.0 > kMaxRecordBytes; };
  const char* what = until_done ? "max_ticks" : "ticks";
  const std::string why = "would record more than the 2 GB a run may record; record fewer signals or run in pieces";
  if (!until_done && too_big(total_max)) throw_invalid("MotionLoop.run", what, ticks, why);
  std::size_t total = 0;
  {
    RunLock lock({&loop, &loop.axis()});
    py::gil_scoped_release release;
    ChunkClock clock;
    while (total < total_max) {
      if (total > 0) check_signals();
      const std::size_t chunk = std::min(clock.size(), total_max - total);
      if (too_big(total + chunk)) throw_invalid("MotionLoop.run", what, ticks, why);
      for (auto& [name, v] : buf) v.resize(total + chunk);
      machine::Trace tr;
      machine::LoopTrace lt;
#define SERVOBENCH_POINT(n, unit, doc) \
  if (auto it = buf.find(#n); it != buf.end()) tr.n = it->second.data() + total;
      SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
#define SERVOBENCH_POINT(n, unit, doc) \
  if (auto it = buf.find(#n); it != buf.end()) lt.n = it->second.data() + total;
      SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
      std::size_t k = chunk;
      {
        auto held = lock.chunk();
        clock.start();
        if (until_done) {
          k = loop.run_until_done(chunk, tr, lt);
        } else {
          loop.run(chunk, tr, lt);
        }
        clock.stop();
      }
      total += k;
      if (k < chunk) break;
    }
    for (auto& [name, v] : buf) v.resize(total);
  }
  py::dict out;
  for (const auto& name : wanted) {
    out[py::str(name)] = to_array(buf[name]);
  }
  return out;
}

template <class P>
void def_command(py::class_<MotionLoop>& c) {
  c.def("command", [](MotionLoop& l, const P& p) { l.generator().command(p); }, py::arg("params"));
  c.def("stage", [](MotionLoop& l, const P& p) { l.stage([p](motion::ProfileGenerator& g) { g.command(p); }); },
        py::arg("params"));
}

}  // namespace

void bind_homing(py::module_& m) {
  using namespace motion;
  py::list meta;
#define SERVOBENCH_META(name, unit, doc) meta.append(py::make_tuple(#name, unit, doc));
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_META)
#undef SERVOBENCH_META
  m.attr("LOOP_SIGNALS") = meta;

  ParamClass<AdlinkHomeParams>(m, "AdlinkHome",
      "ADLINK APS_home_move parameters (ADLINK manual L2246-2556), pulse and pulse/s units (unit factor 1).\n"
      "Defaults: the manual's example (L2295-2303): mode 0, dir 1, curve 0, acc 1e6, vm 1e5, vo 5e4.")
      .field("mode", &AdlinkHomeParams::mode, "PRA_HOME_MODE: 0 ORG, 1 EL (limit switch), 2 single EZ (index)")
      .field("dir", &AdlinkHomeParams::dir, "PRA_HOME_DIR: 0 positive, 1 negative")
      .field("curve", &AdlinkHomeParams::curve, "PRA_HOME_CURVE: S-factor 0..1 (0 = T-curve)")
      .field("acc", &AdlinkHomeParams::acc, "PRA_HOME_ACC: acceleration = deceleration, pulse/s^2, 0 < acc <= 1e12")
      .field("vm", &AdlinkHomeParams::vm, "PRA_HOME_VM: search speed, pulse/s, 0 < vm <= 1e9")
      .field("vo", &AdlinkHomeParams::vo, "PRA_HOME_VO: approach speed, pulse/s, 0 < vo <= vm")
      .field("shift", &AdlinkHomeParams::shift, "PRA_HOME_SHIFT: final offset from the reference edge, pulse")
      .field("eza", &AdlinkHomeParams::eza, "PRA_HOME_EZA: also align with the index mark (modes 0, 1)")
      .field("pos", &AdlinkHomeParams::pos, "PRA_HOME_POS: position set at the end, pulse")
      .finish();
  ParamClass<GtHomeParams>(m, "GtHome",
      "GT_Home(pos) + GT_Index(value) automatic homing (GT manual L4152-4213, Examples 6-1/6-2 L2021-2150),\n"
      "T-curve per tick: pos pulse, vel pulse/ST, acc pulse/ST^2.")
      .field("pos", &GtHomeParams::pos, "target beyond the home switch, whole pulses, -2^30..2^30-1 (L4162)")
      .field("vel", &GtHomeParams::vel, "T-curve velocity, pulse/ST, 0 < vel <= 16384")
      .field("acc", &GtHomeParams::acc, "T-curve acceleration, pulse/ST^2, 0 < acc <= 16384")
      .field("index", &GtHomeParams::index, "GT_Index: False home only, True home + index (L4190-4196)")
      .field("zero", &GtHomeParams::zero, "GT_ZeroPos at the end (Examples 6-1, 6-2)")
      .finish();
  ParamClass<AdlinkJogParams>(m, "AdlinkJog",
      "ADLINK jog parameters 40h-47h (ADLINK manual L2639-2710), pulse, pulse/s, pulse/s^2, us.")
      .field("mode", &AdlinkJogParams::mode, "PRA_JG_MODE: 0 continuous, 1 step")
      .field("dir", &AdlinkJogParams::dir, "PRA_JG_DIR: 0 negative, 1 positive")
      .field("sf", &AdlinkJogParams::sf, "PRA_JG_SF: S-factor 0..1")
      .field("acc", &AdlinkJogParams::acc, "PRA_JG_ACC: pulse/s^2, 0 < acc <= 1e12")
      .field("dec", &AdlinkJogParams::dec, "PRA_JG_DEC: pulse/s^2, 0 < dec <= 1e12")
      .field("vm", &AdlinkJogParams::vm, "PRA_JG_VM: pulse/s, 0 < vm <= 1e9")
      .field("offset", &AdlinkJogParams::offset, "PRA_JG_OFFSET: step, pulse, 0 < offset <= 2147483647")
      .field("delay_us", &AdlinkJogParams::delay_us, "PRA_JG_DELAY: us, 0..10000000")
      .finish();

  py::class_<MotionLoop> c(m, "MotionLoop",
      "An Axis driven tick by tick by a profile generator that reacts to it (homing, capture, breakpoints,\n"
      "jog). Use servobench.MotionLoop.");
  c.def(py::init<machine::Axis&>(), py::arg("axis"), py::keep_alive<1, 2>());
  def_command<GtTCurveParams>(c);
  def_command<GtSCurveParams>(c);
  def_command<GtJogParams>(c);
  def_command<GeTCurveParams>(c);
  def_command<GeSCurveParams>(c);
  def_command<GeJogParams>(c);
  def_command<AdlinkPtpParams>(c);
  c.def("stage_smooth_stop", [](MotionLoop& l) { l.stage([](ProfileGenerator& g) { g.smooth_stop(); }); })
      .def("update", &MotionLoop::update)
      .def_property("auto_update", &MotionLoop::auto_update, &MotionLoop::set_auto_update)
      .def_property_readonly("staged_count", &MotionLoop::staged_count)
      .def("smooth_stop", [](MotionLoop& l) { l.generator().smooth_stop(); })
      .def("abrupt_stop", [](MotionLoop& l) { l.generator().abrupt_stop(); })
      .def("adlink_velocity", [](MotionLoop& l, double v, const AdlinkPtpParams& p) { l.generator().adlink_velocity(v, p); },
           py::arg("vel_pulse_per_s"), py::arg("params"))
      .def("capt_home", [](MotionLoop& l) { l.capture().arm(machine::CaptureTrigger::Home); })
      .def("capt_index", [](MotionLoop& l) { l.capture().arm(machine::CaptureTrigger::Index); })
      .def("capt_probe", [](MotionLoop& l, double t_s) {
             if (!std::isfinite(t_s) || t_s < 0) throw_invalid("capt_probe", "at_s", t_s, "must be a finite time >= 0 s");
             l.capture().arm(machine::CaptureTrigger::Probe);
             l.set_probe_time(t_s);
           }, py::arg("at_s"))
      .def("capt_off", [](MotionLoop& l) { l.capture().arm(machine::CaptureTrigger::None); })
      .def_property_readonly("captured", [](MotionLoop& l) { return l.capture().captured(); })
      .def_property_readonly("capture_value", [](MotionLoop& l) { return l.capture().value(); })
      .def_property_readonly("capture_source", [](MotionLoop& l) { return std::string(to_string(l.capture().source())); })
      .def_property_readonly("capture_armed", [](MotionLoop& l) { return std::string(to_string(l.capture().armed())); })
      .def("clear_status", &MotionLoop::clear_status)
      .def("set_brk_cn", [](MotionLoop& l, double v) { l.breakpoint().set_compare(v); }, py::arg("brk_cn"))
      .def_property_readonly("brk_cn", [](MotionLoop& l) { return l.breakpoint().compare(); })
      .def("pos_brk", [](MotionLoop& l) { l.breakpoint().arm(BreakKind::PositionAbove); })
      .def("neg_brk", [](MotionLoop& l) { l.breakpoint().arm(BreakKind::PositionBelow); })
      .def("mtn_brk", [](MotionLoop& l) { l.breakpoint().arm(BreakKind::MotionComplete); })
      .def("ext_brk", [](MotionLoop& l) { l.breakpoint().arm(BreakKind::Home); })
      .def("brk_off", [](MotionLoop& l) { l.breakpoint().off(); })
      .def_property_readonly("breakpoint_armed", [](MotionLoop& l) { return std::string(to_string(l.breakpoint().armed())); })
      .def_property_readonly("breakpoint_flag", &MotionLoop::breakpoint_flag)
      .def("home", py::overload_cast<const AdlinkHomeParams&>(&MotionLoop::home), py::arg("params"))
      .def("home", py::overload_cast<const GtHomeParams&>(&MotionLoop::home), py::arg("params"))
      .def_property_readonly("home_phase", [](const MotionLoop& l) -> std::string {
        return l.homing() ? to_string(l.homing()->phase()) : "none";
      })
      .def_property_readonly("home_error_code", [](const MotionLoop& l) { return l.homing() ? l.homing()->error_code() : 0; })
      .def_property_readonly("home_reference", [](const MotionLoop& l) -> py::object {
        if (!l.homing() || !l.homing()->reference_found()) return py::none();
        return py::float_(l.homing()->reference_pos());
      })
      .def("jog", &MotionLoop::jog, py::arg("params"))
      .def_property("jog_on", &MotionLoop::jog_on, &MotionLoop::set_jog_on)
      .def_property_readonly("jog_phase", [](const MotionLoop& l) -> std::string {
        return l.jogger() ? to_string(l.jogger()->phase()) : "none";
      })
      .def_property_readonly("jog_origin", [](const MotionLoop& l) { return l.jogger() ? l.jogger()->origin() : 0.0; })
      .def_property_readonly("sequence_active", &MotionLoop::sequence_active)
      .def("set_position", &MotionLoop::set_position, py::arg("pos"))
      .def_property_readonly("offset", &MotionLoop::offset)
      .def_property_readonly("pos", [](const MotionLoop& l) { return l.generator().reported_pos(); })
      .def_property_readonly("actual_pos", &MotionLoop::actual_pos)
      .def_property_readonly("moving", [](const MotionLoop& l) { return l.generator().moving(); })
      .def_property_readonly("vel", [](const MotionLoop& l) { return l.generator().state().vel; })
      .def_property_readonly("mode", [](const MotionLoop& l) { return std::string(to_string(l.generator().mode())); })
      .def("run", [](MotionLoop& l, double ticks, const py::object& s) { return run_loop(l, ticks, false, s); },
           py::arg("ticks"), py::arg("signals") = py::none())
      .def("run_until_done", [](MotionLoop& l, double max_ticks, const py::object& s) {
             return run_loop(l, max_ticks, true, s);
           }, py::arg("max_ticks") = 1e7, py::arg("signals") = py::none());
  serialise_methods(c, {"run", "run_until_done"});  // one run at a time; the rest between chunks (object_lock.hpp)
}

}  // namespace servobench::bindings
