#include "servobench/motion/coord_system.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

void CrdPrm::validate() const {
  const char* o = "CrdPrm";
  check_integer(o, "dimension", dimension, 1, 4, "X-Y-Z-A; GUC L375, iDEABOX L7113");
  std::array<int, 5> used{};
  for (std::size_t k = 0; k < 8; ++k) {
    check_integer(o, "profile[k]", profile[k], 0, 4, "0 none, 1 X, 2 Y, 3 Z, 4 A; GUC L785");
    if (profile[k] > dimension)
      throw_invalid(o, "profile[k]", profile[k],
                    "names a coordinate beyond the dimension " + std::to_string(dimension));
    if (profile[k] > 0 && ++used[static_cast<std::size_t>(profile[k])] > 1)
      throw_invalid(o, "profile[k]", profile[k],
                    "maps a second profile to the same coordinate (an error return, GUC L785, iDEABOX L7139)");
  }
  for (int c = 1; c <= dimension; ++c)
    if (used[static_cast<std::size_t>(c)] == 0)
      throw_invalid(o, "dimension", dimension, "has coordinate " + std::to_string(c) + " mapped to no profile");
  check_range(o, "syn_vel_max", syn_vel_max, 0, 32767, "pulse/ms, open interval; GUC L771");
  if (!(syn_vel_max > 0 && syn_vel_max < 32767)) throw_invalid(o, "syn_vel_max", syn_vel_max, "must be in (0, 32767) pulse/ms (GUC L771)");
  check_range(o, "syn_acc_max", syn_acc_max, 0, 32767, "pulse/ms^2, open interval; GUC L773");
  if (!(syn_acc_max > 0 && syn_acc_max < 32767)) throw_invalid(o, "syn_acc_max", syn_acc_max, "must be in (0, 32767) pulse/ms^2 (GUC L773)");
  check_integer(o, "even_time_ms", even_time_ms, 0, 32766, "ms; GUC L775");
  for (double p : origin_pos) check_integer(o, "origin_pos[k]", p, -2147483648.0, 2147483647.0, "pulse; GUC L789");
}

CoordSystem CoordSystem::identity(int dim, const std::vector<double>& offsets) {
  if (dim < 1 || dim > 4) throw_invalid("CoordSystem", "dim", dim, "is outside the allowed range 1..4");
  if (!offsets.empty() && offsets.size() != static_cast<std::size_t>(dim))
    throw_invalid("CoordSystem", "offsets", static_cast<double>(offsets.size()), "must have one value per coordinate");
  CoordSystem cs;
  cs.dim_ = dim;
  for (int k = 0; k < dim; ++k) {
    std::array<double, 5> r{};
    r[static_cast<std::size_t>(k)] = 1.0;
    if (!offsets.empty()) {
      check_range("CoordSystem", "offsets[k]", offsets[static_cast<std::size_t>(k)], -1073741824.0, 1073741823.0,
                  "pulse; GE GT_MapCnt L5179-5187");
      r[4] = offsets[static_cast<std::size_t>(k)];
    }
    cs.axes_.push_back(k + 1);
    cs.rows_.push_back(r);
  }
  return cs;
}

CoordSystem CoordSystem::gt_map(const std::vector<GtAxisMap>& rows) {
  const char* o = "GtAxisMap";
  if (rows.empty()) throw std::invalid_argument("GtAxisMap: at least one axis must be mapped (GT_MapAxis, GT L1533)");
  std::vector<GtAxisMap> sorted = rows;
  std::sort(sorted.begin(), sorted.end(), [](const GtAxisMap& a, const GtAxisMap& b) { return a.axis < b.axis; });
  CoordSystem cs;
  cs.dim_ = 4;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const auto& r = sorted[i];
    check_integer(o, "axis", r.axis, 1, 4, "GT L1533");
    if (i > 0 && sorted[i - 1].axis == r.axis)
      throw PathGeometryError(6, std::string(o) + ".axis = " + format_value(r.axis) +
                                     " is mapped twice (GT_MapAxis return code 6, GT L408)");
    const std::array<double, 5> row{r.cx, r.cy, r.cz, r.ca, r.c};
    for (double v : row)
      if (!std::isfinite(v)) throw_invalid(o, "coefficient", v, "is not a finite number");
    if (row[0] == 0 && row[1] == 0 && row[2] == 0 && row[3] == 0)
      throw PathGeometryError(6, std::string(o) + ".axis = " + format_value(r.axis) +
                                     " maps to no coordinate (all of Cx, Cy, Cz, Ca zero; return code 6, GT L408)");
    cs.axes_.push_back(r.axis);
    cs.rows_.push_back(row);
  }
  return cs;
}

CoordSystem CoordSystem::crd_prm(const CrdPrm& prm, const std::array<double, 8>& profile_pos) {
  prm.validate();
  CoordSystem cs;
  cs.dim_ = prm.dimension;
  for (std::size_t k = 0; k < 8; ++k) {
    if (prm.profile[k] == 0) continue;
    std::array<double, 5> r{};
    r[static_cast<std::size_t>(prm.profile[k] - 1)] = 1.0;
    r[4] = prm.set_origin ? prm.origin_pos[k] : profile_pos[k];
    cs.axes_.push_back(static_cast<int>(k) + 1);
    cs.rows_.push_back(r);
  }
  return cs;
}

void CoordSystem::to_axes(const CrdPoint& p, double* out) const {
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const auto& r = rows_[i];
    out[i] = r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3] * p[3] + r[4];
  }
}

std::vector<double> CoordSystem::to_axes(const CrdPoint& p) const {
  std::vector<double> out(rows_.size());
  to_axes(p, out.data());
  return out;
}

void CoordSystem::map_vector(const CrdPoint& v, double* out) const {
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const auto& r = rows_[i];
    out[i] = r[0] * v[0] + r[1] * v[1] + r[2] * v[2] + r[3] * v[3];
  }
}

CrdPoint CoordSystem::to_crd(const std::vector<double>& axis_pos) const {
  if (axis_pos.size() != rows_.size())
    throw std::invalid_argument("CoordSystem.to_crd: expected " + std::to_string(rows_.size()) + " axis positions");
  // Keep rows in axis order while independent (Gram-Schmidt), then x = R^T (R R^T)^-1 (p - c).
  std::vector<std::array<double, 4>> kept, ortho;
  std::vector<double> rhs;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    std::array<double, 4> q{rows_[i][0], rows_[i][1], rows_[i][2], rows_[i][3]};
    const double n0 = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (const auto& e : ortho) {
      const double d = q[0] * e[0] + q[1] * e[1] + q[2] * e[2] + q[3] * e[3];
      for (int k = 0; k < 4; ++k) q[static_cast<std::size_t>(k)] -= d * e[static_cast<std::size_t>(k)];
    }
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n <= 1e-12 * n0) continue;  // depends on a lower-numbered axis: that axis decides
    for (double& v : q) v /= n;
    ortho.push_back(q);
    kept.push_back({rows_[i][0], rows_[i][1], rows_[i][2], rows_[i][3]});
    rhs.push_back(axis_pos[i] - rows_[i][4]);
  }
  const std::size_t m = kept.size();
  // Solve (R R^T) y = rhs by Gaussian elimination (m <= 4), then x = R^T y.
  double A[4][5] = {};
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      double s = 0.0;
      for (std::size_t k = 0; k < 4; ++k) s += kept[i][k] * kept[j][k];
      A[i][j] = s;
    }
    A[i][m] = rhs[i];
  }
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::fabs(A[r][c]) > std::fabs(A[piv][c])) piv = r;
    for (std::size_t k = 0; k <= m; ++k) std::swap(A[c][k], A[piv][k]);
    for (std::size_t r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = A[r][c] / A[c][c];
      for (std::size_t k = c; k <= m; ++k) A[r][k] -= f * A[c][k];
    }
  }
  CrdPoint x{};
  for (std::size_t i = 0; i < m; ++i) {
    const double y = A[i][m] / A[i][i];
    for (std::size_t k = 0; k < 4; ++k) x[k] += kept[i][k] * y;
  }
  return x;
}

}  // namespace servobench::motion
