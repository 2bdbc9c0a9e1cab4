#include "servobench/drive/torque_drive.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::drive {

void TorqueDriveParams::validate() const {
  check_positive("TorqueDrive", "amps_per_volt", amps_per_volt);
  check_positive("TorqueDrive", "kt", kt);
  check_positive_or_inf("TorqueDrive", "current_limit_a", current_limit_a);
  check_positive_or_inf("TorqueDrive", "current_bw_hz", current_bw_hz);
}

DriveLti torque_drive_lti(const TorqueDriveParams& p) {
  DriveLti m;
  if (p.ideal()) {
    m.a.resize(0, 0);
    m.b.resize(0, 1);
    m.c.resize(1, 0);
    m.d = Eigen::MatrixXd::Constant(1, 1, p.kt);
  } else {
    const double wc = 2.0 * M_PI * p.current_bw_hz;
    m.a = Eigen::MatrixXd::Constant(1, 1, -wc);
    m.b = Eigen::MatrixXd::Constant(1, 1, wc);
    m.c = Eigen::MatrixXd::Constant(1, 1, p.kt);
    m.d = Eigen::MatrixXd::Zero(1, 1);
  }
  return m;
}

}  // namespace servobench::drive
