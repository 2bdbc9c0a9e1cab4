#include "servobench/machine/card.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/machine/card_scope.hpp"

namespace servobench::machine {

namespace {

constexpr double kPosMin = -1073741824.0;  // -2^30 (GT L854, GE L991)
constexpr double kPosMax = 1073741823.0;   // 2^30 - 1

Trace shifted(const Trace& t, std::size_t k) {
  Trace out;
#define SERVOBENCH_SHIFT(name, unit, doc) out.name = t.name ? t.name + k : nullptr;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return out;
}

LoopTrace shifted(const LoopTrace& t, std::size_t k) {
  LoopTrace out;
#define SERVOBENCH_SHIFT(name, unit, doc) out.name = t.name ? t.name + k : nullptr;
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return out;
}

std::string axis_name(std::size_t i) { return "axis " + std::to_string(i + 1); }

}  // namespace

const char* to_string(AxisMode mode) {
  switch (mode) {
    case AxisMode::TCurve: return "t_curve";
    case AxisMode::Jog: return "jog";
    case AxisMode::SCurve: return "s_curve";
    case AxisMode::Gear: return "gear";
    case AxisMode::Coordinated: return "coordinated";
    case AxisMode::Pvt: return "pvt";
    case AxisMode::Follow: return "follow";
  }
  return "?";
}

const char* to_string(CommandFault fault) {
  switch (fault) {
    case CommandFault::None: return "none";
    case CommandFault::MotionParamOverflow: return "motion_param_overflow";
    case CommandFault::IllegalControlParam: return "illegal_control_param";
    case CommandFault::NoAxisInMask: return "no_axis_in_mask";
    case CommandFault::DriveResetWhileEnabled: return "drive_reset_while_enabled";
    case CommandFault::ModeChangeInMotion: return "mode_change_in_motion";
    case CommandFault::IndexCaptureArmed: return "index_capture_armed";
    case CommandFault::HomeCaptureArmed: return "home_capture_armed";
    case CommandFault::AxisOnWhileAlarm: return "axis_on_while_alarm";
    case CommandFault::ChangeInMotion: return "change_in_motion";
    case CommandFault::DirectionInhibited: return "direction_inhibited";
    case CommandFault::EmergencyStopActive: return "emergency_stop_active";
    case CommandFault::InvalidInMode: return "invalid_in_mode";
    case CommandFault::DriveAlarmActive: return "drive_alarm_active";
    case CommandFault::DistanceTooShort: return "distance_too_short";
    case CommandFault::MotorStateWhileEnabled: return "motor_state_while_enabled";
    case CommandFault::AxisStateError: return "axis_state_error";
    case CommandFault::NotInCommandSet: return "not_in_command_set";
    case CommandFault::NotSimulated: return "not_simulated";
    case CommandFault::CrdStateError: return "crd_state_error";
    case CommandFault::NoInterruptPending: return "no_interrupt_pending";
  }
  return "?";
}

const char* to_string(StopCause cause) {
  switch (cause) {
    case StopCause::None: return "none";
    case StopCause::EmergencyStop: return "emergency_stop";
    case StopCause::DriveAlarm: return "drive_alarm";
    case StopCause::PosLimit: return "pos_limit";
    case StopCause::NegLimit: return "neg_limit";
    case StopCause::SoftPosLimit: return "soft_pos_limit";
    case StopCause::SoftNegLimit: return "soft_neg_limit";
    case StopCause::ErrorLevel: return "error_level";
    case StopCause::FollowingError: return "following_error";
  }
  return "?";
}

void CardCycles::validate() const {
  check_integer("CardCycles", "motion_cycle_ticks", motion_cycle_ticks, 1, 1000);
  check_integer("CardCycles", "host_cycle_ticks", host_cycle_ticks, 1, 10000);
  if (std::fmod(host_cycle_ticks, motion_cycle_ticks) != 0.0)
    throw_invalid("CardCycles", "host_cycle_ticks", host_cycle_ticks,
                  "must be a whole multiple of motion_cycle_ticks = " + format_value(motion_cycle_ticks));
}

void LimitConfig::validate() const {
  if (!std::isfinite(soft_pos_pulse)) throw_invalid("CardLimits", "soft_pos_pulse", soft_pos_pulse, "must be finite");
  if (!std::isfinite(soft_neg_pulse)) throw_invalid("CardLimits", "soft_neg_pulse", soft_neg_pulse, "must be finite");
  if (soft_pos_enabled && soft_neg_enabled && !(soft_neg_pulse < soft_pos_pulse))
    throw_invalid("CardLimits", "soft_neg_pulse", soft_neg_pulse,
                  "must be below soft_pos_pulse = " + format_value(soft_pos_pulse) + " when both soft limits are on");
}

// -- construction -------------------------------------------------------------------------------------------

Card::Card(int axes, const AxisConfig& axis_config, const CardCycles& cycles) {
  if (axes != 4 && axes != 8) throw_invalid("Card", "axes", axes, "must be 4 or 8 (the cards' axis counts)");
  for (int i = 0; i < axes; ++i) {
    owned_.push_back(std::make_unique<Axis>(axis_config));
    loops_.push_back(std::make_unique<MotionLoop>(*owned_.back()));
  }
  init(cycles);
}

Card::Card(const std::vector<Axis*>& axes, const CardCycles& cycles) {
  const auto n = static_cast<double>(axes.size());
  if (axes.size() != 4 && axes.size() != 8) throw_invalid("Card", "axes", n, "must be 4 or 8 axes");
  std::set<const Axis*> seen;
  for (Axis* a : axes) {
    if (a == nullptr) throw std::invalid_argument("Card.axes: an axis is missing (null)");
    if (!seen.insert(a).second) throw std::invalid_argument("Card.axes: the same Axis is given twice; each card axis needs its own");
    if (a->servo_period_s() != axes[0]->servo_period_s())
      throw_invalid("Card", "servo_period_s", a->servo_period_s(),
                    "differs between axes; one card has one servo clock (axis 1: " +
                        format_value(axes[0]->servo_period_s()) + " s)");
    loops_.push_back(std::make_unique<MotionLoop>(*a));
  }
  init(cycles);
}

Card::~Card() = default;

// [modes] the driven modes live in CardModes (machine/card_modes.cpp), created on first use and attached as a module.
CardModes& Card::modes() {
  if (!modes_) {
    modes_ = std::make_unique<CardModes>(*this);
    attach(*modes_);
  }
  return *modes_;
}

void Card::attach(CardHooks& module) {
  for (CardHooks* h : hooks_)
    if (h == &module) return;
  if (hooks_.size() >= 16) throw_invalid("Card.attach", "module", static_cast<double>(hooks_.size() + 1),
                                         "is one module too many: a card takes at most 16");
  hooks_.push_back(&module);
}

void Card::detach(CardHooks& module) {
  for (auto it = hooks_.begin(); it != hooks_.end(); ++it)
    if (*it == &module) {
      hooks_.erase(it);
      return;
    }
}

bool Card::limit_enabled(std::size_t i, bool positive) const {
  for (const CardHooks* h : hooks_)
    if (!h->limit_enabled(i, positive)) return false;
  return true;
}

void Card::check_axis(std::size_t i) const {
  if (i >= st_.size()) throw_invalid("Card", "axis", static_cast<double>(i), "is not an axis of this card");
}

void Card::set_driven_mode(std::size_t i, AxisMode mode) { at(i).mode = mode; }

void Card::set_stop_cause(std::size_t i, StopCause cause) { at(i).stop_cause = cause; }

void Card::init(const CardCycles& cycles) {
  cycles.validate();
  cycles_ = cycles;
  period_s_ = loops_[0]->axis().servo_period_s();
  st_.assign(loops_.size(), CardAxisState{});
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    // The given laws are the power-on registers; the drives start disabled (V11).
    st_[i].staged.law = st_[i].active.law = loops_[i]->axis().config().law;
    apply_output(i);
  }
}

MotionLoop& Card::loop(std::size_t i) {
  if (i >= loops_.size()) throw_invalid("Card", "axis", static_cast<double>(i), "is not an axis of this card");
  return *loops_[i];
}
const MotionLoop& Card::loop(std::size_t i) const {
  if (i >= loops_.size()) throw_invalid("Card", "axis", static_cast<double>(i), "is not an axis of this card");
  return *loops_[i];
}
const CardAxisState& Card::state(std::size_t i) const {
  if (i >= st_.size()) throw_invalid("Card", "axis", static_cast<double>(i), "is not an axis of this card");
  return st_[i];
}
CardAxisState& Card::at(std::size_t i) {
  if (i >= st_.size()) throw_invalid("Card", "axis", static_cast<double>(i), "is not an axis of this card");
  return st_[i];
}

void Card::reset() {
  for (CardHooks* h : hooks_) h->reset();  // [modes] no gear, PVT, cam or mapping after a reset (GT HardRst [17])
  estop_ = false;
  last_fault_ = CommandFault::None;
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    MotionLoop& l = *loops_[i];
    l.cancel_sequence();
    l.generator().abrupt_stop();
    l.set_position(0.0);  // registers = 0 (HardRst [1]) with the coordinates where the axis stands (V12)
    l.breakpoint().off();
    l.breakpoint().set_compare(0.0);
    l.capture().arm(CaptureTrigger::None);
    l.clear_status();
    l.capture().shift(-l.capture().value());
    CardAxisState s;
    if (std::holds_alternative<control::ApsServoLawParams>(st_[i].active.law)) {
      s.staged.law = s.active.law = control::ApsServoLawParams{};
    } else {
      s.staged.law = s.active.law = control::GtServoLawParams{};  // gains 0, ILmt/MtrLmt 32767 (HardRst [6,7,13])
    }
    st_[i] = s;
    l.axis().set_law(s.active.law);
    apply_output(i);
  }
  if (scope_) scope_->reset_registers();  // sampler, compare, probe position (V126)
}

// -- faults -------------------------------------------------------------------------------------------------

void Card::record_fault(int axis, CommandFault fault) {
  last_fault_ = fault;
  if (axis >= 0 && static_cast<std::size_t>(axis) < st_.size())
    st_[static_cast<std::size_t>(axis)].events |= event_bit(CardEvent::CommandError);
}

void Card::refuse(int axis, CommandFault fault, const std::string& what) {
  record_fault(axis, fault);
  const std::string who = axis >= 0 ? axis_name(static_cast<std::size_t>(axis)) + ": " : std::string();
  throw CardCommandRefused(fault, axis, who + what + " [refused: " + to_string(fault) + "; return code 1]");
}

template <class F>
void Card::checked(std::size_t i, CommandFault fault, F&& check) {
  try {
    check();
  } catch (const std::invalid_argument&) {
    record_fault(static_cast<int>(i), fault);
    throw;
  }
}

void Card::touch(std::size_t i, std::uint32_t bits) { st_[i].dirty |= bits; }

// -- staged registers ---------------------------------------------------------------------------------------

void Card::stage_pos(std::size_t i, double pos) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow,
          [&] { check_integer("Card", "pos", pos, kPosMin, kPosMax, "whole pulses, GT L854"); });
  st_[i].staged.pos = pos;
  touch(i, kStagedPos);
}

void Card::stage_vel(std::size_t i, double vel) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] {
    if (!std::isfinite(vel)) throw_invalid("Card", "vel", vel, "must be finite (pulse/tick)");
  });
  st_[i].staged.vel = vel;
  touch(i, kStagedVel);
}

void Card::stage_acc(std::size_t i, double acc) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { check_nonnegative("Card", "acc", acc); });
  st_[i].staged.acc = acc;
  touch(i, kStagedAcc);
}

void Card::stage_macc(std::size_t i, double macc) {
  at(i);
  checked(i, CommandFault::IllegalControlParam, [&] { check_nonnegative("Card", "macc", macc); });
  st_[i].staged.macc = macc;
  touch(i, kStagedMAcc);
}

void Card::stage_jerk(std::size_t i, double jerk) {
  at(i);
  checked(i, CommandFault::IllegalControlParam, [&] { check_nonnegative("Card", "jerk", jerk); });
  st_[i].staged.jerk = jerk;
  touch(i, kStagedJerk);
}

void Card::stage_ratio(std::size_t i, double ratio) {
  at(i);
  checked(i, CommandFault::IllegalControlParam,
          [&] { check_range("Card", "ratio", ratio, -16384, 16384, "GT L1043, L5020"); });
  st_[i].staged.ratio = ratio;
  touch(i, kStagedRatio);
}

void Card::stage_brk_cn(std::size_t i, double brk_cn) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow,
          [&] { check_integer("Card", "brk_cn", brk_cn, kPosMin, kPosMax, "GT L4721-4727"); });
  st_[i].staged.brk_cn = brk_cn;
  touch(i, kStagedBrkCn);
}

void Card::stage_pos_err(std::size_t i, double pos_err) {
  at(i);
  checked(i, CommandFault::IllegalControlParam,
          [&] { check_range("Card", "pos_err", pos_err, 0, 32767, "GT L5000-5012"); });
  st_[i].staged.pos_err = pos_err;
  touch(i, kStagedPosErr);
}

void Card::stage_law(std::size_t i, const LawParams& law) {
  at(i);
  checked(i, CommandFault::IllegalControlParam, [&] {
    std::visit([](const auto& p) { p.validate(); }, law);
    if (law.index() != st_[i].staged.law.index())
      throw std::invalid_argument("Card.law: " + axis_name(i) + " runs the other card family's servo law; stage " +
                                  "the same kind (GtServoLaw or ApsServoLaw)");
  });
  st_[i].staged.law = law;
  touch(i, kStagedLaw);
}

void Card::stage_smooth_stop(std::size_t i) {
  if (at(i).mode == AxisMode::Gear)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "GT_SmthStp is not valid in gear mode (GT L1144, L5096)");
  touch(i, kStagedSmoothStop);
}

void Card::stage_synch_pos(std::size_t i) {
  at(i);
  touch(i, kStagedSynchPos);
}

CommandFault Card::check_commit(std::size_t i, const AxisRegisters& r, std::uint32_t d, std::string* why) const {
  const CardAxisState& s = st_[i];
  const motion::ProfileGenerator& gen = loops_[i]->generator();
  const bool mv = gen.moving();
  auto fail = [&](CommandFault f, const std::string& w) {
    if (why) *why = w;
    return f;
  };
  if (d & kStagedSynchPos) {
    if (s.mode == AxisMode::Jog) return fail(CommandFault::ChangeInMotion, "GT_SynchPos is an error in jog mode (GT L474)");
    if (s.mode == AxisMode::Gear) return fail(CommandFault::InvalidInMode, "GT_SynchPos is invalid in gear mode (GT L1425)");
    if (mv) return fail(CommandFault::ChangeInMotion, "GT_SynchPos only at rest (GT L1425, L5154)");
  }
  if (d & kStagedMotion) {
    if (estop_) return fail(CommandFault::EmergencyStopActive, "motion refused while the emergency stop is active");
    if (mv && gen.stopping() && !(d & kStagedSmoothStop))
      return fail(CommandFault::ChangeInMotion, "motion commands wait until the smooth stop ends");
    double dir = 0.0;
    switch (s.mode) {
      case AxisMode::TCurve:
        if (!(r.vel > 0.0) || !(r.acc > 0.0))
          return fail(CommandFault::IllegalControlParam,
                      "T-curve needs vel > 0 and acc > 0 (now vel = " + format_value(r.vel) +
                          ", acc = " + format_value(r.acc) + "; GT L929-930)");
        if (mv && r.acc != s.active.acc)
          return fail(CommandFault::ChangeInMotion,
                      "the T-curve acceleration cannot change during motion (GT L974-978, GE L311)");
        dir = r.pos - gen.state().pos;
        break;
      case AxisMode::SCurve:
        if (!(r.vel > 0.0) || !(r.macc > 0.0) || !(r.jerk > 0.0))
          return fail(CommandFault::IllegalControlParam,
                      "S-curve needs vel, macc and jerk > 0 (GT L856-858)");
        if (mv && (r.vel != s.active.vel || r.macc != s.active.macc || r.jerk != s.active.jerk))
          return fail(CommandFault::ChangeInMotion,
                      "during an S-curve move only the target may change (GT L909, L474)");
        dir = r.pos - gen.state().pos;
        break;
      case AxisMode::Jog:
        if (!(r.acc > 0.0))
          return fail(CommandFault::IllegalControlParam, "jog needs acc > 0 (GT L995)");
        dir = r.vel;
        break;
      case AxisMode::Gear:
      case AxisMode::Coordinated:
      case AxisMode::Pvt:
      case AxisMode::Follow:
        return fail(CommandFault::InvalidInMode, std::string("no profile registers in ") + to_string(s.mode) + " mode");
    }
    if (!(d & kStagedSmoothStop)) {
      bool by_module = false;  // [modes] a geared slave's latched limit (GT L2213)
      for (const CardHooks* h : hooks_) by_module = by_module || h->inhibits_move(i, dir);
      if (by_module)
        return fail(CommandFault::DirectionInhibited,
                    "a gear slave of this axis is at a limit in the direction this move would drive it (GT L2213)");
      if (dir > 0.0 && inhibited_pos(i))
        return fail(CommandFault::DirectionInhibited,
                    "motion toward the positive limit is refused until the limit event is cleared (GT L2209)");
      if (dir < 0.0 && inhibited_neg(i))
        return fail(CommandFault::DirectionInhibited,
                    "motion toward the negative limit is refused until the limit event is cleared (GT L2209)");
    }
  }
  return CommandFault::None;
}

void Card::update(std::uint32_t mask) {
  const std::uint32_t all = (1u << loops_.size()) - 1u;
  mask &= all;
  if (mask == 0)
    refuse(-1, CommandFault::NoAxisInMask, "GT_MltiUpdt(0): no axis of this card in the mask (GT L460)");
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    if (!(mask & (1u << i))) continue;
    std::string why;
    const CommandFault f = check_commit(i, st_[i].staged, st_[i].dirty, &why);
    if (f == CommandFault::EmergencyStopActive) st_[i].stop_cause = StopCause::EmergencyStop;
    if (f == CommandFault::DirectionInhibited) {
      const CardAxisState& s = st_[i];
      const double dir = s.mode == AxisMode::Jog ? s.staged.vel : s.staged.pos - loops_[i]->generator().state().pos;
      const bool pos = dir > 0.0;
      const bool hard = s.limits.enabled && (s.events & event_bit(pos ? CardEvent::PosLimit : CardEvent::NegLimit));
      st_[i].stop_cause = pos ? (hard ? StopCause::PosLimit : StopCause::SoftPosLimit)
                              : (hard ? StopCause::NegLimit : StopCause::SoftNegLimit);
    }
    if (f != CommandFault::None) refuse(static_cast<int>(i), f, "update: " + why);
  }
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    if (!(mask & (1u << i))) continue;
    CardAxisState& s = st_[i];
    s.pending = s.staged;
    s.pending_dirty |= s.dirty;
    s.dirty = 0;
    s.commit_pending = true;
  }
}

void Card::commit(std::size_t i, const AxisRegisters& r, std::uint32_t d) {
  CardAxisState& s = st_[i];
  if (d == 0) return;
  const CommandFault f = check_commit(i, r, d, nullptr);
  if (f != CommandFault::None) {
    // The state changed between the Update and this tick (a limit, an e-stop): nothing is committed.
    record_fault(static_cast<int>(i), f);
    return;
  }
  MotionLoop& l = *loops_[i];
  motion::ProfileGenerator& gen = l.generator();
  if (d & kStagedLaw) {
    l.axis().set_law(r.law);
    s.active.law = r.law;
  }
  if (d & kStagedPosErr) s.active.pos_err = r.pos_err;
  if (d & kStagedBrkCn) {
    l.breakpoint().set_compare(r.brk_cn);
    s.active.brk_cn = r.brk_cn;
  }
  if (d & kStagedRatio) {
    s.active.ratio = r.ratio;
    for (CardHooks* h : hooks_) h->on_ratio(i, r.ratio);  // [modes] a geared slave takes the ratio from this tick
  }
  try {
    if (d & kStagedSynchPos) {
      const double a = std::nearbyint(l.actual_pos());
      gen.set_position(a);
      s.staged.pos = s.active.pos = a;
    }
    if (d & kStagedMotion) {
      s.active.pos = r.pos;
      s.active.vel = r.vel;
      s.active.acc = r.acc;
      s.active.macc = r.macc;
      s.active.jerk = r.jerk;
      switch (s.mode) {
        case AxisMode::TCurve: gen.move_t_curve(r.pos, {r.vel, r.acc}); break;
        case AxisMode::SCurve: gen.move_s_curve(r.pos, {r.vel, r.macc, r.jerk}); break;
        case AxisMode::Jog: gen.jog(r.vel, r.acc); break;
        default: break;
      }
      if (gen.moving()) s.stop_cause = StopCause::None;  // a new motion clears the abnormal stop (ADLINK L3652)
    }
    if (d & kStagedSmoothStop) gen.smooth_stop();
  } catch (const motion::MotionCommandRefused&) {
    record_fault(static_cast<int>(i), CommandFault::ChangeInMotion);
  } catch (const std::invalid_argument&) {
    record_fault(static_cast<int>(i), CommandFault::IllegalControlParam);
  }
}

// -- immediate commands -------------------------------------------------------------------------------------

void Card::set_mode(std::size_t i, AxisMode mode) {
  CardAxisState& s = at(i);
  if (mode != AxisMode::TCurve && mode != AxisMode::SCurve && mode != AxisMode::Jog)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode,
           std::string(to_string(mode)) + " mode is entered through Card::modes() (set_gear, set_pvt, set_follow, "
           "a coordinate system)");
  if (moving(i) && s.mode != AxisMode::Gear)
    refuse(static_cast<int>(i), CommandFault::ModeChangeInMotion,
           "the motion mode can change only when the motion has ended (GT L837, L464)");
  for (CardHooks* h : hooks_) h->leave(i);  // [modes] leaving gear / PVT / cam / a coordinate system
  s.mode = mode;
}

void Card::stop_profile(std::size_t i) {
  loops_[i]->generator().abrupt_stop();
  st_[i].was_moving = false;
  st_[i].events |= event_bit(CardEvent::MotionComplete);
}

void Card::abrupt_stop(std::size_t i) {
  at(i);
  for (CardHooks* h : hooks_) h->on_abrupt_stop(i);  // [modes] halts the gear / PVT / cam / the coordinate system
  stop_profile(i);
}

void Card::check_position_set(std::size_t i) {
  const CardAxisState& s = at(i);
  if (s.mode == AxisMode::Gear)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "ZeroPos/SetAtlPos are invalid in gear mode (GT L1421-1429)");
  if (s.mode == AxisMode::Coordinated)  // [modes] the coordinate system owns the position (V55)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "ZeroPos/SetAtlPos are invalid in a coordinate system (GT L1659)");
  if (moving(i) || loops_[i]->sequence_active())
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "ZeroPos/SetAtlPos only at rest (GT L1421, L4617)");
}

void Card::set_actual_pos(std::size_t i, double pos) {
  CardAxisState& s = at(i);
  checked(i, CommandFault::MotionParamOverflow,
          [&] { check_integer("Card", "pos", pos, -2147483648.0, 2147483647.0, "whole pulses, the 32-bit register"); });
  check_position_set(i);
  loops_[i]->set_actual_position(pos);  // actual = profile = pos (GT L4613-4622)
  s.staged.pos = s.active.pos = pos;  // target
}

void Card::zero_pos_range(std::size_t first, double count) {
  at(first);
  check_integer("Card", "count", count, 1.0, static_cast<double>(loops_.size() - first),
                "axes from `first` to the card's last");
  const std::size_t last = first + static_cast<std::size_t>(count);
  for (std::size_t i = first; i < last; ++i) check_position_set(i);  // all or nothing
  for (std::size_t i = first; i < last; ++i) set_actual_pos(i, 0.0);
}

void Card::apply_output(std::size_t i) {
  const CardAxisState& s = st_[i];
  Axis& a = loops_[i]->axis();
  a.set_servo_on(s.enabled && s.closed_loop);
  loops_[i]->set_output_add(s.enabled && !s.closed_loop, control::GtServoLaw::counts_to_volts(s.mtr_cmd));
}

void Card::axis_on(std::size_t i) {
  CardAxisState& s = at(i);
  if (s.events & event_bit(CardEvent::DriveAlarm))
    refuse(static_cast<int>(i), CommandFault::AxisOnWhileAlarm,
           "AxisOn with the drive-alarm event set: DrvRst and clear it first (GT L472, L2188-2192)");
  s.enabled = true;
  s.events |= event_bit(CardEvent::MotionComplete);  // GT L1481
  apply_output(i);
}

void Card::axis_off(std::size_t i) {
  at(i).enabled = false;
  apply_output(i);
}

void Card::drive_reset(std::size_t i) {
  if (at(i).enabled)
    refuse(static_cast<int>(i), CommandFault::DriveResetWhileEnabled,
           "DrvRst only with the drive disabled (GT L461, L3216)");
  loops_[i]->axis().clear_drive_alarm();
}

void Card::set_closed_loop(std::size_t i, bool closed) {
  at(i).closed_loop = closed;
  apply_output(i);
}

void Card::set_mtr_cmd(std::size_t i, double counts) {
  at(i);
  checked(i, CommandFault::IllegalControlParam,
          [&] { check_range("Card", "mtr_cmd", counts, -32767, 32767, "GT L4960-4966"); });
  st_[i].mtr_cmd = counts;
  apply_output(i);
}

void Card::arm_breakpoint(std::size_t i, motion::BreakKind kind) {
  CardAxisState& s = at(i);
  s.brk_deferred = false;
  if (kind != motion::BreakKind::None && s.commit_pending && (s.pending_dirty & kStagedBrkCn)) {
    s.brk_deferred = true;  // the compare value the program just updated becomes active first (V26)
    s.brk_deferred_kind = kind;
    return;
  }
  if (kind == motion::BreakKind::None) {
    loops_[i]->breakpoint().off();
  } else {
    loops_[i]->breakpoint().arm(kind);
  }
}

void Card::arm_capture(std::size_t i, CaptureTrigger trigger) {
  at(i);
  try {
    loops_[i]->capture().arm(trigger);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i),
           trigger == CaptureTrigger::Index ? CommandFault::IndexCaptureArmed : CommandFault::HomeCaptureArmed,
           e.what());
  }
}

void Card::home(std::size_t i, const motion::GtHomeParams& p) {
  at(i);
  p.validate();
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "GT_Home only at rest");
  if (estop_) refuse(static_cast<int>(i), CommandFault::EmergencyStopActive, "GT_Home refused while the e-stop is active");
  try {
    loops_[i]->home(p);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

bool Card::alarm_active(std::size_t i) const {
  const CardAxisState& s = st_[i];
  return s.alarm_enabled && (loops_[i]->axis().alarm() || s.alarm_input);
}

void Card::check_move_allowed(std::size_t i, double dir) {
  CardAxisState& s = at(i);
  const int ai = static_cast<int>(i);
  if (s.mode != AxisMode::TCurve && s.mode != AxisMode::SCurve && s.mode != AxisMode::Jog)
    refuse(ai, CommandFault::InvalidInMode, std::string("no point-to-point or velocity move in ") + to_string(s.mode) + " mode");
  if (loops_[i]->sequence_active()) refuse(ai, CommandFault::ChangeInMotion, "a homing sequence runs");
  if (estop_) {
    s.stop_cause = StopCause::EmergencyStop;
    refuse(ai, CommandFault::EmergencyStopActive, "motion ignored while the emergency stop is active (ADLINK L3936)");
  }
  if (alarm_active(i)) {
    s.stop_cause = StopCause::DriveAlarm;
    refuse(ai, CommandFault::DriveAlarmActive, "motion ignored while the alarm input is active (ADLINK L3953)");
  }
  if (dir > 0.0 && inhibited_pos(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::PosLimit));
    s.stop_cause = hard ? StopCause::PosLimit : StopCause::SoftPosLimit;
    refuse(ai, CommandFault::DirectionInhibited, "positive motion ignored while the positive limit is active (ADLINK L3971, L4007)");
  }
  if (dir < 0.0 && inhibited_neg(i)) {
    const bool hard = s.limits.enabled && (s.events & event_bit(CardEvent::NegLimit));
    s.stop_cause = hard ? StopCause::NegLimit : StopCause::SoftNegLimit;
    refuse(ai, CommandFault::DirectionInhibited, "negative motion ignored while the negative limit is active (ADLINK L3973, L4009)");
  }
}

void Card::move_ptp(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { p.validate(); });
  check_move_allowed(i, p.pos - loops_[i]->generator().state().pos);
  start_ptp(i, p);
}

void Card::start_ptp(std::size_t i, const motion::AdlinkPtpParams& p) {
  motion::ProfileGenerator& gen = loops_[i]->generator();
  const double start = gen.state().pos;
  const bool was_ptp = st_[i].ptp_active && gen.moving();
  try {
    gen.move_adlink_ptp(p.pos, p.limits(period_s_));
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  } catch (const std::invalid_argument& e) {
    refuse(static_cast<int>(i), CommandFault::DistanceTooShort, e.what());
  }
  CardAxisState& s = st_[i];
  s.staged.pos = s.active.pos = p.pos;
  s.wait_trigger = false;
  if (gen.moving()) {
    s.stop_cause = StopCause::None;
    // PRED/POSTD are cleared when the axis starts moving (L3661-3662); an on-the-fly change keeps the start.
    if (!was_ptp) {
      s.move_start = start;
      s.pre_event = s.post_event = false;
    }
    s.ptp_active = true;
    s.move_target = p.pos;
  }
}

void Card::move_velocity(std::size_t i, double vel_pulse_per_s, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] {
    p.validate();
    check_range("Card", "vel_pulse_per_s", vel_pulse_per_s, -p.vm, p.vm, "-PRA_VM..PRA_VM, pulse/s");
  });
  check_move_allowed(i, vel_pulse_per_s);
  motion::ProfileGenerator& gen = loops_[i]->generator();
  try {
    gen.move_adlink_velocity(vel_pulse_per_s * period_s_, p.limits(period_s_));
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
  if (gen.moving()) {
    st_[i].stop_cause = StopCause::None;
    st_[i].ptp_active = false;
    st_[i].pre_event = st_[i].post_event = false;
  }
}

void Card::stop_move(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { p.validate(); });
  st_[i].wait_trigger = false;
  // A homing or jog sequence ends; the axis decelerates at PRA_SD_DEC like any other move (L2570-2574).
  if (loops_[i]->sequence_active()) loops_[i]->cancel_sequence();
  loops_[i]->generator().adlink_stop_move(p);
}

// -- ADLINK sequences and synchronous start ------------------------------------------------------------------

void Card::home(std::size_t i, const motion::AdlinkHomeParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { p.validate(); });
  if (st_[i].mode == AxisMode::Gear || st_[i].mode == AxisMode::Coordinated)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "APS_home_move: not in gear or coordinated mode");
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "APS_home_move only at rest (L2706-2708)");
  check_move_allowed(i, 0.0);
  try {
    loops_[i]->home(p);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
  CardAxisState& s = st_[i];
  s.stop_cause = StopCause::None;
  s.ptp_active = false;
  s.pre_event = s.post_event = false;
}

void Card::jog(std::size_t i, const motion::AdlinkJogParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { p.validate(); });
  if (st_[i].mode == AxisMode::Gear || st_[i].mode == AxisMode::Coordinated)
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "jog: not in gear or coordinated mode");
  try {
    loops_[i]->jog(p);
  } catch (const motion::MotionCommandRefused& e) {
    refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

void Card::set_jog_on(std::size_t i, bool on) {
  at(i);
  MotionLoop& l = *loops_[i];
  if (!l.jogger())
    refuse(static_cast<int>(i), CommandFault::InvalidInMode, "JOG-ON: no jog parameters installed (jog() first)");
  if (on && !l.jog_on()) {
    check_move_allowed(i, l.jogger()->params().dir >= 0.5 ? 1.0 : -1.0);
    CardAxisState& s = st_[i];
    s.stop_cause = StopCause::None;
    s.ptp_active = false;
    s.pre_event = s.post_event = false;
  }
  l.set_jog_on(on);
}

bool Card::jogging(std::size_t i) const {
  const MotionLoop& l = loop(i);
  return l.jogger() && (l.jog_on() || l.jogger()->phase() != motion::JogPhase::Idle);
}

void Card::move_ptp_wait(std::size_t i, const motion::AdlinkPtpParams& p) {
  at(i);
  checked(i, CommandFault::MotionParamOverflow, [&] { p.validate(); });
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "a move waiting for the trigger only at rest");
  check_move_allowed(i, p.pos - loops_[i]->generator().state().pos);
  st_[i].waiting = p;
  st_[i].wait_trigger = true;
}

void Card::move_trigger(std::uint32_t mask) {
  const auto n = st_.size();
  if (mask == 0 || (n < 32 && (mask >> n) != 0))
    throw_invalid("Card", "mask", static_cast<double>(mask), "must name axes of this card (bit k = axis k)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(mask & (1u << i)) || !st_[i].wait_trigger) continue;
    const motion::AdlinkPtpParams p = st_[i].waiting;
    st_[i].wait_trigger = false;
    // Conditions may have changed while waiting (a limit, the e-stop): such an axis is ignored (stop code).
    try {
      check_move_allowed(i, p.pos - loops_[i]->generator().state().pos);
      start_ptp(i, p);
    } catch (const CardCommandRefused&) {
    }
  }
}

void Card::set_limit_stop_mode(std::size_t i, bool decelerate, double dec_pulse_per_s2) {
  at(i);
  check_range("Card", "dec_pulse_per_s2", dec_pulse_per_s2, 1e-9, 1e12, "PRA_SD_DEC, pulse/s^2");
  st_[i].limit_decelerate = decelerate;
  st_[i].limit_dec = dec_pulse_per_s2;
}

void Card::set_move_event_distances(std::size_t i, double pre_pulse, double post_pulse) {
  at(i);
  check_range("Card", "pre_pulse", pre_pulse, 0.0, 2147483647.0, "PRA_PRE_EVENT_DIST, pulse");
  check_range("Card", "post_pulse", post_pulse, 0.0, 2147483647.0, "PRA_POST_EVENT_DIST, pulse");
  st_[i].pre_event_dist = pre_pulse;
  st_[i].post_event_dist = post_pulse;
}

void Card::limit_stop(std::size_t i, StopCause cause) {
  CardAxisState& s = st_[i];
  if (!s.limit_decelerate) {
    fault_stop(i, cause, false);
    return;
  }
  // PRA_EL_MODE 1: a decelerating stop at PRA_SD_DEC, issued once; the axis passes the limit while stopping.
  s.stop_cause = cause;
  if (s.limit_stopping) return;
  s.limit_stopping = true;
  loops_[i]->cancel_sequence();
  loops_[i]->generator().smooth_stop_with(s.limit_dec * period_s_ * period_s_, std::numeric_limits<double>::infinity());
}

void Card::set_in_position_band(std::size_t i, double pulse) {
  at(i);
  check_nonnegative("Card", "in_position_pulse", pulse);
  st_[i].in_position_pulse = pulse;
}

bool Card::in_position(std::size_t i) const {
  const CardAxisState& s = state(i);
  return s.enabled && !moving(i) && std::fabs(s.error_pulse) <= s.in_position_pulse;
}

void Card::set_limits(std::size_t i, const LimitConfig& limits) {
  at(i);
  limits.validate();
  st_[i].limits = limits;
}

void Card::set_error_level(std::size_t i, double pulse) {
  at(i);
  check_nonnegative("Card", "error_level_pulse", pulse);
  st_[i].error_level_pulse = pulse;
}

void Card::clear_events(std::size_t i, std::uint32_t which) {
  CardAxisState& s = at(i);
  which &= kAllEvents;
  if (s.following_error_now) which &= ~event_bit(CardEvent::FollowingError);  // GT L1453
  s.events &= ~which;
  if (which & event_bit(CardEvent::Breakpoint)) loops_[i]->clear_breakpoint_flag();
  if (which & event_bit(CardEvent::Captured)) loops_[i]->capture().clear();
}

// -- GE additions -------------------------------------------------------------------------------------------

void Card::smooth_stop(std::size_t i) {
  at(i);
  if (loops_[i]->sequence_active()) {
    loops_[i]->cancel_sequence();
    stop_profile(i);
    return;
  }
  if (loops_[i]->generator().moving()) loops_[i]->generator().smooth_stop();
}

void Card::arm_probe() {
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    const CaptureUnit& c = loops_[i]->capture();
    if (c.armed() != CaptureTrigger::None || c.captured())
      refuse(static_cast<int>(i), CommandFault::HomeCaptureArmed,
             "GT_CaptProb: the capture is armed or still flags a capture; GT_ClrSts first (GE L2334-2336)");
  }
  for (auto& l : loops_) l->capture().arm(CaptureTrigger::Probe);
}

void Card::synch_pos_now(std::size_t i) {
  CardAxisState& s = at(i);
  if (moving(i)) refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "synchronise the profile only at rest");
  const double a = std::nearbyint(loops_[i]->actual_pos());
  loops_[i]->generator().set_position(a);
  s.staged.pos = s.active.pos = a;
}

// -- readbacks ----------------------------------------------------------------------------------------------

bool Card::moving(std::size_t i) const {
  const MotionLoop& l = loop(i);
  for (const CardHooks* h : hooks_)  // [modes] a halted gear / a PVT or cam axis: the mode says
    if (const std::optional<bool> m = h->moving(i)) return *m || l.generator().moving();
  return state(i).mode == AxisMode::Gear || l.generator().moving() || l.sequence_active();
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

// -- the tick -----------------------------------------------------------------------------------------------

void Card::fault_stop(std::size_t i, StopCause cause, bool servo_off) {
  CardAxisState& s = st_[i];
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
  // Direction inhibit: motion toward a latched limit stops at once (GT L2206-2209), or decelerates with
  // PRA_EL_MODE 1. An ADLINK homing sequence meets the limits itself (it reverses or stops at them, L2341-2508).
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
  // Position-error protection (ADLINK PRA_ERR_POS_LEVEL, L4012-4023): servo off.
  if (s.error_level_pulse > 0.0 && s.enabled && s.closed_loop && !(std::fabs(error) <= s.error_level_pulse)) {
    s.events |= event_bit(CardEvent::ErrorLevel);
    fault_stop(i, StopCause::ErrorLevel, true);
  }
  if (l.breakpoint_flag()) s.events |= event_bit(CardEvent::Breakpoint);
  if (l.capture().captured()) s.events |= event_bit(CardEvent::Captured);
  const bool mv = l.generator().moving();
  const double v = l.generator().state().vel;
  if (v > 0.0) s.dir_positive = true;
  if (v < 0.0) s.dir_positive = false;
  if (s.was_moving && !mv) s.events |= event_bit(CardEvent::MotionComplete);
  s.was_moving = mv;
  if (!mv) s.limit_stopping = false;
  // ADLINK pre/post-distance events of a point-to-point move (L3284-3292).
  if (s.ptp_active) {
    const double p = l.generator().state().pos;
    if (s.pre_event_dist > 0.0 && std::fabs(p - s.move_start) > s.pre_event_dist) s.pre_event = true;
    if (s.post_event_dist > 0.0 && std::fabs(s.move_target - p) < s.post_event_dist) s.post_event = true;
    if (!mv) s.ptp_active = false;
  }
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
    if (!s.fired().empty()) break;
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
