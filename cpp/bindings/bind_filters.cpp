// Biquads (float and ADLINK integer form) and filter design. Thin: the logic is in control/biquad and
// control/filter_design; this file translates arguments and vectorises the frequency response.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>

#include <array>
#include <complex>
#include <optional>

#include "param_class.hpp"
#include "servobench/control/biquad.hpp"
#include "servobench/control/filter_design.hpp"

namespace servobench::bindings {

using control::AdlinkBiquadParams;
using control::FloatBiquadParams;

namespace {

template <class P>
py::object response(const P& p, const py::object& freq_hz, std::optional<double> sample_time_s) {
  const double ts = sample_time_s ? *sample_time_s : p.sample_time_s;
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Array f = Array::ensure(freq_hz);
  if (!f) throw py::type_error("freq_hz must be a number or an array of numbers (Hz)");
  std::vector<py::ssize_t> shape(f.shape(), f.shape() + f.ndim());
  py::array_t<std::complex<double>> out(shape);
  const double* in = f.data();
  std::complex<double>* o = out.mutable_data();
  for (py::ssize_t k = 0; k < f.size(); ++k) o[k] = control::frequency_response(p, in[k], ts);
  if (f.ndim() == 0) return py::cast(o[0]);
  return std::move(out);
}

// Runs the filter (the same control::Biquad the Axis runs) over x from rest; returns y, same length.
template <class P>
py::array_t<double> filter_of(const P& p, const py::object& x) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Array a = Array::ensure(x);
  if (!a || a.ndim() != 1) throw py::value_error("x must be a 1-D array of numbers (one sample per tick)");
  py::array_t<double> out(a.shape(0));
  const double* in = a.data();
  double* o = out.mutable_data();
  control::Biquad b(p);
  {
    py::gil_scoped_release release;
    for (py::ssize_t k = 0; k < a.shape(0); ++k) o[k] = b.step(in[k]);
  }
  return out;
}

template <class P>
py::tuple poles_of(const P& p) {
  const auto r = control::poles(p);
  return py::make_tuple(r.first, r.second);
}

// filter.plot(...): servobench.plot.filter_response for this one filter, its keywords spelled out (not **kwargs).
py::object plot_of(const py::object& self, const py::object& freq_hz, std::optional<double> sample_time_s,
                   std::optional<std::string> title, const py::object& path, const py::object& ax) {
  return py::module_::import("servobench.plot").attr("filter_response")(
      self, py::arg("freq_hz") = freq_hz, py::arg("sample_time_s") = py::cast(sample_time_s),
      py::arg("title") = py::cast(title), py::arg("path") = path, py::arg("ax") = ax);
}

#define SERVOBENCH_PLOT_ARGS                                                                                  \
  py::kw_only(), py::arg("freq_hz") = py::none(), py::arg("sample_time_s") = py::none(),                       \
      py::arg("title") = py::none(), py::arg("path") = py::none(), py::arg("ax") = py::none()

constexpr const char* kResponseDoc =
    "Complex frequency response H(exp(j 2 pi f Ts)) at freq_hz (Hz; a number or an array, result of the same\n"
    "shape). sample_time_s (s) defaults to the one the filter was designed for; required if that is 0.";

}  // namespace

void bind_filters(py::module_& m) {
  ParamClass<FloatBiquadParams>(m, "FloatBiquad",
      "A biquad in floating point, usual sign convention (scipy.signal, MATLAB)::\n"
      "\n"
      "  y(k) = b0 x(k) + b1 x(k-1) + b2 x(k-2) - a1 y(k-1) - a2 y(k-2),\n"
      "  H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2).\n"
      "\n"
      "sample_time_s is the sample time it was designed for (s; 0 = not bound to a period). Keyword arguments only;\n"
      "the default is a pass-through. Designed by servobench.design.lowpass/notch/lead_lag/from_s; to_adlink()\n"
      "quantises it to the ADLINK card's integers.")
      .field("b0", &FloatBiquadParams::b0, "numerator coefficient of z^0, finite")
      .field("b1", &FloatBiquadParams::b1, "numerator coefficient of z^-1, finite")
      .field("b2", &FloatBiquadParams::b2, "numerator coefficient of z^-2, finite")
      .field("a1", &FloatBiquadParams::a1, "denominator coefficient of z^-1 (subtracted), finite")
      .field("a2", &FloatBiquadParams::a2, "denominator coefficient of z^-2 (subtracted), finite")
      .field("sample_time_s", &FloatBiquadParams::sample_time_s, "design sample time, s, 0..1; 0 = not bound")
      .finish()
      .def("frequency_response", &response<FloatBiquadParams>, py::arg("freq_hz"),
           py::arg("sample_time_s") = py::none(), kResponseDoc)
      .def("filter", &filter_of<FloatBiquadParams>, py::arg("x"),
           "Runs the filter from rest over the samples x (1-D, one per tick) and returns its output, the same\n"
           "arithmetic the Axis uses every tick. Releases the GIL.")
      .def("poles", &poles_of<FloatBiquadParams>, "The two poles (complex z), roots of z^2 + a1 z + a2.")
      .def("is_stable", [](const FloatBiquadParams& p) { return control::is_stable(p); },
           "True if both poles are strictly inside the unit circle.")
      .def("plot", &plot_of, SERVOBENCH_PLOT_ARGS,
           "Bode plot (magnitude dB, phase deg, over frequency in Hz); see servobench.plot.filter_response for\n"
           "the keywords (freq_hz in Hz, sample_time_s in s). Returns what filter_response returns.");

  ParamClass<AdlinkBiquadParams>(m, "AdlinkBiquad",
      "The ADLINK PCI-8254/8258 integer biquad (PRA_BIQUADn_A1, A2, B0, B1, B2, DIV; manual L1873-1911)::\n"
      "\n"
      "  R(k) = (B0 X(k) + B1 X(k-1) + B2 X(k-2) + A1 R(k-1) + A2 R(k-2)) / DIV   (feedback ADDED),\n"
      "  H(z) = (B0 + B1 z^-1 + B2 z^-2) / (DIV - A1 z^-1 - A2 z^-2).\n"
      "\n"
      "Every coefficient a whole number -32768..32767, DIV != 0; defaults B0 = DIV = 1, others 0 (pass-through).\n"
      "Evaluated in double precision, no truncation of R (the card's DSP is floating point, L322; decisions.md F1).\n"
      "sample_time_s: the sample time the integers were designed for (s; 0 = not bound; not a card parameter).")
      .field("a1", &AdlinkBiquadParams::a1, "PRA_BIQUADn_A1 (132h/138h), feedback of R(k-1), -32768..32767")
      .field("a2", &AdlinkBiquadParams::a2, "PRA_BIQUADn_A2 (133h/139h), feedback of R(k-2), -32768..32767")
      .field("b0", &AdlinkBiquadParams::b0, "PRA_BIQUADn_B0 (134h/13Ah), -32768..32767")
      .field("b1", &AdlinkBiquadParams::b1, "PRA_BIQUADn_B1 (135h/13Bh), -32768..32767")
      .field("b2", &AdlinkBiquadParams::b2, "PRA_BIQUADn_B2 (136h/13Ch), -32768..32767")
      .field("div", &AdlinkBiquadParams::div, "PRA_BIQUADn_DIV (137h/13Dh), -32768..32767, not 0")
      .field("sample_time_s", &AdlinkBiquadParams::sample_time_s, "design sample time, s, 0..1; 0 = not bound")
      .finish()
      .def("frequency_response", &response<AdlinkBiquadParams>, py::arg("freq_hz"),
           py::arg("sample_time_s") = py::none(), kResponseDoc)
      .def("to_float", &AdlinkBiquadParams::to_float,
           "The same filter as a FloatBiquad: b_i = B_i/DIV, a1 = -A1/DIV, a2 = -A2/DIV.")
      .def("filter", &filter_of<AdlinkBiquadParams>, py::arg("x"),
           "Runs the filter from rest over the samples x (1-D, one per tick) and returns its output, the same\n"
           "arithmetic the Axis uses every tick. Releases the GIL.")
      .def("poles", &poles_of<AdlinkBiquadParams>, "The two poles (complex z), roots of DIV z^2 - A1 z - A2.")
      .def("is_stable", [](const AdlinkBiquadParams& p) { return control::is_stable(p); },
           "True if both poles are strictly inside the unit circle (exact integer test).")
      .def("plot", &plot_of, SERVOBENCH_PLOT_ARGS,
           "Bode plot (magnitude dB, phase deg, over frequency in Hz); see servobench.plot.filter_response for\n"
           "the keywords (freq_hz in Hz, sample_time_s in s). Returns what filter_response returns.");

#undef SERVOBENCH_PLOT_ARGS

  // After AdlinkBiquad is registered, so that its signature names the Python type (stubs, help()).
  auto float_biquad = py::reinterpret_borrow<py::class_<FloatBiquadParams>>(py::type::of<FloatBiquadParams>());
  float_biquad.def("to_adlink",
           [](const py::object& self) {
             return py::module_::import("servobench.quantisation").attr("to_adlink")(self).cast<AdlinkBiquadParams>();
           },
           "The ADLINK integer biquad (AdlinkBiquad): DIV = trunc(32767/max ``|coef|``), the largest ``|coef|`` -> +-32767,\n"
           "the others trunc(coef*DIV) (adlink.md §3.6; reproduces the manual's integers L1919, L1948). Raises\n"
           "ValueError if the integers cannot hold the design (coefficient > 32767, numerator truncated to 0,\n"
           "quantised poles on or outside the unit circle). Warns (servobench.quantisation.AdlinkQuantisationWarning,\n"
           "naming the figures) when the integers depart from the design by > 0.5 dB in its passband or move its\n"
           "notch null by > 10 % of the notch bandwidth (servobench.design.adlink_quantisation measures both).");

  py::module_ d = m.def_submodule("design", "Filter design (C++). Use servobench.design.");
  d.def("lowpass", &control::lowpass, py::arg("cutoff_hz"), py::arg("sample_time_s"), py::arg("zeta"),
        py::arg("prewarp"));
  d.def("quantize_adlink", &control::quantize_adlink, py::arg("design"),
        "FloatBiquad.to_adlink without the departure check (servobench.quantisation).");
  d.def("notch", &control::notch, py::arg("center_hz"), py::arg("q"), py::arg("sample_time_s"), py::arg("prewarp"));
  d.def("notch_band", &control::notch_band, py::arg("center_hz"), py::arg("low_hz"), py::arg("high_hz"),
        py::arg("sample_time_s"), py::arg("prewarp"));
  d.def("notch_band_q", &control::notch_band_q, py::arg("center_hz"), py::arg("low_hz"), py::arg("high_hz"),
        py::arg("sample_time_s"));
  d.def("lead_lag", &control::lead_lag, py::arg("zero_hz"), py::arg("pole_hz"), py::arg("sample_time_s"),
        py::arg("gain"), py::arg("prewarp"));
  d.def("from_s", &control::from_s, py::arg("num"), py::arg("den"), py::arg("sample_time_s"),
        py::arg("prewarp_hz"));
}

}  // namespace servobench::bindings
