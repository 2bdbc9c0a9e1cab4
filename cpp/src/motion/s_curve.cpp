#include "servobench/motion/s_curve.hpp"

#include <cmath>

#include "servobench/motion/check.hpp"
#include "servobench/motion/units.hpp"
#include "servobench/motion/velocity_change.hpp"

namespace servobench::motion {

void SCurveLimits::validate() const {
  check_positive("SCurveLimits", "vel", vel);
  check_positive("SCurveLimits", "acc", acc);
  check_positive("SCurveLimits", "jerk", jerk);
}

namespace {

// Rest-to-rest timing: jerk phase t1, hold t2 (each of the 4 ramps), cruise tc, peak velocity vp.
struct RestToRest {
  double t1, t2, tc, vp;
};

inline RestToRest rest_to_rest(double dist, double V, double A, double J) {
  RestToRest r{};
  // Accelerating from rest to V.
  double t1, t2;
  if (V * J >= A * A) {
    t1 = A / J;
    t2 = V / A - t1;
  } else {
    t1 = std::sqrt(V / J);
    t2 = 0.0;
  }
  const double d_ramps = V * (2.0 * t1 + t2);  // both ramps: average velocity V/2 over 2*(2t1+t2)
  if (d_ramps <= dist) {
    r = {t1, t2, (dist - d_ramps) / V, V};
    return r;
  }
  // V is not reached: the peak vp satisfies vp * (ramp time) = dist.
  const double a_over_j = A / J;
  if (dist >= 2.0 * A * a_over_j * a_over_j) {  // MAcc reached: dist = vp^2/A + vp*A/J
    const double b = A * a_over_j;
    const double vp = 0.5 * (-b + std::sqrt(b * b + 4.0 * dist * A));
    r = {a_over_j, vp / A - a_over_j, 0.0, vp};
    if (r.t2 < 0.0) r.t2 = 0.0;
  } else {  // jerk-only ramps: dist = 2 vp sqrt(vp/J)
    const double vp = std::cbrt(dist * dist * J * 0.25);
    r = {std::sqrt(vp / J), 0.0, 0.0, vp};
  }
  return r;
}

}  // namespace

Profile plan_s_curve_rest_to_rest(double start_pos, double target, const SCurveLimits& lim) {
  Profile prof(MotionState{start_pos, 0.0, 0.0, 0.0});
  const double d = target - start_pos;
  if (d == 0.0) return prof.finish_at_rest(target);
  const double s = d > 0 ? 1.0 : -1.0;
  const RestToRest r = rest_to_rest(std::fabs(d), lim.vel, lim.acc, lim.jerk);
  const double J = s * lim.jerk;
  prof.push(r.t1, J).push(r.t2, 0.0).push(r.t1, -J).settle_acc();
  prof.push(r.tc, 0.0);
  prof.push(r.t1, -J).push(r.t2, 0.0).push(r.t1, J);
  return prof.finish_at_rest(target);
}

double s_curve_min_time(double distance, const SCurveLimits& lim) {
  if (distance == 0.0) return 0.0;
  const RestToRest r = rest_to_rest(std::fabs(distance), lim.vel, lim.acc, lim.jerk);
  return 4.0 * r.t1 + 2.0 * r.t2 + r.tc;
}

void plan_s_curve_batch(std::size_t n, const double* start, const double* target, const double* vel,
                        const double* acc, const double* jerk, double* duration) {
  for (std::size_t i = 0; i < n; ++i) {
    const Profile p = plan_s_curve_rest_to_rest(start[i], target[i], SCurveLimits{vel[i], acc[i], jerk[i]});
    duration[i] = p.duration();
  }
}

void plan_s_curve_from_state_batch(std::size_t n, const double* pos0, const double* vel0, const double* acc0,
                                   const double* target, const double* vel, const double* acc, const double* jerk,
                                   double* duration) {
  for (std::size_t i = 0; i < n; ++i) {
    MotionState from;
    from.pos = pos0[i];
    from.vel = vel0[i];
    from.acc = acc0[i];
    duration[i] = plan_s_curve(from, target[i], SCurveLimits{vel[i], acc[i], jerk[i]}).duration();
  }
}

Profile plan_s_curve(const MotionState& from, double target, const SCurveLimits& lim) {
  if (from.vel == 0.0 && from.acc == 0.0) return plan_s_curve_rest_to_rest(from.pos, target, lim);
  const double V = lim.vel, A = lim.acc, J = lim.jerk;
  // Where the axis would stop if braking now.
  const ChangeExtent brake = velocity_change_extent(from.vel, from.acc, 0.0, A, J);
  const double rel = target - from.pos;
  const double gap = rel - brake.dist;
  Profile prof(from);
  if (gap == 0.0) {
    push_velocity_change(prof, 0.0, A, J);
    return prof.finish_at_rest(target);
  }
  // Direction of travel after the change (a target behind the braking point reverses).
  const double s = gap > 0 ? 1.0 : -1.0;
  const double D = s * rel;
  auto dist_for_peak = [&](double vp) {  // distance (in direction s) of: change to s*vp, change to 0
    return s * (velocity_change_extent(from.vel, from.acc, s * vp, A, J).dist +
                velocity_change_extent(s * vp, 0.0, 0.0, A, J).dist);
  };
  double vp = V;
  if (dist_for_peak(V) > D) {
    double lo = 0.0, hi = V;  // dist_for_peak(lo) <= D < dist_for_peak(hi)
    for (int it = 0; it < 200 && hi - lo > 1e-15 * V; ++it) {
      const double mid = 0.5 * (lo + hi);
      (dist_for_peak(mid) <= D ? lo : hi) = mid;
    }
    vp = lo;
  }
  const double rest = D - dist_for_peak(vp);
  push_velocity_change(prof, s * vp, A, J);
  prof.settle_acc();
  if (vp > 0.0 && rest > 0.0) prof.push(rest / vp, 0.0);
  push_velocity_change(prof, 0.0, A, J);
  return prof.finish_at_rest(target);
}

void GtSCurveParams::validate() const {
  check_profile_position("GtSCurve", "pos", pos, "GT L854");
  check_motion_value("GtSCurve", "vel", vel, 0.0, 16384.0, "GT L858");
  check_motion_value("GtSCurve", "macc", macc, 0.0, 0.5, "GT L857", true, true);
  check_motion_value("GtSCurve", "jerk", jerk, 0.0, 0.5, "GT L856", true, true);
}

void GeSCurveParams::validate() const {
  check_profile_position("GeSCurve", "pos", pos, "GE L1095-1101");
  check_motion_value("GeSCurve", "vel", vel, 0.0, 40957.0, "GE L1095-1101");
  check_motion_value("GeSCurve", "macc", macc, 0.0, 102400.0, "GE L1095-1101");
  check_motion_value("GeSCurve", "jerk", jerk, 0.0, 256000.0, "GE L1095-1101");
}

SCurveLimits GeSCurveParams::limits(double period_s) const {
  check_period("GeSCurve", period_s);
  return {per_ms_to_per_tick(vel, period_s, 1), per_ms_to_per_tick(macc, period_s, 2),
          per_ms_to_per_tick(jerk, period_s, 3)};
}

}  // namespace servobench::motion
