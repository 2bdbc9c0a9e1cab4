// Geometry of one coordinated-path segment: a line in 1-4 coordinates, or an arc in the XY, YZ or ZX plane
// whose other coordinates may move linearly with the arc angle (a helix).
//
// Coordinates are X, Y, Z, A (index 0..3) in the coordinate system's unit (pulse for GE / GUC-ECAT / iDEABOX,
// the user's unit for GT). Arc direction: a positive sweep is counter-clockwise seen from the positive third
// axis, by the right-hand rule, in all three planes (GT L1793, GE L1481-1486, GUC L883-886, iDEABOX
// L1374-1382); the plane coordinates are (x, y) for XY, (y, z) for YZ and (z, x) for ZX.
//
// Constructors check the geometry and throw PathGeometryError (a std::invalid_argument, ValueError in Python)
// carrying the GT/GE return code: 2 wrong arc radius (zero radius or chord), 3 line length zero, 5 end point
// or radius impossible (chord longer than the diameter, or an end point off the circle). The GUC-ECAT and
// iDEABOX cards return 7 for all of these (GUC L906, iDEABOX L1444-1446); the facades map the code.
#pragma once

#include <array>
#include <limits>
#include <stdexcept>
#include <string>

namespace servobench::motion {

constexpr int kCrdMaxDim = 4;
using CrdPoint = std::array<double, kCrdMaxDim>;

class PathGeometryError : public std::invalid_argument {
 public:
  PathGeometryError(int gt_code, const std::string& what) : std::invalid_argument(what), gt_code_(gt_code) {}
  // The GT/GE return code: 2 bad arc radius, 3 bad line length, 5 bad arc end point or radius.
  int gt_code() const { return gt_code_; }
  // The GUC-ECAT / iDEABOX return code: always 7 (parameter error).
  static constexpr int guc_code() { return 7; }

 private:
  int gt_code_;
};

enum class ArcPlane { XY = 0, YZ = 1, ZX = 2 };
const char* to_string(ArcPlane plane);
// The coordinate indices (first, second) of the plane and of its normal: XY (0, 1; 2), YZ (1, 2; 0), ZX (2, 0; 1).
int plane_axis(ArcPlane plane, int which);

enum class SegmentKind { Line = 0, Arc = 1 };

class PathSegmentGeometry {
 public:
  // A straight line from `start` to `end`, in the first `dim` coordinates (1..4; the others must agree).
  static PathSegmentGeometry line(const CrdPoint& start, const CrdPoint& end, int dim);

  // GT/GE form (GT_ArcXY, GE L3434-3443): centre (absolute, plane coordinates) and swept angle in degrees,
  // -360..360, non-zero, positive = CCW; the radius is the start point's distance from the centre. `axial`:
  // displacement of the coordinates outside the plane over the arc (0 for a plain arc; non-zero = helix).
  static PathSegmentGeometry arc_center_angle(const CrdPoint& start, int dim, ArcPlane plane, double center_1,
                                              double center_2, double angle_deg, const CrdPoint& axial = {});

  // End point and signed radius (GE GT_ArcXYP L3477-3483, GUC/iDEABOX GT_Arc..R L3894-3902): |radius| is the
  // radius; radius > 0 gives the arc <= 180 deg, radius < 0 the arc > 180 deg; `ccw` the direction. Cannot
  // describe a full circle. `end` is the full end point (its out-of-plane coordinates != start: a helix).
  static PathSegmentGeometry arc_end_radius(const CrdPoint& start, const CrdPoint& end, int dim, ArcPlane plane,
                                            double radius, bool ccw);

  // End point and centre offset from the start point (GUC/iDEABOX GT_Arc..C, L1410-1440): end == start in the
  // plane gives a full circle. The end must lie on the circle within 1 pulse (decision C6); a mismatch within
  // that is absorbed by letting the radius vary linearly along the arc, so the arc ends exactly at `end`.
  static PathSegmentGeometry arc_center_offset(const CrdPoint& start, const CrdPoint& end, int dim, ArcPlane plane,
                                               double offset_1, double offset_2, bool ccw);

  SegmentKind kind() const { return kind_; }
  int dim() const { return dim_; }
  const CrdPoint& start() const { return start_; }
  const CrdPoint& end() const { return end_; }
  double length() const { return length_; }
  // Arc data (meaningless for a line): plane, centre (plane coordinates), start radius, start angle (rad),
  // signed sweep (rad, positive = CCW).
  ArcPlane plane() const { return plane_; }
  double center(int which) const { return which == 0 ? c1_ : c2_; }
  double radius() const { return r0_; }
  double start_angle_rad() const { return theta0_; }
  double sweep_rad() const { return sweep_; }

  // Point at path length s (0..length; clamped). point_at(length()) == end() exactly.
  CrdPoint point_at(double s) const;
  // Unit tangent at path length s (the direction of travel).
  CrdPoint tangent_at(double s) const;
  // Radius of curvature of the path (infinite for a line; for a helix (r^2 + c^2)/r with c = axial rise per
  // radian): a path speed v gives a centripetal acceleration v^2 / curvature_radius().
  double curvature_radius() const;

 private:
  SegmentKind kind_ = SegmentKind::Line;
  int dim_ = 2;
  CrdPoint start_{}, end_{};
  double length_ = 0.0;
  ArcPlane plane_ = ArcPlane::XY;
  double c1_ = 0.0, c2_ = 0.0, r0_ = 0.0, r1_ = 0.0, theta0_ = 0.0, sweep_ = 0.0;
  CrdPoint axial_{};  // displacement of the out-of-plane coordinates over the arc
  CrdPoint dir_{};    // line: unit direction

  static PathSegmentGeometry make_arc(const CrdPoint& start, const CrdPoint& end, int dim, ArcPlane plane, double c1,
                                      double c2, double sweep, double r0, double r1);
};

}  // namespace servobench::motion
