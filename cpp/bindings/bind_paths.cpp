// Bindings of the coordinated paths (path_segment.hpp, coord_system.hpp, lookahead.hpp, path_generator.hpp).
// Thin: coordinates in and out as NumPy arrays, the GIL released on the tick loops.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arrays.hpp"
#include "param_class.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/coord_system.hpp"
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
             "GT per-axis corner acceleration limit (AccLmt), pulse/ms^2; 0 = off")
      .field("return_to_stop_point", &PathSetup::return_to_stop_point,
             "resume away from the breakpoint returns to it (GT/GE) instead of being refused (GUC/iDEABOX)")
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
                                   const std::string& plane, double radius, bool ccw) {
            if (start.size() != end.size()) throw std::invalid_argument("PathArcRadius: start and end differ in length");
            return PathSegmentGeometry::arc_end_radius(point(start, "start"), point(end, "end"),
                                                       static_cast<int>(start.size()), plane_of(plane), radius, ccw);
          }, py::arg("start"), py::arg("end"), py::arg("plane"), py::arg("radius"), py::arg("ccw"),
          "End point and signed radius: radius > 0 the arc <= 180 deg, < 0 the arc > 180 deg (no full circle).")
      .def_static("arc_center", [](const std::vector<double>& start, const std::vector<double>& end,
                                   const std::string& plane, std::pair<double, double> offset, bool ccw) {
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
                                double syn_acc_max, double even_time_ms, bool set_origin,
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
      .def_property_readonly("da", [](const PathState& s) { return std::vector<double>(s.da.begin(), s.da.end()); });

  py::class_<PathGenerator>(m, "PathGenerator",
      "One coordinate system's path interpolator, stepped once per motion cycle (see docs/paths.md).")
      .def(py::init([](const CoordSystem& c, const PathSetup& s, const std::vector<double>& start) {
             return PathGenerator(c, s, start.empty() ? CrdPoint{} : point(start, "start"));
           }), py::arg("coords"), py::arg("setup") = PathSetup{}, py::arg("start") = std::vector<double>{})
      .def("init_lookahead", &PathGenerator::init_lookahead, py::arg("params"))
      .def("set_override", &PathGenerator::set_override, py::arg("ratio"))
      .def("set_g0_override", &PathGenerator::set_g0_override, py::arg("ratio"))
      .def("set_stop_dec", &PathGenerator::set_stop_dec, py::arg("smooth"), py::arg("abrupt"))
      .def("set_aux_position", &PathGenerator::set_aux_position, py::arg("axis"), py::arg("pos"))
      .def_property_readonly("tail", [](const PathGenerator& g) { return crd_array(g.tail(), g.coords().dim()); },
                             "start point of the next buffered segment")
      .def("push_segment", &PathGenerator::push_segment, py::arg("segment"), py::arg("vel"), py::arg("acc"),
           py::arg("vel_end") = 0.0, py::arg("g0") = false, py::arg("auto_end") = false, py::arg("stop_at_end") = false)
      .def("line", [](PathGenerator& g, const std::vector<double>& end, double vel, double acc, double vel_end, bool g0) {
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
                            bool ccw, double vel, double acc, double vel_end) {
             g.push_segment(PathSegmentGeometry::arc_end_radius(g.tail(), point_from(end, g.tail(), "end"),
                                                                g.coords().dim(), plane_of(plane), radius, ccw),
                            vel, acc, vel_end);
           }, py::arg("plane"), py::arg("end"), py::arg("radius"), py::arg("ccw"), py::arg("vel"), py::arg("acc"),
           py::arg("vel_end") = 0.0)
      .def("arc_center", [](PathGenerator& g, const std::string& plane, const std::vector<double>& end,
                            std::pair<double, double> offset, bool ccw, double vel, double acc, double vel_end) {
             g.push_segment(PathSegmentGeometry::arc_center_offset(g.tail(), point_from(end, g.tail(), "end"),
                                                                   g.coords().dim(), plane_of(plane), offset.first,
                                                                   offset.second, ccw),
                            vel, acc, vel_end);
           }, py::arg("plane"), py::arg("end"), py::arg("center_offset"), py::arg("ccw"), py::arg("vel"),
           py::arg("acc"), py::arg("vel_end") = 0.0)
      .def("buf_io", &PathGenerator::buf_io, py::arg("do_type"), py::arg("mask"), py::arg("value"))
      .def("buf_delay", &PathGenerator::buf_delay, py::arg("delay_ms"))
      .def("buf_da", &PathGenerator::buf_da, py::arg("channel"), py::arg("value"))
      .def("buf_move", &PathGenerator::buf_move, py::arg("axis"), py::arg("pos"), py::arg("vel"), py::arg("acc"),
           py::arg("modal"))
      .def("buf_gear", &PathGenerator::buf_gear, py::arg("axis"), py::arg("distance"))
      .def("set_user_seg_num", &PathGenerator::set_user_seg_num, py::arg("seg_num"))
      .def("flush", &PathGenerator::flush, "GT_CrdData(NULL): window -> FIFO; False if the FIFO filled first")
      .def("start", &PathGenerator::start)
      .def("stop", &PathGenerator::stop, py::arg("abrupt") = false)
      .def("clear", &PathGenerator::clear)
      .def("move_immediate", [](PathGenerator& g, const std::vector<double>& end, double vel, double acc) {
             g.move_immediate(point_from(end, g.state().pos, "end"), vel, acc);
           }, py::arg("end"), py::arg("vel"), py::arg("acc"))
      .def("step", &PathGenerator::step, py::return_value_policy::copy)
      .def_property_readonly("state", &PathGenerator::state, py::return_value_policy::copy)
      .def("record", [](PathGenerator& g, double ticks, bool until_done) {
             check_integer("PathGenerator.record", "ticks", ticks, 0, 1e8);
             PathRecording r;
             {
               py::gil_scoped_release release;
               r = record(g, static_cast<std::size_t>(ticks), until_done);
             }
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
           }, py::arg("ticks"), py::arg("until_done") = false,
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
      "The look-ahead's corner cap acc_max * t_ms / |u_in - u_out| (unit/ms) for unit tangents.");
}

}  // namespace servobench::bindings
