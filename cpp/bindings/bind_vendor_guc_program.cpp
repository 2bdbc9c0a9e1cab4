// The GUC-ECAT motion program's card module (vendor/googol/guc_program.hpp): thin, commands return the manual's code
// as an int, reads a tuple (code, values...); servobench.dialects._gts_program is its adapter and the host that steps
// the program's Python functions. The module shares the card's locks (card_locks.cpp: guc_program(card) returns it
// by reference), so a realtime clock's thread never ticks the card mid-call.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/guc_program.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using vendor::googol::GucFunction;
using vendor::googol::GucProgram;
using vendor::googol::GucStepEnd;

namespace {
int code(vendor::googol::GucCode c) { return static_cast<int>(c); }
using FunctionRow = std::tuple<std::string, std::vector<std::string>, std::vector<bool>, int>;

py::object step_tuple(const std::optional<vendor::googol::GucStep>& s) {
  if (!s) return py::none();
  py::dict args;
  for (const auto& [name, v] : s->args) args[py::str(name)] = v;
  return py::make_tuple(s->thread, s->start, s->fun_id, args);
}
}  // namespace

void bind_vendor_guc_program(py::module_& m) {
  py::class_<GucProgram, std::unique_ptr<GucProgram, py::nodelete>>(
      m, "GucProgram",
      "The GUC-ECAT motion program of one card (vendor/googol/guc_program.hpp; GUC Chapter 5 L2100-2560): the\n"
      "downloaded program's symbols, the 32 threads (binding, run/pause, TThreadSts), the 32 data pages and the\n"
      "globals (DINT), the checks and codes (0, 1 refused in this state, 7 out of range). The host steps the\n"
      "program's functions: next_step() says which thread now, stepped() takes the outcome.")
      .def("load", [](GucProgram& p, const std::vector<FunctionRow>& functions, std::vector<std::string> globals,
                      std::vector<double> values) {
             std::vector<GucFunction> fs;
             for (const auto& [name, vars, defaults, line] : functions) fs.push_back(GucFunction{name, vars, defaults, line});
             p.load(std::move(fs), std::move(globals), std::move(values));
           }, py::arg("functions"), py::arg("globals"), py::arg("values"),
           "GT_Download: functions [(name, variables (parameters first), has_default per parameter, first line)], "
           "the global names and their values; every thread stops and is unbound, the pages are cleared")
      .def_property_readonly("loaded", &GucProgram::loaded, "whether a program is downloaded")
      .def("stop_all", &GucProgram::stop_all, "every thread stops (GT_Close, GT_Reset)")
      .def("fun_id", [](const GucProgram& p, const std::string& name) {
             const auto [c, id] = p.fun_id(name);
             return py::make_tuple(code(c), id);
           }, py::arg("name"), "GT_GetFunId: (code, id 1..)")
      .def("var_id", [](const GucProgram& p, const std::string& function, const std::string& var) {
             const auto [c, v] = p.var_id(function, var);
             return py::make_tuple(code(c), v.id, v.function, v.name);
           }, py::arg("function"), py::arg("var"), "GT_GetVarId: (code, id, function, name); function '' = a global")
      .def("bind", [](GucProgram& p, double t, double f, double page) { return code(p.bind(t, f, page)); },
           py::arg("thread"), py::arg("fun_id"), py::arg("page"), "GT_Bind")
      .def("run_thread", [](GucProgram& p, double t) { return code(p.run_thread(t)); }, py::arg("thread"),
           "GT_RunThread")
      .def("stop_thread", [](GucProgram& p, double t) { return code(p.stop_thread(t)); }, py::arg("thread"),
           "GT_StopThread")
      .def("pause_thread", [](GucProgram& p, double t) { return code(p.pause_thread(t)); }, py::arg("thread"),
           "GT_PauseThread")
      .def("thread_status", [](const GucProgram& p, double t) {
             const auto [c, s] = p.thread_status(t);
             return py::make_tuple(code(c), s.run, s.error, s.result, s.line);
           }, py::arg("thread"), "GT_GetThreadSts: (code, run, error, result, line)")
      .def("any_active", &GucProgram::any_active, "some thread started and not ended (paused included)")
      .def("set_var_value", [](GucProgram& p, double page, double id, const std::string& function,
                               const std::vector<double>& values, double count) {
             return code(p.set_var_value(page, id, function, values, count));
           }, py::arg("page"), py::arg("id"), py::arg("function"), py::arg("values"), py::arg("count"),
           "GT_SetVarValue (DINT values as doubles)")
      .def("var_value", [](const GucProgram& p, double page, double id, const std::string& function, double count) {
             const auto [c, v] = p.var_value(page, id, function, count);
             return py::make_tuple(code(c), v);
           }, py::arg("page"), py::arg("id"), py::arg("function"), py::arg("count"), "GT_GetVarValue: (code, values)")
      .def("next_step", [](GucProgram& p, int after) { return step_tuple(p.next_step(after)); }, py::arg("after"),
           "the next thread after `after` (-1: the first) to step this tick: (thread, start, fun_id, start "
           "arguments by name) or None")
      .def("stepped", [](GucProgram& p, int t, int end, double value, int line,
                         const std::vector<std::optional<double>>& locals) {
             return step_tuple(p.stepped(t, static_cast<GucStepEnd>(end), value, line, locals));
           }, py::arg("thread"), py::arg("end"), py::arg("value"), py::arg("line"), py::arg("locals"),
           "a step's outcome: end 0 yielded, 1 returned value, 2 raised; line (0 unchanged); the locals (None "
           "unset); returns next_step(thread)")
      .def("record_error", &GucProgram::record_error, py::arg("code"), "the current thread's last GT call code")
      .def_property_readonly("global_names", &GucProgram::global_names)
      .def_property_readonly("global_values", &GucProgram::global_values)
      .def("set_global_values", &GucProgram::set_global_values, py::arg("values"),
           "the globals as the program's namespace holds them after a step");

  m.def("guc_program", [](Card& card) { return &vendor::googol::guc_program(card); }, py::arg("card"),
        py::return_value_policy::reference_internal, "the card's GUC motion-program module (created on first use)");
}

}  // namespace servobench::bindings
