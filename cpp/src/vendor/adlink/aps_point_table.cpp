#include "servobench/vendor/adlink/aps_point_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_outputs.hpp"
#include "servobench/vendor/adlink/aps_parameters.hpp"

namespace servobench::vendor::adlink {

using Code = AdlinkCode;

namespace {

bool whole(double v) { return std::isfinite(v) && v == std::floor(v); }
bool in_range(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }
// The first n values, all finite, or nullopt.
std::optional<motion::SpacePoint> point(const std::vector<double>& v, std::size_t n) {
  if (v.size() < n || n > static_cast<std::size_t>(motion::kSpaceMaxDim)) return std::nullopt;
  motion::SpacePoint p{};
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(v[k])) return std::nullopt;
    p[k] = v[k];
  }
  return p;
}
bool dir_ok(double d) { return whole(d) && std::fabs(d) <= 32767; }  // I16 Dir

}  // namespace

Code ApsPointTables::find(double board, double ptb, Table*& t) {
  t = nullptr;
  if (board != 0 || (ptb != 0 && ptb != 1)) return Code::ParametersInvalid;
  auto it = tables_.find(static_cast<int>(ptb));
  if (it == tables_.end()) return Code::FunctionNotAvailable;
  t = &it->second;
  return Code::NoError;
}

bool ApsPointTables::owns_group(const Table& t) const {
  const AdlinkGroup* g = adlink_group(static_cast<const machine::Card&>(card_));
  return g != nullptr && g->point_table() && g->array() == t.axes;
}

long long ApsPointTables::sync(Table& t) {
  const AdlinkGroup* g = owns_group(t) ? adlink_group(card_) : nullptr;
  const long long started =
      g == nullptr ? 0 : g->interp().state().moves_done + static_cast<long long>(g->interp().running_moves());
  ApsOutputs& outs = aps_outputs(card_);
  for (; t.applied < started; ++t.applied) {
    auto it = t.actions.find(t.applied);
    if (it == t.actions.end()) continue;
    for (const Action& a : it->second) {
      if (a.vao) outs.select_vao(a.a, a.b);
      else outs.set_do_bit(a.a, a.b != 0);
    }
    t.actions.erase(it);
  }
  return started;
}

void ApsPointTables::sync() {
  for (auto& [id, t] : tables_) sync(t);
}

PtStatus ApsPointTables::status_of(Table& t) {
  const long long started = sync(t);
  const AdlinkGroup* g = owns_group(t) ? adlink_group(card_) : nullptr;
  const int used = g == nullptr ? 0 : static_cast<int>(g->interp().pending() + g->interp().running_moves());
  const bool working = g != nullptr && g->busy() && !g->waiting();
  PtStatus s;
  s.bit_sts = (working ? kPtbWorking : 0) | (used >= kPtBufferPoints ? kPtbFull : 0) | (used == 0 ? kPtbEmpty : 0);
  s.free_space = kPtBufferPoints - used;
  s.usage_space = used;
  s.running_cnt = t.base + started;
  return s;
}

Code ApsPointTables::enable(double board, double ptb, double dim, const std::vector<double>& axes) {
  if (board != 0 || (ptb != 0 && ptb != 1) || !whole(dim) || dim < 2 || dim > kPtMaxDim) return Code::ParametersInvalid;
  const auto d = static_cast<std::size_t>(dim);
  if (axes.size() < d) return Code::ParametersInvalid;
  std::vector<std::size_t> arr;
  for (std::size_t k = 0; k < d; ++k) {
    const double a = axes[k];
    if (!whole(a) || a < 0 || a >= static_cast<double>(card_.axis_count())) return Code::ParametersInvalid;
    const auto ax = static_cast<std::size_t>(a);
    if (std::find(arr.begin(), arr.end(), ax) != arr.end()) return Code::ParametersInvalid;
    arr.push_back(ax);
  }
  if (!tables_.empty()) return Code::FunctionNotAvailable;
  for (std::size_t a : arr)
    if (card_.moving(a)) return Code::FunctionNotAvailable;
  const motion::AdlinkPtpParams& p = aps_parameters(card_).axis(arr[0]).motion;
  Table t;
  t.axes = arr;
  t.vm = p.vm;
  t.acc = p.acc;
  t.dec = p.dec;
  t.sf = p.sf;
  tables_[static_cast<int>(ptb)] = t;
  return Code::NoError;
}

Code ApsPointTables::disable(double board, double ptb) {
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  if (owns_group(*t)) {
    const AdlinkGroup* g = adlink_group(card_);
    if (g->busy() && !g->waiting()) return Code::FunctionNotAvailable;
    try {
      if (g->busy()) card_.modes().stop_group(kAdlinkGroupSlot, true);  // points not started are dropped
      card_.set_mode(t->axes[0], machine::AxisMode::TCurve);
    } catch (const motion::MotionCommandRefused&) {
      return Code::FunctionNotAvailable;
    }
  }
  tables_.erase(static_cast<int>(ptb));
  return Code::NoError;
}

Code ApsPointTables::status(double board, double ptb, PtStatus& out) {
  out = PtStatus{};
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  out = status_of(*t);
  return Code::NoError;
}

Code ApsPointTables::start(double board, double ptb, double reserved) {
  if (reserved != 0) return Code::ParametersInvalid;
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  t->started = true;
  if (owns_group(*t) && adlink_group(card_)->waiting()) adlink_group_trigger(card_, 1u << t->axes[0]);
  return Code::NoError;
}

Code ApsPointTables::stop(double board, double ptb) {
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  t->started = false;
  if (owns_group(*t) && adlink_group(card_)->busy()) {
    sync(*t);
    card_.modes().stop_group(kAdlinkGroupSlot, adlink_group(card_)->waiting());
  }
  return Code::NoError;
}

Code ApsPointTables::set_relative(double board, double ptb, bool relative) {
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  t->relative = relative;
  return Code::NoError;
}

Code ApsPointTables::set_speed(double board, double ptb, Speed which, double v) {
  const bool ok = which == Speed::Vm ? in_range(v, 0, 1e9) && v != 0
                  : which == Speed::Ve ? in_range(v, 0, 1e9)
                  : which == Speed::Sf ? in_range(v, 0, 1)
                                       : in_range(v, 1e-9, 1e12);
  if (!ok) return Code::ParametersInvalid;
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  switch (which) {
    case Speed::Vm: t->vm = v; break;
    case Speed::Ve: t->ve = v; break;
    case Speed::Acc: t->acc = v; break;
    case Speed::Dec: t->dec = v; break;
    case Speed::AccDec: t->acc = t->dec = v; break;
    case Speed::Sf: t->sf = v; break;
  }
  return Code::NoError;
}

Code ApsPointTables::set_transition(double board, double ptb, Transition tr, double bp) {
  using motion::BlendMode;
  const bool ok = tr == Transition::BlendDec ? std::isfinite(bp) && bp >= 0
                  : tr == Transition::BlendDist ? in_range(bp, 0, 1e12) && bp > 0
                  : tr == Transition::BlendPcnt ? std::isfinite(bp) && bp > 0 && bp < 100
                                                : true;
  if (!ok) return Code::ParametersInvalid;
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  switch (tr) {
    case Transition::InPosition: return Code::FunctionNotAvailable;  // no in-position transition (AF8)
    case Transition::Buffered: t->mode = BlendMode::Buffered; t->blend = 0; break;
    case Transition::BlendDec: t->mode = BlendMode::BlendDecel; t->blend = 0; break;  // Bp unused (AF9)
    case Transition::BlendDist: t->mode = BlendMode::BlendDistance; t->blend = bp; break;
    case Transition::BlendPcnt: t->mode = BlendMode::BlendPercent; t->blend = bp; break;
  }
  return Code::NoError;
}

Code ApsPointTables::ext_set_do(double board, double ptb, double channel, double on) {
  if (!whole(channel) || channel < 0 || channel > 7 || (on != 0 && on != 1)) return Code::ParametersInvalid;
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  t->ext.push_back(Action{false, static_cast<int>(channel), static_cast<int>(on)});
  return Code::NoError;
}

Code ApsPointTables::ext_set_table(double board, double ptb, double ctrl, double table) {
  if ((ctrl != 0 && ctrl != 1) || !whole(table) || table < 0 || table > 7) return Code::ParametersInvalid;
  Table* t = nullptr;
  if (const Code c = find(board, ptb, t); c != Code::NoError) return c;
  t->ext.push_back(Action{true, static_cast<int>(ctrl), static_cast<int>(table)});
  return Code::NoError;
}

Code ApsPointTables::index_check(const Table& t, const std::vector<double>& index, std::size_t n) const {
  for (double x : index)
    if (!std::isfinite(x)) return Code::ParametersInvalid;
  // The card's 2-D arcs and 3-D spirals run on the first axes of the array: Index 0..n-1 in order (AF10).
  if (index.size() < n || t.axes.size() != n) return Code::FunctionNotAvailable;
  for (std::size_t k = 0; k < n; ++k)
    if (std::trunc(index[k]) != static_cast<double>(k)) return Code::FunctionNotAvailable;
  return Code::NoError;
}

Code ApsPointTables::geometry(const Table& t, const PtMove& m, motion::AdlinkMoveSpec& s) const {
  using K = PtMove::Kind;
  using SK = motion::AdlinkMoveSpec::Kind;
  const std::size_t n = m.kind == K::Arc2Ca || m.kind == K::Arc2Ce ? 2 : 3;
  if (m.kind == K::Line) {
    const auto p = point(m.pos, t.axes.size());
    if (m.dim != static_cast<double>(t.axes.size()) || !p) return Code::ParametersInvalid;
    s.kind = SK::Line;
    s.target = *p;
    return Code::NoError;
  }
  if (m.kind == K::Dwell) {
    s.kind = SK::Dwell;
    s.dwell_s = m.dw_time_ms * 1e-3;
    return Code::NoError;
  }
  const auto ctr = point(m.center, n);
  if (!ctr) return Code::ParametersInvalid;
  s.center = *ctr;
  if (m.kind == K::SpiralCa || m.kind == K::SpiralCe) {
    const auto nrm = point(m.normal, 3);
    if (!nrm) return Code::ParametersInvalid;
    s.normal = {(*nrm)[0], (*nrm)[1], (*nrm)[2]};
  }
  if (m.kind == K::Arc2Ca || m.kind == K::SpiralCa) {
    if (!std::isfinite(m.angle_deg)) return Code::ParametersInvalid;
    s.angle_deg = m.angle_deg;
    s.kind = m.kind == K::Arc2Ca ? SK::Arc2Ca : SK::SpiralCa;
    if (m.kind == K::SpiralCa) {
      if (!std::isfinite(m.delta_h) || !std::isfinite(m.final_r)) return Code::ParametersInvalid;
      s.height = m.delta_h;
      s.final_radius = m.final_r;
    }
    return Code::NoError;
  }
  const auto end = point(m.pos, n);
  if (!end || !dir_ok(m.dir)) return Code::ParametersInvalid;
  s.target = *end;
  s.dir = static_cast<int>(m.dir);
  s.kind = m.kind == K::Arc2Ce ? SK::Arc2Ce : SK::SpiralCe;
  return Code::NoError;
}

Code ApsPointTables::push(double board, double ptb, const PtMove& m, PtStatus& out) {
  using K = PtMove::Kind;
  out = PtStatus{};
  const bool dwell = m.kind == K::Dwell;
  if (dwell && !(in_range(m.dw_time_ms, 0, 1e9) && m.dw_time_ms > 0)) return Code::ParametersInvalid;
  Table* tp = nullptr;
  if (const Code c = find(board, ptb, tp); c != Code::NoError) return c;
  Table& t = *tp;
  if (m.kind != K::Line && !dwell) {
    const std::size_t n = m.kind == K::Arc2Ca || m.kind == K::Arc2Ce ? 2 : 3;
    if (const Code c = index_check(t, m.index, n); c != Code::NoError) return c;
  }
  motion::AdlinkMoveSpec spec;
  if (const Code c = geometry(t, m, spec); c != Code::NoError) {
    if (m.kind == K::Line) out = status_of(t);
    return c;
  }
  out = status_of(t);
  if (out.bit_sts & kPtbFull) return Code::FunctionNotAvailable;  // the buffer is full (L3880; BitSts b1, L3901)
  const AdlinkGroup* g = owns_group(t) ? adlink_group(card_) : nullptr;
  if (g == nullptr || !g->busy()) {  // the table ran dry or has not begun: a new group holds it
    if (g != nullptr) t.base += t.pushed;
    t.pushed = t.applied = 0;
    t.actions.clear();
    t.last_ve = 0;
    for (std::size_t a : t.axes) aps_release_axis(card_, a);  // an idle group hands its axes back first (V116)
  }
  const bool first = t.pushed == 0;
  const double ve = dwell ? 0.0 : t.ve;
  ApsParameters& prm = aps_parameters(card_);
  AdlinkGroupMove mv;
  mv.array = t.axes;
  spec.relative = t.relative && !dwell;
  mv.spec = spec;
  mv.mode = t.mode;
  mv.blend = t.blend;
  mv.vm = t.vm;
  mv.all = motion::AdlinkPtpParams{0.0, first ? 0.0 : std::min(t.last_ve, t.vm), t.vm, std::min(ve, t.vm),
                                   t.acc, t.dec, t.sf, prm.axis(t.axes[0]).motion.sd_dec};
  mv.wait = first && !t.started;
  mv.buffer_size = kPtBufferPoints;
  mv.point_table = true;
  try {
    mv.all->validate();
    for (std::size_t a : t.axes) {
      mv.params.push_back(prm.axis(a).motion);
      mv.params.back().validate();
    }
    adlink_group_move(card_, mv);
  } catch (const motion::MotionCommandRefused&) {
    out = status_of(t);
    return Code::FunctionNotAvailable;
  } catch (const std::invalid_argument&) {
    out = status_of(t);
    return Code::ParametersInvalid;
  }
  t.actions[t.pushed] = std::move(t.ext);
  t.ext.clear();
  ++t.pushed;
  t.last_ve = dwell ? 0.0 : std::min(ve, t.vm);
  out = status_of(t);
  return Code::NoError;
}

const std::vector<ApsCommandDoc>& pt_commands() {
  static const std::vector<ApsCommandDoc> kCommands = {
    {"APS_pt_enable", "Dimension, AxisArr",
     "``APS_pt_enable(Board_ID, PtbId, Dimension, I32 *AxisArr)`` (L3856): table 0..1 on ``Dimension``"
     " (2..6) axes, the first the reference axis; its speeds start as that axis's PRA_VM/ACC/DEC/SF "
     "(AF6), the mode absolute and buffered. The card has one interpolation group: a second table, or "
     "a table on axes that are moving, is refused (ERR_FunctionNotAvailable, AF5)."},
    {"APS_pt_disable", "",
     "``APS_pt_disable(Board_ID, PtbId)`` (L3860): ends the table (refused while it moves: stop it "
     "first); its axes return to single-axis motion."},
    {"APS_get_pt_status", "",
     "``APS_get_pt_status(Board_ID, PtbId, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3867, L3899-3901)."},
    {"APS_pt_start", "Reserved=0",
     "``APS_pt_start(Board_ID, PtbId)`` (L3874; the example passes a third argument 0, L3910: only 0 "
     "is accepted): starts executing the points in sequence (L3870-3872); points pushed later run as "
     "they come."},
    {"APS_pt_stop", "",
     "``APS_pt_stop(Board_ID, PtbId)`` (L3875): the table decelerates to rest along its path at the "
     "reference axis's PRA_SD_DEC; the points not started are dropped."},
    {"APS_pt_set_absolute", "",
     "``APS_pt_set_absolute(Board_ID, PtbId)`` (L3808-3820): the next points are absolute positions (pulse)."},
    {"APS_pt_set_relative", "",
     "``APS_pt_set_relative(Board_ID, PtbId)`` (L3808-3820): the next points are relative to the previous end "
     "point."},
    {"APS_pt_set_vm", "Vm",
     "``APS_pt_set_vm(Board_ID, PtbId, F64 Vm)`` (L3808-3820): maximum (vector) speed of the next points, pulse/s, "
     "0 < Vm <= 1e9."},
    {"APS_pt_set_ve", "Ve",
     "``APS_pt_set_ve(Board_ID, PtbId, F64 Ve)`` (L3808-3820): the speed the next points end with, pulse/s (the "
     "point after starts at it, AF7)."},
    {"APS_pt_set_acc", "Acc",
     "``APS_pt_set_acc(Board_ID, PtbId, F64 Acc)`` (L3808-3820): acceleration of the next points, pulse/s^2 (> 0)."},
    {"APS_pt_set_dec", "Dec",
     "``APS_pt_set_dec(Board_ID, PtbId, F64 Dec)`` (L3808-3820): deceleration of the next points, pulse/s^2 (> 0)."},
    {"APS_pt_set_acc_dec", "AccDec",
     "``APS_pt_set_acc_dec(Board_ID, PtbId, F64 AccDec)`` (L3808-3820): acceleration and deceleration at once, "
     "pulse/s^2."},
    {"APS_pt_set_s", "Sf",
     "``APS_pt_set_s(Board_ID, PtbId, F64 Sf)``: S-factor 0..1 of the next points (L2211-2236)."},
    {"APS_pt_set_trans_buffered", "",
     "``APS_pt_set_trans_buffered(Board_ID, PtbId)``: each next point starts when the one before has "
     "ended, with its own speeds (transition mode 4, L3117-3122)."},
    {"APS_pt_set_trans_inp", "",
     "``APS_pt_set_trans_inp(Board_ID, PtbId)``: buffered with an in-position wait between points. The"
     " card's interpolation has no in-position transition (its modes are L3085-3143's seven): "
     "ERR_FunctionNotAvailable, the mode unchanged (AF8)."},
    {"APS_pt_set_trans_blend_dec", "Bp",
     "``APS_pt_set_trans_blend_dec(Board_ID, PtbId, F64 Bp)``: the next point starts when the one "
     "before starts decelerating (mode 5, L3124-3129). Mode 5 has no parameter (L3126): Bp must be a "
     "finite number >= 0 and does not change the motion (AF9)."},
    {"APS_pt_set_trans_blend_dist", "Bp",
     "``APS_pt_set_trans_blend_dist(Board_ID, PtbId, F64 Bp)``: the next point starts when the "
     "remaining path of the one before is < Bp pulse (> 0; mode 6, L3131-3136)."},
    {"APS_pt_set_trans_blend_pctn", "Bp",
     "``APS_pt_set_trans_blend_pctn(Board_ID, PtbId, F64 Bp)`` (the manual's spelling, L3820; the "
     "library's ``_pcnt``): the next point starts when the remaining path of the one before is < Bp % "
     "of its length (0 < Bp < 100; mode 7, L3138-3143)."},
    {"APS_pt_ext_set_do_ch", "Channel, OnOff",
     "``APS_pt_ext_set_do_ch(Board_ID, PtbId, Channel, OnOff)``: digital output ``Channel`` (0..7) "
     "goes on (1) or off (0) when the next movement command starts (L3824-3827; read with "
     "APS_read_d_output)."},
    {"APS_pt_ext_set_table_no", "CtrlNo, TableNo",
     "``APS_pt_ext_set_table_no(Board_ID, PtbId, CtrlNo, TableNo)``: VAO controller ``CtrlNo`` (0..1) "
     "switches to VAO table ``TableNo`` (0..7) when the next movement command starts (L3828, L3446)."},
    {"APS_pt_line", "Prof: PTLINE",
     "``APS_pt_line(Board_ID, PtbId, PTLINE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3835, "
     "L3903-3907): a line to ``Prof.Pos`` (pulse; ``Prof.Dim`` = the table's dimension). A full buffer"
     " (50 points) returns ERR_FunctionNotAvailable (L3880)."},
    {"APS_pt_arc2_ca", "Prof: PTA2CA",
     "``APS_pt_arc2_ca(Board_ID, PtbId, PTA2CA *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a "
     "2-D arc about ``Prof.Center`` by ``Prof.Angle`` degrees (``Prof.Index`` 0, 1 on a 2-axis table, "
     "AF10)."},
    {"APS_pt_arc2_ce", "Prof: PTA2CE",
     "``APS_pt_arc2_ce(Board_ID, PtbId, PTA2CE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a "
     "2-D arc about ``Prof.Center`` to ``Prof.End`` (``Prof.Dir`` laps, L2943-2958)."},
    {"APS_pt_sprial_ca", "Prof: PTHCA",
     "``APS_pt_sprial_ca(Board_ID, PtbId, PTHCA *Prof, PTSTS *Status)`` (the manual's spelling, L3837)"
     " -> ``(rtn, PTSTS)``: a spiral of a 3-axis table (L3001-3035)."},
    {"APS_pt_sprial_ce", "Prof: PTHCE",
     "``APS_pt_sprial_ce(Board_ID, PtbId, PTHCE *Prof, PTSTS *Status)`` (L3837) -> ``(rtn, PTSTS)``: a"
     " spiral to ``Prof.End`` (L3037-3063)."},
    {"APS_pt_dwell", "Prof: PTDWL",
     "``APS_pt_dwell(Board_ID, PtbId, PTDWL *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3838): the "
     "table holds its position ``Prof.DwTime`` ms (> 0, whole motion cycles) after the moves before it"
     " have ended; the next point starts after it."},
  };
  return kCommands;
}

ApsPointTables& aps_point_tables(machine::Card& card) { return card.module<ApsPointTables>(); }

}  // namespace servobench::vendor::adlink
