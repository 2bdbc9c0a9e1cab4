#include "servobench/drive/pulse_drive.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::drive {

void StepperDriveParams::validate() const {
  constexpr const char* owner = "StepperDrive";
  check_integer(owner, "full_steps_per_rev", full_steps_per_rev, 4, 10000);
  if (std::fmod(full_steps_per_rev, 4.0) != 0.0)
    throw_invalid(owner, "full_steps_per_rev", full_steps_per_rev, "must be a multiple of 4 (a two-phase hybrid stepper)");
  check_integer(owner, "microsteps", microsteps, 1, 256);
  check_positive(owner, "holding_torque_nm", holding_torque_nm);
  if (std::isnan(alarm_at_s) || alarm_at_s < 0) throw_invalid(owner, "alarm_at_s", alarm_at_s, "must be >= 0 (inf = never)");
}

void ServoPositionDriveParams::validate() const {
  constexpr const char* owner = "ServoPositionDrive";
  check_positive(owner, "pulses_per_rev", pulses_per_rev);
  check_nonnegative(owner, "kpp_per_s", kpp_per_s);
  check_range(owner, "speed_feedforward", speed_feedforward, 0.0, 1.0);
  // The speed loop's own fields are checked with this drive's name.
  VelocityDriveParams v = speed_loop();
  check_nonnegative(owner, "kp_nms", kp_nms);
  check_nonnegative(owner, "ki_nm_per_rad", ki_nm_per_rad);
  check_range(owner, "loop_rate_hz", loop_rate_hz, 100.0, 1e6);
  check_positive(owner, "kt", kt);
  check_positive_or_inf(owner, "current_limit_a", current_limit_a);
  check_positive_or_inf(owner, "torque_limit_nm", torque_limit_nm);
  check_positive_or_inf(owner, "current_bw_hz", current_bw_hz);
  if (std::isnan(alarm_at_s) || alarm_at_s < 0) throw_invalid(owner, "alarm_at_s", alarm_at_s, "must be >= 0 (inf = never)");
  if (current_limit_a == kInf && torque_limit_nm == kInf)
    throw_invalid(owner, "torque_limit_nm", torque_limit_nm, "and current_limit_a cannot both be inf (the speed loop needs a limit)");
  (void)v;
}

VelocityDriveParams ServoPositionDriveParams::speed_loop() const {
  VelocityDriveParams v;
  v.speed_per_volt_rad_s = 1.0;
  v.kp_nms = kp_nms;
  v.ki_nm_per_rad = ki_nm_per_rad;
  v.loop_rate_hz = loop_rate_hz;
  v.kt = kt;
  v.current_limit_a = current_limit_a;
  v.torque_limit_nm = torque_limit_nm;
  v.current_bw_hz = current_bw_hz;
  v.alarm_at_s = alarm_at_s;
  return v;
}

}  // namespace servobench::drive
