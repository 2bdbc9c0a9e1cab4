#include <pybind11/complex.h>
#include <pybind11/numpy.h>

#include "param_class.hpp"
#include "flag.hpp"
#include "servobench/plant/encoder.hpp"
#include "servobench/plant/lti.hpp"
#include "servobench/plant/mechanics.hpp"
#include "servobench/plant/rigid.hpp"
#include "servobench/plant/switches.hpp"
#include "servobench/plant/two_mass.hpp"

namespace servobench::bindings {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<double> to_vector(const py::handle& obj, const char* name) {
  Array a = Array::ensure(obj);
  if (!a) throw py::type_error(std::string(name) + " must be an array of numbers");
  const py::ssize_t n = a.size();
  return std::vector<double>(a.data(), a.data() + n);
}

py::array_t<std::complex<double>> response(const plant::Mechanics& m, const py::handle& freq, Flag load_side,
                                           const std::optional<double>& period_s) {
  if (period_s && !(*period_s > 0 && std::isfinite(*period_s)))
    throw_invalid("frequency_response", "period_s", *period_s, "must be finite and > 0 (or None: continuous)");
  std::vector<double> f = to_vector(freq, "freq_hz");
  std::vector<std::complex<double>> h;
  {
    py::gil_scoped_release release;
    h = plant::frequency_response(m, f, load_side, period_s ? *period_s : 0.0);
  }
  py::array_t<std::complex<double>> out(static_cast<py::ssize_t>(h.size()));
  std::copy(h.begin(), h.end(), out.mutable_data());
  return out;
}

py::array_t<double> friction_curve(const plant::FrictionParams& fp, const py::handle& speed) {
  Array s = Array::ensure(speed);
  if (!s) throw py::type_error("speed_rad_s must be an array of numbers");
  py::array_t<double> out(s.request().shape);
  const double* in = s.data();
  double* o = out.mutable_data();
  for (py::ssize_t k = 0; k < s.size(); ++k) {
    if (!std::isfinite(in[k])) throw_invalid("friction_torque", "speed_rad_s", in[k], "is not a finite number");
    o[k] = fp.steady_torque_nm(in[k]);
  }
  return out;
}


// A 2-D matrix from a number, a 1-D or a 2-D array; `as_row`: a 1-D array is a row (C), else a column (B).
Eigen::MatrixXd matrix_from(const py::handle& obj, const char* name, bool as_row) {
  Array arr = Array::ensure(obj);
  if (!arr) throw py::type_error(std::string("LtiPlant.") + name + " must be an array of numbers");
  if (arr.ndim() > 2) throw py::value_error(std::string("LtiPlant.") + name + " must be 1-D or 2-D");
  Eigen::Index r = 1, c = 1;
  if (arr.ndim() == 2) {
    r = arr.shape(0);
    c = arr.shape(1);
  } else if (arr.ndim() == 1) {
    (as_row ? c : r) = arr.shape(0);
  }
  Eigen::MatrixXd m(r, c);
  const double* d = arr.data();
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) m(i, j) = d[i * c + j];
  return m;
}

py::array_t<double> matrix_to(const Eigen::MatrixXd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out.mutable_at(i, j) = m(i, j);
  out.attr("setflags")(py::arg("write") = false);
  return out;
}

// The scalar fields of LtiPlant, in order (the matrices a, b, c come first).
using plant::LtiPlantParams;
const std::vector<std::pair<const char*, double LtiPlantParams::*>>& lti_fields() {
  static const std::vector<std::pair<const char*, double LtiPlantParams::*>> f = {
      {"d", &LtiPlantParams::d},
      {"lead_m_per_rev", &LtiPlantParams::lead_m_per_rev},
      {"coulomb_nm", &LtiPlantParams::coulomb_nm},
      {"static_nm", &LtiPlantParams::static_nm},
      {"stribeck_speed_rad_s", &LtiPlantParams::stribeck_speed_rad_s},
      {"stribeck_exponent", &LtiPlantParams::stribeck_exponent},
      {"coulomb_asym_nm", &LtiPlantParams::coulomb_asym_nm},
      {"load_nm", &LtiPlantParams::load_nm}};
  return f;
}

void lti_apply(LtiPlantParams& p, const py::dict& kw) {
  for (const auto& item : kw) {
    const std::string key = py::str(item.first);
    if (key == "a") p.a = matrix_from(item.second, "a", false);
    else if (key == "b") p.b = matrix_from(item.second, "b", false);
    else if (key == "c") p.c = matrix_from(item.second, "c", true);
    else {
      bool found = false;
      for (const auto& [name, member] : lti_fields()) {
        if (key == name) {
          const Eigen::MatrixXd v = matrix_from(item.second, name, false);
          if (v.size() != 1) throw py::value_error(std::string("LtiPlant.") + name + " must be a number");
          p.*member = v(0, 0);
          found = true;
        }
      }
      if (!found) {
        std::string names = "a, b, c";
        for (const auto& f : lti_fields()) names += std::string(", ") + f.first;
        throw py::type_error("LtiPlant: unknown parameter '" + key + "'; the parameters are " + names);
      }
    }
  }
}

// replace()'s docstring, its first line the signature with every field as a keyword (omitted = unchanged), as
// ParamClass writes it (decision Y2): help(), completion and the stubs see the fields; unknown ones still get
// lti_apply's "unknown parameter" error naming the fields.
const std::string& lti_replace_doc() {
  static const std::string doc = [] {
    std::string s = "replace(self, *, a: numpy.typing.ArrayLike = ..., b: numpy.typing.ArrayLike = ..., "
                    "c: numpy.typing.ArrayLike = ...";
    for (const auto& [name, member] : lti_fields()) s += std::string(", ") + name + ": float = ...";
    return s + ") -> servobench._core.LtiPlant\n\nA validated copy with the given fields changed (the others kept).";
  }();
  return doc;
}

py::dict lti_dict(const LtiPlantParams& p) {
  py::dict d;
  d["a"] = matrix_to(p.a);
  d["b"] = matrix_to(p.b);
  d["c"] = matrix_to(p.c);
  for (const auto& [name, member] : lti_fields()) d[name] = p.*member;
  return d;
}

LtiPlantParams lti_from(const py::dict& kw) {
  LtiPlantParams p;
  lti_apply(p, kw);
  p.validate();
  return p;
}

const char* kResponseDoc =
    "Frequency response from motor torque (N*m) to the motor (output='motor') or load (output='load') angle (rad)\n"
    "at freq_hz (Hz), complex. period_s=None: the continuous plant; period_s=Ts: its zero-order-hold\n"
    "discretisation at Ts (what a sampled loop sees), valid below the Nyquist frequency. Linear part only\n"
    "(inertias, shaft, viscous friction); dry friction and disturbances are nonlinear and left out.";

}  // namespace

void bind_plant(py::module_& m) {
  using plant::EncoderParams;
  using plant::RigidPlantParams;
  using plant::SwitchParams;
  using plant::TwoMassPlantParams;

  ParamClass<RigidPlantParams>(m, "RigidPlant",
      "Rigid single-inertia mechanics (SI): J*w' = torque - friction(w) - load - unbalance*sin(theta) +\n"
      "cogging*sin(N*theta). Friction: viscous + Coulomb + Stribeck, with stiction (at rest while the applied\n"
      "torque stays within the breakaway level).")
      .field("inertia_kgm2", &RigidPlantParams::inertia_kgm2, "total inertia at the motor, kg*m^2, > 0")
      .field("viscous_nms", &RigidPlantParams::viscous_nms, "viscous friction, N*m*s/rad, >= 0")
      .field("coulomb_nm", &RigidPlantParams::coulomb_nm, "Coulomb (sliding) friction, N*m, >= 0")
      .field("static_nm", &RigidPlantParams::static_nm, "breakaway friction, N*m, 0 (= coulomb) or >= coulomb_nm")
      .field("stribeck_speed_rad_s", &RigidPlantParams::stribeck_speed_rad_s, "Stribeck speed, rad/s, > 0")
      .field("stribeck_exponent", &RigidPlantParams::stribeck_exponent, "Stribeck shape exponent, 0.5..4")
      .field("coulomb_asym_nm", &RigidPlantParams::coulomb_asym_nm,
             "Coulomb asymmetry (Fc+ - Fc-)/2, N*m, magnitude <= coulomb_nm (Fc+/- = coulomb_nm +/- this)")
      .field("viscous_asym_nms", &RigidPlantParams::viscous_asym_nms,
             "viscous asymmetry (b+ - b-)/2, N*m*s/rad, magnitude <= viscous_nms (b+/- = viscous_nms +/- this)")
      .field("load_nm", &RigidPlantParams::load_nm, "constant load torque, N*m (positive opposes positive motion)")
      .field("unbalance_nm", &RigidPlantParams::unbalance_nm, "gravity torque amplitude of an unbalanced arm, N*m")
      .field("cogging_nm", &RigidPlantParams::cogging_nm, "cogging ripple amplitude, N*m, >= 0")
      .field("cogging_periods", &RigidPlantParams::cogging_periods, "cogging periods per revolution, 0..1000")
      .finish()
      .def("frequency_response",
           [](const RigidPlantParams& p, const py::handle& f, std::optional<double> period_s) {
             return response(plant::rigid_mechanics(p), f, false, period_s);
           },
           py::arg("freq_hz"), py::kw_only(), py::arg("period_s") = py::none(), kResponseDoc)
      .def("friction_torque", [](const RigidPlantParams& p, const py::handle& s) { return friction_curve(p.friction(), s); },
           py::arg("speed_rad_s"),
           "Steady friction torque (N*m) opposing motion at each speed (rad/s): Stribeck curve plus viscous; 0 at rest.");

  ParamClass<TwoMassPlantParams>(m, "TwoMassPlant",
      "Two-mass mechanics (SI): motor inertia jm and load inertia jl joined by a shaft of stiffness k and damping c,\n"
      "friction (viscous + Coulomb + Stribeck, stiction) on each side, load torque, unbalance and cogging.\n"
      "resonance_hz / antiresonance_hz give the undamped resonance sqrt(k(jm+jl)/(jm jl)) and anti-resonance\n"
      "sqrt(k/jl) of the motor-side response.")
      .field("jm_kgm2", &TwoMassPlantParams::jm_kgm2, "motor inertia, kg*m^2, > 0")
      .field("jl_kgm2", &TwoMassPlantParams::jl_kgm2, "load inertia, kg*m^2, > 0")
      .field("k_nm_per_rad", &TwoMassPlantParams::k_nm_per_rad, "shaft stiffness, N*m/rad, > 0")
      .field("c_nms_per_rad", &TwoMassPlantParams::c_nms_per_rad, "shaft damping, N*m*s/rad, >= 0")
      .field("motor_viscous_nms", &TwoMassPlantParams::motor_viscous_nms, "motor-side viscous friction, N*m*s/rad")
      .field("motor_coulomb_nm", &TwoMassPlantParams::motor_coulomb_nm, "motor-side Coulomb friction, N*m")
      .field("motor_static_nm", &TwoMassPlantParams::motor_static_nm, "motor-side breakaway friction, N*m (0 = coulomb)")
      .field("motor_stribeck_speed_rad_s", &TwoMassPlantParams::motor_stribeck_speed_rad_s, "rad/s, > 0")
      .field("motor_stribeck_exponent", &TwoMassPlantParams::motor_stribeck_exponent, "0.5..4")
      .field("load_viscous_nms", &TwoMassPlantParams::load_viscous_nms, "load-side viscous friction, N*m*s/rad")
      .field("load_coulomb_nm", &TwoMassPlantParams::load_coulomb_nm, "load-side Coulomb friction, N*m")
      .field("load_static_nm", &TwoMassPlantParams::load_static_nm, "load-side breakaway friction, N*m (0 = coulomb)")
      .field("load_stribeck_speed_rad_s", &TwoMassPlantParams::load_stribeck_speed_rad_s, "rad/s, > 0")
      .field("load_stribeck_exponent", &TwoMassPlantParams::load_stribeck_exponent, "0.5..4")
      .field("motor_coulomb_asym_nm", &TwoMassPlantParams::motor_coulomb_asym_nm,
             "motor-side Coulomb asymmetry (Fc+ - Fc-)/2, N*m, magnitude <= motor_coulomb_nm")
      .field("motor_viscous_asym_nms", &TwoMassPlantParams::motor_viscous_asym_nms,
             "motor-side viscous asymmetry (b+ - b-)/2, N*m*s/rad, magnitude <= motor_viscous_nms")
      .field("load_coulomb_asym_nm", &TwoMassPlantParams::load_coulomb_asym_nm,
             "load-side Coulomb asymmetry (Fc+ - Fc-)/2, N*m, magnitude <= load_coulomb_nm")
      .field("load_viscous_asym_nms", &TwoMassPlantParams::load_viscous_asym_nms,
             "load-side viscous asymmetry (b+ - b-)/2, N*m*s/rad, magnitude <= load_viscous_nms")
      .field("load_nm", &TwoMassPlantParams::load_nm, "constant load torque on the load side, N*m")
      .field("unbalance_nm", &TwoMassPlantParams::unbalance_nm, "gravity torque amplitude on the load side, N*m")
      .field("cogging_nm", &TwoMassPlantParams::cogging_nm, "motor cogging amplitude, N*m, >= 0")
      .field("cogging_periods", &TwoMassPlantParams::cogging_periods, "cogging periods per motor revolution, 0..1000")
      .finish()
      .def_property_readonly("resonance_hz", &TwoMassPlantParams::resonance_hz, "undamped resonance, Hz")
      .def_property_readonly("antiresonance_hz", &TwoMassPlantParams::antiresonance_hz, "undamped anti-resonance, Hz")
      .def("frequency_response",
           [](const TwoMassPlantParams& p, const py::handle& f, const std::string& output, std::optional<double> period_s) {
             if (output != "motor" && output != "load")
               throw py::value_error("output = '" + output + "' must be 'motor' or 'load'");
             return response(plant::two_mass_mechanics(p), f, output == "load", period_s);
           },
           py::arg("freq_hz"), py::kw_only(), py::arg("output") = "motor", py::arg("period_s") = py::none(), kResponseDoc)
      .def("friction_torque",
           [](const TwoMassPlantParams& p, const py::handle& s, const std::string& side) {
             if (side != "motor" && side != "load") throw py::value_error("side = '" + side + "' must be 'motor' or 'load'");
             return friction_curve(side == "motor" ? p.motor_friction() : p.load_friction(), s);
           },
           py::arg("speed_rad_s"), py::kw_only(), py::arg("side") = "motor",
           "Steady friction torque (N*m) of one side at each speed (rad/s): Stribeck curve plus viscous; 0 at rest.");


  py::class_<LtiPlantParams>(m, "LtiPlant",
      "A linear plant of your own (plant/lti.hpp): x' = A x + B u, y = C x (D = 0), 2..7 states, from the motor\n"
      "torque u (N*m) to the encoder angle y (rad); with lead_m_per_rev > 0 a linear axis model from force (N) to\n"
      "position (m) behind an ideal screw of that lead (m/rev). Relative degree >= 2 (c @ b = 0). Discretised\n"
      "exactly by zero-order hold at every sub-step; optional dry friction at the motor (Coulomb, Stribeck,\n"
      "stiction, asymmetry; it needs c @ a @ b > 0) and a constant load torque. Unstable plants are allowed:\n"
      "see `stability`. From python-control: LtiPlant.from_control(sys) (servobench.lti).")
      .def(py::init([](const py::object& a, const py::object& b, const py::object& c, double d, double lead,
                       double coulomb, double stat, double ws, double delta, double asym, double load) {
             py::dict kw;
             kw["a"] = a;
             kw["b"] = b;
             kw["c"] = c;
             LtiPlantParams p;
             lti_apply(p, kw);
             p.d = d;
             p.lead_m_per_rev = lead;
             p.coulomb_nm = coulomb;
             p.static_nm = stat;
             p.stribeck_speed_rad_s = ws;
             p.stribeck_exponent = delta;
             p.coulomb_asym_nm = asym;
             p.load_nm = load;
             p.validate();
             return p;
           }),
           py::kw_only(), py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d") = 0.0, py::arg("lead_m_per_rev") = 0.0,
           py::arg("coulomb_nm") = 0.0, py::arg("static_nm") = 0.0, py::arg("stribeck_speed_rad_s") = 0.01,
           py::arg("stribeck_exponent") = 2.0, py::arg("coulomb_asym_nm") = 0.0, py::arg("load_nm") = 0.0)
      .def_property_readonly("a", [](const LtiPlantParams& p) { return matrix_to(p.a); }, "A, n x n, 1/s")
      .def_property_readonly("b", [](const LtiPlantParams& p) { return matrix_to(p.b); },
                             "B, n x 1, state units per s per N*m (per N with a lead)")
      .def_property_readonly("c", [](const LtiPlantParams& p) { return matrix_to(p.c); },
                             "C, 1 x n, rad (m with a lead) per state unit")
      .def_property_readonly("d", [](const LtiPlantParams& p) { return p.d; }, "D, always 0")
      .def_property_readonly("lead_m_per_rev", [](const LtiPlantParams& p) { return p.lead_m_per_rev; },
                             "0: rotary model; > 0: linear model (N -> m) behind this lead, m/rev")
      .def_property_readonly("coulomb_nm", [](const LtiPlantParams& p) { return p.coulomb_nm; },
                             "Coulomb friction at the motor, N*m, >= 0")
      .def_property_readonly("static_nm", [](const LtiPlantParams& p) { return p.static_nm; },
                             "breakaway friction, N*m, 0 (= coulomb) or >= coulomb_nm")
      .def_property_readonly("stribeck_speed_rad_s", [](const LtiPlantParams& p) { return p.stribeck_speed_rad_s; },
                             "Stribeck speed, rad/s, > 0")
      .def_property_readonly("stribeck_exponent", [](const LtiPlantParams& p) { return p.stribeck_exponent; },
                             "Stribeck shape exponent, 0.5..4")
      .def_property_readonly("coulomb_asym_nm", [](const LtiPlantParams& p) { return p.coulomb_asym_nm; },
                             "Coulomb asymmetry (Fc+ - Fc-)/2, N*m")
      .def_property_readonly("load_nm", [](const LtiPlantParams& p) { return p.load_nm; },
                             "constant load torque at the motor, N*m")
      .def_property_readonly("states", &LtiPlantParams::states, "state count n")
      .def_property_readonly("stability", &LtiPlantParams::stability,
                             "'stable', 'marginal (k poles on the imaginary axis)' or 'unstable (k poles in Re s > 0)'")
      .def_property_readonly("inertia_kgm2", &LtiPlantParams::inertia_kgm2,
                             "high-frequency inertia 1/(c a b) at the motor (ports' units), kg*m^2; 0 above relative degree 2")
      .def("port_model",
           [](const LtiPlantParams& p) {
             Eigen::MatrixXd a, b, c;
             p.port_model(a, b, c);
             return py::make_tuple(matrix_to(a), matrix_to(b), matrix_to(c));
           },
           "(A, B, C) from motor torque (N*m) to encoder angle (rad): B and C scaled by 2 pi / lead for a linear model.")
      .def("to_dict", &lti_dict, "The parameters as a dict (a, b, c as arrays, the rest numbers).")
      .def("__repr__",
           [](const LtiPlantParams& p) {
             std::string s = "LtiPlant(states=" + std::to_string(p.states()) + ", " + p.stability();
             for (const auto& [name, member] : lti_fields()) {
               const double v = p.*member;
               const LtiPlantParams def;
               if (v != def.*member) s += std::string(", ") + name + "=" + format_value(v);
             }
             return s + ")";
           })
      .def("__eq__",
           [](const LtiPlantParams& x, const py::object& other) {
             if (!py::isinstance<LtiPlantParams>(other)) return false;
             const auto& y = other.cast<const LtiPlantParams&>();
             if (x.a != y.a || x.b != y.b || x.c != y.c) return false;
             for (const auto& f : lti_fields())
               if (x.*(f.second) != y.*(f.second)) return false;
             return true;
           })
      .def(py::pickle([](const LtiPlantParams& p) { return lti_dict(p); },
                      [](const py::dict& d) { return lti_from(d); }))
      .def("frequency_response",
           [](const LtiPlantParams& p, const py::handle& f, std::optional<double> period_s) {
             return response(plant::lti_mechanics(p), f, false, period_s);
           },
           py::arg("freq_hz"), py::kw_only(), py::arg("period_s") = py::none(),
           "Frequency response from motor torque (N*m) to the encoder angle (rad) at freq_hz (Hz), complex.\n"
           "period_s=None: the continuous plant; period_s=Ts: its zero-order-hold discretisation at Ts. Linear part\n"
           "only (dry friction and the load are left out).")
      .def("friction_torque", [](const LtiPlantParams& p, const py::handle& s) { return friction_curve(p.friction(), s); },
           py::arg("speed_rad_s"),
           "Steady dry friction torque (N*m) opposing motion at each speed (rad/s); 0 at rest (viscous terms are in A).");
  {  // replace(): its signature is its docstring's first line (lti_replace_doc), as ParamClass does
    py::options options;
    options.disable_function_signatures();
    py::object cls = m.attr("LtiPlant");
    cls.attr("replace") = py::cpp_function(
        [](const LtiPlantParams& p, const py::kwargs& kw) {
          LtiPlantParams q = p;
          lti_apply(q, kw);
          q.validate();
          return q;
        },
        py::name("replace"), py::is_method(cls), lti_replace_doc().c_str());
  }
  m.attr("LtiPlant").attr("__hash__") = py::none();
  m.attr("LtiPlant").attr("FIELDS") = py::make_tuple("a", "b", "c", "d", "lead_m_per_rev", "coulomb_nm", "static_nm",
                                                     "stribeck_speed_rad_s", "stribeck_exponent", "coulomb_asym_nm",
                                                     "load_nm");

  m.def("plant_linear",
        [](const py::object& p) {
          Eigen::MatrixXd a, b, c_motor, c_load;
          if (py::isinstance<LtiPlantParams>(p)) {
            p.cast<const LtiPlantParams&>().port_model(a, b, c_motor);
            c_load = c_motor;
          } else {
            plant::Mechanics mech;
            if (py::isinstance<RigidPlantParams>(p)) mech = plant::rigid_mechanics(p.cast<RigidPlantParams>());
            else if (py::isinstance<TwoMassPlantParams>(p)) mech = plant::two_mass_mechanics(p.cast<TwoMassPlantParams>());
            else throw py::type_error("plant must be a RigidPlant, a TwoMassPlant or an LtiPlant");
            a = mech.a;
            b = mech.b.col(0);
            c_motor = Eigen::MatrixXd::Zero(1, a.rows());
            c_load = c_motor;
            c_motor(0, mech.motor_angle) = 1.0;
            c_load(0, mech.load_angle) = 1.0;
          }
          return py::make_tuple(matrix_to(a), matrix_to(b), matrix_to(c_motor), matrix_to(c_load));
        },
        py::arg("plant"),
        "The plant's linear part (A, B, C_motor, C_load), continuous, from the motor torque (N*m) to the motor / load "
        "angle (rad): the simulator's own matrices (an LtiPlant's in its own coordinates, at the ports).");

  ParamClass<EncoderParams>(m, "Encoder",
      "Position encoder: count = floor(angle*counts_per_rev/(2*pi) + noise + 1/2) (quantize=True) or the continuous\n"
      "value. counts_per_rev is after x4 quadrature decoding (2500 lines -> 10000). noise_counts: Gaussian noise,\n"
      "counts (std dev), from a generator seeded with `seed`. index_angle_rad: where the once-per-revolution index\n"
      "mark sits. on_load: mounted on the load (fully closed loop) instead of the motor (semi-closed).")
      .field("counts_per_rev", &EncoderParams::counts_per_rev, "counts per revolution, whole number 1..2^31")
      .field("quantize", &EncoderParams::quantize, "False: ideal continuous encoder")
      .field("noise_counts", &EncoderParams::noise_counts, "noise standard deviation, counts, >= 0")
      .field("seed", &EncoderParams::seed, "noise seed, whole number 0..2^32-1")
      .field("index_angle_rad", &EncoderParams::index_angle_rad, "index mark angle, rad")
      .field("on_load", &EncoderParams::on_load, "True: on the load side (two-mass plants)")
      .finish();

  ParamClass<SwitchParams>(m, "Switches",
      "Home and limit switches along the load's travel (load angle, rad): home on while home_min_rad <= angle <=\n"
      "home_max_rad (both inf: none); positive limit on while angle >= pos_limit_rad (inf: none); negative limit on\n"
      "while angle <= neg_limit_rad (-inf: none).")
      .field("home_min_rad", &SwitchParams::home_min_rad, "home window start, rad (inf: no home switch)")
      .field("home_max_rad", &SwitchParams::home_max_rad, "home window end, rad (inf: no home switch)")
      .field("pos_limit_rad", &SwitchParams::pos_limit_rad, "positive limit position, rad (inf: none)")
      .field("neg_limit_rad", &SwitchParams::neg_limit_rad, "negative limit position, rad (-inf: none)")
      .finish();
}

}  // namespace servobench::bindings
