// The GE series' status words (vendor/googol/ge_status.hpp) and the Card commands the GE dialect added
// (smooth_stop, arm_probe, set_encoder_fault; the probe edge set_probe_time is bind_card_scope's). Thin: axis indices are 0-based here; the GE
// dialect (servobench.dialects.ge) numbers axes from 1.
#include <pybind11/pybind11.h>

#include "flag.hpp"

#include <string>

#include "card_axis.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/ge_status.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;

namespace {

vendor::googol::GeVariant variant_from(const std::string& s) {
  if (s == "PX") return vendor::googol::GeVariant::PX;
  if (s == "SX") return vendor::googol::GeVariant::SX;
  throw py::value_error("variant: '" + s + "' is not one of PX, SX (GE manual L99-103)");
}

}  // namespace

void bind_card_ge(py::module_& m) {
  py::object cls = m.attr("Card");
  cls.attr("smooth_stop") = py::cpp_function(
      [](Card& k, AxisIndex i) { k.smooth_stop(card_axis(k, i)); }, py::is_method(cls), py::arg("axis"),
      "GE GT_SmthStp: immediate smooth stop at the mode's limits (GE L1310-1312); no-op at rest.");
  cls.attr("arm_probe") = py::cpp_function(
      [](Card& k) { k.arm_probe(); }, py::is_method(cls),
      "GE GT_CaptProb: arms every axis's capture on the probe input EXI0, one shot (GE L3828-3862).");
  cls.attr("set_encoder_fault") = py::cpp_function(
      [](Card& k, AxisIndex i, Flag on) { k.set_encoder_fault(card_axis(k, i), on); }, py::is_method(cls),
      py::arg("axis"), py::arg("on"), "The encoder-abnormal input of an axis (GE PX status bit 27).");
  cls.attr("synch_pos_now") = py::cpp_function(
      [](Card& k, AxisIndex i) { k.synch_pos_now(card_axis(k, i)); }, py::is_method(cls), py::arg("axis"),
      "GE GT_AxisOn's synchronisation: target = profile = actual position, at once, at rest only (GE L3716-3720).");
  cls.attr("encoder_fault") = py::cpp_function(
      [](const Card& k, AxisIndex i) { return k.state(card_axis(k, i)).encoder_fault; }, py::is_method(cls),
      py::arg("axis"), "The encoder-abnormal input of an axis.");

  m.def("ge_axis_status", [](const Card& k, AxisIndex i, const std::string& variant) -> std::uint32_t {
          const std::size_t a = card_axis(k, i);
          return variant_from(variant) == vendor::googol::GeVariant::PX ? vendor::googol::ge_px_axis_status(k, a)
                                                                  : vendor::googol::ge_sx_axis_status(k, a);
        }, py::arg("card"), py::arg("axis"), py::arg("variant"),
        "GE axis status register of a card axis (0-based): PX 32 bits (Table 4-3), SX 16 bits (Table 4-2).");
  m.def("ge_mode_register", [](const Card& k, AxisIndex i) { return vendor::googol::ge_mode_register(k, card_axis(k, i)); },
        py::arg("card"), py::arg("axis"), "GE PX axis mode register (Table 4-4) of a card axis (0-based).");
  m.def("ge_command_status", [](const Card& k, const std::string& variant) {
          return vendor::googol::ge_command_status(variant_from(variant), k);
        }, py::arg("card"), py::arg("variant"),
        "GE command-error register (PX Table 2-3, SX Table 2-4): the bit of the last refused command's cause.");
  m.def("ge_events_to_clear", [](double mask) {
          check_integer("GT_RstSts", "mask", mask, 0, 65535);
          return vendor::googol::ge_events_to_clear(static_cast<std::uint16_t>(mask));
        }, py::arg("mask"), "The card events GE GT_RstSts(axis, mask) clears (mask bit 1 keeps, 0 clears; bits 0-7).");
}

}  // namespace servobench::bindings
