// The GT vendor module (vendor/googol/gt_card.hpp, gt_crd_list.hpp, gt_interrupts.hpp): thin, every GT command
// returns the manual's code as an int; servobench.dialects.gt is a table of one-line adapters over it.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <any>
#include <string>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gt_card.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using vendor::googol::GtArg;
using vendor::googol::GtCard;
using vendor::googol::GtCode;
using vendor::googol::GtCrdList;
using vendor::googol::GtInterrupts;

namespace {

int code(GtCode c) { return static_cast<int>(c); }

motion::ArcPlane plane_of(const std::string& plane) {
  if (plane == "xy") return motion::ArcPlane::XY;
  if (plane == "yz") return motion::ArcPlane::YZ;
  if (plane == "zx") return motion::ArcPlane::ZX;
  throw std::invalid_argument("plane = '" + plane + "' is not one of xy, yz, zx");
}

machine::CommandFault fault_of(const std::string& name) {
  using F = machine::CommandFault;
  for (int f = 0; f <= static_cast<int>(F::NoInterruptPending); ++f)
    if (name == machine::to_string(static_cast<F>(f))) return static_cast<F>(f);
  throw std::invalid_argument("fault = '" + name + "' is not a CommandFault name");
}

std::function<void()> caller(const py::object& f, const char* method) {
  if (f.is_none()) return {};
  py::object target = method ? f.attr(method) : f;
  return [target] { target(); };
}

}  // namespace

void bind_vendor_gt(py::module_& m) {
  py::class_<vendor::googol::GtSystemRegs>(m, "GtSystemRegs", "The GT I/O and system registers (gt_card.hpp)")
      .def_readwrite("enc_sns", &vendor::googol::GtSystemRegs::enc_sns)
      .def_readwrite("step_pulse", &vendor::googol::GtSystemRegs::step_pulse)
      .def_readwrite("adc_chn", &vendor::googol::GtSystemRegs::adc_chn)
;

  py::class_<vendor::googol::AuxInputs>(
      m, "GtAuxInputs",
      "What the machine gives the GT auxiliary-encoder inputs at one read (gt_aux_encoder.hpp): counts(n, t_s) the\n"
      "raw whole count (pulse) of encoder n (0, 1) at card time t_s (s), the wiring's reversed bits (4, 5) and\n"
      "encoder 1's index marks (counts per index, 0 = none; the offset of one mark, pulse).")
      .def(py::init([](std::function<long long(int, double)> counts, int reversed, long long counts_per_index,
                       double index_offset) {
             return vendor::googol::AuxInputs{std::move(counts), reversed, counts_per_index, index_offset};
           }), py::arg("counts"), py::arg("reversed") = 0, py::arg("counts_per_index") = 0,
           py::arg("index_offset") = 0.0);
  m.def("aux_index_mark_between", &vendor::googol::index_mark_between, py::arg("a"), py::arg("b"),
        py::arg("counts_per_index"), py::arg("index_offset"),
        "the first index-mark count (pulse) reached moving from count a to count b, marks at index_offset + k\n"
        "counts_per_index; None when none is (gt_aux_encoder.hpp)");

  py::class_<GtCard, std::unique_ptr<GtCard, py::nodelete>>(
      m, "GtCard",
      "The GT registers of one card (vendor/googol/gt_card.hpp): current axis, LmtSns, Index, the coordinated\n"
      "list, the interrupts, the system registers. Every command returns the GT code (Table 2-1 L393-408).")
      .def_property_readonly("axis", &GtCard::axis, "the current axis, 0-based (GT_Axis)")
      .def("check", [](GtCard& g, double v, double lo, double hi, const std::string& kind, const std::string& fault) {
             const GtArg k = kind == "int" ? GtArg::Integer : kind == "real" ? GtArg::Real : GtArg::RealHalfOpen;
             return code(g.check(v, lo, hi, k, fault_of(fault)));
           }, py::arg("value"), py::arg("lo"), py::arg("hi"), py::arg("kind") = "int",
           py::arg("fault") = "illegal_control_param",
           "0, or 7 with the fault recorded on the current axis: value in lo..hi (kind int, real, real_open)")
      .def("refuse", [](GtCard& g, const std::string& fault) { return code(g.refuse(fault_of(fault))); },
           py::arg("fault"), "records the fault on the current axis; 1")
      .def("select_axis", [](GtCard& g, double n) { return code(g.select_axis(n)); }, py::arg("num"))
      .def("select_interrupting_axis", [](GtCard& g) { return code(g.select_interrupting_axis()); })
      .def("set_limit_sense", [](GtCard& g, double s) { return code(g.set_limit_sense(s)); }, py::arg("sense"))
      .def_property_readonly("limit_sense", &GtCard::limit_sense)
      .def("limit_switches", &GtCard::limit_switches)
      .def("set_index", [](GtCard& g, double v) { return code(g.set_index(v)); }, py::arg("value"))
      .def("index", [](const GtCard& g, int i) { return g.index(static_cast<std::size_t>(i)); }, py::arg("axis"))
      .def("home", [](GtCard& g, double pos) { return code(g.home(pos)); }, py::arg("pos"))
      .def("command_status", &GtCard::command_status)
      .def("capture_probe", [](GtCard& g) { return code(g.capture_probe()); })
      .def_property_readonly("system", [](GtCard& g) { return &g.system(); }, py::return_value_policy::reference_internal,
                             "the I/O and system registers")
      .def("hard_reset", [](GtCard& g) { return code(g.hard_reset()); })
      // -- encoders (gt_aux_encoder.hpp) ----------------------------------------------------------------------
      .def("set_encoder_sense", [](GtCard& g, double s, const vendor::googol::AuxInputs& in) {
             return code(g.set_encoder_sense(s, in));
           }, py::arg("sense"), py::arg("inputs"))
      .def("aux_position", [](GtCard& g, double n, const vendor::googol::AuxInputs& in) {
             const auto [c, v] = g.aux_position(n, in);
             return py::make_tuple(code(c), v);
           }, py::arg("num"), py::arg("inputs"))
      .def("aux_velocity", [](GtCard& g, double n, const vendor::googol::AuxInputs& in) {
             const auto [c, v] = g.aux_velocity(n, in);
             return py::make_tuple(code(c), v);
           }, py::arg("num"), py::arg("inputs"))
      .def("clear_aux_position", [](GtCard& g, double n, const vendor::googol::AuxInputs& in) {
             return code(g.clear_aux_position(n, in));
           }, py::arg("num"), py::arg("inputs"))
      .def("arm_aux_capture", [](GtCard& g, const vendor::googol::AuxInputs& in) { return code(g.arm_aux_capture(in)); },
           py::arg("inputs"))
      .def("aux_capture_status", [](GtCard& g, const vendor::googol::AuxInputs& in) {
             const auto [c, v] = g.aux_capture_status(in);
             return py::make_tuple(code(c), v);
           }, py::arg("inputs"))
      .def("aux_capture_value", [](GtCard& g, const vendor::googol::AuxInputs& in) {
             const auto [c, v] = g.aux_capture_value(in);
             return py::make_tuple(code(c), v);
           }, py::arg("inputs"))
      .def_property_readonly("aux_zero", [](const GtCard& g) { return g.aux().zero(); },
                             "the auxiliary encoders' zero offsets, pulse")
      // -- coordinated list ------------------------------------------------------------------------------------
      .def("map_axis", [](GtCard& g, double a, const std::vector<double>& c) { return code(g.crd().map_axis(a, c)); },
           py::arg("axis"), py::arg("counts"))
      .def("set_syn_vel", [](GtCard& g, double v) { return code(g.crd().set_syn_vel(v)); }, py::arg("vel"))
      .def("set_syn_acc", [](GtCard& g, double a) { return code(g.crd().set_syn_acc(a)); }, py::arg("acc"))
      .def("set_acc_lmt", [](GtCard& g, double a) { return code(g.crd().set_acc_lmt(a)); }, py::arg("acc"))
      .def("line", [](GtCard& g, const std::vector<double>& p) { return code(g.crd().line(p)); }, py::arg("point"))
      .def("arc_center_angle", [](GtCard& g, const std::string& plane, double c1, double c2, double angle) {
             return code(g.crd().arc_center_angle(plane_of(plane), c1, c2, angle));
           }, py::arg("plane"), py::arg("center_1"), py::arg("center_2"), py::arg("angle_deg"))
      .def("arc_end_radius", [](GtCard& g, const std::string& plane, double e1, double e2, double r, double dir) {
             return code(g.crd().arc_end_radius(plane_of(plane), e1, e2, r, dir));
           }, py::arg("plane"), py::arg("end_1"), py::arg("end_2"), py::arg("radius"), py::arg("direction"))
      .def("start_list", [](GtCard& g) { return code(g.crd().start_list()); })
      .def("move_start_point", [](GtCard& g, const std::vector<double>& p, double v, double a) {
             return code(g.crd().move_start_point(p, v, a));
           }, py::arg("point"), py::arg("vel"), py::arg("acc"))
      .def("end_list", [](GtCard& g) { return code(g.crd().end_list()); })
      .def("add_list", [](GtCard& g) { return code(g.crd().add_list()); })
      .def("start_motion", [](GtCard& g) { return code(g.crd().start_motion()); })
      .def("stop_motion", [](GtCard& g, bool abrupt) { return code(g.crd().stop(abrupt)); }, py::arg("abrupt"))
      .def("set_crd_auto_stop", [](GtCard& g, bool on) { return code(g.crd().set_auto_stop(on)); }, py::arg("on"))
      .def("motion_number", [](const GtCard& g) { return g.crd().motion_number(); })
      .def("crd_status", [](const GtCard& g) { return g.crd().status(); })
      .def("crd_breakpoint", [](GtCard& g) {
             std::optional<std::vector<double>> p;
             const GtCode c = g.crd().breakpoint(p);
             return py::make_tuple(code(c), p ? py::cast(*p) : c == GtCode::Success ? py::none() : py::object(py::int_(0)));
           })
      .def("crd_registers", [](const GtCard& g) {
             const auto& r = g.crd().regs();
             py::dict d;
             d["vel"] = r.vel, d["acc"] = r.acc, d["buffer"] = r.buffer, d["open"] = r.open, d["mv"] = r.mv;
             d["started"] = r.started, d["error"] = r.error, d["au_stp"] = r.au_stp, d["cmd_bit"] = r.cmd_bit;
             d["pushed"] = r.pushed, d["mv_pushed"] = r.mv_pushed, d["acc_lmt"] = r.acc_lmt;
             return d;
           }, "the list registers (read-only view)")
      // -- interrupts --------------------------------------------------------------------------------------------
      .def("hook_isr", [](GtCard& g, py::object isr) {
             if (!isr.is_none() && !PyCallable_Check(isr.ptr()))
               throw py::type_error("GT_HookIsr: isr must be callable (or None)");
             auto& held = g.interrupts().isr_object;
             py::object old = held.has_value() ? std::any_cast<py::object>(held) : py::none();
             held = isr;
             g.interrupts().isr = caller(isr, nullptr);
             return old;
           }, py::arg("isr"), "sets the host's routine; returns the previous one (None at first)")
      .def("set_sync_event", [](GtCard& g, py::object ev) {
             if (!ev.is_none() && !(py::hasattr(ev, "set") && PyCallable_Check(ev.attr("set").ptr())))
               return code(GtCode::ParameterError);
             g.interrupts().sync = caller(ev, "set");
             return code(GtCode::Success);
           }, py::arg("event"))
      .def("set_resubscribe", [](GtCard& g, py::object f) { g.interrupts().resubscribe = caller(f, nullptr); },
           py::arg("renew"), "the dialect's renewal of its Card.on_event subscriptions")
      .def("event_interrupts", [](GtCard& g) { return code(g.interrupts().event_mode()); })
      .def("timer_interrupts", [](GtCard& g) { return code(g.interrupts().timer_mode()); })
      .def("set_interrupt_timer", [](GtCard& g, double t) { return code(g.interrupts().set_timer(t)); },
           py::arg("periods"))
      .def_property_readonly("interrupt_timer", [](const GtCard& g) { return g.interrupts().regs().timer; })
      .def_property_readonly("timer_interrupt_mode", [](const GtCard& g) { return g.interrupts().timer_active(); })
      .def("set_interrupt_mask", [](GtCard& g, double mk) { return code(g.interrupts().set_mask(mk)); },
           py::arg("mask"))
      .def("interrupt_mask", [](const GtCard& g) { return g.interrupts().mask_of_current_axis(); })
      .def("interrupt_status", [](const GtCard& g) { return g.interrupts().status(); })
      .def("reset_interrupt", [](GtCard& g, double mk) { return code(g.interrupts().reset_request(mk)); },
           py::arg("mask"))
      .def("clear_interrupt", [](GtCard& g, double n) { return code(g.interrupts().clear(n)); }, py::arg("card_no"))
      .def("watched_bits", [](const GtCard& g) { return g.interrupts().watched_bits(); })
      .def_property("subscriptions", [](const GtCard& g) { return g.interrupts().regs().subscriptions; },
                    [](GtCard& g, std::vector<long long> ids) { g.interrupts().set_subscriptions(std::move(ids)); })
      .def("request_interrupt", [](GtCard& g) { g.interrupts().request(); })
      .def("timer_interrupt", [](GtCard& g) { g.interrupts().timer(); });

  m.def("gt_card", [](Card& card) { return &vendor::googol::gt(card); }, py::arg("card"),
        py::return_value_policy::reference_internal,
        "the card's GT module (created and attached on first use; 4-axis cards only)");
}

}  // namespace servobench::bindings
