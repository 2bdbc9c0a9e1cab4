#include "servobench/motion/adlink_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <limits>

#include "servobench/motion/check.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/units.hpp"
#include "servobench/motion/velocity_change.hpp"

namespace servobench::motion {

double adlink_ramp_jerk(double dv, double acc, double sf) {
  if (sf == 0.0 || dv == 0.0) return std::numeric_limits<double>::infinity();
  return acc * acc / (sf * std::fabs(dv));
}

namespace {
// Appends the S-factor ramp from the profile end velocity (acceleration 0) to v1 at peak acceleration acc.
void push_ramp(Profile& prof, double v1, double acc, double sf) {
  const double v0 = prof.end().vel;
  const double dv = v1 - v0;
  if (dv == 0.0) return;
  const double s = dv > 0 ? 1.0 : -1.0;
  if (sf == 0.0) {
    prof.push_with_acc(std::fabs(dv) / acc, s * acc, 0.0).settle_acc();
    return;
  }
  const double t1 = sf * std::fabs(dv) / acc;
  const double t2 = (1.0 - sf) * std::fabs(dv) / acc;
  const double j = s * acc / t1;
  prof.push(t1, j);
  if (t2 > 0.0) prof.push_with_acc(t2, s * acc, 0.0);
  prof.push(t1, -j).settle_acc();
}
}  // namespace

Profile plan_adlink_ptp(double start_pos, double target, const AdlinkLimits& lim) {
  const double rel = target - start_pos;
  const double D = std::fabs(rel);
  const double s = rel >= 0 ? 1.0 : -1.0;
  if (D == 0.0) return Profile::rest(target);
  const double k = 1.0 + lim.sf;  // ramp distance = k * (v1^2 - v0^2) / (2 * rate)
  const double vm2 = (2.0 * lim.acc * lim.dec * D / k + lim.dec * lim.vs * lim.vs + lim.acc * lim.ve * lim.ve) /
                     (lim.acc + lim.dec);
  const double vp = std::min(lim.vm, std::sqrt(vm2));
  if (vp < std::max(lim.vs, lim.ve)) {
    const double need = k * std::fabs(lim.vs * lim.vs - lim.ve * lim.ve) /
                        (2.0 * (lim.vs > lim.ve ? lim.dec : lim.acc));
    throw std::invalid_argument("AdlinkPtp: the move of " + format_value(D) +
                                " pulse is shorter than the VS -> VE ramp needs (" + format_value(need) +
                                " pulse); lower VS or VE");
  }
  const double d_acc = k * (vp * vp - lim.vs * lim.vs) / (2.0 * lim.acc);
  const double d_dec = k * (vp * vp - lim.ve * lim.ve) / (2.0 * lim.dec);
  double cruise = (D - d_acc - d_dec) / vp;
  if (cruise < 0.0) cruise = 0.0;
  Profile prof(MotionState{start_pos, s * lim.vs, 0.0, 0.0});
  push_ramp(prof, s * vp, lim.acc, lim.sf);
  prof.push(cruise, 0.0);
  push_ramp(prof, s * lim.ve, lim.dec, lim.sf);
  return prof.finish_at_rest(target);
}

Profile plan_adlink_velocity(const MotionState& from, double vel, const AdlinkLimits& lim) {
  // The jog profile with the ADLINK rate (ACC speeding up, DEC slowing down) and the S-factor's jerk.
  const double rate = std::fabs(vel) >= std::fabs(from.vel) ? lim.acc : lim.dec;
  return plan_jog(from, vel, rate, adlink_ramp_jerk(vel - from.vel, rate, lim.sf));
}

Profile plan_adlink_stop(const MotionState& from, double sd_dec, double sf) {
  MotionState start = from;
  start.jerk = 0.0;
  Profile prof(start);
  push_velocity_change(prof, 0.0, sd_dec, adlink_ramp_jerk(from.vel, sd_dec, sf));
  return prof.finish_at_rest(prof.end().pos);
}

void AdlinkPtpParams::validate() const {
  const char* src = "ADLINK L2744-2751";
  check_range("AdlinkPtp", "pos", pos, -2147483647.0, 2147483647.0, src);
  check_motion_value("AdlinkPtp", "vm", vm, 0.0, 1e9, src);
  check_range("AdlinkPtp", "vs", vs, 0.0, vm, "ADLINK L2744-2751: 0..vm");
  check_range("AdlinkPtp", "ve", ve, 0.0, vm, "ADLINK L2744-2751: 0..vm");
  check_motion_value("AdlinkPtp", "acc", acc, 0.0, 1e12, src);
  check_motion_value("AdlinkPtp", "dec", dec, 0.0, 1e12, src);
  check_range("AdlinkPtp", "sf", sf, 0.0, 1.0, "ADLINK L2213-2219");
  check_range("AdlinkPtp", "sd_dec", sd_dec, 0.0, 1e12, src);
}

AdlinkLimits AdlinkPtpParams::limits(double period_s) const {
  check_period("AdlinkPtp", period_s);
  return {per_s_to_per_tick(vs, period_s, 1), per_s_to_per_tick(vm, period_s, 1), per_s_to_per_tick(ve, period_s, 1),
          per_s_to_per_tick(acc, period_s, 2), per_s_to_per_tick(dec, period_s, 2), sf};
}

double AdlinkPtpParams::sd_dec_per_tick(double period_s) const {
  check_period("AdlinkPtp", period_s);
  return per_s_to_per_tick(sd_dec > 0.0 ? sd_dec : dec, period_s, 2);
}

}  // namespace servobench::motion
