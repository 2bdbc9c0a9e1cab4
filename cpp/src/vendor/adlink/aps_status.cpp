#include "servobench/vendor/adlink/aps_status.hpp"

#include <cmath>

#include "servobench/vendor/adlink/adlink_axes.hpp"

namespace servobench::vendor::adlink {

using namespace machine;  // the kernel's types: Card, CardEvent, CommandFault, StopCause ...

namespace {
constexpr std::uint32_t bit(ApsMsts b) { return 1u << static_cast<int>(b); }
constexpr std::uint32_t bit(ApsMio b) { return 1u << static_cast<int>(b); }
}  // namespace

std::uint32_t aps_motion_status(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  const AdlinkAxisState& ad = adlink_state(card, axis);
  const MotionLoop& l = card.loop(axis);
  const motion::ProfileGenerator& gen = l.generator();
  const bool profile = gen.moving();
  std::uint32_t w = 0;
  if (!profile) w |= bit(ApsMsts::CSTP);
  if (profile) {
    const double v = gen.state().vel, a = gen.state().acc;
    if (a * v > 0.0) w |= bit(ApsMsts::ACC);
    else if (a * v < 0.0) w |= bit(ApsMsts::DEC);
    else if (v != 0.0) w |= bit(ApsMsts::VM);
  }
  if (s.dir_positive) w |= bit(ApsMsts::DIR);
  w |= card.moving(axis) ? bit(ApsMsts::NSTP) : bit(ApsMsts::MDN);
  if (l.homing() && !l.homing()->finished()) w |= bit(ApsMsts::HMV);
  if (ad.wait_trigger) w |= bit(ApsMsts::WAIT);
  if (jogging(card, axis)) w |= bit(ApsMsts::JOG);
  if (ad.pre_event) w |= bit(ApsMsts::PRED);
  if (ad.post_event) w |= bit(ApsMsts::POSTD);
  if (s.stop_cause != StopCause::None) w |= bit(ApsMsts::ASTP);
  if (s.mode == AxisMode::Gear) w |= bit(ApsMsts::GER);
  return w;
}

std::uint32_t aps_motion_io_status(const Card& card, std::size_t axis) {
  const CardAxisState& s = card.state(axis);
  const Axis& a = card.loop(axis).axis();
  std::uint32_t w = 0;
  if (s.alarm_enabled && (a.alarm() || s.alarm_input)) w |= bit(ApsMio::ALM);
  if (card.pos_limit_input(axis)) w |= bit(ApsMio::PEL);
  if (card.neg_limit_input(axis)) w |= bit(ApsMio::MEL);
  if (a.config().switches.home(a.load_angle_rad())) w |= bit(ApsMio::ORG);
  if (card.emergency_stop()) w |= bit(ApsMio::EMG);
  if (in_position(card, axis)) w |= bit(ApsMio::INP);
  if (s.enabled) w |= bit(ApsMio::SVON);
  const double act = card.actual_pos(axis);
  if (s.limits.soft_pos_enabled && act >= s.limits.soft_pos_pulse) w |= bit(ApsMio::SPEL);
  if (s.limits.soft_neg_enabled && act <= s.limits.soft_neg_pulse) w |= bit(ApsMio::SMEL);
  return w;
}

int aps_stop_code(StopCause cause) {
  switch (cause) {
    case StopCause::None: return kApsStopNormal;
    case StopCause::EmergencyStop: return kApsStopEmg;
    case StopCause::DriveAlarm: return kApsStopAlm;
    case StopCause::PosLimit: return kApsStopPel;
    case StopCause::NegLimit: return kApsStopMel;
    case StopCause::SoftPosLimit: return kApsStopSpel;
    case StopCause::SoftNegLimit: return kApsStopSmel;
    case StopCause::ErrorLevel: return kApsStopErrorLevel;
    case StopCause::FollowingError: return kApsStopSvno;
  }
  return kApsStopNormal;
}

int aps_stop_code(const Card& card, std::size_t axis) { return aps_stop_code(card.state(axis).stop_cause); }

}  // namespace servobench::vendor::adlink
