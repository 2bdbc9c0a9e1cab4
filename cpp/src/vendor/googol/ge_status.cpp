#include "servobench/vendor/googol/ge_status.hpp"
#include "servobench/vendor/googol/ge_list.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::vendor::googol {

using namespace machine;  // the kernel's types: Card, CardEvent, CommandFault, StopCause ...

namespace {

// The bits both variants share (Tables 4-2 and 4-3): events 1, 3-6, state 9-11, capture armed 14-15.
std::uint32_t common_bits(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  std::uint32_t w = 0;
  if (s.events & event_bit(CardEvent::DriveAlarm)) w |= 1u << 1;
  if (s.events & event_bit(CardEvent::Captured)) w |= 1u << 3;
  if (s.events & event_bit(CardEvent::FollowingError)) w |= 1u << 4;
  if (s.events & (event_bit(CardEvent::PosLimit) | event_bit(CardEvent::SoftPosLimit))) w |= 1u << 5;
  if (s.events & (event_bit(CardEvent::NegLimit) | event_bit(CardEvent::SoftNegLimit))) w |= 1u << 6;
  if (s.enabled) w |= 1u << 9;
  // Bit 10: the planner has a motion to plan (L871): moving, or an Update/MltiUpdt carrying motion registers
  // waits for its commit at the next tick (V34), so a host polling right after GT_Update sees the motion.
  if (card.moving(axis) || (s.commit_pending && (s.pending_dirty & kStagedMotion))) w |= 1u << 10;
  if (s.limits.enabled) w |= 1u << 11;
  const CaptureTrigger armed = card.loop(axis).capture().armed();
  if (armed == CaptureTrigger::Home) w |= 1u << 14;
  if (armed == CaptureTrigger::Index) w |= 1u << 15;
  return w;
}

}  // namespace

std::uint32_t ge_px_axis_status(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  std::uint32_t w = common_bits(card, axis);
  if (s.events & event_bit(CardEvent::CommandError)) w |= 1u << 7;
  if (s.closed_loop) w |= 1u << 8;
  if (s.encoder_fault) w |= 1u << 27;
  w |= static_cast<std::uint32_t>(axis & 7u) << 28;
  return w;
}

std::uint16_t ge_sx_axis_status(const Card& card, std::size_t axis) {
  std::uint32_t w = common_bits(card, axis);
  w |= static_cast<std::uint32_t>(axis & 3u) << 12;
  return static_cast<std::uint16_t>(w);
}

std::uint16_t ge_mode_register(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  std::uint32_t w = 0;
  if (s.auto_stop) w |= 1u << 7;
  switch (s.mode) {
    case AxisMode::TCurve: break;                     // 000
    case AxisMode::Jog: w |= 1u << 11; break;         // 001 velocity
    case AxisMode::SCurve: w |= 1u << 12; break;      // 010
    case AxisMode::Gear:                              // not GE modes: the dialect never selects them
    case AxisMode::Coordinated:
    case AxisMode::Pvt:
    case AxisMode::Follow: break;
  }
  return static_cast<std::uint16_t>(w);
}

std::uint16_t ge_command_status_bit(GeVariant variant, CommandFault fault) {
  const bool px = variant == GeVariant::PX;
  switch (fault) {
    case CommandFault::MotionParamOverflow: return px ? (1u << 0) : (1u << 1);  // SX has no bit 0: illegal (bit 1)
    case CommandFault::IllegalControlParam: return 1u << 1;
    case CommandFault::NoAxisInMask: return 1u << 2;
    case CommandFault::DriveResetWhileEnabled: return 1u << 3;
    case CommandFault::MotorStateWhileEnabled: return px ? 0 : (1u << 3);
    case CommandFault::IndexCaptureArmed:
    case CommandFault::HomeCaptureArmed: return 1u << 5;
    case CommandFault::ModeChangeInMotion: return px ? (1u << 6) : 0;
    case CommandFault::AxisStateError: return px ? 0 : (1u << 6);
    case CommandFault::AxisOnWhileAlarm: return px ? (1u << 9) : (1u << 3);
    case CommandFault::ChangeInMotion: return 1u << 11;
    case CommandFault::NotInCommandSet: return px ? 0 : (1u << 14);
    case CommandFault::CrdStateError: return px ? 0 : (1u << 8);  // SX path-command error (Table 2-4, L324-347)
    case CommandFault::None:
    case CommandFault::InvalidInMode:
    case CommandFault::DirectionInhibited:
    case CommandFault::EmergencyStopActive:
    case CommandFault::DriveAlarmActive:
    case CommandFault::DistanceTooShort:
    case CommandFault::NoInterruptPending:  // GE has no interrupts (ge.md §6.7)
    case CommandFault::NotSimulated: return 0;
  }
  return 0;
}

std::uint16_t ge_command_status(GeVariant variant, const Card& card) {
  // SX: a path refusal names its own bit (8 path command, 9 buffer state, 15 buffer full; Table 2-4, V100)
  const GeList* list = variant == GeVariant::SX ? ge_list_if_any(card) : nullptr;
  if (list && list->command_bit()) return static_cast<std::uint16_t>(1u << *list->command_bit());
  return ge_command_status_bit(variant, card.last_fault());
}

std::uint32_t ge_events_to_clear(std::uint16_t rst_sts_mask) {
  // Bits 0-7 are laid out as the GT's (Tables 4-2/4-3 = GT Table 4-14 in these bits).
  return gt_events_to_clear(rst_sts_mask);
}

}  // namespace servobench::vendor::googol
