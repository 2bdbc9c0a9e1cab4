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

ApsPointTables& aps_point_tables(machine::Card& card) { return card.module<ApsPointTables>(); }

}  // namespace servobench::vendor::adlink
