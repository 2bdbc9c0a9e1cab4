// The drive and the mechanics, integrated together over the sub-steps of one servo tick.
//
// Linear part: the drive's current loop in series with the mechanics (inertias, shaft, viscous friction),
// discretised exactly once (zero-order hold on the current command and on the external torques).
// Nonlinear parts act on the inputs held over a sub-step:
//  - the drive's input stage (torque mode: A/V and limits; velocity mode: a discrete PI speed loop run every
//    1/loop_rate_hz), and the drive alarm (current command forced to zero once tripped);
//  - position-dependent torques (cogging, unbalance) and the constant load, evaluated at the sub-step start;
//  - dry friction of each body, solved implicitly (time-stepping): the friction torque held over the sub-step
//    is the one that stops the body if static friction can (|needed| <= breakaway level), otherwise the
//    sliding friction opposing the motion, and never more than what opposes the body's net displacement over
//    the sub-step (so friction never does positive work). A body at rest that stays at rest is integrated with
//    an exactly locked discretisation (no creep, no work); a body never reverses through friction alone.
#pragma once

#include <array>
#include <limits>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "servobench/drive/pulse_drive.hpp"
#include "servobench/drive/torque_drive.hpp"
#include "servobench/drive/velocity_drive.hpp"
#include "servobench/plant/dry_friction.hpp"
#include "servobench/plant/mechanics.hpp"

namespace servobench::machine {

using DriveParams = std::variant<drive::TorqueDriveParams, drive::VelocityDriveParams, drive::StepperDriveParams,
                                 drive::ServoPositionDriveParams>;

// The linear part of a power train over one servo tick, as a discrete system at the servo rate:
//   z[k+1] = a z[k] + b v[k],   motor angle = c_motor z,   load angle = c_load z   (rad)
// v: the drive's input voltage held over the tick (V). z: the power train's states (current loop, mechanics) and,
// for a velocity-mode drive, its speed-loop integrator (N*m) and held current command (A). The sub-steps and the
// speed loop's updates inside the tick are composed exactly (the lifted system), so this is what a sampled
// controller sees. Left out: current and torque limits, dry friction, disturbances and the alarm -- exact for a
// linear configuration.
struct TickModel {
  Eigen::MatrixXd a, b, c_motor, c_load;
};

class PowerTrain {
 public:
  static constexpr int kMaxStates = 8;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxStates>;
  using InMat = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxStates, 3>;

  // substeps: integration sub-steps per tick requested by the user; a velocity-mode drive multiplies them by
  // its loop updates per tick (servo_period_s * loop_rate_hz must then be a whole number).
  PowerTrain(const DriveParams& drive, const plant::Mechanics& mechanics, double servo_period_s, int substeps);

  // At rest, no shaft twist, motor angle = load angle = angle_rad, current zero, alarm cleared, time 0.
  void reset(double angle_rad = 0.0);
  // Sets the mechanical state (rad, rad/s); on a rigid plant the load values must equal the motor's.
  void set_state(double motor_angle_rad, double motor_speed_rad_s, double load_angle_rad, double load_speed_rad_s);
  // The drive's input voltage for the coming tick (voltage-input drives).
  void set_input(double volts);
  // The card's command position for the coming tick, in whole pulses (pulse-input drives); the step train is spread
  // evenly over the tick.
  void set_pulse_input(double pulses);
  // True for drives fed with a step train (stepper, servo in position mode) instead of a voltage.
  bool pulse_input() const { return mode_ == Mode::kStepper || mode_ == Mode::kServoPosition; }
  // Advances one servo tick (all sub-steps) with the held input.
  void advance_tick();

  double motor_angle_rad() const { return x_[motor_angle_]; }
  double motor_speed_rad_s() const { return x_[motor_speed_]; }
  double load_angle_rad() const { return x_[load_angle_]; }
  double load_speed_rad_s() const { return x_[load_speed_]; }
  // Motor current now, A (an ideal current loop follows its command at once).
  double current_a() const { return mode_ == Mode::kStepper ? 0.0 : (drive_states_ > 0 ? x_[0] : i_cmd_); }
  // Motor (electromagnetic) torque now, N*m.
  double torque_nm() const { return mode_ == Mode::kStepper ? stepper_torque_ : kt_ * current_a(); }
  // The drive's commanded motor angle (pulse-input drives), rad.
  double command_angle_rad() const { return cmd_angle_; }
  bool alarm() const { return alarm_; }
  // Drive reset: clears the alarm and cancels a scheduled one (alarm_at_s).
  void clear_alarm() {
    alarm_ = false;
    alarm_at_s_ = std::numeric_limits<double>::infinity();
  }
  int substeps_per_tick() const { return n_sub_; }
  double substep_s() const { return h_; }
  const plant::Mechanics& mechanics() const { return mech_; }
  // Total mechanical energy (kinetic + shaft), J. For passivity checks.
  double mechanical_energy_j() const;
  // The servo-rate linear model (see TickModel). Only for voltage-input drives (torque and velocity mode).
  TickModel linear_tick_model() const;
  // Bodies frozen by static friction now.
  bool stuck(std::size_t body) const { return stuck_[body] != 0; }

  // The fused tick (machine/axis_fused.cpp, decision P16): the state count N (2..5) for which a local copy
  // PowerTrain::Local<N, NB> (machine/powertrain_local.hpp) advances this power train exactly as advance_tick
  // does -- a torque drive on the fixed-size discretisations -- or 0 when only the general tick applies.
  int fused_states() const {
    if (mode_ != Mode::kTorque || fixed_.index() == 0) return 0;
    return static_cast<int>(fixed_.index()) + 1;
  }
  std::size_t bodies() const { return nb_; }
  // W: how the two-body rows are held (1: one double each; 4: rows 0-3 in an AVX2 vector; 8: one AVX-512 vector).
  template <int N, int NB, int W = 1>
  class Local;

 private:
  void substep();
  // The bodies' linear motion and dry friction over one sub-step with the held inputs (plant/dry_friction.hpp).
  void friction_step(double t_motor, double t_load);

  // Compile-time-sized copies of the discretisations for the usual state counts: 2 (rigid, ideal current loop),
  // 3 (rigid + current loop), 4 (two-mass), 5 (two-mass + current loop). The sub-step then runs unrolled, without
  // size checks or heap-shaped loops, and gives the same doubles as the run-time-sized path (zoh_product).
  template <int N>
  struct Fixed {
    std::array<Eigen::Matrix<double, N, N>, 4> phi;
    std::array<Eigen::Matrix<double, N, 3>, 4> gamma;
  };
  template <int N>
  void fixed_step(const Fixed<N>& f, double t_motor, double t_load);
  std::variant<std::monostate, Fixed<2>, Fixed<3>, Fixed<4>, Fixed<5>> fixed_;

  enum class Mode { kTorque, kVelocity, kStepper, kServoPosition };
  DriveParams drive_;
  plant::Mechanics mech_;
  Mode mode_ = Mode::kTorque;
  bool velocity_mode_ = false;  // a speed loop runs in the drive (velocity and servo position modes)
  // Pulse input: rad per pulse, commanded angle at the tick's start and end, stepper parameters.
  double rad_per_pulse_ = 0.0, cmd_start_ = 0.0, cmd_end_ = 0.0, cmd_angle_ = 0.0, angle_origin_ = 0.0;
  bool pulse_primed_ = false;
  double kpp_ = 0.0, speed_ff_ = 0.0, servo_period_s_ = 0.0;
  double stepper_teeth_ = 0.0, holding_torque_ = 0.0, stepper_torque_ = 0.0;
  int sub_in_tick_ = 0;
  double kt_ = 1.0;
  double i_max_ = 0.0;
  double amps_per_volt_ = 0.0;
  double alarm_at_s_ = 0.0;
  drive::SpeedLoop speed_loop_;
  int drive_states_ = 0;
  int motor_angle_ = 0, motor_speed_ = 1, load_angle_ = 0, load_speed_ = 1;
  int n_sub_ = 1, loop_every_ = 1;
  double h_ = 0.0;
  Mat phi_;
  InMat gamma_;
  // Discretisations with a subset of bodies locked by stiction (index = bit mask of locked bodies; 0 = none).
  std::vector<Mat> phi_locked_;
  std::vector<InMat> gamma_locked_;
  Vec x_, x_free_;
  // The bodies' places in x_ and their dry friction (plant/dry_friction.hpp); nb_ bodies (1 or 2).
  std::size_t nb_ = 0;
  plant::BodyIndex body_index_[2];
  plant::DryFriction<double> dry_[2];
  std::vector<char> stuck_;
  double volts_ = 0.0, i_cmd_ = 0.0;
  bool alarm_ = false;
  long long substep_count_ = 0;
};

}  // namespace servobench::machine
