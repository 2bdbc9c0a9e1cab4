#include "servobench/plant/zoh.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace servobench::plant {

Zoh discretize_zoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double h) {
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(n + m, n + m);
  block.topLeftCorner(n, n) = a * h;
  block.topRightCorner(n, m) = b * h;
  const Eigen::MatrixXd e = block.exp();
  return Zoh{e.topLeftCorner(n, n), e.topRightCorner(n, m)};
}

}  // namespace servobench::plant
