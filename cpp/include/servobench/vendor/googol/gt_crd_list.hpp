// GtCrdList: the GT coordinated-motion commands (GT manual L1513-2011, gt.md §4, §8.11) over the card's GT_MapAxis
// coordinate system (machine::CardModes::gt_map_axis / gt_path, a motion::PathGenerator in coordinate units per
// sample time ST): immediate mode (a line or arc runs at once, one at a time, L1800) and buffer mode (GT_StrtList,
// one Mv* start point, path commands, GT_EndList / GT_AddList, GT_StrtMtn, the stops; L1841-1940), the modal
// vector velocity and acceleration (GT_SetSynVel / SetSynAcc, L1725-1729), the per-axis acceleration limit at the
// joints (GT_SetAccLmt L1956-1966), the executing segment number (GT_GetMtnNm, decision GF9) and the coordinate
// status word (Table 5-6, L1990-2011).
//
// Return codes (Table 2-1 L393-408): 0, 1 (the command in the wrong state: GT_GetCmdSts bit 12; an Mv* error:
// bit 13; buffer full: bit 15, Table 2-2 L455-478), 2/3/5 (arc radius, line length, arc end point: the path
// geometry's code), 4 (SynVel/SynAcc zero, negative or too large), 6 (a map that determines no coordinate),
// 7 (a parameter out of range), -1 never (the dialect answers -1 without a card).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "servobench/motion/path_generator.hpp"
#include "servobench/motion/path_segment.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

class GtCard;  // gt_card.hpp

// The list registers (reset state = HardRst items 1, 15, 16: SynVel/SynAcc 0, CrdAuStp on, immediate mode).
struct GtCrdRegs {
  double vel = 0.0;          // vector velocity, coordinate units/ST (GT_SetSynVel, or the last Mv*'s)
  double acc = 0.0;          // vector acceleration, coordinate units/ST^2
  bool buffer = false;       // buffer mode (GT_StrtList) / immediate mode
  bool open = false;         // the buffer takes commands (StrtList / AddList .. EndList / StpMtn / EStpMtn)
  bool mv = false;           // the Mv* start point is in the buffer (L1843)
  bool started = false;      // GT_StrtMtn ran the buffer (crd status bit 13 is defined only then)
  bool error = false;        // the last coordinated command failed (crd status bit 3)
  bool au_stp = true;        // GT_CrdAuStpOn (crd status bit 6)
  int cmd_bit = 12;          // GT_GetCmdSts bit of the last refused coordinated command: 12, 13 or 15
  long long pushed = 0;      // path segments buffered since GT_StrtList
  long long mv_pushed = 0;   // 1 when the Mv* start line was a motion segment (it is segment 0)
  std::array<double, 4> acc_lmt{};  // GT_SetAccLmt per motor axis, pulse/ST^2 (0 = no limit)
};

class GtCrdList {
 public:
  explicit GtCrdList(GtCard& gt) : gt_(gt) {}

  const GtCrdRegs& regs() const { return r_; }
  void reset() { r_ = GtCrdRegs{}; }
  // The command status word while the last fault is a coordinated one (Table 2-2): 1 << cmd_bit.
  std::uint16_t command_status_bit() const { return static_cast<std::uint16_t>(1u << r_.cmd_bit); }

  // GT_MapAxis(axis 1..4, {Cx, Cy, Cz, Ca, C}) (L1533-1538, L1528, L1660).
  GtCode map_axis(double axis, const std::vector<double>& counts);
  GtCode set_syn_vel(double vel);           // 0 < vel <= 16384, else 4 (L1725, L401)
  GtCode set_syn_acc(double acc);           // 0 < acc <= 16384, else 4 (L1729)
  GtCode set_acc_lmt(double acc);           // current axis, 0..16384 pulse/ST^2 (L1956, decision GF10)
  // GT_LnXY / LnXYZ / LnXYZA: a line to the absolute point (the first n coordinates; the rest stay) (L1749-1751).
  GtCode line(const std::vector<double>& point);
  // GT_ArcXY / ArcYZ / ArcZX: centre (absolute, plane coordinates) and angle in degrees (+ = CCW) (L1752-1756).
  GtCode arc_center_angle(motion::ArcPlane plane, double center_1, double center_2, double angle_deg);
  // GT_ArcXYP / ArcYZP / ArcZXP: end point, signed radius, direction +1 CCW / -1 CW (L1753, decision GF8).
  GtCode arc_end_radius(motion::ArcPlane plane, double end_1, double end_2, double radius, double direction);
  GtCode start_list();                      // GT_StrtList (L1841)
  // GT_MvXY / MvXYZ / MvXYZA: the buffer's start point, reached at rest; vel/acc become the defaults (L1843-1845).
  GtCode move_start_point(const std::vector<double>& point, double vel, double acc);
  GtCode end_list();                        // GT_EndList (L1849)
  GtCode add_list();                        // GT_AddList (L1853-1859)
  GtCode start_motion();                    // GT_StrtMtn (L1928, L1940)
  GtCode stop(bool abrupt);                 // GT_StpMtn / GT_EStpMtn: both close the buffer (L1934-1936, L3332)
  GtCode set_auto_stop(bool on);            // GT_CrdAuStpOn / Off (L2011, decision V64)
  // GT_GetMtnNm (L1971-1985, GF9): the segment executing (Mv* = 0, then 1, 2, ...); 0 in immediate mode.
  long long motion_number() const;
  // GT_GetCrdSts (Table 5-6, L1990-2011).
  std::uint16_t status() const;
  // GT_GetBrkPnt (L1971): the coordinate point where the buffer was stopped, if any (1 without a system).
  GtCode breakpoint(std::optional<std::vector<double>>& point);

 private:
  GtCode refuse(int bit = 12, GtCode code = GtCode::CommandError);
  // Runs a list command; a refusal becomes bit 15 (buffer full), 13 (an Mv*) or 12 (wrong state).
  GtCode run(const std::function<void()>& command, bool mv = false);
  motion::PathGenerator* path();            // the GT system's path, or null when the card refuses it
  const motion::PathGenerator* path_if_set_up() const;
  void apply_acc_lmt();
  GtCode path_command(const std::function<motion::PathSegmentGeometry(const motion::CrdPoint&, int)>& make);

  GtCard& gt_;
  GtCrdRegs r_{};
};

}  // namespace servobench::vendor::googol
