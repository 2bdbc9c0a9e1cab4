// PVT description modes: the points a user downloads into a PVT table, turned into a chain of cubic
// (constant-jerk) pieces in the manuals' own units: time ms, position pulse, velocity pulse/ms,
// acceleration pulse/ms^2, jerk pulse/ms^3.
//
// GUC-ECAT §4.2 (seed 002 L1116-2100) and iDEABOX §4.4 (seed 003 L2713-3772) describe the same engine:
//  - PVT (GT_PvtTable): (t, p, v) per point; between two points p is cubic and v quadratic, solved from the
//    four boundary conditions (GUC L1293-1302, iDEABOX L2764-2777).
//  - PVT-Ex (iDEABOX GT_PvtTableEx, L6446-6472): a begin and an end velocity per point (a velocity jump).
//  - Complete (GT_PvtTableComplete): (t, p) plus velBegin/velEnd; interior velocities make velocity and
//    acceleration continuous (GUC L1397, iDEABOX L2924-2930): a C2 clamped cubic spline.
//  - Percent (GT_PvtTablePercent): (t, p, percent) plus velBegin; v_{i+1} = 2(p_{i+1}-p_i)/T - v_i
//    (GUC L1436-1457, iDEABOX L3390-3400); the percent of point i shapes segment i as an S ramp whose
//    jerk phases take percent % of the segment time (percent = 2ta/(2ta+te)), without moving any p, t, v.
//  - Continuous (GT_PvtTableContinuous[Ex]): (p, v, vMax, acc, dec, percent) per point and no times; each
//    segment accelerates, cruises at <= vMax and decelerates (GUC L1475-1504, iDEABOX L3031-3047).
// Every piece is a Segment (profile.hpp) with time in ms. The table store and the sampling at the tick are
// in pvt_table.hpp. Decisions M20-M27 in docs/decisions.md.
#pragma once

#include <vector>

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

enum class PvtMode { Pvt, PvtEx, Complete, Percent, Continuous, ContinuousEx };
const char* to_string(PvtMode mode);

// How the Continuous mode reads `acc`/`dec` (the manuals do not say, guc-ecat.md §3.4): Peak = the peak
// acceleration of the S-shaped phase (a hard limit; default, decision M24), Average = the phase's mean rate.
enum class ContinuousAcc { Peak, Average };

// One cubic piece starting at table time t0_ms: seg.duration ms, seg.p pulse, seg.v pulse/ms,
// seg.a pulse/ms^2, seg.j pulse/ms^3.
struct PvtPiece {
  double t0_ms = 0.0;
  Segment seg;
};

// A compiled PVT table: the points as given (velocity at each point as computed: the node velocity; for
// PVT-Ex the end velocity of the segment arriving there) and the pieces between them.
class PvtCurve {
 public:
  PvtMode mode = PvtMode::Pvt;
  std::vector<double> time_ms, pos, vel;
  std::vector<PvtPiece> pieces;
  // Memory blocks per point (PVT/Complete 1; Percent 1-3; Continuous 1-8: GUC L1169-1232, iDEABOX L6419-6949).
  std::vector<int> blocks_per_point;

  int blocks() const;
  double t_first() const { return time_ms.front(); }
  double t_last() const { return time_ms.back(); }
  double p_first() const { return pos.front(); }
  double p_last() const { return pos.back(); }
  // State (pulse, pulse/ms, pulse/ms^2, pulse/ms^3) at table time t_ms; before the first point: the first
  // point at rest; at or after the last point: the end of the last piece.
  MotionState at(double t_ms) const;
};

// Points of every mode: count >= 2, equal lengths, finite values, times strictly increasing and >= 0.
PvtCurve pvt_table(const std::vector<double>& time_ms, const std::vector<double>& pos,
                   const std::vector<double>& vel);
PvtCurve pvt_table_ex(const std::vector<double>& time_ms, const std::vector<double>& pos,
                      const std::vector<double>& vel_begin, const std::vector<double>& vel_end);

// Complete: the node velocities of the clamped C2 spline (v_0 = vel_begin, v_{n-1} = vel_end).
std::vector<double> pvt_complete_velocities(const std::vector<double>& time_ms, const std::vector<double>& pos,
                                            double vel_begin, double vel_end);
PvtCurve pvt_table_complete(const std::vector<double>& time_ms, const std::vector<double>& pos, double vel_begin,
                            double vel_end);

// GT_PvtPercentCalculate: the node velocities (percent, 0..100, does not change them; it is validated).
std::vector<double> pvt_percent_calculate(const std::vector<double>& time_ms, const std::vector<double>& pos,
                                          const std::vector<double>& percent, double vel_begin);
PvtCurve pvt_table_percent(const std::vector<double>& time_ms, const std::vector<double>& pos,
                           const std::vector<double>& percent, double vel_begin);

// Continuous: per point pos, vel (at the point), acc_percent/dec_percent (0..100), vel_max (> 0), acc, dec
// (> 0), all applying to the segment that leaves the point (the last point's are unused except vel).
struct ContinuousPoints {
  std::vector<double> pos, vel, acc_percent, dec_percent, vel_max, acc, dec;
};
// GT_PvtContinuousCalculate: the point times, time[0] = 0 (cumulative, iDEABOX L3706-3716).
std::vector<double> pvt_continuous_calculate(const ContinuousPoints& pts, ContinuousAcc meaning = ContinuousAcc::Peak);
// GT_PvtTableContinuous / ...Ex: times start at time_begin_ms (the start delay, GUC L1242).
PvtCurve pvt_table_continuous(const ContinuousPoints& pts, double time_begin_ms,
                              ContinuousAcc meaning = ContinuousAcc::Peak, bool ex = false);

// The S ramp of the Percent mode from v0 to v1 over T (any unit of time or master travel) with jerk
// share q = percent/100: returns up to 3 constant-jerk pieces appended to `out` starting at (t0, p0);
// returns the number of pieces (0 if T == 0).
int append_percent_ramp(std::vector<PvtPiece>& out, double t0, double duration, double p0, double v0, double v1,
                        double q);

}  // namespace servobench::motion
