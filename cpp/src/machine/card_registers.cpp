// The card kernel's staged (double-buffered) registers: stage_*, the checks of an update, update and commit
// (GT Table 4-10, L1156-1180; machine/card.hpp).
#include "servobench/machine/card.hpp"

#include <cmath>
#include <string>

#include "card_detail.hpp"
#include "servobench/common/validate.hpp"

namespace servobench::machine {

using detail::axis_name;
using detail::kPosMin;
using detail::kPosMax;

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

}  // namespace servobench::machine
