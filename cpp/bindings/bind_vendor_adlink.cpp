// The ADLINK vendor module's scope registers (vendor/adlink/aps_scope.hpp: sampling, trigger parameters, compare
// timer), host interrupts (aps_interrupts.hpp), the PRA_* table (aps_parameters.hpp) and the board outputs
// (aps_outputs.hpp: DO, board parameters, VAO). Thin: every method returns the APS code as an int (getters: (code, value)); servobench.dialects.aps
// adapts the APS_* names to them. Registered in module.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "card_axis.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/aps_command_table.hpp"
#include "servobench/vendor/adlink/aps_constants.hpp"
#include "servobench/vendor/adlink/aps_interrupts.hpp"
#include "servobench/vendor/adlink/aps_outputs.hpp"
#include "servobench/vendor/adlink/aps_parameters.hpp"
#include "servobench/vendor/adlink/aps_point_table.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_scope.hpp"
#include "servobench/vendor/adlink/aps_watchdog.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using vendor::adlink::AdlinkCode;
using vendor::adlink::ApsInterrupts;
using vendor::adlink::ApsOutputs;
using vendor::adlink::ApsParameters;
using vendor::adlink::ApsSample;
using vendor::adlink::ApsScope;

namespace {

int code(AdlinkCode c) { return static_cast<int>(c); }

py::tuple with_status(AdlinkCode c, const vendor::adlink::PtStatus& s) {
  return py::make_tuple(code(c), py::make_tuple(s.bit_sts, s.free_space, s.usage_space, s.running_cnt));
}

// The run's DataArr as a NumPy array of STR_SAMP_DATA_4CH over the module's buffer (kept alive by the array).
py::object buffer_array(const ApsScope& s) {
  auto buf = s.sampling_buffer();
  if (!buf) return py::none();
  auto* keep = new std::shared_ptr<std::vector<ApsSample>>(buf);
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<std::vector<ApsSample>>*>(p); });
  return py::array_t<ApsSample>({static_cast<py::ssize_t>(buf->size())}, {static_cast<py::ssize_t>(sizeof(ApsSample))},
                                buf->data(), base);
}


// The point tables (vendor/adlink/aps_point_table.hpp): every method returns the APS code, the status ones
// (code, (BitSts, PntBufFreeSpace, PntBufUsageSpace, RunningCnt)).
void bind_point_tables(py::module_& m) {
  using vendor::adlink::ApsPointTables;
  using vendor::adlink::PtMove;
  using vendor::adlink::PtStatus;
  py::enum_<PtMove::Kind>(m, "ApsPtKind", "an ADLINK point-table movement command (APS_pt_line ... APS_pt_dwell)")
      .value("LINE", PtMove::Kind::Line).value("ARC2_CA", PtMove::Kind::Arc2Ca).value("ARC2_CE", PtMove::Kind::Arc2Ce)
      .value("SPIRAL_CA", PtMove::Kind::SpiralCa).value("SPIRAL_CE", PtMove::Kind::SpiralCe)
      .value("DWELL", PtMove::Kind::Dwell);
  py::enum_<ApsPointTables::Speed>(m, "ApsPtSpeed", "which speed APS_pt_set_* sets (pulse/s, pulse/s^2, S-factor)")
      .value("VM", ApsPointTables::Speed::Vm).value("VE", ApsPointTables::Speed::Ve)
      .value("ACC", ApsPointTables::Speed::Acc).value("DEC", ApsPointTables::Speed::Dec)
      .value("ACC_DEC", ApsPointTables::Speed::AccDec).value("SF", ApsPointTables::Speed::Sf);
  py::enum_<ApsPointTables::Transition>(m, "ApsPtTransition", "an APS_pt_set_trans_* transition mode")
      .value("BUFFERED", ApsPointTables::Transition::Buffered)
      .value("IN_POSITION", ApsPointTables::Transition::InPosition)
      .value("BLEND_DEC", ApsPointTables::Transition::BlendDec)
      .value("BLEND_DIST", ApsPointTables::Transition::BlendDist)
      .value("BLEND_PCNT", ApsPointTables::Transition::BlendPcnt);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  py::class_<ApsPointTables>(m, "ApsPointTables",
                             "The ADLINK point tables of a card (vendor/adlink/aps_point_table.hpp, L3794-3911): "
                             "tables 0..1, their speeds, transition, instruction commands and buffer. Get it with "
                             "aps_point_tables(card).")
      .def("power_on", &ApsPointTables::power_on, "no table enabled (APS_initial)")
      .def("enable", [](ApsPointTables& s, double b, double p, double d, const std::vector<double>& axes) {
             return code(s.enable(b, p, d, axes));
           }, py::arg("board"), py::arg("ptb"), py::arg("dim"), py::arg("axes"))
      .def("disable", [](ApsPointTables& s, double b, double p) { return code(s.disable(b, p)); }, py::arg("board"),
           py::arg("ptb"))
      .def("status", [](ApsPointTables& s, double b, double p) {
             PtStatus st;
             const AdlinkCode c = s.status(b, p, st);
             return with_status(c, st);
           }, py::arg("board"), py::arg("ptb"))
      .def("start", [](ApsPointTables& s, double b, double p, double r) { return code(s.start(b, p, r)); },
           py::arg("board"), py::arg("ptb"), py::arg("reserved") = 0.0)
      .def("stop", [](ApsPointTables& s, double b, double p) { return code(s.stop(b, p)); }, py::arg("board"),
           py::arg("ptb"))
      .def("set_relative", [](ApsPointTables& s, double b, double p, bool r) { return code(s.set_relative(b, p, r)); },
           py::arg("board"), py::arg("ptb"), py::arg("relative"))
      .def("set_speed", [](ApsPointTables& s, double b, double p, ApsPointTables::Speed w, double v) {
             return code(s.set_speed(b, p, w, v));
           }, py::arg("board"), py::arg("ptb"), py::arg("which"), py::arg("value"))
      .def("set_transition", [](ApsPointTables& s, double b, double p, ApsPointTables::Transition t, double bp) {
             return code(s.set_transition(b, p, t, bp));
           }, py::arg("board"), py::arg("ptb"), py::arg("transition"), py::arg("bp") = 0.0)
      .def("ext_set_do", [](ApsPointTables& s, double b, double p, double ch, double on) {
             return code(s.ext_set_do(b, p, ch, on));
           }, py::arg("board"), py::arg("ptb"), py::arg("channel"), py::arg("on"))
      .def("ext_set_table", [](ApsPointTables& s, double b, double p, double ctrl, double table) {
             return code(s.ext_set_table(b, p, ctrl, table));
           }, py::arg("board"), py::arg("ptb"), py::arg("ctrl"), py::arg("table"))
      .def("push", [](ApsPointTables& s, double b, double p, PtMove::Kind kind, double dim, std::vector<double> index,
                      std::vector<double> pos, std::vector<double> center, std::vector<double> normal, double angle,
                      double dh, double fr, double dir, double dw) {
             PtMove mv;
             mv.kind = kind;
             mv.dim = dim;
             mv.index = std::move(index);
             mv.pos = std::move(pos);
             mv.center = std::move(center);
             mv.normal = std::move(normal);
             mv.angle_deg = angle;
             mv.delta_h = dh;
             mv.final_r = fr;
             mv.dir = dir;
             mv.dw_time_ms = dw;
             PtStatus st;
             const AdlinkCode c = s.push(b, p, mv, st);
             return with_status(c, st);
           }, py::arg("board"), py::arg("ptb"), py::arg("kind"), py::kw_only(), py::arg("dim") = nan,
           py::arg("index") = std::vector<double>{}, py::arg("pos") = std::vector<double>{},
           py::arg("center") = std::vector<double>{}, py::arg("normal") = std::vector<double>{},
           py::arg("angle_deg") = nan, py::arg("delta_h") = nan, py::arg("final_r") = nan, py::arg("dir") = nan,
           py::arg("dw_time_ms") = nan,
           "a movement command (the fields of PTLINE/PTA2CA/PTA2CE/PTHCA/PTHCE/PTDWL; NaN = not a number)")
      .def("sync", py::overload_cast<>(&ApsPointTables::sync),
           "carries out the instruction commands of the moves started so far")
      .def("enabled", &ApsPointTables::enabled, py::arg("ptb"));
  py::list commands;
  for (const vendor::adlink::ApsCommandDoc& d : vendor::adlink::pt_commands())
    commands.append(py::make_tuple(d.name, d.args, d.doc));
  m.attr("APS_PT_COMMANDS") = commands;  // (name, arguments after Board_ID/PtbId, doc): the dialect's rows
  py::list described;
  for (const vendor::adlink::ApsCommandDoc& d : vendor::adlink::aps_commands())
    described.append(py::make_tuple(d.name, d.args, d.doc));
  m.attr("APS_COMMANDS") = described;  // (name, arguments after self, doc): the dialect's docstrings (AX2)
  py::list constants;
  for (const vendor::adlink::ApsConstant& c : vendor::adlink::aps_constants())
    constants.append(py::make_tuple(c.name, c.value, c.hex, c.doc));
  m.attr("APS_CONSTANTS") = constants;  // (name, value, hex, doc): _aps_constants.py is written from it
  m.def("aps_point_tables", [](machine::Card& k) -> ApsPointTables& { return vendor::adlink::aps_point_tables(k); },
        py::arg("card"), py::return_value_policy::reference_internal,
        "the card's ADLINK point tables (created on first use, owned by the card)");
}

}  // namespace

void bind_vendor_adlink(py::module_& m) {
  PYBIND11_NUMPY_DTYPE(ApsSample, tick, data);
  py::class_<ApsScope>(m, "ApsScope",
                       "The ADLINK scope registers of a card (vendor/adlink/aps_scope.hpp): sampling (L3544-3665), "
                       "trigger parameters (L3348-3435), compare timer (L3363-3378). Get it with aps_scope(card).")
      .def("power_on", &ApsScope::power_on, "the registers at their APS_initial values; no sampling run")
      .def("set_sampling_param", [](ApsScope& s, double p, double v) { return code(s.set_sampling_param(p, v)); },
           py::arg("para"), py::arg("value"), "SAMP_PA_* register; returns the APS code")
      .def("sampling_param", [](const ApsScope& s, double p) {
             int v = 0;
             const int c = code(s.sampling_param(p, v));
             return py::make_tuple(c, v);
           }, py::arg("para"), "(code, value) of a SAMP_PA_* register")
      .def("start_sampling", [](ApsScope& s, double n, double pre, double tmo) { return code(s.start_sampling(n, pre, tmo)); },
           py::arg("length"), py::arg("pretrigger"), py::arg("timeout_ms"),
           "starts a block of length samples (pretrigger before the trigger), time-out in ms of card time (-1: 1 h)")
      .def("sampling_block_ready", &ApsScope::sampling_block_ready, "the block is full")
      .def("sampling_ticks_left", &ApsScope::sampling_ticks_left, "servo ticks until the sampling time-out")
      .def("finish_sampling", [](ApsScope& s) { return code(s.finish_sampling()); },
           "the full block into DataArr (ERR_NoError) or the sampler stopped (ERR_TimeOut)")
      .def("sampling_count", &ApsScope::sampling_count, "samples copied into DataArr so far")
      .def("stop_sampling", &ApsScope::stop_sampling)
      .def("sampling_buffer", &buffer_array, "DataArr: NumPy array of STR_SAMP_DATA_4CH (None before a run)")
      .def("set_trigger_param", [](ApsScope& s, double p, double v) { return code(s.set_trigger_param(p, v)); },
           py::arg("para"), py::arg("value"), "TGR_* / TIMR_* register; returns the APS code")
      .def("trigger_param", [](const ApsScope& s, double p) {
             int v = 0;
             const int c = code(s.trigger_param(p, v));
             return py::make_tuple(c, v);
           }, py::arg("para"), "(code, value) of a TGR_* / TIMR_* register")
      .def("timer_counter", &ApsScope::timer_counter, "the compare timer's count now")
      .def("set_timer_counter", [](ApsScope& s, double v) { return code(s.set_timer_counter(v)); }, py::arg("value"),
           "sets the timer count (I32)");
  m.def("aps_scope", [](machine::Card& k) -> ApsScope& { return vendor::adlink::aps_scope(k); }, py::arg("card"),
        py::return_value_policy::reference_internal,
        "the card's ADLINK scope module (created on first use, owned by the card)");
  py::class_<ApsInterrupts>(m, "ApsInterrupts",
                            "The ADLINK host interrupts of a card (vendor/adlink/aps_interrupts.hpp, L4090-4330): the "
                            "main switch, the factors, the signaled flags. Get it with aps_interrupts(card).")
      .def("power_on", &ApsInterrupts::power_on, "main switch off, no factor, no interrupt number known")
      .def("set_main", [](ApsInterrupts& s, double on) { return code(s.set_main(on)); }, py::arg("enable"))
      .def("set_factor", &ApsInterrupts::set_factor, py::arg("item"), py::arg("factor"), py::arg("enable"),
           "the interrupt number (item x 32 + bit) or a negative APS code")
      .def("factor_enabled", [](const ApsInterrupts& s, double item, double f) {
             int on = 0;
             const int c = code(s.factor_enabled(item, f, on));
             return py::make_tuple(c, on);
           }, py::arg("item"), py::arg("factor"))
      .def("msts_mask", &ApsInterrupts::msts_mask, py::arg("axis"))
      .def("mio_mask", &ApsInterrupts::mio_mask, py::arg("axis"))
      .def("system_mask", &ApsInterrupts::system_mask)
      .def("fired", &ApsInterrupts::fired, py::arg("axis"), py::arg("word"), py::arg("bits"),
           "a watched event fired (Card.on_event): signals the enabled factors it matches")
      .def("set_signaled", [](ApsInterrupts& s, double no, bool on) { return code(s.set_signaled(no, on)); },
           py::arg("int_no"), py::arg("on"))
      .def("begin_wait", [](ApsInterrupts& s, double n, const std::vector<double>& nos, double all, double tmo) {
             long long ticks = 0;
             const int c = code(s.begin_wait(n, nos, all, tmo, ticks));
             return py::make_tuple(c, ticks);
           }, py::arg("count"), py::arg("nos"), py::arg("wait_all"), py::arg("time_out_ms"),
           "(code, ticks the wait may run)")
      .def("wait_done", &ApsInterrupts::wait_done, "the wait's numbers are signaled (all / any)");
  m.def("aps_interrupts", [](machine::Card& k) -> ApsInterrupts& { return vendor::adlink::aps_interrupts(k); },
        py::arg("card"), py::return_value_policy::reference_internal,
        "the card's ADLINK interrupt module (created on first use, owned by the card)");
  py::class_<ApsParameters>(m, "ApsParameters",
                            "The ADLINK PRA_* axis parameters of a card (vendor/adlink/aps_parameters.hpp): stored "
                            "motion / home / jog / gear parameters, the others written through. Get it with "
                            "aps_parameters(card).")
      .def("power_on", &ApsParameters::power_on, "every axis back to the defaults (APS_initial)")
      .def("set", [](ApsParameters& s, std::size_t i, double para, double v) { return code(s.set(i, para, v)); },
           py::arg("axis"), py::arg("para"), py::arg("value"), "APS_set_axis_param_f: the APS code")
      .def("get", [](const ApsParameters& s, std::size_t i, double para) {
             double v = 0.0;
             const int c = code(s.get(i, para, v));
             return py::make_tuple(c, v);
           }, py::arg("axis"), py::arg("para"), "APS_get_axis_param_f: (code, value)")
      .def("motion", [](const ApsParameters& s, std::size_t i) { return s.axis(i).motion; }, py::arg("axis"),
           "PRA_SF/ACC/DEC/VS/VM/VE/SD_DEC as an AdlinkPtp (not validated: replace() validates)")
      .def("home", [](const ApsParameters& s, std::size_t i) { return s.axis(i).home; }, py::arg("axis"),
           "PRA_HOME_* as an AdlinkHome (not validated)")
      .def("jog", [](const ApsParameters& s, std::size_t i) { return s.axis(i).jog; }, py::arg("axis"),
           "PRA_JG_* as an AdlinkJog (not validated)")
      .def("gear", [](const ApsParameters& s, std::size_t i) {
             const auto& r = s.axis(i);
             return py::make_tuple(r.gear_master, r.gear_ratio, r.gear_rate);
           }, py::arg("axis"), "(PRA_GEAR_MASTER, PRA_GEAR_RATIO, PRA_GEAR_ENGAGE_RATE ratio/s)");
  m.def("aps_parameters", [](machine::Card& k) -> ApsParameters& { return vendor::adlink::aps_parameters(k); },
        py::arg("card"), py::return_value_policy::reference_internal,
        "the card's ADLINK PRA_* parameter table (created on first use, owned by the card)");
  py::class_<ApsOutputs>(m, "ApsOutputs",
                         "The ADLINK board outputs of a card (vendor/adlink/aps_outputs.hpp): DO0..7, board "
                         "parameters, VAO tables (L3436-3542). Get it with aps_outputs(card).")
      .def("power_on", &ApsOutputs::power_on, "outputs off, no PWM mapping, VAO tables empty (APS_initial)")
      .def("write_do", [](ApsOutputs& s, double g, double d) { return code(s.write_do(g, d)); }, py::arg("group"),
           py::arg("data"))
      .def("read_do", [](const ApsOutputs& s, double g) {
             int d = 0;
             const int c = code(s.read_do(g, d));
             return py::make_tuple(c, d);
           }, py::arg("group"), "(code, DO0..7 as bits)")
      .def("set_do_bit", &ApsOutputs::set_do_bit, py::arg("channel"), py::arg("on"))
      .def("all_do_off", &ApsOutputs::all_do_off)
      .def("set_board_param", [](ApsOutputs& s, double p, double v) { return code(s.set_board_param(p, v)); },
           py::arg("para"), py::arg("value"))
      .def("board_param", [](const ApsOutputs& s, double p) {
             int v = 0;
             const int c = code(s.board_param(p, v));
             return py::make_tuple(c, v);
           }, py::arg("para"))
      .def("set_vao_param", [](ApsOutputs& s, double p, double v) { return code(s.set_vao_param(p, v)); },
           py::arg("para"), py::arg("value"))
      .def("set_vao_table", [](ApsOutputs& s, double n, double vmin, double dv, double cnt, const std::vector<double>& pw) {
             return code(s.set_vao_table(n, vmin, dv, cnt, pw));
           }, py::arg("table"), py::arg("min_velocity"), py::arg("interval"), py::arg("count"), py::arg("powers"))
      .def("switch_vao_table", [](ApsOutputs& s, double n) { return code(s.switch_vao_table(n)); }, py::arg("table"))
      .def("select_vao", &ApsOutputs::select_vao, py::arg("ctrl"), py::arg("table"))
      .def("start_vao", [](ApsOutputs& s, double ch, double en) { return code(s.start_vao(ch, en)); },
           py::arg("channel"), py::arg("enable"))
      .def("all_pwm_off", &ApsOutputs::all_pwm_off)
      .def("vao_output", [](const ApsOutputs& s, int ctrl) {
             const vendor::adlink::VaoOutput o = s.vao_output(ctrl);
             py::dict d;
             d["on"] = o.on;
             d["table"] = o.table;
             d["speed"] = o.speed;
             d["power"] = o.power;
             d["unit"] = o.unit;
             return d;
           }, py::arg("ctrl"), "on, table, speed (pulse/s), power (the output type's unit), unit");
  m.def("aps_outputs", [](machine::Card& k) -> ApsOutputs& { return vendor::adlink::aps_outputs(k); },
        py::arg("card"), py::return_value_policy::reference_internal,
        "the card's ADLINK output module (created on first use, owned by the card)");
  bind_point_tables(m);
  using vendor::adlink::ApsWatchdog;
  py::class_<ApsWatchdog>(m, "ApsWatchdog",
                          "The ADLINK watchdog of a card (vendor/adlink/aps_watchdog.hpp, L4025-4084): time-out "
                          "x 100 ms of card time, action bits (servo off, DO off, PWM off), checked every 1 ms. Get "
                          "it with aps_watchdog(card).")
      .def("power_on", &ApsWatchdog::power_on, "off, time-out 0, action 0 (APS_initial / APS_close)")
      .def("set_action", [](ApsWatchdog& s, double b, double t, double v) { return code(s.set_action(b, t, v)); },
           py::arg("board"), py::arg("timer"), py::arg("bits"))
      .def("action", [](const ApsWatchdog& s, double b, double t) {
             int v = 0;
             const int c = code(s.action(b, t, v));
             return py::make_tuple(c, v);
           }, py::arg("board"), py::arg("timer"), "(code, action bits)")
      .def("start", [](ApsWatchdog& s, double b, double t, double v) { return code(s.start(b, t, v)); },
           py::arg("board"), py::arg("timer"), py::arg("time_out"), "arms it: time_out x 100 ms (0 disables)")
      .def("period", [](const ApsWatchdog& s, double b, double t) {
             int v = 0;
             const int c = code(s.period(b, t, v));
             return py::make_tuple(c, v);
           }, py::arg("board"), py::arg("timer"), "(code, time-out x 100 ms)")
      .def("reset_counter", [](ApsWatchdog& s, double b, double t) { return code(s.reset_counter(b, t)); },
           py::arg("board"), py::arg("timer"))
      .def_property_readonly("armed", &ApsWatchdog::armed)
      .def_property_readonly("fired", &ApsWatchdog::fired);
  m.def("aps_watchdog", [](machine::Card& k) -> ApsWatchdog& { return vendor::adlink::aps_watchdog(k); },
        py::arg("card"), py::return_value_policy::reference_internal,
        "the card's ADLINK watchdog (created on first use, owned by the card)");
  m.def("aps_release_axis", [](machine::Card& k, AxisIndex i) { vendor::adlink::aps_release_axis(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"),
        "before a single-axis command: an idle group or halted gear hands the axis back, ended limit events clear");
  m.def("aps_release_modes",
        [](machine::Card& k, AxisIndex i) { vendor::adlink::aps_release_modes(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"),
        "an idle interpolation group or a halted gear hands the axis back (V116, V121)");
  m.def("aps_stop_modes", [](machine::Card& k, AxisIndex i, bool abrupt) {
          return vendor::adlink::aps_stop_modes(k, card_axis(k, i), abrupt);
        }, py::arg("card"), py::arg("axis"), py::arg("abrupt"),
        "a stop of an axis of a moving group stops the group; of a gear slave releases the gear: True if so");
}

}  // namespace servobench::bindings
