// The hosted groups of the card's driven modes (machine/card_modes.hpp): coordinate systems and their slots, the
// GUC-ECAT / iDEABOX crd FIFOs, the GT coordinate mapping. The gear, PVT, FollowEx and the tick: card_modes.cpp.
#include "servobench/machine/card_modes.hpp"

#include <algorithm>
#include <string>

#include "card_detail.hpp"
#include "servobench/common/validate.hpp"

namespace servobench::machine {

using detail::axis_name;

// -- coordinate systems ---------------------------------------------------------------------------------------

HostedGroup& CardModes::slot(std::size_t s) {
  if (s >= kGroupSlots) throw_invalid("Card", "group slot", static_cast<double>(s), "must be 0..4");
  return groups_[s];
}

CardGroup* CardModes::group(std::size_t s) { return slot(s).group.get(); }

const HostedGroup& CardModes::hosted(std::size_t s) const {
  if (s >= kGroupSlots) throw_invalid("Card", "group slot", static_cast<double>(s), "must be 0..4");
  return groups_[s];
}

void CardModes::add_group(std::size_t s, std::unique_ptr<CardGroup> g) {
  HostedGroup& h = slot(s);
  if (h.group && (h.feeding || h.group->busy()))
    card_.refuse(-1, CommandFault::ChangeInMotion, "the coordinate system moves; it can be set up again only at rest");
  for (std::size_t a : g->axes()) {
    if (a >= n_) throw_invalid("Card", "coordinate-system axis", static_cast<double>(a + 1), "is not an axis of this card");
    if (group_of_[a] >= 0 && static_cast<std::size_t>(group_of_[a]) != s)
      card_.refuse(static_cast<int>(a), CommandFault::ChangeInMotion,
                   axis_name(a) + " is in another coordinate system (iDEABOX L7139-7140, L7174)");
    check_at_rest(a, "coordinate system set-up");
  }
  const std::vector<std::size_t> old = h.group ? h.group->axes() : std::vector<std::size_t>{};
  remove_group(s);
  for (std::size_t a : old) card_.set_driven_mode(a, AxisMode::TCurve);
  for (std::size_t a : g->axes()) {
    leave(a);
    group_of_[a] = static_cast<int>(s);
    set_kind(a, Kind::Group);
    card_.set_driven_mode(a, AxisMode::Coordinated);
  }
  h = HostedGroup{};
  h.group = std::move(g);
  const std::size_t m = h.group->axes().size();
  h.cur.assign(m, 0.0);
  h.group->positions(h.cur.data());
  h.prev = h.cur;
  h.vel.assign(m, 0.0);
  ++n_groups_;
}

void CardModes::remove_group(std::size_t s) {
  HostedGroup& h = slot(s);
  if (!h.group) return;
  for (std::size_t a : h.group->axes()) {
    group_of_[a] = -1;
    set_kind(a, Kind::None);
  }
  h = HostedGroup{};
  --n_groups_;
}

void CardModes::before_group_start(std::size_t s) {
  HostedGroup& h = slot(s);
  if (!h.group) card_.refuse(-1, CommandFault::InvalidInMode, "the coordinate system is not set up");
  if (card_.emergency_stop()) card_.refuse(-1, CommandFault::EmergencyStopActive, "the path cannot start while the e-stop is active");
  for (std::size_t a : h.group->axes())
    if (card_.alarm_active(a))
      card_.refuse(static_cast<int>(a), CommandFault::DriveAlarmActive, "the path cannot start while the drive alarm is active");
  h.fault_stopped = false;
  h.fault_cause = StopCause::None;
  h.fault_axis = -1;
  h.group->set_outside_positions(profile_positions());
  h.group->aux_positions(h.aux_cur);
  h.aux_prev = h.aux_cur;
  for (std::size_t a : h.group->axes()) card_.set_stop_cause(a, StopCause::None);
}

void CardModes::stop_group(std::size_t s, bool abrupt) {
  HostedGroup& h = slot(s);
  if (!h.group) card_.refuse(-1, CommandFault::InvalidInMode, "the coordinate system is not set up");
  h.group->stop(abrupt);
}

// -- GUC-ECAT / iDEABOX ---------------------------------------------------------------------------------------

void CardModes::set_crd_prm(int crd, const motion::CrdPrm& prm) {
  if (crd < 1 || crd > 2) throw_invalid("Card", "crd", crd, "must be 1 or 2 (GUC L370)");
  prm.validate();
  std::array<double, 8> pp{};
  const std::vector<double> p = profile_positions();
  for (std::size_t k = 0; k < std::min<std::size_t>(8, n_); ++k) pp[k] = p[k];
  for (std::size_t k = 0; k < 8; ++k)
    if (prm.profile[k] != 0 && k >= n_)
      throw_invalid("CrdPrm", "profile[k]", static_cast<double>(k + 1), "maps an axis this card does not have");
  const motion::CoordSystem cs = motion::CoordSystem::crd_prm(prm, pp);
  motion::PathSetup setup;
  setup.cycle_ms = cycle_ticks_ * card_.servo_period_s() * 1e3;
  setup.syn_vel_max = prm.syn_vel_max;
  setup.syn_acc_max = prm.syn_acc_max;
  setup.even_time_ms = prm.even_time_ms;
  setup.return_to_stop_point = false;  // GUC L1005, iDEABOX L1648-1653: resume only at the breakpoint
  std::vector<double> axis_pos;
  for (int a : cs.axes()) axis_pos.push_back(p[static_cast<std::size_t>(a - 1)]);
  add_group(static_cast<std::size_t>(crd - 1),
            std::make_unique<CrdPairGroup>(cs, setup, cs.to_crd(axis_pos), 0.5));
  crd_prm_[static_cast<std::size_t>(crd - 1)] = prm;
}

const motion::CrdPrm& CardModes::crd_prm(int crd) const {
  if (crd < 1 || crd > 2) throw_invalid("Card", "crd", crd, "must be 1 or 2 (GUC L370)");
  return crd_prm_[static_cast<std::size_t>(crd - 1)];
}

motion::CrdFifoPair& CardModes::crd(int crd) {
  if (crd < 1 || crd > 2) throw_invalid("Card", "crd", crd, "must be 1 or 2 (GUC L370)");
  auto* g = dynamic_cast<CrdPairGroup*>(groups_[static_cast<std::size_t>(crd - 1)].group.get());
  if (!g) card_.refuse(-1, CommandFault::InvalidInMode, "crd " + std::to_string(crd) + " is not set up (GT_SetCrdPrm)");
  return g->pair();
}

void CardModes::crd_start(std::uint32_t mask, std::uint32_t option) {
  if ((mask & 3u) == 0) card_.refuse(-1, CommandFault::NoAxisInMask, "GT_CrdStart: no coordinate system in the mask");
  for (int c = 1; c <= 2; ++c)
    if (mask & (1u << (c - 1))) {
      crd(c);
      before_group_start(static_cast<std::size_t>(c - 1));
    }
  for (int c = 1; c <= 2; ++c)
    if (mask & (1u << (c - 1))) {
      try {
        crd(c).start((option >> (c - 1)) & 1u ? 1 : 0);
      } catch (const motion::MotionCommandRefused& e) {
        card_.refuse(-1, CommandFault::ChangeInMotion, e.what());
      }
    }
}

motion::CrdPoint CardModes::crd_pos(int c) const {
  if (c < 1 || c > 2) throw_invalid("Card", "crd", c, "must be 1 or 2 (GUC L370)");
  const auto* g = dynamic_cast<const CrdPairGroup*>(groups_[static_cast<std::size_t>(c - 1)].group.get());
  if (!g) throw_invalid("Card", "crd", c, "is not set up (GT_SetCrdPrm)");
  return g->pair().state().pos;
}

// -- GT ---------------------------------------------------------------------------------------------------------

void CardModes::gt_map_axis(const motion::GtAxisMap& row) {
  if (row.axis < 1 || row.axis > static_cast<int>(n_))
    throw_invalid("GtAxisMap", "axis", row.axis, "is not an axis of this card (GT L1533)");
  std::vector<motion::GtAxisMap> rows;
  for (const auto& r : gt_rows_)
    if (r.axis != row.axis) rows.push_back(r);
  rows.push_back(row);
  const motion::CoordSystem cs = motion::CoordSystem::gt_map(rows);
  motion::PathSetup setup;
  setup.cycle_ms = cycle_ticks_;  // the GT's path time unit is the sample time ST (GT L1725-1729)
  setup.return_to_stop_point = true;  // GT L1940
  const std::vector<double> p = profile_positions();
  std::vector<double> axis_pos;
  for (int a : cs.axes()) axis_pos.push_back(p[static_cast<std::size_t>(a - 1)]);
  add_group(kGtCrdSlot, std::make_unique<PathGroup>(cs, setup, cs.to_crd(axis_pos)));
  gt_rows_ = rows;
}

motion::PathGenerator& CardModes::gt_path() {
  auto* g = dynamic_cast<PathGroup*>(groups_[kGtCrdSlot].group.get());
  if (!g) card_.refuse(-1, CommandFault::InvalidInMode, "no axis is mapped (GT_MapAxis)");
  return g->path();
}

}  // namespace servobench::machine
