// A servo amplifier in torque (current) mode: V -> current command -> current loop -> torque.
//
//   i_cmd = clamp(amps_per_volt * V, +-min(current_limit_a, torque_limit_nm / kt))   (A)
//   di/dt = 2*pi*current_bw_hz * (i_cmd - i)                                          (first-order current loop)
//   torque = kt * i                                                                   (N*m)
//
// current_bw_hz = inf is an ideal current loop (i = i_cmd at once). A drive alarm can be injected at
// alarm_at_s: the amplifier trips, its current command drops to zero and stays there (like a real ALM).
#pragma once

#include <limits>

#include <Eigen/Core>

namespace servobench::drive {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Upper bounds of the drive parameters (decision RB3). The current-loop bandwidth stays below what the plant's
// exact discretisation resolves (above ~1e6 Hz the loop's pole, -2 pi f Ts, underflows the matrix exponential:
// the axis freezes or runs NaN); inf = an ideal current loop.
constexpr double kMaxCurrentBwHz = 1e6;
constexpr double kMaxAmpsPerVolt = 1e3;  // A/V
constexpr double kMaxKt = 1e3;           // N*m/A
constexpr double kMaxCurrentA = 1e12;    // A (the generic cap: a finite "no limit" stays allowed)
constexpr double kMaxTorqueNm = 1e12;    // N*m

struct TorqueDriveParams {
  double amps_per_volt = 0.8;     // A/V, > 0
  double kt = 0.5;                // torque constant, N*m/A, > 0
  double current_limit_a = 8.0;   // |i_cmd| limit, A, > 0 (inf = none)
  double torque_limit_nm = kInf;  // |torque| limit, N*m, > 0 (inf = none)
  double current_bw_hz = 1500.0;  // current-loop bandwidth, Hz, > 0 (inf = ideal)
  double alarm_at_s = kInf;       // time at which the drive alarm trips, s, >= 0 (inf = never)
  void validate() const;
  bool ideal() const { return current_bw_hz == kInf; }
  double max_current_a() const;   // min(current limit, torque limit / kt)
};

// The current loop as a continuous linear system, current command (A) in, motor torque (N*m) out:
//   x' = A x + B i_cmd,  torque = C x + D i_cmd.  Zero states when the loop is ideal.
struct DriveLti {
  Eigen::MatrixXd a, b, c, d;
};

DriveLti current_loop_lti(double kt, double current_bw_hz);

}  // namespace servobench::drive
