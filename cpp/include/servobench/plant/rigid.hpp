// A rigid single-inertia mechanism in SI units (rad, rad/s, N*m, kg*m^2).
//
//   J * dw/dt = torque_motor - b*w - friction(w) - load_torque,   dtheta/dt = w
//
// Linear part: inertia J and viscous friction b. Coulomb friction and the constant load are torques held
// over each integration sub-step by the machine layer, with stiction: at rest, the mechanism stays at rest
// while |applied torque| <= coulomb_nm.
#pragma once

#include <Eigen/Core>

namespace servobench::plant {

struct RigidPlantParams {
  double inertia_kgm2 = 1.0e-4;  // total inertia seen by the motor, kg*m^2, > 0
  double viscous_nms = 1.0e-4;   // viscous friction, N*m*s/rad, >= 0
  double coulomb_nm = 0.0;       // Coulomb (and static) friction level, N*m, >= 0
  double load_nm = 0.0;          // constant load torque (e.g. gravity on a vertical axis), N*m
  void validate() const;
};

// Continuous linear model: state [theta (rad), w (rad/s)], inputs [torque_motor, torque_external] (N*m),
// where torque_external collects everything the machine layer holds constant over a sub-step
// (-load, -Coulomb friction).
struct PlantLti {
  Eigen::MatrixXd a, b;
  int angle_index = 0;  // index of the motor angle in the state
  int speed_index = 1;  // index of the motor speed in the state
};

PlantLti rigid_plant_lti(const RigidPlantParams& params);

}  // namespace servobench::plant
