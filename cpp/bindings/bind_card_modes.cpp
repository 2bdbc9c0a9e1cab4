// The Card's driven modes (machine/card_modes.hpp): electronic gear, PVT, FollowEx, coordinate systems, and the
// coordinate-system status words (vendor/googol/crd_status.hpp). Thin: axes 0-based, crd 1..2 as the manuals; the
// dialects (servobench.dialects.gt / gts) translate. Called from bind_card.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "flag.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "card_axis.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/googol/crd_status.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using machine::CardModes;

namespace {

std::uint32_t mask_of(double m, const char* name) {
  check_integer("Card", name, m, 0, 4294967295.0);
  return static_cast<std::uint32_t>(m);
}

int crd_of(double c) {
  check_integer("Card", "crd", c, 1, 2, "GUC L370");
  return static_cast<int>(c);
}

// A Python view of an object owned by a shared_ptr held by the card's modes: the view keeps the owner and the
// card alive, so it stays valid even after the card replaces that object (it is then detached from the card).
template <class T>
py::object view(T* obj, std::shared_ptr<void> owner, const py::object& card) {
  struct Keep {
    std::shared_ptr<void> owner;
    py::object card;
  };
  auto* keep = new Keep{std::move(owner), card};
  py::capsule cap(keep, [](void* p) { delete static_cast<Keep*>(p); });
  return py::cast(obj, py::return_value_policy::reference_internal, cap);
}

motion::CrdPrm crd_prm_from(double dimension, const std::vector<double>& profile, double syn_vel_max,
                            double syn_acc_max, double even_time_ms, Flag set_origin,
                            const std::vector<double>& origin_pos) {
  motion::CrdPrm p;
  check_integer("CrdPrm", "dimension", dimension, 1, 4, "GUC L375");
  p.dimension = static_cast<int>(dimension);
  if (profile.size() > 8 || origin_pos.size() > 8)
    throw std::invalid_argument("CrdPrm: profile and origin_pos have at most 8 entries");
  for (std::size_t k = 0; k < profile.size(); ++k) {
    check_integer("CrdPrm", "profile[k]", profile[k], 0, 4, "GUC L785");
    p.profile[k] = static_cast<int>(profile[k]);
  }
  for (std::size_t k = 0; k < origin_pos.size(); ++k) p.origin_pos[k] = origin_pos[k];
  p.syn_vel_max = syn_vel_max;
  p.syn_acc_max = syn_acc_max;
  p.even_time_ms = even_time_ms;
  p.set_origin = set_origin;
  return p;
}

py::dict hosted_dict(const machine::HostedGroup& h) {
  py::dict d;
  d["set_up"] = static_cast<bool>(h.group);
  d["feeding"] = h.feeding;
  d["fault_stopped"] = h.fault_stopped;
  d["fault_cause"] = std::string(to_string(h.fault_cause));
  d["fault_axis"] = h.fault_axis;
  std::vector<std::size_t> axes;
  if (h.group) axes = h.group->axes();
  d["axes"] = axes;
  return d;
}

vendor::googol::CrdStatusInputs inputs_from(const py::kwargs& kw) {
  vendor::googol::CrdStatusInputs in;
  for (const auto& item : kw) {
    const std::string k = py::str(item.first);
    const bool v = item.second.cast<bool>();
    if (k == "moving") in.moving = v;
    else if (k == "buffer_closed") in.buffer_closed = v;
    else if (k == "last_command_error") in.last_command_error = v;
    else if (k == "segment_complete") in.segment_complete = v;
    else if (k == "acc_limit_alarm") in.acc_limit_alarm = v;
    else if (k == "auto_stop_on") in.auto_stop_on = v;
    else if (k == "immediate_mode") in.immediate_mode = v;
    else if (k == "fault_stopped") in.fault_stopped = v;
    else if (k == "buffer_empty") in.buffer_empty = v;
    else if (k == "buffer_started") in.buffer_started = v;
    else throw py::value_error("crd status: unknown input '" + k + "'");
  }
  return in;
}

}  // namespace

void bind_card_modes(py::class_<Card>& c, py::module_& m) {
  // -- electronic gear
  c.def("set_gear", [](Card& k, AxisIndex i, AxisIndex master) { k.modes().set_gear(card_axis(k, i), card_axis(k, master)); },
        py::arg("axis"), py::arg("master"), "GT_PrflG: axis follows master's profile position with the active ratio")
      .def("gear_master", [](Card& k, AxisIndex i) { return k.modes().gear_master(card_axis(k, i)); }, py::arg("axis"))
      .def("gear_halted", [](Card& k, AxisIndex i) { return k.modes().gear_halted(card_axis(k, i)); }, py::arg("axis"))
      // -- PVT
      .def("pvt_download", [](Card& k, double table, const motion::PvtCurve& curve) {
             check_integer("Card", "table_id", table, 1, 32, "GUC L1304");
             k.modes().pvt_download(static_cast<int>(table), curve);
           }, py::arg("table_id"), py::arg("curve"))
      .def("pvt_table", [](Card& k, double table) -> py::object {
             check_integer("Card", "table_id", table, 1, 32, "GUC L1304");
             const motion::PvtCurve* t = k.modes().pvt_tables().table(static_cast<int>(table));
             return t ? py::cast(*t) : py::none();
           }, py::arg("table_id"))
      .def("set_pvt", [](Card& k, AxisIndex i) { k.modes().set_pvt(card_axis(k, i)); }, py::arg("axis"), "GT_PrfPvt")
      .def("pvt_select", [](Card& k, AxisIndex i, double table) {
             check_integer("Card", "table_id", table, 1, 32, "GUC L1304");
             k.modes().pvt_select(card_axis(k, i), static_cast<int>(table));
           }, py::arg("axis"), py::arg("table_id"))
      .def("pvt_loop", [](Card& k, AxisIndex i, double loop) { k.modes().pvt_loop(card_axis(k, i), loop); },
           py::arg("axis"), py::arg("loop"))
      .def("pvt_start", [](Card& k, double mask) { k.modes().pvt_start(mask_of(mask, "mask")); }, py::arg("mask"))
      .def("pvt_status", [](Card& k, AxisIndex i) {
             const motion::PvtAxis& a = k.modes().pvt(card_axis(k, i));
             return py::make_tuple(a.table_id(), a.time_ms());
           }, py::arg("axis"), "(table id, PVT time ms) (GT_PvtStatus)")
      .def("pvt_loop_status", [](Card& k, AxisIndex i) {
             const motion::PvtAxis& a = k.modes().pvt(card_axis(k, i));
             return py::make_tuple(a.loop_count(), a.loop());
           }, py::arg("axis"), "(passes done, loop setting) (GT_GetPvtLoop)")
      // -- FollowEx
      .def("set_follow", [](Card& k, AxisIndex i, const motion::FollowExSetup& s, AxisIndex master) {
             k.modes().set_follow(card_axis(k, i), s, machine::FollowMaster{card_axis(k, master)});
           }, py::arg("axis"), py::arg("setup"), py::arg("master"), "GT_PrfFollowEx + GT_SetFollowMasterEx")
      .def("follow_configure", [](Card& k, AxisIndex i, const motion::FollowExSetup& s) {
             k.modes().follow_configure(card_axis(k, i), s);
           }, py::arg("axis"), py::arg("setup"))
      .def("follow_set_master", [](Card& k, AxisIndex i, AxisIndex master) {
             k.modes().follow_master(card_axis(k, i), machine::FollowMaster{card_axis(k, master)});
           }, py::arg("axis"), py::arg("master"))
      .def("follow_master", [](Card& k, AxisIndex i) { return k.modes().follow_master_of(card_axis(k, i)).master; },
           py::arg("axis"))
      .def("follow", [](py::object self, AxisIndex i) {
             Card& k = self.cast<Card&>();
             auto f = k.modes().follow_shared(card_axis(k, i));
             return view(f.get(), f, self);
           }, py::arg("axis"), "the axis's FollowEx (data, FIFOs, loop count); start through follow_start")
      .def("follow_start", [](Card& k, double mask, double option) {
             k.modes().follow_start(mask_of(mask, "mask"), mask_of(option, "option"));
           }, py::arg("mask"), py::arg("option") = 0.0)
      .def("follow_switch", [](Card& k, double mask) { k.modes().follow_switch(mask_of(mask, "mask")); },
           py::arg("mask"))
      .def("follow_master_pos", [](Card& k, AxisIndex i) {
             const std::size_t a = card_axis(k, i);
             k.modes().follow(a);
             return k.modes().follow_master_pos(a);
           }, py::arg("axis"))
      // -- coordinate systems
      .def("set_crd_prm", [](Card& k, double crd, double dimension, const std::vector<double>& profile,
                             double syn_vel_max, double syn_acc_max, double even_time_ms, Flag set_origin,
                             const std::vector<double>& origin_pos) {
             k.modes().set_crd_prm(crd_of(crd), crd_prm_from(dimension, profile, syn_vel_max, syn_acc_max,
                                                             even_time_ms, set_origin, origin_pos));
           }, py::arg("crd"), py::kw_only(), py::arg("dimension"), py::arg("profile"), py::arg("syn_vel_max"),
           py::arg("syn_acc_max"), py::arg("even_time_ms") = 0.0, py::arg("set_origin") = false,
           py::arg("origin_pos") = std::vector<double>{}, "GT_SetCrdPrm (GUC-ECAT / iDEABOX), crd 1..2")
      .def("crd_prm", [](Card& k, double crd) {
             const motion::CrdPrm& p = k.modes().crd_prm(crd_of(crd));
             py::dict d;
             d["dimension"] = p.dimension;
             d["profile"] = std::vector<int>(p.profile.begin(), p.profile.end());
             d["syn_vel_max"] = p.syn_vel_max;
             d["syn_acc_max"] = p.syn_acc_max;
             d["even_time_ms"] = p.even_time_ms;
             d["set_origin"] = p.set_origin;
             d["origin_pos"] = std::vector<double>(p.origin_pos.begin(), p.origin_pos.end());
             return d;
           }, py::arg("crd"))
      .def("crd", [](py::object self, double crd) {
             Card& k = self.cast<Card&>();
             const int cn = crd_of(crd);
             k.modes().crd(cn);  // refuses when not set up
             auto g = k.modes().group_shared(static_cast<std::size_t>(cn - 1));
             auto* pair = &static_cast<machine::CrdPairGroup*>(g.get())->pair();
             return view(pair, g, self);
           }, py::arg("crd"), "the crd's CrdFifoPair: push commands to .fifo(k); start through crd_start")
      .def("crd_start", [](Card& k, double mask, double option) {
             k.modes().crd_start(mask_of(mask, "mask"), mask_of(option, "option"));
           }, py::arg("mask"), py::arg("option") = 0.0)
      .def("crd_stop", [](Card& k, double crd, Flag abrupt) {
             k.modes().stop_group(static_cast<std::size_t>(crd_of(crd) - 1), abrupt);
           }, py::arg("crd"), py::arg("abrupt") = false)
      .def("crd_status", [](Card& k, double crd, double fifo) {
             check_integer("Card", "fifo", fifo, 0, 1);
             const vendor::googol::GucCrdStatus s = vendor::googol::guc_crd_status(k, crd_of(crd), static_cast<int>(fifo));
             return py::make_tuple(s.run, s.segment);
           }, py::arg("crd"), py::arg("fifo") = 0.0, "(run, segment) as GT_CrdStatus")
      .def("crd_pos", [](Card& k, double crd) {
             const int cn = crd_of(crd);
             const motion::CrdPoint p = k.modes().crd_pos(cn);
             const int dim = k.modes().crd(cn).coords().dim();
             return std::vector<double>(p.begin(), p.begin() + dim);
           }, py::arg("crd"), "GT_GetCrdPos: crd coordinates, pulse")
      .def("crd_vel", [](Card& k, double crd) { return k.modes().crd(crd_of(crd)).state().speed; }, py::arg("crd"),
           "GT_GetCrdVel: path speed, pulse/ms")
      .def("group_info", [](Card& k, double slot) {
             check_integer("Card", "slot", slot, 0, static_cast<double>(machine::kGroupSlots) - 1);
             return hosted_dict(k.modes().hosted(static_cast<std::size_t>(slot)));
           }, py::arg("slot"), "the hosted group in slot (crd c: slot c-1; GT map: slot 2)")
      .def("group_of", [](Card& k, AxisIndex i) { return k.modes().group_of(card_axis(k, i)); }, py::arg("axis"))
      .def("gt_map_axis", [](Card& k, AxisIndex axis, const std::vector<double>& cnt) {  // GT numbering 1..axes
             if (cnt.size() != 5) throw std::invalid_argument("GT_MapAxis: map_count has 5 values {Cx, Cy, Cz, Ca, C}");
             check_integer("GT_MapAxis", "axis", axis.value, 1, static_cast<double>(k.axis_count()), "GT L1533");
             k.modes().gt_map_axis({static_cast<int>(axis.value), cnt[0], cnt[1], cnt[2], cnt[3], cnt[4]});
           }, py::arg("axis"), py::arg("map_count"))
      .def("gt_path", [](py::object self) {
             Card& k = self.cast<Card&>();
             k.modes().gt_path();
             auto g = k.modes().group_shared(machine::kGtCrdSlot);
             auto* path = &static_cast<machine::PathGroup*>(g.get())->path();
             return view(path, g, self);
           }, "the GT coordinate system's PathGenerator (units per sample time)")
      .def("group_start", [](Card& k, double slot) {
             check_integer("Card", "slot", slot, 0, static_cast<double>(machine::kGroupSlots) - 1);
             const auto s = static_cast<std::size_t>(slot);
             k.modes().before_group_start(s);
           }, py::arg("slot"), "the card's checks and bookkeeping before a group's own start()")
      .def("group_stop", [](Card& k, double slot, Flag abrupt) {
             check_integer("Card", "slot", slot, 0, static_cast<double>(machine::kGroupSlots) - 1);
             k.modes().stop_group(static_cast<std::size_t>(slot), abrupt);
           }, py::arg("slot"), py::arg("abrupt") = false);

  m.def("gt_crd_status", [](const py::kwargs& kw) { return vendor::googol::gt_crd_status(inputs_from(kw)); },
        "GT GT_GetCrdSts word (Table 5-6, GT L1990-2011) from keyword inputs (see CrdStatusInputs)");
  m.def("ge_crd_status", [](const py::kwargs& kw) { return vendor::googol::ge_crd_status(inputs_from(kw)); },
        "GE GT_GetCrdSts word (Table 4-5, GE L951-968) from keyword inputs (see CrdStatusInputs)");
}

}  // namespace servobench::bindings
