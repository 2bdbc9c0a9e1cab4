#include "servobench/machine/powertrain.hpp"

#include <stdexcept>

#include "servobench/common/validate.hpp"
#include "servobench/plant/zoh.hpp"

namespace servobench::machine {

PowerTrain::PowerTrain(const drive::TorqueDriveParams& drive, const plant::RigidPlantParams& plant, double substep_s)
    : drive_(drive), plant_(plant) {
  drive_.validate();
  plant_.validate();
  check_positive("PowerTrain", "substep_s", substep_s);
  const drive::DriveLti d = torque_drive_lti(drive_);
  const plant::PlantLti p = plant::rigid_plant_lti(plant_);
  const Eigen::Index nd = d.a.rows();
  const Eigen::Index np = p.a.rows();
  const Eigen::Index n = nd + np;
  if (n > kMaxStates) throw std::invalid_argument("PowerTrain: too many states");
  drive_states_ = static_cast<int>(nd);
  angle_ = static_cast<int>(nd) + p.angle_index;
  speed_ = static_cast<int>(nd) + p.speed_index;

  // Series connection: drive (i_cmd -> torque) feeds the plant's motor-torque input.
  // Inputs of the whole: [i_cmd, torque_external].
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 2);
  a.topLeftCorner(nd, nd) = d.a;
  a.bottomLeftCorner(np, nd) = p.b.col(0) * d.c;
  a.bottomRightCorner(np, np) = p.a;
  b.topLeftCorner(nd, 1) = d.b;
  b.bottomLeftCorner(np, 1) = p.b.col(0) * d.d;
  b.bottomRightCorner(np, 1) = p.b.col(1);
  const plant::Zoh full = plant::discretize_zoh(a, b, substep_s);

  // Locked mechanics (stiction holds): only the drive's own states evolve.
  phi_ = full.phi;
  gamma_ = full.gamma;
  if (nd > 0) {
    const plant::Zoh locked = plant::discretize_zoh(d.a, d.b, substep_s);
    phi_locked_ = locked.phi;
    gamma_locked_ = locked.gamma;
  }
  x_ = Vec::Zero(n);
  u_ = Vec::Zero(2);
  reset();
}

void PowerTrain::reset(double angle_rad) {
  x_.setZero();
  x_[angle_] = angle_rad;
  i_cmd_ = 0.0;
  stuck_ = true;
}

void PowerTrain::step() {
  const double coulomb = plant_.coulomb_nm;
  const double load = plant_.load_nm;
  u_[0] = i_cmd_;
  if (coulomb == 0.0) {
    u_[1] = -load;
    x_ = phi_ * x_ + gamma_ * u_;
    stuck_ = false;
    return;
  }
  const double w0 = x_[speed_];
  const double applied = torque_nm() - load;
  double friction;
  if (stuck_ || w0 == 0.0) {
    if (applied <= coulomb && applied >= -coulomb) {
      // Static friction balances the applied torque: the mechanism does not move.
      if (drive_states_ > 0) {
        const auto xd = x_.head(drive_states_).eval();
        x_.head(drive_states_) = phi_locked_ * xd + gamma_locked_ * i_cmd_;
      }
      x_[speed_] = 0.0;
      stuck_ = true;
      return;
    }
    friction = applied > 0 ? -coulomb : coulomb;  // breaks away
    stuck_ = false;
  } else {
    friction = w0 > 0 ? -coulomb : coulomb;
  }
  u_[1] = friction - load;
  x_ = phi_ * x_ + gamma_ * u_;
  const double w1 = x_[speed_];
  if (w0 != 0.0 && (w1 == 0.0 || (w1 > 0) != (w0 > 0))) {
    // The speed reached zero inside the sub-step: stop there unless the torque breaks it away again.
    const double applied1 = torque_nm() - load;
    if (applied1 <= coulomb && applied1 >= -coulomb) {
      x_[speed_] = 0.0;
      stuck_ = true;
    }
  }
}

}  // namespace servobench::machine
