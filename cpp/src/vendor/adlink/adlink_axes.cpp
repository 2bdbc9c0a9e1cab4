#include "servobench/vendor/adlink/adlink_axes.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "servobench/common/validate.hpp"

namespace servobench::vendor::adlink {

using machine::CardCommandRefused;
using machine::CommandFault;
using machine::StopCause;

AdlinkAxes::AdlinkAxes(machine::Card& card) : card_(card), st_(card.axis_count()) {}

const AdlinkAxisState& AdlinkAxes::state(std::size_t i) const {
  card_.check_axis(i);
  return st_[i];
}

AdlinkAxisState& AdlinkAxes::at(std::size_t i) {
  card_.check_axis(i);
  return st_[i];
}

template <class F>
void AdlinkAxes::checked(std::size_t i, F&& check) {
  try {
    check();
  } catch (const std::invalid_argument&) {
    card_.record_fault(static_cast<int>(i), CommandFault::MotionParamOverflow);
    throw;
  }
}

void AdlinkAxes::motion_started(std::size_t i) {
  card_.set_stop_cause(i, StopCause::None);  // a new motion clears the abnormal stop (ASTP, L3652)
  AdlinkAxisState& s = st_[i];
  s.ptp_active = false;
  s.pre_event = s.post_event = false;
}

// -- immediate moves ----------------------------------------------------------------------------------------

void AdlinkAxes::move_ptp(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, [&] { p.validate(); });
  card_.check_move_allowed(i, p.pos - card_.loop(i).generator().state().pos);
  start_ptp(i, p);
}

void AdlinkAxes::start_ptp(std::size_t i, const motion::AdlinkPtpParams& p) {
  motion::ProfileGenerator& gen = card_.loop(i).generator();
  const double start = gen.state().pos;
  AdlinkAxisState& s = st_[i];
  const bool was_ptp = s.ptp_active && gen.moving();
  try {
    gen.move_adlink_ptp(p.pos, p.limits(card_.servo_period_s()));
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  } catch (const std::invalid_argument& e) {
    card_.refuse(static_cast<int>(i), CommandFault::DistanceTooShort, e.what());
  }
  card_.set_target_pos(i, p.pos);
  s.wait_trigger = false;
  if (gen.moving()) {
    card_.set_stop_cause(i, StopCause::None);
    // PRED/POSTD are cleared when the axis starts moving (L3661-3662); an on-the-fly change keeps the start.
    if (!was_ptp) {
      s.move_start = start;
      s.pre_event = s.post_event = false;
    }
    s.ptp_active = true;
    s.move_target = p.pos;
  }
}

void AdlinkAxes::move_velocity(std::size_t i, double vel_pulse_per_s, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, [&] {
    p.validate();
    check_range("Card", "vel_pulse_per_s", vel_pulse_per_s, -p.vm, p.vm, "-PRA_VM..PRA_VM, pulse/s");
  });
  card_.check_move_allowed(i, vel_pulse_per_s);
  motion::ProfileGenerator& gen = card_.loop(i).generator();
  const double ts = card_.servo_period_s();
  try {
    gen.move_adlink_velocity(vel_pulse_per_s * ts, p.limits(ts));
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
  if (gen.moving()) motion_started(i);
}

void AdlinkAxes::stop_move(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, [&] { p.validate(); });
  st_[i].wait_trigger = false;
  // A homing or jog sequence ends; the axis decelerates at PRA_SD_DEC like any other move (L2570-2574).
  machine::MotionLoop& l = card_.loop(i);
  if (l.sequence_active()) l.cancel_sequence();
  l.generator().adlink_stop_move(p);
}

void AdlinkAxes::move_ptp_wait(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, [&] { p.validate(); });
  if (card_.moving(i))
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "a move waiting for the trigger only at rest");
  card_.check_move_allowed(i, p.pos - card_.loop(i).generator().state().pos);
  st_[i].waiting = p;
  st_[i].wait_trigger = true;
}

void AdlinkAxes::move_trigger(std::uint32_t mask) {
  const auto n = st_.size();
  if (mask == 0 || (n < 32 && (mask >> n) != 0))
    throw_invalid("Card", "mask", static_cast<double>(mask), "must name axes of this card (bit k = axis k)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(mask & (1u << i)) || !st_[i].wait_trigger) continue;
    const motion::AdlinkPtpParams p = st_[i].waiting;
    st_[i].wait_trigger = false;
    // Conditions may have changed while waiting (a limit, the e-stop): such an axis is ignored (stop code).
    try {
      card_.check_move_allowed(i, p.pos - card_.loop(i).generator().state().pos);
      start_ptp(i, p);
    } catch (const CardCommandRefused&) {
    }
  }
}

// -- sequences ----------------------------------------------------------------------------------------------

void AdlinkAxes::home(std::size_t i, const motion::AdlinkHomeParams& p) {
  at(i);
  checked(i, [&] { p.validate(); });
  const machine::AxisMode mode = card_.state(i).mode;
  if (mode == machine::AxisMode::Gear || mode == machine::AxisMode::Coordinated)
    card_.refuse(static_cast<int>(i), CommandFault::InvalidInMode, "APS_home_move: not in gear or coordinated mode");
  if (card_.moving(i))
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "APS_home_move only at rest (L2706-2708)");
  card_.check_move_allowed(i, 0.0);
  try {
    card_.loop(i).home(p);
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
  motion_started(i);
}

void AdlinkAxes::jog(std::size_t i, const motion::AdlinkJogParams& p) {
  at(i);
  checked(i, [&] { p.validate(); });
  const machine::AxisMode mode = card_.state(i).mode;
  if (mode == machine::AxisMode::Gear || mode == machine::AxisMode::Coordinated)
    card_.refuse(static_cast<int>(i), CommandFault::InvalidInMode, "jog: not in gear or coordinated mode");
  try {
    card_.loop(i).jog(p);
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

void AdlinkAxes::set_jog_on(std::size_t i, bool on) {
  at(i);
  machine::MotionLoop& l = card_.loop(i);
  if (!l.jogger())
    card_.refuse(static_cast<int>(i), CommandFault::InvalidInMode, "JOG-ON: no jog parameters installed (jog() first)");
  if (on && !l.jog_on()) {
    card_.check_move_allowed(i, l.jogger()->params().dir >= 0.5 ? 1.0 : -1.0);
    motion_started(i);
  }
  l.set_jog_on(on);
}

// -- parameters ---------------------------------------------------------------------------------------------

void AdlinkAxes::set_limit_stop_mode(std::size_t i, bool decelerate, double dec_pulse_per_s2) {
  AdlinkAxisState& s = at(i);
  check_range("Card", "dec_pulse_per_s2", dec_pulse_per_s2, 1e-9, 1e12, "PRA_SD_DEC, pulse/s^2");
  s.limit_decelerate = decelerate;
  s.limit_dec = dec_pulse_per_s2;
}

void AdlinkAxes::set_move_event_distances(std::size_t i, double pre_pulse, double post_pulse) {
  AdlinkAxisState& s = at(i);
  check_range("Card", "pre_pulse", pre_pulse, 0.0, 2147483647.0, "PRA_PRE_EVENT_DIST, pulse");
  check_range("Card", "post_pulse", post_pulse, 0.0, 2147483647.0, "PRA_POST_EVENT_DIST, pulse");
  s.pre_event_dist = pre_pulse;
  s.post_event_dist = post_pulse;
}

void AdlinkAxes::set_error_level(std::size_t i, double pulse) {
  AdlinkAxisState& s = at(i);
  check_nonnegative("Card", "error_level_pulse", pulse);
  s.error_level_pulse = pulse;
}

void AdlinkAxes::set_in_position_band(std::size_t i, double pulse) {
  AdlinkAxisState& s = at(i);
  check_nonnegative("Card", "in_position_pulse", pulse);
  s.in_position_pulse = pulse;
}

// -- hooks --------------------------------------------------------------------------------------------------

void AdlinkAxes::after_axis(std::size_t i, const machine::LoopTick& r) {
  AdlinkAxisState& s = st_[i];
  const machine::CardAxisState& k = card_.state(i);
  // Position-error protection (PRA_ERR_POS_LEVEL, L4012-4023): servo off. NaN trips.
  if (s.error_level_pulse > 0.0 && k.enabled && k.closed_loop && !(std::fabs(r.error_pulse) <= s.error_level_pulse)) {
    card_.latch_event(i, machine::CardEvent::ErrorLevel);
    card_.fault_stop(i, StopCause::ErrorLevel, true);
  }
  const motion::ProfileGenerator& gen = card_.loop(i).generator();
  const bool mv = gen.moving();
  if (!mv) s.limit_stopping = false;
  // The pre/post-distance events of a point-to-point move (L3284-3292).
  if (s.ptp_active) {
    const double p = gen.state().pos;
    if (s.pre_event_dist > 0.0 && std::fabs(p - s.move_start) > s.pre_event_dist) s.pre_event = true;
    if (s.post_event_dist > 0.0 && std::fabs(s.move_target - p) < s.post_event_dist) s.post_event = true;
    if (!mv) s.ptp_active = false;
  }
}

bool AdlinkAxes::on_limit(std::size_t i, StopCause cause) {
  AdlinkAxisState& s = st_[i];
  if (!s.limit_decelerate) return false;
  // PRA_EL_MODE 1: a decelerating stop at PRA_SD_DEC, issued once; the axis passes the limit while stopping.
  card_.set_stop_cause(i, cause);
  if (s.limit_stopping) return true;
  s.limit_stopping = true;
  machine::MotionLoop& l = card_.loop(i);
  l.cancel_sequence();
  const double ts = card_.servo_period_s();
  l.generator().smooth_stop_with(s.limit_dec * ts * ts, std::numeric_limits<double>::infinity());
  return true;
}

void AdlinkAxes::reset() { st_.assign(st_.size(), AdlinkAxisState{}); }

// -- access and status ---------------------------------------------------------------------------------------

AdlinkAxes& adlink(machine::Card& card) { return card.module<AdlinkAxes>(); }

const AdlinkAxes* adlink_if_any(const machine::Card& card) { return card.module_if_any<AdlinkAxes>(); }

const AdlinkAxisState& adlink_state(const machine::Card& card, std::size_t i) {
  static const AdlinkAxisState power_on{};
  card.check_axis(i);
  const AdlinkAxes* m = adlink_if_any(card);
  return m ? m->state(i) : power_on;
}

bool in_position(const machine::Card& card, std::size_t i) {
  const machine::CardAxisState& s = card.state(i);
  return s.enabled && !card.moving(i) && std::fabs(s.error_pulse) <= adlink_state(card, i).in_position_pulse;
}

bool jogging(const machine::Card& card, std::size_t i) {
  const machine::MotionLoop& l = card.loop(i);
  return l.jogger() && (l.jog_on() || l.jogger()->phase() != motion::JogPhase::Idle);
}

}  // namespace servobench::vendor::adlink
