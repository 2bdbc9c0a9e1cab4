#include "servobench/vendor/googol/ge_registers.hpp"

#include <cmath>
#include <variant>

#include "servobench/machine/axis.hpp"
#include "servobench/machine/powertrain.hpp"

namespace servobench::vendor::googol {

using machine::CommandFault;

namespace {

bool int_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi && v == std::floor(v); }

int order_of(GeMotionRegister r) { return r == GeMotionRegister::Vel ? 1 : r == GeMotionRegister::Jerk ? 3 : 2; }

double staged_value(const machine::AxisRegisters& s, GeMotionRegister r) {
  switch (r) {
    case GeMotionRegister::Vel: return s.vel;
    case GeMotionRegister::Acc: return s.acc;
    case GeMotionRegister::MAcc: return s.macc;
    case GeMotionRegister::Jerk: return s.jerk;
  }
  return 0.0;
}

}  // namespace

GeRegisters::GeRegisters(machine::Card& card) : card_(card), watch_(card) { reset(); }

void GeRegisters::reset() {
  axes_.assign(card_.axis_count(), GeAxisRegisters{});
  for (auto& w : sense_) w = 0;
  inputs_ = 0;
  adc_channels_ = 8;
  written_.clear();
  watch_.reset();
}

std::optional<std::size_t> GeRegisters::axis(double number) {
  if (int_in(number, 1, static_cast<double>(card_.axis_count()))) return static_cast<std::size_t>(number) - 1;
  card_.record_fault(-1, CommandFault::IllegalControlParam);
  return std::nullopt;
}

GeCode GeRegisters::set_sense(GeSense which, double word) {
  if (!int_in(word, 0, 0xFFFF)) {
    card_.record_fault(-1, CommandFault::IllegalControlParam);
    return GeCode::ParameterError;
  }
  const auto w = static_cast<std::uint32_t>(word);
  if (which == GeSense::Limit) {
    for (std::size_t k = 0; k < card_.axis_count(); ++k) {
      machine::LimitConfig lim = card_.state(k).limits;
      lim.pos_active_low = (w >> (2 * k)) & 1u;
      lim.neg_active_low = (w >> (2 * k + 1)) & 1u;
      card_.set_limits(k, lim);
    }
  } else if (w & ((1u << card_.axis_count()) - 1u)) {
    card_.record_fault(-1, CommandFault::NotSimulated);  // only the simulated edge / direction (V93)
    return GeCode::CommandError;
  }
  sense_[static_cast<int>(which)] = w;
  return GeCode::Success;
}

GeCode GeRegisters::set_encoder(double number, bool on) {
  const auto a = axis(number);
  if (!a) return GeCode::ParameterError;
  if (card_.servo_on(*a)) {
    card_.record_fault(static_cast<int>(*a), CommandFault::MotorStateWhileEnabled);
    return GeCode::CommandError;
  }
  axes_[*a].encoder_on = on;
  return GeCode::Success;
}

GeCode GeRegisters::set_ctrl_mode(double number, double mode) {
  const auto a = axis(number);
  if (!a) return GeCode::ParameterError;
  const int i = static_cast<int>(*a);
  if (mode != 0 && mode != 1) {
    card_.record_fault(i, CommandFault::IllegalControlParam);
    return GeCode::ParameterError;
  }
  if (card_.servo_on(*a)) {
    card_.record_fault(i, CommandFault::AxisStateError);
    return GeCode::CommandError;
  }
  const auto& drive = card_.axis(*a).config().drive;
  const bool pulse = std::holds_alternative<drive::StepperDriveParams>(drive) ||
                     std::holds_alternative<drive::ServoPositionDriveParams>(drive);
  if ((mode == 1) != pulse) {
    card_.record_fault(i, CommandFault::NotSimulated);
    return GeCode::CommandError;
  }
  axes_[*a].ctrl_mode = static_cast<int>(mode);
  return GeCode::Success;
}

GeCode GeRegisters::set_step_form(double number, bool pulse) {
  const auto a = axis(number);
  if (!a) return GeCode::ParameterError;
  if (axes_[*a].ctrl_mode != 1) {
    card_.record_fault(static_cast<int>(*a), CommandFault::AxisStateError);
    return GeCode::CommandError;
  }
  axes_[*a].step_pulse = pulse;
  return GeCode::Success;
}

bool GeRegisters::refuse_on_pulse_axis(std::size_t a) {
  if (axes_.at(a).ctrl_mode != 1) return false;
  card_.record_fault(static_cast<int>(a), CommandFault::AxisStateError);
  return true;
}

GeCode GeRegisters::set_adc_channels(double n) {
  if (!int_in(n, 1, 8)) {
    card_.record_fault(-1, CommandFault::IllegalControlParam);
    return GeCode::ParameterError;
  }
  adc_channels_ = static_cast<int>(n);
  return GeCode::Success;
}

void GeRegisters::stage_motion(std::size_t a, GeMotionRegister r, double value, double ms_per_tick) {
  const double per_tick = value * std::pow(ms_per_tick, order_of(r));
  switch (r) {
    case GeMotionRegister::Vel: card_.stage_vel(a, per_tick); break;
    case GeMotionRegister::Acc: card_.stage_acc(a, per_tick); break;
    case GeMotionRegister::MAcc: card_.stage_macc(a, per_tick); break;
    case GeMotionRegister::Jerk: card_.stage_jerk(a, per_tick); break;
  }
  written_[{a, static_cast<int>(r)}] = {value, per_tick};
}

double GeRegisters::read_motion(std::size_t a, GeMotionRegister r, double ms_per_tick) const {
  const double per_tick = staged_value(card_.state(a).staged, r);
  const auto it = written_.find({a, static_cast<int>(r)});
  if (it != written_.end() && it->second.second == per_tick) return it->second.first;
  return per_tick / std::pow(ms_per_tick, order_of(r));
}

std::uint32_t GeRegisters::limit_levels() const {
  std::uint32_t w = 0;
  for (std::size_t k = 0; k < card_.axis_count(); ++k) {
    const machine::LimitConfig& lim = card_.state(k).limits;
    w |= static_cast<std::uint32_t>(card_.pos_limit_input(k) != lim.pos_active_low) << (2 * k);
    w |= static_cast<std::uint32_t>(card_.neg_limit_input(k) != lim.neg_active_low) << (2 * k + 1);
  }
  return w;
}

std::uint32_t GeRegisters::home_levels() {
  std::uint32_t w = 0;
  for (std::size_t k = 0; k < card_.axis_count(); ++k) {
    const machine::Axis& ax = card_.axis(k);
    const plant::SwitchParams& sw = ax.config().switches;
    const double angle = ax.load_angle_rad();
    w |= static_cast<std::uint32_t>(sw.home_min_rad <= angle && angle <= sw.home_max_rad) << k;
  }
  return w;
}

double GeRegisters::actual_vel(std::size_t a) {
  const machine::Axis& ax = card_.axis(a);
  const auto& enc = ax.config().encoder;
  const double speed = enc.on_load ? ax.load_speed_rad_s() : ax.speed_rad_s();
  return speed * enc.counts_per_rev / (2 * M_PI) * 1e-3;
}

GeRegisters& ge_registers(machine::Card& card) { return card.module<GeRegisters>(); }

}  // namespace servobench::vendor::googol
