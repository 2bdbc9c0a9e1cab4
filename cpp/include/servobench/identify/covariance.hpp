// Standard errors of fitted plant parameters, and which ones the data cannot determine.
#pragma once

#include <string>
#include <vector>

#include <ceres/crs_matrix.h>

#include "servobench/identify/fit_report.hpp"

namespace servobench::identify {

// The covariance of the plant parameters from the Jacobian J of the scaled residuals at the solution (columns: the
// free plant parameters free_index, in that order, then blocks of `nuisance_per_block` nuisance columns, each block
// touching its own rows only -- e.g. the shooting segments' initial states). The nuisance parameters are eliminated
// by the Schur complement, so the result is exactly the plant block of s^2 (J^T J)^-1, with s^2 = 2 cost / (m - n)
// the residual variance (m residuals, n free parameters in all). Rows that touch two nuisance blocks (the
// multiple-shooting continuity constraints) are left out: the standard errors are those of the measurements alone,
// slightly conservative.
//
// Identifiability, on the correlation form of the reduced information matrix:
//  - a free parameter with no influence on the residuals is "not excited by these data";
//  - an eigenvalue below 1e-10 marks a combination the data cannot see: its parameters are "not separable";
//  - a free parameter whose standard error exceeds max_relative_error times its size (the larger of |estimate| and
//    |initial|) is "too weakly excited".
// std_error has one entry per plant parameter (n_params): 0 for fixed ones, inf for non-identifiable ones.
CovarianceResult reduced_covariance(const ceres::CRSMatrix& jacobian, const std::vector<int>& free_index,
                                    int n_params, int nuisance_per_block, double cost,
                                    const std::vector<double>& values, const std::vector<double>& initial,
                                    const std::vector<std::string>& names, double max_relative_error);

}  // namespace servobench::identify
