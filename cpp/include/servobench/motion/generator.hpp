// ProfileGenerator: one axis's profile generator, stepped once per tick, with the manuals' rules for
// commands during motion.
//
// It holds the current profile and the time into it; step() advances one tick and returns the new state.
// Commands replan from the current state (fractional position kept inside; reported_pos() is the whole
// pulse the card reports). Rules (GT L837, L909, L974-978, L1025, L1142-1148; GE L315, L1067-1071,
// L1179-1183, L1263-1264, L1312):
//  - a mode change (T-curve, S-curve, jog, ADLINK PTP, ADLINK velocity) is refused while in motion;
//  - T-curve in motion: target and velocity may change, acceleration may not;
//  - S-curve in motion: only the target may change;
//  - jog in motion: velocity and acceleration may change;
//  - during a smooth stop, motion commands are refused until it completes; an abrupt stop is always valid.
// Refusals throw MotionCommandRefused (RuntimeError in Python); the vendor return codes come with the card.
// Internal units: pulse and ticks (pulse/tick, pulse/tick^2, pulse/tick^3).
#pragma once

#include <stdexcept>
#include <string>

#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/jog.hpp"
#include "servobench/motion/profile.hpp"
#include "servobench/motion/s_curve.hpp"
#include "servobench/motion/t_curve.hpp"

namespace servobench::motion {

class MotionCommandRefused : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

enum class ProfileMode { TCurve, SCurve, Jog, AdlinkPtp, AdlinkVelocity };

const char* to_string(ProfileMode mode);

class ProfileGenerator {
 public:
  // period_s: the tick in seconds, used to convert the pulse/ms (GE, GUC-ECAT, iDEABOX) and pulse/s (ADLINK)
  // parameters; GT parameters are per tick already.
  explicit ProfileGenerator(double start_pos = 0.0, double period_s = 200e-6);

  // The manuals' commands with their own parameter sets (validated, converted to ticks, then as below).
  void command(const GtTCurveParams& p);
  void command(const GtSCurveParams& p);
  void command(const GtJogParams& p);
  void command(const GeTCurveParams& p);
  void command(const GeSCurveParams& p);
  void command(const GeJogParams& p);
  void command(const AdlinkPtpParams& p);
  // ADLINK APS_vel: velocity move to the signed `vel_pulse_per_s` with p's ACC, DEC and S-factor.
  void adlink_velocity(double vel_pulse_per_s, const AdlinkPtpParams& p);
  // ADLINK APS_stop_move: decelerate at PRA_SD_DEC (p.sd_dec, or p.dec if 0) with p's S-factor.
  void adlink_stop_move(const AdlinkPtpParams& p);
  double period_s() const { return period_s_; }

  // GT/GE T-curve: start a move to `target` (pulse), or change target/velocity on the fly.
  void move_t_curve(double target, const TCurveLimits& lim);
  // GT/GE S-curve: start a move, or change only the target on the fly.
  void move_s_curve(double target, const SCurveLimits& lim);
  // GT/GE jog: ramp at `acc` (pulse/tick^2, linear) to the signed `vel` (pulse/tick) and hold it.
  void jog(double vel, double acc);
  // ADLINK point to point; during an ADLINK PTP or velocity move it changes the move on the fly (new target,
  // new speeds, or both: L2757-2767, L2564-2566), taking effect at the next instant the acceleration is zero
  // (at once on a T-curve or a cruise; at the end of the running S ramp otherwise; decision M44).
  void move_adlink_ptp(double target, const AdlinkLimits& lim);
  // ADLINK velocity move: ramp (S-factor) to the signed `vel` and hold; may change on the fly.
  void move_adlink_velocity(double vel, const AdlinkLimits& lim);

  // Smooth stop at the current mode's limits (T: acc; S: macc and jerk; jog: acc; ADLINK: dec and S).
  void smooth_stop();
  // Smooth stop at the given deceleration (pulse/tick^2) and jerk (+inf = linear): ADLINK stop_move SD_DEC.
  void smooth_stop_with(double acc, double jerk);
  // Velocity and acceleration zero at once, the position holds (GT_AbptStp, APS_emg_stop).
  void abrupt_stop();
  // Sets the position (at rest only): GT_SetAtlPos / GT_ZeroPos.
  void set_position(double pos);
  // An outside source drives the axis (a card's gear, PVT, cam or coordinated path): the next step() returns
  // exactly `s` (velocity and acceleration kept for the feed-forward); moving() is true after that step. Without
  // a further follow() the step after rests at s.pos (velocity 0). Any running profile is dropped.
  void follow(const MotionState& s);

  // Advances one tick and returns the state at the new tick.
  const MotionState& step();

  const MotionState& state() const { return state_; }
  // The profile position in whole pulses, as the card reports it (rounded half away from zero).
  long long reported_pos() const;
  // In motion: the profile has not finished (or a jog holds a non-zero velocity).
  bool moving() const;
  bool stopping() const { return stopping_; }
  ProfileMode mode() const { return mode_; }
  const Profile& profile() const { return profile_; }
  // Ticks since the current profile started.
  double time_in_profile() const { return t_; }

 private:
  void start(const Profile& p);
  // Time (ticks, >= t_) of the first instant from now at which the current profile's acceleration is zero.
  double next_zero_acc_time() const;
  void refuse_if_other_mode_moving(ProfileMode wanted, const char* cmd) const;

  Profile profile_;
  MotionState state_;
  double t_ = 0.0;
  double period_s_ = 200e-6;
  ProfileMode mode_ = ProfileMode::TCurve;  // reset default: T-curve (GT HardRst [5], L4130)
  bool stopping_ = false;
  TCurveLimits t_lim_{};
  SCurveLimits s_lim_{};
  double jog_acc_ = 0.0;
  AdlinkLimits adlink_{};
  // An ADLINK on-the-fly PTP change waiting for the running S ramp to end (at profile time `at`, ticks).
  struct PendingPtp {
    double at = 0.0;
    double target = 0.0;
    AdlinkLimits lim{};
  };
  bool pending_ = false;
  PendingPtp pending_ptp_{};
};

}  // namespace servobench::motion
