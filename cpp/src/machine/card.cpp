// The card kernel: construction, modules and kernel services, reset, faults, readbacks (machine/card.hpp).
// The staged registers: card_registers.cpp; the immediate commands: card_commands.cpp; the tick: card_tick.cpp.
#include "servobench/machine/card.hpp"

#include <set>
#include <stdexcept>
#include <string>

#include "card_detail.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/machine/card_scope.hpp"

namespace servobench::machine {

using detail::axis_name;

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

void Card::touch(std::size_t i, std::uint32_t bits) { st_[i].dirty |= bits; }

// -- readbacks ----------------------------------------------------------------------------------------------

bool Card::moving(std::size_t i) const {
  const MotionLoop& l = loop(i);
  for (const CardHooks* h : hooks_)  // [modes] a halted gear / a PVT or cam axis: the mode says
    if (const std::optional<bool> m = h->moving(i)) return *m || l.generator().moving();
  return state(i).mode == AxisMode::Gear || l.generator().moving() || l.sequence_active();
}

}  // namespace servobench::machine
