// PVT tables and the PVT motion of one axis, sampled at the tick.
//
// PvtTables: 32 tables x 1024 memory blocks, independent of the axes; one table may drive several axes
// (GUC L1272, L1304; iDEABOX L2779-2781). A download replaces the table's contents; downloading into a table
// an axis is moving on is refused, as is more than 1024 blocks (return code 1: GUC L1306, iDEABOX L2787,
// L6436-6438).
//
// PvtAxis: GT_PrfPvt + GT_PvtTableSelect + GT_SetPvtLoop + GT_PvtStart + GT_PvtStatus/GT_GetPvtLoop.
//  - No select: table 1. Start on an empty table, or select of an empty table: refused (GUC L1279,
//    iDEABOX L6319-6327, L7048).
//  - At start the axis's PVT time is 0; a first point at t0 > 0 delays the motion by t0 ms (GUC L1310).
//  - Loop (0 = infinite, GUC L1150, L1312): after each pass the time goes back to the first point's time,
//    not 0, so the delay is not repeated; the position continues from the pass's end (decision M22).
//  - A select while moving takes effect when the current pass ends (GUC L1308, iDEABOX L2789-2791).
//  - After the last pass the axis holds the last point at rest (decision M23).
// Table positions are relative: the axis moves by p(t) - p_first from where it started (decision M22).
// Output units as ProfileGenerator: pulse, pulse/tick, pulse/tick^2, pulse/tick^3.
#pragma once

#include <array>
#include <optional>

#include "servobench/motion/profile.hpp"
#include "servobench/motion/pvt.hpp"

namespace servobench::motion {

class PvtTables {
 public:
  static constexpr int kTables = 32;
  static constexpr int kBlocksPerTable = 1024;

  // Replaces table `table_id` (1..32). Refused (MotionCommandRefused, return code 1) if the curve needs
  // more than 1024 blocks or a moving axis uses the table.
  void download(int table_id, const PvtCurve& curve);
  // nullptr if the table is empty.
  const PvtCurve* table(int table_id) const;
  bool empty(int table_id) const { return table(table_id) == nullptr; }
  // Number of moving axes on the table (kept by PvtAxis).
  int users(int table_id) const;
  void acquire(int table_id);
  void release(int table_id);

  static void check_id(double table_id);

 private:
  std::array<std::optional<PvtCurve>, kTables> tables_{};
  std::array<int, kTables> users_{};
};

class PvtAxis {
 public:
  PvtAxis(PvtTables& tables, double start_pos = 0.0, double period_s = 1e-3);
  ~PvtAxis();
  PvtAxis(const PvtAxis&) = delete;
  PvtAxis& operator=(const PvtAxis&) = delete;

  // GT_PvtTableSelect: at rest at once; while moving at the end of the current pass.
  void select(int table_id);
  // GT_SetPvtLoop: total passes, 0 = infinite (used at the next start; while moving, for the rest of this run).
  void set_loop(double loop);
  // GT_PvtStart for this axis (several axes: call start() on each before stepping, pvt_start()).
  void start();
  // GT_Stop (abrupt): the motion ends where it is.
  void stop();
  // Advances one tick; returns the state at the new tick.
  const MotionState& step();

  const MotionState& state() const { return state_; }
  long long reported_pos() const;
  bool moving() const { return running_; }
  double period_s() const { return period_s_; }
  // GT_PvtStatus: the table in use (the selected one at rest) and the axis's PVT time in ms.
  int table_id() const { return running_ ? active_ : selected_; }
  double time_ms() const { return time_ms_; }
  // GT_GetPvtLoop: passes completed and the loop setting.
  long loop_count() const { return passes_done_; }
  long loop() const { return loop_; }

 private:
  void finish();

  PvtTables& tables_;
  double period_s_;
  double period_ms_;
  MotionState state_;
  int selected_ = 1;
  int active_ = 1;
  const PvtCurve* curve_ = nullptr;
  bool running_ = false;
  long loop_ = 1;
  long passes_done_ = 0;
  long long ticks_ = 0;     // ticks since start
  double origin_ms_ = 0.0;  // elapsed time at which the current pass's table time is 0
  double base_pos_ = 0.0;   // axis position that the current pass's first point maps to
  double time_ms_ = 0.0;
};

// GT_PvtStart(mask): starts every axis in the list on the same tick.
void pvt_start(const std::vector<PvtAxis*>& axes);

}  // namespace servobench::motion
