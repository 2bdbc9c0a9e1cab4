// The virtual card (machine::Card) and the GT status words. Thin: axis indices are 0-based here; the Python
// wrapper (servobench.card) and the dialects translate.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "flag.hpp"
#include "object_lock.hpp"
#include "param_class.hpp"
#include "card_axis.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;

void bind_card_ge(py::module_& m);  // bind_card_ge.cpp
void bind_card_modes(py::class_<Card>& cls, py::module_& m);  // bind_card_modes.cpp
void bind_card_aps(py::class_<Card>& cls, py::module_& m);    // bind_card_aps.cpp: ADLINK interpolation group, gear ramp
void bind_card_ge_path(py::class_<Card>& cls);  // bind_card_ge_path.cpp (GE SX path)
void bind_card_codes(py::module_& m);  // bind_card_codes.cpp: typed vendor codes, codes on the exceptions

namespace {

machine::AxisMode mode_from(const std::string& s) {
  if (s == "t_curve") return machine::AxisMode::TCurve;
  if (s == "s_curve") return machine::AxisMode::SCurve;
  if (s == "jog") return machine::AxisMode::Jog;
  if (s == "gear") return machine::AxisMode::Gear;
  if (s == "coordinated") return machine::AxisMode::Coordinated;
  throw py::value_error("mode: '" + s + "' is not one of t_curve, s_curve, jog, gear, coordinated");
}

motion::BreakKind break_from(const std::string& s) {
  if (s == "none") return motion::BreakKind::None;
  if (s == "pos") return motion::BreakKind::PositionAbove;
  if (s == "neg") return motion::BreakKind::PositionBelow;
  if (s == "motion") return motion::BreakKind::MotionComplete;
  if (s == "home") return motion::BreakKind::Home;
  throw py::value_error("kind: '" + s + "' is not one of none, pos, neg, motion, home");
}

machine::CaptureTrigger capture_from(const std::string& s) {
  if (s == "none") return machine::CaptureTrigger::None;
  if (s == "home") return machine::CaptureTrigger::Home;
  if (s == "index") return machine::CaptureTrigger::Index;
  if (s == "probe") return machine::CaptureTrigger::Probe;
  throw py::value_error("trigger: '" + s + "' is not one of none, home, index, probe");
}

machine::CommandFault fault_from(const std::string& s) {
  for (int f = 0; f < 64; ++f) {  // every cause up to the last (to_string gives "?" past it)
    const auto c = static_cast<machine::CommandFault>(f);
    if (std::string(to_string(c)) == "?") break;
    if (s == to_string(c)) return c;
  }
  throw py::value_error("fault: '" + s + "' is not a card command fault");
}

py::dict registers(const machine::AxisRegisters& r) {
  py::dict d;
  d["pos"] = r.pos;
  d["vel"] = r.vel;
  d["acc"] = r.acc;
  d["macc"] = r.macc;
  d["jerk"] = r.jerk;
  d["ratio"] = r.ratio;
  d["brk_cn"] = r.brk_cn;
  d["pos_err"] = r.pos_err;
  d["law"] = std::visit([](const auto& p) { return py::cast(p); }, r.law);
  return d;
}

const std::vector<std::string>& card_signal_names() {
  static const std::vector<std::string> names = {"events", "moving", "servo_on", "prf_vel"};
  return names;
}

// Runs n ticks recording the wanted signals of every axis: a list of dicts (one per axis).
}  // namespace

// The card, then its axes: the objects a card run locks (object_lock.hpp).
std::vector<const void*> card_keys(Card& card) {
  std::vector<const void*> keys{&card};
  for (std::size_t i = 0; i < card.axis_count(); ++i) keys.push_back(&card.axis(i));
  return keys;
}

namespace {

// Card.step, the step API for a card (issue 22.2): `n` ticks of every axis recording nothing; returns the card's
// tick count. One binding (decision FV10): a few ticks run under the card's and its axes' state locks with the GIL
// held, as every other method; from kLongStep ticks on the call is a run (run locks, GIL released, Ctrl-C
// between chunks of about 20 ms).
long long step_card(Card& card, double n_ticks) {
  constexpr std::size_t kLongStep = 256;
  if (!(n_ticks >= 0 && n_ticks <= 1e9 && n_ticks == std::floor(n_ticks)))
    throw_invalid("Card.step", "n", n_ticks, "must be a whole number of ticks, 0..1e9");
  const auto n = static_cast<std::size_t>(n_ticks);
  if (n < kLongStep) {
    // The card, then its 4 or 8 axes (object_lock.hpp), looked up in one visit of the lock table (decision FV25).
    const std::size_t m = card.axis_count() + 1;
    std::array<const void*, 9> keys{&card};
    for (std::size_t i = 1; i < m; ++i) keys[i] = &card.axis(i - 1);
    std::array<std::shared_ptr<ObjectLocks>, 9> locks;
    locks_of(keys.data(), m, locks.data());
    std::array<std::unique_lock<std::recursive_mutex>, 9> held;  // released before `locks` goes
    for (std::size_t i = 0; i < m; ++i) held[i] = lock_releasing_gil(locks[i]->state);
    card.run(n);
    return card.tick();
  }
  run_in_chunks(card_keys(card), n, [&](std::size_t k) { card.run(k); });
  return card.tick();
}

py::list run_card(Card& card, double ticks, const py::object& signals) {
  check_integer("Card.run", "ticks", ticks, 0, 1e9);
  std::vector<std::string> all;
#define SERVOBENCH_NAME(name, unit, doc) all.push_back(#name);
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_NAME)
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_NAME)
#undef SERVOBENCH_NAME
  for (const auto& s : card_signal_names()) all.push_back(s);
  std::vector<std::string> wanted;
  if (signals.is_none()) {
    wanted = {"time_s", "pos", "actual_pos", "error", "volts", "prf_vel", "events", "moving", "servo_on"};
  } else {
    for (const auto& s : signals) wanted.push_back(py::str(s));
  }
  for (const auto& w : wanted) {
    bool known = false;
    for (const auto& s : all) known = known || s == w;
    if (!known) {
      std::string list;
      for (const auto& s : all) list += (list.empty() ? "" : ", ") + s;
      throw py::value_error("signals: unknown signal '" + w + "'; the signals are: " + list);
    }
  }
  const std::size_t n_ax = card.axis_count();
  const auto n = static_cast<std::size_t>(ticks);
  const double bytes = static_cast<double>(n) * static_cast<double>(n_ax * wanted.size()) * 8.0;
  if (bytes > kMaxRecordBytes)
    throw_invalid("Card.run", "ticks", ticks,
                  "would record " + format_value(bytes * 1e-9) + " GB (" + std::to_string(wanted.size()) +
                      " signals x " + std::to_string(n_ax) +
                      " axes), above the 2 GB a run may record; record fewer signals (signals=[]) or run in pieces");
  std::vector<std::map<std::string, std::vector<double>>> buf(n_ax);
  {
    RunLock lock(card_keys(card));
    py::gil_scoped_release release;
    ChunkClock clock;
    std::size_t done = 0;
    while (done < n || (n == 0 && done == 0)) {
      const std::size_t chunk = std::min(clock.size(), n - done);
      std::vector<machine::CardTrace> tr(n_ax);
      for (std::size_t i = 0; i < n_ax; ++i) {
        for (const auto& w : wanted) buf[i][w].resize(done + chunk);
        auto& b = buf[i];
        machine::CardTrace& t = tr[i];
#define SERVOBENCH_POINT(name, unit, doc) \
  if (auto it = b.find(#name); it != b.end()) t.axis.name = it->second.data() + done;
        SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
#define SERVOBENCH_POINT(name, unit, doc) \
  if (auto it = b.find(#name); it != b.end()) t.loop.name = it->second.data() + done;
        SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
        if (auto it = b.find("events"); it != b.end()) t.events = it->second.data() + done;
        if (auto it = b.find("moving"); it != b.end()) t.moving = it->second.data() + done;
        if (auto it = b.find("servo_on"); it != b.end()) t.servo_on = it->second.data() + done;
        if (auto it = b.find("prf_vel"); it != b.end()) t.prf_vel = it->second.data() + done;
      }
      {
        auto held = lock.chunk();
        clock.start();
        card.run(chunk, tr);
        clock.stop();
      }
      done += chunk;
      if (n == 0) break;
      if (done < n) check_signals();
    }
  }
  py::list out;
  for (std::size_t i = 0; i < n_ax; ++i) {
    py::dict d;
    for (const auto& w : wanted) d[py::str(w)] = to_array(buf[i][w]);
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_card_scope(py::module_& m, py::class_<Card>& c);  // bind_card_scope.cpp (issue 10.3)

void bind_card(py::module_& m) {
  py::register_exception<machine::CardCommandRefused>(m, "CardCommandRefused", m.attr("MotionCommandRefused"));
  bind_card_codes(m);

  ParamClass<machine::LimitConfig>(m, "CardLimits",
      "Limit configuration of a card axis: hard limits (the axis's Switches; GT_LmtsOn/Off, GT_LmtSns) and soft\n"
      "limits on the actual position (ADLINK PRA_SPEL_*/PRA_SMEL_*), pulse.")
      .field("enabled", &machine::LimitConfig::enabled, "react to the hard limits (GT_LmtsOn, default True)")
      .field("pos_active_low", &machine::LimitConfig::pos_active_low,
             "GT_LmtSns bit 2(k-1): False triggers on a high level (default, normally-closed switch), True on low")
      .field("neg_active_low", &machine::LimitConfig::neg_active_low, "GT_LmtSns bit 2(k-1)+1")
      .field("soft_pos_enabled", &machine::LimitConfig::soft_pos_enabled, "ADLINK PRA_SPEL_EN")
      .field("soft_neg_enabled", &machine::LimitConfig::soft_neg_enabled, "ADLINK PRA_SMEL_EN")
      .field("soft_pos_pulse", &machine::LimitConfig::soft_pos_pulse, "PRA_SPEL_POS: triggers at actual >= it, pulse")
      .field("soft_neg_pulse", &machine::LimitConfig::soft_neg_pulse, "PRA_SMEL_POS: triggers at actual <= it, pulse")
      .finish();

  py::list events;
  for (const char* e : {"motion_complete", "drive_alarm", "breakpoint", "captured", "following_error", "pos_limit",
                        "neg_limit", "command_error", "soft_pos_limit", "soft_neg_limit", "emergency_stop",
                        "error_level"})
    events.append(e);
  m.attr("CARD_EVENTS") = events;

  py::class_<Card> c(m, "Card", "The virtual motion-control card (machine::Card). Use servobench.Card.");
  c.def(py::init([](const std::vector<machine::Axis*>& axes, double motion_cycle_ticks, double host_cycle_ticks) {
          machine::CardCycles cy;
          cy.motion_cycle_ticks = motion_cycle_ticks;
          cy.host_cycle_ticks = host_cycle_ticks;
          return std::make_unique<Card>(axes, cy);
        }),
        py::arg("axes"), py::arg("motion_cycle_ticks") = 1.0, py::arg("host_cycle_ticks") = 1.0, py::keep_alive<1, 2>())
      .def_property_readonly("axis_count", &Card::axis_count)
      .def_property_readonly("tick", &Card::tick)
      .def_property_readonly("servo_period_s", &Card::servo_period_s)
      .def_property_readonly("motion_cycle_ticks", [](const Card& k) { return k.cycles().motion_cycle_ticks; })
      .def_property_readonly("host_cycle_ticks", [](const Card& k) { return k.cycles().host_cycle_ticks; })
      .def("reset", &Card::reset)
      .def("stage_pos", [](Card& k, AxisIndex i, double v) { k.stage_pos(card_axis(k, i), v); }, py::arg("axis"), py::arg("pos"))
      .def("stage_vel", [](Card& k, AxisIndex i, double v) { k.stage_vel(card_axis(k, i), v); }, py::arg("axis"), py::arg("vel"))
      .def("stage_acc", [](Card& k, AxisIndex i, double v) { k.stage_acc(card_axis(k, i), v); }, py::arg("axis"), py::arg("acc"))
      .def("stage_macc", [](Card& k, AxisIndex i, double v) { k.stage_macc(card_axis(k, i), v); }, py::arg("axis"), py::arg("macc"))
      .def("stage_jerk", [](Card& k, AxisIndex i, double v) { k.stage_jerk(card_axis(k, i), v); }, py::arg("axis"), py::arg("jerk"))
      .def("stage_ratio", [](Card& k, AxisIndex i, double v) { k.stage_ratio(card_axis(k, i), v); }, py::arg("axis"), py::arg("ratio"))
      .def("stage_brk_cn", [](Card& k, AxisIndex i, double v) { k.stage_brk_cn(card_axis(k, i), v); }, py::arg("axis"), py::arg("brk_cn"))
      .def("stage_pos_err", [](Card& k, AxisIndex i, double v) { k.stage_pos_err(card_axis(k, i), v); }, py::arg("axis"), py::arg("pos_err"))
      .def("stage_law", [](Card& k, AxisIndex i, const py::object& law) {
             machine::LawParams p;
             if (py::isinstance<control::GtServoLawParams>(law)) {
               p = law.cast<control::GtServoLawParams>();
             } else if (py::isinstance<control::ApsServoLawParams>(law)) {
               p = law.cast<control::ApsServoLawParams>();
             } else {
               throw py::type_error("law must be a GtServoLaw or an ApsServoLaw");
             }
             k.stage_law(card_axis(k, i), p);
           }, py::arg("axis"), py::arg("law"))
      .def("stage_smooth_stop", [](Card& k, AxisIndex i) { k.stage_smooth_stop(card_axis(k, i)); }, py::arg("axis"))
      .def("stage_synch_pos", [](Card& k, AxisIndex i) { k.stage_synch_pos(card_axis(k, i)); }, py::arg("axis"))
      .def("update", [](Card& k, double mask) {
             check_integer("Card", "mask", mask, 0, 65535);
             k.update(static_cast<std::uint32_t>(mask));
           }, py::arg("mask"))
      .def("staged", [](const Card& k, AxisIndex i) { return registers(k.state(card_axis(k, i)).staged); }, py::arg("axis"))
      .def("active", [](const Card& k, AxisIndex i) { return registers(k.state(card_axis(k, i)).active); }, py::arg("axis"))
      .def("commit_pending", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).commit_pending; }, py::arg("axis"))
      .def("set_mode", [](Card& k, AxisIndex i, const std::string& s) { k.set_mode(card_axis(k, i), mode_from(s)); },
           py::arg("axis"), py::arg("mode"))
      .def("mode", [](const Card& k, AxisIndex i) { return std::string(to_string(k.state(card_axis(k, i)).mode)); }, py::arg("axis"))
      .def("update_pending", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).commit_pending; }, py::arg("axis"))
      .def("staged_changes", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).dirty; }, py::arg("axis"))
      .def("abrupt_stop", [](Card& k, AxisIndex i) { k.abrupt_stop(card_axis(k, i)); }, py::arg("axis"))
      .def("zero_pos", [](Card& k, AxisIndex i) { k.zero_pos(card_axis(k, i)); }, py::arg("axis"))
      .def("zero_pos_range", [](Card& k, AxisIndex first, double count) {
             check_integer("Card", "count", count, 0, 64, "a number of axes");  // whole; the range is the kernel's
             k.zero_pos_range(card_axis(k, first), static_cast<std::size_t>(count));
           },
           py::arg("first"), py::arg("count"),
           "GTS GT_ZeroPos(axis, count): actual = target = profile = 0 on `count` axes from `first` (0-based), all or "
           "none: refused (CardCommandRefused) with nothing changed if any of them moves or is in gear/crd mode.")
      .def("set_actual_pos", [](Card& k, AxisIndex i, double p) { k.set_actual_pos(card_axis(k, i), p); }, py::arg("axis"), py::arg("pos"))
      .def("axis_on", [](Card& k, AxisIndex i) { k.axis_on(card_axis(k, i)); }, py::arg("axis"))
      .def("axis_off", [](Card& k, AxisIndex i) { k.axis_off(card_axis(k, i)); }, py::arg("axis"))
      .def("drive_reset", [](Card& k, AxisIndex i) { k.drive_reset(card_axis(k, i)); }, py::arg("axis"))
      .def("set_closed_loop", [](Card& k, AxisIndex i, Flag on) { k.set_closed_loop(card_axis(k, i), on); }, py::arg("axis"), py::arg("closed"))
      .def("set_mtr_cmd", [](Card& k, AxisIndex i, double v) { k.set_mtr_cmd(card_axis(k, i), v); }, py::arg("axis"), py::arg("counts"))
      .def("mtr_cmd", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).mtr_cmd; }, py::arg("axis"))
      .def("set_auto_stop", [](Card& k, AxisIndex i, Flag on) { k.set_auto_stop(card_axis(k, i), on); }, py::arg("axis"), py::arg("on"))
      .def("set_auto_update", [](Card& k, AxisIndex i, Flag on) { k.set_auto_update(card_axis(k, i), on); }, py::arg("axis"), py::arg("on"))
      .def("arm_breakpoint", [](Card& k, AxisIndex i, const std::string& s) { k.arm_breakpoint(card_axis(k, i), break_from(s)); },
           py::arg("axis"), py::arg("kind"))
      .def("breakpoint_armed", [](Card& k, AxisIndex i) { return std::string(to_string(k.loop(card_axis(k, i)).breakpoint().armed())); },
           py::arg("axis"))
      .def("arm_capture", [](Card& k, AxisIndex i, const std::string& s) { k.arm_capture(card_axis(k, i), capture_from(s)); },
           py::arg("axis"), py::arg("trigger"))
      .def("capture_value", [](Card& k, AxisIndex i) { return k.loop(card_axis(k, i)).capture().value(); }, py::arg("axis"))
      .def("home", [](Card& k, AxisIndex i, const motion::GtHomeParams& p) { k.home(card_axis(k, i), p); }, py::arg("axis"), py::arg("params"))
      .def("set_limits", [](Card& k, AxisIndex i, const machine::LimitConfig& l) { k.set_limits(card_axis(k, i), l); },
           py::arg("axis"), py::arg("limits"))
      .def("limits", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).limits; }, py::arg("axis"))
      .def("set_alarm_enabled", [](Card& k, AxisIndex i, Flag on) { k.set_alarm_enabled(card_axis(k, i), on); }, py::arg("axis"), py::arg("on"))
      .def("set_alarm_input", [](Card& k, AxisIndex i, Flag on) { k.set_alarm_input(card_axis(k, i), on); }, py::arg("axis"), py::arg("alarm"))
      .def_property("emergency_stop", &Card::emergency_stop, &Card::set_emergency_stop)
      .def("clear_events", [](Card& k, AxisIndex i, double which) {
             check_integer("Card", "which", which, 0, 4095);
             k.clear_events(card_axis(k, i), static_cast<std::uint32_t>(which));
           }, py::arg("axis"), py::arg("which"))
      .def("events", [](const Card& k, AxisIndex i) { return k.events(card_axis(k, i)); }, py::arg("axis"))
      .def("record_fault", [](Card& k, AxisIndex axis, const std::string& f) {
             check_integer("Card", "axis", axis.value, -1, static_cast<double>(k.axis_count()) - 1);  // -1: card-wide
             k.record_fault(static_cast<int>(axis.value), fault_from(f));
           }, py::arg("axis"), py::arg("fault"))
      .def_property_readonly("last_fault", [](const Card& k) { return std::string(to_string(k.last_fault())); })
      .def("stop_cause", [](const Card& k, AxisIndex i) { return std::string(to_string(k.state(card_axis(k, i)).stop_cause)); }, py::arg("axis"))
      .def("moving", [](const Card& k, AxisIndex i) { return k.moving(card_axis(k, i)); }, py::arg("axis"))
      .def("servo_on", [](const Card& k, AxisIndex i) { return k.servo_on(card_axis(k, i)); }, py::arg("axis"))
      .def("closed_loop", [](const Card& k, AxisIndex i) { return k.closed_loop(card_axis(k, i)); }, py::arg("axis"))
      .def("auto_stop", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).auto_stop; }, py::arg("axis"))
      .def("auto_update", [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).auto_update; }, py::arg("axis"))
      .def("profile_pos", [](const Card& k, AxisIndex i) { return k.profile_pos(card_axis(k, i)); }, py::arg("axis"))
      .def("profile_vel", [](const Card& k, AxisIndex i) { return k.profile_vel(card_axis(k, i)); }, py::arg("axis"))
      .def("actual_pos", [](const Card& k, AxisIndex i) { return k.actual_pos(card_axis(k, i)); }, py::arg("axis"))
      .def("following_error", [](const Card& k, AxisIndex i) { return k.following_error(card_axis(k, i)); }, py::arg("axis"))
      .def("integral", [](Card& k, AxisIndex i) -> double {
             // the GT law's accumulator (GT_GetIntgr), pulse*tick; 0 for the other law
             return k.axis(card_axis(k, i)).law_error_sum();
           }, py::arg("axis"))
      .def("pos_limit_input", [](const Card& k, AxisIndex i) { return k.pos_limit_input(card_axis(k, i)); }, py::arg("axis"))
      .def("neg_limit_input", [](const Card& k, AxisIndex i) { return k.neg_limit_input(card_axis(k, i)); }, py::arg("axis"))
      .def("run", &run_card, py::arg("ticks"), py::arg("signals") = py::none())
      .def("step", &step_card, py::arg("n") = 1,
           "Advances n ticks (default 1) of every axis recording nothing; returns the card's tick count.");
  bind_card_modes(c, m);  // gear, PVT, FollowEx, coordinate systems
  bind_card_scope(m, c);  // scope, events, compare, probe (issue 10.3)
  bind_card_aps(c, m);    // [aps] ADLINK interpolation group, gear engage ramp
  bind_card_ge_path(c);   // GE SX crd (card_group_ge.hpp)
  // Every other method waits for the running chunk (object_lock.hpp): the card stays readable while it runs.
  serialise_methods(c, {"run", "run_until_event", "step"});  // step locks itself (step_card)

  m.def("gt_axis_status", [](const Card& k, AxisIndex i) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::googol::gt_axis_status(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "GT axis status register (Table 4-14) of a card axis (0-based).");
  m.def("aps_motion_status", [](const Card& k, AxisIndex i) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::adlink::aps_motion_status(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "ADLINK APS_motion_status (MSTS) of a card axis (0-based), L3164-3206");
  m.def("aps_motion_io_status", [](const Card& k, AxisIndex i) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::adlink::aps_motion_io_status(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "ADLINK APS_motion_io_status (MIO) of a card axis (0-based), L3611-3631");
  m.def("aps_stop_code", [](const Card& k, AxisIndex i) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::adlink::aps_stop_code(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "ADLINK APS_get_stop_code of a card axis (0-based), L3922-4023");
  m.def("gt_mode_register", [](const Card& k, AxisIndex i) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::googol::gt_mode_register(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "GT axis mode register (Table 4-15) of a card axis (0-based).");
  m.def("gt_command_status", [](const Card& k) { auto lk = lock_releasing_gil(locks_of(&k)->state); return vendor::googol::gt_command_status(k); }, py::arg("card"),
        "GT command status register (Table 2-2): the bit of the last refused command's cause.");
  m.def("gt_events_to_clear", [](double mask) {
          check_integer("GT_RstSts", "mask", mask, 0, 65535);
          return vendor::googol::gt_events_to_clear(static_cast<std::uint16_t>(mask));
        }, py::arg("mask"), "The card events GT_RstSts(mask) clears (mask bit 1 keeps, 0 clears; bits 0-7).");
  bind_card_ge(m);
}

}  // namespace servobench::bindings
