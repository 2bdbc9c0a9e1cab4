#include "servobench/plant/zoh.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace servobench::plant {

namespace {
// Diagonal similarity D (powers of two, so exact) that balances the row and column norms of m:
// exp(D^-1 M D) = D^-1 exp(M) D, and the balanced matrix has a far smaller norm when the states have very different
// scales (angles ~1 rad, speeds ~1e4 rad/s), which is what the scaling-and-squaring exponential needs for accuracy.
Eigen::VectorXd balance(const Eigen::MatrixXd& m) {
  const Eigen::Index n = m.rows();
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  Eigen::MatrixXd b = m;
  for (int pass = 0; pass < 50; ++pass) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double c = b.col(i).cwiseAbs().sum() - std::abs(b(i, i));
      const double r = b.row(i).cwiseAbs().sum() - std::abs(b(i, i));
      if (c == 0.0 || r == 0.0) continue;
      double f = 1.0;
      double cc = c, rr = r;
      while (cc < rr / 2) { cc *= 2; rr /= 2; f *= 2; }
      while (cc > rr * 2) { cc /= 2; rr *= 2; f /= 2; }
      if ((cc + rr) < 0.95 * (c + r)) {
        d(i) *= f;
        b.col(i) *= f;
        b.row(i) /= f;
        changed = true;
      }
    }
    if (!changed) break;
  }
  return d;
}
}  // namespace

Zoh discretize_zoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double h) {
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(n + m, n + m);
  block.topLeftCorner(n, n) = a * h;
  block.topRightCorner(n, m) = b * h;
  const Eigen::VectorXd d = balance(block);
  const Eigen::MatrixXd scaled = d.cwiseInverse().asDiagonal() * block * d.asDiagonal();
  const Eigen::MatrixXd e = d.asDiagonal() * scaled.exp() * d.cwiseInverse().asDiagonal();
  return Zoh{e.topLeftCorner(n, n), e.topRightCorner(n, m)};
}

namespace {
Eigen::MatrixXd balanced_exp(const Eigen::MatrixXd& block) {
  const Eigen::VectorXd d = balance(block);
  const Eigen::MatrixXd scaled = d.cwiseInverse().asDiagonal() * block * d.asDiagonal();
  return d.asDiagonal() * scaled.exp() * d.cwiseInverse().asDiagonal();
}
}  // namespace

ZohDerivatives discretize_zoh_with_derivatives(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                               const std::vector<Eigen::MatrixXd>& da,
                                               const std::vector<Eigen::MatrixXd>& db, double h) {
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  const Eigen::Index q = n + m;
  ZohDerivatives r;
  r.zoh = discretize_zoh(a, b, h);
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(2 * q, 2 * q);
  big.block(0, 0, n, n) = a * h;
  big.block(0, n, n, m) = b * h;
  big.block(q, q, n, n) = a * h;
  big.block(q, q + n, n, m) = b * h;
  for (std::size_t k = 0; k < da.size(); ++k) {
    big.block(0, q, n, n) = da[k] * h;
    big.block(0, q + n, n, m) = db[k] * h;
    const Eigen::MatrixXd e = balanced_exp(big);
    r.dphi.push_back(e.block(0, q, n, n));
    r.dgamma.push_back(e.block(0, q + n, n, m));
  }
  return r;
}

}  // namespace servobench::plant
