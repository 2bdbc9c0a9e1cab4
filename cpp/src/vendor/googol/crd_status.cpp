#include "servobench/vendor/googol/crd_status.hpp"

#include "servobench/machine/card_modes.hpp"

namespace servobench::vendor::googol {

using namespace machine;  // the kernel's types: Card, CardEvent, CommandFault, StopCause ...

std::uint16_t gt_crd_status(const CrdStatusInputs& in) {
  std::uint32_t w = 0;
  if (!in.moving) w |= 1u << 0;
  if (in.buffer_closed) w |= 1u << 1;
  if (in.last_command_error) w |= 1u << 3;
  if (in.segment_complete) w |= 1u << 4;
  if (in.acc_limit_alarm) w |= 1u << 5;
  if (in.auto_stop_on) w |= 1u << 6;
  if (in.immediate_mode) w |= 1u << 7;
  if (in.fault_stopped) w |= 1u << 9;
  if (in.buffer_started && in.buffer_empty) w |= 1u << 13;
  return static_cast<std::uint16_t>(w);
}

std::uint16_t ge_crd_status(const CrdStatusInputs& in) {
  std::uint32_t w = 0;
  if (!in.moving) w |= 1u << 0;
  if (in.buffer_closed) w |= 1u << 1;
  if (in.segment_complete) w |= 1u << 4;
  if (in.immediate_mode) w |= 1u << 7;
  if (in.fault_stopped) w |= 1u << 9;
  if (in.buffer_empty) w |= 1u << 13;
  return static_cast<std::uint16_t>(w);
}

GucCrdStatus guc_crd_status(const motion::PathGenerator& fifo) {
  GucCrdStatus s;
  s.run = fifo.running() || fifo.busy() ? 1 : 0;
  s.segment = fifo.state().segments_done;
  return s;
}

GucCrdStatus guc_crd_status(Card& card, int crd, int fifo) { return guc_crd_status(card.modes().crd(crd).fifo(fifo)); }

}  // namespace servobench::vendor::googol
