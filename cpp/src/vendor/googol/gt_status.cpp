#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::vendor::googol {

using namespace machine;  // the kernel's types: Card, CardEvent, CommandFault, StopCause ...

namespace {

// Status bits 0-7 (Table 4-14, L1439-1464) and the kernel events each one shows.
struct EventBit {
  int bit;
  std::uint32_t events;
};
constexpr EventBit kEventBits[] = {
    {0, event_bit(CardEvent::MotionComplete)},
    {1, event_bit(CardEvent::DriveAlarm)},
    {2, event_bit(CardEvent::Breakpoint)},
    {3, event_bit(CardEvent::Captured)},
    {4, event_bit(CardEvent::FollowingError)},
    {5, event_bit(CardEvent::PosLimit) | event_bit(CardEvent::SoftPosLimit)},
    {6, event_bit(CardEvent::NegLimit) | event_bit(CardEvent::SoftNegLimit)},
    {7, event_bit(CardEvent::CommandError)},
};

}  // namespace

std::uint32_t gt_event_bits(std::uint32_t events) {
  std::uint32_t w = 0;
  for (const EventBit& e : kEventBits)
    if (events & e.events) w |= 1u << e.bit;
  return w;
}

std::uint16_t gt_mode_code(AxisMode mode) {
  switch (mode) {
    case AxisMode::TCurve: return 0;
    case AxisMode::Jog: return 1;
    case AxisMode::SCurve: return 2;
    case AxisMode::Gear: return 3;
    case AxisMode::Coordinated: return 5;
    case AxisMode::Pvt: return 6;
    case AxisMode::Follow: return 7;
  }
  return 0;
}

std::uint16_t gt_axis_status(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  std::uint32_t w = gt_event_bits(s.events);
  if (s.closed_loop) w |= 1u << 8;
  if (s.enabled) w |= 1u << 9;
  // Bit 10 also while an Update carrying motion registers waits for its commit at the next tick (V34), so a host
  // polling right after GT_Update sees the motion it started.
  if (card.moving(axis) || (s.commit_pending && (s.pending_dirty & kStagedMotion))) w |= 1u << 10;
  if (s.limits.enabled) w |= 1u << 11;
  w |= static_cast<std::uint32_t>(axis & 3u) << 12;
  const CaptureTrigger armed = card.loop(axis).capture().armed();
  if (armed == CaptureTrigger::Home) w |= 1u << 14;
  if (armed == CaptureTrigger::Index) w |= 1u << 15;
  return static_cast<std::uint16_t>(w);
}

std::uint16_t gt_mode_register(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  std::uint32_t w = 0;
  if (s.auto_stop) w |= 1u << 7;
  if (s.auto_update) w |= 1u << 10;
  w |= static_cast<std::uint32_t>(gt_mode_code(s.mode)) << 11;
  return static_cast<std::uint16_t>(w);
}

std::uint16_t gt_command_status_bit(CommandFault fault) {
  switch (fault) {
    case CommandFault::MotionParamOverflow: return 1u << 0;
    case CommandFault::IllegalControlParam: return 1u << 1;
    case CommandFault::NoAxisInMask: return 1u << 2;
    case CommandFault::DriveResetWhileEnabled: return 1u << 3;
    case CommandFault::ModeChangeInMotion: return 1u << 6;
    case CommandFault::IndexCaptureArmed: return 1u << 7;
    case CommandFault::HomeCaptureArmed: return 1u << 8;
    case CommandFault::AxisOnWhileAlarm: return 1u << 9;
    case CommandFault::ChangeInMotion:
    case CommandFault::InvalidInMode: return 1u << 11;
    case CommandFault::None:
    case CommandFault::DirectionInhibited:
    case CommandFault::EmergencyStopActive:
    case CommandFault::DriveAlarmActive: return 0;
    case CommandFault::DistanceTooShort: return 1u << 0;
    case CommandFault::MotorStateWhileEnabled:
    case CommandFault::AxisStateError:
    case CommandFault::NotInCommandSet:
    case CommandFault::NotSimulated: return 0;  // GE causes (vendor/googol/ge_status.hpp)
    case CommandFault::CrdStateError: return 1u << 12;
    case CommandFault::NoInterruptPending: return 1u << 4;
  }
  return 0;
}

std::uint16_t gt_command_status(const Card& card) { return gt_command_status_bit(card.last_fault()); }

std::uint32_t gt_events_to_clear(std::uint16_t rst_sts_mask) {
  const std::uint32_t clear = ~static_cast<std::uint32_t>(rst_sts_mask) & 0xFFu;
  std::uint32_t e = 0;
  for (const EventBit& b : kEventBits)
    if (clear & (1u << b.bit)) e |= b.events;
  return e;
}

}  // namespace servobench::vendor::googol
