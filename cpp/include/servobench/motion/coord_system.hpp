// Coordinate systems: how the path coordinates X, Y, Z, A become motor-axis (profile) positions.
//
//  - GT (GT_MapAxis, GT L1519-1672): each motor axis 1..4 is a linear map of the coordinates,
//    axis = Cx*x + Cy*y + Cz*z + Ca*a + C (L1538): scaling, skew, rotation, translation. When two axes
//    map the same coordinates (a conflict) the lower-numbered axis decides the coordinate position (L1665).
//  - GUC-ECAT / iDEABOX (GT_SetCrdPrm, TCrdPrm; GUC L369-388, L736-792, iDEABOX L7095-7176): dimension 1..4,
//    profile[k] = the coordinate (1 X .. 4 A, 0 none) that profile k+1 follows, each coordinate used exactly
//    once; machine position = origin + coordinate; origin = the current profile positions (setOriginFlag 0)
//    or originPos (1). synVelMax / synAccMax clamp, and evenTime shapes, every segment (see PathSetup).
//  - GE (GE L1471, L1960-1971): the fixed identity X = axis 1 .. A = axis 4 with per-axis work offsets
//    (GT_MapCnt): identity() with offsets.
#pragma once

#include <array>
#include <vector>

#include "servobench/motion/path_segment.hpp"

namespace servobench::motion {

// One GT_MapAxis row: axis (pulse) = cx*x + cy*y + cz*z + ca*a + c.
struct GtAxisMap {
  int axis = 1;  // 1..4
  double cx = 0.0, cy = 0.0, cz = 0.0, ca = 0.0, c = 0.0;
};

// TCrdPrm (GUC L371-388, iDEABOX L7113-7164).
struct CrdPrm {
  int dimension = 2;                     // 1..4
  std::array<int, 8> profile{};          // profile[k] in 0..4: coordinate of profile k+1 (0 = none)
  double syn_vel_max = 0.0;              // (0, 32767) pulse/ms
  double syn_acc_max = 0.0;              // (0, 32767) pulse/ms^2
  double even_time_ms = 0.0;             // [0, 32767) ms, whole
  bool set_origin = false;               // setOriginFlag
  std::array<double, 8> origin_pos{};    // pulse, used if set_origin
  void validate() const;
};

class CoordSystem {
 public:
  // GE: coordinate k = axis k+1 (k < dim), plus a work offset per axis (GT_MapCnt), pulse.
  static CoordSystem identity(int dim, const std::vector<double>& offsets = {});
  // GT: up to 4 rows, axes 1..4 each at most once. The dimension is 4 (X-Y-Z-A, GT L1521).
  static CoordSystem gt_map(const std::vector<GtAxisMap>& rows);
  // GUC/iDEABOX: profile positions (8 values, pulse) give the origin when !prm.set_origin.
  static CoordSystem crd_prm(const CrdPrm& prm, const std::array<double, 8>& profile_pos = {});

  int dim() const { return dim_; }
  // The motor axes (1-based numbers) this system drives, in ascending order.
  const std::vector<int>& axes() const { return axes_; }
  // Row of axis axes()[i]: coefficients of X, Y, Z, A and the offset.
  const std::array<double, 5>& row(std::size_t i) const { return rows_[i]; }
  // Motor positions (pulse, in axes() order) of a coordinate point.
  void to_axes(const CrdPoint& p, double* out) const;
  std::vector<double> to_axes(const CrdPoint& p) const;
  // The coordinate point of motor positions (in axes() order): rows taken in axis-number order and kept
  // when independent of the rows before (the lower axis wins a conflict, GT L1665); least squares over the
  // kept rows, minimum norm for coordinates no kept row determines.
  CrdPoint to_crd(const std::vector<double>& axis_pos) const;
  // d(axis)/d(coordinate) applied to a coordinate-space vector (velocity, tangent), in axes() order.
  void map_vector(const CrdPoint& v, double* out) const;

 private:
  int dim_ = 2;
  std::vector<int> axes_;
  std::vector<std::array<double, 5>> rows_;
};

}  // namespace servobench::motion
