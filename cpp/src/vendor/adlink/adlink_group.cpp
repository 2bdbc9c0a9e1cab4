#include "servobench/vendor/adlink/adlink_group.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/machine/card_modes.hpp"

namespace servobench::vendor::adlink {

using machine::Card;  // the kernel services this module uses
using machine::CardCommandRefused;
using machine::CardModes;
using machine::CommandFault;
using machine::HostedGroup;
using machine::StopCause;

namespace {

std::vector<int> ids(const std::vector<std::size_t>& a) {
  std::vector<int> v;
  for (std::size_t k : a) v.push_back(static_cast<int>(k));
  return v;
}

[[noreturn]] void refuse(Card& card, int axis, CommandFault f, const std::string& what) {
  card.record_fault(axis, f);
  throw CardCommandRefused(f, axis, what);
}

bool in(const std::vector<std::size_t>& a, std::size_t k) { return std::find(a.begin(), a.end(), k) != a.end(); }

// The motion cycle the group steps on, s (the card steps hosted groups once per motion cycle).
double cycle_s(const Card& card) { return card.cycles().motion_cycle_ticks * card.servo_period_s(); }

}  // namespace

std::vector<std::size_t> AdlinkGroup::sorted(std::vector<std::size_t> a) {
  std::sort(a.begin(), a.end());
  return a;
}

AdlinkGroup::AdlinkGroup(const std::vector<std::size_t>& array, double period_s, const std::vector<double>& start,
                         double buffer_size, bool point_table)
    : CardGroup(sorted(array)), array_(array), interp_(ids(array), [&] {
        motion::AdlinkInterpSetup s;
        s.period_s = period_s;
        s.buffer_size = buffer_size;
        return s;
      }(), start), point_table_(point_table) {
  for (std::size_t a : axes())
    slot_of_.push_back(static_cast<std::size_t>(std::find(array_.begin(), array_.end(), a) - array_.begin()));
}

void AdlinkGroup::step_cycle() {
  if (!waiting_) interp_.step();
}

void AdlinkGroup::positions(double* out) const {
  const motion::SpacePoint& p = interp_.state().pos;
  for (std::size_t k = 0; k < slot_of_.size(); ++k) out[k] = p[slot_of_[k]];
}

void AdlinkGroup::fault_stop() {
  waiting_ = false;
  interp_.emg_stop();
}

void AdlinkGroup::stop(bool abrupt) {
  waiting_ = false;
  if (abrupt) interp_.emg_stop();
  else interp_.stop_move();
}

AdlinkGroup* adlink_group(Card& card) {
  return dynamic_cast<AdlinkGroup*>(card.modes().group(kAdlinkGroupSlot));
}

const AdlinkGroup* adlink_group(const Card& card) {
  const CardModes* modes = card.modes_if_any();  // no modes yet: no group
  return modes == nullptr ? nullptr : dynamic_cast<const AdlinkGroup*>(modes->group(kAdlinkGroupSlot));
}

void adlink_group_move(Card& card, const AdlinkGroupMove& m) {
  const std::size_t n = card.axis_count();
  if (m.array.size() < 2 || m.array.size() > 6)
    throw_invalid("AdlinkGroupMove", "array", static_cast<double>(m.array.size()), "must name 2..6 axes (ADLINK L2817)");
  for (std::size_t a : m.array)
    if (a >= n) throw_invalid("AdlinkGroupMove", "array[k]", static_cast<double>(a), "is not an axis of this card");
  if (m.params.size() != m.array.size())
    throw_invalid("AdlinkGroupMove", "params", static_cast<double>(m.params.size()), "must hold one entry per axis");
  const motion::AdlinkPtpParams* all = m.all ? &*m.all : nullptr;
  AdlinkGroup* g = adlink_group(card);
  const int ref = static_cast<int>(m.array[0]);
  if (g != nullptr && g->busy()) {
    if (g->array() != m.array || g->point_table() != m.point_table)
      refuse(card, ref, CommandFault::ChangeInMotion,
             "another axis array interpolates; a continuous interpolation keeps its axes (ADLINK L3077-3079)");
    for (std::size_t k = 0; k < m.array.size(); ++k) g->interp().set_axis_params(static_cast<int>(m.array[k]), m.params[k]);
    try {
      g->interp().push(m.spec, m.mode, m.blend, m.vm, all);
    } catch (const CardCommandRefused&) {
      throw;
    } catch (const motion::MotionCommandRefused& e) {
      refuse(card, ref, CommandFault::ChangeInMotion, e.what());
    }
    if (m.wait) g->set_waiting(true);
    return;
  }
  for (std::size_t a : m.array) {
    if (card.moving(a) && !(g != nullptr && in(g->axes(), a)))
      refuse(card, static_cast<int>(a), CommandFault::ModeChangeInMotion,
             "axis " + std::to_string(a) + " moves: an interpolation starts only with its axes at rest");
    if (card.emergency_stop()) {
      for (std::size_t b : m.array) card.modes().note_refused_start(b, StopCause::EmergencyStop);
      refuse(card, static_cast<int>(a), CommandFault::EmergencyStopActive, "the e-stop is active (ADLINK L3931)");
    }
    if (aps_motion_io_status(card, a) & (1u << static_cast<int>(ApsMio::ALM)))
      refuse(card, static_cast<int>(a), CommandFault::DriveAlarmActive, "the alarm input is active (ADLINK L3950)");
  }
  std::vector<double> start;
  for (std::size_t a : m.array) start.push_back(static_cast<double>(card.profile_pos(a)));
  auto ng = std::make_unique<AdlinkGroup>(m.array, cycle_s(card), start, m.buffer_size, m.point_table);
  for (std::size_t k = 0; k < m.array.size(); ++k) ng->interp().set_axis_params(static_cast<int>(m.array[k]), m.params[k]);
  try {
    ng->interp().push(m.spec, m.mode, m.blend, m.vm, all);  // bad geometry throws here: nothing changed yet
  } catch (const motion::MotionCommandRefused& e) {
    refuse(card, ref, CommandFault::DistanceTooShort, e.what());
  }
  ng->set_waiting(m.wait);
  CardModes& modes = card.modes();
  modes.add_group(kAdlinkGroupSlot, std::move(ng));
  modes.before_group_start(kAdlinkGroupSlot);
}

bool adlink_group_trigger(Card& card, std::uint32_t mask) {
  AdlinkGroup* g = adlink_group(card);
  if (g == nullptr || !g->waiting() || !(mask & (1u << g->array()[0]))) return false;
  g->set_waiting(false);
  return true;
}

namespace {
constexpr std::uint32_t mbit(ApsMsts b) { return 1u << static_cast<int>(b); }
}  // namespace

std::uint32_t aps_group_motion_status(const Card& card, std::size_t axis) {
  std::uint32_t w = aps_motion_status(card, axis);
  const CardModes* modes = card.modes_if_any();
  if (modes != nullptr && modes->gear_halted(axis)) w &= ~mbit(ApsMsts::GER);  // released (L3321)
  const AdlinkGroup* g = adlink_group(card);
  if (g == nullptr || !in(g->axes(), axis)) return w;
  const HostedGroup& h = modes->hosted(kAdlinkGroupSlot);  // a group exists, so the modes do
  const bool moving = g->busy() && !g->waiting();
  w &= ~(mbit(ApsMsts::CSTP) | mbit(ApsMsts::MDN) | mbit(ApsMsts::NSTP) | mbit(ApsMsts::WAIT) | mbit(ApsMsts::BLD));
  if (!moving) w |= mbit(ApsMsts::CSTP);
  const bool done = !g->busy() && !h.feeding;
  if (moving && g->point_table()) w |= mbit(ApsMsts::PTB);  // point buffer moving: MDN and ASTP clear (L3656)
  else w |= done ? mbit(ApsMsts::MDN) : mbit(ApsMsts::NSTP);
  if (g->waiting()) w |= mbit(ApsMsts::WAIT);
  if (moving && g->blending()) w |= mbit(ApsMsts::BLD);
  if (h.fault_stopped && !(w & mbit(ApsMsts::PTB))) w |= mbit(ApsMsts::ASTP);
  if (w & mbit(ApsMsts::PTB)) w = (w & ~mbit(ApsMsts::ASTP)) | mbit(ApsMsts::NSTP);
  return w;
}

int aps_group_stop_code(const Card& card, std::size_t axis) {
  const AdlinkGroup* g = adlink_group(card);
  if (g != nullptr && in(g->axes(), axis)) {
    const HostedGroup& h = card.modes_if_any()->hosted(kAdlinkGroupSlot);  // a group exists, so the modes do
    if (h.fault_stopped) return aps_stop_code(h.fault_cause);
  }
  return aps_stop_code(card, axis);
}

void aps_release_modes(Card& card, std::size_t i) {
  card.check_axis(i);
  if (const AdlinkGroup* g = adlink_group(card); g != nullptr && in(g->array(), i) && !g->busy())
    card.set_mode(g->array()[0], machine::AxisMode::TCurve);
  if (card.state(i).mode == machine::AxisMode::Gear && card.modes().gear_halted(i))
    card.set_mode(i, machine::AxisMode::TCurve);
}

void aps_release_axis(Card& card, std::size_t i) {
  using machine::CardEvent;
  aps_release_modes(card, i);
  const double act = card.actual_pos(i);
  const machine::LimitConfig& lim = card.state(i).limits;
  std::uint32_t bits = 0;
  if (!card.pos_limit_input(i)) bits |= machine::event_bit(CardEvent::PosLimit);
  if (!card.neg_limit_input(i)) bits |= machine::event_bit(CardEvent::NegLimit);
  if (!(lim.soft_pos_enabled && act >= lim.soft_pos_pulse)) bits |= machine::event_bit(CardEvent::SoftPosLimit);
  if (!(lim.soft_neg_enabled && act <= lim.soft_neg_pulse)) bits |= machine::event_bit(CardEvent::SoftNegLimit);
  if (card.events(i) & bits) card.clear_events(i, bits);
}

bool aps_stop_modes(Card& card, std::size_t i, bool abrupt) {
  card.check_axis(i);
  if (const AdlinkGroup* g = adlink_group(card); g != nullptr && in(g->array(), i) && g->busy()) {
    card.modes().stop_group(kAdlinkGroupSlot, abrupt);
    return true;
  }
  if (card.state(i).mode == machine::AxisMode::Gear) {
    card.set_mode(i, machine::AxisMode::TCurve);
    return true;
  }
  return false;
}

}  // namespace servobench::vendor::adlink
