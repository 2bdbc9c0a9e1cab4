#include "servobench/motion/pvt_table.hpp"

#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/units.hpp"

namespace servobench::motion {

void PvtTables::check_id(double table_id) {
  check_integer("PvtTable", "table_id", table_id, 1, kTables, "GUC L1304, iDEABOX L2779");
}

void PvtTables::download(int table_id, const PvtCurve& curve) {
  check_id(table_id);
  const auto k = static_cast<std::size_t>(table_id - 1);
  const int blocks = curve.blocks();
  if (blocks > kBlocksPerTable)
    throw MotionCommandRefused("PvtTable " + std::to_string(table_id) + ": the " +
                               std::string(to_string(curve.mode)) + " data needs " + std::to_string(blocks) +
                               " memory blocks, a table holds 1024 (return code 1; GUC L1272, iDEABOX "
                               "L6436-6438)");
  if (users_[k] > 0)
    throw MotionCommandRefused("PvtTable " + std::to_string(table_id) +
                               ": refused, an axis is moving on this table (return code 1; GUC L1306, iDEABOX L2787)");
  tables_[k] = curve;
}

const PvtCurve* PvtTables::table(int table_id) const {
  check_id(table_id);
  const auto& t = tables_[static_cast<std::size_t>(table_id - 1)];
  return t ? &*t : nullptr;
}

int PvtTables::users(int table_id) const {
  check_id(table_id);
  return users_[static_cast<std::size_t>(table_id - 1)];
}

void PvtTables::acquire(int table_id) { ++users_[static_cast<std::size_t>(table_id - 1)]; }
void PvtTables::release(int table_id) { --users_[static_cast<std::size_t>(table_id - 1)]; }

PvtAxis::PvtAxis(PvtTables& tables, double start_pos, double period_s)
    : tables_(tables), period_s_(period_s), period_ms_(period_s * 1e3) {
  if (!std::isfinite(start_pos)) throw_invalid("PvtAxis", "start_pos", start_pos, "must be a finite number");
  check_range("PvtAxis", "period_s", period_s, 1e-6, 1.0, "s");
  state_.pos = start_pos;
}

PvtAxis::~PvtAxis() {
  if (running_) tables_.release(active_);
}

void PvtAxis::select(int table_id) {
  PvtTables::check_id(table_id);
  if (tables_.empty(table_id))
    throw MotionCommandRefused("PvtTableSelect: table " + std::to_string(table_id) +
                               " is empty (return code 1; iDEABOX L7048)");
  selected_ = table_id;
}

void PvtAxis::set_loop(double loop) {
  check_integer("PvtAxis", "loop", loop, 0, 2147483647.0, "0 = infinite, GUC L1150, iDEABOX L7458");
  loop_ = static_cast<long>(loop);
}

void PvtAxis::start() {
  if (running_)
    throw MotionCommandRefused("PvtStart: refused, the axis is moving (return code 1; GT_Stop first)");
  curve_ = tables_.table(selected_);
  if (curve_ == nullptr)
    throw MotionCommandRefused("PvtStart: table " + std::to_string(selected_) +
                               " is empty, the start fails (return code 1; GUC L1279, iDEABOX L6319-6321)");
  active_ = selected_;
  tables_.acquire(active_);
  running_ = true;
  passes_done_ = 0;
  ticks_ = 0;
  origin_ms_ = 0.0;
  time_ms_ = 0.0;
  base_pos_ = state_.pos;
  state_ = {state_.pos, 0.0, 0.0, 0.0};
}

void pvt_start(const std::vector<PvtAxis*>& axes) {
  for (auto* a : axes)
    if (a->moving()) throw MotionCommandRefused("PvtStart: refused, an axis in the mask is moving (return code 1)");
  for (auto* a : axes) a->start();
}

void PvtAxis::finish() {
  tables_.release(active_);
  running_ = false;
}

void PvtAxis::stop() {
  if (!running_) return;
  finish();
  state_ = {state_.pos, 0.0, 0.0, 0.0};
}

long long PvtAxis::reported_pos() const { return std::llround(state_.pos); }

const MotionState& PvtAxis::step() {
  if (!running_) {
    state_ = {state_.pos, 0.0, 0.0, 0.0};
    return state_;
  }
  ++ticks_;
  const double elapsed = static_cast<double>(ticks_) * period_ms_;
  double t = elapsed - origin_ms_;
  // Pass ends (a while: a pass may be shorter than a tick).
  while (t >= curve_->t_last()) {
    ++passes_done_;
    const double end_pos = base_pos_ + (curve_->p_last() - curve_->p_first());
    if (loop_ != 0 && passes_done_ >= loop_) {
      time_ms_ = curve_->t_last();
      finish();
      state_ = {end_pos, 0.0, 0.0, 0.0};
      return state_;
    }
    const double pass_end = origin_ms_ + curve_->t_last();
    if (selected_ != active_) {  // deferred table switch (GUC L1308)
      tables_.release(active_);
      active_ = selected_;
      tables_.acquire(active_);
      curve_ = tables_.table(active_);
    }
    origin_ms_ = pass_end - curve_->t_first();
    base_pos_ = end_pos;
    t = elapsed - origin_ms_;
  }
  time_ms_ = t;
  const MotionState s = curve_->at(t);
  state_.pos = base_pos_ + (t < curve_->t_first() ? 0.0 : s.pos - curve_->p_first());
  state_.vel = per_ms_to_per_tick(s.vel, period_s_, 1);
  state_.acc = per_ms_to_per_tick(s.acc, period_s_, 2);
  state_.jerk = per_ms_to_per_tick(s.jerk, period_s_, 3);
  return state_;
}

}  // namespace servobench::motion
