#include "servobench/motion/generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "servobench/common/validate.hpp"
#include "servobench/motion/adlink_replan.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/stop.hpp"

namespace servobench::motion {

const char* to_string(ProfileMode mode) {
  switch (mode) {
    case ProfileMode::TCurve: return "t_curve";
    case ProfileMode::SCurve: return "s_curve";
    case ProfileMode::Jog: return "jog";
    case ProfileMode::AdlinkPtp: return "adlink_ptp";
    case ProfileMode::AdlinkVelocity: return "adlink_velocity";
  }
  return "?";
}

ProfileGenerator::ProfileGenerator(double start_pos, double period_s)
    : profile_(Profile::rest(start_pos)), period_s_(period_s) {
  if (!std::isfinite(start_pos)) throw_invalid("ProfileGenerator", "start_pos", start_pos, "must be a finite number");
  check_range("ProfileGenerator", "period_s", period_s, 1e-6, 1.0, "s");
  state_ = profile_.start();
}

void ProfileGenerator::command(const GtTCurveParams& p) {
  p.validate();
  move_t_curve(p.pos, p.limits());
}
void ProfileGenerator::command(const GtSCurveParams& p) {
  p.validate();
  move_s_curve(p.pos, p.limits());
}
void ProfileGenerator::command(const GtJogParams& p) {
  p.validate();
  jog(p.vel, p.acc);
}
void ProfileGenerator::command(const GeTCurveParams& p) {
  p.validate();
  move_t_curve(p.pos, p.limits(period_s_));
}
void ProfileGenerator::command(const GeSCurveParams& p) {
  p.validate();
  move_s_curve(p.pos, p.limits(period_s_));
}
void ProfileGenerator::command(const GeJogParams& p) {
  p.validate();
  jog(p.vel_per_tick(period_s_), p.acc_per_tick(period_s_));
}
void ProfileGenerator::command(const AdlinkPtpParams& p) {
  p.validate();
  move_adlink_ptp(p.pos, p.limits(period_s_));
}
void ProfileGenerator::adlink_velocity(double vel_pulse_per_s, const AdlinkPtpParams& p) {
  p.validate();
  check_range("adlink_velocity", "vel_pulse_per_s", vel_pulse_per_s, -p.vm, p.vm, "-vm..vm");
  move_adlink_velocity(vel_pulse_per_s * period_s_, p.limits(period_s_));
}
void ProfileGenerator::adlink_stop_move(const AdlinkPtpParams& p) {
  p.validate();
  if (!moving()) return;
  const double dec = p.sd_dec_per_tick(period_s_);
  smooth_stop_with(dec, adlink_ramp_jerk(state_.vel, dec, p.sf));
}

bool ProfileGenerator::moving() const {
  if (profile_.open_ended()) return true;
  return t_ < profile_.duration();
}

long long ProfileGenerator::reported_pos() const { return std::llround(state_.pos); }

void ProfileGenerator::start(const Profile& p) {
  pending_ = false;
  profile_ = p;
  t_ = 0.0;
  state_ = profile_.at(0.0);
}

void ProfileGenerator::refuse_if_other_mode_moving(ProfileMode wanted, const char* cmd) const {
  if (!moving()) return;
  if (stopping_)
    throw MotionCommandRefused(std::string(cmd) +
                               ": refused during a smooth stop; new motion parameters only after it completes "
                               "(GE L1312)");
  if (mode_ != wanted)
    throw MotionCommandRefused(std::string(cmd) + ": refused, the axis is moving in " + to_string(mode_) +
                               " mode; the mode can change only when the motion has ended (GT L837, GE L310)");
}

void ProfileGenerator::move_t_curve(double target, const TCurveLimits& lim) {
  lim.validate();
  refuse_if_other_mode_moving(ProfileMode::TCurve, "move_t_curve");
  if (moving() && lim.acc != t_lim_.acc)
    throw MotionCommandRefused("move_t_curve: the acceleration may not change during a T-curve motion (GE L315, "
                               "L1067-1071); only the target and the velocity may");
  mode_ = ProfileMode::TCurve;
  t_lim_ = lim;
  start(plan_t_curve(state_, target, lim));
}

void ProfileGenerator::move_s_curve(double target, const SCurveLimits& lim) {
  lim.validate();
  refuse_if_other_mode_moving(ProfileMode::SCurve, "move_s_curve");
  if (moving() && (lim.vel != s_lim_.vel || lim.acc != s_lim_.acc || lim.jerk != s_lim_.jerk))
    throw MotionCommandRefused("move_s_curve: only the target position may change during an S-curve motion "
                               "(GT L909, GE L1179-1183)");
  mode_ = ProfileMode::SCurve;
  s_lim_ = lim;
  start(plan_s_curve(state_, target, lim));
}

void ProfileGenerator::jog(double vel, double acc) {
  check_positive("jog", "acc", acc);
  if (!std::isfinite(vel)) throw_invalid("jog", "vel", vel, "must be a finite number");
  refuse_if_other_mode_moving(ProfileMode::Jog, "jog");
  mode_ = ProfileMode::Jog;
  jog_acc_ = acc;
  start(plan_jog(state_, vel, acc));
}

void ProfileGenerator::move_adlink_ptp(double target, const AdlinkLimits& lim) {
  if (!moving()) {
    mode_ = ProfileMode::AdlinkPtp;
    adlink_ = lim;
    start(plan_adlink_ptp(state_.pos, target, lim));
    return;
  }
  if (stopping_)
    throw MotionCommandRefused("move_adlink_ptp: refused during a stop; a new move only after it completes");
  if (mode_ != ProfileMode::AdlinkPtp && mode_ != ProfileMode::AdlinkVelocity)
    throw MotionCommandRefused(std::string("move_adlink_ptp: refused, the axis is moving in ") + to_string(mode_) +
                               " mode; the mode can change only when the motion has ended");
  // On the fly (ADLINK L2757-2767): replan at the next instant of zero acceleration.
  const double at = next_zero_acc_time();
  mode_ = ProfileMode::AdlinkPtp;
  adlink_ = lim;
  if (at <= t_) {
    MotionState s = state_;
    s.acc = 0.0;
    start(plan_adlink_ptp_from(s, target, lim));
    return;
  }
  pending_ = true;
  pending_ptp_ = {at, target, lim};
}

double ProfileGenerator::next_zero_acc_time() const {
  if (adlink_.sf == 0.0) return t_;  // T ramps: the acceleration may step, replan now
  if (state_.acc == 0.0 && state_.jerk == 0.0) return t_;
  // Segment boundaries after now where the acceleration is (numerically) zero.
  const double scale = std::max(adlink_.acc, adlink_.dec);
  double t0 = 0.0;
  for (int i = 0; i < profile_.size(); ++i) {
    const Segment& g = profile_.segment(i);
    const double t1 = t0 + g.duration;
    if (t1 > t_) {
      if (std::isinf(t1)) return std::max(t0, t_);
      const double a_end = g.at(g.duration).acc;
      const bool next_starts_flat = i + 1 >= profile_.size() || profile_.segment(i + 1).a == 0.0;
      if (std::fabs(a_end) <= 1e-9 * scale && next_starts_flat) return t1;
    }
    t0 = t1;
  }
  return std::max(t_, profile_.duration());
}

void ProfileGenerator::move_adlink_velocity(double vel, const AdlinkLimits& lim) {
  refuse_if_other_mode_moving(ProfileMode::AdlinkVelocity, "move_adlink_velocity");
  mode_ = ProfileMode::AdlinkVelocity;
  adlink_ = lim;
  start(plan_adlink_velocity(state_, vel, lim));
}

void ProfileGenerator::smooth_stop() {
  if (!moving()) return;
  const double inf = std::numeric_limits<double>::infinity();
  switch (mode_) {
    case ProfileMode::TCurve: smooth_stop_with(t_lim_.acc, inf); break;
    case ProfileMode::SCurve: smooth_stop_with(s_lim_.acc, s_lim_.jerk); break;
    case ProfileMode::Jog: smooth_stop_with(jog_acc_, inf); break;
    case ProfileMode::AdlinkPtp:
    case ProfileMode::AdlinkVelocity:
      stopping_ = true;
      start(plan_adlink_stop(state_, adlink_.dec, adlink_.sf));
      break;
  }
}

void ProfileGenerator::smooth_stop_with(double acc, double jerk) {
  check_positive("smooth_stop", "acc", acc);
  if (!(jerk > 0)) throw_invalid("smooth_stop", "jerk", jerk, "must be > 0 (inf = linear ramp)");
  if (!moving()) return;
  stopping_ = true;
  start(plan_smooth_stop(state_, acc, jerk));
}

void ProfileGenerator::abrupt_stop() {
  stopping_ = false;
  start(plan_abrupt_stop(state_));
}

void ProfileGenerator::set_position(double pos) {
  if (!std::isfinite(pos)) throw_invalid("set_position", "pos", pos, "must be a finite number");
  if (moving()) throw MotionCommandRefused("set_position: only at rest (GT L1429, L4617)");
  start(Profile::rest(pos));
}

void ProfileGenerator::follow(const MotionState& s) {
  stopping_ = false;
  Profile p(MotionState{s.pos, s.vel, s.acc, 0.0});
  p.push(0.5, 0.0).finish_at_rest(s.pos);  // at(0) = s; from t = 0.5 on at rest at s.pos
  start(p);
  t_ = -1.0;  // the next step() lands on t = 0
}

const MotionState& ProfileGenerator::step() {
  if (pending_ && t_ + 1.0 >= pending_ptp_.at) {
    // The deferred on-the-fly PTP change starts at the instant the ramp ended (between two ticks).
    MotionState s = profile_.at(pending_ptp_.at);
    s.acc = 0.0;
    const double tau = t_ + 1.0 - pending_ptp_.at;
    start(plan_adlink_ptp_from(s, pending_ptp_.target, pending_ptp_.lim));
    t_ = tau;
    state_ = profile_.at(t_);
    return state_;
  }
  t_ += 1.0;
  state_ = profile_.at(t_);
  if (stopping_ && !moving()) stopping_ = false;
  return state_;
}

}  // namespace servobench::motion
