#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>

#include "arrays.hpp"
#include "param_class.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/gear.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/s_curve.hpp"
#include "servobench/motion/t_curve.hpp"
#include "servobench/motion/trapezoid.hpp"

namespace servobench::bindings {

namespace py = pybind11;


void bind_motion(py::module_& m) {
  using namespace motion;
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

  py::register_exception<MotionCommandRefused>(m, "MotionCommandRefused", PyExc_RuntimeError);

  ParamClass<GtTCurveParams>(m, "GtTCurve",
      "GT_PrflT point-to-point T-curve (GT manual L914-978), units per sample time ST (the tick): pos pulse,\n"
      "vel pulse/ST, acc pulse/ST^2 (one value for acceleration and deceleration).")
      .field("pos", &GtTCurveParams::pos, "target position, whole pulses, -1073741824..1073741823 (L854)")
      .field("vel", &GtTCurveParams::vel, "velocity, pulse/ST, 0 < vel <= 16384 (L930)")
      .field("acc", &GtTCurveParams::acc, "acceleration, pulse/ST^2, 0 < acc <= 16384 (L929)")
      .finish();
  ParamClass<GtSCurveParams>(m, "GtSCurve",
      "GT_PrflS point-to-point S-curve (GT manual L839-912), units per ST: pos pulse, vel pulse/ST,\n"
      "macc pulse/ST^2, jerk pulse/ST^3. Seven phases, missing phases allowed, symmetric.")
      .field("pos", &GtSCurveParams::pos, "target position, whole pulses, -1073741824..1073741823 (L854)")
      .field("vel", &GtSCurveParams::vel, "velocity, pulse/ST, 0 < vel <= 16384 (L858)")
      .field("macc", &GtSCurveParams::macc, "maximum acceleration, pulse/ST^2, 0 < macc < 0.5 (L857)")
      .field("jerk", &GtSCurveParams::jerk, "jerk, pulse/ST^3, 0 < jerk < 0.5 (L856)")
      .finish();
  ParamClass<GtJogParams>(m, "GtJog",
      "GT_PrflV jog / velocity mode (GT manual L980-1027): vel pulse/ST (signed), acc pulse/ST^2.")
      .field("vel", &GtJogParams::vel, "velocity, pulse/ST, -16384..16384; the sign is the direction (L994)")
      .field("acc", &GtJogParams::acc, "acceleration, pulse/ST^2, 0 < acc <= 16384 (L995)")
      .finish();
  ParamClass<GeTCurveParams>(m, "GeTCurve",
      "GE / GUC-ECAT / iDEABOX GT_PrflT T-curve (GE manual L978-1079) in pulse/ms units: pos pulse,\n"
      "vel pulse/ms, acc pulse/ms^2.")
      .field("pos", &GeTCurveParams::pos, "target position, whole pulses, -1073741824..1073741823")
      .field("vel", &GeTCurveParams::vel, "velocity, pulse/ms, 0 < vel <= 40957 (L991-996)")
      .field("acc", &GeTCurveParams::acc, "acceleration, pulse/ms^2, 0 < acc <= 102400 (L991-996)")
      .finish();
  ParamClass<GeSCurveParams>(m, "GeSCurve",
      "GE / GUC-ECAT / iDEABOX GT_PrflS S-curve (GE manual L1081-1188) in pulse/ms units.")
      .field("pos", &GeSCurveParams::pos, "target position, whole pulses, -1073741824..1073741823")
      .field("vel", &GeSCurveParams::vel, "velocity, pulse/ms, 0 < vel <= 40957 (L1095-1101)")
      .field("macc", &GeSCurveParams::macc, "maximum acceleration, pulse/ms^2, 0 < macc <= 102400")
      .field("jerk", &GeSCurveParams::jerk, "jerk, pulse/ms^3, 0 < jerk <= 256000")
      .finish();
  ParamClass<GeJogParams>(m, "GeJog", "GE GT_PrflV velocity mode (GE manual L1190-1266) in pulse/ms units.")
      .field("vel", &GeJogParams::vel, "velocity, pulse/ms, -40958..40957 (L1202-1206)")
      .field("acc", &GeJogParams::acc, "acceleration, pulse/ms^2, 0 < acc <= 102400")
      .finish();
  ParamClass<AdlinkPtpParams>(m, "AdlinkPtp",
      "ADLINK APS_ptp_all point-to-point move (ADLINK manual L2176-2244, L2712-2767) in pulse/s units (unit\n"
      "factor 1): starts at vs, ramps at acc to vm, cruises, ramps at dec to ve. sf = S-factor t1/(t1+t2):\n"
      "0 = T-curve, 1 = pure S. Short moves keep acc, dec and sf and lower the peak velocity (the jerk changes).")
      .field("pos", &AdlinkPtpParams::pos, "target position, pulse, ``|pos| <= 2147483647``")
      .field("vs", &AdlinkPtpParams::vs, "PRA_VS start velocity, pulse/s, 0..vm")
      .field("vm", &AdlinkPtpParams::vm, "PRA_VM maximum velocity, pulse/s, 0 < vm <= 1e9")
      .field("ve", &AdlinkPtpParams::ve, "PRA_VE end velocity, pulse/s, 0..vm")
      .field("acc", &AdlinkPtpParams::acc, "PRA_ACC peak acceleration, pulse/s^2, 0 < acc <= 1e12")
      .field("dec", &AdlinkPtpParams::dec, "PRA_DEC peak deceleration, pulse/s^2, 0 < dec <= 1e12")
      .field("sf", &AdlinkPtpParams::sf, "PRA_SF S-factor, 0..1")
      .field("sd_dec", &AdlinkPtpParams::sd_dec, "PRA_SD_DEC stop_move deceleration, pulse/s^2, 0 (= dec)..1e12")
      .finish();

  py::class_<ProfileGenerator>(m, "ProfileGenerator",
      "One axis's profile generator, stepped once per tick (tick = period_s seconds). Internal units: pulse and\n"
      "ticks; GT parameters are per tick, GE/GUC/iDEABOX parameters pulse/ms and ADLINK pulse/s are converted with\n"
      "period_s. Positions are kept fractional inside; `reported_pos` is the whole pulse a card reports.\n"
      "Commands during motion follow the manuals (T-curve: target and velocity; S-curve: target only; jog:\n"
      "velocity and acceleration); refused commands raise MotionCommandRefused (a RuntimeError).")
      .def(py::init<double, double>(), py::kw_only(), py::arg("start_pos") = 0.0, py::arg("period_s") = 200e-6)
      .def("command", py::overload_cast<const GtTCurveParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const GtSCurveParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const GtJogParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const GeTCurveParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const GeSCurveParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const GeJogParams&>(&ProfileGenerator::command), py::arg("params"))
      .def("command", py::overload_cast<const AdlinkPtpParams&>(&ProfileGenerator::command), py::arg("params"),
           "Start a move (or change it on the fly where the manual allows): the card's Set* + Update.")
      .def("adlink_velocity", &ProfileGenerator::adlink_velocity, py::arg("vel_pulse_per_s"), py::arg("params"),
           "ADLINK APS_vel: ramp to the signed velocity (pulse/s) with params' acc, dec, sf; hold it.")
      .def("adlink_stop_move", &ProfileGenerator::adlink_stop_move, py::arg("params"),
           "ADLINK APS_stop_move: decelerate at sd_dec (pulse/s^2) with params' S-factor.")
      .def("smooth_stop", &ProfileGenerator::smooth_stop,
           "Decelerate to rest at the current mode's limits (GT_SmthStp).")
      .def("abrupt_stop", &ProfileGenerator::abrupt_stop, "Velocity zero at once, position holds (GT_AbptStp).")
      .def("set_position", &ProfileGenerator::set_position, py::arg("pos"),
           "Set the profile position, pulse; only at rest (GT_SetAtlPos, GT_ZeroPos).")
      .def("step", [](ProfileGenerator& g) { return state_tuple(g.step()); },
           "Advance one tick; returns (pos pulse, vel pulse/tick, acc pulse/tick^2, jerk pulse/tick^3).")
      .def("run", [](ProfileGenerator& g, double ticks) { return run_ticks("ProfileGenerator.run", ticks, false, [&]() -> const motion::MotionState& { return g.step(); }, [&] { return g.moving(); }, [&] { return g.reported_pos(); }); }, py::arg("ticks"),
           "Step `ticks` times; dict of arrays pos (whole pulses), pos_exact (pulse), vel (pulse/tick),\n"
           "acc (pulse/tick^2), jerk (pulse/tick^3), one sample per tick after each step.")
      .def("run_until_done", [](ProfileGenerator& g, double max_ticks) { return run_ticks("ProfileGenerator.run", max_ticks, true, [&]() -> const motion::MotionState& { return g.step(); }, [&] { return g.moving(); }, [&] { return g.reported_pos(); }); },
           py::arg("max_ticks") = 1e8, "As run(), stopping when the motion has ended.")
      .def_property_readonly("state", [](const ProfileGenerator& g) { return state_tuple(g.state()); },
                             "(pos pulse, vel pulse/tick, acc pulse/tick^2, jerk pulse/tick^3) now")
      .def_property_readonly("reported_pos", &ProfileGenerator::reported_pos, "profile position, whole pulses")
      .def_property_readonly("moving", &ProfileGenerator::moving)
      .def_property_readonly("stopping", &ProfileGenerator::stopping)
      .def_property_readonly("mode", [](const ProfileGenerator& g) { return std::string(to_string(g.mode())); })
      .def_property_readonly("period_s", &ProfileGenerator::period_s)
      .def_property_readonly("duration_ticks", [](const ProfileGenerator& g) { return g.profile().duration(); },
                             "duration of the current profile in ticks (inf for a jog)")
      .def("__repr__", [](const ProfileGenerator& g) {
        return "ProfileGenerator(mode=" + std::string(to_string(g.mode())) + ", pos=" + format_value(g.state().pos) +
               ", vel=" + format_value(g.state().vel) + " pulse/tick, moving=" + (g.moving() ? "True" : "False") + ")";
      });

  ParamClass<GtGearParams>(m, "GtGear",
      "GT_PrflG(master) + GT_SetRatio electronic gear (GT manual L1029-1090): slave increment = ratio x master\n"
      "increment.")
      .field("master", &GtGearParams::master, "master: 1-4 axes, 5-6 auxiliary encoders (L1042)",
             GtGearParams::kMasterRange)
      .field("ratio", &GtGearParams::ratio, "gear ratio, -16384..16384; negative reverses (L1043)")
      .finish();
  py::class_<ElectronicGear>(m, "ElectronicGear",
      "Electronic gear slave (GT L1029-1090), stepped once per tick with the master's whole-pulse position.\n"
      "Drift-free: slave = base + ratio * (master - master_base); the fraction of a pulse stays inside.")
      .def(py::init<double, long long, double>(), py::kw_only(), py::arg("ratio"), py::arg("master_pos") = 0,
           py::arg("slave_pos") = 0.0)
      .def("set_ratio", &ElectronicGear::set_ratio, py::arg("ratio"), py::arg("master_pos"),
           "Change the ratio from now on, rebasing at master_pos (pulse): no jump.")
      .def("step", [](ElectronicGear& g, long long master_pos) { return state_tuple(g.step(master_pos)); },
           py::arg("master_pos"), "One tick: returns (pos pulse, vel pulse/tick, acc pulse/tick^2, jerk).")
      .def("follow", [](ElectronicGear& g, py::array_t<long long, py::array::c_style | py::array::forcecast> master) {
             py::array_t<double> out(master.size());
             {
               // GIL held: one thread per gear
               for (py::ssize_t i = 0; i < master.size(); ++i) {
                 g.step(master.data()[i]);
                 out.mutable_data()[i] = static_cast<double>(g.reported_pos());
               }
             }
             return out;
           }, py::arg("master_pos"), "Steps once per master sample (whole pulses); returns the slave's whole pulses.")
      .def_property_readonly("ratio", &ElectronicGear::ratio)
      .def_property_readonly("reported_pos", &ElectronicGear::reported_pos)
      .def_property_readonly("remainder", &ElectronicGear::remainder, "fraction of a pulse not yet reported")
      .def_property_readonly("state", [](const ElectronicGear& g) { return state_tuple(g.state()); });

  m.def(
      "plan_s_curve_batch",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> start,
         py::array_t<double, py::array::c_style | py::array::forcecast> target,
         py::array_t<double, py::array::c_style | py::array::forcecast> vel,
         py::array_t<double, py::array::c_style | py::array::forcecast> acc,
         py::array_t<double, py::array::c_style | py::array::forcecast> jerk) {
        const auto n = start.size();
        if (target.size() != n || vel.size() != n || acc.size() != n || jerk.size() != n)
          throw std::invalid_argument("plan_s_curve_batch: start, target, vel, acc and jerk must have equal lengths");
        for (py::ssize_t i = 0; i < n; ++i) {
          if (!(vel.data()[i] > 0) || !(acc.data()[i] > 0) || !(jerk.data()[i] > 0) || !std::isfinite(vel.data()[i]) ||
              !std::isfinite(acc.data()[i]) || !std::isfinite(jerk.data()[i]))
            throw std::invalid_argument("plan_s_curve_batch: vel, acc and jerk must be finite and > 0 (index " +
                                        std::to_string(i) + ")");
        }
        py::array_t<double> out(n);
        {
          py::gil_scoped_release release;
          plan_s_curve_batch(static_cast<std::size_t>(n), start.data(), target.data(), vel.data(), acc.data(),
                             jerk.data(), out.mutable_data());
        }
        return out;
      },
      py::arg("start"), py::arg("target"), py::arg("vel"), py::arg("acc"), py::arg("jerk"),
      "Plans rest-to-rest S-curves (pulse; limits pulse/tick, pulse/tick^2, pulse/tick^3, all > 0) and returns\n"
      "their minimal durations in ticks. The benchmark's batch entry point (GIL released while planning).");
  m.def(
      "plan_s_curve_replan_batch",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> pos,
         py::array_t<double, py::array::c_style | py::array::forcecast> vel,
         py::array_t<double, py::array::c_style | py::array::forcecast> acc,
         py::array_t<double, py::array::c_style | py::array::forcecast> target,
         py::array_t<double, py::array::c_style | py::array::forcecast> vmax,
         py::array_t<double, py::array::c_style | py::array::forcecast> amax,
         py::array_t<double, py::array::c_style | py::array::forcecast> jmax) {
        const auto n = pos.size();
        if (vel.size() != n || acc.size() != n || target.size() != n || vmax.size() != n || amax.size() != n ||
            jmax.size() != n)
          throw std::invalid_argument(
              "plan_s_curve_replan_batch: pos, vel, acc, target, vmax, amax and jmax must have equal lengths");
        for (py::ssize_t i = 0; i < n; ++i) {
          check_replan_input(MotionState{pos.data()[i], vel.data()[i], acc.data()[i], 0.0}, target.data()[i],
                             SCurveLimits{vmax.data()[i], amax.data()[i], jmax.data()[i]});
        }
        py::array_t<double> out(n);
        {
          py::gil_scoped_release release;
          plan_s_curve_replan_batch(static_cast<std::size_t>(n), pos.data(), vel.data(), acc.data(), target.data(),
                                    vmax.data(), amax.data(), jmax.data(), out.mutable_data());
        }
        return out;
      },
      py::arg("pos"), py::arg("vel"), py::arg("acc"), py::arg("target"), py::arg("vmax"), py::arg("amax"),
      py::arg("jmax"),
      "Replans S-curves from moving states (pos pulse, vel pulse/tick, acc pulse/tick^2) to rest at target (pulse)\n"
      "with limits vmax, amax, jmax (pulse/tick, /tick^2, /tick^3, > 0, finite); returns the durations in ticks.\n"
      "A state outside its limits is first braked back inside (decision MO2). ValueError on bad input.\n"
      "The replan benchmark's batch entry point (GIL released while planning).");
  m.def("s_curve_min_time", [](double distance, double vel, double acc, double jerk) {
        SCurveLimits lim{vel, acc, jerk};
        lim.validate();
        return s_curve_min_time(distance, lim);
      }, py::arg("distance"), py::arg("vel"), py::arg("acc"), py::arg("jerk"),
      "Minimal rest-to-rest S-curve duration, ticks (distance pulse, limits per tick).");
  m.def("t_curve_min_time", [](double distance, double vel, double acc) {
        TCurveLimits lim{vel, acc};
        lim.validate();
        return t_curve_min_time(distance, lim);
      }, py::arg("distance"), py::arg("vel"), py::arg("acc"),
      "Minimal rest-to-rest T-curve duration, ticks (distance pulse, limits per tick).");
}

}  // namespace servobench::bindings
