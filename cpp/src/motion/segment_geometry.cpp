#include "servobench/motion/segment_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

template <class P>
Vec3 v3(const P& p) { return {p[0], p[1], p[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scale(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }

template <class P>
void check_coords(const char* o, const char* field, const P& p, int dim) {
  for (int k = 0; k < dim; ++k)
    if (!std::isfinite(p[static_cast<std::size_t>(k)]))
      throw_invalid(o, field, p[static_cast<std::size_t>(k)], "is not a finite coordinate");
}

[[noreturn]] void geometry_error(int code, const std::string& what) {
  throw PathGeometryError(code, what + " (GT/GE return code " + std::to_string(code) +
                                    "; GUC-ECAT/iDEABOX return code 7)");
}

// ---- Googol checks
void check_googol_dim(const char* o, int dim, int min_dim, int max_dim) {
  if (dim < min_dim || dim > max_dim)
    throw_invalid(o, "dim", dim, "is outside the allowed range " + std::to_string(min_dim) + ".." +
                                     std::to_string(max_dim) + " (X, Y, Z, A)");
}

// ---- ADLINK checks
void check_angle(const char* o, double angle_deg) {
  check_range(o, "angle_deg", angle_deg, -1e6, 1e6, "degrees, sign = direction, |angle| > 360 = laps; ADLINK L2921");
  if (angle_deg == 0.0) throw_invalid(o, "angle_deg", angle_deg, "must be non-zero (an arc of no angle)");
}

void check_dir(const char* o, int dir) {
  check_integer(o, "dir", dir, -32768, 32767, "I16: >= 0 positive, <= -1 negative, Angle = theta + Dir*360; ADLINK L2943-2958");
}

void check_end_radius(const char* o, double r0, double r1) {
  if (std::fabs(r1 - r0) > 1.0)
    throw_invalid(o, "end", r1, "is " + format_value(r1) + " from the centre but the start is " + format_value(r0) +
                                    " (they must agree within 1 unit, decision C37)");
}

// The normal corrected by Gram-Schmidt against centre -> start (ADLINK L2909-2911), unit length.
Vec3 corrected_normal(const char* o, const Vec3& n, const Vec3& u) {
  const double nn = norm(n);
  if (!(nn > 0.0) || !std::isfinite(nn)) throw_invalid(o, "normal", nn, "must be a non-zero finite vector");
  const double uu = norm(u);
  Vec3 m = sub(n, scale(u, dot(n, u) / (uu * uu)));
  const double mm = norm(m);
  if (!(mm > 1e-12 * nn))
    throw_invalid(o, "normal", nn, "is parallel to centre -> start: no circle plane (ADLINK L2911)");
  return scale(m, 1.0 / mm);
}

template <class P>
Vec3 center3(const char* o, const P& start, const P& center, int dim) {
  check_coords(o, "start", start, dim);
  check_coords(o, "center", center, dim);
  Vec3 c = v3(center), s = v3(start);
  if (dim == 2) c[2] = s[2] = 0.0;
  if (!(norm(sub(s, c)) > 0.0)) throw_invalid(o, "center", 0.0, "is the start point (radius 0)");
  return c;
}

// An ADLINK curve's frame as D-vectors: centre (the start's coordinates beyond the third), e1 = unit centre ->
// start, e2 = n x e1, and the rise `height` along n as the axial displacement.
template <class P>
void adlink_frame(const P& start, int dim, const Vec3& c, const Vec3& n, double height, P* cp, P* e1, P* e2, P* axial) {
  Vec3 s3 = v3(start);
  if (dim == 2) s3[2] = 0.0;
  const Vec3 u = sub(s3, c);
  const double r0 = norm(u);
  const Vec3 a = scale(u, 1.0 / r0), b = cross(n, a);
  *cp = start;
  *e1 = P{};
  *e2 = P{};
  *axial = P{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (static_cast<int>(i) >= dim) break;
    (*cp)[i] = c[i];
    (*e1)[i] = a[i];
    (*e2)[i] = b[i];
    (*axial)[i] = height * n[i];
  }
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

// ---- lines ---------------------------------------------------------------------------------------------------------

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::line(const Point& start, const Point& end, int dim) {
  check_googol_dim("PathLine", dim, 1, D);
  check_coords("PathLine", "start", start, D);
  check_coords("PathLine", "end", end, D);
  SegmentGeometry g;
  g.kind_ = Kind::Line;
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

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::hold(const Point& start, int dim) {
  check_integer("AdlinkDwell", "dim", dim, 2, D, "axes; ADLINK L2817, L2829");
  check_coords("AdlinkDwell", "start", start, dim);
  SegmentGeometry g;
  g.kind_ = Kind::Line;
  g.dim_ = dim;
  g.start_ = start;
  g.end_ = start;
  g.length_ = 0.0;  // dir_ stays 0: point_at = start, tangent_at = 0
  return g;
}

// ---- the curve -----------------------------------------------------------------------------------------------------

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::make_curve(Kind kind, const Point& start, int dim, const Point& c,
                                                  const Point& e1, const Point& e2, double sweep, double r0, double r1,
                                                  const Point& axial, const Point* end) {
  SegmentGeometry g;
  g.kind_ = kind;
  g.dim_ = dim;
  g.start_ = start;
  g.c_ = c;
  g.e1_ = e1;
  g.e2_ = e2;
  g.axial_ = axial;
  g.r0_ = r0;
  g.r1_ = r1;
  g.sweep_ = sweep;
  const double th = std::fabs(sweep);
  g.k_ = (r1 - r0) / th;
  double axial_sq = 0.0;
  for (double v : axial) axial_sq += v * v;
  g.c2_ = g.k_ * g.k_ + axial_sq / (th * th);
  g.length_ = g.length_to(th);
  if (end != nullptr) {
    g.end_ = *end;
  } else {
    g.end_ = start;
    const double ph = sweep > 0 ? th : -th;
    for (int k = 0; k < dim; ++k) {
      const auto i = static_cast<std::size_t>(k);
      g.end_[i] = c[i] + r1 * (std::cos(ph) * e1[i] + std::sin(ph) * e2[i]) + axial[i];
    }
  }
  return g;
}

template <int D>
double SegmentGeometry<D>::length_to(double psi) const {
  // ds/dpsi = sqrt(r^2 + c^2), r = r0 + k psi, c^2 = k^2 + (|axial| / |sweep|)^2.
  const double r = r0_ + k_ * psi;
  if (std::fabs(k_) * std::fabs(sweep_) <= 1e-12 * (r0_ + std::fabs(r1_) + 1.0)) return psi * std::sqrt(r0_ * r0_ + c2_);
  const double c = std::sqrt(c2_);
  auto F = [c](double x) { return 0.5 * (x * std::sqrt(x * x + c * c) + c * c * std::asinh(x / c)); };
  return (F(r) - F(r0_)) / k_;
}

template <int D>
double SegmentGeometry<D>::psi_at(double s) const {
  const double th = std::fabs(sweep_);
  double psi = th * s / length_;
  // A constant radius is a constant speed in the angle: the first guess is the answer.
  if (std::fabs(k_) * th <= 1e-12 * (r0_ + std::fabs(r1_) + 1.0)) return psi;
  for (int it = 0; it < 50; ++it) {
    const double r = r0_ + k_ * psi;
    const double d = (length_to(psi) - s) / std::sqrt(r * r + c2_);
    psi = std::min(std::max(psi - d, 0.0), th);
    if (std::fabs(d) <= 1e-14 * th) break;
  }
  return psi;
}

template <int D>
typename SegmentGeometry<D>::Point SegmentGeometry<D>::point_at(double s) const {
  if (s <= 0.0) return start_;
  if (s >= length_) return end_;
  Point p = start_;
  if (kind_ == Kind::Line) {
    for (int k = 0; k < dim_; ++k) {
      const auto i = static_cast<std::size_t>(k);
      p[i] = start_[i] + dir_[i] * s;
    }
    return p;
  }
  const double th = std::fabs(sweep_);
  const double psi = psi_at(s);
  const double ph = sweep_ > 0 ? psi : -psi;
  const double r = r0_ + k_ * psi;
  const double u = psi / th;
  const double cs = std::cos(ph), sn = std::sin(ph);
  for (int k = 0; k < dim_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    p[i] = c_[i] + r * (cs * e1_[i] + sn * e2_[i]) + axial_[i] * u;
  }
  return p;
}

template <int D>
typename SegmentGeometry<D>::Point SegmentGeometry<D>::tangent_at(double s) const {
  if (kind_ == Kind::Line) return dir_;
  const double th = std::fabs(sweep_);
  const double psi = psi_at(std::min(std::max(s, 0.0), length_));
  const double sg = sweep_ > 0 ? 1.0 : -1.0;
  const double ph = sg * psi;
  const double r = r0_ + k_ * psi;
  const double cs = std::cos(ph), sn = std::sin(ph);
  Point t{};
  double sq = 0.0;
  for (int k = 0; k < dim_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    t[i] = k_ * (cs * e1_[i] + sn * e2_[i]) + r * sg * (-sn * e1_[i] + cs * e2_[i]) + axial_[i] / th;
    sq += t[i] * t[i];
  }
  const double nn = std::sqrt(sq);
  for (double& v : t) v /= nn;
  return t;
}

template <int D>
double SegmentGeometry<D>::curvature_radius() const {
  if (kind_ == Kind::Line) return std::numeric_limits<double>::infinity();
  double axial_sq = 0.0;
  for (double v : axial_) axial_sq += v * v;
  const double r = std::fmin(r0_, r1_);
  const double c = std::sqrt(axial_sq) / std::fabs(sweep_);
  return (r * r + c * c) / r;
}

template <int D>
double SegmentGeometry<D>::center(int which) const {
  if (kind_ == Kind::Line) return 0.0;
  return c_[static_cast<std::size_t>(plane_axis(plane_, which == 0 ? 0 : 1))];
}

// ---- Googol arcs ---------------------------------------------------------------------------------------------------
namespace {
// A Googol arc in `plane` about (c1, c2): the D-vectors of its frame. The coordinates outside the plane sit at the
// start's and move by end - start over the arc (the helix's axial displacement).
template <class P>
void googol_frame(const P& start, const P& end, int dim, ArcPlane plane, double c1, double c2, double r0, P* cp,
                  P* e1, P* e2, P* axial) {
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  *cp = start;
  (*cp)[a] = c1;
  (*cp)[b] = c2;
  *e1 = P{};
  *e2 = P{};
  *axial = P{};
  (*e1)[a] = (start[a] - c1) / r0;
  (*e1)[b] = (start[b] - c2) / r0;
  // A quarter turn ahead, counter-clockwise seen from the positive third axis: (x, y) -> (-y, x) in plane coords.
  (*e2)[a] = -(*e1)[b];
  (*e2)[b] = (*e1)[a];
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (i != a && i != b) (*axial)[i] = end[i] - start[i];
  }
}

Vec3 plane_normal(ArcPlane plane) {
  Vec3 n{0, 0, 0};
  n[static_cast<std::size_t>(plane_axis(plane, 2))] = 1.0;
  return n;
}
}  // namespace

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::googol_arc(const Point& start, const Point& end, int dim, ArcPlane plane,
                                                  double c1, double c2, double frame_r, double sweep, double r0,
                                                  double r1) {
  Point c, e1, e2, ax;
  googol_frame(start, end, dim, plane, c1, c2, frame_r, &c, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(Kind::Arc, start, dim, c, e1, e2, sweep, r0, r1, ax, &end);
  g.plane_ = plane;
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  g.theta0_ = std::atan2(start[b] - c2, start[a] - c1);
  g.n_ = plane_normal(plane);
  return g;
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc_center_angle(const Point& start, int dim, ArcPlane plane, double center_1,
                                                        double center_2, double angle_deg, const Point& axial) {
  const char* o = "PathArcCenterAngle";
  check_googol_dim(o, dim, plane == ArcPlane::XY ? 2 : 3, std::min(D, kCrdMaxDim));
  check_coords(o, "start", start, D);
  check_coords(o, "axial", axial, D);
  check_range(o, "angle_deg", angle_deg, -360.0, 360.0, "degrees, sign = direction; GE L3434-3443");
  if (angle_deg == 0.0) throw_invalid(o, "angle_deg", angle_deg, "must be non-zero (an arc of no angle)");
  if (!std::isfinite(center_1) || !std::isfinite(center_2))
    throw_invalid(o, "center", std::isfinite(center_1) ? center_2 : center_1, "is not a finite coordinate");
  const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
  const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
  const double r = std::hypot(start[a] - center_1, start[b] - center_2);
  if (!(r > 0.0)) geometry_error(2, std::string(o) + ": the start point is the centre (radius 0)");
  const double sweep = angle_deg * kPi / 180.0;
  const double th0 = std::atan2(start[b] - center_2, start[a] - center_1);
  const double th1 = th0 + sweep;
  Point end = start;
  end[a] = center_1 + r * std::cos(th1);
  end[b] = center_2 + r * std::sin(th1);
  if (std::fabs(angle_deg) == 360.0) end[a] = start[a], end[b] = start[b];  // a full circle closes exactly
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (i != a && i != b) end[i] = start[i] + axial[i];
  }
  return googol_arc(start, end, dim, plane, center_1, center_2, r, sweep, r, r);
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc_end_radius(const Point& start, const Point& end, int dim, ArcPlane plane,
                                                      double radius, bool ccw) {
  const char* o = "PathArcRadius";
  check_googol_dim(o, dim, plane == ArcPlane::XY ? 2 : 3, std::min(D, kCrdMaxDim));
  check_coords(o, "start", start, D);
  check_coords(o, "end", end, D);
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
  Point e = start;
  for (int k = 0; k < dim; ++k) e[static_cast<std::size_t>(k)] = end[static_cast<std::size_t>(k)];
  const double r0 = std::hypot(start[a] - c1, start[b] - c2);
  return googol_arc(start, e, dim, plane, c1, c2, r0, sweep, r, r);
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc_center_offset(const Point& start, const Point& end, int dim, ArcPlane plane,
                                                         double offset_1, double offset_2, bool ccw) {
  const char* o = "PathArcCenter";
  check_googol_dim(o, dim, plane == ArcPlane::XY ? 2 : 3, std::min(D, kCrdMaxDim));
  check_coords(o, "start", start, D);
  check_coords(o, "end", end, D);
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
  Point e = start;
  for (int k = 0; k < dim; ++k) e[static_cast<std::size_t>(k)] = end[static_cast<std::size_t>(k)];
  return googol_arc(start, e, dim, plane, c1, c2, r0, sweep, r0, r1);
}

// ---- ADLINK arcs and spirals ---------------------------------------------------------------------------------------

namespace {
// Arc when the radius holds (within 1 unit) and nothing rises; otherwise a spiral.
SegmentKind adlink_kind(double r0, double r1, double height) {
  return (height != 0.0 || std::fabs(r1 - r0) > 1.0) ? SegmentKind::Spiral : SegmentKind::Arc;
}
}  // namespace

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc2_ca(const Point& start, const Point& center, double angle_deg) {
  const char* o = "AdlinkArc2CenterAngle";
  check_angle(o, angle_deg);
  const Vec3 c = center3(o, start, center, 2);
  const double r = std::hypot(start[0] - c[0], start[1] - c[1]);
  Point cp, e1, e2, ax;
  adlink_frame(start, 2, c, {0, 0, 1}, 0.0, &cp, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(adlink_kind(r, r, 0.0), start, 2, cp, e1, e2, angle_deg * kPi / 180.0, r, r, ax,
                                 nullptr);
  return g;
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc3_ca(const Point& start, const Point& center, const Vec3& normal,
                                               double angle_deg) {
  const char* o = "AdlinkArc3CenterAngle";
  check_angle(o, angle_deg);
  const Vec3 c = center3(o, start, center, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  const double r = norm(u);
  Point cp, e1, e2, ax;
  adlink_frame(start, 3, c, n, 0.0, &cp, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(adlink_kind(r, r, 0.0), start, 3, cp, e1, e2, angle_deg * kPi / 180.0, r, r, ax,
                                 nullptr);
  g.n_ = n;
  return g;
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc2_ce(const Point& start, const Point& center, const Point& end, int dir) {
  const char* o = "AdlinkArc2CenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 2);
  check_coords(o, "end", end, 2);
  const Vec3 u{start[0] - c[0], start[1] - c[1], 0}, w{end[0] - c[0], end[1] - c[1], 0};
  const double r0 = norm(u), r1 = norm(w);
  check_end_radius(o, r0, r1);
  double th = std::atan2(cross(u, w)[2], dot(u, w));
  if (th < 0) th += kTwoPi;
  if (r1 == 0.0 || std::fabs(th) < 1e-9 || std::fabs(th - kPi) < 1e-9 || std::fabs(th - kTwoPi) < 1e-9)
    throw_invalid(o, "end", th * 180.0 / kPi,
                  "gives a half or full circle, which the centre-end form cannot execute (ADLINK L2930-2933)");
  Point e = start;
  e[0] = end[0];
  e[1] = end[1];
  Point cp, e1, e2, ax;
  adlink_frame(start, 2, c, {0, 0, 1}, 0.0, &cp, &e1, &e2, &ax);
  return make_curve(adlink_kind(r0, r1, 0.0), start, 2, cp, e1, e2, th + dir * kTwoPi, r0, r1, ax, &e);
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::arc3_ce(const Point& start, const Point& center, const Point& end, int dir) {
  const char* o = "AdlinkArc3CenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 3);
  check_coords(o, "end", end, 3);
  const Vec3 u = sub(v3(start), c), w = sub(v3(end), c);
  const double r0 = norm(u), r1 = norm(w);
  check_end_radius(o, r0, r1);
  const Vec3 x = cross(u, w);
  const double sx = norm(x);
  if (!(r1 > 0.0) || sx <= 1e-9 * r0 * r1)
    throw_invalid(o, "end", sx, "is collinear with the centre and the start: a half or full circle, which the "
                                "centre-end form cannot execute (ADLINK L2930-2933)");
  const double th = std::atan2(sx, dot(u, w));
  Point e = start;
  for (std::size_t i = 0; i < 3; ++i) e[i] = end[i];
  const Vec3 n = scale(x, 1.0 / sx);
  Point cp, e1, e2, ax;
  adlink_frame(start, 3, c, n, 0.0, &cp, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(adlink_kind(r0, r1, 0.0), start, 3, cp, e1, e2, th + dir * kTwoPi, r0, r1, ax, &e);
  g.n_ = n;
  return g;
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::spiral_ca(const Point& start, const Point& center, const Vec3& normal,
                                                 double angle_deg, double height, double final_radius) {
  const char* o = "AdlinkSpiralCenterAngle";
  check_angle(o, angle_deg);
  check_range(o, "height", height, -1e12, 1e12, "relative cone height along the normal; ADLINK L3013");
  check_range(o, "final_radius", final_radius, 0, 1e12, "radius at the end point; ADLINK L3013");
  const Vec3 c = center3(o, start, center, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  const double r0 = norm(u);
  Point cp, e1, e2, ax;
  adlink_frame(start, 3, c, n, height, &cp, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(adlink_kind(r0, final_radius, height), start, 3, cp, e1, e2,
                                 angle_deg * kPi / 180.0, r0, final_radius, ax, nullptr);
  g.n_ = n;
  return g;
}

template <int D>
SegmentGeometry<D> SegmentGeometry<D>::spiral_ce(const Point& start, const Point& center, const Vec3& normal,
                                                 const Point& end, int dir) {
  const char* o = "AdlinkSpiralCenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 3);
  check_coords(o, "end", end, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  const Vec3 full = sub(v3(end), c);
  const double h = dot(full, n);
  const Vec3 w = sub(full, scale(n, h));
  const double r1 = norm(w);
  const Vec3 a = scale(u, 1.0 / norm(u)), b = cross(n, a);
  double th = r1 > 0.0 ? std::atan2(dot(w, b), dot(w, a)) : 0.0;
  if (th < 0) th += kTwoPi;
  if (th > kTwoPi - 1e-9) th = 0.0;  // at the start angle (rounding of a whole number of laps)
  const double sweep = th + dir * kTwoPi;
  if (std::fabs(sweep) < 1e-12)
    throw_invalid(o, "dir", dir, "gives a spiral of no angle (the end is at the start angle; use Dir = 1 or -1)");
  Point e = start;
  for (std::size_t i = 0; i < 3; ++i) e[i] = end[i];
  const double r0 = norm(u);
  Point cp, e1, e2, ax;
  adlink_frame(start, 3, c, n, h, &cp, &e1, &e2, &ax);
  SegmentGeometry g = make_curve(adlink_kind(r0, r1, h), start, 3, cp, e1, e2, sweep, r0, r1, ax, &e);
  g.n_ = n;
  return g;
}

template class SegmentGeometry<kCrdMaxDim>;
template class SegmentGeometry<kSpaceMaxDim>;

}  // namespace servobench::motion
