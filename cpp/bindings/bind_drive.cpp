#include "param_class.hpp"
#include "servobench/drive/dac.hpp"
#include "servobench/drive/pulse_drive.hpp"
#include "servobench/drive/torque_drive.hpp"
#include "servobench/drive/velocity_drive.hpp"

namespace servobench::bindings {

void bind_drive(py::module_& m) {
  using drive::DacParams;
  using drive::TorqueDriveParams;
  using drive::VelocityDriveParams;
  using drive::ServoPositionDriveParams;
  using drive::StepperDriveParams;

  ParamClass<DacParams>(m, "Dac",
      "Bipolar DAC: saturates at +-full_scale_v and (if quantize) rounds to the nearest of the symmetric codes\n"
      "-(2^(bits-1)-1)..+(2^(bits-1)-1). Default 16 bits, +-10 V as on the GT and ADLINK cards.")
      .field("bits", &DacParams::bits, "resolution, 8..24 bits")
      .field("full_scale_v", &DacParams::full_scale_v, "full scale, V, 0.001..100")
      .field("quantize", &DacParams::quantize, "False: ideal continuous DAC (saturation only)")
      .finish();

  ParamClass<TorqueDriveParams>(m, "TorqueDrive",
      "Servo amplifier in torque mode: i_cmd = clamp(amps_per_volt*V, +-min(current_limit_a, torque_limit_nm/kt));\n"
      "first-order current loop of bandwidth current_bw_hz (inf = ideal); torque = kt*i. alarm_at_s: time at which\n"
      "a drive alarm trips (current command forced to 0 from then on; inf = never).")
      .field("amps_per_volt", &TorqueDriveParams::amps_per_volt, "current command per volt, A/V, > 0")
      .field("kt", &TorqueDriveParams::kt, "torque constant, N*m/A, > 0")
      .field("current_limit_a", &TorqueDriveParams::current_limit_a, "current command limit, A, > 0 (inf = none)")
      .field("torque_limit_nm", &TorqueDriveParams::torque_limit_nm, "torque limit, N*m, > 0 (inf = none)")
      .field("current_bw_hz", &TorqueDriveParams::current_bw_hz, "current-loop bandwidth, Hz, > 0 (inf = ideal)")
      .field("alarm_at_s", &TorqueDriveParams::alarm_at_s, "drive alarm trip time, s, >= 0 (inf = never)")
      .finish();

  ParamClass<VelocityDriveParams>(m, "VelocityDrive",
      "Servo amplifier in velocity mode: w_cmd = speed_per_volt_rad_s*V; a discrete PI speed loop at loop_rate_hz\n"
      "(T = kp_nms*e + integral of ki_nm_per_rad*e, both clamped to the torque limit) on the motor speed, then the\n"
      "current loop. The servo period must be a whole number of speed-loop periods.")
      .field("speed_per_volt_rad_s", &VelocityDriveParams::speed_per_volt_rad_s, "speed command per volt, rad/s/V, > 0")
      .field("kp_nms", &VelocityDriveParams::kp_nms, "speed-loop P gain, N*m per rad/s, >= 0")
      .field("ki_nm_per_rad", &VelocityDriveParams::ki_nm_per_rad, "speed-loop I gain, N*m per rad, >= 0")
      .field("loop_rate_hz", &VelocityDriveParams::loop_rate_hz, "speed-loop rate, Hz, 100..1e6")
      .field("kt", &VelocityDriveParams::kt, "torque constant, N*m/A, > 0")
      .field("current_limit_a", &VelocityDriveParams::current_limit_a, "current limit, A, > 0 (inf = none)")
      .field("torque_limit_nm", &VelocityDriveParams::torque_limit_nm, "torque limit, N*m, > 0 (inf = none)")
      .field("current_bw_hz", &VelocityDriveParams::current_bw_hz, "current-loop bandwidth, Hz, > 0 (inf = ideal)")
      .field("alarm_at_s", &VelocityDriveParams::alarm_at_s, "drive alarm trip time, s, >= 0 (inf = never)")
      .finish();

  ParamClass<StepperDriveParams>(m, "StepperDrive",
      "Pulse-input stepper motor and driver (for pulse-output cards). Each command pulse advances the current vector\n"
      "one microstep; rotor torque T = holding_torque_nm*sin(N*(theta_cmd - theta)), N = full_steps_per_rev/4 rotor\n"
      "teeth. Beyond the pull-out torque the rotor slips by whole tooth pitches (4 full steps): steps are lost.\n"
      "Model the rotor inertia and friction in the plant.")
      .field("full_steps_per_rev", &StepperDriveParams::full_steps_per_rev, "full steps per revolution, multiple of 4, 4..10000")
      .field("microsteps", &StepperDriveParams::microsteps, "pulses per full step, 1..256")
      .field("holding_torque_nm", &StepperDriveParams::holding_torque_nm, "peak of the torque-angle curve, N*m, > 0")
      .field("alarm_at_s", &StepperDriveParams::alarm_at_s, "driver alarm trip time, s (inf = never)")
      .finish();

  ParamClass<ServoPositionDriveParams>(m, "ServoPositionDrive",
      "Pulse-input servo amplifier in position mode: pulses -> angle command (pulses_per_rev), position loop\n"
      "kpp_per_s plus speed_feedforward x the pulse rate, PI speed loop (kp_nms, ki_nm_per_rad) and current loop,\n"
      "at loop_rate_hz (a whole multiple of the servo rate).")
      .field("pulses_per_rev", &ServoPositionDriveParams::pulses_per_rev, "command pulses per motor revolution, > 0")
      .field("kpp_per_s", &ServoPositionDriveParams::kpp_per_s, "position-loop gain, 1/s, >= 0")
      .field("speed_feedforward", &ServoPositionDriveParams::speed_feedforward, "speed feed-forward fraction, 0..1")
      .field("kp_nms", &ServoPositionDriveParams::kp_nms, "speed-loop P gain, N*m per rad/s, >= 0")
      .field("ki_nm_per_rad", &ServoPositionDriveParams::ki_nm_per_rad, "speed-loop I gain, N*m per rad, >= 0")
      .field("loop_rate_hz", &ServoPositionDriveParams::loop_rate_hz, "loop rate, Hz, 100..1e6")
      .field("kt", &ServoPositionDriveParams::kt, "torque constant, N*m/A, > 0")
      .field("current_limit_a", &ServoPositionDriveParams::current_limit_a, "current limit, A, > 0 (inf = none)")
      .field("torque_limit_nm", &ServoPositionDriveParams::torque_limit_nm, "torque limit, N*m, > 0 (inf = none)")
      .field("current_bw_hz", &ServoPositionDriveParams::current_bw_hz, "current-loop bandwidth, Hz (inf = ideal)")
      .field("alarm_at_s", &ServoPositionDriveParams::alarm_at_s, "alarm trip time, s (inf = never)")
      .finish();
}

}  // namespace servobench::bindings
