#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "servobench/common/validate.hpp"
#include "servobench/motion/trapezoid.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {
py::array_t<double> to_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}
}  // namespace

void bind_motion(py::module_& m) {
  m.def(
      "trapezoid_move",
      [](double start_pulse, double distance_pulse, double vel, double acc, double dwell_before, double dwell_after) {
        check_integer("trapezoid_move", "dwell_before", dwell_before, 0, 1e8);
        check_integer("trapezoid_move", "dwell_after", dwell_after, 0, 1e8);
        motion::SampledProfile p;
        {
          py::gil_scoped_release release;
          p = motion::trapezoid_move(start_pulse, distance_pulse, vel, acc, static_cast<std::size_t>(dwell_before),
                                     static_cast<std::size_t>(dwell_after));
        }
        return py::make_tuple(to_array(p.pos), to_array(p.vel), to_array(p.acc));
      },
      py::kw_only(), py::arg("start_pulse") = 0.0, py::arg("distance_pulse"), py::arg("vel_pulse_per_tick"),
      py::arg("acc_pulse_per_tick2"), py::arg("dwell_before") = 0.0, py::arg("dwell_after") = 0.0,
      "Sampled trapezoid move: (pos pulse, vel pulse/tick, acc pulse/tick^2) arrays, one sample per tick.");
}

}  // namespace servobench::bindings
