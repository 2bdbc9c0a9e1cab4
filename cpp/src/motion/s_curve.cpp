#include "servobench/motion/s_curve.hpp"

#include <algorithm>
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

namespace {

// The replanning family (see s_curve.hpp), in the frame where the move goes towards +: jerk +J from a0 to a1
// (phase 1), a hold at a1 = A for t2 (phase 2), then jerk -J from a1 down to a3 <= min(a1, 0), a hold at a3 = -A
// and jerk +J back to a = 0 at rest. The part after phase 2 is the tail of the symmetric stopping ramp from the
// (virtual, if a1 < 0) peak velocity vpk = v0 + (2 a1^2 - a0^2)/(2J) + a1 t2 at which a would cross zero.
// One parameter u: a1 = min(u, A), t2 = max(u - A, 0)/J. The distance grows with u (more acceleration first).
struct Family {
  double v0, a0, A, J;
  // Parameter of the member whose peak velocity is `v` (needs v >= v0 + (a1^2 - a0^2)/(2J) reachable with a1 >= 0).
  double u_for_peak(double v) const {
    const double a1sq = J * (v - v0) + 0.5 * a0 * a0;
    if (a1sq <= A * A) return std::sqrt(std::max(a1sq, 0.0));
    const double t2 = (v - v0 - (2.0 * A * A - a0 * a0) / (2.0 * J)) / A;
    return A + J * std::max(t2, 0.0);
  }
};

// One member: phase times and the distance and duration it covers.
struct Member {
  double a1, t1, t2, vpk, ta, th, tau;  // tau = -a1/J: where phase 3 starts in the stopping ramp from vpk
  double dist, time;
};

inline Member member(const Family& f, double u) {
  Member m{};
  const double J = f.J, A = f.A;
  m.a1 = std::min(u, A);
  m.t2 = u > A ? (u - A) / J : 0.0;
  m.t1 = std::max((m.a1 - f.a0) / J, 0.0);
  const double t1 = m.t1, a0 = f.a0, a1 = m.a1;
  const double d1 = t1 * (f.v0 + t1 * (0.5 * a0 + t1 * J * (1.0 / 6.0)));
  const double v1 = f.v0 + (a1 * a1 - a0 * a0) / (2.0 * J);
  const double d2 = m.t2 * (v1 + 0.5 * a1 * m.t2);
  m.vpk = std::max(v1 + a1 * m.t2 + a1 * a1 / (2.0 * J), 0.0);
  if (J * m.vpk >= A * A) {
    m.ta = A / J;
    m.th = m.vpk / A - m.ta;
  } else {
    m.ta = std::sqrt(m.vpk / J);
    m.th = 0.0;
  }
  m.tau = -a1 / J;
  const double x_tau = m.tau * (m.vpk - J * m.tau * m.tau * (1.0 / 6.0));  // ramp position at tau (from the peak)
  m.dist = d1 + d2 + 0.5 * m.vpk * (2.0 * m.ta + m.th) - x_tau;
  m.time = t1 + m.t2 + 2.0 * m.ta + m.th - m.tau;
  return m;
}

// Root of the increasing g(u) = dist(u) - D on [lo, hi] with g(lo) <= 0 < g(hi): Illinois regula falsi with a
// bisection guard; converges superlinearly, ~10 evaluations to a relative 1e-15.
inline double solve_increasing(const Family& f, double D, double lo, double hi, double glo, double ghi) {
  int side = 0;
  const double xtol = 4e-16 * std::max({std::fabs(lo), std::fabs(hi), f.A});
  const double ftol = 1e-15 * std::max(std::fabs(D), 1.0);
  for (int it = 0; it < 100 && hi - lo > xtol; ++it) {
    double x = (lo * ghi - hi * glo) / (ghi - glo);
    if (!(x > lo && x < hi) || it % 8 == 7) x = 0.5 * (lo + hi);  // guard (and a bisection every 8 steps)
    const double g = member(f, x).dist - D;
    if (std::fabs(g) <= ftol) return x;
    if (g <= 0.0) {
      lo = x;
      glo = g;
      if (side == -1) ghi *= 0.5;
      side = -1;
    } else {
      hi = x;
      ghi = g;
      if (side == 1) glo *= 0.5;
      side = 1;
    }
  }
  return glo >= -ghi ? lo : hi;  // the end nearer the root
}


// Brake pre-phase (MO2) for a state the limits do not reach: |a| > A is brought to A at full jerk; then, if the
// velocity would pass the limit even with a taken to 0 at once (|v + a|a|/(2J)| > V), a is driven (through
// zero) to the value a_b, or held at -A, that makes it exactly V: the fastest way back inside the limits.
void push_brake(Profile& prof, double V, double A, double J) {
  const MotionState& e = prof.end();
  if (std::fabs(e.acc) > A) prof.push((std::fabs(e.acc) - A) / J, e.acc > 0 ? -J : J);
  const double v = prof.end().vel, a = prof.end().acc;
  const double v_star = v + a * std::fabs(a) / (2.0 * J);
  if (std::fabs(v_star) <= V) return;
  const double sg = v_star > 0 ? 1.0 : -1.0;  // brake against sg
  const double as = sg * a, over = sg * v_star - V;
  const double ab = std::sqrt(J * over);  // |a_b|, the braking acceleration that lands on V
  if (ab <= A) {
    prof.push((as + ab) / J, -sg * J);
  } else {
    prof.push((as + A) / J, -sg * J);
    prof.push((over - A * A / J) / A, 0.0);
  }
}

}  // namespace

void check_replan_input(const MotionState& from, double target, const SCurveLimits& lim) {
  lim.validate();
  check_range("plan_s_curve", "from.pos", from.pos, -kMaxMagnitude, kMaxMagnitude, "pulse");
  check_range("plan_s_curve", "from.vel", from.vel, -kMaxMagnitude, kMaxMagnitude, "pulse/tick");
  check_range("plan_s_curve", "from.acc", from.acc, -kMaxMagnitude, kMaxMagnitude, "pulse/tick^2");
  check_range("plan_s_curve", "target", target, -kMaxMagnitude, kMaxMagnitude, "pulse");
}

Profile plan_s_curve(const MotionState& from_in, double target, const SCurveLimits& lim) {
  if (from_in.vel == 0.0 && from_in.acc == 0.0) return plan_s_curve_rest_to_rest(from_in.pos, target, lim);
  const double V = lim.vel, A = lim.acc, J = lim.jerk;
  Profile prof(from_in);
  push_brake(prof, V, A, J);
  const MotionState from = prof.end();
  // Where the axis would stop if braking now (time-optimal stop).
  const ChangeExtent brake = velocity_change_extent(from.vel, from.acc, 0.0, A, J);
  const double rel = target - from.pos;
  const double gap = rel - brake.dist;
  if (gap == 0.0) {
    push_velocity_change(prof, 0.0, A, J);
    return prof.finish_at_rest(target);
  }
  // Direction of travel after the change (a target behind the braking point reverses, M3); planned mirrored
  // so that it goes towards +.
  const double s = gap > 0 ? 1.0 : -1.0;
  const Family f{s * from.vel, s * from.acc, A, J};
  const double D = s * rel;
  const double v_star = f.v0 + f.a0 * std::fabs(f.a0) / (2.0 * J);  // velocity if a went to 0 at once
  // Lowest member: the stop itself. If the stop first lowers a (v* >= 0) it is u = a0 (no phase 1); otherwise it
  // raises a to stop at peak 0.
  const double u_lo = v_star >= 0.0 ? f.a0 : f.u_for_peak(0.0);
  // Highest member: peak velocity V (a1 >= 0 there since vpk = V >= v0).
  const double u_hi = std::max(f.u_for_peak(V), u_lo);
  const Member top = member(f, u_hi);
  double u = u_hi, cruise = 0.0;
  if (top.dist <= D) {
    cruise = (D - top.dist) / top.vpk;
  } else {
    const double glo = member(f, u_lo).dist - D;
    u = glo >= 0.0 ? u_lo : solve_increasing(f, D, u_lo, u_hi, glo, top.dist - D);
  }
  const Member m = member(f, u);
  const double Js = s * J;
  prof.push(m.t1, Js).push(m.t2, 0.0);
  if (m.a1 > 0.0) prof.push(m.a1 / J, -Js).settle_acc();  // down to a = 0 at the peak
  if (cruise > 0.0) prof.push(cruise, 0.0);
  prof.push(m.ta - std::max(m.tau, 0.0), -Js).push(m.th, 0.0).push(m.ta, Js);
  return prof.finish_at_rest(target);
}

void plan_s_curve_replan_batch(std::size_t n, const double* pos, const double* vel, const double* acc,
                               const double* target, const double* vmax, const double* amax, const double* jmax,
                               double* duration) {
  for (std::size_t i = 0; i < n; ++i) {
    const Profile p = plan_s_curve(MotionState{pos[i], vel[i], acc[i], 0.0}, target[i],
                                   SCurveLimits{vmax[i], amax[i], jmax[i]});
    duration[i] = p.duration();
  }
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
