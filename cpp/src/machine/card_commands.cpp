// The card kernel's immediate commands: mode, stops, position set, servo on/off, open loop, breakpoint, capture,
// GT homing, the move guard, limits and events (machine/card.hpp).
#include "servobench/machine/card.hpp"

#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

// -- immediate commands -------------------------------------------------------------------------------------

void Card::set_mode(std::size_t i, AxisMode mode) {
  CardAxisState& s = at(i);
  if (mode != AxisMode::TCurve && mode != AxisMode::SCurve && mode != AxisMode::Jog)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode,
           std::string(to_string(mode)) + " mode is entered through Card::modes() (set_gear, set_pvt, set_follow, "
           "a coordinate system)");
  if (moving(i) && s.mode != AxisMode::Gear)
    refuse(static_cast<int>(i), CommandFault::ModeChangeInMotion,
           "the motion mode can change only when the motion has ended (GT L837, L464)");
  for (CardHooks* h : hooks_) h->leave(i);  // [modes] leaving gear / PVT / cam / a coordinate system
  s.mode = mode;
}

void Card::stop_profile(std::size_t i) {
  loops_[i]->generator().abrupt_stop();
  st_[i].was_moving = false;
  st_[i].events |= event_bit(CardEvent::MotionComplete);
}

void Card::abrupt_stop(std::size_t i) {
  at(i);
  for (CardHooks* h : hooks_) h->on_abrupt_stop(i);  // [modes] halts the gear / PVT / cam / the coordinate system
  stop_profile(i);
}

void Card::check_position_set(std::size_t i) {
  const CardAxisState& s = at(i);
  if (s.mode == AxisMode::Gear)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "ZeroPos/SetAtlPos are invalid in gear mode (GT L1421-1429)");
  if (s.mode == AxisMode::Coordinated)  // [modes] the coordinate system owns the position (V55)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "ZeroPos/SetAtlPos are invalid in a coordinate system (GT L1659)");
  if (moving(i) || loops_[i]->sequence_active())
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "ZeroPos/SetAtlPos only at rest (GT L1421, L4617)");
}

void Card::set_actual_pos(std::size_t i, double pos) {
  CardAxisState& s = at(i);
  checked(i, CommandFault::MotionParamOverflow,
          [&] { check_integer("Card", "pos", pos, -2147483648.0, 2147483647.0, "whole pulses, the 32-bit register"); });
  check_position_set(i);
  loops_[i]->set_actual_position(pos);  // actual = profile = pos (GT L4613-4622)
  s.staged.pos = s.active.pos = pos;  // target
}

void Card::zero_pos_range(std::size_t first, std::size_t count) {
  at(first);
  if (count < 1 || count > loops_.size() - first)
    throw_invalid("Card", "count", static_cast<double>(count),
                  "must be 1.." + std::to_string(loops_.size() - first) + " (axes from `first` to the card's last)");
  const std::size_t last = first + count;
  for (std::size_t i = first; i < last; ++i) check_position_set(i);  // all or nothing
  for (std::size_t i = first; i < last; ++i) set_actual_pos(i, 0.0);
}

void Card::apply_output(std::size_t i) {
  const CardAxisState& s = st_[i];
  Axis& a = loops_[i]->axis();
  a.set_servo_on(s.enabled && s.closed_loop);
  loops_[i]->set_output_add(s.enabled && !s.closed_loop, control::GtServoLaw::counts_to_volts(s.mtr_cmd));
}

void Card::axis_on(std::size_t i) {
  CardAxisState& s = at(i);
  if (s.events & event_bit(CardEvent::DriveAlarm))
    refuse(static_cast<int>(i), CommandFault::AxisOnWhileAlarm,
           "AxisOn with the drive-alarm event set: DrvRst and clear it first (GT L472, L2188-2192)");
  s.enabled = true;
  s.events |= event_bit(CardEvent::MotionComplete);  // GT L1481
  apply_output(i);
}

void Card::axis_off(std::size_t i) {
  at(i).enabled = false;
  apply_output(i);
}

void Card::drive_reset(std::size_t i) {
  if (at(i).enabled)
    refuse(static_cast<int>(i), CommandFault::DriveResetWhileEnabled,
           "DrvRst only with the drive disabled (GT L461, L3216)");
  loops_[i]->axis().clear_drive_alarm();
}

void Card::set_closed_loop(std::size_t i, bool closed) {
  at(i).closed_loop = closed;
  apply_output(i);
}

void Card::set_mtr_cmd(std::size_t i, double counts) {
  at(i);
  checked(i, CommandFault::IllegalControlParam,
          [&] { check_range("Card", "mtr_cmd", counts, -32767, 32767, "GT L4960-4966"); });
  st_[i].mtr_cmd = counts;
  apply_output(i);
}

void Card::arm_breakpoint(std::size_t i, motion::BreakKind kind) {
  CardAxisState& s = at(i);
  s.brk_deferred = false;
  if (kind != motion::BreakKind::None && s.commit_pending && (s.pending_dirty & kStagedBrkCn)) {
    s.brk_deferred = true;  // the compare value the program just updated becomes active first (V26)
    s.brk_deferred_kind = kind;
    return;
  }
  if (kind == motion::BreakKind::None) {
    loops_[i]->breakpoint().off();
  } else {
    loops_[i]->breakpoint().arm(kind);
  }
}

void Card::arm_capture(std::size_t i, CaptureTrigger trigger) {
  at(i);
  try {
    loops_[i]->capture().arm(trigger);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i),
           trigger == CaptureTrigger::Index ? CommandFault::IndexCaptureArmed : CommandFault::HomeCaptureArmed,
           e.what());
  }
}

void Card::home(std::size_t i, const motion::GtHomeParams& p) {
  at(i);
  p.validate();
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "GT_Home only at rest");
  if (estop_) refuse(static_cast<int>(i), CommandFault::EmergencyStopActive, "GT_Home refused while the e-stop is active");
  try {
    loops_[i]->home(p);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

bool Card::alarm_active(std::size_t i) const {
  const CardAxisState& s = st_[i];
  return s.alarm_enabled && (loops_[i]->axis().alarm() || s.alarm_input);
}

void Card::check_move_allowed(std::size_t i, double dir) {
  CardAxisState& s = at(i);
  const int ai = static_cast<int>(i);
  if (s.mode != AxisMode::TCurve && s.mode != AxisMode::SCurve && s.mode != AxisMode::Jog)
    refuse(ai, CommandFault::InvalidInMode, std::string("no point-to-point or velocity move in ") + to_string(s.mode) + " mode");
  if (loops_[i]->sequence_active()) refuse(ai, CommandFault::ChangeInMotion, "a homing sequence runs");
  if (estop_) {
    s.stop_cause = StopCause::EmergencyStop;
    refuse(ai, CommandFault::EmergencyStopActive, "motion ignored while the emergency stop is active (ADLINK L3936)");
  }
  if (alarm_active(i)) {
    s.stop_cause = StopCause::DriveAlarm;
    refuse(ai, CommandFault::DriveAlarmActive, "motion ignored while the alarm input is active (ADLINK L3953)");
  }
  if (dir > 0.0 && inhibited_pos(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::PosLimit));
    s.stop_cause = hard ? StopCause::PosLimit : StopCause::SoftPosLimit;
    refuse(ai, CommandFault::DirectionInhibited, "positive motion ignored while the positive limit is active (ADLINK L3971, L4007)");
  }
  if (dir < 0.0 && inhibited_neg(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::NegLimit));
    s.stop_cause = hard ? StopCause::NegLimit : StopCause::SoftNegLimit;
    refuse(ai, CommandFault::DirectionInhibited, "negative motion ignored while the negative limit is active (ADLINK L3973, L4009)");
  }
}

void Card::set_target_pos(std::size_t i, double pos) {
  CardAxisState& s = at(i);
  s.staged.pos = s.active.pos = pos;
}

void Card::latch_event(std::size_t i, CardEvent e) { at(i).events |= event_bit(e); }

void Card::set_limits(std::size_t i, const LimitConfig& limits) {
  at(i);
  limits.validate();
  st_[i].limits = limits;
}

void Card::clear_events(std::size_t i, std::uint32_t which) {
  CardAxisState& s = at(i);
  which &= kAllEvents;
  if (s.following_error_now) which &= ~event_bit(CardEvent::FollowingError);  // GT L1453
  s.events &= ~which;
  if (which & event_bit(CardEvent::Breakpoint)) loops_[i]->clear_breakpoint_flag();
  if (which & event_bit(CardEvent::Captured)) loops_[i]->capture().clear();
}

// -- GE additions -------------------------------------------------------------------------------------------

void Card::smooth_stop(std::size_t i) {
  at(i);
  if (loops_[i]->sequence_active()) {
    loops_[i]->cancel_sequence();
    stop_profile(i);
    return;
  }
  if (loops_[i]->generator().moving()) loops_[i]->generator().smooth_stop();
}

void Card::arm_probe() {
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    const CaptureUnit& c = loops_[i]->capture();
    if (c.armed() != CaptureTrigger::None || c.captured())
      refuse(static_cast<int>(i), CommandFault::HomeCaptureArmed,
             "GT_CaptProb: the capture is armed or still flags a capture; GT_ClrSts first (GE L2334-2336)");
  }
  for (auto& l : loops_) l->capture().arm(CaptureTrigger::Probe);
}

void Card::synch_pos_now(std::size_t i) {
  CardAxisState& s = at(i);
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "synchronise the profile only at rest");
  const double a = std::nearbyint(loops_[i]->actual_pos());
  loops_[i]->generator().set_position(a);
  s.staged.pos = s.active.pos = a;
}

}  // namespace servobench::machine
