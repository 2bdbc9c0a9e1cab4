// The one geometry of a path segment: a straight line, or a curve about a centre -- an arc, a helix or a conical
// spiral -- in up to D coordinates. Every vendor's line and arc is built by a named constructor of this type:
//
//  - Googol GT / GE / GUC-ECAT / iDEABOX (D = 4: X, Y, Z, A; PathSegmentGeometry): lines in 1-4 coordinates, arcs in
//    the XY, YZ or ZX plane given by centre + angle, end + signed radius or end + centre offset, the coordinates
//    outside the plane moving linearly with the angle (a helix). A positive sweep is counter-clockwise seen from the
//    positive third axis (right-hand rule) in all three planes (GT L1793, GE L1481-1486, GUC L883-886, iDEABOX
//    L1374-1382); the plane coordinates are (x, y) for XY, (y, z) for YZ and (z, x) for ZX. Errors throw
//    PathGeometryError carrying the GT/GE return code (2 wrong radius, 3 zero line, 5 impossible end point or
//    radius; GUC-ECAT / iDEABOX return 7 for all, GUC L906, iDEABOX L1444-1446).
//  - ADLINK PCI-8254/8258 (D = 6; SpaceSegment; manual section 4.8, seed 004 L2813-3063): lines in 2-6 axes, 2-D and
//    3-D arcs by centre + angle (+ normal) or centre + end point, 3-D spirals; see the constructors. Errors throw
//    std::invalid_argument naming the parameter.
//
// One representation for all of them: a curve is
//     p(psi) = c + r(psi) (cos(phi) e1 + sin(phi) e2) + axial * psi / |sweep|,   phi = sign(sweep) psi,
//     r(psi) = r0 + (r1 - r0) psi / |sweep|,   psi in [0, |sweep|],
// with c the centre (its coordinates outside the plane are the start's), e1 the unit vector centre -> start, e2 the
// unit vector a quarter turn ahead in the plane (e2 = n x e1 about the unit normal n), and `axial` the displacement
// of the coordinates outside the plane over the whole curve (the rise of a helix or spiral). The path length is the
// exact arc length of that conical spiral (closed form) and point_at(s) inverts it, so a constant path speed is a
// constant speed in space; for a constant radius psi = |sweep| s / length exactly. point_at(length()) == end().
#pragma once

#include <array>
#include <stdexcept>
#include <string>

namespace servobench::motion {

constexpr int kCrdMaxDim = 4;    // Googol coordinate systems: X, Y, Z, A
constexpr int kSpaceMaxDim = 6;  // ADLINK interpolation: up to 6 axes
using Vec3 = std::array<double, 3>;

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

// Line; Arc (a circle, a helix); Spiral (an ADLINK spiral: a rise along the normal or a radius that changes by
// more than 1 unit).
enum class SegmentKind { Line = 0, Arc = 1, Spiral = 2 };

template <int D>
class SegmentGeometry {
 public:
  using Point = std::array<double, D>;
  using Kind = SegmentKind;

  // ---- Googol forms (GT, GE, GUC-ECAT, iDEABOX) ------------------------------------------------------------------
  // A straight line from `start` to `end`, in the first `dim` coordinates (1..D; the others keep the start's). Every
  // vendor's line: Googol 1-4 coordinates, ADLINK 2-6 axes (dP = sqrt(sum dXi^2), Vi = dXi/dP V, L2829-2855). A
  // zero length throws PathGeometryError code 3 (GT/GE; 7 on GUC-ECAT/iDEABOX; ADLINK: an invalid end point).
  static SegmentGeometry line(const Point& start, const Point& end, int dim);
  // Centre (absolute, plane coordinates) and swept angle in degrees, -360..360, non-zero, positive = CCW (GT_ArcXY,
  // GE L3434-3443); the radius is the start point's distance from the centre. `axial`: displacement of the
  // coordinates outside the plane over the arc (0 for a plain arc; non-zero = helix).
  static SegmentGeometry arc_center_angle(const Point& start, int dim, ArcPlane plane, double center_1, double center_2,
                                  double angle_deg, const Point& axial = {});
  // End point and signed radius (GE GT_ArcXYP L3477-3483, GUC/iDEABOX GT_Arc..R L3894-3902): |radius| is the
  // radius; radius > 0 gives the arc <= 180 deg, radius < 0 the arc > 180 deg; `ccw` the direction. Cannot describe
  // a full circle. `end` is the full end point (its out-of-plane coordinates != start: a helix).
  static SegmentGeometry arc_end_radius(const Point& start, const Point& end, int dim, ArcPlane plane, double radius,
                                bool ccw);
  // End point and centre offset from the start point (GUC/iDEABOX GT_Arc..C, L1410-1440): end == start in the plane
  // gives a full circle. The end must lie on the circle within 1 pulse (decision C6); a mismatch within that is
  // absorbed by letting the radius vary linearly along the arc, so the arc ends exactly at `end`.
  static SegmentGeometry arc_center_offset(const Point& start, const Point& end, int dim, ArcPlane plane, double offset_1,
                                   double offset_2, bool ccw);

  // ---- ADLINK forms (PCI-8254/8258 L2813-3063) -------------------------------------------------------------------
  // A segment of zero length that stays at `start` (a point-table dwell, APS_pt_dwell L3838).
  static SegmentGeometry hold(const Point& start, int dim);
  // 2-D arcs (dim 2): centre absolute; angle in degrees (non-zero, |angle| <= 1e6, |angle| > 360 = laps), + = CCW.
  static SegmentGeometry arc2_ca(const Point& start, const Point& center, double angle_deg);
  // Centre + end: Dir >= 0 positive, <= -1 negative, Angle = theta + Dir*360 deg (L2928-2958); half and full circles
  // are refused (L2930-2933); the end must lie on the circle within 1 unit (decision C37).
  static SegmentGeometry arc2_ce(const Point& start, const Point& center, const Point& end, int dir);
  // 3-D arcs (dim 3): the normal is corrected by Gram-Schmidt against centre -> start (L2909-2911).
  static SegmentGeometry arc3_ca(const Point& start, const Point& center, const Vec3& normal, double angle_deg);
  static SegmentGeometry arc3_ce(const Point& start, const Point& center, const Point& end, int dir);
  // 3-D spirals (dim 3, L3001-3063): height along the (corrected) normal; final_radius >= 0 (decision C38).
  static SegmentGeometry spiral_ca(const Point& start, const Point& center, const Vec3& normal, double angle_deg,
                           double height, double final_radius);
  static SegmentGeometry spiral_ce(const Point& start, const Point& center, const Vec3& normal, const Point& end, int dir);

  // ---- the geometry ----------------------------------------------------------------------------------------------
  Kind kind() const { return kind_; }
  int dim() const { return dim_; }
  const Point& start() const { return start_; }
  const Point& end() const { return end_; }
  double length() const { return length_; }
  // Signed swept angle (rad, + = right-hand rule about the normal; CCW for the Googol planes); 0 for a line.
  double sweep_rad() const { return sweep_; }
  // The plane of a Googol arc (XY for an ADLINK curve), and its centre in plane coordinates.
  ArcPlane plane() const { return plane_; }
  double center(int which) const;
  // The start point's distance from the centre, and the angle (rad) of centre -> start in the plane coordinates.
  double radius() const { return r0_; }
  double start_angle_rad() const { return theta0_; }
  double start_radius() const { return r0_; }
  double end_radius() const { return r1_; }
  // The unit normal of the curve's plane (+Z for 2-D arcs and the Googol XY plane, +X for YZ, +Y for ZX).
  const Vec3& normal() const { return n_; }

  // Point at path length s (0..length; clamped). point_at(length()) == end() exactly.
  Point point_at(double s) const;
  // Unit tangent at path length s (the direction of travel; 0 for a hold).
  Point tangent_at(double s) const;
  // Radius of curvature (infinite for a line; for a helix (r^2 + c^2)/r with c = axial rise per radian, r the smaller
  // of the two radii): a path speed v gives a centripetal acceleration v^2 / curvature_radius().
  double curvature_radius() const;

 private:
  // The curve through `start` about centre c in the plane (e1 = unit centre -> start, e2 a quarter turn ahead),
  // swept by `sweep` rad, radius r0 -> r1, `axial` the displacement outside the plane; `end` exact if given.
  static SegmentGeometry make_curve(Kind kind, const Point& start, int dim, const Point& c, const Point& e1, const Point& e2,
                            double sweep, double r0, double r1, const Point& axial, const Point* end);
  // A Googol arc in `plane` about (c1, c2) from `start` to the exact `end`: the frame's e1 is scaled by frame_r, the
  // radius runs r0 -> r1, the coordinates outside the plane move by end - start (a helix), theta0 the start's angle.
  static SegmentGeometry googol_arc(const Point& start, const Point& end, int dim, ArcPlane plane, double c1, double c2,
                                    double frame_r, double sweep, double r0, double r1);
  double length_to(double psi) const;  // arc length from the start to |angle| psi
  double psi_at(double s) const;       // its inverse

  Kind kind_ = Kind::Line;
  int dim_ = 2;
  Point start_{}, end_{}, dir_{};
  double length_ = 0.0;
  ArcPlane plane_ = ArcPlane::XY;
  Point c_{}, e1_{}, e2_{}, axial_{};
  Vec3 n_{0, 0, 1};
  double r0_ = 0.0, r1_ = 0.0, theta0_ = 0.0, sweep_ = 0.0, k_ = 0.0, c2_ = 0.0;
};

extern template class SegmentGeometry<kCrdMaxDim>;
extern template class SegmentGeometry<kSpaceMaxDim>;

// The Googol coordinate systems' segments (X, Y, Z, A) and the ADLINK interpolation's (up to 6 axes).
using PathSegmentGeometry = SegmentGeometry<kCrdMaxDim>;
using CrdPoint = PathSegmentGeometry::Point;
using SpaceSegment = SegmentGeometry<kSpaceMaxDim>;
using SpacePoint = SpaceSegment::Point;

}  // namespace servobench::motion
