// The card kernel's tick: commit, safety, the axes two calls deep (Card -> MotionLoop::step -> Axis::run), the
// checks on what the step returned, the modules' hooks, the scope (machine/card.hpp "One tick").
#include "servobench/machine/card.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "card_detail.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card_scope.hpp"

namespace servobench::machine {

using detail::shifted;

// -- the tick -----------------------------------------------------------------------------------------------

// The inputs and inhibits safety reads every tick (here, beside the tick, so the tick inlines them).

bool Card::limit_enabled(std::size_t i, bool positive) const {
  for (const CardHooks* h : hooks_)
    if (!h->limit_enabled(i, positive)) return false;
  return true;
}

bool Card::pos_limit_input(std::size_t i) const {
  const Axis& a = loop(i).axis();
  const bool hit = a.config().switches.pos_limit(a.load_angle_rad());
  return hit != state(i).limits.pos_active_low;
}

bool Card::neg_limit_input(std::size_t i) const {
  const Axis& a = loop(i).axis();
  const bool hit = a.config().switches.neg_limit(a.load_angle_rad());
  return hit != state(i).limits.neg_active_low;
}

bool Card::inhibited_pos(std::size_t i) const {
  const CardAxisState& s = st_[i];
  return (s.limits.enabled && (s.events & event_bit(CardEvent::PosLimit))) ||
         (s.limits.soft_pos_enabled && (s.events & event_bit(CardEvent::SoftPosLimit)));
}

bool Card::inhibited_neg(std::size_t i) const {
  const CardAxisState& s = st_[i];
  return (s.limits.enabled && (s.events & event_bit(CardEvent::NegLimit))) ||
         (s.limits.soft_neg_enabled && (s.events & event_bit(CardEvent::SoftNegLimit)));
}

void Card::limit_stop(std::size_t i, StopCause cause) {
  for (CardHooks* h : hooks_)  // a module may stop the axis its own way (ADLINK PRA_EL_MODE 1: decelerating)
    if (h->on_limit(i, cause)) return;
  fault_stop(i, cause, false);
}

void Card::fault_stop(std::size_t i, StopCause cause, bool servo_off) {
  CardAxisState& s = at(i);
  for (CardHooks* h : hooks_) h->on_fault(i, cause);  // [modes] the gear master / the coordinate system stops too
  if (loops_[i]->generator().moving() || loops_[i]->sequence_active()) {
    loops_[i]->cancel_sequence();
    stop_profile(i);
  } else if (servo_off && s.enabled) {
    s.events |= event_bit(CardEvent::MotionComplete);
  }
  s.stop_cause = cause;
  if (servo_off && s.enabled) {
    s.enabled = false;
    apply_output(i);
  }
}

void Card::safety_before(std::size_t i) {
  CardAxisState& s = st_[i];
  MotionLoop& l = *loops_[i];
  const double vel = l.generator().state().vel;
  // Emergency stop (ADLINK L3924-3938): moving axes stop at once.
  if (estop_ && l.generator().moving()) {
    s.events |= event_bit(CardEvent::EmergencyStop);
    fault_stop(i, StopCause::EmergencyStop, false);
  }
  // Drive alarm (GT L2180-2194): bits 1 and 0, drive disabled like AxisOff.
  const bool alarm = s.alarm_enabled && (l.axis().alarm() || s.alarm_input);
  if (alarm && (!s.alarm_prev || s.enabled || l.generator().moving())) {
    s.events |= event_bit(CardEvent::DriveAlarm) | event_bit(CardEvent::MotionComplete);
    fault_stop(i, StopCause::DriveAlarm, true);
  }
  s.alarm_prev = alarm;
  // Hard limits (GT L2196-2213): latch the event while triggered; stop motion toward the limit.
  if (s.limits.enabled) {  // [modes] a GUC crd's BufLmtsOff hides the limit from its place in the FIFO on (V129)
    if (pos_limit_input(i) && limit_enabled(i, true)) s.events |= event_bit(CardEvent::PosLimit);
    if (neg_limit_input(i) && limit_enabled(i, false)) s.events |= event_bit(CardEvent::NegLimit);
  }
  const double act = l.actual_pos();
  if (s.limits.soft_pos_enabled && act >= s.limits.soft_pos_pulse) s.events |= event_bit(CardEvent::SoftPosLimit);
  if (s.limits.soft_neg_enabled && act <= s.limits.soft_neg_pulse) s.events |= event_bit(CardEvent::SoftNegLimit);
  // Direction inhibit: motion toward a latched limit stops at once (GT L2206-2209), or as a module says (on_limit:
  // the ADLINK PRA_EL_MODE 1 decelerates). An ADLINK homing sequence meets the limits itself (it reverses or stops at them, L2341-2508).
  if (l.homing() && !l.homing()->finished() && !l.homing()->is_gt()) return;
  if (vel > 0.0 && inhibited_pos(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::PosLimit));
    limit_stop(i, hard ? StopCause::PosLimit : StopCause::SoftPosLimit);
  } else if (vel < 0.0 && inhibited_neg(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::NegLimit));
    limit_stop(i, hard ? StopCause::NegLimit : StopCause::SoftNegLimit);
  }
}

void Card::after_tick(std::size_t i, const LoopTick& r) {
  CardAxisState& s = st_[i];
  MotionLoop& l = *loops_[i];
  if (r.breakpoint_fired && s.auto_update) {
    // GT L1263: the auto-update commits everything staged; effective from the next tick.
    const std::uint32_t d = s.dirty;
    s.dirty = 0;
    commit(i, s.staged, d);
  }
  const double error = r.error_pulse;
  s.error_pulse = error;
  // Following error (GT L2154-2178): every sample, closed loop, drive enabled.
  // An encoder fault (GE status bit 27) counts as a following error: the feedback can no longer be trusted, and the
  // following-error protection is the card's guard against encoder faults (GE L2358; decision RB6). NaN trips.
  s.following_error_now = s.enabled && s.closed_loop && (!(std::fabs(error) <= s.active.pos_err) || s.encoder_fault);
  if (s.following_error_now) {
    s.events |= event_bit(CardEvent::FollowingError);
    if (s.auto_stop) {
      fault_stop(i, StopCause::FollowingError, true);
      s.following_error_now = false;  // the drive is off: the check is no longer in effect (V13)
    }
  }
  if (l.breakpoint_flag()) s.events |= event_bit(CardEvent::Breakpoint);
  if (l.capture().captured()) s.events |= event_bit(CardEvent::Captured);
  const bool mv = l.generator().moving();
  const double v = l.generator().state().vel;
  if (v > 0.0) s.dir_positive = true;
  if (v < 0.0) s.dir_positive = false;
  if (s.was_moving && !mv) s.events |= event_bit(CardEvent::MotionComplete);
  s.was_moving = mv;
}

void Card::tick_once(const std::vector<CardTrace>& traces, std::size_t k) {
  const auto n = loops_.size();
  // 1. commits, at a motion-cycle boundary
  if (tick_ % static_cast<long long>(cycles_.motion_cycle_ticks) == 0)
    for (std::size_t i = 0; i < n; ++i)
      if (st_[i].commit_pending) {
        CardAxisState& s = st_[i];
        s.commit_pending = false;
        const std::uint32_t d = s.pending_dirty;
        s.pending_dirty = 0;
        commit(i, s.pending, d);
        if (s.brk_deferred) {
          s.brk_deferred = false;
          loops_[i]->breakpoint().arm(s.brk_deferred_kind);
        }
      }
  // 2. safety on this instant's inputs
  for (std::size_t i = 0; i < n; ++i) safety_before(i);
  // 3. the loops, two calls deep: Card -> MotionLoop::step -> Axis::run; 4. the checks after the law, on what the
  // step returned. Driven axes ([modes]) get their command first, in axis order.
  std::uint32_t driven = 0;  // bit m: module m is active this tick (decided once, before any axis runs)
  for (std::size_t m = 0; m < hooks_.size(); ++m)
    if (hooks_[m]->active()) {
      driven |= 1u << m;
      hooks_[m]->begin_tick(tick_);
    }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t m = 0; driven >> m; ++m)
      if (driven & (1u << m)) hooks_[m]->feed(i);
    Trace tr;
    LoopTrace lt;
    if (!traces.empty()) {
      tr = shifted(traces[i].axis, k);
      lt = shifted(traces[i].loop, k);
    }
    if (scope_ && scope_->needs_signals(i)) scope_->bind_signals(i, tr, lt);  // scope hook (issue 10.3)
    const LoopTick r = loops_[i]->step(tr, lt);
    after_tick(i, r);
    for (CardHooks* h : hooks_) h->after_axis(i, r);  // a vendor's checks on what the step returned
    if (!traces.empty()) record(i, traces[i], k);
  }
  if (scope_) scope_tick();  // scope hook (issue 10.3)
  ++tick_;
}

void Card::record(std::size_t i, const CardTrace& ct, std::size_t k) const {
  if (ct.events) ct.events[k] = static_cast<double>(st_[i].events);
  if (ct.moving) ct.moving[k] = moving(i) ? 1.0 : 0.0;
  if (ct.servo_on) ct.servo_on[k] = st_[i].enabled ? 1.0 : 0.0;
  if (ct.prf_vel) ct.prf_vel[k] = loops_[i]->generator().state().vel;
}

void Card::run(std::size_t n, const std::vector<CardTrace>& traces) {
  if (!traces.empty() && traces.size() != loops_.size())
    throw_invalid("Card.run", "traces", static_cast<double>(traces.size()),
                  "must be empty or one per axis (" + std::to_string(loops_.size()) + ")");
  if (scope_) scope_->resync();  // scope hook (issue 10.3)
  for (std::size_t k = 0; k < n; ++k) tick_once(traces, k);
}

// -- scope, events, compare, probe (issue 10 point 3; machine/card_scope.hpp) ----------------------------------

CardScope& Card::scope() {
  if (!scope_) scope_ = std::make_unique<CardScope>(*this);
  return *scope_;
}

void Card::scope_tick() {
  const std::uint32_t latched = scope_->probe(tick_);
  for (std::size_t i = 0; i < st_.size(); ++i)
    if (latched & (1u << i)) st_[i].events |= event_bit(CardEvent::Captured);
  scope_->after_tick(tick_);
}

std::size_t Card::run_until_event(std::size_t n, const std::vector<CardTrace>& traces) {
  if (!traces.empty() && traces.size() != loops_.size())
    throw_invalid("Card.run", "traces", static_cast<double>(traces.size()),
                  "must be empty or one per axis (" + std::to_string(loops_.size()) + ")");
  CardScope& s = scope();
  s.resync();
  std::size_t k = 0;
  while (k < n) {
    tick_once(traces, k);
    ++k;
    if (s.run_ended()) break;
  }
  return k;
}

void Card::set_probe_time(double t_s) {
  if (!std::isnan(t_s) && !std::isfinite(t_s))
    throw_invalid("Card", "probe_time_s", t_s, "must be a finite time in s (or NaN: never)");
  // The loops compare with their Axis's own clock; a card's axes may have run before they joined the card.
  for (auto& l : loops_) {
    const double offset_s = static_cast<double>(l->axis().tick() - tick_) * period_s_;
    l->set_probe_time(std::isnan(t_s) ? t_s : t_s + offset_s);
  }
}

}  // namespace servobench::machine
