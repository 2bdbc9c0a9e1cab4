// A servo amplifier in velocity mode: the card's voltage is a speed command; the drive closes its own
// PI speed loop at loop_rate_hz on the motor speed, with a torque limit, and drives its current loop.
//
//   w_cmd = speed_per_volt_rad_s * V                                                (rad/s)
//   every 1/loop_rate_hz:  e = w_cmd - w_motor,  I += ki*e*Td (clamped),  T = clamp(kp*e + I, +-T_max)
//   i_cmd = T / kt,   T_max = min(torque_limit_nm, current_limit_a * kt)
//
// Velocity-mode drives are how many GE/GT users wire the analog output (ge.md §9.6).
#pragma once

#include "servobench/drive/torque_drive.hpp"

namespace servobench::drive {

struct VelocityDriveParams {
  double speed_per_volt_rad_s = 31.41592653589793;  // speed command per volt, rad/s/V (3000 rpm at 10 V), > 0
  double kp_nms = 0.02;            // speed-loop proportional gain, N*m per rad/s, >= 0
  double ki_nm_per_rad = 4.0;      // speed-loop integral gain, N*m per rad (per rad/s per s), >= 0
  double loop_rate_hz = 20000.0;   // speed-loop rate, Hz, 100..1e6; the servo period must be a whole number of its periods
  double kt = 0.5;                 // torque constant, N*m/A, > 0
  double current_limit_a = 8.0;    // A, > 0 (inf = none)
  double torque_limit_nm = kInf;   // N*m, > 0 (inf = none)
  double current_bw_hz = 1500.0;   // current-loop bandwidth, Hz (inf = ideal)
  double alarm_at_s = kInf;        // drive alarm trip time, s (inf = never)
  // owner: the parameter object named in messages (a position-mode drive validates its speed loop as its own).
  void validate(const char* owner = "VelocityDrive") const;
  double max_torque_nm() const;
};

// The discrete PI speed loop (state: the integrator, N*m).
class SpeedLoop {
 public:
  explicit SpeedLoop(const VelocityDriveParams& p);
  void reset() { integral_ = 0.0; }
  // One loop update: returns the current command, A.
  double update(double volts, double speed_rad_s) { return update_speed(p_.speed_per_volt_rad_s * volts, speed_rad_s); }
  // The same with the speed command given directly, rad/s.
  double update_speed(double speed_cmd_rad_s, double speed_rad_s) {
    const double e = speed_cmd_rad_s - speed_rad_s;
    double integ = integral_ + ki_td_ * e;
    integ = integ > tmax_ ? tmax_ : (integ < -tmax_ ? -tmax_ : integ);
    integral_ = integ;
    double t = p_.kp_nms * e + integ;
    t = t > tmax_ ? tmax_ : (t < -tmax_ ? -tmax_ : t);
    return t / p_.kt;
  }
  double integral_nm() const { return integral_; }

 private:
  VelocityDriveParams p_;
  double ki_td_;
  double tmax_;
  double integral_ = 0.0;
};

}  // namespace servobench::drive
