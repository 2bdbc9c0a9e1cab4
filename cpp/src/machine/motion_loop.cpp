#include "servobench/machine/motion_loop.hpp"

#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

namespace {
Trace shifted(const Trace& t, std::size_t k) {
  Trace out;
#define SERVOBENCH_SHIFT(name, unit, doc) out.name = t.name ? t.name + k : nullptr;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return out;
}

void to_card(motion::SignalEvent& e, double offset) { e.edge_pos -= offset; }
}  // namespace

MotionLoop::MotionLoop(Axis& axis)
    : axis_(axis), sensing_(axis), gen_(axis.feedback_pulse(), axis.servo_period_s()) {
  inputs_ = sensing_.levels(sample_mechanism(axis_));
}

void MotionLoop::update() {
  std::vector<Staged> cmds;
  cmds.swap(staged_);
  for (auto& c : cmds) c(gen_);
}

bool MotionLoop::sequence_active() const {
  if (homing_ && !homing_->finished()) return true;
  return jog_ && (jog_->phase() != motion::JogPhase::Idle || jog_on_);
}

void MotionLoop::home(const motion::AdlinkHomeParams& p) {
  if (gen_.moving() || sequence_active())
    throw motion::MotionCommandRefused("home: refused while the axis moves (ADLINK L2706-2708)");
  homing_.emplace(p, gen_.period_s());
  jog_.reset();
}

void MotionLoop::home(const motion::GtHomeParams& p) {
  if (gen_.moving() || sequence_active())
    throw motion::MotionCommandRefused("home: refused while the axis moves (GT_Home, GT L4152-4168)");
  homing_.emplace(p);
  jog_.reset();
}

void MotionLoop::jog(const motion::AdlinkJogParams& p) {
  if (gen_.moving() || (homing_ && !homing_->finished()))
    throw motion::MotionCommandRefused(
        "jog: ignored while another motion (e.g. homing) runs (ADLINK L2708); wait for it to end");
  jog_.emplace(p, gen_.period_s());
  jog_on_ = false;
}

void MotionLoop::set_position(double pos) {
  if (!std::isfinite(pos)) throw_invalid("MotionLoop", "pos", pos, "must be a finite number");
  const double delta = gen_.state().pos - pos;
  gen_.set_position(pos);  // refuses while moving
  offset_ += delta;
  inputs_.actual_pos -= delta;
  capture_.shift(-delta);
}

void MotionLoop::set_actual_position(double pos) {
  if (!std::isfinite(pos)) throw_invalid("MotionLoop", "pos", pos, "must be a finite number");
  // GT L4613-4622, L5196-5202, GE L5457-5463, L5907-5913: the actual (encoder) position, the target and the
  // profile position all become `pos`; the offset absorbs the encoder's distance from `pos`, so a following
  // error left at rest is dropped (profile = actual afterwards), not carried into the new coordinates (VF1).
  const double delta = inputs_.actual_pos - pos;
  gen_.set_position(pos);  // refuses while moving
  offset_ += delta;
  inputs_.actual_pos = pos;
  capture_.shift(-delta);
}

void MotionLoop::clear_status() {
  brk_flag_ = false;
  capture_.clear();
}

void MotionLoop::cancel_sequence() {
  homing_.reset();
  jog_.reset();
  jog_on_ = false;
}

double MotionLoop::phase_code() const {
  if (homing_ && (!jog_)) return static_cast<double>(static_cast<int>(homing_->phase()));
  if (jog_) return static_cast<double>(static_cast<int>(jog_->phase()));
  return -1.0;
}

LoopTick MotionLoop::step(const Trace& tr, const LoopTrace& lt, std::size_t k) {
  LoopTick out;
  // 1. the sequences react to the previous tick's events
  if (homing_ && !homing_->finished()) {
    const motion::HomeAction act = homing_->step(inputs_, gen_);
    if (act.set_position) set_position(act.pos);
  }
  if (jog_) jog_->step(jog_on_, gen_);
  // 2. the generator advances
  const motion::MotionState& st = gen_.step();
  const double cmd = static_cast<double>(gen_.reported_pos()) + offset_;
  const double vel = st.vel, acc = st.acc;
  // 3. one Axis tick
  const double h = axis_.servo_period_s();
  const double t0 = static_cast<double>(axis_.tick()) * h;
  const MechSample before = sample_mechanism(axis_);
  CommandInput in;
  in.pos = &cmd;
  in.vel = &vel;
  in.acc = &acc;
  if (add_on_) in.volts_add = &add_volts_;
  in.n = 1;
  out.error_pulse = axis_.run(in, shifted(tr, k)).last_error_pulse;
  const MechSample after = sample_mechanism(axis_);
  // 4. sensing, capture, breakpoint
  TickSense ts = sensing_.between(before, after, h);
  inputs_ = ts.in;
  inputs_.actual_pos -= offset_;
  to_card(inputs_.org, offset_);
  to_card(inputs_.pel, offset_);
  to_card(inputs_.mel, offset_);
  to_card(inputs_.ez, offset_);
  bool probe = false;
  double probe_pos = 0.0;
  if (probe_time_s_ >= t0 && probe_time_s_ < t0 + h) {
    probe = true;
    probe_pos = sensing_.pulse_at(before, after, h, (probe_time_s_ - t0) / h) - offset_;
  }
  capture_.update(inputs_.org, inputs_.ez, probe, probe_pos);
  const bool home_captured = capture_.captured() && capture_.source() == CaptureTrigger::Home;
  if (brk_.check(inputs_.actual_pos, !gen_.moving(), home_captured)) {
    out.breakpoint_fired = true;
    brk_flag_ = true;
    if (auto_update_) update();
  }
  if (lt.pos) lt.pos[k] = static_cast<double>(gen_.reported_pos());
  if (lt.actual_pos) lt.actual_pos[k] = inputs_.actual_pos;
  if (lt.offset) lt.offset[k] = offset_;
  if (lt.phase) lt.phase[k] = phase_code();
  if (lt.captured) lt.captured[k] = capture_.captured() ? 1.0 : 0.0;
  if (lt.breakpoint) lt.breakpoint[k] = brk_flag_ ? 1.0 : 0.0;
  return out;
}

void MotionLoop::run(std::size_t n, const Trace& tr, const LoopTrace& lt) {
  for (std::size_t k = 0; k < n; ++k) step(tr, lt, k);
}

std::size_t MotionLoop::run_until_done(std::size_t max_ticks, const Trace& tr, const LoopTrace& lt) {
  std::size_t k = 0;
  const bool with_sequence = sequence_active();
  for (; k < max_ticks; ++k) {
    if (with_sequence ? !sequence_active() : !gen_.moving()) break;
    step(tr, lt, k);
  }
  return k;
}

}  // namespace servobench::machine
