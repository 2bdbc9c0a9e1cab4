// Bindings of the coordinated paths (path_segment.hpp, coord_system.hpp, lookahead.hpp, path_generator.hpp).
// Thin: coordinates in and out as NumPy arrays, the GIL released on the tick loops.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arrays.hpp"
#include "flag.hpp"
#include "param_class.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/adlink_interpolation.hpp"
#include "servobench/motion/coord_system.hpp"
#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/ge_lookahead.hpp"
#include "servobench/motion/lookahead.hpp"
#include "servobench/motion/path_generator.hpp"
#include "servobench/motion/path_segment.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using Arr = py::array_t<double, py::array::c_style | py::array::forcecast>;

namespace {
using motion::ArcPlane;
using motion::CrdPoint;

CrdPoint point(const std::vector<double>& v, const char* what) {
  if (v.empty() || v.size() > 4)
    throw std::invalid_argument(std::string(what) + " must have 1..4 coordinates (X, Y, Z, A), got " +
                                std::to_string(v.size()));
  CrdPoint p{};
  for (std::size_t k = 0; k < v.size(); ++k) p[k] = v[k];
  return p;
}

// A point of the generator's dimension: the coordinates given, the rest from `base`.
CrdPoint point_from(const std::vector<double>& v, const CrdPoint& base, const char* what) {
  CrdPoint p = point(v, what);
  for (std::size_t k = v.size(); k < 4; ++k) p[k] = base[k];
  return p;
}

ArcPlane plane_of(const std::string& s) {
  if (s == "xy" || s == "XY") return ArcPlane::XY;
  if (s == "yz" || s == "YZ") return ArcPlane::YZ;
  if (s == "zx" || s == "ZX") return ArcPlane::ZX;
  throw std::invalid_argument("plane = '" + s + "' is not one of 'xy', 'yz', 'zx'");
}

py::array_t<double> matrix(const std::vector<double>& v, std::size_t cols) {
  const auto rows = cols ? v.size() / cols : 0;
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::array_t<double> crd_array(const CrdPoint& p, int dim) {
  return to_array(std::vector<double>(p.begin(), p.begin() + dim));
}

py::dict recording_dict(const motion::PathRecording& r) {
  py::dict d;
  d["t_ms"] = to_array(r.t_ms);
  d["pos"] = matrix(r.crd, static_cast<std::size_t>(r.dim));
  d["axis_pos"] = matrix(r.axis_pos, r.axes.size());
  d["axes"] = r.axes;
  d["speed"] = to_array(r.speed);
  d["acc"] = to_array(r.acc);
  d["segments"] = to_array(r.segments);
  d["gpo"] = to_array(r.gpo);
  d["aux_axes"] = r.aux_axes;
  d["aux"] = matrix(r.aux, r.aux_axes.size());
  return d;
}

template <class G>
py::dict record_py(G& g, double ticks, Flag until_done) {
  check_integer("record", "ticks", ticks, 0, 1e8);
  motion::PathRecording r;
  r = motion::record(g, static_cast<std::size_t>(ticks), until_done);  // GIL held: one thread per generator
  return recording_dict(r);
}

motion::SpacePoint space_point(const std::vector<double>& v, const char* what) {
  if (v.size() > 6) throw std::invalid_argument(std::string(what) + " has at most 6 coordinates");
  motion::SpacePoint p{};
  for (std::size_t k = 0; k < v.size(); ++k) p[k] = v[k];
  return p;
}

motion::Vec3 vec3(const std::vector<double>& v) {
  if (v.size() != 3) throw std::invalid_argument("normal must have 3 components");
  return {v[0], v[1], v[2]};
}
}  // namespace

void bind_paths(py::module_& m) {
  using namespace motion;

  py::register_exception<PathGeometryError>(m, "PathGeometryError", PyExc_ValueError);

  ParamClass<PathSetup>(m, "PathSetup",
      "Path interpolator configuration. Units: coordinate unit (pulse), ms, unit/ms, unit/ms^2.")
      .field("cycle_ms", &PathSetup::cycle_ms, "motion cycle, ms, 0.01..100")
      .field("fifo_capacity", &PathSetup::fifo_capacity, "FIFO entries, 1..1e7 (GUC/iDEABOX: 4096 segments)")
      .field("syn_vel_max", &PathSetup::syn_vel_max, "clamp of every synVel, unit/ms (GUC synVelMax L771)")
      .field("syn_acc_max", &PathSetup::syn_acc_max, "clamp of every synAcc, unit/ms^2 (GUC synAccMax L773)")
      .field("even_time_ms", &PathSetup::even_time_ms, "minimum cruise time per segment, ms (GUC evenTime L775)")
      .field("stop_dec_smooth", &PathSetup::stop_dec_smooth, "smooth-stop deceleration, unit/ms^2; 0 = segment's")
      .field("stop_dec_abrupt", &PathSetup::stop_dec_abrupt, "abrupt-stop deceleration, unit/ms^2; 0 = at once")
      .field("corner_axis_acc", &PathSetup::corner_axis_acc,
             "GT AccLmt for every motor axis of the coordinate system, pulse/ms^2; 0 = off (axis_acc_k override it)")
      .field("axis_acc_1", &PathSetup::axis_acc_1,
             "acceleration limit of the 1st motor axis, pulse/ms^2 (GT_SetAccLmt, L1956); 0 = corner_axis_acc. Any\n"
             "limit set: that axis's position second difference per motion cycle stays <= it, corners included")
      .field("axis_acc_2", &PathSetup::axis_acc_2, "as axis_acc_1, 2nd motor axis, pulse/ms^2")
      .field("axis_acc_3", &PathSetup::axis_acc_3, "as axis_acc_1, 3rd motor axis, pulse/ms^2")
      .field("axis_acc_4", &PathSetup::axis_acc_4, "as axis_acc_1, 4th motor axis, pulse/ms^2")
      .field("return_to_stop_point", &PathSetup::return_to_stop_point,
             "resume away from the breakpoint returns to it (GT/GE) instead of being refused (GUC/iDEABOX)")
      .field("start_vel", &PathSetup::start_vel,
             "GE GT_SetStrtVel start velocity, unit/ms (GE default 0.5 pulse/ms); 0 = from and to rest")
      .field("resume_tolerance", &PathSetup::resume_tolerance,
             "unit per coordinate: a resume this close to the breakpoint is accepted (GUC/iDEABOX)")
      .finish();

  ParamClass<LookAheadParams>(m, "LookAheadParams",
      "GT_InitLookAhead parameters (GUC L725-732, iDEABOX L5848-5879): corner time t_ms (ms), maximum\n"
      "acceleration acc_max (unit/ms^2), window n (segments; 0 = off).")
      .field("t_ms", &LookAheadParams::t_ms, "corner time T, ms, 0 < T <= 1000 (empirically 1..10)")
      .field("acc_max", &LookAheadParams::acc_max, "maximum acceleration, unit/ms^2, 0 < acc_max <= 32767")
      .field("n", &LookAheadParams::n, "window, segments, 0..32766 (GE requires >= 200)")
      .finish();

  py::class_<PathSegmentGeometry>(m, "PathSegment",
      "Geometry of one path segment (line, arc or helix) in coordinates X, Y, Z, A. Build it with line(),\n"
      "arc_center_angle(), arc_radius() or arc_center(); impossible geometry raises PathGeometryError (a\n"
      "ValueError) naming the GT/GE return code (2, 3 or 5; 7 on GUC-ECAT/iDEABOX).")
      .def_static("line", [](const std::vector<double>& start, const std::vector<double>& end) {
            if (start.size() != end.size()) throw std::invalid_argument("PathLine: start and end differ in length");
            return PathSegmentGeometry::line(point(start, "start"), point(end, "end"), static_cast<int>(start.size()));
          }, py::arg("start"), py::arg("end"), "A line in 1..4 coordinates.")
      .def_static("arc_center_angle", [](const std::vector<double>& start, const std::string& plane,
                                         std::pair<double, double> center, double angle_deg,
                                         const std::vector<double>& axial) {
            CrdPoint ax{};
            for (std::size_t k = 0; k < axial.size() && k < 4; ++k) ax[k] = axial[k];
            return PathSegmentGeometry::arc_center_angle(point(start, "start"), static_cast<int>(start.size()),
                                                         plane_of(plane), center.first, center.second, angle_deg, ax);
          }, py::arg("start"), py::arg("plane"), py::arg("center"), py::arg("angle_deg"),
          py::arg("axial") = std::vector<double>{},
          "GT/GE arc: absolute centre (plane coordinates), angle in degrees (-360..360, + = CCW about the\n"
          "positive third axis); axial: displacement of the other coordinates over the arc (a helix).")
      .def_static("arc_radius", [](const std::vector<double>& start, const std::vector<double>& end,
                                   const std::string& plane, double radius, Flag ccw) {
            if (start.size() != end.size()) throw std::invalid_argument("PathArcRadius: start and end differ in length");
            return PathSegmentGeometry::arc_end_radius(point(start, "start"), point(end, "end"),
                                                       static_cast<int>(start.size()), plane_of(plane), radius, ccw);
          }, py::arg("start"), py::arg("end"), py::arg("plane"), py::arg("radius"), py::arg("ccw"),
          "End point and signed radius: radius > 0 the arc <= 180 deg, < 0 the arc > 180 deg (no full circle).")
      .def_static("arc_center", [](const std::vector<double>& start, const std::vector<double>& end,
                                   const std::string& plane, std::pair<double, double> offset, Flag ccw) {
            if (start.size() != end.size()) throw std::invalid_argument("PathArcCenter: start and end differ in length");
            return PathSegmentGeometry::arc_center_offset(point(start, "start"), point(end, "end"),
                                                          static_cast<int>(start.size()), plane_of(plane),
                                                          offset.first, offset.second, ccw);
          }, py::arg("start"), py::arg("end"), py::arg("plane"), py::arg("center_offset"), py::arg("ccw"),
          "GUC/iDEABOX centre form: centre = start + center_offset; end == start gives a full circle.")
      .def_property_readonly("kind", [](const PathSegmentGeometry& g) {
        return std::string(g.kind() == SegmentKind::Line ? "line" : "arc");
      })
      .def_property_readonly("length", &PathSegmentGeometry::length, "path length, unit")
      .def_property_readonly("start", [](const PathSegmentGeometry& g) { return crd_array(g.start(), g.dim()); })
      .def_property_readonly("end", [](const PathSegmentGeometry& g) { return crd_array(g.end(), g.dim()); })
      .def_property_readonly("center", [](const PathSegmentGeometry& g) { return py::make_tuple(g.center(0), g.center(1)); })
      .def_property_readonly("radius", &PathSegmentGeometry::radius)
      .def_property_readonly("sweep_deg", [](const PathSegmentGeometry& g) { return g.sweep_rad() * 180.0 / 3.14159265358979323846; })
      .def_property_readonly("curvature_radius", &PathSegmentGeometry::curvature_radius)
      .def("point_at", [](const PathSegmentGeometry& g, const Arr& s) {
            std::vector<double> out;
            for (py::ssize_t i = 0; i < s.size(); ++i) {
              const auto p = g.point_at(s.data()[i]);
              out.insert(out.end(), p.begin(), p.begin() + g.dim());
            }
            return matrix(out, static_cast<std::size_t>(g.dim()));
          }, py::arg("s"), "Points at path lengths s: array (len(s), dim).")
      .def("tangent_at", [](const PathSegmentGeometry& g, double s) { return crd_array(g.tangent_at(s), g.dim()); })
      .def("__repr__", [](const PathSegmentGeometry& g) {
        return std::string("PathSegment(") + (g.kind() == SegmentKind::Line ? "line" : "arc") +
               ", length=" + format_value(g.length()) + ")";
      });

  py::class_<CoordSystem>(m, "CoordSystem",
      "How path coordinates become motor positions: identity (GE), GT_MapAxis rows (GT), TCrdPrm (GUC/iDEABOX).")
      .def_static("identity", &CoordSystem::identity, py::arg("dim"), py::arg("offsets") = std::vector<double>{},
                  "GE: coordinate k = axis k+1 plus a work offset (GT_MapCnt), pulse.")
      .def_static("gt_map", [](const std::vector<std::vector<double>>& rows) {
            std::vector<GtAxisMap> r;
            for (const auto& row : rows) {
              if (row.size() != 6) throw std::invalid_argument("GtAxisMap rows are (axis, cx, cy, cz, ca, c)");
              check_integer("GtAxisMap", "axis", row[0], 1, 4, "GT L1533");
              r.push_back({static_cast<int>(row[0]), row[1], row[2], row[3], row[4], row[5]});
            }
            return CoordSystem::gt_map(r);
          }, py::arg("rows"), "GT_MapAxis: rows (axis, Cx, Cy, Cz, Ca, C): axis = Cx x + Cy y + Cz z + Ca a + C.")
      .def_static("crd_prm", [](double dimension, const std::vector<double>& profile, double syn_vel_max,
                                double syn_acc_max, double even_time_ms, Flag set_origin,
                                const std::vector<double>& origin_pos, const std::vector<double>& profile_pos) {
            CrdPrm p;
            check_integer("CrdPrm", "dimension", dimension, 1, 4, "GUC L375");
            p.dimension = static_cast<int>(dimension);
            if (profile.size() > 8 || origin_pos.size() > 8 || profile_pos.size() > 8)
              throw std::invalid_argument("CrdPrm: profile, origin_pos and profile_pos have at most 8 entries");
            for (std::size_t k = 0; k < profile.size(); ++k) {
              check_integer("CrdPrm", "profile[k]", profile[k], 0, 4, "GUC L785");
              p.profile[k] = static_cast<int>(profile[k]);
            }
            for (std::size_t k = 0; k < origin_pos.size(); ++k) p.origin_pos[k] = origin_pos[k];
            p.syn_vel_max = syn_vel_max;
            p.syn_acc_max = syn_acc_max;
            p.even_time_ms = even_time_ms;
            p.set_origin = set_origin;
            std::array<double, 8> pp{};
            for (std::size_t k = 0; k < profile_pos.size(); ++k) pp[k] = profile_pos[k];
            return CoordSystem::crd_prm(p, pp);
          }, py::kw_only(), py::arg("dimension"), py::arg("profile"), py::arg("syn_vel_max"), py::arg("syn_acc_max"),
          py::arg("even_time_ms") = 0.0, py::arg("set_origin") = false, py::arg("origin_pos") = std::vector<double>{},
          py::arg("profile_pos") = std::vector<double>{},
          "GT_SetCrdPrm (TCrdPrm): profile[k] = coordinate (1 X..4 A, 0 none) of profile k+1; origin = origin_pos\n"
          "if set_origin else profile_pos (the profiles' present positions). syn_vel_max/syn_acc_max/even_time_ms\n"
          "are validated here; give them to PathSetup for the interpolator.")
      .def_property_readonly("dim", &CoordSystem::dim)
      .def_property_readonly("axes", &CoordSystem::axes, "motor axes driven, 1-based, ascending")
      .def("to_axes", [](const CoordSystem& c, const std::vector<double>& p) {
            return to_array(c.to_axes(point(p, "point")));
          }, py::arg("point"), "Motor positions (pulse) of a coordinate point.")
      .def("to_crd", &CoordSystem::to_crd, py::arg("axis_pos"),
           "Coordinate point of motor positions; the lower-numbered axis decides a conflict (GT L1665).");

  py::class_<PathState>(m, "PathState", "The interpolator's state after a cycle.")
      .def_readonly("t_ms", &PathState::t_ms)
      .def_property_readonly("pos", [](const PathState& s) { return to_array(std::vector<double>(s.pos.begin(), s.pos.end())); },
                             "coordinate position X, Y, Z, A")
      .def_readonly("speed", &PathState::speed, "path speed, unit/ms")
      .def_readonly("acc", &PathState::acc, "path acceleration, unit/ms^2")
      .def_readonly("segments_done", &PathState::segments_done)
      .def_readonly("user_seg_num", &PathState::user_seg_num)
      .def_property_readonly("gpo", [](const PathState& s) { return s.do_words[0]; }, "general outputs word")
      .def_property_readonly("enable", [](const PathState& s) { return s.do_words[1]; })
      .def_property_readonly("clear", [](const PathState& s) { return s.do_words[2]; })
      .def_property_readonly("da", [](const PathState& s) { return std::vector<double>(s.da.begin(), s.da.end()); })
      .def_readonly("limits_pos", &PathState::limits_pos, "bit k: positive limit of axis k+1 enabled (BufLmtsOn/Off)")
      .def_readonly("limits_neg", &PathState::limits_neg, "bit k: negative limit of axis k+1 enabled")
      .def_readonly("io_stop_axis", &PathState::io_stop_axis, "axis whose armed stop input stopped motion last, 0 none");

  py::class_<PathGenerator>(m, "PathGenerator",
      "One coordinate system's path interpolator, stepped once per motion cycle (see docs/paths.md).")
      .def(py::init([](const CoordSystem& c, const PathSetup& s, const std::vector<double>& start) {
             return PathGenerator(c, s, start.empty() ? CrdPoint{} : point(start, "start"));
           }), py::arg("coords"), py::arg("setup") = PathSetup{}, py::arg("start") = std::vector<double>{})
      .def("init_lookahead", &PathGenerator::init_lookahead, py::arg("params"))
      .def("set_override", &PathGenerator::set_override, py::arg("ratio"))
      .def("set_g0_override", &PathGenerator::set_g0_override, py::arg("ratio"))
      .def("set_stop_dec", &PathGenerator::set_stop_dec, py::arg("smooth"), py::arg("abrupt"))
      .def("set_axis_acc", &PathGenerator::set_axis_acc, py::arg("axis"), py::arg("acc"),
           "acceleration limit of motor axis 1..4 at the joints (PathSetup.axis_acc_k; GT_SetAccLmt, L1956)")
      .def("set_aux_position", &PathGenerator::set_aux_position, py::arg("axis"), py::arg("pos"))
      .def_property_readonly("tail", [](const PathGenerator& g) { return crd_array(g.tail(), g.coords().dim()); },
                             "start point of the next buffered segment")
      .def("push_segment", strict(&PathGenerator::push_segment), py::arg("segment"), py::arg("vel"), py::arg("acc"),
           py::arg("vel_end") = 0.0, py::arg("g0") = false, py::arg("auto_end") = false, py::arg("stop_at_end") = false)
      .def("line", [](PathGenerator& g, const std::vector<double>& end, double vel, double acc, double vel_end, Flag g0) {
             g.line(point_from(end, g.tail(), "end"), vel, acc, vel_end, g0);
           }, py::arg("end"), py::arg("vel"), py::arg("acc"), py::arg("vel_end") = 0.0, py::arg("g0") = false)
      .def("arc_center_angle", [](PathGenerator& g, const std::string& plane, std::pair<double, double> center,
                                  double angle_deg, double vel, double acc, double vel_end,
                                  const std::vector<double>& axial) {
             CrdPoint ax{};
             for (std::size_t k = 0; k < axial.size() && k < 4; ++k) ax[k] = axial[k];
             g.push_segment(PathSegmentGeometry::arc_center_angle(g.tail(), g.coords().dim(), plane_of(plane),
                                                                  center.first, center.second, angle_deg, ax),
                            vel, acc, vel_end);
           }, py::arg("plane"), py::arg("center"), py::arg("angle_deg"), py::arg("vel"), py::arg("acc"),
           py::arg("vel_end") = 0.0, py::arg("axial") = std::vector<double>{})
      .def("arc_radius", [](PathGenerator& g, const std::string& plane, const std::vector<double>& end, double radius,
                            Flag ccw, double vel, double acc, double vel_end) {
             g.push_segment(PathSegmentGeometry::arc_end_radius(g.tail(), point_from(end, g.tail(), "end"),
                                                                g.coords().dim(), plane_of(plane), radius, ccw),
                            vel, acc, vel_end);
           }, py::arg("plane"), py::arg("end"), py::arg("radius"), py::arg("ccw"), py::arg("vel"), py::arg("acc"),
           py::arg("vel_end") = 0.0)
      .def("arc_center", [](PathGenerator& g, const std::string& plane, const std::vector<double>& end,
                            std::pair<double, double> offset, Flag ccw, double vel, double acc, double vel_end) {
             g.push_segment(PathSegmentGeometry::arc_center_offset(g.tail(), point_from(end, g.tail(), "end"),
                                                                   g.coords().dim(), plane_of(plane), offset.first,
                                                                   offset.second, ccw),
                            vel, acc, vel_end);
           }, py::arg("plane"), py::arg("end"), py::arg("center_offset"), py::arg("ccw"), py::arg("vel"),
           py::arg("acc"), py::arg("vel_end") = 0.0)
      .def("buf_io", &PathGenerator::buf_io, py::arg("do_type"), py::arg("mask"), py::arg("value"))
      .def("buf_delay", &PathGenerator::buf_delay, py::arg("delay_ms"))
      .def("buf_da", &PathGenerator::buf_da, py::arg("channel"), py::arg("value"))
      .def("buf_move", strict(&PathGenerator::buf_move), py::arg("axis"), py::arg("pos"), py::arg("vel"), py::arg("acc"),
           py::arg("modal"))
      .def("buf_gear", &PathGenerator::buf_gear, py::arg("axis"), py::arg("distance"))
      .def("set_user_seg_num", &PathGenerator::set_user_seg_num, py::arg("seg_num"))
      .def("buf_lmts", strict(&PathGenerator::buf_lmts), py::arg("axis"), py::arg("limit_type"), py::arg("on"),
           "GT_BufLmtsOn (on) / GT_BufLmtsOff: axis 1..16, limit_type 0 positive, 1 negative, -1 both.")
      .def("buf_set_stop_io", &PathGenerator::buf_set_stop_io, py::arg("axis"), py::arg("stop_type"),
           py::arg("input_type"), py::arg("input_index"),
           "GT_BufSetStopIo: axis 1..8, stop_type 0 emergency / 1 smooth, input_type 0 +limit, 1 -limit, 2 alarm,\n"
           "3 home, 4 GPI; input_index 1..8 (GPI 1..16).")
      .def("set_input", strict(&PathGenerator::set_input), py::arg("input_type"), py::arg("index"), py::arg("active"),
           "The logical state of an input (the card's sense applied): input_type 0..4, index 1..8 (GPI 1..16).")
      .def("input", &PathGenerator::input, py::arg("input_type"), py::arg("index"))
      .def("stop_io", [](const PathGenerator& g, int axis) -> py::object {
             const auto& m = g.stop_io(axis);
             if (!m.armed) return py::none();
             py::dict d;
             d["stop_type"] = m.stop_type;
             d["input_type"] = m.input_type;
             d["input_index"] = m.input_index;
             return d;
           }, py::arg("axis"), "The armed stop input of an axis (dict), or None.")
      .def("flush", &PathGenerator::flush, "GT_CrdData(NULL): window -> FIFO; False if the FIFO filled first")
      .def("start", &PathGenerator::start)
      .def("stop", strict(&PathGenerator::stop), py::arg("abrupt") = false)
      .def("clear", &PathGenerator::clear)
      .def("move_immediate", [](PathGenerator& g, const std::vector<double>& end, double vel, double acc) {
             g.move_immediate(point_from(end, g.state().pos, "end"), vel, acc);
           }, py::arg("end"), py::arg("vel"), py::arg("acc"))
      .def("step", &PathGenerator::step, py::return_value_policy::copy)
      .def_property_readonly("state", &PathGenerator::state, py::return_value_policy::copy)
      .def("record", &record_py<PathGenerator>, py::arg("ticks"), py::arg("until_done") = false,
           "Steps `ticks` cycles (or until done); dict of arrays t_ms, pos (n, dim), axis_pos (n, axes), speed,\n"
           "acc, segments, gpo, aux (n, aux axes) and the lists axes, aux_axes.")
      .def_property_readonly("running", &PathGenerator::running)
      .def_property_readonly("busy", &PathGenerator::busy)
      .def_property_readonly("stopped", &PathGenerator::stopped)
      .def_property_readonly("done", &PathGenerator::done)
      .def_property_readonly("lookahead_on", &PathGenerator::lookahead_on)
      .def_property_readonly("breakpoint", [](const PathGenerator& g) -> py::object {
        if (!g.has_breakpoint()) return py::none();
        return crd_array(g.breakpoint(), g.coords().dim());
      })
      .def_property_readonly("remaining_segments", &PathGenerator::remaining_segments)
      .def_property_readonly("fifo_space", &PathGenerator::fifo_space)
      .def_property_readonly("fifo_size", &PathGenerator::fifo_size)
      .def_property_readonly("window_size", &PathGenerator::window_size)
      .def_property_readonly("aux_axes", &PathGenerator::aux_axes)
      .def("aux_position", &PathGenerator::aux_position, py::arg("axis"))
      .def_property_readonly("coords", &PathGenerator::coords)
      .def_property_readonly("setup", &PathGenerator::setup);

  py::class_<CrdFifoPair>(m, "CrdFifoPair",
      "The two FIFOs of a GUC-ECAT / iDEABOX coordinate system (FIFO0 principal, FIFO1 auxiliary) with the\n"
      "manuals' suspend/resume rules: data to FIFO1 only while FIFO0 is stopped; FIFO0 resumes only at its\n"
      "breakpoint (within resume_tolerance, pulse per coordinate); starting FIFO0 clears FIFO1.")
      .def(py::init([](const CoordSystem& c, const PathSetup& s, const std::vector<double>& start, double tol) {
             return std::make_unique<CrdFifoPair>(c, s, start.empty() ? CrdPoint{} : point(start, "start"), tol);
           }), py::arg("coords"), py::arg("setup") = PathSetup{}, py::arg("start") = std::vector<double>{},
           py::arg("resume_tolerance") = 0.5)
      .def("fifo", py::overload_cast<int>(&CrdFifoPair::fifo), py::arg("k"), py::return_value_policy::reference_internal,
           "FIFO k (0 or 1) as a PathGenerator: push commands to it; start through start(k).")
      .def("start", &CrdFifoPair::start, py::arg("fifo"), "GT_CrdStart with option bit = fifo")
      .def("stop", strict(&CrdFifoPair::stop), py::arg("abrupt") = false)
      .def("step", &CrdFifoPair::step, py::return_value_policy::copy)
      .def_property_readonly("state", &CrdFifoPair::state, py::return_value_policy::copy)
      .def_property_readonly("active", &CrdFifoPair::active, "the FIFO that moved the coordinate system last")
      .def_property_readonly("running", &CrdFifoPair::running)
      .def_property_readonly("done", &CrdFifoPair::done)
      .def_property_readonly("coords", &CrdFifoPair::coords)
      .def_property_readonly("aux_axes", &CrdFifoPair::aux_axes)
      .def("aux_position", &CrdFifoPair::aux_position, py::arg("axis"))
      .def("record", &record_py<CrdFifoPair>, py::arg("ticks"), py::arg("until_done") = false,
           "As PathGenerator.record, for the coordinate system (the active FIFO's state each cycle).");

  ParamClass<GeLookAheadParams>(m, "GeLookAheadParams",
      "GE GT_InitLookAhead (module A) in the GE units: t_s (s), acc_max and acc (mm/s^2), vel (mm/s), n\n"
      "(segments), con (pulse/mm); GE L1681-1701, L4879-4887.")
      .field("t_s", &GeLookAheadParams::t_s, "corner time T, s, 0 < T <= 1 (empirically 0.001..0.01)")
      .field("acc_max", &GeLookAheadParams::acc_max, "maximum acceleration, mm/s^2 (empirically 100..10000)")
      .field("acc", &GeLookAheadParams::acc, "running acceleration, mm/s^2, 0 < acc < acc_max")
      .field("vel", &GeLookAheadParams::vel, "feed, mm/s (used by segments with vel 0)")
      .field("n", &GeLookAheadParams::n, "window, segments, 1..32766")
      .field("con", &GeLookAheadParams::con, "pulse/mm")
      .finish();

  py::class_<GeLookAhead>(m, "GeLookAhead",
      "GE look-ahead module A: add_look_data() (GT_AddLookData) then cal_vel() (GT_CalVel) per segment; the\n"
      "end velocities are in mm/s (send them to the card with GT_SetDccVel in pulse/ms = mm/s * con / 1000).")
      .def(py::init([](const GeLookAheadParams& p, const std::vector<double>& start) {
             return GeLookAhead(p, start.empty() ? CrdPoint{} : point(start, "start"));
           }), py::arg("params"), py::arg("start_mm") = std::vector<double>{})
      .def("add_look_data", strict(&GeLookAhead::add), py::arg("code"), py::arg("plane_group"), py::arg("r"), py::arg("x"),
           py::arg("y"), py::arg("z"), py::arg("vel"), py::arg("cx"), py::arg("cy"), py::arg("number"),
           py::arg("flag"),
           "code 0 G00, 1 G01, 2 G02 (CW), 3 G03 (CCW); plane_group 17 XY, 18 ZX, 19 YZ; mm, mm/s. Returns 0, or\n"
           "1 if the point equals the previous one (nothing added).")
      .def("cal_vel", [](GeLookAhead& g) {
             double v = 0.0;
             long long n = 0;
             const int rc = g.cal_vel(v, n);
             return py::make_tuple(rc, v, n);
           }, "(return code, end velocity mm/s, user number): code 0 more follow, 1 this was the last")
      .def_property_readonly("pending", &GeLookAhead::pending);

  py::enum_<BlendMode>(m, "BlendMode", "ADLINK continuous-interpolation transition modes (Flag, L3085-3143)")
      .value("ABORT_BLEND", BlendMode::AbortBlend)
      .value("ABORT_FORCED", BlendMode::AbortForced)
      .value("ABORT_STOP", BlendMode::AbortStop)
      .value("BUFFERED", BlendMode::Buffered)
      .value("BLEND_DECEL", BlendMode::BlendDecel)
      .value("BLEND_DISTANCE", BlendMode::BlendDistance)
      .value("BLEND_PERCENT", BlendMode::BlendPercent);

  ParamClass<AdlinkInterpSetup>(m, "AdlinkInterpSetup", "ADLINK interpolator configuration.")
      .field("period_s", &AdlinkInterpSetup::period_s, "motion cycle, s (ADLINK: 1 ms)")
      .field("buffer_size", &AdlinkInterpSetup::buffer_size, "pending moves (decision C40: 10)")
      .finish();

  py::class_<AdlinkInterpolator>(m, "AdlinkInterpolator",
      "ADLINK interpolation of an axis array (2..6 axes, the first the reference axis whose profile drives the\n"
      "path): lines, 2-D/3-D arcs, spirals, seven transition modes. Units pulse, pulse/s, s.")
      .def(py::init<const std::vector<int>&, const AdlinkInterpSetup&, const std::vector<double>&>(), py::arg("axes"),
           py::arg("setup") = AdlinkInterpSetup{}, py::arg("start") = std::vector<double>{})
      .def("set_axis_params", &AdlinkInterpolator::set_axis_params, py::arg("axis"), py::arg("params"))
      .def("push", [](AdlinkInterpolator& g, const std::string& kind, const std::vector<double>& target,
                      const std::vector<double>& center, const std::vector<double>& normal, double angle_deg, int dir,
                      double height, double final_radius, Flag relative, BlendMode mode, double blend, double vm,
                      const AdlinkPtpParams* all) {
             AdlinkMoveSpec s;
             using K = AdlinkMoveSpec::Kind;
             if (kind == "line") s.kind = K::Line;
             else if (kind == "arc2_ca") s.kind = K::Arc2Ca;
             else if (kind == "arc2_ce") s.kind = K::Arc2Ce;
             else if (kind == "arc3_ca") s.kind = K::Arc3Ca;
             else if (kind == "arc3_ce") s.kind = K::Arc3Ce;
             else if (kind == "spiral_ca") s.kind = K::SpiralCa;
             else if (kind == "spiral_ce") s.kind = K::SpiralCe;
             else throw std::invalid_argument("kind = '" + kind + "' is not one of line, arc2_ca, arc2_ce, arc3_ca, "
                                              "arc3_ce, spiral_ca, spiral_ce");
             s.relative = relative;
             s.target = space_point(target, "target");
             s.center = space_point(center, "center");
             if (!normal.empty()) s.normal = vec3(normal);
             s.angle_deg = angle_deg;
             s.dir = dir;
             s.height = height;
             s.final_radius = final_radius;
             g.push(s, mode, blend, vm, all);
           }, py::arg("kind"), py::kw_only(), py::arg("target") = std::vector<double>{},
           py::arg("center") = std::vector<double>{}, py::arg("normal") = std::vector<double>{},
           py::arg("angle_deg") = 0.0, py::arg("dir") = 0, py::arg("height") = 0.0, py::arg("final_radius") = 0.0,
           py::arg("relative") = false, py::arg("mode") = BlendMode::Buffered, py::arg("blend") = 0.0,
           py::arg("vm") = 0.0, py::arg("params") = nullptr)
      .def("stop_move", &AdlinkInterpolator::stop_move)
      .def("emg_stop", &AdlinkInterpolator::emg_stop)
      .def("step", [](AdlinkInterpolator& g) {
             const auto& s = g.step();
             return py::make_tuple(s.t_s, to_array(std::vector<double>(s.pos.begin(), s.pos.begin() + g.dim())), s.speed);
           }, "one motion cycle: (t_s, positions, vector speed pulse/s)")
      .def_property_readonly("pos", [](const AdlinkInterpolator& g) {
             return to_array(std::vector<double>(g.state().pos.begin(), g.state().pos.begin() + g.dim()));
           })
      .def_property_readonly("tail", [](const AdlinkInterpolator& g) {
             return to_array(std::vector<double>(g.tail().begin(), g.tail().begin() + g.dim()));
           })
      .def_property_readonly("axes", &AdlinkInterpolator::axes)
      .def_property_readonly("pending", &AdlinkInterpolator::pending)
      .def_property_readonly("done", &AdlinkInterpolator::done)
      .def("record", [](AdlinkInterpolator& g, double ticks, Flag until_done) {
             check_integer("AdlinkInterpolator.record", "ticks", ticks, 0, 1e8);
             AdlinkInterpRecording r = record(g, static_cast<std::size_t>(ticks), until_done);  // GIL held
             py::dict d;
             d["t_s"] = to_array(r.t_s);
             d["pos"] = matrix(r.pos, static_cast<std::size_t>(r.dim));
             d["speed"] = to_array(r.speed);
             d["moves_done"] = to_array(r.moves_done);
             return d;
           }, py::arg("ticks"), py::arg("until_done") = false);

  m.def("plan_polyline_lookahead", [](const Arr& points, double vel, double acc, const LookAheadParams& p) {
        if (points.ndim() != 2 || points.shape(1) < 1 || points.shape(1) > 4)
          throw std::invalid_argument("plan_polyline_lookahead: points must be an (n, dim) array, dim 1..4");
        std::vector<double> v;
        {
          py::gil_scoped_release release;
          v = plan_polyline_lookahead(points.data(), static_cast<std::size_t>(points.shape(0)),
                                      static_cast<int>(points.shape(1)), vel, acc, p);
        }
        return to_array(v);
      }, py::arg("points"), py::arg("vel"), py::arg("acc"), py::arg("params"),
      "Look-ahead end speeds (unit/ms) of the polyline through `points` ((n, dim), unit) at feed vel (unit/ms)\n"
      "and acceleration acc (unit/ms^2): one per non-zero step, the last 0.");
  m.def("corner_speed_limit", [](const std::vector<double>& u_out, const std::vector<double>& u_in, double t_ms,
                                 double acc_max) {
        return corner_speed_limit(point(u_out, "u_out"), point(u_in, "u_in"), t_ms, acc_max);
      }, py::arg("u_out"), py::arg("u_in"), py::arg("t_ms"), py::arg("acc_max"),
      "The look-ahead's corner cap acc_max * t_ms / ``|u_in - u_out|`` (unit/ms) for unit tangents.");
}

}  // namespace servobench::bindings
