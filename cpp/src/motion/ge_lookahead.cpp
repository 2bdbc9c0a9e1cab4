#include "servobench/motion/ge_lookahead.hpp"

#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/motion/generator.hpp"

namespace servobench::motion {

namespace {
LookAheadParams to_pulse_ms(const GeLookAheadParams& p) {
  p.validate();
  LookAheadParams q;
  q.t_ms = p.t_s * 1000.0;
  q.acc_max = p.acc_max * p.con / 1e6;
  q.n = p.n;
  return q;
}
}  // namespace

void GeLookAheadParams::validate() const {
  const char* o = "GeLookAheadParams";
  check_range(o, "t_s", t_s, 0, 1, "corner time, s; empirically 0.001-0.01, GE L1691-1693");
  if (!(t_s > 0)) throw_invalid(o, "t_s", t_s, "is outside the allowed range 0..1 (0 excluded; s, GE L1691-1693)");
  check_range(o, "con", con, 0, 1e9, "pulse/mm; GE L4885");
  if (!(con > 0)) throw_invalid(o, "con", con, "is outside the allowed range 0..1000000000 (0 excluded; pulse/mm, GE L4885)");
  check_range(o, "acc_max", acc_max, 0, 1e9, "mm/s^2; empirically 100-10000, GE L1693");
  if (!(acc_max > 0)) throw_invalid(o, "acc_max", acc_max, "is outside the allowed range 0..1000000000 (0 excluded; mm/s^2, GE L1693)");
  if (!(acc > 0 && acc < acc_max))
    throw_invalid(o, "acc", acc, "must be in the open interval (0, acc_max = " + format_value(acc_max) +
                                     ") mm/s^2 (GE L1695: smaller than the maximum acceleration)");
  check_range(o, "vel", vel, 0, 1e9, "feed, mm/s; GE L1697");
  if (!(vel > 0)) throw_invalid(o, "vel", vel, "is outside the allowed range 0..1000000000 (0 excluded; mm/s, GE L1697)");
  check_integer(o, "n", n, 1, 32766, "segments; GE L4885");
  if (acc_max * con / 1e6 > 32767) throw_invalid(o, "acc_max", acc_max, "exceeds 32767 pulse/ms^2 with this con");
}

GeLookAhead::GeLookAhead(const GeLookAheadParams& p, const CrdPoint& start_mm) : p_(p), la_(to_pulse_ms(p)) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (!std::isfinite(start_mm[k])) throw_invalid("GeLookAhead", "start", start_mm[k], "is not a finite coordinate");
    last_[k] = start_mm[k] * p.con;
  }
}

int GeLookAhead::add(int code, int plane_group, double r, double x, double y, double z, double vel, double cx,
                     double cy, long long number, bool flag) {
  const char* o = "GT_AddLookData";
  check_integer(o, "code", code, 0, 3, "0 G00, 1 G01, 2 G02 (CW arc), 3 G03 (CCW arc); GE L1711-1716");
  check_range(o, "vel", vel, 0, 1e9, "segment feed, mm/s (0 = the init feed); GE L1720");
  const double c = p_.con;
  const CrdPoint end{x * c, y * c, z * c, 0.0};
  for (std::size_t k = 0; k < 3; ++k)
    if (!std::isfinite(end[k])) throw_invalid(o, "end", end[k], "is not a finite coordinate (mm)");
  PathSegmentGeometry g;
  if (code <= 1) {
    if (end[0] == last_[0] && end[1] == last_[1] && end[2] == last_[2]) return 1;  // GE L3392-3394
    g = PathSegmentGeometry::line(last_, end, 3);
  } else {
    check_integer(o, "plane_group", plane_group, 17, 19, "17 XY, 18 ZX, 19 YZ; GE L1717");
    const ArcPlane plane = plane_group == 17 ? ArcPlane::XY : plane_group == 18 ? ArcPlane::ZX : ArcPlane::YZ;
    const auto a = static_cast<std::size_t>(plane_axis(plane, 0));
    const auto b = static_cast<std::size_t>(plane_axis(plane, 1));
    const double r0 = std::hypot(last_[a] - cx * c, last_[b] - cy * c);
    if (!std::isfinite(r) || std::fabs(std::fabs(r) * c - r0) > 1.0)
      throw_invalid(o, "r", r, "disagrees with the distance centre-start " + format_value(r0 / c) +
                                   " mm (they must agree within 1 pulse, decision C34)");
    g = PathSegmentGeometry::arc_center_offset(last_, end, 3, plane, cx * c - last_[a], cy * c - last_[b], code == 3);
  }
  const double v = (vel > 0 ? vel : p_.vel) * c / 1000.0;
  const double acc = p_.acc * c / 1e6;
  const bool g0 = code == 0;
  if (la_.push(lookahead_segment(g, v, acc, g0 || stop_next_, g0 || flag))) {
    done_.push_back({la_.pop(), numbers_.front()});
    numbers_.pop_front();
  }
  numbers_.push_back(number);
  stop_next_ = g0;
  last_ = g.end();
  return 0;
}

int GeLookAhead::cal_vel(double& vel_mm_s, long long& number) {
  if (done_.empty()) {
    if (numbers_.empty()) throw MotionCommandRefused("GT_CalVel: no segment left (return code 1)");
    done_.push_back({la_.pop(), numbers_.front()});
    numbers_.pop_front();
  }
  vel_mm_s = done_.front().first * 1000.0 / p_.con;
  number = done_.front().second;
  done_.pop_front();
  return done_.empty() && numbers_.empty() ? 1 : 0;
}

}  // namespace servobench::motion
