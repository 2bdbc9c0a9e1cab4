// Bindings of the broadband excitations and their estimate (tuning/chirp, tuning/multisine, tuning/spectral_lines):
// arrays in and out, no logic (servobench.frequency and servobench.experiment forward to them).
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arrays.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/tuning/chirp.hpp"
#include "servobench/tuning/multisine.hpp"
#include "servobench/tuning/spectral_lines.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {
tuning::ChirpOptions chirp_options(double start_hz, double end_hz, double duration_s, double servo_period_s,
                                   double amplitude, const std::string& kind) {
  tuning::ChirpOptions o;
  o.start_hz = start_hz;
  o.end_hz = end_hz;
  o.duration_s = duration_s;
  o.servo_period_s = servo_period_s;
  o.amplitude = amplitude;
  if (kind == "log") {
    o.kind = tuning::ChirpKind::kLog;
  } else if (kind == "linear") {
    o.kind = tuning::ChirpKind::kLinear;
  } else {
    throw py::value_error("kind = '" + kind + "' must be 'log' or 'linear'");
  }
  return o;
}

std::vector<int> int_vector(const py::handle& obj, const char* name) {
  std::vector<int> out;
  for (double v : real_vector(obj, name)) {
    check_integer("excitation", name, v, -2147483647.0, 2147483647.0);
    out.push_back(static_cast<int>(v));
  }
  return out;
}
}  // namespace

void bind_excitation(py::module_& m) {
  m.def(
      "chirp",
      [](double start_hz, double end_hz, double duration_s, double servo_period_s, double amplitude,
         const std::string& kind) {
        return to_array(tuning::chirp(chirp_options(start_hz, end_hz, duration_s, servo_period_s, amplitude, kind)));
      },
      py::kw_only(), py::arg("start_hz"), py::arg("end_hz"), py::arg("duration_s"), py::arg("servo_period_s"),
      py::arg("amplitude") = 1.0, py::arg("kind") = "log",
      "Swept sine sampled every servo_period_s (s) for duration_s (s), start_hz..end_hz (Hz), peak `amplitude` "
      "(tuning/chirp.hpp).");
  m.def(
      "chirp_record",
      [](double start_hz, double end_hz, double duration_s, double servo_period_s, double amplitude,
         double rest_ticks) {
        check_integer("chirp_record", "rest_ticks", rest_ticks, 0, 1e8);
        return to_array(tuning::chirp_record(
            chirp_options(start_hz, end_hz, duration_s, servo_period_s, amplitude, "log"), static_cast<int>(rest_ticks)));
      },
      py::kw_only(), py::arg("start_hz"), py::arg("end_hz"), py::arg("duration_s"), py::arg("servo_period_s"),
      py::arg("amplitude"), py::arg("rest_ticks"),
      "The broadband record: the log chirp tapered to start and end at rest, then rest_ticks zeros.");
  m.def(
      "chirp_lines",
      [](double record_ticks, double servo_period_s, double start_hz, double end_hz, double lines) {
        check_integer("chirp_lines", "record_ticks", record_ticks, 1, 1e9);
        check_integer("chirp_lines", "lines", lines, -1, 1e9);
        return to_array(tuning::chirp_lines(static_cast<int>(record_ticks), servo_period_s, start_hz, end_hz,
                                            static_cast<int>(lines)));
      },
      py::kw_only(), py::arg("record_ticks"), py::arg("servo_period_s"), py::arg("start_hz"), py::arg("end_hz"),
      py::arg("lines"), "DFT lines of a record in start_hz..end_hz, thinned to `lines` log-spaced ones (-1: all).");
  m.def(
      "schroeder_multisine",
      [](double start_hz, double end_hz, double period_ticks, double servo_period_s, double amplitude, double lines) {
        check_integer("multisine", "period_ticks", period_ticks, 8, 1e9);
        check_integer("multisine", "lines", lines, 0, 1e9);
        const tuning::Multisine ms = tuning::schroeder_multisine(start_hz, end_hz, static_cast<int>(period_ticks),
                                                                 servo_period_s, amplitude, static_cast<int>(lines));
        return py::make_tuple(to_array(ms.period), to_array(ms.lines));
      },
      py::kw_only(), py::arg("start_hz"), py::arg("end_hz"), py::arg("period_ticks"), py::arg("servo_period_s"),
      py::arg("amplitude"), py::arg("lines"),
      "One period of the Schroeder multisine and its DFT lines (lines = 0: every line in the band).");
  m.def(
      "multisine_sum",
      [](double n_samples, double servo_period_s, const py::object& lines, const py::object& phases_rad,
         double amplitude) {
        check_integer("multisine", "n_samples", n_samples, 1, 1e9);
        return to_array(tuning::multisine_sum(static_cast<int>(n_samples), servo_period_s, int_vector(lines, "lines"),
                                              real_vector(phases_rad, "phases_rad"), amplitude));
      },
      py::kw_only(), py::arg("n_samples"), py::arg("servo_period_s"), py::arg("lines"), py::arg("phases_rad"),
      py::arg("amplitude"), "Sum of cosines at DFT lines with the given phases, scaled to a peak of `amplitude`.");
  m.def(
      "h1_estimate",
      [](const py::object& r, const py::object& e, const py::object& u, const py::object& y, double record_ticks,
         double records, double skip_ticks, const py::object& lines, double servo_period_s, bool remove_offset) {
        check_integer("h1_estimate", "record_ticks", record_ticks, 1, 1e9);
        check_integer("h1_estimate", "records", records, 1, 1e9);
        check_integer("h1_estimate", "skip_ticks", skip_ticks, 0, 1e9);
        const auto rv = real_vector(r, "r"), ev = real_vector(e, "e"), uv = real_vector(u, "u"),
                   yv = real_vector(y, "y");
        const auto lv = int_vector(lines, "lines");
        tuning::H1Estimate h;
        {
          py::gil_scoped_release release;
          h = tuning::h1_estimate(rv, ev, uv, yv, static_cast<int>(record_ticks), static_cast<int>(records),
                                  static_cast<int>(skip_ticks), lv, servo_period_s, remove_offset);
        }
        py::dict d;
        d["freq_hz"] = to_array(h.freq_hz);
        d["plant"] = to_array(h.plant);
        d["open_loop"] = to_array(h.open_loop);
        d["closed_loop"] = to_array(h.closed_loop);
        d["coherence"] = to_array(h.coherence);
        return d;
      },
      py::kw_only(), py::arg("r"), py::arg("e"), py::arg("u"), py::arg("y"), py::arg("record_ticks"),
      py::arg("records"), py::arg("skip_ticks"), py::arg("lines"), py::arg("servo_period_s"),
      py::arg("remove_offset"),
      "H1 estimate of a broadband run at DFT lines: Y/U, Y/E, Y/R and the coherence (tuning/spectral_lines.hpp). "
      "Releases the GIL.");
}

}  // namespace servobench::bindings
