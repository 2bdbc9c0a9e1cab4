#include "servobench/identify/covariance.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Dense>

namespace servobench::identify {

CovarianceResult reduced_covariance(const ceres::CRSMatrix& jacobian, const std::vector<int>& free_index,
                                    int n_params, int nuisance_per_block, double cost,
                                    const std::vector<double>& values, const std::vector<double>& initial,
                                    const std::vector<std::string>& names, double max_relative_error) {
  const Eigen::Index g = static_cast<Eigen::Index>(free_index.size());
  if (g == 0) {  // nothing estimated (every parameter held): no covariance to compute
    CovarianceResult none;
    none.covariance = Eigen::MatrixXd::Zero(n_params, n_params);
    none.std_error.assign(static_cast<std::size_t>(n_params), 0.0);
    return none;
  }
  const Eigen::Index q = nuisance_per_block;
  const Eigen::Index blocks = q > 0 ? (jacobian.num_cols - g) / q : 0;
  Eigen::MatrixXd hgg = Eigen::MatrixXd::Zero(g, g);
  std::vector<Eigen::MatrixXd> hgl(static_cast<std::size_t>(blocks), Eigen::MatrixXd::Zero(g, q));
  std::vector<Eigen::MatrixXd> hll(static_cast<std::size_t>(blocks), Eigen::MatrixXd::Zero(q, q));
  Eigen::VectorXd jg(g), jl(q);
  for (int r = 0; r < jacobian.num_rows; ++r) {
    jg.setZero();
    jl.setZero();
    Eigen::Index block = -1;
    bool coupling = false;
    for (int e = jacobian.rows[static_cast<std::size_t>(r)]; e < jacobian.rows[static_cast<std::size_t>(r) + 1]; ++e) {
      const Eigen::Index c = jacobian.cols[static_cast<std::size_t>(e)];
      const double v = jacobian.values[static_cast<std::size_t>(e)];
      if (v == 0.0) continue;  // structural zeros (e.g. a measurement row and the next segment's state)
      if (c < g) {
        jg[c] = v;
      } else {
        const Eigen::Index b = (c - g) / q;
        if (block >= 0 && b != block) coupling = true;
        block = b;
        jl[(c - g) % q] = v;
      }
    }
    if (coupling) continue;  // a row tying two blocks (a continuity constraint): left out, see the header
    hgg.noalias() += jg * jg.transpose();
    if (block >= 0) {
      hgl[static_cast<std::size_t>(block)].noalias() += jg * jl.transpose();
      hll[static_cast<std::size_t>(block)].noalias() += jl * jl.transpose();
    }
  }
  Eigen::MatrixXd reduced = hgg;
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const auto& l = hll[static_cast<std::size_t>(b)];
    const auto& c = hgl[static_cast<std::size_t>(b)];
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(l);
    reduced.noalias() -= c * cod.solve(c.transpose());
  }
  reduced = 0.5 * (reduced + reduced.transpose());
  const double dof = static_cast<double>(jacobian.num_rows) - static_cast<double>(jacobian.num_cols);
  const double s2 = dof > 0 ? 2.0 * cost / dof : std::numeric_limits<double>::infinity();

  CovarianceResult out;
  const std::size_t np = static_cast<std::size_t>(n_params);
  out.covariance = Eigen::MatrixXd::Zero(n_params, n_params);
  out.std_error.assign(np, 0.0);
  std::vector<bool> bad(static_cast<std::size_t>(g), false);
  Eigen::VectorXd d(g);
  for (Eigen::Index i = 0; i < g; ++i) {
    d[i] = reduced(i, i) > 0 ? std::sqrt(reduced(i, i)) : 0.0;
    if (d[i] == 0.0) {
      bad[static_cast<std::size_t>(i)] = true;
      out.not_identifiable.push_back(names[static_cast<std::size_t>(free_index[static_cast<std::size_t>(i)])] +
                                     ": not excited by these data (the residuals do not depend on it)");
    }
  }
  Eigen::MatrixXd corr = reduced;
  for (Eigen::Index i = 0; i < g; ++i)
    for (Eigen::Index j = 0; j < g; ++j) corr(i, j) = (d[i] > 0 && d[j] > 0) ? reduced(i, j) / (d[i] * d[j]) : (i == j);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(corr);
  for (Eigen::Index k = 0; k < g; ++k) {
    if (eig.eigenvalues()[k] >= 1e-10) continue;
    std::string who;
    int count = 0;
    for (Eigen::Index i = 0; i < g; ++i) {
      if (std::fabs(eig.eigenvectors()(i, k)) < 0.3 || d[i] == 0.0) continue;
      who += (count++ ? ", " : "") + names[static_cast<std::size_t>(free_index[static_cast<std::size_t>(i)])];
      bad[static_cast<std::size_t>(i)] = true;
    }
    if (count > 1) out.not_identifiable.push_back(who + ": not separable by these data (they act alike)");
    else if (count == 1) out.not_identifiable.push_back(who + ": not determined by these data");
  }
  // Covariance in the scaled coordinates, then back: cov = s^2 D^-1 corr^-1 D^-1 (pseudo-inverse when singular).
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(corr);
  const Eigen::MatrixXd cinv = cod.pseudoInverse();
  for (Eigen::Index i = 0; i < g; ++i) {
    const std::size_t pi = static_cast<std::size_t>(free_index[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < g; ++j) {
      const std::size_t pj = static_cast<std::size_t>(free_index[static_cast<std::size_t>(j)]);
      if (d[i] > 0 && d[j] > 0)
        out.covariance(static_cast<Eigen::Index>(pi), static_cast<Eigen::Index>(pj)) = s2 * cinv(i, j) / (d[i] * d[j]);
    }
    const double var = out.covariance(static_cast<Eigen::Index>(pi), static_cast<Eigen::Index>(pi));
    out.std_error[pi] = bad[static_cast<std::size_t>(i)] ? std::numeric_limits<double>::infinity()
                                                        : std::sqrt(std::max(var, 0.0));
    const double size = std::fabs(values[pi]);  // its own value, not the guess (issue 19.5)
    (void)initial;
    if (!bad[static_cast<std::size_t>(i)] && size > 0 && out.std_error[pi] > max_relative_error * size) {
      char buf[200];
      std::snprintf(buf, sizeof buf, ": relative standard error %.3g %% above %.3g %%: too weakly excited",
                    100.0 * out.std_error[pi] / size, 100.0 * max_relative_error);
      out.not_identifiable.push_back(names[pi] + buf);
    }
  }
  return out;
}

}  // namespace servobench::identify
