#include "servobench/motion/space_segment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

Vec3 v3(const SpacePoint& p) { return {p[0], p[1], p[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scale(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }

void check_point(const char* o, const char* field, const SpacePoint& p, int dim) {
  for (int k = 0; k < dim; ++k)
    if (!std::isfinite(p[static_cast<std::size_t>(k)])) throw_invalid(o, field, p[static_cast<std::size_t>(k)], "is not a finite coordinate");
}

void check_angle(const char* o, double angle_deg) {
  check_range(o, "angle_deg", angle_deg, -1e6, 1e6, "degrees, sign = direction, |angle| > 360 = laps; ADLINK L2921");
  if (angle_deg == 0.0) throw_invalid(o, "angle_deg", angle_deg, "must be non-zero (an arc of no angle)");
}

void check_dir(const char* o, int dir) {
  check_integer(o, "dir", dir, -32768, 32767, "I16: >= 0 positive, <= -1 negative, Angle = theta + Dir*360; ADLINK L2943-2958");
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

Vec3 center3(const char* o, const SpacePoint& start, const SpacePoint& center, int dim) {
  check_point(o, "start", start, dim);
  check_point(o, "center", center, dim);
  Vec3 c = v3(center), s = v3(start);
  if (dim == 2) c[2] = s[2] = 0.0;
  if (!(norm(sub(s, c)) > 0.0)) throw_invalid(o, "center", 0.0, "is the start point (radius 0)");
  return c;
}
}  // namespace

SpaceSegment SpaceSegment::line(const SpacePoint& start, const SpacePoint& end, int dim) {
  const char* o = "AdlinkLine";
  check_integer(o, "dim", dim, 2, 6, "axes; ADLINK L2817, L2829");
  check_point(o, "start", start, dim);
  check_point(o, "end", end, dim);
  SpaceSegment g;
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
  if (!(g.length_ > 0.0)) throw_invalid(o, "end", 0.0, "equals the start point (a line of zero length)");
  for (int k = 0; k < dim; ++k) {
    const auto i = static_cast<std::size_t>(k);
    g.dir_[i] = (g.end_[i] - start[i]) / g.length_;
  }
  return g;
}

SpaceSegment SpaceSegment::hold(const SpacePoint& start, int dim) {
  check_integer("AdlinkDwell", "dim", dim, 2, 6, "axes; ADLINK L2817, L2829");
  check_point("AdlinkDwell", "start", start, dim);
  SpaceSegment g;
  g.kind_ = Kind::Line;
  g.dim_ = dim;
  g.start_ = start;
  g.end_ = start;
  g.length_ = 0.0;  // dir_ stays 0: point_at = start, tangent_at = 0
  return g;
}

SpaceSegment SpaceSegment::make_curve(const SpacePoint& start, int dim, const Vec3& c, const Vec3& n, double sweep,
                                      double r1, double height, const SpacePoint* exact_end) {
  SpaceSegment g;
  g.dim_ = dim;
  g.start_ = start;
  g.c_ = c;
  g.n_ = n;
  Vec3 s3 = v3(start);
  if (dim == 2) s3[2] = 0.0;
  const Vec3 u = sub(s3, c);
  g.r0_ = norm(u);
  g.e1_ = scale(u, 1.0 / g.r0_);
  g.e2_ = cross(n, g.e1_);
  g.r1_ = r1;
  g.kind_ = (height != 0.0 || std::fabs(r1 - g.r0_) > 1.0) ? Kind::Spiral : Kind::Arc;
  g.sweep_ = sweep;
  g.height_ = height;
  const double th = std::fabs(sweep);
  g.k_ = (r1 - g.r0_) / th;
  const double m = height / th;
  g.c2_ = g.k_ * g.k_ + m * m;
  g.length_ = g.length_to(th);
  if (exact_end != nullptr) {
    g.end_ = *exact_end;
  } else {
    g.end_ = start;
    const double sg = sweep > 0 ? 1.0 : -1.0;
    const double ph = sg * th;
    for (int k = 0; k < std::min(dim, 3); ++k) {
      const auto i = static_cast<std::size_t>(k);
      g.end_[i] = c[i] + r1 * (std::cos(ph) * g.e1_[i] + std::sin(ph) * g.e2_[i]) + height * n[i];
    }
  }
  return g;
}

double SpaceSegment::length_to(double psi) const {
  // ds/dpsi = sqrt(r^2 + c^2), r = r0 + k psi, c^2 = k^2 + (height/theta)^2.
  const double r = r0_ + k_ * psi;
  if (std::fabs(k_) * std::fabs(sweep_) <= 1e-12 * (r0_ + std::fabs(r1_) + 1.0)) return psi * std::sqrt(r0_ * r0_ + c2_);
  const double c = std::sqrt(c2_);
  auto F = [c](double x) { return 0.5 * (x * std::sqrt(x * x + c * c) + c * c * std::asinh(x / c)); };
  return (F(r) - F(r0_)) / k_;
}

double SpaceSegment::psi_at(double s) const {
  const double th = std::fabs(sweep_);
  double psi = th * s / length_;
  for (int it = 0; it < 50; ++it) {
    const double r = r0_ + k_ * psi;
    const double d = (length_to(psi) - s) / std::sqrt(r * r + c2_);
    psi = std::min(std::max(psi - d, 0.0), th);
    if (std::fabs(d) <= 1e-14 * th) break;
  }
  return psi;
}

SpacePoint SpaceSegment::point_at(double s) const {
  if (s <= 0.0) return start_;
  if (s >= length_) return end_;
  SpacePoint p = start_;
  if (kind_ == Kind::Line) {
    for (int k = 0; k < dim_; ++k) {
      const auto i = static_cast<std::size_t>(k);
      p[i] = start_[i] + dir_[i] * s;
    }
    return p;
  }
  const double psi = psi_at(s);
  const double th = std::fabs(sweep_);
  const double ph = sweep_ > 0 ? psi : -psi;
  const double r = r0_ + k_ * psi;
  const double h = height_ * psi / th;
  for (int k = 0; k < std::min(dim_, 3); ++k) {
    const auto i = static_cast<std::size_t>(k);
    p[i] = c_[i] + r * (std::cos(ph) * e1_[i] + std::sin(ph) * e2_[i]) + h * n_[i];
  }
  return p;
}

SpacePoint SpaceSegment::tangent_at(double s) const {
  if (kind_ == Kind::Line) return dir_;
  const double psi = psi_at(std::min(std::max(s, 0.0), length_));
  const double th = std::fabs(sweep_);
  const double sg = sweep_ > 0 ? 1.0 : -1.0;
  const double ph = sg * psi;
  const double r = r0_ + k_ * psi;
  const double m = height_ / th;
  SpacePoint t{};
  double sq = 0.0;
  for (int k = 0; k < std::min(dim_, 3); ++k) {
    const auto i = static_cast<std::size_t>(k);
    t[i] = k_ * (std::cos(ph) * e1_[i] + std::sin(ph) * e2_[i]) +
           r * sg * (-std::sin(ph) * e1_[i] + std::cos(ph) * e2_[i]) + m * n_[i];
    sq += t[i] * t[i];
  }
  const double nn = std::sqrt(sq);
  for (double& v : t) v /= nn;
  return t;
}

SpaceSegment SpaceSegment::arc2_ca(const SpacePoint& start, const SpacePoint& center, double angle_deg) {
  const char* o = "AdlinkArc2CenterAngle";
  check_angle(o, angle_deg);
  const Vec3 c = center3(o, start, center, 2);
  const double r = std::hypot(start[0] - c[0], start[1] - c[1]);
  return make_curve(start, 2, c, {0, 0, 1}, angle_deg * kPi / 180.0, r, 0.0, nullptr);
}

SpaceSegment SpaceSegment::arc3_ca(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                                   double angle_deg) {
  const char* o = "AdlinkArc3CenterAngle";
  check_angle(o, angle_deg);
  const Vec3 c = center3(o, start, center, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  return make_curve(start, 3, c, n, angle_deg * kPi / 180.0, norm(u), 0.0, nullptr);
}

namespace {
void check_end_radius(const char* o, double r0, double r1) {
  if (std::fabs(r1 - r0) > 1.0)
    throw_invalid(o, "end", r1, "is " + format_value(r1) + " from the centre but the start is " + format_value(r0) +
                                    " (they must agree within 1 unit, decision C37)");
}
}  // namespace

SpaceSegment SpaceSegment::arc2_ce(const SpacePoint& start, const SpacePoint& center, const SpacePoint& end, int dir) {
  const char* o = "AdlinkArc2CenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 2);
  check_point(o, "end", end, 2);
  const Vec3 u{start[0] - c[0], start[1] - c[1], 0}, w{end[0] - c[0], end[1] - c[1], 0};
  const double r0 = norm(u), r1 = norm(w);
  check_end_radius(o, r0, r1);
  double th = std::atan2(cross(u, w)[2], dot(u, w));
  if (th < 0) th += kTwoPi;
  if (r1 == 0.0 || std::fabs(th) < 1e-9 || std::fabs(th - kPi) < 1e-9 || std::fabs(th - kTwoPi) < 1e-9)
    throw_invalid(o, "end", th * 180.0 / kPi,
                  "gives a half or full circle, which the centre-end form cannot execute (ADLINK L2930-2933)");
  SpacePoint e = start;
  e[0] = end[0];
  e[1] = end[1];
  return make_curve(start, 2, c, {0, 0, 1}, th + dir * kTwoPi, r1, 0.0, &e);
}

SpaceSegment SpaceSegment::arc3_ce(const SpacePoint& start, const SpacePoint& center, const SpacePoint& end, int dir) {
  const char* o = "AdlinkArc3CenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 3);
  check_point(o, "end", end, 3);
  const Vec3 u = sub(v3(start), c), w = sub(v3(end), c);
  const double r0 = norm(u), r1 = norm(w);
  check_end_radius(o, r0, r1);
  const Vec3 x = cross(u, w);
  const double sx = norm(x);
  if (!(r1 > 0.0) || sx <= 1e-9 * r0 * r1)
    throw_invalid(o, "end", sx, "is collinear with the centre and the start: a half or full circle, which the "
                                "centre-end form cannot execute (ADLINK L2930-2933)");
  const double th = std::atan2(sx, dot(u, w));
  SpacePoint e = start;
  for (std::size_t i = 0; i < 3; ++i) e[i] = end[i];
  return make_curve(start, 3, c, scale(x, 1.0 / sx), th + dir * kTwoPi, r1, 0.0, &e);
}

SpaceSegment SpaceSegment::spiral_ca(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                                     double angle_deg, double height, double final_radius) {
  const char* o = "AdlinkSpiralCenterAngle";
  check_angle(o, angle_deg);
  check_range(o, "height", height, -1e12, 1e12, "relative cone height along the normal; ADLINK L3013");
  check_range(o, "final_radius", final_radius, 0, 1e12, "radius at the end point; ADLINK L3013");
  const Vec3 c = center3(o, start, center, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  return make_curve(start, 3, c, n, angle_deg * kPi / 180.0, final_radius, height, nullptr);
}

SpaceSegment SpaceSegment::spiral_ce(const SpacePoint& start, const SpacePoint& center, const Vec3& normal,
                                     const SpacePoint& end, int dir) {
  const char* o = "AdlinkSpiralCenterEnd";
  check_dir(o, dir);
  const Vec3 c = center3(o, start, center, 3);
  check_point(o, "end", end, 3);
  const Vec3 u = sub(v3(start), c);
  const Vec3 n = corrected_normal(o, normal, u);
  const Vec3 full = sub(v3(end), c);
  const double h = dot(full, n);
  const Vec3 w = sub(full, scale(n, h));
  const double r1 = norm(w);
  const Vec3 e1 = scale(u, 1.0 / norm(u)), e2 = cross(n, e1);
  double th = r1 > 0.0 ? std::atan2(dot(w, e2), dot(w, e1)) : 0.0;
  if (th < 0) th += kTwoPi;
  if (th > kTwoPi - 1e-9) th = 0.0;  // at the start angle (rounding of a whole number of laps)
  const double sweep = th + dir * kTwoPi;
  if (std::fabs(sweep) < 1e-12)
    throw_invalid(o, "dir", dir, "gives a spiral of no angle (the end is at the start angle; use Dir = 1 or -1)");
  SpacePoint e = start;
  for (std::size_t i = 0; i < 3; ++i) e[i] = end[i];
  return make_curve(start, 3, c, n, sweep, r1, h, &e);
}

}  // namespace servobench::motion
