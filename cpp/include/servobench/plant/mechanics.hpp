// The common linear description every plant compiles to, plus what the machine layer needs for the
// nonlinear parts (friction per body, position-dependent torques).
//
//   x' = A x + B u,   u = [motor torque, external torque on the motor body, external torque on the load body]
//
// Angles in rad, speeds in rad/s, torques in N*m. A rigid plant has one body (motor and load are one);
// a two-mass plant has two bodies joined by a spring-damper shaft.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "servobench/plant/friction.hpp"

namespace servobench::plant {

// The inertias a plant may have, kg*m^2 (decision RB2): below 1e-9 (a thousandth of the smallest servo rotor) the
// motor's time constant falls far below any servo tick and the dry-friction stepping stalls; above 1e6 the
// axis cannot be moved by any drive the library models.
constexpr double kMinInertiaKgm2 = 1e-9;
constexpr double kMaxInertiaKgm2 = 1e6;
// Throws std::invalid_argument unless kMinInertiaKgm2 <= j <= kMaxInertiaKgm2 (finite), naming owner.field.
void check_inertia(const char* owner, const char* field, double j);

struct Body {
  int angle_index = 0;  // index in x
  int speed_index = 1;
  int torque_input = 1; // column of B for external torques on this body
  double inertia_kgm2 = 1.0;
  FrictionParams friction;
};

// Position-dependent and constant disturbances.
struct Disturbances {
  double load_nm = 0.0;          // constant torque on the load body, opposing positive motion
  double unbalance_nm = 0.0;     // gravity of an unbalanced load: -unbalance*sin(load angle) on the load body
  double cogging_nm = 0.0;       // cogging ripple amplitude on the motor body
  double cogging_periods = 0.0;  // ripple periods per motor revolution
};

struct Mechanics {
  Eigen::MatrixXd a;  // n x n
  Eigen::MatrixXd b;  // n x 3
  std::vector<Body> bodies;  // bodies[0] is the motor; bodies.back() is the load (the same body when rigid)
  Disturbances disturbances;
  int motor_angle = 0, motor_speed = 1, load_angle = 0, load_speed = 1;
  // The state at rest with the motor angle at 1 rad, scaled by the angle on a reset (plant/lti.hpp). Empty: the
  // built-in plants' rest (motor and load angles equal, everything else 0). rest_anywhere false: the plant has no
  // rest state away from angle 0 (no free integrator in A), so a reset can only put it at 0.
  Eigen::VectorXd rest;
  bool rest_anywhere = true;
  int states() const { return static_cast<int>(a.rows()); }
  bool rigid() const { return bodies.size() == 1; }
};

// Frequency response from motor torque (N*m) to the motor or load angle (rad), at freq_hz (Hz).
// period_s <= 0: continuous G(j w); period_s > 0: the zero-order-hold discretisation at that period evaluated
// at z = exp(j w T), i.e. what a sampled controller sees from a held torque to a sampled angle.
std::vector<std::complex<double>> frequency_response(const Mechanics& m, const std::vector<double>& freq_hz,
                                                     bool load_side, double period_s);

}  // namespace servobench::plant
