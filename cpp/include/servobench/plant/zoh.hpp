// Exact zero-order-hold discretisation of a continuous linear system x' = A x + B u:
//   x(t+h) = Phi x(t) + Gamma u,  Phi = e^{A h},  Gamma = int_0^h e^{A s} ds B,
// both read off one matrix exponential of the block matrix [[A, B], [0, 0]] * h (Eigen's MatrixFunctions).
#pragma once

#include <Eigen/Core>

namespace servobench::plant {

struct Zoh {
  Eigen::MatrixXd phi;    // n x n
  Eigen::MatrixXd gamma;  // n x m
};

Zoh discretize_zoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double h);

}  // namespace servobench::plant
