// The GE list module (vendor/googol/ge_list.hpp) for the GE dialect: _core.ge_list(card) -> GeList, whose methods
// return the GE return code as an int (Table 2-2 L272-283). Thin: no logic; planes by name, msg as a tuple.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <tuple>

#include "servobench/vendor/googol/ge_commands.hpp"
#include "servobench/vendor/googol/ge_list.hpp"
#include "servobench/vendor/googol/ge_registers.hpp"
#include "servobench/vendor/googol/ge_watch.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using vendor::googol::GeCode;
using vendor::googol::GeList;
using vendor::googol::GeLookAheadMsg;
using vendor::googol::GePlane;
using vendor::googol::GeRegisters;
using vendor::googol::GeSense;
using vendor::googol::GeMotionRegister;

namespace {

int rc(GeCode c) { return static_cast<int>(c); }

GeSense sense_of(const std::string& s) {
  if (s == "limit") return GeSense::Limit;
  if (s == "home") return GeSense::Home;
  if (s == "index") return GeSense::Index;
  if (s == "encoder") return GeSense::Encoder;
  throw py::value_error("sense: '" + s + "' is not one of limit, home, index, encoder");
}

GeMotionRegister register_of(const std::string& s) {
  if (s == "vel") return GeMotionRegister::Vel;
  if (s == "acc") return GeMotionRegister::Acc;
  if (s == "macc") return GeMotionRegister::MAcc;
  if (s == "jerk") return GeMotionRegister::Jerk;
  throw py::value_error("register: '" + s + "' is not one of vel, acc, macc, jerk");
}

GePlane plane_of(const std::string& s) {
  if (s == "xy") return GePlane::XY;
  if (s == "yz") return GePlane::YZ;
  if (s == "zx") return GePlane::ZX;
  throw py::value_error("plane: '" + s + "' is not one of xy, yz, zx");
}

using Msg = std::tuple<long long, long long, int>;  // TLookAheadMsg (mtnNum, num, error)
GeLookAheadMsg msg_of(const Msg& m) { return {std::get<0>(m), std::get<1>(m), std::get<2>(m)}; }
Msg msg_to(const GeLookAheadMsg& m) { return {m.mtn_num, m.num, m.error}; }

// A reply as the manual's C call returns it in Python: the code, or (code, value) for a read.
py::object reply(const vendor::googol::GeReply& r) {
  if (!r.read) return py::int_(rc(r.code));
  if (r.integer) return py::make_tuple(rc(r.code), static_cast<long long>(r.value));
  return py::make_tuple(rc(r.code), r.value);
}

// (code, msg') for an Ex command that fills a TLookAheadMsg.
template <class F>
std::pair<int, Msg> with_msg(const Msg& in, F&& f) {
  GeLookAheadMsg m = msg_of(in);
  const int code = rc(f(m));
  return {code, msg_to(m)};
}

}  // namespace

void bind_vendor_ge(py::module_& m) {
  py::class_<GeList>(m, "GeList",
      "The GE SX path list of a card (vendor/googol/ge_list.hpp): feed, buffer, look-ahead modules A and B; every\n"
      "method returns the GE return code (pulse, pulse/ms, pulse/ms^2; the Ex commands mm, mm/s).")
      .def("line", [](GeList& l, const std::vector<double>& p, bool g0) { return rc(l.line(p, g0)); },
           py::arg("point"), py::arg("g0"))
      .def("arc_center", [](GeList& l, const std::string& pl, double c1, double c2, double angle) {
             return rc(l.arc_center(plane_of(pl), c1, c2, angle)); })
      .def("arc_radius", [](GeList& l, const std::string& pl, double e1, double e2, double r, double dir) {
             return rc(l.arc_radius(plane_of(pl), e1, e2, r, dir)); })
      .def("set_syn_vel", [](GeList& l, double v) { return rc(l.set_syn_vel(v)); })
      .def("set_syn_acc", [](GeList& l, double v) { return rc(l.set_syn_acc(v)); })
      .def("set_strt_vel", [](GeList& l, double v) { return rc(l.set_strt_vel(v)); })
      .def("set_max_vel", [](GeList& l, double v) { return rc(l.set_max_vel(v)); })
      .def("set_stp_acc", [](GeList& l, double v) { return rc(l.set_stp_acc(v)); })
      .def("set_override", [](GeList& l, double v, bool g0) { return rc(l.set_override(v, g0)); })
      .def("set_dcc_vel", [](GeList& l, double v) { return rc(l.set_dcc_vel(v)); })
      .def("map_cnt", [](GeList& l, double axis, double count) { return rc(l.map_cnt(axis, count)); })
      .def("strt_list", [](GeList& l) { return rc(l.strt_list()); })
      .def("mv", [](GeList& l, const std::vector<double>& p, double vel, double acc) { return rc(l.mv(p, vel, acc)); })
      .def("end_list", [](GeList& l) { return rc(l.end_list()); })
      .def("add_list", [](GeList& l) { return rc(l.add_list()); })
      .def("strt_mtn", [](GeList& l) { return rc(l.strt_mtn()); })
      .def("stp_mtn", [](GeList& l, bool abrupt) { return rc(l.stp_mtn(abrupt)); })
      .def("restore_mtn", [](GeList& l) { return rc(l.restore_mtn()); })
      .def("buf_io", [](GeList& l, double w) { return rc(l.buf_io(w)); })
      .def("buf_io_bit", [](GeList& l, double b, double v) { return rc(l.buf_io_bit(b, v)); })
      .def("delay", [](GeList& l, double ms) { return rc(l.delay(ms)); })
      .def("crd_status", &GeList::crd_status)
      .def("point", &GeList::point, py::arg("which"), "0 profile point, 1 segment end, 2 breakpoint (or None)")
      .def("mtn_nm", &GeList::mtn_nm)
      .def("prf_vel", &GeList::prf_vel)
      .def("init_look_ahead", [](GeList& l, double t, double acc_max, double acc, double vel, double n, double con) {
             motion::GeLookAheadParams p;
             p.t_s = t, p.acc_max = acc_max, p.acc = acc, p.vel = vel, p.n = n, p.con = con;
             return rc(l.init_look_ahead(p));
           })
      .def("add_look_data", &GeList::add_look_data)
      .def("cal_vel", [](GeList& l) {
             double v = 0.0;
             long long n = 0;
             const int code = l.cal_vel(v, n);
             return std::make_tuple(code, v, n);
           })
      .def("init_look_ahead_ex", [](GeList& l, double t, double amax, double am, double n, double con) {
             return rc(l.init_look_ahead_ex(t, amax, am, n, con)); })
      .def("mv_ex", [](GeList& l, const std::vector<double>& p, double vel) { return rc(l.mv_ex(p, vel)); })
      .def("line_ex", [](GeList& l, const std::vector<double>& p, double f, double dcc, double num, bool g0,
                         const Msg& msg) {
             return with_msg(msg, [&](GeLookAheadMsg& m) { return l.line_ex(p, f, dcc, num, g0, m); }); })
      .def("arc_center_ex", [](GeList& l, const std::string& pl, double c1, double c2, double angle, double f,
                               double dcc, double num, const Msg& msg) {
             return with_msg(msg, [&](GeLookAheadMsg& m) {
               return l.arc_center_ex(plane_of(pl), c1, c2, angle, f, dcc, num, m); }); })
      .def("arc_radius_ex", [](GeList& l, const std::string& pl, double e1, double e2, double r, double dir, double f,
                               double dcc, double num, const Msg& msg) {
             return with_msg(msg, [&](GeLookAheadMsg& m) {
               return l.arc_radius_ex(plane_of(pl), e1, e2, r, dir, f, dcc, num, m); }); })
      .def("buf_io_ex", [](GeList& l, double w) { return rc(l.buf_io_ex(w)); })
      .def("buf_io_bit_ex", [](GeList& l, double b, double v) { return rc(l.buf_io_bit_ex(b, v)); })
      .def("delay_ex", [](GeList& l, double ms) { return rc(l.delay_ex(ms)); })
      .def("m30", [](GeList& l, const Msg& msg) {
             return with_msg(msg, [&](GeLookAheadMsg& m) { return l.m30(m); }); })
      .def("leave_crd", &GeList::leave_crd, py::arg("axis"))
      .def("outputs", &GeList::outputs, "the EXO word with the buffer's writes merged")
      .def("set_outputs", &GeList::set_outputs, py::arg("word"))
      .def("reset", &GeList::reset, "back to the power-on values (as GT_Reset)");

  py::class_<GeRegisters>(m, "GeRegisters",
      "The GE registers of a card the kernel has no field for (vendor/googol/ge_registers.hpp): CtrlMode, StepDir/\n"
      "StepPulse, EncOn/Off, the sense words, EXI levels, A/D channels, Set* values in GE units. Axes 1..axes;\n"
      "the commands return the GE return code.")
      .def("set_sense", [](GeRegisters& r, const std::string& which, double w) { return rc(r.set_sense(sense_of(which), w)); })
      .def("sense", [](const GeRegisters& r, const std::string& which) { return r.sense(sense_of(which)); })
      .def("set_encoder", [](GeRegisters& r, double axis, bool on) { return rc(r.set_encoder(axis, on)); })
      .def("set_ctrl_mode", [](GeRegisters& r, double axis, double mode) { return rc(r.set_ctrl_mode(axis, mode)); })
      .def("set_step_form", [](GeRegisters& r, double axis, bool pulse) { return rc(r.set_step_form(axis, pulse)); })
      .def("refuse_on_pulse_axis", &GeRegisters::refuse_on_pulse_axis, py::arg("axis"))
      .def("ctrl_mode", [](const GeRegisters& r, std::size_t a) { return r.at(a).ctrl_mode; }, py::arg("axis"))
      .def("step_pulse", [](const GeRegisters& r, std::size_t a) { return r.at(a).step_pulse; }, py::arg("axis"))
      .def("encoder_on", [](const GeRegisters& r, std::size_t a) { return r.at(a).encoder_on; }, py::arg("axis"))
      .def("limit_levels", &GeRegisters::limit_levels, "GT_GetLmtSwt word")
      .def("home_levels", &GeRegisters::home_levels, "GT_GetHomeSwt word")
      .def("actual_vel", &GeRegisters::actual_vel, py::arg("axis"), "GT_GetAtlVel, pulse/ms")
      .def("set_inputs", &GeRegisters::set_inputs, py::arg("word"))
      .def("inputs", &GeRegisters::inputs)
      .def("set_adc_channels", [](GeRegisters& r, double n) { return rc(r.set_adc_channels(n)); })
      .def("adc_channels", &GeRegisters::adc_channels)
      .def("stage_motion", [](GeRegisters& r, std::size_t a, const std::string& reg, double v, double k) {
             r.stage_motion(a, register_of(reg), v, k); }, py::arg("axis"), py::arg("register"), py::arg("value"),
           py::arg("ms_per_tick"))
      .def("reset", &GeRegisters::reset, "back to the power-on values (as GT_Reset)")
      .def("read_motion", [](const GeRegisters& r, std::size_t a, const std::string& reg, double k) {
             return r.read_motion(a, register_of(reg), k); }, py::arg("axis"), py::arg("register"),
           py::arg("ms_per_tick"));

  m.def("ge_command_table", [] {
          py::list rows;
          for (const auto& r : vendor::googol::ge_command_table())
            rows.append(py::make_tuple(r.name, r.params, r.set == vendor::googol::GeCommandSet::PX ? "PX"
                                       : r.set == vendor::googol::GeCommandSet::SX ? "SX" : "", r.read, r.doc));
          return rows;
        }, "The GE commands (vendor/googol/ge_commands.hpp): (name, parameters, 'PX'/'SX'/'' the command set, read, doc).");
  m.def("ge_axis_command_names", &vendor::googol::ge_axis_command_names, "The commands ge_command runs.");
  m.def("ge_command", [](Card& card, const std::string& variant, const std::string& name,
                         const std::vector<double>& args) {
          const auto v = variant == "SX" ? vendor::googol::GeVariant::SX : vendor::googol::GeVariant::PX;
          return reply(vendor::googol::ge_command(card, v, name, args));
        }, py::arg("card"), py::arg("variant"), py::arg("name"), py::arg("args"),
        "Runs GE command `name` (arguments as doubles in the manual's units): its code, or (code, value) for a read.");
  py::class_<vendor::googol::GeWatch> watch(m, "GeWatch",
      "The GE data watch of a card (vendor/googol/ge_watch.hpp) on its sampler; the commands return the GE code.");
  watch.def("set_watch", [](vendor::googol::GeWatch& w, const std::vector<double>& config, double size) {
             return rc(w.set_watch(config, size)); }, py::arg("config"), py::arg("size"))
      .def("channels", &vendor::googol::GeWatch::channels, "(axis 0-based, config bit) in sampling order")
      .def("size", &vendor::googol::GeWatch::size, "samples per block")
      .def("start", [](vendor::googol::GeWatch& w, double n) { return rc(w.start(n)); }, py::arg("n"))
      .def("next_block", [](vendor::googol::GeWatch& w) {
             std::vector<std::vector<double>> block;
             const int code = rc(w.next_block(block));
             return std::make_pair(code, block.empty() ? py::object(py::none()) : py::cast(block));
           }, "(code, [values per channel in GE units] or None when no block is full)")
      .def("stop", &vendor::googol::GeWatch::stop);
  watch.attr("WATCH_MEMORY_VALUES") = vendor::googol::GeWatch::kWatchMemoryValues;
  m.def("ge_watch", [](Card& card) -> vendor::googol::GeWatch& { return vendor::googol::ge_watch(card); },
        py::return_value_policy::reference_internal, py::arg("card"),
        "The card's GE data watch module (created on first use, owned by the card).");
  m.def("ge_registers", [](Card& card) -> GeRegisters& { return vendor::googol::ge_registers(card); },
        py::return_value_policy::reference_internal, py::arg("card"),
        "The card's GE registers module (created on first use, owned by the card).");
  m.def("ge_list", [](Card& card) -> GeList& { return vendor::googol::ge_list(card); },
        py::return_value_policy::reference_internal, py::arg("card"),
        "The card's GE list module (created on first use, owned by the card).");
}

}  // namespace servobench::bindings
