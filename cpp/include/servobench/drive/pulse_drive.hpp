// Drives for the pulse-output cards: the card sends a step train (the command position in whole pulses) instead of
// a voltage (GT SG/SP cards, the ADLINK card in pulse mode; gt.md §2.3, adlink.md §1).
//
// StepperDriveParams: an ideal two-phase hybrid stepper and its driver. Each pulse advances the current vector by one
// microstep; the rotor torque is the stepper's torque-angle curve
//     T = holding_torque_nm * sin(N * (theta_cmd - theta)),   N = full_steps_per_rev / 4 (rotor teeth)
// so the rotor follows while the load needs less than the pull-out torque, and slips by whole tooth pitches (4 full
// steps) — steps are lost — when it needs more.
//
// ServoPositionDriveParams: a servo amplifier in position mode: pulses -> motor angle command (electronic gear
// pulses_per_rev), a proportional position loop plus speed feed-forward, then a PI speed loop and the current loop,
// all at loop_rate_hz.
#pragma once

#include "servobench/drive/torque_drive.hpp"
#include "servobench/drive/velocity_drive.hpp"

namespace servobench::drive {

struct StepperDriveParams {
  double full_steps_per_rev = 200.0;  // full steps per revolution (1.8 deg motor: 200), whole number 4..10000, multiple of 4
  double microsteps = 1.0;            // microsteps per full step (pulses per full step), whole number 1..256
  double holding_torque_nm = 0.5;     // peak of the torque-angle curve, N*m, > 0
  double alarm_at_s = kInf;           // driver alarm trip time, s (inf = never); the rotor is then unpowered
  void validate() const;
  double pulses_per_rev() const { return full_steps_per_rev * microsteps; }
  double teeth() const { return full_steps_per_rev / 4.0; }
};

struct ServoPositionDriveParams {
  double pulses_per_rev = 10000.0;   // electronic gear: command pulses per motor revolution, > 0
  double kpp_per_s = 200.0;          // position-loop gain, (rad/s) per rad = 1/s, >= 0
  double speed_feedforward = 1.0;    // fraction of the pulse rate fed forward to the speed loop, 0..1
  double kp_nms = 0.02;              // speed-loop P gain, N*m per rad/s
  double ki_nm_per_rad = 4.0;        // speed-loop I gain, N*m per rad
  double loop_rate_hz = 20000.0;     // position/speed loop rate, Hz (the servo period must be a whole number of its periods)
  double kt = 0.5;                   // N*m/A
  double current_limit_a = 8.0;      // A (inf = none)
  double torque_limit_nm = kInf;     // N*m (inf = none)
  double current_bw_hz = 1500.0;     // Hz (inf = ideal)
  double alarm_at_s = kInf;          // s (inf = never)
  void validate() const;
  // The speed loop of this drive, as a VelocityDriveParams (1 rad/s per "volt": the loop is fed in rad/s).
  VelocityDriveParams speed_loop() const;
};

}  // namespace servobench::drive
