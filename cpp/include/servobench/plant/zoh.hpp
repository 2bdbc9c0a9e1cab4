// Exact zero-order-hold discretisation of a continuous linear system x' = A x + B u:
//   x(t+h) = Phi x(t) + Gamma u,  Phi = e^{A h},  Gamma = int_0^h e^{A s} ds B,
// both read off one matrix exponential of the block matrix [[A, B], [0, 0]] * h (Eigen's MatrixFunctions).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace servobench::plant {

struct Zoh {
  Eigen::MatrixXd phi;    // n x n
  Eigen::MatrixXd gamma;  // n x m
};

Zoh discretize_zoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double h);

// The discretisation and its derivatives with respect to parameters p_k, given dA/dp_k and dB/dp_k:
// d exp(M)/dp_k is the upper-right block of exp([[M, dM_k], [0, M]]) (Van Loan, 1978), M = [[A, B], [0, 0]] h.
// Exact to rounding; used by the identification to differentiate the simulator's own discretisation.
struct ZohDerivatives {
  Zoh zoh;
  std::vector<Eigen::MatrixXd> dphi;    // dPhi/dp_k, n x n
  std::vector<Eigen::MatrixXd> dgamma;  // dGamma/dp_k, n x m
};

ZohDerivatives discretize_zoh_with_derivatives(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                               const std::vector<Eigen::MatrixXd>& da,
                                               const std::vector<Eigen::MatrixXd>& db, double h);

}  // namespace servobench::plant
