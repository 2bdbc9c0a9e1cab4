// The ADLINK module of the Card (vendor/adlink/adlink_axes.hpp: immediate moves, trigger, limit stop mode, distance
// events, error level, in-position band, homing and jog sequences), the interpolation group
// (vendor/adlink/adlink_group.hpp) and the gear engage ramp: thin, axes 0-based; servobench.dialects.aps translates.
// The module's methods stay methods of Card (the Python API of the card is unchanged). Called from bind_card.cpp.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "flag.hpp"

#include <string>
#include <vector>

#include "card_axis.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;

namespace {

motion::SpacePoint point(const std::vector<double>& v, const char* name) {
  if (v.size() > static_cast<std::size_t>(motion::kSpaceMaxDim))
    throw_invalid("Card.aps_interp", name, static_cast<double>(v.size()), "has at most 6 values");
  motion::SpacePoint p{};
  for (std::size_t k = 0; k < v.size(); ++k) p[k] = v[k];
  return p;
}

motion::AdlinkMoveSpec::Kind kind_of(const std::string& kind) {
  using K = motion::AdlinkMoveSpec::Kind;
  if (kind == "line") return K::Line;
  if (kind == "arc2_ca") return K::Arc2Ca;
  if (kind == "arc2_ce") return K::Arc2Ce;
  if (kind == "arc3_ca") return K::Arc3Ca;
  if (kind == "arc3_ce") return K::Arc3Ce;
  if (kind == "spiral_ca") return K::SpiralCa;
  if (kind == "spiral_ce") return K::SpiralCe;
  if (kind == "dwell") return K::Dwell;
  throw std::invalid_argument("kind = '" + kind + "' is not one of line, arc2_ca, arc2_ce, arc3_ca, arc3_ce, "
                              "spiral_ca, spiral_ce, dwell");
}

}  // namespace

void bind_card_aps(py::class_<Card>& c, py::module_& m) {
  using vendor::adlink::adlink;
  using vendor::adlink::adlink_state;
  c.def("home", [](Card& k, AxisIndex i, const motion::AdlinkHomeParams& p) { adlink(k).home(card_axis(k, i), p); },
        py::arg("axis"), py::arg("params"))
      .def("jog", [](Card& k, AxisIndex i, const motion::AdlinkJogParams& p) { adlink(k).jog(card_axis(k, i), p); },
           py::arg("axis"), py::arg("params"))
      .def("set_jog_on", [](Card& k, AxisIndex i, Flag on) { adlink(k).set_jog_on(card_axis(k, i), on); }, py::arg("axis"),
           py::arg("on"))
      .def("jog_on", [](const Card& k, AxisIndex i) { return k.loop(card_axis(k, i)).jog_on(); }, py::arg("axis"))
      .def("jogging", [](const Card& k, AxisIndex i) { return vendor::adlink::jogging(k, card_axis(k, i)); }, py::arg("axis"))
      .def("move_ptp_wait", [](Card& k, AxisIndex i, const motion::AdlinkPtpParams& p) { adlink(k).move_ptp_wait(card_axis(k, i), p); },
           py::arg("axis"), py::arg("params"))
      .def("move_trigger", [](Card& k, double mask) {
             check_integer("Card", "mask", mask, 1, 255);
             adlink(k).move_trigger(static_cast<std::uint32_t>(mask));
           }, py::arg("mask"))
      .def("waiting_trigger", [](const Card& k, AxisIndex i) { return adlink_state(k, card_axis(k, i)).wait_trigger; },
           py::arg("axis"))
      .def("set_limit_stop_mode", [](Card& k, AxisIndex i, Flag dec, double d) {
             adlink(k).set_limit_stop_mode(card_axis(k, i), dec, d);
           }, py::arg("axis"), py::arg("decelerate"), py::arg("dec_pulse_per_s2"))
      .def("limit_stop_mode", [](const Card& k, AxisIndex i) {
             const auto& s = adlink_state(k, card_axis(k, i));
             return py::make_tuple(s.limit_decelerate, s.limit_dec);
           }, py::arg("axis"))
      .def("set_move_event_distances", [](Card& k, AxisIndex i, double pre, double post) {
             adlink(k).set_move_event_distances(card_axis(k, i), pre, post);
           }, py::arg("axis"), py::arg("pre_pulse"), py::arg("post_pulse"))
      .def("move_event_distances", [](const Card& k, AxisIndex i) {
             const auto& s = adlink_state(k, card_axis(k, i));
             return py::make_tuple(s.pre_event_dist, s.post_event_dist);
           }, py::arg("axis"))
      .def("move_ptp", [](Card& k, AxisIndex i, const motion::AdlinkPtpParams& p) { adlink(k).move_ptp(card_axis(k, i), p); },
           py::arg("axis"), py::arg("params"))
      .def("move_velocity", [](Card& k, AxisIndex i, double v, const motion::AdlinkPtpParams& p) {
             adlink(k).move_velocity(card_axis(k, i), v, p);
           }, py::arg("axis"), py::arg("vel_pulse_per_s"), py::arg("params"))
      .def("stop_move", [](Card& k, AxisIndex i, const motion::AdlinkPtpParams& p) { adlink(k).stop_move(card_axis(k, i), p); },
           py::arg("axis"), py::arg("params"))
      .def("set_in_position_band", [](Card& k, AxisIndex i, double v) { adlink(k).set_in_position_band(card_axis(k, i), v); },
           py::arg("axis"), py::arg("pulse"))
      .def("in_position", [](const Card& k, AxisIndex i) { return vendor::adlink::in_position(k, card_axis(k, i)); },
           py::arg("axis"))
      .def("set_error_level", [](Card& k, AxisIndex i, double v) { adlink(k).set_error_level(card_axis(k, i), v); },
           py::arg("axis"), py::arg("pulse"))
      .def("error_level", [](const Card& k, AxisIndex i) { return adlink_state(k, card_axis(k, i)).error_level_pulse; },
           py::arg("axis"));
  c.def("aps_interp", [](Card& k, const std::vector<AxisIndex>& array, const std::vector<motion::AdlinkPtpParams>& params,
                         const std::string& kind, const std::vector<double>& target, const std::vector<double>& center,
                         const std::vector<double>& normal, double angle_deg, int dir, double height,
                         double final_radius, Flag relative, motion::BlendMode mode, double blend, double vm,
                         const motion::AdlinkPtpParams* all, Flag wait, double dwell_s, double buffer_size,
                         Flag point_table) {
         vendor::adlink::AdlinkGroupMove mv;
         for (AxisIndex a : array) mv.array.push_back(card_axis(k, a));
         mv.params = params;
         mv.spec.kind = kind_of(kind);
         mv.spec.relative = relative;
         mv.spec.target = point(target, "target");
         mv.spec.center = point(center, "center");
         if (!normal.empty()) {
           if (normal.size() != 3) throw_invalid("Card.aps_interp", "normal", static_cast<double>(normal.size()), "has 3 values");
           mv.spec.normal = {normal[0], normal[1], normal[2]};
         }
         mv.spec.angle_deg = angle_deg;
         mv.spec.dir = dir;
         mv.spec.height = height;
         mv.spec.final_radius = final_radius;
         mv.mode = mode;
         mv.blend = blend;
         mv.vm = vm;
         if (all != nullptr) mv.all = *all;
         mv.wait = wait;
         mv.spec.dwell_s = dwell_s;
         check_range("Card.aps_interp", "buffer_size", buffer_size, 1, 1e6, "pending moves");
         mv.buffer_size = buffer_size;
         mv.point_table = point_table;
         vendor::adlink::adlink_group_move(k, mv);
       }, py::arg("array"), py::arg("params"), py::arg("kind"), py::kw_only(),
       py::arg("target") = std::vector<double>{}, py::arg("center") = std::vector<double>{},
       py::arg("normal") = std::vector<double>{}, py::arg("angle_deg") = 0.0, py::arg("dir") = 0,
       py::arg("height") = 0.0, py::arg("final_radius") = 0.0, py::arg("relative") = false,
       py::arg("mode") = motion::BlendMode::AbortBlend, py::arg("blend") = 0.0, py::arg("vm") = 0.0,
       py::arg("all") = nullptr, py::arg("wait") = false, py::arg("dwell_s") = 0.0, py::arg("buffer_size") = 10.0,
       py::arg("point_table") = false,
       "an ADLINK interpolation (APS_line / arc / spiral, or a point-table dwell of dwell_s s) of the axis array "
       "(0-based, first = reference axis) in group slot 3: hosted at rest (with buffer_size pending moves; "
       "point_table: an APS_pt_* table, MTS PTB), buffered with its transition mode while the same array moves")
      .def("aps_interp_trigger", [](Card& k, double mask) {
             check_integer("Card", "mask", mask, 0, 4294967295.0);
             return vendor::adlink::adlink_group_trigger(k, static_cast<std::uint32_t>(mask));
           }, py::arg("mask"), "starts a waiting (MF_WAIT) interpolation whose reference axis is in mask")
      .def("aps_interp_info", [](Card& k) {
             py::dict d;
             const vendor::adlink::AdlinkGroup* g = vendor::adlink::adlink_group(k);
             d["set_up"] = g != nullptr;
             if (g == nullptr) return d;
             std::vector<std::size_t> arr = g->array();
             d["array"] = arr;
             d["busy"] = g->busy();
             d["waiting"] = g->waiting();
             d["blending"] = g->blending();
             d["point_table"] = g->point_table();
             d["running"] = g->interp().running_moves();
             d["pending"] = g->interp().pending();
             d["moves_done"] = g->interp().state().moves_done;
             d["speed"] = g->interp().state().speed;  // vector speed, pulse/s
             const motion::SpacePoint& p = g->interp().state().pos;
             d["pos"] = std::vector<double>(p.begin(), p.begin() + g->interp().dim());
             return d;
           }, "the ADLINK interpolation group: array, busy, waiting, blending, pending, moves_done, speed, pos");
  c.def("set_gear_ramp", [](Card& k, AxisIndex i, AxisIndex master, double ratio, double rate_per_tick) {
         k.modes().set_gear_ramp(card_axis(k, i), card_axis(k, master), ratio, rate_per_tick);
       }, py::arg("axis"), py::arg("master"), py::arg("ratio"), py::arg("rate_per_tick"),
       "ADLINK APS_start_gear: gear on master's profile, the ratio ramped from 0 at rate_per_tick (ratio/tick)")
      .def("gear_ramp_to", [](Card& k, AxisIndex i, double ratio, double rate_per_tick) {
             k.modes().gear_ramp_to(card_axis(k, i), ratio, rate_per_tick);
           }, py::arg("axis"), py::arg("ratio"), py::arg("rate_per_tick"), "on-the-fly ratio change, ramped")
      .def("gear_ratio", [](Card& k, AxisIndex i) { return k.modes().gear_ratio(card_axis(k, i)); }, py::arg("axis"),
           "the gear ratio in effect now");
  m.def("aps_group_motion_status", [](const Card& k, AxisIndex i) { return vendor::adlink::aps_group_motion_status(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "APS_motion_status with the interpolation group's view (WAIT, BLD, MDN)");
  m.def("aps_group_stop_code", [](const Card& k, AxisIndex i) { return vendor::adlink::aps_group_stop_code(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "APS_get_stop_code with a group fault's code on every group axis");
}

}  // namespace servobench::bindings
