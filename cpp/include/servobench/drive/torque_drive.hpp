// A servo amplifier in torque (current) mode: V -> current command -> current loop -> torque.
//
//   i_cmd = clamp(amps_per_volt * V, +-current_limit_a)          (A)
//   di/dt = 2*pi*current_bw_hz * (i_cmd - i)                      (first-order current loop)
//   torque = kt * i                                               (N*m)
//
// current_bw_hz = inf is an ideal current loop (i = i_cmd at once). The linear part is given as a
// continuous state-space model so the machine layer can integrate it exactly together with the mechanics.
#pragma once

#include <limits>

#include <Eigen/Core>

namespace servobench::drive {

struct TorqueDriveParams {
  double amps_per_volt = 0.8;    // A/V, > 0
  double kt = 0.5;               // torque constant, N*m/A, > 0
  double current_limit_a = 8.0;  // |i_cmd| limit, A, > 0 (inf = none)
  double current_bw_hz = 1500.0; // current-loop bandwidth, Hz, > 0 (inf = ideal)
  void validate() const;
  bool ideal() const { return current_bw_hz == std::numeric_limits<double>::infinity(); }
};

// The drive's linear part, current command (A) in, motor torque (N*m) out:
//   x' = A x + B i_cmd,  torque = C x + D i_cmd.  Zero states when the current loop is ideal.
struct DriveLti {
  Eigen::MatrixXd a, b, c, d;
};

DriveLti torque_drive_lti(const TorqueDriveParams& params);

// The nonlinear input stage: current command for a voltage, with the current limit.
inline double torque_drive_current_command(const TorqueDriveParams& p, double volts) {
  const double i = p.amps_per_volt * volts;
  const double lim = p.current_limit_a;
  return i > lim ? lim : (i < -lim ? -lim : i);
}

}  // namespace servobench::drive
