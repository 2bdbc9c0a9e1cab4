#include "servobench/drive/torque_drive.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::drive {

void TorqueDriveParams::validate() const {
  check_positive("TorqueDrive", "amps_per_volt", amps_per_volt, kMaxAmpsPerVolt);
  check_positive("TorqueDrive", "kt", kt, kMaxKt);
  check_positive_or_inf("TorqueDrive", "current_limit_a", current_limit_a, kMaxCurrentA);
  check_positive_or_inf("TorqueDrive", "torque_limit_nm", torque_limit_nm, kMaxTorqueNm);
  check_positive_or_inf("TorqueDrive", "current_bw_hz", current_bw_hz, kMaxCurrentBwHz);
  if (std::isnan(alarm_at_s) || alarm_at_s < 0) throw_invalid("TorqueDrive", "alarm_at_s", alarm_at_s, "must be >= 0 (inf = never)");
}

double TorqueDriveParams::max_current_a() const { return std::min(current_limit_a, torque_limit_nm / kt); }

DriveLti current_loop_lti(double kt, double current_bw_hz) {
  DriveLti m;
  if (current_bw_hz == kInf) {
    m.a.resize(0, 0);
    m.b.resize(0, 1);
    m.c.resize(1, 0);
    m.d = Eigen::MatrixXd::Constant(1, 1, kt);
  } else {
    const double wc = 2.0 * M_PI * current_bw_hz;
    m.a = Eigen::MatrixXd::Constant(1, 1, -wc);
    m.b = Eigen::MatrixXd::Constant(1, 1, wc);
    m.c = Eigen::MatrixXd::Constant(1, 1, kt);
    m.d = Eigen::MatrixXd::Zero(1, 1);
  }
  return m;
}

}  // namespace servobench::drive
