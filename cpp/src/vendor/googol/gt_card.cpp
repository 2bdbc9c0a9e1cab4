// GtCard: the GT registers the kernel does not hold (vendor/googol/gt_card.hpp).
#include "servobench/vendor/googol/gt_card.hpp"

#include <cmath>
#include <stdexcept>

#include "servobench/machine/capture.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/home_sequence.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::vendor::googol {

using machine::CommandFault;

GtCard::GtCard(machine::Card& card) : card_(card), crd_(*this), intr_(*this), aux_(card) {
  if (card.axis_count() != 4)
    throw std::invalid_argument("a GT card has 4 axes (GT L752-756)");
}

GtCard& gt(machine::Card& card) { return card.module<GtCard>(); }

GtCode GtCard::check(double value, double lo, double hi, GtArg kind, CommandFault fault) {
  bool ok = std::isfinite(value) && lo <= value && (kind == GtArg::RealHalfOpen ? value < hi : value <= hi);
  if (ok && kind == GtArg::Integer) ok = value == std::floor(value);
  if (ok) return GtCode::Success;
  card_.record_fault(static_cast<int>(axis_), fault);
  return GtCode::ParameterError;
}

GtCode GtCard::run(const std::function<void()>& command) {
  try {
    command();
  } catch (const motion::MotionCommandRefused&) {  // the card recorded why (command status)
    return GtCode::CommandError;
  } catch (const std::invalid_argument&) {
    return GtCode::ParameterError;
  }
  return GtCode::Success;
}

GtCode GtCard::refuse(CommandFault fault) {
  card_.record_fault(static_cast<int>(axis_), fault);
  return GtCode::CommandError;
}

GtCode GtCard::select_axis(double num) {
  if (GtCode c = check(num, 1, 4); c != GtCode::Success) return c;
  axis_ = static_cast<std::size_t>(num) - 1;
  return GtCode::Success;
}

GtCode GtCard::select_interrupting_axis() {
  const auto k = intr_.pending_axis();
  if (!k) return refuse(CommandFault::NoInterruptPending);
  axis_ = *k;
  return GtCode::Success;
}

GtCode GtCard::set_limit_sense(double sense) {
  if (GtCode c = check(sense, 0, 0xFFFF); c != GtCode::Success) return c;
  const int s = static_cast<int>(sense);
  for (std::size_t k = 0; k < 4; ++k) {
    machine::LimitConfig lim = card_.state(k).limits;
    lim.pos_active_low = (s >> (2 * k)) & 1;
    lim.neg_active_low = (s >> (2 * k + 1)) & 1;
    card_.set_limits(k, lim);
  }
  lmt_sns_ = s;
  return GtCode::Success;
}

int GtCard::limit_switches() const {
  int w = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const machine::LimitConfig& lim = card_.state(k).limits;
    w |= static_cast<int>(card_.pos_limit_input(k) != lim.pos_active_low) << (2 * k);
    w |= static_cast<int>(card_.neg_limit_input(k) != lim.neg_active_low) << (2 * k + 1);
  }
  return w;
}

GtCode GtCard::set_index(double value) {
  if (value != 0.0 && value != 1.0) {
    card_.record_fault(static_cast<int>(axis_), CommandFault::IllegalControlParam);
    return GtCode::ParameterError;
  }
  index_[axis_] = static_cast<int>(value);
  return GtCode::Success;
}

int GtCard::index(std::size_t i) const {
  card_.check_axis(i);
  return index_[i];
}

GtCode GtCard::home(double pos) {
  if (GtCode c = check(pos, -1073741824.0, 1073741823.0, GtArg::Integer, CommandFault::MotionParamOverflow);
      c != GtCode::Success)
    return c;
  const machine::AxisRegisters& reg = card_.state(axis_).staged;
  if (!(reg.vel > 0 && reg.acc > 0)) return refuse(CommandFault::IllegalControlParam);
  motion::GtHomeParams p;
  p.pos = pos;
  p.vel = reg.vel;
  p.acc = reg.acc;
  p.index = index_[axis_] != 0;
  p.zero = false;
  return run([&] { card_.home(axis_, p); });
}

std::uint16_t GtCard::command_status() const {
  if (card_.last_fault() == CommandFault::CrdStateError) return crd_.command_status_bit();  // 12, 13 or 15 (V127)
  return gt_command_status(card_);
}

GtCode GtCard::capture_probe() {
  std::vector<std::size_t> free;
  for (std::size_t k = 0; k < 4; ++k)
    if (card_.loop(k).capture().armed() == machine::CaptureTrigger::None &&
        !(card_.events(k) & (1u << static_cast<int>(machine::CardEvent::Captured))))
      free.push_back(k);
  if (free.empty()) return refuse(CommandFault::HomeCaptureArmed);
  return run([&] {
    for (std::size_t k : free) card_.arm_capture(k, machine::CaptureTrigger::Probe);
  });
}

GtCode GtCard::set_encoder_sense(double sense, const AuxInputs& in) {
  if (GtCode c = check(sense, 0, 0x3F); c != GtCode::Success) return c;
  const int s = static_cast<int>(sense);
  if ((s ^ in.reversed) & 0xF) return refuse(CommandFault::NotSimulated);
  aux_.keep_position_on_sense(sys_.enc_sns, s, in);
  sys_.enc_sns = s;
  return GtCode::Success;
}

std::pair<GtCode, long long> GtCard::aux_position(double num, const AuxInputs& in) {
  if (GtCode c = check(num, 1, 2); c != GtCode::Success) return {c, 0};
  return {GtCode::Success, aux_.position(static_cast<int>(num) - 1, sys_.enc_sns, in)};
}

std::pair<GtCode, double> GtCard::aux_velocity(double num, const AuxInputs& in) {
  if (GtCode c = check(num, 1, 2); c != GtCode::Success) return {c, 0.0};
  return {GtCode::Success, aux_.velocity(static_cast<int>(num) - 1, sys_.enc_sns, in)};
}

GtCode GtCard::clear_aux_position(double num, const AuxInputs& in) {
  if (!(num == 1.0 || num == 2.0)) return GtCode::CommError;
  aux_.clear(static_cast<int>(num) - 1, sys_.enc_sns, in);
  return GtCode::Success;
}

GtCode GtCard::arm_aux_capture(const AuxInputs& in) {
  aux_.arm_capture(in);
  return GtCode::Success;
}

GtCode GtCard::hard_reset() {
  lmt_sns_ = 0;
  index_ = {};
  crd_.reset();
  intr_.reset();
  if (intr_.resubscribe) intr_.resubscribe();
  sys_.enc_sns = 0;
  sys_.step_pulse = {};
  sys_.adc_chn = 8;
  return run([&] { card_.reset(); });
}

}  // namespace servobench::vendor::googol
