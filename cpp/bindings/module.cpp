// servobench._core: the pybind11 module. One bind_<layer>.cpp per layer; no logic here.
#include <pybind11/pybind11.h>

#include <cstdlib>
#include <string>

#include "signatures.hpp"

namespace py = pybind11;

namespace servobench::bindings {
void bind_control(py::module_& m);
void bind_filters(py::module_& m);
void bind_drive(py::module_& m);
void bind_plant(py::module_& m);
void bind_motion(py::module_& m);
void bind_pvt(py::module_& m);
void bind_machine(py::module_& m);
void bind_tuning(py::module_& m);
void bind_homing(py::module_& m);
void bind_identify(py::module_& m);
void bind_paths(py::module_& m);
void bind_card(py::module_& m);
void bind_batch(py::module_& m);
void bind_vendor_ge(py::module_& m);  // bind_vendor_ge.cpp: the GE list module (vendor/googol/ge_list.hpp)
void bind_vendor_gt(py::module_& m);
void bind_vendor_gts(py::module_& m);
void bind_vendor_gts_commands(py::module_& m);
void bind_vendor_guc_program(py::module_& m);  // bind_vendor_guc_program.cpp: the GUC motion program
void bind_vendor_adlink(py::module_& m);  // bind_vendor_adlink.cpp: the ADLINK vendor module
void bind_vendor_adlink_commands(py::module_& m);  // bind_vendor_adlink_commands.cpp: the APS runner
void bind_excitation(py::module_& m);
void serialise_card_functions(py::module_& m);  // card_locks.cpp: last, over every card function
}  // namespace servobench::bindings

PYBIND11_MODULE(_core, m) {
  m.doc() = "servobench C++ core (servo laws, drives, plants, motion, axis). Use the `servobench` package.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  servobench::bindings::bind_control(m);
  servobench::bindings::bind_filters(m);
  servobench::bindings::bind_drive(m);
  servobench::bindings::bind_plant(m);
  servobench::bindings::bind_motion(m);
  servobench::bindings::bind_pvt(m);
  servobench::bindings::bind_machine(m);
  servobench::bindings::bind_tuning(m);
  servobench::bindings::bind_homing(m);
  servobench::bindings::bind_identify(m);
  servobench::bindings::bind_paths(m);
  servobench::bindings::bind_card(m);
  servobench::bindings::bind_batch(m);
  servobench::bindings::bind_vendor_ge(m);
  servobench::bindings::bind_vendor_gt(m);
  servobench::bindings::bind_vendor_gts(m);
  servobench::bindings::bind_vendor_gts_commands(m);
  servobench::bindings::bind_vendor_guc_program(m);
  servobench::bindings::bind_vendor_adlink(m);
  servobench::bindings::bind_vendor_adlink_commands(m);
  servobench::bindings::bind_excitation(m);
  // After every binding: each function taking the card first holds the card's lock (card_locks.cpp).
  servobench::bindings::serialise_card_functions(m);
  // Last: every function's signature readable by inspect.signature() (help(), IPython completion; decision Y3).
  // Not while pybind11-stubgen reads the module at build time (CMakeLists.txt sets SERVOBENCH_STUBGEN): it takes a
  // text signature over the docstring's typed line, and the stubs need the types.
  if (std::getenv("SERVOBENCH_STUBGEN") == nullptr)
    servobench::bindings::add_text_signatures(m, py::str(m.attr("__name__")).cast<std::string>());
}
