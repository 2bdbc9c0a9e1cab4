// The GUC-ECAT / iDEABOX vendor module (vendor/googol/gts_card.hpp): thin, commands return the manual's code as an
// int; servobench.dialects.gts and its mixins are adapters over it.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gts_card.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using vendor::googol::GtsCard;
using vendor::googol::GtsInput;

namespace {

int code(vendor::googol::GucCode c) { return static_cast<int>(c); }

int crd_arg(double crd) {
  check_integer("GtsCard", "crd", crd, 1, 2, "GUC L370");
  return static_cast<int>(crd);
}

int fifo_arg(double fifo) {
  check_integer("GtsCard", "fifo", fifo, 0, 1, "GUC L449");
  return static_cast<int>(fifo);
}

}  // namespace

void bind_vendor_gts(py::module_& m) {
  py::class_<GtsCard, std::unique_ptr<GtsCard, py::nodelete>>(
      m, "GtsCard",
      "The GUC-ECAT / iDEABOX registers of one card (vendor/googol/gts_card.hpp): look-ahead windows, GPI levels\n"
      "and polarity, stop decelerations and stop inputs, velocity filters and their history, jog smoothing.\n"
      "Axes 0-based here (the dialect converts); commands return the GUC/iDEABOX code.")
      .def("set_lookahead", [](GtsCard& g, double crd, double fifo, int n) {
             g.set_lookahead(crd_arg(crd), fifo_arg(fifo), n);
           }, py::arg("crd"), py::arg("fifo"), py::arg("n"), "GT_InitLookAhead's window n (0 = off)")
      .def("lookahead", [](const GtsCard& g, double crd, double fifo) { return g.lookahead(crd_arg(crd), fifo_arg(fifo)); },
           py::arg("crd"), py::arg("fifo"))
      .def("drop_lookahead", [](GtsCard& g, double crd) { g.drop_lookahead(crd_arg(crd)); }, py::arg("crd"))
      .def("check_push", [](GtsCard& g, double crd, double fifo) { return code(g.check_push(crd_arg(crd), fifo_arg(fifo))); },
           py::arg("crd"), py::arg("fifo"), "0, 7 (look-ahead on a 4-D crd) or 1 (crd not set up)")
      .def("set_inputs", [](GtsCard& g, std::uint32_t bits) { g.set_inputs(bits); }, py::arg("bits"))
      .def("set_gpi_sense", [](GtsCard& g, double s) { return code(g.set_gpi_sense(s)); }, py::arg("sense"))
      .def("input_word", [](const GtsCard& g, int type) -> py::object {
             const auto w = g.input_word(static_cast<GtsInput>(type));
             return w ? py::object(py::int_(*w)) : py::none();
           }, py::arg("type"), "GT_GetDi word of MC_* type 0..5; None for MC_HOME / MC_ARRIVE (not wired)")
      .def("set_stop_dec", [](GtsCard& g, double p, double s, double a) { return code(g.set_stop_dec(p, s, a)); },
           py::arg("profile"), py::arg("smooth"), py::arg("abrupt"), "profile 1..axes; (0, 32767] pulse/ms^2")
      .def("stop_dec", [](const GtsCard& g, int a) { return g.stop_dec(static_cast<std::size_t>(a)); }, py::arg("axis"))
      .def("set_crd_stop_dec", [](GtsCard& g, double crd, double s, double a) { g.set_crd_stop_dec(crd_arg(crd), s, a); },
           py::arg("crd"), py::arg("smooth"), py::arg("abrupt"))
      .def("crd_stop_dec", [](const GtsCard& g, double crd) { return g.crd_stop_dec(crd_arg(crd)); }, py::arg("crd"))
      .def("stop_axis", [](GtsCard& g, int a, bool abrupt) { g.stop_axis(static_cast<std::size_t>(a), abrupt); },
           py::arg("axis"), py::arg("abrupt"))
      .def("set_stop_io", [](GtsCard& g, double axis, double st, double in, double idx) {
             return code(g.set_stop_io(axis, st, in, idx));
           }, py::arg("axis"), py::arg("stop_type"), py::arg("input_type"), py::arg("index"))
      .def("set_prf_vel_filter", [](GtsCard& g, double a, double e) { return code(g.set_prf_vel_filter(a, e)); },
           py::arg("axis"), py::arg("exp"))
      .def("set_enc_vel_filter", [](GtsCard& g, double a, double e) { return code(g.set_enc_vel_filter(a, e)); },
           py::arg("axis"), py::arg("exp"))
      .def("prf_vel_filter", [](const GtsCard& g, int a) { return g.prf_vel_filter(static_cast<std::size_t>(a)); },
           py::arg("axis"))
      .def("enc_vel_filter", [](const GtsCard& g, int a) { return g.enc_vel_filter(static_cast<std::size_t>(a)); },
           py::arg("axis"))
      .def("filtered_prf_vel", [](GtsCard& g, int a) { return g.filtered_prf_vel(static_cast<std::size_t>(a)); },
           py::arg("axis"), "pulse/ms")
      .def("filtered_enc_vel", [](GtsCard& g, int a) { return g.filtered_enc_vel(static_cast<std::size_t>(a)); },
           py::arg("axis"), "pulse/ms")
      .def("set_jog_smooth", [](GtsCard& g, int a, double s) { g.set_jog_smooth(static_cast<std::size_t>(a), s); },
           py::arg("axis"), py::arg("smooth"))
      .def("jog_smooth", [](const GtsCard& g, int a) { return g.jog_smooth(static_cast<std::size_t>(a)); },
           py::arg("axis"));

  m.def("gts_card", [](Card& card) { return &vendor::googol::gts(card); }, py::arg("card"),
        py::return_value_policy::reference_internal, "the card's GUC-ECAT / iDEABOX module (created on first use)");
}

}  // namespace servobench::bindings
