#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <functional>
#include <cmath>
#include <string>
#include <vector>

#include "servobench/common/validate.hpp"
#include "servobench/machine/axis.hpp"
#include "arrays.hpp"
#include "object_lock.hpp"
#include "flag.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Axis;
using machine::AxisConfig;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using ExternalLaw = std::function<double(std::size_t, double, double)>;
using CompiledLaw = double (*)(std::int64_t, double, double, double*);

const std::vector<std::string>& signal_names() {
  static const std::vector<std::string> names = {
#define SERVOBENCH_NAME(name, unit, doc) #name,
      SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_NAME)
#undef SERVOBENCH_NAME
  };
  return names;
}

double** trace_slot(machine::Trace& t, const std::string& name) {
#define SERVOBENCH_SLOT(n, unit, doc) \
  if (name == #n) return &t.n;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_SLOT)
#undef SERVOBENCH_SLOT
  return nullptr;
}

machine::PlantParams plant_from(const py::handle& p) {
  if (py::isinstance<plant::RigidPlantParams>(p)) return p.cast<plant::RigidPlantParams>();
  if (py::isinstance<plant::TwoMassPlantParams>(p)) return p.cast<plant::TwoMassPlantParams>();
  if (py::isinstance<plant::LtiPlantParams>(p)) return p.cast<plant::LtiPlantParams>();
  throw py::type_error("plant must be a RigidPlant, a TwoMassPlant or an LtiPlant, got " + py::str(py::type::of(p)).cast<std::string>());
}

machine::DriveParams drive_from(const py::handle& d) {
  if (py::isinstance<drive::TorqueDriveParams>(d)) return d.cast<drive::TorqueDriveParams>();
  if (py::isinstance<drive::VelocityDriveParams>(d)) return d.cast<drive::VelocityDriveParams>();
  if (py::isinstance<drive::StepperDriveParams>(d)) return d.cast<drive::StepperDriveParams>();
  if (py::isinstance<drive::ServoPositionDriveParams>(d)) return d.cast<drive::ServoPositionDriveParams>();
  throw py::type_error("drive must be a TorqueDrive, VelocityDrive, StepperDrive or ServoPositionDrive, got " +
                       py::str(py::type::of(d)).cast<std::string>());
}

machine::LawParams law_from(const py::handle& law) {
  if (py::isinstance<control::GtServoLawParams>(law)) return law.cast<control::GtServoLawParams>();
  if (py::isinstance<control::ApsServoLawParams>(law)) return law.cast<control::ApsServoLawParams>();
  throw py::type_error("law must be a GtServoLaw or an ApsServoLaw, got " + py::str(py::type::of(law)).cast<std::string>());
}

control::BiquadParams filter_from(const py::handle& f, std::size_t index) {
  if (f.is_none()) return control::AdlinkBiquadParams{};
  if (py::isinstance<control::FloatBiquadParams>(f)) return f.cast<control::FloatBiquadParams>();
  if (py::isinstance<control::AdlinkBiquadParams>(f)) return f.cast<control::AdlinkBiquadParams>();
  throw py::type_error("filters[" + std::to_string(index) + "] must be None, a FloatBiquad or an AdlinkBiquad, got " +
                       py::str(py::type::of(f)).cast<std::string>());
}

std::array<control::BiquadParams, 2> filters_from(const py::object& filters) {
  std::array<control::BiquadParams, 2> out{control::AdlinkBiquadParams{}, control::AdlinkBiquadParams{}};
  if (filters.is_none()) return out;
  if (!py::isinstance<py::sequence>(filters) || py::isinstance<py::str>(filters))
    throw py::type_error("filters must be a pair (filter 0, filter 1), each None, a FloatBiquad or an AdlinkBiquad");
  const py::sequence seq = filters;
  if (seq.size() != 2)
    throw py::value_error("filters must hold exactly 2 entries (biquad 0, biquad 1; ADLINK L1735), got " +
                          std::to_string(seq.size()));
  for (std::size_t i = 0; i < 2; ++i) out[i] = filter_from(seq[i], i);
  return out;
}

py::tuple filters_to_python(const std::array<control::BiquadParams, 2>& filters) {
  return py::make_tuple(std::visit([](const auto& p) { return py::cast(p); }, filters[0]),
                        std::visit([](const auto& p) { return py::cast(p); }, filters[1]));
}

// The trace with every recording pointer moved `k` samples on (a chunk of a run starting at tick k).
machine::Trace offset_trace(machine::Trace t, std::size_t k) {
#define SERVOBENCH_SHIFT(n, unit, doc) \
  if (t.n) t.n += k;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return t;
}

// The input arrays of a run, checked finite block by block right before each block runs (decisions SP5, SQ1): a
// block's inputs (kCheckBlock ticks, 64 KiB per array) are then still in the core's cache when the tick loop reads
// them, so the check adds no pass over memory.
struct RunInput {
  const char* name;
  const double* data;
};
constexpr std::size_t kCheckBlock = 8192;
// True if every sample of d[0, n) is finite. A double is not finite exactly when its 11 exponent bits are all ones;
// then (bits & exponent) + 2^52 carries into bit 63, else bit 63 stays clear. Integer and/add/or vectorise with SSE2
// (a compare per sample feeding a flag does not), so the check runs at the speed of the cache.
bool all_finite(const double* d, std::size_t n) {
  constexpr std::uint64_t kExponent = 0x7FF0000000000000ULL, kUnit = std::uint64_t{1} << 52;
  std::uint64_t any = 0;
  for (std::size_t k = 0; k < n; ++k) {
    std::uint64_t bits;
    std::memcpy(&bits, d + k, sizeof bits);
    any |= (bits & kExponent) + kUnit;
  }
  return (any >> 63) == 0;
}
// Throws std::invalid_argument (ValueError) naming the first non-finite sample of [from, to), if any.
void check_finite(const std::vector<RunInput>& inputs, std::size_t from, std::size_t to) {
  for (const RunInput& in : inputs) {
    if (in.data == nullptr || all_finite(in.data + from, to - from)) continue;
    for (std::size_t k = from; k < to; ++k)
      if (!std::isfinite(in.data[k]))
        throw std::invalid_argument(std::string(in.name) + "[" + std::to_string(k) + "] = " +
                                    format_value(in.data[k]) + " is not a finite number");
  }
}

// Runs the axis in chunks of about 20 ms of work, each under the axis's state lock, checking for Ctrl-C between
// chunks (object_lock.hpp); the axis keeps its state between chunks, so the result is the one-call result.
// chunk_start (optional): set to the run's tick index at which each block starts, for a per-tick hook that needs
// the index in the whole run.
// inputs: checked block by block; a non-finite sample found after some ticks ran puts the axis back as `undo` (the
// caller's copy from before the call) or as it stood when the run began, then raises: a run with a bad input never
// changes the axis.
machine::RunOutcome run_chunked(Axis& axis, const machine::CommandInput& in, const machine::Trace& trace,
                                const machine::RunGuard& guard, std::size_t* chunk_start = nullptr,
                                const std::vector<RunInput>& inputs = {}, const Axis* undo = nullptr) {
  RunLock lock({&axis});
  py::gil_scoped_release release;
  ChunkClock clock;
  std::optional<Axis> snapshot;
  if (!inputs.empty() && undo == nullptr && in.n > std::min(clock.size(), kCheckBlock)) {  // more than one block
    auto held = lock.chunk();
    snapshot.emplace(axis);
    undo = &*snapshot;
  }
  machine::RunOutcome outcome;
  std::size_t done = 0;
  bool stopped = false;
  const bool check_after = !inputs.empty() && in.external == nullptr && undo != nullptr;
  while (done < in.n && !stopped) {
    const std::size_t chunk_end = done + std::min(clock.size(), in.n - done);
    {
      auto held = lock.chunk();
      clock.start();
      // The chunk in blocks (decision SQ1). Each block's inputs are checked where that costs no pass over memory:
      // right after the law's tick loop read them (they are in cache), when there is an undo copy to go back to;
      // before the block otherwise (a short run without one, and a compiled controller, which must never see a bad
      // sample). Either way a bad sample in a block that is reached raises, the axis as it was before the call.
      while (done < chunk_end) {
        machine::CommandInput c = in;
        c.n = std::min(inputs.empty() ? chunk_end - done : kCheckBlock, chunk_end - done);
        const auto check = [&] {
          try {
            check_finite(inputs, done, done + c.n);
          } catch (const std::invalid_argument&) {
            if (undo != nullptr) axis = *undo;  // without `undo` nothing ran yet (a run of one block at most)
            throw;
          }
        };
        if (!check_after) check();
        c.pos += done;
        if (c.vel) c.vel += done;
        if (c.acc) c.acc += done;
        if (c.volts_add) c.volts_add += done;
        if (chunk_start) *chunk_start = done;  // the per-tick hook's index in the whole run: chunk_start + its own
        const machine::RunOutcome o = axis.run(c, offset_trace(trace, done), guard);
        if (check_after) check();
        done += o.ticks;
        if (o.stop != machine::RunStop::kCompleted) {
          outcome = o;
          stopped = true;
          break;
        }
      }
      clock.stop();
    }
    if (!stopped && done < in.n) check_signals();
  }
  outcome.ticks = done;
  return outcome;
}

// A run's input array: 1-D, `expected` samples (-1: any); its finiteness is checked by check_finite.
Array shaped_array(const py::handle& obj, const char* name, py::ssize_t expected) {
  Array a = Array::ensure(obj);
  if (!a) throw py::type_error(std::string(name) + " must be a 1-D array of numbers");
  if (a.ndim() != 1) throw py::value_error(std::string(name) + " must be 1-D, got " + std::to_string(a.ndim()) + " dimensions");
  if (expected >= 0 && a.shape(0) != expected)
    throw py::value_error(std::string(name) + " has " + std::to_string(a.shape(0)) + " samples; expected " +
                          std::to_string(expected) + " (one per tick, like the positions)");
  return a;
}

// A user controller's voltage request must be a number: NaN or inf would enter the DAC and the plant's state.
double finite_request(double volts, std::size_t tick) {
  if (!std::isfinite(volts))
    throw py::value_error("controller returned " + format_value(volts) + " V at tick " + std::to_string(tick) +
                          " of the run: it must return a finite voltage request");
  return volts;
}

// The tick count of Axis.step: a whole number >= 1 (an int or anything with __index__, not a bool).
std::size_t step_ticks(py::handle n) {
  if (PyLong_CheckExact(n.ptr())) {
    const long long v = PyLong_AsLongLong(n.ptr());
    if (v >= 1) return static_cast<std::size_t>(v);
    PyErr_Clear();  // an overflow
  } else if (!PyBool_Check(n.ptr()) && PyIndex_Check(n.ptr())) {
    const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(n.ptr()));
    if (!i) throw py::error_already_set();
    const long long v = PyLong_AsLongLong(i.ptr());
    if (v >= 1) return static_cast<std::size_t>(v);
    PyErr_Clear();
  }
  throw py::value_error("n = " + py::repr(n).cast<std::string>() + " must be a whole number >= 1 (ticks)");
}

// Axis.step, the step API (issue 22.2): the checks, the object's locks and the ticks in one binding, so a call
// costs one pybind11 dispatch (decision FV10). A few ticks run under the state lock with the GIL held, as every
// other method (object_lock.hpp); from kLongStep ticks on the call is a run: the run lock for the whole call, the
// GIL released and Ctrl-C checked between chunks of about 20 ms, the state lock for each chunk.
double axis_step(Axis& a, double command_pulse, py::handle n_obj, py::handle volts_obj) {
  constexpr std::size_t kLongStep = 1024;
  if (!std::isfinite(command_pulse)) throw_invalid("Axis.step", "command_pulse", command_pulse, "must be a finite number (pulse)");
  const std::size_t n = step_ticks(n_obj);
  std::optional<ExternalLaw> ext;
  if (!volts_obj.is_none()) {
    const double v = volts_obj.cast<double>();
    if (!std::isfinite(v)) throw_invalid("Axis.step", "volts", v, "must be a finite number (V)");
    ext.emplace([v](std::size_t, double, double) { return v; });
  }
  const ExternalLaw* law = ext ? &*ext : nullptr;
  if (n < kLongStep) {
    auto lk = lock_releasing_gil(locks_of(&a)->state);
    return a.step(command_pulse, n, law);
  }
  double fb = 0.0;
  run_in_chunks({&a}, n, [&](std::size_t k) { fb = a.step(command_pulse, k, law); });
  return fb;
}

}  // namespace

void bind_machine(py::module_& m) {
  py::list meta;
#define SERVOBENCH_META(name, unit, doc) meta.append(py::make_tuple(#name, unit, doc));
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_META)
#undef SERVOBENCH_META
  m.attr("TRACE_SIGNALS") = meta;
  m.def("tick_kernel", [] { return std::string(machine::tick_kernel_name(machine::auto_tick_kernel())); },
        "The fused tick's kernel that Axis.run uses on this CPU: 'avx512', 'avx2', 'sse4.1' or 'portable' (decisions "
        "SP1, FV20)");

  py::class_<Axis> axis_cls(m, "Axis", "One simulated servo axis (C++ core). Use servobench.Axis.");
  axis_cls.def(py::init([](const py::object& law, const py::object& drv, const py::object& plant,
                       const plant::EncoderParams& enc, const drive::DacParams& dac, const plant::SwitchParams& sw,
                       std::optional<double> servo_period_s, double substeps, const py::object& filters) {
             check_integer("Axis", "substeps", substeps, 1, 1000);
             AxisConfig c;
             c.law = law_from(law);
             c.drive = drive_from(drv);
             c.plant = plant_from(plant);
             c.encoder = enc;
             c.switches = sw;
             c.dac = dac;
             c.servo_period_s = servo_period_s;
             c.substeps = static_cast<int>(substeps);
             c.filters = filters_from(filters);
             return Axis(c);
           }),
           py::kw_only(), py::arg("law"), py::arg("drive"), py::arg("plant"), py::arg("encoder"), py::arg("dac"),
           py::arg("switches"), py::arg("servo_period_s") = py::none(), py::arg("substeps") = 1.0,
           py::arg("filters") = py::none())
      .def("reset", [](Axis& a, double angle_rad) {
             check_range("Axis.reset", "angle_rad", angle_rad, -1e6, 1e6);
             a.reset(angle_rad);
           }, py::arg("angle_rad") = 0.0)
      .def("reset_state", &Axis::reset_state, py::arg("angle_rad"), py::arg("speed_rad_s"), py::arg("load_angle_rad"),
           py::arg("load_speed_rad_s"))
      .def("set_law", [](Axis& a, const py::object& law) { a.set_law(law_from(law)); }, py::arg("law"))
      .def_property_readonly("law", [](const Axis& a) -> py::object {
        return std::visit([](const auto& p) { return py::cast(p); }, a.config().law);
      })
      .def_property_readonly("drive", [](const Axis& a) -> py::object {
        return std::visit([](const auto& p) { return py::cast(p); }, a.config().drive);
      })
      .def_property_readonly("plant", [](const Axis& a) -> py::object {
        return std::visit([](const auto& p) { return py::cast(p); }, a.config().plant);
      })
      .def_property_readonly("switches", [](const Axis& a) { return a.config().switches; })
      .def("set_filters", [](Axis& a, const py::object& f) { a.set_filters(filters_from(f)); }, py::arg("filters"))
      .def_property_readonly("filters", [](const Axis& a) { return filters_to_python(a.config().filters); })
      .def_property_readonly("encoder", [](const Axis& a) { return a.config().encoder; })
      .def_property_readonly("dac", [](const Axis& a) { return a.config().dac; })
      .def_property_readonly("servo_period_s", &Axis::servo_period_s)
      .def_property_readonly("substeps", [](const Axis& a) { return a.config().substeps; })
      .def_property_readonly("tick", &Axis::tick)
      .def_property_readonly("feedback_pulse", &Axis::feedback_pulse)
      .def_property_readonly("angle_rad", &Axis::angle_rad)
      .def_property_readonly("speed_rad_s", &Axis::speed_rad_s)
      .def_property_readonly("load_angle_rad", &Axis::load_angle_rad)
      .def_property_readonly("load_speed_rad_s", &Axis::load_speed_rad_s)
      .def_property_readonly("alarm", &Axis::alarm)
      .def_property_readonly("substeps_per_tick", [](const Axis& a) { return a.power_train().substeps_per_tick(); })
      .def_property_readonly("mechanical_energy_j", [](const Axis& a) { return a.power_train().mechanical_energy_j(); })
      .def_property_readonly("servo_on", &Axis::servo_on)
      .def("set_servo_on", strict(&Axis::set_servo_on), py::arg("on"))
      .def("copy", [](const Axis& a) { return Axis(a); },
           "A copy of this axis: configuration and the whole state (law memories, filters, power train, encoder noise "
           "generator), so the copy runs the same ticks")
      .def("set_fused_tick", strict(&Axis::set_fused_tick), py::arg("on"),
           "True (default): the fused per-configuration tick where it applies; False: the general loop (for tests)")
      .def("set_tick_kernel", [](Axis& a, const std::string& kernel) {
             for (auto k : {machine::TickKernel::kAuto, machine::TickKernel::kPortable, machine::TickKernel::kSse41,
                            machine::TickKernel::kAvx512, machine::TickKernel::kAvx2})
               if (kernel == machine::tick_kernel_name(k)) return a.set_tick_kernel(k);
             throw py::value_error("Axis.set_tick_kernel: kernel = '" + kernel +
                                   "' must be 'auto', 'portable', 'sse4.1', 'avx2' or 'avx512'");
           }, py::arg("kernel"),
           "The fused tick's kernel: 'auto' (default: the fastest this CPU runs), 'portable', 'sse4.1', 'avx2' or "
           "'avx512' (ValueError if this CPU lacks its instructions); all give the same doubles (for tests and "
           "benchmarks)")
      .def_property_readonly("last_command_pulse", &Axis::last_command_pulse)
      .def(
          "run",
          [](Axis& axis, const py::object& pos, const py::object& vel, const py::object& acc, const py::object& signals,
             const py::object& injection, double error_limit, Flag stop_on_alarm, const py::object& controller,
             std::uintptr_t controller_address, const py::object& controller_state, const py::object& undo) {
            // Shapes now; finiteness chunk by chunk as the run goes (run_chunked), or all first for a Python
            // controller's one-piece run.
            Array p = shaped_array(pos, "positions", -1);
            const py::ssize_t n = p.shape(0);
            Array v, a, inj;
            machine::CommandInput in;
            in.pos = p.data();
            in.n = static_cast<std::size_t>(n);
            if (!vel.is_none()) {
              v = shaped_array(vel, "velocities", n);
              in.vel = v.data();
            }
            if (!acc.is_none()) {
              a = shaped_array(acc, "accelerations", n);
              in.acc = a.data();
            }
            if (!injection.is_none()) {
              inj = shaped_array(injection, "injection_v", n);
              in.volts_add = inj.data();
            }
            check_range("Axis.run", "error_limit_pulse", error_limit, 0, 1e15, "0 = off");
            machine::RunGuard guard;
            guard.error_limit_pulse = error_limit;
            guard.stop_on_alarm = stop_on_alarm;
            std::vector<std::string> wanted;
            if (signals.is_none()) {
              wanted = signal_names();
            } else {
              for (const auto& s : signals) wanted.push_back(py::str(s));
            }
            if (static_cast<double>(n) * static_cast<double>(wanted.size()) * 8.0 > kMaxRecordBytes)
              throw py::value_error("Axis.run.positions: " + std::to_string(n) + " ticks x " +
                                    std::to_string(wanted.size()) + " signals would record " +
                                    format_value(static_cast<double>(n) * static_cast<double>(wanted.size()) * 8e-9) +
                                    " GB, above the 2 GB a run may record; record fewer signals or run in pieces");
            machine::Trace trace;
            py::dict out;
            for (const auto& name : wanted) {
              double** slot = trace_slot(trace, name);
              if (slot == nullptr) {
                std::string all;
                for (const auto& s : signal_names()) all += (all.empty() ? "" : ", ") + s;
                throw py::value_error("signals: unknown signal '" + name + "'; the signals are: " + all);
              }
              py::array_t<double> buf = output_array(n);  // decision SP3
              *slot = buf.mutable_data();
              out[py::str(name)] = buf;
            }
            // A user's controller in place of the law: a Python callable (called with the GIL, per tick) or a
            // compiled C function double(int64 tick, double cmd_pulse, double fb_pulse, double* state). The
            // compiled one runs in chunks like the law (run_chunked); `chunk_start` turns the chunk's tick index
            // back into the index in this run.
            ExternalLaw ext;
            Array state;
            std::size_t chunk_start = 0;
            if (!controller.is_none()) {
              ext = [&controller](std::size_t k, double r, double y) {
                return finite_request(controller(k, r, y).cast<double>(), k);
              };
              in.external = &ext;
            } else if (controller_address != 0) {
              double* st = nullptr;
              if (!controller_state.is_none()) {
                state = Array::ensure(controller_state);
                if (!state || !py::isinstance<py::array>(controller_state) || state.ptr() != controller_state.ptr())
                  throw py::type_error("controller_state must be a C-contiguous float64 NumPy array (it is updated in place)");
                st = state.mutable_data();
              }
              const auto fn = reinterpret_cast<CompiledLaw>(controller_address);
              ext = [fn, st, &chunk_start](std::size_t k, double r, double y) {
                const std::size_t tick = chunk_start + k;
                return finite_request(fn(static_cast<std::int64_t>(tick), r, y, st), tick);
              };
              in.external = &ext;
            }
            const std::vector<RunInput> inputs{{"positions", in.pos}, {"velocities", in.vel},
                                               {"accelerations", in.acc}, {"injection_v", in.volts_add}};
            const Axis* undo_axis = undo.is_none() ? nullptr : &undo.cast<const Axis&>();
            machine::RunOutcome outcome;
            if (!controller.is_none()) {
              // The Python controller needs the GIL every tick: one piece, under the run lock; Ctrl-C surfaces
              // as the KeyboardInterrupt the controller's own Python code raises.
              try {
                check_finite(inputs, 0, in.n);
              } catch (const std::invalid_argument&) {
                if (undo_axis != nullptr) axis = *undo_axis;
                throw;
              }
              RunLock lock({&axis});
              auto held = lock_releasing_gil(locks_of(&axis)->state);
              outcome = axis.run(in, trace, guard);
            } else {
              outcome = run_chunked(axis, in, trace, guard, &chunk_start, inputs, undo_axis);
            }
            const char* stop = outcome.stop == machine::RunStop::kCompleted  ? ""
                               : outcome.stop == machine::RunStop::kErrorLimit ? "error_limit"
                                                                               : "drive_alarm";
            if (outcome.ticks < static_cast<std::size_t>(n)) {
              py::dict cut;
              for (auto item : out) cut[item.first] = item.second.cast<py::array_t<double>>()[py::slice(
                  0, static_cast<py::ssize_t>(outcome.ticks), 1)];
              out = cut;
            }
            return py::make_tuple(out, stop, outcome.error_pulse);
          },
          py::arg("positions"), py::arg("velocities") = py::none(), py::arg("accelerations") = py::none(),
          py::arg("signals") = py::none(), py::arg("injection_v") = py::none(), py::arg("error_limit_pulse") = 0.0,
          py::arg("stop_on_alarm") = false, py::arg("controller") = py::none(), py::arg("controller_address") = 0,
          py::arg("controller_state") = py::none(), py::arg("undo") = py::none(),
          "Runs one tick per position (pulse); returns ({signal: array}, stop reason or '', error at the stop). "
          "A non-finite input sample raises ValueError with the axis as `undo` (a copy of it from before the call) "
          "or, without one, as it stood when the run began. "
          "Releases the GIL (not with a Python controller); one run at a time per axis (a second thread waits); "
          "Ctrl-C raises KeyboardInterrupt within about 20 ms, the axis standing at the last whole tick run.")
      .def("step", &axis_step, py::arg("command_pulse"), py::arg("n") = 1, py::kw_only(), py::arg("volts") = py::none(),
           "Advances n ticks (default 1) holding command_pulse (pulse), the law's output replaced by `volts` (V) if "
           "given; returns the feedback read at the last tick, pulse. Nothing is recorded.");
  serialise_methods(axis_cls, {"run", "step"});  // step takes the locks itself (axis_step)
}

}  // namespace servobench::bindings
