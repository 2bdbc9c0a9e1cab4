// The GUC-ECAT / iDEABOX set-up commands as vendor functions (vendor/googol/gts_commands.hpp).
#include "servobench/vendor/googol/gts_commands.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/vendor/googol/gts_card.hpp"

namespace servobench::vendor::googol {

using machine::AxisMode;
using machine::Card;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool whole_in(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && lo <= v && v <= hi; }
bool open_in(double v, double lo, double hi) { return std::isfinite(v) ? lo < v && v < hi : false; }
bool positive(double v) { return open_in(v, 0, kInf); }

// Runs a kernel command the manuals' way: 1 when the card refuses it in its present state (the card recorded
// why), 7 when it rejects a value, else 0 -- by the exception's type, never its text.
template <class F>
GucCode run(F&& command) {
  try {
    command();
  } catch (const motion::MotionCommandRefused&) {
    return GucCode::CommandError;
  } catch (const std::invalid_argument&) {
    return GucCode::ParameterError;
  } catch (const std::domain_error&) {
    return GucCode::ParameterError;
  }
  return GucCode::Success;
}

bool valid_profile(const Card& card, double profile) {
  return whole_in(profile, 1, static_cast<double>(card.axis_count()));
}

double ms(const Card& card) { return card.servo_period_s() * 1e3; }

// The first `count` values of a (the manual's count argument): nullopt when count is not whole or a is shorter.
std::optional<std::vector<double>> first(const std::vector<double>& a, double count) {
  if (!whole_in(count, 0, static_cast<double>(a.size()))) return std::nullopt;
  return std::vector<double>(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(count));
}

std::optional<motion::ContinuousPoints> first(const motion::ContinuousPoints& p, double count) {
  auto pos = first(p.pos, count), vel = first(p.vel, count), qa = first(p.acc_percent, count),
       qd = first(p.dec_percent, count), vm = first(p.vel_max, count), acc = first(p.acc, count),
       dec = first(p.dec, count);
  if (!pos || !vel || !qa || !qd || !vm || !acc || !dec) return std::nullopt;
  return motion::ContinuousPoints{*pos, *vel, *qa, *qd, *vm, *acc, *dec};
}

// A PVT download: table id 1..32, the curve `build` makes (7 when it throws for the data), the card's download.
template <class F>
GucCode download(Card& card, double table_id, F&& build) {
  if (!whole_in(table_id, 1, 32)) return GucCode::ParameterError;
  std::optional<motion::PvtCurve> curve;  // nullopt: the arrays hold fewer than count values
  if (run([&] { curve = build(); }) != GucCode::Success || !curve) return GucCode::ParameterError;
  return run([&] { card.modes().pvt_download(static_cast<int>(table_id), *curve); });
}

}  // namespace

// -- profiles ---------------------------------------------------------------------------------------------------------
GucCode gts_set_trap_prm(Card& card, double profile, double acc, double dec, double vel_start, double smooth_time) {
  if (!valid_profile(card, profile)) return GucCode::ParameterError;
  if (!positive(acc) || !positive(dec) || vel_start != 0 || smooth_time != 0) return GucCode::ParameterError;
  return run([&] { card.stage_acc(static_cast<std::size_t>(profile) - 1, acc * ms(card) * ms(card)); });
}

GucCode gts_set_jog_prm(Card& card, double profile, double acc, double dec, double smooth) {
  if (!valid_profile(card, profile)) return GucCode::ParameterError;
  if (!(std::isfinite(smooth) && 0 <= smooth && smooth <= 1)) return GucCode::ParameterError;
  const GucCode c = gts_set_trap_prm(card, profile, acc, dec, 0, 0);
  if (c == GucCode::Success) gts(card).set_jog_smooth(static_cast<std::size_t>(profile) - 1, smooth);
  return c;
}

GucCode gts_stop(Card& card, double mask, double option) {
  if (!whole_in(mask, 0, 0xFFFFFFFF) || !whole_in(option, 0, 0xFFFFFFFF)) return GucCode::ParameterError;
  const auto m = static_cast<std::uint64_t>(mask), o = static_cast<std::uint64_t>(option);
  return run([&] {
    for (int c = 1; c <= 2; ++c) {
      const std::uint64_t bit = std::uint64_t{1} << (12 + c - 1);  // bit 12 = crd 1, 13 = crd 2 (iDEABOX L1793)
      const auto slot = static_cast<std::size_t>(c - 1);
      if ((m & bit) && card.modes().hosted(slot).group) card.modes().stop_group(slot, (o & bit) != 0);
    }
    for (std::size_t a = 0; a < card.axis_count() && a < 32; ++a) {
      const std::uint64_t bit = std::uint64_t{1} << a;
      if (!(m & bit)) continue;
      const AxisMode mode = card.state(a).mode;
      if (mode != AxisMode::TCurve && mode != AxisMode::SCurve && mode != AxisMode::Jog) {
        if (card.modes().group_of(a) < 0) card.abrupt_stop(a);
      } else if ((o & bit) || card.moving(a)) {
        gts(card).stop_axis(a, (o & bit) != 0);  // GT_SetStopDec decelerations (GS7)
      }
    }
  });
}

// -- coordinate systems ---------------------------------------------------------------------------------------------------
GucCode gts_set_crd_prm(Card& card, double crd, const GtsCrdPrm& p) {
  if (!whole_in(crd, 1, 2) || !whole_in(p.dimension, 1, 4) || p.profile.size() > 8 || p.origin_pos.size() > 8 ||
      !open_in(p.syn_vel_max, 0, 32767) || !open_in(p.syn_acc_max, 0, 32767) || !whole_in(p.even_time, 0, 32766) ||
      !whole_in(p.set_origin_flag, 0, 1))
    return GucCode::ParameterError;
  std::set<int> used;
  std::size_t mapped = 0;
  motion::CrdPrm prm;
  prm.dimension = static_cast<int>(p.dimension);
  for (std::size_t k = 0; k < p.profile.size(); ++k) {
    if (!whole_in(p.profile[k], 0, 4)) return GucCode::ParameterError;
    const int coord = static_cast<int>(p.profile[k]);
    prm.profile[k] = coord;
    if (coord == 0) continue;
    ++mapped;
    // a coordinate mapped twice or beyond the dimension (L785), a profile the card does not have
    if (!used.insert(coord).second || coord > prm.dimension || k >= card.axis_count()) return GucCode::ParameterError;
  }
  if (mapped != static_cast<std::size_t>(prm.dimension)) return GucCode::ParameterError;
  for (std::size_t k = 0; k < p.origin_pos.size(); ++k) {
    if (!whole_in(p.origin_pos[k], -2147483648.0, 2147483647.0)) return GucCode::ParameterError;
    prm.origin_pos[k] = p.origin_pos[k];
  }
  prm.syn_vel_max = p.syn_vel_max;
  prm.syn_acc_max = p.syn_acc_max;
  prm.even_time_ms = p.even_time;
  prm.set_origin = p.set_origin_flag != 0;
  const GucCode c = run([&] { card.modes().set_crd_prm(static_cast<int>(crd), prm); });
  if (c == GucCode::Success) gts(card).drop_lookahead(static_cast<int>(crd));
  return c;
}

std::pair<GucCode, motion::CrdPrm> gts_get_crd_prm(Card& card, double crd) {
  if (!whole_in(crd, 1, 2)) return {GucCode::ParameterError, {}};
  if (!card.modes().hosted(static_cast<std::size_t>(crd) - 1).group) return {GucCode::CommandError, {}};
  return {GucCode::Success, card.modes().crd_prm(static_cast<int>(crd))};
}

GucCode gts_init_lookahead(Card& card, double crd, double fifo, double t_ms, double acc_max, double n) {
  // T (0, 1000] ms, accMax (0, 32767] pulse/ms^2 (GUC L725-732; the bounds with the former 1e-4 tolerance)
  if (!whole_in(crd, 1, 2) || !whole_in(fifo, 0, 1) || !open_in(t_ms, 0, 1000.0001) ||
      !open_in(acc_max, 0, 32767.0001) || !whole_in(n, 0, 32766))
    return GucCode::ParameterError;
  const int c = static_cast<int>(crd), f = static_cast<int>(fifo);
  motion::LookAheadParams la;
  la.t_ms = t_ms;
  la.acc_max = acc_max;
  la.n = n;
  const GucCode code = run([&] { card.modes().crd(c).fifo(f).init_lookahead(la); });
  if (code == GucCode::Success) gts(card).set_lookahead(c, f, static_cast<int>(n));
  return code;
}

GucCode gts_crd_data(Card& card, double crd, bool null_data, double fifo) {
  if (!null_data || !whole_in(crd, 1, 2) || !whole_in(fifo, 0, 1)) return GucCode::ParameterError;
  bool ok = false;
  const GucCode c = run([&] { ok = card.modes().crd(static_cast<int>(crd)).fifo(static_cast<int>(fifo)).flush(); });
  return c != GucCode::Success ? c : ok ? GucCode::Success : GucCode::CommandError;
}

// -- PVT tables -------------------------------------------------------------------------------------------------------------
GucCode gts_pvt_table(Card& card, double table_id, double count, const std::vector<double>& t,
                      const std::vector<double>& p, const std::vector<double>& v) {
  return download(card, table_id, [&]() -> std::optional<motion::PvtCurve> {
    auto tt = first(t, count), pp = first(p, count), vv = first(v, count);
    if (!tt || !pp || !vv) return std::nullopt;
    return motion::pvt_table(*tt, *pp, *vv);
  });
}

GucCode gts_pvt_table_ex(Card& card, double table_id, double count, const std::vector<double>& t,
                         const std::vector<double>& p, const std::vector<double>& vb, const std::vector<double>& ve) {
  return download(card, table_id, [&]() -> std::optional<motion::PvtCurve> {
    auto tt = first(t, count), pp = first(p, count), b = first(vb, count), e = first(ve, count);
    if (!tt || !pp || !b || !e) return std::nullopt;
    return motion::pvt_table_ex(*tt, *pp, *b, *e);
  });
}

GucCode gts_pvt_table_complete(Card& card, double table_id, double count, const std::vector<double>& t,
                               const std::vector<double>& p, double vel_begin, double vel_end) {
  return download(card, table_id, [&]() -> std::optional<motion::PvtCurve> {
    auto tt = first(t, count), pp = first(p, count);
    if (!tt || !pp) return std::nullopt;
    return motion::pvt_table_complete(*tt, *pp, vel_begin, vel_end);
  });
}

GucCode gts_pvt_table_percent(Card& card, double table_id, double count, const std::vector<double>& t,
                              const std::vector<double>& p, const std::vector<double>& q, double vel_begin) {
  return download(card, table_id, [&]() -> std::optional<motion::PvtCurve> {
    auto tt = first(t, count), pp = first(p, count), qq = first(q, count);
    if (!tt || !pp || !qq) return std::nullopt;
    return motion::pvt_table_percent(*tt, *pp, *qq, vel_begin);
  });
}

GucCode gts_pvt_table_continuous(Card& card, double table_id, double count, const motion::ContinuousPoints& pts,
                                 double time_begin_ms, bool ex) {
  return download(card, table_id, [&]() -> std::optional<motion::PvtCurve> {
    auto pp = first(pts, count);
    if (!pp) return std::nullopt;
    return motion::pvt_table_continuous(*pp, time_begin_ms, motion::ContinuousAcc::Peak, ex);
  });
}

std::pair<GucCode, std::vector<double>> gts_pvt_percent_calculate(double count, const std::vector<double>& t,
                                                                  const std::vector<double>& p,
                                                                  const std::vector<double>& q, double vel_begin) {
  auto tt = first(t, count), pp = first(p, count), qq = first(q, count);
  std::vector<double> v;
  if (!tt || !pp || !qq || run([&] { v = motion::pvt_percent_calculate(*tt, *pp, *qq, vel_begin); }) != GucCode::Success)
    return {GucCode::ParameterError, {}};
  return {GucCode::Success, v};
}

std::pair<GucCode, std::vector<double>> gts_pvt_continuous_calculate(double count, const motion::ContinuousPoints& pts) {
  auto pp = first(pts, count);
  std::vector<double> t;
  if (!pp || run([&] { t = motion::pvt_continuous_calculate(*pp); }) != GucCode::Success)
    return {GucCode::ParameterError, {}};
  return {GucCode::Success, t};
}

}  // namespace servobench::vendor::googol
