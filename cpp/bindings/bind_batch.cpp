// Binding of the batch layer (machine/batch.hpp): many plants, one command, all cores, the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "flag.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "servobench/common/validate.hpp"
#include "servobench/machine/batch.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

double** batch_slot(machine::Trace& t, const std::string& name) {
#define SB_SLOT(n, unit, doc) \
  if (name == #n) return &t.n;
  SERVOBENCH_TRACE_SIGNALS(SB_SLOT)
#undef SB_SLOT
  return nullptr;
}

Array finite_array(const py::handle& obj, const char* name, int ndim) {
  Array a = Array::ensure(obj);
  if (!a) throw py::type_error(std::string(name) + " must be an array of numbers");
  if (a.ndim() != ndim)
    throw py::value_error(std::string(name) + " must have " + std::to_string(ndim) + " dimension(s), got " +
                          std::to_string(a.ndim()));
  const double* d = a.data();
  for (py::ssize_t k = 0; k < a.size(); ++k)
    if (!std::isfinite(d[k]))
      throw py::value_error(std::string(name) + " holds " + format_value(d[k]) + " at flat index " +
                            std::to_string(k) + ": every value must be a finite number");
  return a;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def(
      "axis_parameter_names",
      [](const machine::Axis& axis) { return machine::axis_parameter_names(axis.config()); }, py::arg("axis"),
      "The parameter names ('part.field') a batch's parameter table may set on copies of this axis.");
  m.def(
      "run_batch",
      [](const machine::Axis& base, const std::vector<std::string>& names, const py::object& table,
         const py::object& pos, const py::object& vel, const py::object& acc, const std::vector<std::string>& signals,
         Flag metrics, double settle_band_pulse, int threads, const py::object& progress) {
        Array tab = finite_array(table, "parameters", 2);
        if (static_cast<std::size_t>(tab.shape(1)) != names.size())
          throw py::value_error("parameters has " + std::to_string(tab.shape(1)) + " columns for " +
                                std::to_string(names.size()) + " parameter names");
        Array p = finite_array(pos, "command", 1);
        const py::ssize_t n = p.shape(0);
        Array v, a;
        machine::BatchInput in;
        in.base = base.config();
        in.parameter_names = names;
        in.parameters = tab.data();
        in.plants = static_cast<std::size_t>(tab.shape(0));
        in.pos = p.data();
        in.n = static_cast<std::size_t>(n);
        if (!vel.is_none()) {
          v = finite_array(vel, "velocities", 1);
          if (v.shape(0) != n) throw py::value_error("velocities must have one value per command tick");
          in.vel = v.data();
        }
        if (!acc.is_none()) {
          a = finite_array(acc, "accelerations", 1);
          if (a.shape(0) != n) throw py::value_error("accelerations must have one value per command tick");
          in.acc = a.data();
        }
        if (threads < 0) throw_invalid("simulate_many", "threads", threads, "must be >= 0 (0 = every core)");
        machine::BatchOutput out;
        out.settle_band_pulse = settle_band_pulse;
        py::dict recorded;
        const py::ssize_t plants = tab.shape(0);
        for (const auto& name : signals) {
          double** slot = batch_slot(out.signals, name);
          if (!slot) throw py::value_error("signals: unknown signal '" + name + "'");
          py::array_t<double> buf({plants, n});
          *slot = buf.mutable_data();
          recorded[py::str(name)] = buf;
        }
        py::object met = py::none();
        py::array_t<double> mbuf;
        if (metrics) {
          mbuf = py::array_t<double>({plants, static_cast<py::ssize_t>(machine::kMoveMetricsCount)});
          out.metrics = reinterpret_cast<machine::MoveMetricsRow*>(mbuf.mutable_data());
          met = mbuf;
        }
        // Ctrl-C and the progress callback are served from this thread every 50 ms while the workers run
        // (decision FV28); a pending signal or a false from the callback stops the plants not yet started.
        std::shared_ptr<py::error_already_set> interrupt;
        const std::function<bool(int, int)> cb = progress_callback(progress, &interrupt);
        int used = 0;
        bool stopped = false;
        {
          py::gil_scoped_release release;
          machine::BatchOptions opt;
          opt.threads = threads;
          opt.poll = [&cb](std::size_t done, std::size_t total) {
            return cb(static_cast<int>(std::min<std::size_t>(done, INT_MAX)),
                      static_cast<int>(std::min<std::size_t>(total, INT_MAX)));
          };
          try {
            used = machine::run_batch(in, out, opt);
          } catch (const machine::BatchStopped&) {
            stopped = true;
          }
        }
        raise_pending(interrupt);
        if (stopped) throw std::runtime_error("simulate_many: the progress callback returned False: batch stopped");
        return py::make_tuple(recorded, met, used);
      },
      py::arg("base"), py::arg("names"), py::arg("parameters"), py::arg("positions"), py::arg("velocities"),
      py::arg("accelerations"), py::arg("signals"), py::arg("metrics"), py::arg("settle_band_pulse"),
      py::arg("threads"), py::arg("progress") = py::none(),
      "Runs one copy of `base` per parameter-table row over the command (pulse) across threads, GIL released, "
      "answering Ctrl-C within about 50 ms; progress(done, total) -> bool is called as plants finish (False stops); "
      "returns ({signal: plants x ticks array}, plants x 6 move metrics or None, threads used).");
}

}  // namespace servobench::bindings
