#include "servobench/motion/t_curve.hpp"

#include <cmath>

#include "servobench/motion/check.hpp"
#include "servobench/motion/units.hpp"

namespace servobench::motion {

void TCurveLimits::validate() const {
  check_positive("TCurveLimits", "vel", vel);
  check_positive("TCurveLimits", "acc", acc);
}

Profile plan_t_curve(const MotionState& from, double target, const TCurveLimits& lim) {
  const double V = lim.vel, A = lim.acc;
  MotionState start = from;
  start.acc = 0.0;
  start.jerk = 0.0;
  Profile prof(start);
  const double v0 = from.vel;
  const double rel = target - from.pos;
  const double brake = v0 * std::fabs(v0) / (2.0 * A);
  const double gap = rel - brake;
  if (gap == 0.0) {
    prof.push_with_acc(std::fabs(v0) / A, v0 > 0 ? -A : A, 0.0);
    return prof.finish_at_rest(target);
  }
  const double s = gap > 0 ? 1.0 : -1.0;  // direction after the change; a target behind the brake point reverses
  const double D = s * rel;
  const double w = s * v0;  // velocity in the travel direction (may be negative: moving away)
  double vp, d_change;      // peak velocity, distance of the ramps without cruise
  if (w <= V) {
    vp = std::sqrt(A * D + 0.5 * w * w);
    if (vp > V) vp = V;
    if (vp < w) vp = w;  // (only through rounding: D >= brake distance)
    d_change = (2.0 * vp * vp - w * w) / (2.0 * A);
  } else {  // above the new velocity: decelerate to V first
    vp = V;
    d_change = w * w / (2.0 * A);
  }
  double cruise = vp > 0.0 ? (D - d_change) / vp : 0.0;
  // A triangle (vp below V, reached by accelerating) has no cruise; a rounding residue is not one.
  if (cruise < 0.0 || (vp < V && vp > w)) cruise = 0.0;
  prof.push_with_acc(std::fabs(vp - w) / A, vp >= w ? s * A : -s * A, 0.0);
  prof.push_with_acc(cruise, 0.0, 0.0);
  prof.push_with_acc(vp / A, -s * A, 0.0);
  return prof.finish_at_rest(target);
}

double t_curve_min_time(double distance, const TCurveLimits& lim) {
  const double d = std::fabs(distance);
  const double V = lim.vel, A = lim.acc;
  if (V * V / A <= d) return d / V + V / A;
  return 2.0 * std::sqrt(d / A);
}

void GtTCurveParams::validate() const {
  check_profile_position("GtTCurve", "pos", pos, "GT L854");
  check_motion_value("GtTCurve", "vel", vel, 0.0, 16384.0, "GT L930");
  check_motion_value("GtTCurve", "acc", acc, 0.0, 16384.0, "GT L929");
}

void GeTCurveParams::validate() const {
  check_profile_position("GeTCurve", "pos", pos, "GE L991-996");
  check_motion_value("GeTCurve", "vel", vel, 0.0, 40957.0, "GE L991-996");
  check_motion_value("GeTCurve", "acc", acc, 0.0, 102400.0, "GE L991-996");
}

TCurveLimits GeTCurveParams::limits(double period_s) const {
  check_period("GeTCurve", period_s);
  return {per_ms_to_per_tick(vel, period_s, 1), per_ms_to_per_tick(acc, period_s, 2)};
}

}  // namespace servobench::motion
