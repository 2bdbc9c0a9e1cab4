// The drive and the mechanics integrated together over one sub-step.
//
// The drive's linear part (current loop) and the plant's linear part (inertia, viscous friction) are put in
// series and discretised exactly (zero-order hold on the drive's current command and on the external torque).
// The nonlinear parts act on the inputs held over the sub-step: the current limit on the current command,
// Coulomb friction and the load on the external torque. Stiction: a mechanism at rest stays at rest (its state
// frozen, the drive still integrating) while |drive torque - load| <= coulomb; a moving mechanism whose speed
// changes sign inside a sub-step is stopped there when the torque cannot break it away.
#pragma once

#include <Eigen/Core>

#include "servobench/drive/torque_drive.hpp"
#include "servobench/plant/rigid.hpp"

namespace servobench::machine {

class PowerTrain {
 public:
  static constexpr int kMaxStates = 8;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxStates>;
  using InMat = Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxStates, 2>;

  PowerTrain(const drive::TorqueDriveParams& drive, const plant::RigidPlantParams& plant, double substep_s);

  // At rest at the given angle, current zero.
  void reset(double angle_rad = 0.0);
  // Sets the drive's input voltage, held from now on (current limit applied here).
  void set_input(double volts) { i_cmd_ = drive::torque_drive_current_command(drive_, volts); }
  // Advances one sub-step with the held input.
  void step();
  void step(double volts) {
    set_input(volts);
    step();
  }

  double angle_rad() const { return x_[angle_]; }
  double speed_rad_s() const { return x_[speed_]; }
  // Motor current now, A. An ideal current loop follows the held input at once.
  double current_a() const { return drive_states_ > 0 ? x_[0] : i_cmd_; }
  double torque_nm() const { return drive_.kt * current_a(); }
  bool stuck() const { return stuck_; }

  const drive::TorqueDriveParams& drive_params() const { return drive_; }
  const plant::RigidPlantParams& plant_params() const { return plant_; }

 private:
  drive::TorqueDriveParams drive_;
  plant::RigidPlantParams plant_;
  int drive_states_ = 0;
  int angle_ = 0, speed_ = 1;
  Mat phi_, phi_locked_;       // whole system; drive alone (mechanics locked by stiction)
  InMat gamma_;
  Vec gamma_locked_;
  Vec x_, u_;
  double i_cmd_ = 0.0;
  bool stuck_ = true;
};

}  // namespace servobench::machine
