// ADLINK interpolation geometry (PCI-8254/8258 manual §4.8, seed 004 L2813-3063; digest adlink.md §6.7):
// straight lines in 2-6 axes, 2-D arcs, 3-D arcs and 3-D spirals (conical helices), each in the axes of the
// interpolation's axis array (first axis = reference axis; its profile is the path's, see
// adlink_interpolation.hpp).
//
//  - line: dP = sqrt(sum dXi^2), axis velocity Vi = dXi/dP * V (L2829-2855);
//  - arc by centre + angle (+ normal in 3-D, L2886-2926): the angle in degrees, sign = direction by the
//    right-hand rule about the normal (2-D: about +Z, i.e. CCW positive), |angle| > 360 = several laps (720 =
//    2 laps); a normal not orthogonal to centre->start is corrected by Gram-Schmidt (L2911);
//  - arc by centre + end point (L2928-2958): the end is exact; Dir >= 0 positive, <= -1 negative, Angle =
//    theta + Dir*360 deg, theta the positive angle from start to end (3-D: about the normal (start-c) x (end-c),
//    so theta < 180; 2-D: CCW, 0 < theta < 360). Half and full circles are refused (L2930-2933: the plane or
//    the sweep is undefined); the end must lie on the circle within 1 unit (decision C37);
//  - spiral by centre + angle (L3001-3035): centre, angle projected on the start circle's plane, normal of that
//    plane, height (the rise along the normal over the spiral) and final radius: a conical spiral whose
//    radius and rise vary linearly with the angle (decision C38);
//  - spiral by centre + end (L3037-3063): centre, normal, end point, Dir as for arcs (theta measured about the
//    normal in [0, 360)); radius and rise from the end point.
// Path length is the exact arc length of the conical spiral (closed form), and point_at(s) inverts it, so a
// constant path speed is a constant speed in space. Errors: std::invalid_argument naming the parameter.
#pragma once

#include <array>

namespace servobench::motion {

constexpr int kSpaceMaxDim = 6;
using SpacePoint = std::array<double, kSpaceMaxDim>;
using Vec3 = std::array<double, 3>;

class SpaceSegment {
 public:
  enum class Kind { Line, Arc, Spiral };

  // A line from start to end in the first `dim` axes (2..6).
  static SpaceSegment line(const SpacePoint& start, const SpacePoint& end, int dim);
  // A segment of zero length that stays at `start` (a point-table dwell, ADLINK APS_pt_dwell L3838).
  static SpaceSegment hold(const SpacePoint& start, int dim);
  // 2-D arcs (dim 2): centre absolute; angle in degrees (non-zero, |angle| <= 360000), + = CCW.
  static SpaceSegment arc2_ca(const SpacePoint& start, const SpacePoint& center, double angle_deg);
  static SpaceSegment arc2_ce(const SpacePoint& start, const SpacePoint& center, const SpacePoint& end, int dir);
  // 3-D arcs (dim 3).
  static SpaceSegment arc3_ca(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                              double angle_deg);
  static SpaceSegment arc3_ce(const SpacePoint& start, const SpacePoint& center, const SpacePoint& end, int dir);
  // 3-D spirals (dim 3): height along the (corrected) normal; final_radius >= 0.
  static SpaceSegment spiral_ca(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                                double angle_deg, double height, double final_radius);
  static SpaceSegment spiral_ce(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                                const SpacePoint& end, int dir);

  Kind kind() const { return kind_; }
  int dim() const { return dim_; }
  const SpacePoint& start() const { return start_; }
  const SpacePoint& end() const { return end_; }
  double length() const { return length_; }
  // Signed swept angle (rad, + = right-hand rule about normal()); 0 for a line.
  double sweep_rad() const { return sweep_; }
  // The corrected unit normal (arcs, spirals; +Z for 2-D arcs).
  const Vec3& normal() const { return n_; }
  double start_radius() const { return r0_; }
  double end_radius() const { return r1_; }
  // Point at path length s (clamped to 0..length); point_at(length()) == end() exactly.
  SpacePoint point_at(double s) const;
  // Unit tangent (direction of travel) at path length s.
  SpacePoint tangent_at(double s) const;

 private:
  static SpaceSegment make_curve(const SpacePoint& start, int dim, const Vec3& c, const Vec3& n, double sweep,
                                 double r1, double height, const SpacePoint* exact_end);
  double length_to(double psi) const;  // arc length from the start to |angle| psi
  double psi_at(double s) const;       // its inverse

  Kind kind_ = Kind::Line;
  int dim_ = 2;
  SpacePoint start_{}, end_{}, dir_{};
  double length_ = 0.0;
  Vec3 c_{}, n_{0, 0, 1}, e1_{}, e2_{};
  double r0_ = 0.0, r1_ = 0.0, sweep_ = 0.0, height_ = 0.0, k_ = 0.0, c2_ = 0.0;
};

}  // namespace servobench::motion
