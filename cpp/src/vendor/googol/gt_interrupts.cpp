// GtInterrupts: the GT interrupt registers and their request / service machine (vendor/googol/gt_interrupts.hpp).
#include "servobench/vendor/googol/gt_interrupts.hpp"

#include "servobench/vendor/googol/gt_card.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::vendor::googol {

using machine::CommandFault;

GtCode GtInterrupts::event_mode() {
  r_.mode = GtInterruptMode::Event;
  r_.pending = false;
  if (resubscribe) resubscribe();
  return GtCode::Success;
}

GtCode GtInterrupts::timer_mode() {
  r_.mode = GtInterruptMode::Timer;
  r_.pending = false;
  if (resubscribe) resubscribe();
  return GtCode::Success;
}

GtCode GtInterrupts::set_timer(double periods) {
  if (GtCode c = gt_.check(periods, 0, 32767); c != GtCode::Success) return c;
  r_.timer = static_cast<int>(periods);
  if (resubscribe) resubscribe();
  return GtCode::Success;
}

GtCode GtInterrupts::set_mask(double mask) {
  if (GtCode c = gt_.check(mask, 0, 0xFFFF); c != GtCode::Success) return c;
  r_.mask[gt_.axis()] = static_cast<int>(mask) & 0x7F;
  if (resubscribe) resubscribe();
  request();  // a status bit already set interrupts at once
  return GtCode::Success;
}

int GtInterrupts::mask_of_current_axis() const { return r_.mask[gt_.axis()]; }

std::uint16_t GtInterrupts::status() const {
  if (r_.mode == GtInterruptMode::Timer) return 0;
  return gt_axis_status(gt_.card(), r_.pending ? r_.axis : gt_.axis());
}

std::optional<std::size_t> GtInterrupts::pending_axis() const {
  if (!r_.pending || r_.mode != GtInterruptMode::Event) return std::nullopt;
  return r_.axis;
}

GtCode GtInterrupts::reset_request(double mask) {
  if (GtCode c = gt_.check(mask, 0, 0xFFFF); c != GtCode::Success) return c;
  if (!pending_axis()) return gt_.refuse(CommandFault::NoInterruptPending);
  gt_.card().clear_events(gt_.axis(), gt_events_to_clear(static_cast<std::uint16_t>(static_cast<int>(mask) & 0xFF)));
  r_.pending = false;
  if (r_.in_isr)
    r_.recheck = true;
  else
    request();
  return GtCode::Success;
}

GtCode GtInterrupts::clear(double card_no) {
  if (card_no != 0.0) return GtCode::ParameterError;
  if (r_.mode == GtInterruptMode::Timer) r_.pending = false;
  return GtCode::Success;
}

std::array<int, 4> GtInterrupts::watched_bits() const {
  if (r_.mode == GtInterruptMode::Timer) return {};
  return r_.mask;
}

std::optional<std::size_t> GtInterrupts::level() const {
  const machine::Card& card = gt_.card();
  for (std::size_t k = 0; k < 4; ++k) {
    int bits = gt_axis_status(card, k) & r_.mask[k] & 0x7F;
    if (!card.servo_on(k)) bits &= kDisabledAxisBits;
    if (bits) return k;
  }
  return std::nullopt;
}

void GtInterrupts::call_isr() {
  r_.in_isr = true;
  try {
    isr();
  } catch (...) {
    r_.in_isr = false;
    throw;
  }
  r_.in_isr = false;
}

void GtInterrupts::request() {
  if (r_.mode != GtInterruptMode::Event || r_.pending || r_.in_isr) return;
  while (true) {
    const auto k = level();
    if (!k) return;
    const long long tick = gt_.card().tick();
    r_.storm_count = r_.storm_tick == tick ? r_.storm_count + 1 : 1;
    r_.storm_tick = tick;
    r_.pending = true;
    r_.axis = *k;
    if (sync) sync();  // the driver's ISR signals the program's event (L2338)
    if (!isr || r_.storm_count > kRefireLimit) return;
    call_isr();
    const bool again = r_.recheck && !r_.pending;
    r_.recheck = false;
    if (!again) return;
  }
}

void GtInterrupts::timer() {
  r_.pending = true;
  if (sync) sync();
  if (isr && !r_.in_isr) call_isr();
}

}  // namespace servobench::vendor::googol
