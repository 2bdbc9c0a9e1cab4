// Bindings of the PVT tables (pvt.hpp, pvt_table.hpp) and the FollowEx cam (follow_ex.hpp). Thin: NumPy
// arrays in and out, the GIL released on the tick loops.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "param_class.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/follow_ex.hpp"
#include "servobench/motion/pvt.hpp"
#include "servobench/motion/pvt_table.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using Arr = py::array_t<double, py::array::c_style | py::array::forcecast>;

namespace {
std::vector<double> vec(const Arr& a, const char* owner, const char* name) {
  if (a.ndim() != 1)
    throw std::invalid_argument(std::string(owner) + "." + name + " must be a 1-D array, got " +
                                std::to_string(a.ndim()) + "-D");
  return std::vector<double>(a.data(), a.data() + a.size());
}

motion::ContinuousAcc meaning_of(const std::string& s) {
  if (s == "peak") return motion::ContinuousAcc::Peak;
  if (s == "average") return motion::ContinuousAcc::Average;
  throw std::invalid_argument("PvtTableContinuous.acc_meaning = '" + s +
                              "' is not one of 'peak', 'average' (decision M24)");
}

motion::ContinuousPoints continuous_points(const Arr& pos, const Arr& vel, const Arr& acc_percent,
                                           const Arr& dec_percent, const Arr& vel_max, const Arr& acc,
                                           const Arr& dec) {
  const char* o = "PvtTableContinuous";
  return {vec(pos, o, "pos"),         vec(vel, o, "vel"), vec(acc_percent, o, "acc_percent"),
          vec(dec_percent, o, "dec_percent"), vec(vel_max, o, "vel_max"), vec(acc, o, "acc"),
          vec(dec, o, "dec")};
}


int segment_type(const py::object& t) {
  const double v = py::int_(t).cast<double>();
  check_integer("FollowDataPercent", "type", v, 0, 3, "NORMAL 0, EVEN 1, STOP 2, CONTINUE 3; iDEABOX L4718-4726");
  return static_cast<int>(v);
}

int whole(double v, const char* owner, const char* field, double lo, double hi, const char* src) {
  check_integer(owner, field, v, lo, hi, src);
  return static_cast<int>(v);
}
}  // namespace

void bind_pvt(py::module_& m) {
  using namespace motion;

  // ReturnCode (the GUC-ECAT / iDEABOX codes) is vendor::googol::GucCode, bound by bind_card_codes.cpp; servobench.pvt
  // keeps the old name as an alias of it (decision GX4).

  py::class_<PvtCurve>(m, "PvtCurve",
      "A compiled PVT table: the points (time_ms ms, pos pulse, vel pulse/ms at each point) and the cubic pieces\n"
      "between them. `evaluate(t_ms)` samples it in the manual's units.")
      .def_property_readonly("mode", [](const PvtCurve& c) { return std::string(to_string(c.mode)); })
      .def_property_readonly("time_ms", [](const PvtCurve& c) { return to_array(c.time_ms); }, "point times, ms")
      .def_property_readonly("pos", [](const PvtCurve& c) { return to_array(c.pos); }, "point positions, pulse")
      .def_property_readonly("vel", [](const PvtCurve& c) { return to_array(c.vel); },
                             "velocity at each point, pulse/ms (computed for Complete and Percent)")
      .def_property_readonly("blocks", &PvtCurve::blocks, "memory blocks the table uses (<= 1024)")
      .def_property_readonly("blocks_per_point", [](const PvtCurve& c) { return c.blocks_per_point; })
      .def_property_readonly("pieces", [](const PvtCurve& c) { return c.pieces.size(); }, "number of cubic pieces")
      .def_property_readonly("duration_ms", [](const PvtCurve& c) { return c.t_last() - c.t_first(); },
                             "time from the first point to the last, ms (one pass)")
      .def("evaluate", [](const PvtCurve& c, const Arr& t) {
             const auto tv = vec(t, "PvtCurve.evaluate", "t_ms");
             std::vector<double> p(tv.size()), v(tv.size()), a(tv.size()), j(tv.size());
             for (std::size_t i = 0; i < tv.size(); ++i) {
               const auto s = c.at(tv[i]);
               p[i] = s.pos, v[i] = s.vel, a[i] = s.acc, j[i] = s.jerk;
             }
             py::dict d;
             d["pos"] = to_array(p);
             d["vel"] = to_array(v);
             d["acc"] = to_array(a);
             d["jerk"] = to_array(j);
             return d;
           }, py::arg("t_ms"),
           "Samples the table at times t_ms (ms): dict of pos pulse, vel pulse/ms, acc pulse/ms^2, jerk pulse/ms^3.")
      .def("__repr__", [](const PvtCurve& c) {
        return "PvtCurve(mode=" + std::string(to_string(c.mode)) + ", points=" + std::to_string(c.time_ms.size()) +
               ", blocks=" + std::to_string(c.blocks()) + ", " + format_value(c.t_first()) + ".." +
               format_value(c.t_last()) + " ms)";
      });

  m.def("pvt_table", [](const Arr& t, const Arr& p, const Arr& v) {
        return pvt_table(vec(t, "PvtTable", "time_ms"), vec(p, "PvtTable", "pos"), vec(v, "PvtTable", "vel"));
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("vel"),
      "PVT mode (GT_PvtTable): per point time ms, position pulse, velocity pulse/ms; cubic between points.");
  m.def("pvt_table_ex", [](const Arr& t, const Arr& p, const Arr& vb, const Arr& ve) {
        const char* o = "PvtTableEx";
        return pvt_table_ex(vec(t, o, "time_ms"), vec(p, o, "pos"), vec(vb, o, "vel_begin"), vec(ve, o, "vel_end"));
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("vel_begin"), py::arg("vel_end"),
      "PVT-Ex (iDEABOX GT_PvtTableEx): segment i leaves point i at vel_begin[i] and reaches point i+1 at\n"
      "vel_end[i+1] (pulse/ms): a velocity jump at a point is allowed.");
  m.def("pvt_table_complete", [](const Arr& t, const Arr& p, double vb, double ve) {
        return pvt_table_complete(vec(t, "PvtTableComplete", "time_ms"), vec(p, "PvtTableComplete", "pos"), vb, ve);
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("vel_begin") = 0.0, py::arg("vel_end") = 0.0,
      "Complete mode (GT_PvtTableComplete): times ms and positions pulse; the interior velocities make velocity\n"
      "and acceleration continuous (clamped C2 spline, vel_begin/vel_end pulse/ms at the ends).");
  m.def("pvt_complete_calculate", [](const Arr& t, const Arr& p, double vb, double ve) {
        return to_array(pvt_complete_velocities(vec(t, "PvtTableComplete", "time_ms"), vec(p, "PvtTableComplete", "pos"),
                                           vb, ve));
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("vel_begin") = 0.0, py::arg("vel_end") = 0.0,
      "The Complete mode's node velocities, pulse/ms, without a table.");
  m.def("pvt_percent_calculate", [](const Arr& t, const Arr& p, const Arr& q, double vb) {
        const char* o = "PvtTablePercent";
        return to_array(pvt_percent_calculate(vec(t, o, "time_ms"), vec(p, o, "pos"), vec(q, o, "percent"), vb));
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("percent"), py::arg("vel_begin") = 0.0,
      "GT_PvtPercentCalculate: node velocities (pulse/ms) v[i+1] = 2(p[i+1]-p[i])/(t[i+1]-t[i]) - v[i];\n"
      "percent (0..100) does not change them.");
  m.def("pvt_table_percent", [](const Arr& t, const Arr& p, const Arr& q, double vb) {
        const char* o = "PvtTablePercent";
        return pvt_table_percent(vec(t, o, "time_ms"), vec(p, o, "pos"), vec(q, o, "percent"), vb);
      }, py::kw_only(), py::arg("time_ms"), py::arg("pos"), py::arg("percent"), py::arg("vel_begin") = 0.0,
      "Percent mode (GT_PvtTablePercent): times ms, positions pulse, percent 0..100 per point (the share of\n"
      "segment i spent ramping the acceleration: 0 = constant acceleration, 100 = triangular).");
  m.def("pvt_continuous_calculate",
        [](const Arr& p, const Arr& v, const Arr& q, const Arr& vm, const Arr& a, const Arr& d,
           const std::string& meaning) {
          return to_array(pvt_continuous_calculate(continuous_points(p, v, q, q, vm, a, d), meaning_of(meaning)));
        }, py::kw_only(), py::arg("pos"), py::arg("vel"), py::arg("percent"), py::arg("vel_max"), py::arg("acc"),
        py::arg("dec"), py::arg("acc_meaning") = "peak",
        "GT_PvtContinuousCalculate: the point times in ms (time[0] = 0) for positions pulse, velocities at the\n"
        "points pulse/ms, percent 0..100, vel_max pulse/ms, acc/dec pulse/ms^2 (acc_meaning 'peak' or 'average').");
  m.def("pvt_table_continuous",
        [](const Arr& p, const Arr& v, const Arr& q, const Arr& vm, const Arr& a, const Arr& d, double tb,
           const std::string& meaning) {
          return pvt_table_continuous(continuous_points(p, v, q, q, vm, a, d), tb, meaning_of(meaning), false);
        }, py::kw_only(), py::arg("pos"), py::arg("vel"), py::arg("percent"), py::arg("vel_max"), py::arg("acc"),
        py::arg("dec"), py::arg("time_begin_ms") = 0.0, py::arg("acc_meaning") = "peak",
        "Continuous mode (GT_PvtTableContinuous): no times; each segment accelerates at acc, cruises at <= vel_max\n"
        "and decelerates at dec (S share percent); time_begin_ms is the first point's time (the start delay).");
  m.def("pvt_table_continuous_ex",
        [](const Arr& p, const Arr& v, const Arr& qa, const Arr& qd, const Arr& vm, const Arr& a, const Arr& d,
           double tb, const std::string& meaning) {
          return pvt_table_continuous(continuous_points(p, v, qa, qd, vm, a, d), tb, meaning_of(meaning), true);
        }, py::kw_only(), py::arg("pos"), py::arg("vel"), py::arg("acc_percent"), py::arg("dec_percent"),
        py::arg("vel_max"), py::arg("acc"), py::arg("dec"), py::arg("time_begin_ms") = 0.0,
        py::arg("acc_meaning") = "peak",
        "Continuous-Ex (iDEABOX GT_PvtTableContinuousEx): as pvt_table_continuous with separate S shares for the\n"
        "acceleration and the deceleration phases.");

  py::class_<PvtTables>(m, "PvtTables",
      "The card's 32 PVT tables x 1024 memory blocks, shared by the axes (GUC L1272, L1304; iDEABOX L2779).")
      .def(py::init<>())
      .def("download", [](PvtTables& t, double id, const PvtCurve& c) {
             PvtTables::check_id(id);
             t.download(static_cast<int>(id), c);
           }, py::arg("table_id"), py::arg("curve"),
           "Replaces table table_id (1..32). MotionCommandRefused (return code 1) if it needs more than 1024 blocks\n"
           "or a moving axis uses it.")
      .def("table", [](const PvtTables& t, double id) -> py::object {
             PvtTables::check_id(id);
             const PvtCurve* c = t.table(static_cast<int>(id));
             return c ? py::cast(*c) : py::none();
           }, py::arg("table_id"), "A copy of the table's curve, or None if empty.")
      .def("users", [](const PvtTables& t, double id) {
             PvtTables::check_id(id);
             return t.users(static_cast<int>(id));
           }, py::arg("table_id"), "Number of axes moving on the table.")
      .def_property_readonly_static("TABLES", [](py::object) { return PvtTables::kTables; })
      .def_property_readonly_static("BLOCKS_PER_TABLE", [](py::object) { return PvtTables::kBlocksPerTable; });

  py::class_<PvtAxis>(m, "PvtAxis",
      "One axis in PVT mode (GT_PrfPvt), stepped once per tick of period_s seconds. select(table) (default 1),\n"
      "set_loop(n) (0 = infinite), start(); outputs pulse, pulse/tick, pulse/tick^2, pulse/tick^3. Table positions\n"
      "are relative to where the axis starts; loops continue from the previous pass's end.")
      .def(py::init([](PvtTables& t, double start_pos, double period_s) {
             return std::make_unique<PvtAxis>(t, start_pos, period_s);
           }), py::arg("tables"), py::kw_only(), py::arg("start_pos") = 0.0, py::arg("period_s") = 1e-3,
           py::keep_alive<1, 2>())
      .def("select", [](PvtAxis& a, double id) {
             PvtTables::check_id(id);
             a.select(static_cast<int>(id));
           }, py::arg("table_id"), "GT_PvtTableSelect: at rest at once, while moving at the end of the pass.")
      .def("set_loop", &PvtAxis::set_loop, py::arg("loop"), "GT_SetPvtLoop: passes, 0 = infinite.")
      .def("start", &PvtAxis::start, "GT_PvtStart: PVT time 0; the first point's time is the start delay.")
      .def("stop", &PvtAxis::stop, "GT_Stop: the motion ends where it is.")
      .def("step", [](PvtAxis& a) { return state_tuple(a.step()); },
           "One tick: (pos pulse, vel pulse/tick, acc pulse/tick^2, jerk pulse/tick^3).")
      .def("run", [](PvtAxis& a, double ticks) {
             return run_ticks("PvtAxis.run", ticks, false, [&]() -> const motion::MotionState& { return a.step(); }, [&] { return a.moving(); },
                              [&] { return a.reported_pos(); });
           }, py::arg("ticks"),
           "Step `ticks` times; dict of arrays pos (whole pulses), pos_exact, vel, acc, jerk (per tick units).")
      .def("run_until_done", [](PvtAxis& a, double max_ticks) {
             return run_ticks("PvtAxis.run", max_ticks, true, [&]() -> const motion::MotionState& { return a.step(); }, [&] { return a.moving(); },
                              [&] { return a.reported_pos(); });
           }, py::arg("max_ticks") = 1e8, "As run(), stopping when the PVT motion has ended.")
      .def_property_readonly("state", [](const PvtAxis& a) { return state_tuple(a.state()); })
      .def_property_readonly("reported_pos", &PvtAxis::reported_pos)
      .def_property_readonly("moving", &PvtAxis::moving)
      .def_property_readonly("period_s", &PvtAxis::period_s)
      .def_property_readonly("table_id", &PvtAxis::table_id, "GT_PvtStatus table")
      .def_property_readonly("time_ms", &PvtAxis::time_ms, "GT_PvtStatus time: the axis's PVT time, ms")
      .def_property_readonly("loop_count", &PvtAxis::loop_count, "GT_GetPvtLoop: passes completed")
      .def_property_readonly("loop", &PvtAxis::loop, "GT_GetPvtLoop: the loop setting (0 = infinite)")
      .def("__repr__", [](const PvtAxis& a) {
        return "PvtAxis(table=" + std::to_string(a.table_id()) + ", time_ms=" + format_value(a.time_ms()) +
               ", pos=" + format_value(a.state().pos) + ", moving=" + (a.moving() ? "True" : "False") + ")";
      });
  m.def("pvt_start", [](const std::vector<PvtAxis*>& axes) { pvt_start(axes); }, py::arg("axes"),
        "GT_PvtStart(mask): starts every axis of the list on the same tick.");

  ParamClass<FollowExSetup>(m, "FollowExSetup",
      "FollowEx set-up (iDEABOX L475-550): GT_PrfFollowEx dir, GT_SetFollowMasterEx type/item, GT_SetFollowMemoryEx,\n"
      "GT_SetFollowExMaxSegment, GT_SetFollowEventEx and GT_SetFollowLoopEx.")
      .field("dir", &FollowExSetup::dir, "0 follow both master directions, 1 positive only, -1 negative only (L6185)")
      .field("master_type", &FollowExSetup::master_type,
             "which signal the card feeds as master: 1 encoder, 2 profile (default), 3 axis (L7345-7363)")
      .field("master_item", &FollowExSetup::master_item, "axis master: 0 planned position, 1 encoder")
      .field("memory", &FollowExSetup::memory, "FIFO size: 0 = 16, 1 = 512, 2 = max_segment segments (L489-493)")
      .field("max_segment", &FollowExSetup::max_segment, "dynamic FIFO size, 1..2147483647 (0 = not set)")
      .field("event", &FollowExSetup::event, "start event: 1 START, 2 PASS (L536-542)")
      .field("master_dir", &FollowExSetup::master_dir, "PASS direction: 1 positive, -1 negative")
      .field("event_pos", &FollowExSetup::event_pos, "PASS position, whole pulses")
      .field("loop", &FollowExSetup::loop, "passes, < 1 = infinite (L7302)")
      .finish();

  py::enum_<FollowSegmentType>(m, "FollowSegment", py::arithmetic(),
                               "FollowEx segment types (iDEABOX L516-530, L4718-4726).")
      .value("NORMAL", FollowSegmentType::Normal)
      .value("EVEN", FollowSegmentType::Even)
      .value("STOP", FollowSegmentType::Stop)
      .value("CONTINUE", FollowSegmentType::Continue);

  py::class_<FollowEx>(m, "FollowEx",
      "FollowEx electronic cam (iDEABOX L394-929): the slave follows a master position sequence (pulse, one\n"
      "sample per tick) along segments written to two FIFOs. Data values are cumulative positions from the\n"
      "follow start (decision M30). Outputs pulse, pulse/tick.")
      .def(py::init<const FollowExSetup&, double>(), py::arg("setup") = FollowExSetup{}, py::kw_only(),
           py::arg("slave_pos") = 0.0)
      .def("data_percent", [](FollowEx& f, double master, double slave, const py::object& type, double percent,
                              double fifo) {
             f.data_percent(master, slave, static_cast<FollowSegmentType>(segment_type(type)), percent,
                            whole(fifo, "FollowEx", "fifo", 0, 1, "two FIFOs per axis"));
           }, py::arg("master"), py::arg("slave"), py::arg("type") = FollowSegmentType::Normal,
           py::arg("percent") = 0.0, py::arg("fifo") = 0,
           "GT_FollowDataPercentEx: master (whole pulses) and slave (pulse) positions cumulative from the follow\n"
           "start; type FollowSegment; percent 0..100 of the ratio change spent in the S ramp.")
      .def("data_complete", [](FollowEx& f, const Arr& master, const Arr& slave, double rb, double re, double fifo) {
             f.data_complete(vec(master, "FollowDataComplete", "master"), vec(slave, "FollowDataComplete", "slave"),
                             rb, re, whole(fifo, "FollowEx", "fifo", 0, 1, "two FIFOs per axis"));
           }, py::arg("master"), py::arg("slave"), py::arg("ratio_begin") = 1.0, py::arg("ratio_end") = 1.0,
           py::arg("fifo") = 0,
           "GT_FollowDataCompleteEx: knots (pulse; the first is the curve start) joined by a clamped C2 spline\n"
           "slave(master) with the end velocity ratios given; n knots make n-1 segments, all or nothing.")
      .def("space", [](const FollowEx& f, double fifo) { return f.space(whole(fifo, "FollowEx", "fifo", 0, 1, "")); },
           py::arg("fifo") = 0, "GT_FollowSpaceEx: free segments.")
      .def("size", [](const FollowEx& f, double fifo) { return f.size(whole(fifo, "FollowEx", "fifo", 0, 1, "")); },
           py::arg("fifo") = 0, "Segments held.")
      .def("clear", [](FollowEx& f, double fifo) { f.clear(whole(fifo, "FollowEx", "fifo", 0, 1, "")); },
           py::arg("fifo") = 0, "GT_FollowClearEx: refused while the FIFO is in use.")
      .def("start", [](FollowEx& f, double master_pos, double fifo) {
             f.start(master_pos, whole(fifo, "FollowEx", "fifo", 0, 1, ""));
           }, py::arg("master_pos"), py::arg("fifo") = 0,
           "GT_FollowStartEx with the master's current position (pulse).")
      .def("switch_fifo", &FollowEx::switch_fifo, "GT_FollowSwitchEx: the other FIFO takes over at the pass end.")
      .def("stop", &FollowEx::stop, "GT_Stop: the slave stops where it is.")
      .def("step", [](FollowEx& f, double mp) { return state_tuple(f.step(mp)); }, py::arg("master_pos"),
           "One tick with the master at master_pos (pulse): (pos pulse, vel pulse/tick, acc, jerk).")
      .def("follow", [](FollowEx& f, const Arr& master) {
             const auto mv = vec(master, "FollowEx.follow", "master_pos");
             std::vector<double> pos(mv.size()), exact(mv.size()), vel(mv.size()), acc(mv.size()), ratio(mv.size());
             {
               // GIL held: one thread per FollowEx
               for (std::size_t i = 0; i < mv.size(); ++i) {
                 const auto& s = f.step(mv[i]);
                 pos[i] = static_cast<double>(f.reported_pos());
                 exact[i] = s.pos, vel[i] = s.vel, acc[i] = s.acc, ratio[i] = f.ratio();
               }
             }
             py::dict d;
             d["pos"] = to_array(pos);
             d["pos_exact"] = to_array(exact);
             d["vel"] = to_array(vel);
             d["acc"] = to_array(acc);
             d["ratio"] = to_array(ratio);
             return d;
           }, py::arg("master_pos"),
           "Steps once per master sample (pulse); dict of arrays pos (whole pulses), pos_exact, vel pulse/tick,\n"
           "acc pulse/tick^2, ratio (slave/master velocity ratio).")
      .def_property_readonly("state", [](const FollowEx& f) { return state_tuple(f.state()); })
      .def_property_readonly("reported_pos", &FollowEx::reported_pos)
      .def_property_readonly("moving", &FollowEx::moving)
      .def_property_readonly("waiting", &FollowEx::waiting, "started, waiting for the PASS event")
      .def_property_readonly("active_fifo", &FollowEx::active_fifo)
      .def_property_readonly("switch_pending", &FollowEx::switch_pending)
      .def_property_readonly("loop_count", &FollowEx::loop_count, "GT_GetFollowLoopEx: completed passes")
      .def_property_readonly("ratio", &FollowEx::ratio, "slave/master velocity ratio now")
      .def_property_readonly("travel", &FollowEx::travel, "master travel into the current pass, pulse")
      .def_property_readonly("setup", &FollowEx::setup)
      .def("__repr__", [](const FollowEx& f) {
        return "FollowEx(fifo=" + std::to_string(f.active_fifo()) + ", pos=" + format_value(f.state().pos) +
               ", ratio=" + format_value(f.ratio()) + ", moving=" + (f.moving() ? "True" : "False") + ")";
      });

  m.def("follow_cam", [](const Arr& master, const Arr& slave, const std::vector<int>& types, const Arr& percent,
                         double entry_ratio) {
        const auto mv = vec(master, "FollowCam", "master"), sv = vec(slave, "FollowCam", "slave"),
                   qv = vec(percent, "FollowCam", "percent");
        if (sv.size() != mv.size() || qv.size() != mv.size() || types.size() != mv.size())
          throw std::invalid_argument("FollowCam: master, slave, types and percent must have equal lengths");
        std::vector<FollowSegmentData> segs;
        for (std::size_t i = 0; i < mv.size(); ++i) {
          check_integer("FollowCam", "types[i]", types[i], 0, 3, "NORMAL 0, EVEN 1, STOP 2, CONTINUE 3");
          check_range("FollowCam", "percent[i]", qv[i], 0, 100, "iDEABOX L4728");
          if (!(mv[i] != 0.0) || !std::isfinite(mv[i]) || !std::isfinite(sv[i]))
            throw std::invalid_argument("FollowCam.master[" + std::to_string(i) + "] must be a finite non-zero displacement");
          if ((mv[i] > 0) != (mv[0] > 0))
            throw std::invalid_argument("FollowCam.master[" + std::to_string(i) +
                                        "] reverses the direction of master[0] (a cam's master values are monotonic)");
          segs.push_back({mv[i], sv[i], static_cast<FollowSegmentType>(types[i]), qv[i], false, 0, 0});
        }
        const auto cam = plan_follow_cam(segs, entry_ratio);
        py::dict d;
        d["ratio_begin"] = to_array(cam.ratio_begin);
        d["ratio_end"] = to_array(cam.ratio_end);
        d["length"] = cam.length;
        d["slave_length"] = cam.slave_length;
        return d;
      }, py::kw_only(), py::arg("master"), py::arg("slave"), py::arg("types"), py::arg("percent"),
      py::arg("entry_ratio") = 0.0,
      "Plans the velocity ratios of FollowEx segments given as displacements (pulse): dict of ratio_begin,\n"
      "ratio_end per segment, length (master travel of a pass) and slave_length.");
}

}  // namespace servobench::bindings
