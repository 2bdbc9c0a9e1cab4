#include "servobench/motion/adlink_replan.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/common/validate.hpp"
#include "servobench/motion/velocity_change.hpp"

namespace servobench::motion {

double adlink_ramp_distance(double v0, double v1, double rate, double sf) {
  return (1.0 + sf) * std::fabs(v1 * v1 - v0 * v0) / (2.0 * rate);
}

namespace {
// Appends an S-factor ramp from the profile end (acceleration 0) to v1 at peak rate `rate`.
void push_ramp(Profile& prof, double v1, double rate, double sf) {
  const double dv = v1 - prof.end().vel;
  if (dv == 0.0) return;
  push_velocity_change(prof, v1, rate, adlink_ramp_jerk(dv, rate, sf));
  prof.settle_acc();
}
}  // namespace

Profile plan_adlink_ptp_from(const MotionState& from, double target, const AdlinkLimits& lim) {
  if (from.acc != 0.0)
    throw std::invalid_argument("plan_adlink_ptp_from: the state's acceleration must be 0 (got " +
                                format_value(from.acc) + " pulse/tick^2)");
  if (from.vel == 0.0) return plan_adlink_ptp(from.pos, target, lim);
  const double rel = target - from.pos;
  const double s = rel >= 0 ? 1.0 : -1.0;
  const double D = std::fabs(rel);
  const double v0 = s * from.vel;  // speed towards the target (negative: moving away)
  MotionState start = from;
  start.jerk = 0.0;
  Profile prof(start);
  if (v0 <= 0.0 || adlink_ramp_distance(v0, lim.ve, lim.dec, lim.sf) > D ) {
    // Cannot end at the target at VE going forward: stop at DEC, then a move from rest.
    push_ramp(prof, 0.0, lim.dec, lim.sf);
    AdlinkLimits from_rest = lim;
    from_rest.vs = 0.0;  // the return move starts from rest, without the VS step (decision M44)
    const Profile back = plan_adlink_ptp(prof.end().pos, target, from_rest);
    for (int i = 0; i < back.size(); ++i) {
      const Segment& g = back.segment(i);
      prof.push_with_acc(g.duration, g.a, g.j);
    }
    return prof.finish_at_rest(target);
  }
  const double k = 1.0 + lim.sf;
  const double vm2 =
      (2.0 * lim.acc * lim.dec * D / k + lim.dec * v0 * v0 + lim.acc * lim.ve * lim.ve) / (lim.acc + lim.dec);
  const double vp = std::min(lim.vm, std::sqrt(std::max(vm2, v0 * v0)));
  const double d1 = adlink_ramp_distance(v0, vp, vp >= v0 ? lim.acc : lim.dec, lim.sf);
  const double d2 = adlink_ramp_distance(vp, lim.ve, lim.dec, lim.sf);
  const double cruise = std::max(0.0, (D - d1 - d2) / vp);
  push_ramp(prof, s * vp, vp >= v0 ? lim.acc : lim.dec, lim.sf);
  prof.push(cruise, 0.0);
  push_ramp(prof, s * lim.ve, lim.dec, lim.sf);
  return prof.finish_at_rest(target);
}

}  // namespace servobench::motion
