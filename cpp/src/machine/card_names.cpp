// The card kernel's names (to_string of its enums) and the validation of its configuration structs.
#include "servobench/machine/card.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

const char* to_string(AxisMode mode) {
  switch (mode) {
    case AxisMode::TCurve: return "t_curve";
    case AxisMode::Jog: return "jog";
    case AxisMode::SCurve: return "s_curve";
    case AxisMode::Gear: return "gear";
    case AxisMode::Coordinated: return "coordinated";
    case AxisMode::Pvt: return "pvt";
    case AxisMode::Follow: return "follow";
  }
  return "?";
}

const char* to_string(CommandFault fault) {
  switch (fault) {
    case CommandFault::None: return "none";
    case CommandFault::MotionParamOverflow: return "motion_param_overflow";
    case CommandFault::IllegalControlParam: return "illegal_control_param";
    case CommandFault::NoAxisInMask: return "no_axis_in_mask";
    case CommandFault::DriveResetWhileEnabled: return "drive_reset_while_enabled";
    case CommandFault::ModeChangeInMotion: return "mode_change_in_motion";
    case CommandFault::IndexCaptureArmed: return "index_capture_armed";
    case CommandFault::HomeCaptureArmed: return "home_capture_armed";
    case CommandFault::AxisOnWhileAlarm: return "axis_on_while_alarm";
    case CommandFault::ChangeInMotion: return "change_in_motion";
    case CommandFault::DirectionInhibited: return "direction_inhibited";
    case CommandFault::EmergencyStopActive: return "emergency_stop_active";
    case CommandFault::InvalidInMode: return "invalid_in_mode";
    case CommandFault::DriveAlarmActive: return "drive_alarm_active";
    case CommandFault::DistanceTooShort: return "distance_too_short";
    case CommandFault::MotorStateWhileEnabled: return "motor_state_while_enabled";
    case CommandFault::AxisStateError: return "axis_state_error";
    case CommandFault::NotInCommandSet: return "not_in_command_set";
    case CommandFault::NotSimulated: return "not_simulated";
    case CommandFault::CrdStateError: return "crd_state_error";
    case CommandFault::NoInterruptPending: return "no_interrupt_pending";
  }
  return "?";
}

const char* to_string(StopCause cause) {
  switch (cause) {
    case StopCause::None: return "none";
    case StopCause::EmergencyStop: return "emergency_stop";
    case StopCause::DriveAlarm: return "drive_alarm";
    case StopCause::PosLimit: return "pos_limit";
    case StopCause::NegLimit: return "neg_limit";
    case StopCause::SoftPosLimit: return "soft_pos_limit";
    case StopCause::SoftNegLimit: return "soft_neg_limit";
    case StopCause::ErrorLevel: return "error_level";
    case StopCause::FollowingError: return "following_error";
  }
  return "?";
}

void CardCycles::validate() const {
  check_integer("CardCycles", "motion_cycle_ticks", motion_cycle_ticks, 1, 1000);
  check_integer("CardCycles", "host_cycle_ticks", host_cycle_ticks, 1, 10000);
  if (std::fmod(host_cycle_ticks, motion_cycle_ticks) != 0.0)
    throw_invalid("CardCycles", "host_cycle_ticks", host_cycle_ticks,
                  "must be a whole multiple of motion_cycle_ticks = " + format_value(motion_cycle_ticks));
}

void LimitConfig::validate() const {
  if (!std::isfinite(soft_pos_pulse)) throw_invalid("CardLimits", "soft_pos_pulse", soft_pos_pulse, "must be finite");
  if (!std::isfinite(soft_neg_pulse)) throw_invalid("CardLimits", "soft_neg_pulse", soft_neg_pulse, "must be finite");
  if (soft_pos_enabled && soft_neg_enabled && !(soft_neg_pulse < soft_pos_pulse))
    throw_invalid("CardLimits", "soft_neg_pulse", soft_neg_pulse,
                  "must be below soft_pos_pulse = " + format_value(soft_pos_pulse) + " when both soft limits are on");
}

}  // namespace servobench::machine
