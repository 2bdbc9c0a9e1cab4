#include "servobench/motion/velocity_change.hpp"

#include <cmath>

namespace servobench::motion {

ChangePhases velocity_change_phases(double v0, double a0, double v1, double amax, double jmax) {
  ChangePhases ph;
  if (std::isinf(jmax)) {  // T ramp: acceleration steps
    const double dv = v1 - v0;
    ph.a2 = dv > 0 ? amax : (dv < 0 ? -amax : 0.0);
    ph.t2 = std::fabs(dv) / amax;
    return ph;
  }
  // Velocity reached if the acceleration is brought to zero at once.
  const double v_star = v0 + a0 * std::fabs(a0) / (2.0 * jmax);
  const double s = v1 > v_star ? 1.0 : (v1 < v_star ? -1.0 : 0.0);
  if (s == 0.0) {
    ph.t3 = std::fabs(a0) / jmax;
    ph.j3 = a0 > 0 ? -jmax : jmax;
    return ph;
  }
  const double a0s = s * a0;
  const double dv = s * (v1 - v0);
  double ap;
  double hold = 0.0;
  const double dv_at_amax = (2.0 * amax * amax - a0s * a0s) / (2.0 * jmax);
  if (dv >= dv_at_amax) {
    ap = amax;
    hold = (dv - dv_at_amax) / amax;
  } else {
    ap = std::sqrt(jmax * dv + 0.5 * a0s * a0s);
  }
  ph.t1 = (ap - a0s) / jmax;
  if (ph.t1 < 0.0) ph.t1 = 0.0;
  ph.t2 = hold;
  ph.a2 = s * ap;
  ph.t3 = ap / jmax;
  ph.j1 = s * jmax;
  ph.j3 = -s * jmax;
  return ph;
}

ChangeExtent velocity_change_extent(double v0, double a0, double v1, double amax, double jmax) {
  const ChangePhases ph = velocity_change_phases(v0, a0, v1, amax, jmax);
  ChangeExtent e;
  double v = v0, a = a0;
  if (std::isinf(jmax)) {
    e.dist = 0.5 * (v0 + v1) * ph.t2;
    e.time = ph.t2;
    return e;
  }
  // phase 1
  double t = ph.t1;
  e.dist += v * t + 0.5 * a * t * t + ph.j1 * t * t * t / 6.0;
  v += a * t + 0.5 * ph.j1 * t * t;
  a = ph.a2;
  // phase 2
  t = ph.t2;
  e.dist += v * t + 0.5 * a * t * t;
  v += a * t;
  // phase 3 (from acceleration a to 0)
  if (ph.t2 == 0.0 && ph.t1 == 0.0) a = a0;
  t = ph.t3;
  e.dist += v * t + 0.5 * a * t * t + ph.j3 * t * t * t / 6.0;
  e.time = ph.t1 + ph.t2 + ph.t3;
  return e;
}

void push_velocity_change(Profile& prof, double v1, double amax, double jmax) {
  const MotionState& s0 = prof.end();
  const ChangePhases ph = velocity_change_phases(s0.vel, s0.acc, v1, amax, jmax);
  if (std::isinf(jmax)) {
    prof.push_with_acc(ph.t2, ph.a2, 0.0).settle_acc();
    return;
  }
  prof.push(ph.t1, ph.j1);
  if (ph.t2 > 0.0) prof.push_with_acc(ph.t2, ph.a2, 0.0);
  prof.push(ph.t3, ph.j3);
}

}  // namespace servobench::motion
