// Bindings of the identification layer: time-domain and frequency-domain fits. Thin: arrays in, dicts out.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "param_class.hpp"
#include "arrays.hpp"
#include "result_table.hpp"
#include "flag.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/identify/frequency_fit.hpp"
#include "servobench/identify/time_fit.hpp"

namespace servobench::bindings {

namespace py = pybind11;

namespace {

identify::PlantModel model_of(const std::string& name) {
  if (name == "rigid") return identify::PlantModel::kRigid;
  if (name == "two_mass") return identify::PlantModel::kTwoMass;
  throw py::value_error("model = '" + name + "' is not one of 'rigid', 'two_mass'");
}

identify::Loss loss_of(const std::string& name) {
  if (name == "none") return identify::Loss::kNone;
  if (name == "huber") return identify::Loss::kHuber;
  if (name == "soft_l1") return identify::Loss::kSoftLOne;
  if (name == "cauchy") return identify::Loss::kCauchy;
  throw py::value_error("loss = '" + name + "' is not one of 'none', 'huber', 'soft_l1', 'cauchy'");
}

identify::ParameterSetup setup_of(const py::handle& initial, const std::vector<Flag>& fixed, const py::handle& lower,
                                  const py::handle& upper) {
  identify::ParameterSetup s;
  s.initial = real_vector(initial, "initial");
  s.fixed.assign(fixed.begin(), fixed.end());
  s.lower = real_vector(lower, "lower");
  s.upper = real_vector(upper, "upper");
  return s;
}

py::list estimates(const std::vector<identify::ParameterEstimate>& ps) {
  py::list out;
  for (const auto& e : ps) {
    py::dict d;
    put_described(d, e);  // name ... at_bound, as identify::ParameterEstimate::describe() names them (OR1)
    d["lower"] = e.lower;  // the bounds in force (the fit's setup, not an Estimate field)
    d["upper"] = e.upper;
    out.append(d);
  }
  return out;
}

py::dict summary(const identify::FitSummary& s) {
  py::dict d(py::arg("termination") = s.termination, py::arg("initial_cost") = s.initial_cost,
             py::arg("final_cost") = s.final_cost, py::arg("residuals") = s.residuals,
             py::arg("free_parameters") = s.free_parameters, py::arg("nuisance_parameters") = s.nuisance_parameters,
             py::arg("not_identifiable") = s.not_identifiable, py::arg("report") = s.report);
  put_described(d, s);  // nrmse ... seconds, named as FitSummary::describe() names them (decision OQ6)
  return d;
}

// An iteration callback (iteration, cost) -> bool|None, the GIL taken for the call; empty if None.
// Thrown from the iteration callback on Ctrl-C: unwinds the fit (its stages and its covariance are not computed)
// back to the binding, which raises the kept KeyboardInterrupt (raise_pending). Ceres holds its state in RAII
// objects, so the unwinding frees it; the fit's result is discarded.
struct SolveInterrupted {};

// The solver's per-iteration callback: the user's progress function (None: none) and a Ctrl-C check; a pending
// signal is kept in *interrupt and ends the fit at once (SolveInterrupted). It holds pointers only (`f` outlives
// the fit): the solver may copy it without the GIL, and copying a py::object would touch its reference count.
std::function<bool(int, double)> iteration_callback(const py::object& progress,
                                                   std::shared_ptr<py::error_already_set>* interrupt) {
  const py::object* fp = &progress;
  return [fp, interrupt](int it, double cost) {
    const py::object& f = *fp;
    {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) *interrupt = std::make_shared<py::error_already_set>();
    }
    if (*interrupt) throw SolveInterrupted{};
    py::gil_scoped_acquire gil;
    if (f.is_none()) return true;
    py::object r = f(it, cost);
    return r.is_none() || r.cast<bool>();
  };
}

// A log from arrays.
identify::TimeLog time_log(const py::handle& torque_nm, const py::handle& measured, double sample_period_s,
                           Flag measured_is_speed, Flag measured_on_load) {
  identify::TimeLog log;
  log.sample_period_s = sample_period_s;
  log.torque_nm = real_vector(torque_nm, "torque_nm");
  log.measured = real_vector(measured, "measured");
  log.measured_is_speed = measured_is_speed;
  log.measured_on_load = measured_on_load;
  return log;
}

// TimeFitOptions from keyword arguments named after its described fields (the others at their defaults), through
// the bound parameter class: the names, whole-number checks and ranges are the struct's (describe(), validate();
// decision OQ2). `loss` is chosen by name.
identify::TimeFitOptions options_from(const std::string& model, const py::kwargs& kw) {
  py::dict fields;
  std::string loss = "none";
  for (const auto& item : kw) {
    const std::string k = py::str(item.first);
    if (k == "loss") {
      loss = item.second.cast<std::string>();
    } else {
      fields[item.first] = item.second;
    }
  }
  identify::TimeFitOptions o = py::type::of<identify::TimeFitOptions>()(**fields).cast<identify::TimeFitOptions>();
  o.model = model_of(model);
  o.loss = loss_of(loss);
  o.validate();
  return o;
}

identify::MechanicsIO mechanics_io_from(const py::handle& io) {
  if (py::isinstance<identify::MechanicsIO>(io)) return io.cast<identify::MechanicsIO>();
  // a dict of its described fields (servobench.frequency_fit.MechanicsIO._core_dict)
  return py::type::of<identify::MechanicsIO>()(**io.cast<py::dict>()).cast<identify::MechanicsIO>();
}

}  // namespace

void bind_identify(py::module_& m) {
  // Described once in its C++ struct (decision OP3); fit_frequency reads defaults, units and docs from it.
  ParamClass<identify::FrequencyFitOptions>(m, "FrequencyFitOptions",
                                            "Options of the frequency-response fit (identify/frequency_fit.hpp).")
      .described()
      .finish();
  m.attr("FIT_SUMMARY_FIELDS") = described_fields<identify::FitSummary>();  // servobench.identify.IdentifiedPlant
  m.attr("PARAMETER_ESTIMATE_FIELDS") = described_fields<identify::ParameterEstimate>();  // servobench.identify.Estimate
  // Described once in their C++ structs (decisions OQ2, OQ3): fit_time and MechanicsIO read them.
  ParamClass<identify::TimeFitOptions>(m, "TimeFitOptions",
                                       "Options of the time-domain fit (identify/time_fit.hpp); the model and the "
                                       "loss are chosen by name.")
      .described()
      .finish();
  ParamClass<identify::MechanicsIO>(m, "MechanicsIO",
                                    "What surrounds the mechanics in a measured response without a servobench Axis "
                                    "(identify/frequency_fit.hpp).")
      .described()
      .finish();
  m.def(
      "identify_parameters",
      [](const std::string& model) {
        py::list out;
        for (const auto& p : identify::model_parameters(model_of(model)))
          out.append(py::dict(py::arg("name") = p.name, py::arg("unit") = p.unit, py::arg("lower") = p.lower,
                              py::arg("linear") = p.linear, py::arg("meaning") = p.meaning));
        return out;
      },
      py::arg("model"), "The parameters of a plant model ('rigid' or 'two_mass'), in the order of its vector.");

  m.def(
      "identify_time",
      [](const py::handle& torque_nm, const py::handle& measured, double sample_period_s, Flag measured_is_speed,
         Flag measured_on_load, const std::string& model, const py::handle& initial, const std::vector<Flag>& fixed,
         const py::handle& lower, const py::handle& upper, const py::object& progress, const py::object& join_points,
         double join_rtol, const py::kwargs& kw) {
        const identify::TimeLog log = time_log(torque_nm, measured, sample_period_s, measured_is_speed,
                                               measured_on_load);
        identify::TimeFitOptions o = options_from(model, kw);
        std::shared_ptr<py::error_already_set> interrupt;
        o.progress = iteration_callback(progress, &interrupt);
        const identify::ParameterSetup s = setup_of(initial, fixed, lower, upper);
        identify::StageJoin join;
        join.rtol = join_rtol;
        if (!join_points.is_none())
          for (const py::handle& q : join_points) join.points.push_back(real_vector(q, "join_points[k]"));
        identify::TimeFitResult r;
        try {
          py::gil_scoped_release release;
          r = identify::fit_time_domain(log, s, o, join_points.is_none() ? nullptr : &join);
        } catch (const SolveInterrupted&) {
        }
        raise_pending(interrupt);
        py::dict d;
        py::list stage_parameters;
        for (const auto& q : r.stage_parameters) stage_parameters.append(to_array(q));
        d["stage_parameters"] = stage_parameters;
        d["joined_stage"] = r.joined_stage;
        d["parameters"] = estimates(r.parameters);
        d["summary"] = summary(r.summary);
        d["predicted"] = to_array(r.predicted);
        d["residual"] = to_array(r.residual);
        d["segment_start"] = to_array(r.segment_start);
        d["segment_count"] = to_array(r.segment_count);
        d["segment_states"] = to_array(r.segment_states);
        return d;
      },
      py::arg("torque_nm"), py::arg("measured"), py::kw_only(), py::arg("sample_period_s"),
      py::arg("measured_is_speed"), py::arg("measured_on_load"), py::arg("model"), py::arg("initial"),
      py::arg("fixed"), py::arg("lower"), py::arg("upper"), py::arg("progress") = py::none(),
      py::arg("join_points") = py::none(), py::arg("join_rtol") = 1e-4,
      "Time-domain grey-box fit of the plant (Ceres). Options: TimeFitOptions field names. join_points: another "
      "start's stage_parameters; the fit stops after a stage (not the last) whose free parameters agree with that "
      "start's there within join_rtol (relative), and returns joined_stage >= 0 with only stage_parameters and the "
      "summary's iterations, seconds and report (decision FV15). Releases the GIL.");

  m.def(
      "identify_shooting_problem",
      [](const py::handle& torque_nm, const py::handle& measured, double sample_period_s, Flag measured_is_speed,
         Flag measured_on_load, const std::string& model, const py::kwargs& kw) {
        const identify::TimeLog log = time_log(torque_nm, measured, sample_period_s, measured_is_speed,
                                               measured_on_load);
        const identify::ShootingProblem sp = identify::shooting_problem(log, options_from(model, kw));
        return py::dict(py::arg("starts") = to_array(sp.starts), py::arg("counts") = to_array(sp.counts),
                        py::arg("states") = to_array(sp.states), py::arg("state_size") = sp.state_size);
      },
      py::arg("torque_nm"), py::arg("measured"), py::kw_only(), py::arg("sample_period_s"),
      py::arg("measured_is_speed"), py::arg("measured_on_load"), py::arg("model"),
      "One stage's multiple-shooting layout (segments of about segment_samples, their data-based start states), for "
      "an outside solver. Options: TimeFitOptions field names.");

  m.def(
      "identify_shooting_residual",
      [](const py::handle& torque_nm, const py::handle& measured, double sample_period_s, Flag measured_is_speed,
         Flag measured_on_load, const std::string& model, const py::handle& starts, const py::handle& counts,
         const py::handle& parameters, const py::handle& states, Flag jacobian, const py::kwargs& kw) -> py::object {
        const identify::TimeLog log = time_log(torque_nm, measured, sample_period_s, measured_is_speed,
                                               measured_on_load);
        const identify::TimeFitOptions o = options_from(model, kw);
        identify::ShootingProblem sp;
        for (double v : real_vector(starts, "starts")) sp.starts.push_back(static_cast<int>(v));
        for (double v : real_vector(counts, "counts")) sp.counts.push_back(static_cast<int>(v));
        if (sp.starts.size() != sp.counts.size()) throw py::value_error("starts and counts must have the same length");
        sp.state_size = identify::mechanical_states(o.model);
        sp.states.assign(sp.starts.size() * static_cast<std::size_t>(sp.state_size), 0.0);
        const std::vector<double> p = real_vector(parameters, "parameters");
        const std::vector<double> x = real_vector(states, "states");
        identify::SparseJacobian jac;
        std::vector<double> r;
        {
          py::gil_scoped_release release;
          r = identify::shooting_residual(log, o, sp, p, x, jacobian ? &jac : nullptr);
        }
        if (!jacobian) return to_array(r);
        return py::make_tuple(to_array(r), py::make_tuple(to_array(jac.values), to_array(jac.col_index),
                                                          to_array(jac.row_ptr)),
                              py::make_tuple(jac.rows, jac.cols));
      },
      py::arg("torque_nm"), py::arg("measured"), py::kw_only(), py::arg("sample_period_s"),
      py::arg("measured_is_speed"), py::arg("measured_on_load"), py::arg("model"), py::arg("starts"),
      py::arg("counts"), py::arg("parameters"), py::arg("states"), py::arg("jacobian") = false,
      "The fit's scaled residual at the INTERNAL parameter vector (breakaway entry = Stribeck excess Fs - Fc) and "
      "the segment states; with jacobian=True also (residual, (data, indices, indptr), shape) of its Jacobian over "
      "[parameters, states] in CSR. Releases the GIL.");

  m.def(
      "identify_simulate",
      [](const py::handle& torque_nm, double sample_period_s, Flag measured_is_speed, Flag measured_on_load,
         const std::string& model, const py::handle& parameters, const py::handle& initial_state,
         const py::kwargs& kw) {
        identify::TimeLog log = time_log(torque_nm, torque_nm, sample_period_s, measured_is_speed, measured_on_load);
        const identify::TimeFitOptions o = options_from(model, kw);
        std::vector<double> out;
        const auto p = real_vector(parameters, "parameters");
        const auto x0 = real_vector(initial_state, "initial_state");
        {
          py::gil_scoped_release release;
          out = identify::simulate_model(log, p, x0, o);
        }
        return to_array(out);
      },
      py::arg("torque_nm"), py::kw_only(), py::arg("sample_period_s"), py::arg("measured_is_speed"),
      py::arg("measured_on_load"), py::arg("model"), py::arg("parameters"), py::arg("initial_state"),
      "The identification model run open loop over a torque log (the code the fit differentiates, on double). "
      "Options: TimeFitOptions field names (substeps, current_bw_hz, stribeck_exponent).");

  m.def(
      "identify_frequency",
      [](const py::object& axis, const py::handle& freq_hz, const py::handle& response, const py::handle& weight,
         const std::string& model, const py::handle& initial, const std::vector<Flag>& fixed, const py::handle& lower,
         const py::handle& upper, const identify::FrequencyFitOptions& options, const py::object& progress,
         const py::object& io) {
        identify::FrequencyData data;
        data.freq_hz = real_vector(freq_hz, "freq_hz");
        data.response = complex_vector(response, "response");
        data.weight = real_vector(weight, "weight");
        identify::FrequencyFitOptions o = options;
        o.model = model_of(model);
        o.validate();
        std::shared_ptr<py::error_already_set> interrupt;
        o.progress = iteration_callback(progress, &interrupt);
        const identify::ParameterSetup s = setup_of(initial, fixed, lower, upper);
        identify::FrequencyFitResult r;
        const bool with_axis = !axis.is_none();
        machine::AxisConfig config;
        identify::MechanicsIO mio;
        if (with_axis) {
          config = axis.cast<const machine::Axis&>().config();
        } else {
          mio = mechanics_io_from(io);
        }
        try {
          py::gil_scoped_release release;
          r = with_axis ? identify::fit_frequency_response(config, data, s, o)
                        : identify::fit_frequency_response(mio, data, s, o);
        } catch (const SolveInterrupted&) {
        }
        raise_pending(interrupt);
        py::dict d;
        d["parameters"] = estimates(r.parameters);
        d["summary"] = summary(r.summary);
        d["predicted"] = to_array(r.predicted);
        return d;
      },
      py::arg("axis"), py::arg("freq_hz"), py::arg("response"), py::kw_only(), py::arg("weight"), py::arg("model"),
      py::arg("initial"), py::arg("fixed"), py::arg("lower"), py::arg("upper"), py::arg("options"),
      py::arg("progress") = py::none(), py::arg("io") = py::none(),
      "Frequency-domain fit of the plant to a measured Y/U: U counts -> Y pulse of `axis`, or (axis None) the "
      "mechanics described by `io` (MechanicsIO field names). Releases the GIL.");
}

}  // namespace servobench::bindings
