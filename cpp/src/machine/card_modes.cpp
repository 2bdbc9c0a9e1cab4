#include "servobench/machine/card_modes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

namespace {

// Runs a check; a bad value (std::invalid_argument) records the fault on the card before it propagates.
template <class F>
void checked(Card& card, std::size_t i, CommandFault fault, F&& check) {
  try {
    check();
  } catch (const std::invalid_argument&) {
    card.record_fault(static_cast<int>(i), fault);
    throw;
  }
}
}  // namespace

CardModes::CardModes(Card& card)
    : card_(card),
      n_(card.axis_count()),
      kind_(n_, Kind::None),
      gear_(n_),
      pvt_(n_),
      follow_(n_),
      follow_master_(n_),
      group_of_(n_, -1),
      cmd_(n_),
      aux_fed_(n_, 0),
      cycle_ticks_(card.cycles().motion_cycle_ticks) {}

// -- common ------------------------------------------------------------------------------------------------

void CardModes::check_at_rest(std::size_t i, const char* what) {
  card_.check_axis(i);
  const CardAxisState& s = card_.state(i);
  if (card_.moving(i) && s.mode != AxisMode::Gear)
    card_.refuse(static_cast<int>(i), CommandFault::ModeChangeInMotion,
                 std::string(what) + ": the axis must be at rest (GT L837; GUC L743; iDEABOX L7168)");
}

void CardModes::set_kind(std::size_t i, Kind k) {
  const auto counted = [](Kind x) { return x != Kind::None && x != Kind::Group; };
  if (counted(kind_[i])) --n_driven_;
  if (counted(k)) ++n_driven_;
  kind_[i] = k;
}

long long CardModes::master_profile(std::size_t m) const { return card_.loop(m).generator().reported_pos(); }

std::vector<double> CardModes::profile_positions() const {
  std::vector<double> p(n_);
  for (std::size_t k = 0; k < n_; ++k) p[k] = static_cast<double>(card_.loop(k).generator().reported_pos());
  return p;
}

void CardModes::leave(std::size_t i) {
  switch (kind_[i]) {
    case Kind::Gear: gear_[i] = GearSlave{}; break;
    case Kind::Pvt:
      if (pvt_[i]) pvt_[i]->stop();
      pvt_[i].reset();
      break;
    case Kind::Follow: follow_[i].reset(); break;
    case Kind::Group: {
      // Switching an axis of a crd to another mode destroys the crd (iDEABOX L1616-1622): its other axes
      // fall back to the T-curve mode (V56).
      const auto g = static_cast<std::size_t>(group_of_[i]);
      const std::vector<std::size_t> axes = groups_[g].group->axes();
      remove_group(g);
      for (std::size_t a : axes)
        if (a != i) card_.set_driven_mode(a, AxisMode::TCurve);
      return;
    }
    case Kind::None: break;
  }
  set_kind(i, Kind::None);
}

void CardModes::reset() {
  for (std::size_t s = 0; s < kGroupSlots; ++s) remove_group(s);
  for (std::size_t i = 0; i < n_; ++i) leave(i);
  gt_rows_.clear();
  tables_ = motion::PvtTables{};
}

std::optional<bool> CardModes::moving(std::size_t i) const {
  switch (kind_[i]) {
    case Kind::Gear: return !gear_[i].halted;
    case Kind::Pvt: return pvt_[i] && pvt_[i]->moving();
    case Kind::Follow: return follow_[i] && follow_[i]->moving();
    case Kind::Group: return groups_[static_cast<std::size_t>(group_of_[i])].feeding;
    case Kind::None: break;
  }
  return std::nullopt;
}

// -- electronic gear -----------------------------------------------------------------------------------------

void CardModes::set_gear(std::size_t slave, std::size_t master) {
  card_.check_axis(slave);
  if (master >= n_)
    card_.refuse(static_cast<int>(slave), CommandFault::IllegalControlParam,
                 "GT_PrflG: the master " + std::to_string(master + 1) + " is not an axis of this card");
  if (master == slave)
    card_.refuse(static_cast<int>(slave), CommandFault::IllegalControlParam,
                 "GT_PrflG: an axis cannot be its own master");
  check_at_rest(slave, "GT_PrflG");
  if (kind_[slave] != Kind::Gear) leave(slave);
  const CardAxisState& s = card_.state(slave);
  GearSlave& g = gear_[slave];
  g.master = master;
  g.halted = false;
  g.gear.emplace(s.active.ratio, master_profile(master), card_.loop(slave).generator().state().pos);
  card_.set_driven_mode(slave, AxisMode::Gear);
  set_kind(slave, Kind::Gear);
}

std::size_t CardModes::gear_master(std::size_t slave) const {
  if (kind_.at(slave) != Kind::Gear) throw_invalid("Card", "axis", static_cast<double>(slave), "is not in gear mode");
  return gear_[slave].master;
}

bool CardModes::gear_halted(std::size_t slave) const { return kind_.at(slave) == Kind::Gear && gear_[slave].halted; }

// -- [aps] ADLINK gear engage ramp (seed 004 L3294-3325) -------------------------------------------------------
void CardModes::set_gear_ramp(std::size_t slave, std::size_t master, double ratio, double rate_per_tick) {
  check_range("ApsGear", "ratio", ratio, -1e6, 1e6, "PRA_GEAR_RATIO");
  check_range("ApsGear", "rate", rate_per_tick, 0.0, 1e12, "PRA_GEAR_ENGAGE_RATE per tick, 0 = at once");
  set_gear(slave, master);
  GearSlave& g = gear_[slave];
  g.target = ratio;
  g.rate = rate_per_tick;
  g.keep_master = true;
  g.gear->set_ratio(rate_per_tick > 0.0 ? 0.0 : ratio, master_profile(master));
}

void CardModes::gear_ramp_to(std::size_t slave, double ratio, double rate_per_tick) {
  check_range("ApsGear", "ratio", ratio, -1e6, 1e6, "PRA_GEAR_RATIO");
  check_range("ApsGear", "rate", rate_per_tick, 0.0, 1e12, "PRA_GEAR_ENGAGE_RATE per tick, 0 = at once");
  if (kind_.at(slave) != Kind::Gear || gear_[slave].halted)
    card_.refuse(static_cast<int>(slave), CommandFault::InvalidInMode, "the axis is not an engaged gear slave");
  GearSlave& g = gear_[slave];
  g.target = ratio;
  g.rate = rate_per_tick;
  if (rate_per_tick == 0.0) g.gear->set_ratio(ratio, master_profile(g.master));
}

double CardModes::gear_ratio(std::size_t slave) const {
  if (kind_.at(slave) != Kind::Gear) throw_invalid("Card", "axis", static_cast<double>(slave), "is not in gear mode");
  return gear_[slave].gear->ratio();
}
// -- [/aps] -------------------------------------------------------------------------------------------------------

bool CardModes::gear_inhibits(std::size_t master, double dir) const {
  if (dir == 0.0 || n_driven_ == 0) return false;
  for (std::size_t s = 0; s < n_; ++s) {
    if (kind_[s] != Kind::Gear || gear_[s].master != master || gear_[s].halted) continue;
    const double slave_dir = dir * gear_[s].gear->ratio();
    if ((slave_dir > 0.0 && card_.inhibited_pos(s)) || (slave_dir < 0.0 && card_.inhibited_neg(s))) return true;
  }
  return false;
}

void CardModes::on_ratio(std::size_t i, double ratio) {
  if (kind_[i] != Kind::Gear) return;
  GearSlave& g = gear_[i];
  if (g.halted) {  // re-engage where the slave stands (V53)
    g.gear.emplace(ratio, master_profile(g.master), card_.loop(i).generator().state().pos);
    g.halted = false;
  } else {
    g.gear->set_ratio(ratio, master_profile(g.master));
  }
}

// -- PVT --------------------------------------------------------------------------------------------------------

void CardModes::pvt_download(int table_id, const motion::PvtCurve& curve) {
  try {
    tables_.download(table_id, curve);
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(-1, CommandFault::ChangeInMotion, e.what());
  }
}

void CardModes::set_pvt(std::size_t i) {
  check_at_rest(i, "GT_PrfPvt");
  leave(i);
  pvt_[i] = std::make_unique<motion::PvtAxis>(tables_, card_.loop(i).generator().state().pos, card_.servo_period_s());
  card_.set_driven_mode(i, AxisMode::Pvt);
  set_kind(i, Kind::Pvt);
}

motion::PvtAxis& CardModes::pvt(std::size_t i) {
  card_.check_axis(i);
  if (kind_[i] != Kind::Pvt)
    card_.refuse(static_cast<int>(i), CommandFault::InvalidInMode, "the axis is not in PVT mode (GT_PrfPvt first)");
  return *pvt_[i];
}
const motion::PvtAxis& CardModes::pvt(std::size_t i) const {
  if (kind_.at(i) != Kind::Pvt) throw_invalid("Card", "axis", static_cast<double>(i), "is not in PVT mode");
  return *pvt_[i];
}

void CardModes::pvt_select(std::size_t i, int table_id) {
  motion::PvtAxis& a = pvt(i);
  try {
    a.select(table_id);
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

void CardModes::pvt_loop(std::size_t i, double loop) {
  motion::PvtAxis& a = pvt(i);
  checked(card_, i, CommandFault::IllegalControlParam, [&] { a.set_loop(loop); });
}

void CardModes::pvt_start(std::uint32_t mask) {
  std::vector<motion::PvtAxis*> axes;
  for (std::size_t i = 0; i < n_; ++i)
    if (mask & (1u << i)) axes.push_back(&pvt(i));
  if (axes.empty()) card_.refuse(-1, CommandFault::NoAxisInMask, "GT_PvtStart: no axis of this card in the mask");
  if (card_.emergency_stop()) card_.refuse(-1, CommandFault::EmergencyStopActive, "GT_PvtStart refused while the e-stop is active");
  for (std::size_t i = 0; i < n_; ++i)
    if ((mask & (1u << i)) && card_.alarm_active(i))
      card_.refuse(static_cast<int>(i), CommandFault::DriveAlarmActive, "GT_PvtStart refused while the alarm is active");
  try {
    motion::pvt_start(axes);
  } catch (const motion::MotionCommandRefused& e) {
    for (auto* a : axes) a->stop();  // all or nothing
    card_.refuse(-1, CommandFault::ChangeInMotion, e.what());
  }
  for (std::size_t i = 0; i < n_; ++i)
    if (mask & (1u << i)) card_.set_stop_cause(i, StopCause::None);
}

void CardModes::note_refused_start(std::size_t axis, StopCause cause) { card_.set_stop_cause(axis, cause); }

bool CardModes::limit_enabled(std::size_t axis, bool positive) const {
  for (const HostedGroup& h : groups_)
    if (h.group && !h.group->limit_enabled(axis, positive)) return false;
  return true;
}

void CardModes::feed_inputs(CardGroup& g) const {
  // The card's inputs as the path layer's BufSetStopIo reads them (GUC L625-645; V129): limits, alarm, home of
  // card axes 1..8, logical (the card's sense applied).
  const std::size_t n = std::min<std::size_t>(n_, 8);
  for (std::size_t i = 0; i < n; ++i) {
    const int index = static_cast<int>(i) + 1;
    const CardAxisState& s = card_.state(i);
    const Axis& a = card_.loop(i).axis();
    g.set_input(static_cast<int>(motion::StopInput::LimitPositive), index, card_.pos_limit_input(i));
    g.set_input(static_cast<int>(motion::StopInput::LimitNegative), index, card_.neg_limit_input(i));
    g.set_input(static_cast<int>(motion::StopInput::Alarm), index, s.alarm_enabled && (a.alarm() || s.alarm_input));
    g.set_input(static_cast<int>(motion::StopInput::Home), index, a.config().switches.home(a.load_angle_rad()));
  }
}

// -- FollowEx -----------------------------------------------------------------------------------------------------

void CardModes::set_follow(std::size_t i, const motion::FollowExSetup& setup, const FollowMaster& master) {
  card_.check_axis(i);
  checked(card_, i, CommandFault::IllegalControlParam, [&] { setup.validate(); });
  check_at_rest(i, "GT_PrfFollowEx");
  leave(i);
  follow_[i] = std::make_shared<motion::FollowEx>(setup, card_.loop(i).generator().state().pos);
  card_.set_driven_mode(i, AxisMode::Follow);
  set_kind(i, Kind::Follow);
  follow_master(i, master);
}

motion::FollowEx& CardModes::follow(std::size_t i) {
  card_.check_axis(i);
  if (kind_[i] != Kind::Follow)
    card_.refuse(static_cast<int>(i), CommandFault::InvalidInMode, "the axis is not in FollowEx mode (GT_PrfFollowEx first)");
  return *follow_[i];
}
std::shared_ptr<motion::FollowEx> CardModes::follow_shared(std::size_t i) {
  follow(i);
  return follow_[i];
}

const motion::FollowEx& CardModes::follow(std::size_t i) const {
  if (kind_.at(i) != Kind::Follow) throw_invalid("Card", "axis", static_cast<double>(i), "is not in FollowEx mode");
  return *follow_[i];
}

void CardModes::follow_configure(std::size_t i, const motion::FollowExSetup& setup) {
  motion::FollowEx& f = follow(i);
  checked(card_, i, CommandFault::IllegalControlParam, [&] { setup.validate(); });
  try {
    f.configure(setup);
  } catch (const motion::MotionCommandRefused& e) {
    card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
  }
}

void CardModes::follow_master(std::size_t i, const FollowMaster& master) {
  motion::FollowEx& f = follow(i);
  if (master.master >= n_ || master.master == i)
    card_.refuse(static_cast<int>(i), CommandFault::IllegalControlParam,
                 "GT_SetFollowMasterEx: the master must be another axis of this card (iDEABOX L7341)");
  if (f.moving()) card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "GT_SetFollowMasterEx while following");
  follow_master_[i] = master;
}

const FollowMaster& CardModes::follow_master_of(std::size_t i) const {
  follow(i);
  return follow_master_[i];
}

double CardModes::follow_master_pos(std::size_t i) const {
  // GT_SetFollowMasterEx (iDEABOX L7345-7363): type 1 encoder, 2 planned profile, 3 axis with item 0 planned /
  // 1 encoder; the type and item are the FollowEx setup's, the master axis is follow_master_[i].
  const MotionLoop& l = card_.loop(follow_master_[i].master);
  const motion::FollowExSetup& s = follow_[i]->setup();
  const bool encoder = s.master_type == 1 || (s.master_type == 3 && s.master_item == 1);
  return encoder ? std::nearbyint(l.actual_pos()) : static_cast<double>(l.generator().reported_pos());
}

void CardModes::follow_start(std::uint32_t mask, std::uint32_t option) {
  std::vector<std::size_t> axes;
  for (std::size_t i = 0; i < n_; ++i)
    if (mask & (1u << i)) {
      motion::FollowEx& f = follow(i);
      if (f.moving()) card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "GT_FollowStartEx: already following");
      const int fifo = (option >> i) & 1u ? 1 : 0;
      if (f.size(fifo) == 0)
        card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, "GT_FollowStartEx: the FIFO holds no data");
      axes.push_back(i);
    }
  if (axes.empty()) card_.refuse(-1, CommandFault::NoAxisInMask, "GT_FollowStartEx: no axis of this card in the mask");
  if (card_.emergency_stop()) card_.refuse(-1, CommandFault::EmergencyStopActive, "GT_FollowStartEx refused while the e-stop is active");
  for (std::size_t i : axes) {
    try {
      follow_[i]->start(follow_master_pos(i), (option >> i) & 1u ? 1 : 0);
    } catch (const motion::MotionCommandRefused& e) {
      card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
    }
    card_.set_stop_cause(i, StopCause::None);
  }
}

void CardModes::follow_switch(std::uint32_t mask) {
  for (std::size_t i = 0; i < n_; ++i)
    if (mask & (1u << i)) {
      motion::FollowEx& f = follow(i);
      try {
        f.switch_fifo();
      } catch (const motion::MotionCommandRefused& e) {
        card_.refuse(static_cast<int>(i), CommandFault::ChangeInMotion, e.what());
      }
    }
}

// -- the tick ---------------------------------------------------------------------------------------------------

void CardModes::begin_tick(long long tick) {
  if (n_groups_ == 0) return;
  const auto mc = static_cast<long long>(cycle_ticks_);
  const long long j = tick % mc;
  std::fill(aux_fed_.begin(), aux_fed_.end(), 0);
  for (HostedGroup& h : groups_) {
    if (!h.group) continue;
    const std::vector<std::size_t>& axes = h.group->axes();
    if (j == 0) {  // a motion-cycle boundary: one interpolator cycle
      h.prev = h.cur;
      feed_inputs(*h.group);
      h.group->step_cycle();
      h.group->positions(h.cur.data());
      h.feeding = h.group->busy() || h.cur != h.prev;
      h.aux_prev = h.aux_cur;
      h.group->aux_positions(h.aux_cur);
    }
    const double f = static_cast<double>(j + 1) / static_cast<double>(mc);
    for (std::size_t k = 0; k < axes.size(); ++k) {
      motion::MotionState& c = cmd_[axes[k]];
      const double v = (h.cur[k] - h.prev[k]) / static_cast<double>(mc);
      c.pos = h.prev[k] + (h.cur[k] - h.prev[k]) * f;
      c.acc = v - h.vel[k];
      c.vel = v;
      c.jerk = 0.0;
      if (h.feeding) h.vel[k] = v;
    }
    if (!h.feeding)
      std::fill(h.vel.begin(), h.vel.end(), 0.0);
    // Outside axes moved by the buffer (BufMove / BufGear) while they stay in an independent mode.
    for (std::size_t q = 0; q < h.aux_cur.size(); ++q) {
      const std::size_t a = h.aux_cur[q].first;
      if (a >= n_ || kind_[a] != Kind::None) continue;
      double p0 = h.aux_cur[q].second;
      for (const auto& pr : h.aux_prev)
        if (pr.first == a) p0 = pr.second;
      const double p1 = h.aux_cur[q].second;
      if (p1 == p0) continue;
      motion::MotionState& c = cmd_[a];
      const double v = (p1 - p0) / static_cast<double>(mc);
      c.pos = p0 + (p1 - p0) * f;
      c.acc = v - c.vel;
      c.vel = v;
      aux_fed_[a] = 1;
    }
  }
}

void CardModes::feed(std::size_t i) {
  motion::ProfileGenerator& gen = card_.loop(i).generator();
  switch (kind_[i]) {
    case Kind::None:
      if (aux_fed_[i]) gen.follow(cmd_[i]);
      return;
    case Kind::Gear: {
      GearSlave& g = gear_[i];
      if (g.halted) return;
      if (g.rate > 0.0 && g.gear->ratio() != g.target) {  // [aps] engage ramp
        const double r = g.gear->ratio();
        const double next = g.target > r ? std::min(g.target, r + g.rate) : std::max(g.target, r - g.rate);
        g.gear->set_ratio(next, master_profile(g.master));
      }
      gen.follow(g.gear->step(master_profile(g.master)));
      return;
    }
    case Kind::Pvt: {
      motion::PvtAxis& a = *pvt_[i];
      if (a.moving()) gen.follow(a.step());
      return;
    }
    case Kind::Follow: {
      motion::FollowEx& f = *follow_[i];
      if (f.moving()) gen.follow(f.step(follow_master_pos(i)));
      return;
    }
    case Kind::Group:
      if (groups_[static_cast<std::size_t>(group_of_[i])].feeding) gen.follow(cmd_[i]);
      return;
  }
}

void CardModes::on_fault(std::size_t i, StopCause cause) {
  switch (kind_[i]) {
    case Kind::Gear: {
      // A slave fault stops the master too, unless the master runs open loop (GT L1082).
      GearSlave& g = gear_[i];
      if (g.halted) return;
      g.halted = true;
      const std::size_t m = g.master;
      if (g.keep_master) return;  // [aps] ADLINK: the master is not affected (L3321-3324)
      if (card_.state(m).closed_loop) {
        on_abrupt_stop(m);
        if (card_.loop(m).generator().moving()) card_.stop_profile(m);
      }
      return;
    }
    case Kind::Pvt:
      pvt_[i]->stop();
      return;
    case Kind::Follow:
      follow_[i]->stop();
      return;
    case Kind::Group: {
      // An axis fault stops the whole coordinated motion (GT crd status bit 6 default, L2011; GE bit 9).
      HostedGroup& h = groups_[static_cast<std::size_t>(group_of_[i])];
      if (h.fault_stopped && !h.group->busy()) return;
      if (!h.fault_stopped) {
        h.fault_stopped = true;
        h.fault_cause = cause;
        h.fault_axis = static_cast<int>(i);
        h.group->fault_stop();
      }
      return;
    }
    case Kind::None: return;
  }
}

void CardModes::on_abrupt_stop(std::size_t i) {
  switch (kind_[i]) {
    case Kind::Gear: gear_[i].halted = true; return;
    case Kind::Pvt: pvt_[i]->stop(); return;
    case Kind::Follow: follow_[i]->stop(); return;
    case Kind::Group: groups_[static_cast<std::size_t>(group_of_[i])].group->stop(true); return;
    case Kind::None: return;
  }
}

}  // namespace servobench::machine
