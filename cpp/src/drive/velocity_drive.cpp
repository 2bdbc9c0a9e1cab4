#include "servobench/drive/velocity_drive.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::drive {

void VelocityDriveParams::validate(const char* owner) const {
  check_positive(owner, "speed_per_volt_rad_s", speed_per_volt_rad_s, 1e5);
  check_nonnegative(owner, "kp_nms", kp_nms, 1e6);
  check_nonnegative(owner, "ki_nm_per_rad", ki_nm_per_rad, 1e9);
  check_range(owner, "loop_rate_hz", loop_rate_hz, 100.0, 1e6);
  check_positive(owner, "kt", kt, kMaxKt);
  check_positive_or_inf(owner, "current_limit_a", current_limit_a, kMaxCurrentA);
  check_positive_or_inf(owner, "torque_limit_nm", torque_limit_nm, kMaxTorqueNm);
  check_positive_or_inf(owner, "current_bw_hz", current_bw_hz, kMaxCurrentBwHz);
  if (std::isnan(alarm_at_s) || alarm_at_s < 0) throw_invalid(owner, "alarm_at_s", alarm_at_s, "must be >= 0 (inf = never)");
  if (current_limit_a == kInf && torque_limit_nm == kInf)
    throw_invalid(owner, "torque_limit_nm", torque_limit_nm, "and current_limit_a cannot both be inf (the speed loop needs a limit)");
}

double VelocityDriveParams::max_torque_nm() const { return std::min(torque_limit_nm, current_limit_a * kt); }

SpeedLoop::SpeedLoop(const VelocityDriveParams& p)
    : p_(p), ki_td_(p.ki_nm_per_rad / p.loop_rate_hz), tmax_(p.max_torque_nm()) {}

}  // namespace servobench::drive
