#include "servobench/motion/path_segment.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

void check_dim(const char* owner, int dim, int min_dim) {
  if (dim < min_dim || dim > kCrdMaxDim)
    throw_invalid(owner, "dim", dim, "is outside the allowed range " + std::to_string(min_dim) + "..4 (X, Y, Z, A)");
}

void check_point(const char* owner, const char* field, const CrdPoint& p) {
  for (double v : p)
    if (!std::isfinite(v)) throw_invalid(owner, field, v, "is not a finite coordinate");
}

[[noreturn]] void geometry_error(int code, const std::string& what) {
  throw PathGeometryError(code, what + " (GT/GE return code " + std::to_string(code) +
                                    "; GUC-ECAT/iDEABOX return code 7)");
}
}  // namespace

const char* to_string(ArcPlane plane) {
  switch (plane) {
    case ArcPlane::XY: return "XY";
    case ArcPlane::YZ: return "YZ";
    case ArcPlane::ZX: return "ZX";
  }
  return "?";
}

int plane_axis(ArcPlane plane, int which) {
  static const int table[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  return table[static_cast<int>(plane)][which];
}

PathSegmentGeometry PathSegmentGeometry::line(const CrdPoint& start, const CrdPoint& end, int dim) {
  check_dim("PathLine", dim, 1);
  check_point("PathLine", "start", start);
  check_point("PathLine", "end", end);
  PathSegmentGeometry g;
  g.kind_ = SegmentKind::Line;
  g.dim_ = dim;
  g.start_ = start;
  g.end_ = start;
  double sq = 0.0;
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    g.end_[i] = end[i];
    sq += (end[i] - start[i]) * (end[i] - start[i]);
  }
  g.length_ = std::sqrt(sq);
  if (!(g.length_ > 0.0)) geometry_error(3, "PathLine: the line has zero length (end point = start point)");
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    g.dir_[i] = (g.end_[i] - start[i]) / g.length_;
  }
  return g;
}

PathSegmentGeometry PathSegmentGeometry::make_arc(const CrdPoint& start, const CrdPoint& end, int dim, ArcPlane plane,
                                                  double c1, double c2, double sweep, double r0, double r1) {
  PathSegmentGeometry g;
  g.kind_ = SegmentKind::Arc;
  g.dim_ = dim;
  g.plane_ = plane;
  g.start_ = start;
  g.end_ = start;
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  g.c1_ = c1;
  g.c2_ = c2;
  g.r0_ = r0;
  g.r1_ = r1;
  g.sweep_ = sweep;
  g.theta0_ = std::atan2(start[b] - c2, start[a] - c1);
  double axial_sq = 0.0;
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    g.end_[i] = end[i];
    if (i != a && i != b) {
      g.axial_[i] = end[i] - start[i];
      axial_sq += g.axial_[i] * g.axial_[i];
    }
  }
  const double rm = 0.5 * (r0 + r1);
  g.length_ = std::sqrt(rm * std::fabs(sweep) * rm * std::fabs(sweep) + axial_sq + (r1 - r0) * (r1 - r0));
  return g;
}

PathSegmentGeometry PathSegmentGeometry::arc_center_angle(const CrdPoint& start, int dim, ArcPlane plane,
                                                          double center_1, double center_2, double angle_deg,
                                                          const CrdPoint& axial) {
  const char* o = "PathArcCenterAngle";
  check_dim(o, dim, plane == ArcPlane::XY ? 2 : 3);
  check_point(o, "start", start);
  check_point(o, "axial", axial);
  check_range(o, "angle_deg", angle_deg, -360.0, 360.0, "degrees, sign = direction; GE L3434-3443");
  if (angle_deg == 0.0) throw_invalid(o, "angle_deg", angle_deg, "must be non-zero (an arc of no angle)");
  if (!std::isfinite(center_1) || !std::isfinite(center_2))
    throw_invalid(o, "center", std::isfinite(center_1) ? center_2 : center_1, "is not a finite coordinate");
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  const double r = std::hypot(start[a] - center_1, start[b] - center_2);
  if (!(r > 0.0)) geometry_error(2, std::string(o) + ": the start point is the centre (radius 0)");
  const double sweep = angle_deg * kPi / 180.0;
  const double th1 = std::atan2(start[b] - center_2, start[a] - center_1) + sweep;
  CrdPoint end = start;
  end[a] = center_1 + r * std::cos(th1);
  end[b] = center_2 + r * std::sin(th1);
  if (std::fabs(angle_deg) == 360.0) end[a] = start[a], end[b] = start[b];  // a full circle closes exactly
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (i != a && i != b) end[i] = start[i] + axial[i];
  }
  return make_arc(start, end, dim, plane, center_1, center_2, sweep, r, r);
}

PathSegmentGeometry PathSegmentGeometry::arc_end_radius(const CrdPoint& start, const CrdPoint& end, int dim,
                                                        ArcPlane plane, double radius, bool ccw) {
  const char* o = "PathArcRadius";
  check_dim(o, dim, plane == ArcPlane::XY ? 2 : 3);
  check_point(o, "start", start);
  check_point(o, "end", end);
  if (!std::isfinite(radius)) throw_invalid(o, "radius", radius, "is not a finite number");
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  const double dx = end[a] - start[a], dy = end[b] - start[b];
  const double chord = std::hypot(dx, dy);
  const double r = std::fabs(radius);
  if (!(r > 0.0)) geometry_error(2, std::string(o) + ": radius 0");
  if (!(chord > 0.0))
    geometry_error(2, std::string(o) + ": the end point equals the start point (chord 0; the radius form cannot "
                                       "describe a full circle)");
  const double half = 0.5 * chord;
  if (half > r * (1.0 + 1e-12))
    geometry_error(5, std::string(o) + ": chord " + format_value(chord) + " is longer than the diameter " +
                          format_value(2.0 * r));
  const double h = std::sqrt(std::fmax(r * r - half * half, 0.0));
  const bool major = radius < 0.0;
  // The centre lies left of the chord (seen along start -> end) for a CCW minor or a CW major arc.
  const double side = (ccw != major) ? 1.0 : -1.0;
  const double c1 = start[a] + 0.5 * dx - side * h * dy / chord;
  const double c2 = start[b] + 0.5 * dy + side * h * dx / chord;
  const double th0 = std::atan2(start[b] - c2, start[a] - c1);
  const double th1 = std::atan2(end[b] - c2, end[a] - c1);
  double sweep = th1 - th0;
  if (ccw) {
    while (sweep <= 0.0) sweep += kTwoPi;
    while (sweep > kTwoPi) sweep -= kTwoPi;
  } else {
    while (sweep >= 0.0) sweep -= kTwoPi;
    while (sweep < -kTwoPi) sweep += kTwoPi;
  }
  // A semicircle (h = 0) is both minor and major; otherwise the sweep must match the sign of the radius.
  if (h > 0.0 && (std::fabs(sweep) > kPi) != major) sweep = ccw ? kTwoPi - std::fabs(sweep) : -(kTwoPi - std::fabs(sweep));
  return make_arc(start, end, dim, plane, c1, c2, sweep, r, r);
}

PathSegmentGeometry PathSegmentGeometry::arc_center_offset(const CrdPoint& start, const CrdPoint& end, int dim,
                                                           ArcPlane plane, double offset_1, double offset_2,
                                                           bool ccw) {
  const char* o = "PathArcCenter";
  check_dim(o, dim, plane == ArcPlane::XY ? 2 : 3);
  check_point(o, "start", start);
  check_point(o, "end", end);
  if (!std::isfinite(offset_1) || !std::isfinite(offset_2))
    throw_invalid(o, "center_offset", std::isfinite(offset_1) ? offset_2 : offset_1, "is not a finite number");
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  const double c1 = start[a] + offset_1, c2 = start[b] + offset_2;
  const double r0 = std::hypot(offset_1, offset_2);
  if (!(r0 > 0.0)) geometry_error(2, std::string(o) + ": the centre offset is zero (radius 0)");
  const double r1 = std::hypot(end[a] - c1, end[b] - c2);
  if (std::fabs(r1 - r0) > 1.0)
    geometry_error(5, std::string(o) + ": the end point is " + format_value(r1) +
                          " from the centre but the start point is " + format_value(r0) +
                          " (they must agree within 1 pulse)");
  const bool full = end[a] == start[a] && end[b] == start[b];
  double sweep;
  if (full) {
    sweep = ccw ? kTwoPi : -kTwoPi;
  } else {
    sweep = std::atan2(end[b] - c2, end[a] - c1) - std::atan2(start[b] - c2, start[a] - c1);
    if (ccw) {
      while (sweep <= 0.0) sweep += kTwoPi;
    } else {
      while (sweep >= 0.0) sweep -= kTwoPi;
    }
  }
  return make_arc(start, end, dim, plane, c1, c2, sweep, r0, r1);
}

CrdPoint PathSegmentGeometry::point_at(double s) const {
  if (s <= 0.0) return start_;
  if (s >= length_) return end_;
  const double u = s / length_;
  if (kind_ == SegmentKind::Line) {
    CrdPoint p = start_;
    for (int k = 0; k < dim_; ++k) {
      const auto i = static_cast<std::size_t>(k);
      p[i] = start_[i] + dir_[i] * s;
    }
    return p;
  }
  const auto a = static_cast<std::size_t>(plane_axis(plane_, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane_, 1));
  const double th = theta0_ + sweep_ * u;
  const double r = r0_ + (r1_ - r0_) * u;
  CrdPoint p = start_;
  for (int k = 0; k < dim_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    p[i] = start_[i] + axial_[i] * u;
  }
  p[a] = c1_ + r * std::cos(th);
  p[b] = c2_ + r * std::sin(th);
  return p;
}

CrdPoint PathSegmentGeometry::tangent_at(double s) const {
  if (kind_ == SegmentKind::Line) return dir_;
  const double u = std::fmin(std::fmax(s / length_, 0.0), 1.0);
  const auto a = static_cast<std::size_t>(plane_axis(plane_, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane_, 1));
  const double th = theta0_ + sweep_ * u;
  const double r = r0_ + (r1_ - r0_) * u;
  CrdPoint t{};
  double sq = 0.0;
  for (int k = 0; k < dim_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    t[i] = axial_[i];
  }
  t[a] = (r1_ - r0_) * std::cos(th) - r * sweep_ * std::sin(th);
  t[b] = (r1_ - r0_) * std::sin(th) + r * sweep_ * std::cos(th);
  for (double v : t) sq += v * v;
  const double n = std::sqrt(sq);
  for (double& v : t) v /= n;
  return t;
}

double PathSegmentGeometry::curvature_radius() const {
  if (kind_ == SegmentKind::Line) return std::numeric_limits<double>::infinity();
  double axial_sq = 0.0;
  for (double v : axial_) axial_sq += v * v;
  const double r = std::fmin(r0_, r1_);
  const double c = std::sqrt(axial_sq) / std::fabs(sweep_);
  return (r * r + c * c) / r;
}

}  // namespace servobench::motion
