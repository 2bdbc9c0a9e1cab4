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
  speed_loop().validate(owner);  // the speed-loop fields, named as this drive's
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
