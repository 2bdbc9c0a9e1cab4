// The ADLINK APS runner (vendor/adlink/aps_commands.hpp) and the arcs' command table: thin. aps_command returns the
// APS code as an int, a status word as the word, a read (code, values...); servobench.dialects.aps generates one
// function per row over it (decisions AY1-AY5). Registered in module.cpp.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "lock_table.hpp"
#include "object_lock.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/aps_command_table.hpp"
#include "servobench/vendor/adlink/aps_commands.hpp"

namespace servobench::bindings {

namespace py = pybind11;

void bind_vendor_adlink_commands(py::module_& m) {
  namespace a = vendor::adlink;
  m.def("aps_command", [](machine::Card* k, const std::string& name, const a::ApsArgs& args) -> py::object {
        a::ApsReply r;
        if (k == nullptr) {
          r = a::aps_command(nullptr, name, args);
        } else {  // the card's state lock, as the Card's own methods hold it (a realtime clock may be ticking it)
          auto lk = lock_releasing_gil(locks_of(k)->state);
          r = a::aps_command(k, name, args);
        }
        if (r.kinds.empty()) return py::int_(static_cast<int>(r.code));
        if (r.kinds == "w") return py::int_(static_cast<long long>(r.values.at(0)));
        py::list out;
        out.append(static_cast<int>(r.code));
        for (std::size_t i = 0; i < r.values.size(); ++i)
          out.append(r.kinds[i] == 'i' ? py::object(py::int_(static_cast<long long>(r.values[i])))
                                       : py::object(py::float_(r.values[i])));
        return py::tuple(out);
      }, py::arg("card"), py::arg("name"), py::arg("args"),
      "Runs APS function `name` on card (None: no card open) with its arguments (each a list: one value for a "
      "number, the values of an array, none when not given; NaN = not a number): the code, a status word, or "
      "(code, values...) for a read.");
  py::list shapes;
  for (const a::ApsCommandShape& s : a::aps_command_shapes()) shapes.append(py::make_tuple(s.name, s.args, s.reply));
  m.attr("APS_COMMAND_SHAPES") = shapes;  // (name, 'n'/'a' per argument, reply kinds): what aps_command runs
  py::list arcs;
  for (const a::ApsCommandDoc& d : a::aps_arc_commands()) arcs.append(py::make_tuple(d.name, d.args, d.doc));
  m.attr("APS_ARC_COMMANDS") = arcs;  // (name, arguments after self, doc): the arcs' rows (AY4)
}

}  // namespace servobench::bindings
