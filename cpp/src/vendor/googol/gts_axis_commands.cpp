// The GUC-ECAT / iDEABOX commands whose arguments are numbers, with their argument checks (vendor/googol/
// gts_commands.hpp; GUC-ECAT seed 002, iDEABOX seed 003; decisions GT13, GU1-GU3, GX1-GX3): the basic axis calls,
// the coordinate systems' buffered and path commands, PVT and FollowEx. Each is a row name -> one function of
// (card, GTS registers, arguments); the checks come first (7), then the card's refusal (1) or an invalid value (7).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/follow_ex.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/segment_geometry.hpp"
#include "servobench/vendor/googol/crd_status.hpp"
#include "servobench/vendor/googol/gt_status.hpp"
#include "servobench/vendor/googol/gts_card.hpp"
#include "servobench/vendor/googol/gts_commands.hpp"

namespace servobench::vendor::googol {

using machine::AxisMode;
using machine::Card;
using motion::CrdPoint;
using motion::PathGenerator;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPosMin = -1073741824, kPosMax = 1073741823;  // iDEABOX L3829 (GUC L449: +-1073741823)
constexpr double kI32Min = -2147483648.0, kI32Max = 2147483647.0;

bool whole_in(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && lo <= v && v <= hi; }
bool open_in(double v, double lo, double hi) { return std::isfinite(v) && lo < v && v < hi; }
bool one_of(double v, std::initializer_list<double> allowed) {
  for (double a : allowed)
    if (v == a) return true;
  return false;
}

struct Ctx {
  Card& card;
  const std::vector<double>& p;
  double at(std::size_t k) const { return p.at(k); }
  std::size_t n() const { return card.axis_count(); }
  bool axis_ok(std::size_t k) const { return whole_in(at(k), 1, static_cast<double>(n())); }
  bool mask_ok(std::size_t k) const { return whole_in(at(k), 1, std::ldexp(1.0, static_cast<int>(n())) - 1); }
  std::size_t axis(std::size_t k) const { return static_cast<std::size_t>(at(k)) - 1; }
  int whole(std::size_t k) const { return static_cast<int>(at(k)); }
  GtsCard& gts() const { return googol::gts(card); }
  double ms() const { return card.servo_period_s() * 1e3; }
};
using Impl = GtsReply (*)(Ctx&);

GtsReply reply(GucCode code) { return GtsReply{code, {}, {}}; }  // a command's code, a failing read's

// f() the manuals' way: 1 when the card refuses it (the card recorded why), 7 when it rejects a value.
template <class F>
GucCode run(F&& f) {
  try {
    f();
  } catch (const motion::MotionCommandRefused&) {  // machine::CardCommandRefused too
    return GucCode::CommandError;
  } catch (const std::invalid_argument&) {         // motion::PathGeometryError too (GUC L906)
    return GucCode::ParameterError;
  } catch (const std::domain_error&) {
    return GucCode::ParameterError;
  } catch (const std::out_of_range&) {
    return GucCode::ParameterError;
  }
  return GucCode::Success;
}

// A command: 7 unless ok, else f() run.
template <class F>
GtsReply cmd(bool ok, F&& f) {
  if (!ok) return reply(GucCode::ParameterError);
  return reply(run(std::forward<F>(f)));
}

// A read: 7 unless ok, else (0, f()) with `kinds` per value ('i' integer, 'f' double, "l" one list).
template <class F>
GtsReply read(bool ok, const char* kinds, F&& f) {
  if (!ok) return reply(GucCode::ParameterError);
  GtsReply r{GucCode::Success, {}, std::string(kinds)};
  const GucCode c = run([&] { r.values = f(); });
  if (c != GucCode::Success) return reply(c);
  return r;
}

// The GUC/iDEABOX double position reads: pulse shifted by the multiple of 2^32 that brings it into -2^31..2^31.
double wrap32(double pulse) { return pulse - 4294967296.0 * std::floor((pulse + 2147483648.0) / 4294967296.0); }

bool crd_ok(const Ctx& c, std::size_t k) { return whole_in(c.at(k), 1, 2); }
bool fifo_ok(const Ctx& c, std::size_t k) { return whole_in(c.at(k), 0, 1); }
PathGenerator& fifo(Ctx& c, std::size_t crd, std::size_t f) {
  return c.card.modes().crd(c.whole(crd)).fifo(c.whole(f));
}

// A buffered push into (crd, fifo) (GUC L985, iDEABOX L2012-2014): 7 unless ok or for a bad crd/fifo, the GtsCard's
// check (7 look-ahead on a 4-D crd, 1 crd not set up), then the push on the FIFO.
template <class F>
GtsReply push(Ctx& c, bool ok, std::size_t crd, std::size_t f, F&& body) {
  if (!ok || !crd_ok(c, crd) || !fifo_ok(c, f)) return reply(GucCode::ParameterError);
  const GucCode g = c.gts().check_push(c.whole(crd), c.whole(f));
  if (g != GucCode::Success) return reply(g);
  return reply(run([&] { body(fifo(c, crd, f)); }));
}

// A buffered command of an axis outside the crd (GUC L647, L1052-1060): 7 for a bad value or axis 1..min(8, axes)
// or an axis of the crd itself, else push.
template <class F>
GtsReply outside(Ctx& c, bool ok, std::size_t axis, F&& body) {
  const double hi = std::min<double>(8, static_cast<double>(c.n()));
  if (!ok || !whole_in(c.at(axis), 1, hi)) return reply(GucCode::ParameterError);
  if (crd_ok(c, 0) && c.card.modes().group_of(c.axis(axis)) == c.whole(0) - 1) return reply(GucCode::ParameterError);
  return push(c, true, 0, c.p.size() - 1, std::forward<F>(body));
}

// synVel, synAcc (0, 32767); velEnd [0, 32767) (GUC L449-481, iDEABOX L3845-3852)
bool seg_ok(double vel, double acc, double vel_end) {
  return open_in(vel, 0, 32767) && open_in(acc, 0, 32767) && std::isfinite(vel_end) && 0 <= vel_end &&
         vel_end < 32767;
}

// GT_LnXY.. (crd, d coordinates, synVel, synAcc[, velEnd], fifo): absolute end point, pulse.
GtsReply line(Ctx& c, int dim, bool g0) {
  CrdPoint end{};
  bool ok = true;
  for (int k = 0; k < dim; ++k) ok = ok && whole_in(c.at(1 + k), kPosMin, kPosMax), end[k] = c.at(1 + k);
  const std::size_t v = 1 + dim;
  const double vel_end = g0 ? 0.0 : c.at(v + 2);
  ok = ok && seg_ok(c.at(v), c.at(v + 1), vel_end);
  return push(c, ok, 0, c.p.size() - 1, [&](PathGenerator& f) {
    CrdPoint e = f.tail();
    for (int k = 0; k < dim; ++k) e[k] = end[k];
    f.line(e, c.at(v), c.at(v + 1), vel_end, g0);
  });
}

// GT_Arc..R (crd, p1, p2, radius, circleDir, synVel, synAcc, velEnd, fifo) and GT_Arc..C (crd, p1, p2, c1, c2,
// circleDir, ...): the end point's two plane coordinates replace the FIFO's tail; radius or centre offset.
GtsReply arc(Ctx& c, motion::ArcPlane plane, bool radius) {
  const std::size_t d = radius ? 4 : 5;  // circleDir's index
  bool ok = whole_in(c.at(1), kPosMin, kPosMax) && whole_in(c.at(2), kPosMin, kPosMax) && one_of(c.at(d), {0, 1}) &&
            seg_ok(c.at(d + 1), c.at(d + 2), c.at(d + 3)) && std::isfinite(c.at(3)) &&
            (radius || std::isfinite(c.at(4)));
  const auto [i0, i1] = plane == motion::ArcPlane::XY ? std::pair{0, 1}
                        : plane == motion::ArcPlane::YZ ? std::pair{1, 2} : std::pair{2, 0};
  return push(c, ok, 0, d + 4, [&](PathGenerator& f) {
    CrdPoint end = f.tail();
    end[i0] = c.at(1), end[i1] = c.at(2);
    const bool ccw = c.at(d) != 0;
    const int dim = f.coords().dim();
    f.push_segment(radius ? motion::PathSegmentGeometry::arc_end_radius(f.tail(), end, dim, plane, c.at(3), ccw)
                          : motion::PathSegmentGeometry::arc_center_offset(f.tail(), end, dim, plane, c.at(3),
                                                                           c.at(4), ccw),
                   c.at(d + 1), c.at(d + 2), c.at(d + 3));
  });
}

// A change of a FollowEx axis's setup (its present setup with `change` applied).
template <class F>
void follow_change(Ctx& c, std::size_t a, F&& change) {
  motion::FollowExSetup s = c.card.modes().follow(a).setup();
  change(s);
  c.card.modes().follow_configure(a, s);
}

std::vector<double> counts(long long v) { return {static_cast<double>(v)}; }

const std::unordered_map<std::string, Impl>& commands() {
  using V = std::vector<double>;
  static const std::unordered_map<std::string, Impl> table = {
      // -- basic axis calls
      {"GT_AxisOn", [](Ctx& c) { return cmd(c.axis_ok(0), [&] { c.card.axis_on(c.axis(0)); }); }},
      {"GT_AxisOff", [](Ctx& c) { return cmd(c.axis_ok(0), [&] { c.card.axis_off(c.axis(0)); }); }},
      {"GT_ClrSts", [](Ctx& c) {
         const bool ok = c.axis_ok(0) && whole_in(c.at(1), 1, static_cast<double>(c.n()) - c.at(0) + 1);
         return cmd(ok, [&] {
           for (std::size_t k = c.axis(0); k < c.axis(0) + static_cast<std::size_t>(c.at(1)); ++k)
             c.card.clear_events(k, 0xFFF);
         });
       }},
      {"GT_ZeroPos", [](Ctx& c) {
         const bool ok = c.axis_ok(0) && whole_in(c.at(1), 1, static_cast<double>(c.n()) - c.at(0) + 1);
         return cmd(ok, [&] { c.card.zero_pos_range(c.axis(0), static_cast<std::size_t>(c.at(1))); });
       }},
      {"GT_GetSts", [](Ctx& c) {
         return read(c.axis_ok(0), "i", [&] { return V{double(gt_axis_status(c.card, c.axis(0)))}; }); }},
      {"GT_GetPrfPos", [](Ctx& c) {
         return read(c.axis_ok(0), "f", [&] { return V{wrap32(double(c.card.profile_pos(c.axis(0))))}; }); }},
      {"GT_GetPrfVel", [](Ctx& c) {  // with GT_SetAxisPrfVelFilter the mean over 2^exp ticks (GS9)
         return read(c.axis_ok(0), "f", [&] {
           const std::size_t a = c.axis(0);
           return V{c.gts().prf_vel_filter(a) ? c.gts().filtered_prf_vel(a) : c.card.profile_vel(a) / c.ms()};
         });
       }},
      {"GT_GetEncPos", [](Ctx& c) {
         return read(c.axis_ok(0), "f", [&] { return V{wrap32(c.card.actual_pos(c.axis(0)))}; }); }},
      {"GT_PrfTrap", [](Ctx& c) { return cmd(c.axis_ok(0), [&] { c.card.set_mode(c.axis(0), AxisMode::TCurve); }); }},
      {"GT_PrfJog", [](Ctx& c) { return cmd(c.axis_ok(0), [&] { c.card.set_mode(c.axis(0), AxisMode::Jog); }); }},
      {"GT_SetVel", [](Ctx& c) {
         return cmd(c.axis_ok(0) && std::isfinite(c.at(1)), [&] { c.card.stage_vel(c.axis(0), c.at(1) * c.ms()); }); }},
      {"GT_SetPos", [](Ctx& c) {
         return cmd(c.axis_ok(0) && whole_in(c.at(1), kPosMin, kPosMax), [&] { c.card.stage_pos(c.axis(0), c.at(1)); });
       }},
      {"GT_Update", [](Ctx& c) {
         return cmd(c.mask_ok(0), [&] { c.card.update(static_cast<std::uint32_t>(c.at(0))); }); }},
      // -- coordinate systems: lines and arcs (GUC §4.1 L313-1114, iDEABOX §4.3)
      {"GT_LnXY", [](Ctx& c) { return line(c, 2, false); }},
      {"GT_LnXYZ", [](Ctx& c) { return line(c, 3, false); }},
      {"GT_LnXYZA", [](Ctx& c) { return line(c, 4, false); }},
      {"GT_LnXYG0", [](Ctx& c) { return line(c, 2, true); }},
      {"GT_LnXYZG0", [](Ctx& c) { return line(c, 3, true); }},
      {"GT_LnXYZAG0", [](Ctx& c) { return line(c, 4, true); }},
      {"GT_ArcXYR", [](Ctx& c) { return arc(c, motion::ArcPlane::XY, true); }},
      {"GT_ArcYZR", [](Ctx& c) { return arc(c, motion::ArcPlane::YZ, true); }},
      {"GT_ArcZXR", [](Ctx& c) { return arc(c, motion::ArcPlane::ZX, true); }},
      {"GT_ArcXYC", [](Ctx& c) { return arc(c, motion::ArcPlane::XY, false); }},
      {"GT_ArcYZC", [](Ctx& c) { return arc(c, motion::ArcPlane::YZ, false); }},
      {"GT_ArcZXC", [](Ctx& c) { return arc(c, motion::ArcPlane::ZX, false); }},
      // -- buffered commands (GUC L588-665)
      {"GT_BufIO", [](Ctx& c) {  // MC_GPO 12 -> 0, MC_ENABLE 10 -> 1, MC_CLEAR 11 -> 2 (gts.h)
         const double t = c.at(1);
         const bool ok = one_of(t, {10, 11, 12}) && whole_in(c.at(2), 0, 0xFFFF) && whole_in(c.at(3), 0, 0xFFFF);
         return push(c, ok, 0, 4, [&](PathGenerator& f) {
           f.buf_io(t == 12 ? 0 : t == 10 ? 1 : 2, static_cast<std::uint32_t>(c.at(2)),
                    static_cast<std::uint32_t>(c.at(3)));
         });
       }},
      {"GT_BufDelay", [](Ctx& c) {
         return push(c, whole_in(c.at(1), 0, 16383), 0, 2, [&](PathGenerator& f) { f.buf_delay(c.at(1)); }); }},
      {"GT_BufDA", [](Ctx& c) {
         const bool ok = whole_in(c.at(1), 1, 8) && whole_in(c.at(2), -32768, 32767);
         return push(c, ok, 0, 3, [&](PathGenerator& f) { f.buf_da(c.whole(1), c.at(2)); });
       }},
      {"GT_BufLmtsOn", [](Ctx& c) {
         const bool ok = whole_in(c.at(1), 1, 8) && one_of(c.at(2), {-1, 0, 1});
         return push(c, ok, 0, 3, [&](PathGenerator& f) { f.buf_lmts(c.whole(1), c.whole(2), true); });
       }},
      {"GT_BufLmtsOff", [](Ctx& c) {
         const bool ok = whole_in(c.at(1), 1, 8) && one_of(c.at(2), {-1, 0, 1});
         return push(c, ok, 0, 3, [&](PathGenerator& f) { f.buf_lmts(c.whole(1), c.whole(2), false); });
       }},
      {"GT_BufSetStopIo", [](Ctx& c) {  // index 1..8, GPI (4) 1..16
         const bool ok = whole_in(c.at(1), 1, 8) && one_of(c.at(2), {0, 1}) && whole_in(c.at(3), 0, 4) &&
                         whole_in(c.at(4), 1, c.at(3) == 4 ? 16 : 8);
         return push(c, ok, 0, 5, [&](PathGenerator& f) {
           f.buf_set_stop_io(c.whole(1), c.whole(2), c.whole(3), c.whole(4)); });
       }},
      {"GT_BufMove", [](Ctx& c) {
         const bool ok = whole_in(c.at(2), kI32Min, kI32Max) && open_in(c.at(3), 0, kInf) &&
                         open_in(c.at(4), 0, kInf) && one_of(c.at(5), {0, 1});
         return outside(c, ok, 1, [&](PathGenerator& f) {
           f.buf_move(c.whole(1), c.at(2), c.at(3), c.at(4), c.at(5) != 0); });
       }},
      {"GT_BufGear", [](Ctx& c) {
         return outside(c, whole_in(c.at(2), kI32Min, kI32Max), 1,
                        [&](PathGenerator& f) { f.buf_gear(c.whole(1), c.at(2)); });
       }},
      {"GT_SetUserSegNum", [](Ctx& c) {
         return push(c, whole_in(c.at(1), kI32Min, kI32Max), 0, 2,
                     [&](PathGenerator& f) { f.set_user_seg_num(static_cast<long long>(c.at(1))); });
       }},
      // -- coordinate-system state (GUC L666-712, L979, L5499-5519; iDEABOX L4527-4599, L5581-5595, L7182-7441)
      {"GT_GetUserSegNum", [](Ctx& c) {
         return read(crd_ok(c, 0) && fifo_ok(c, 1), "i", [&] {
           return counts(fifo(c, 0, 1).state().user_seg_num); });
       }},
      {"GT_GetRemainderSegNum", [](Ctx& c) {
         return read(crd_ok(c, 0) && fifo_ok(c, 1), "i", [&] {
           return counts(fifo(c, 0, 1).remaining_segments()); });
       }},
      {"GT_CrdSpace", [](Ctx& c) {
         return read(crd_ok(c, 0) && fifo_ok(c, 1), "i", [&] { return counts(fifo(c, 0, 1).fifo_space()); }); }},
      {"GT_CrdClear", [](Ctx& c) { return cmd(crd_ok(c, 0) && fifo_ok(c, 1), [&] { fifo(c, 0, 1).clear(); }); }},
      {"GT_CrdStart", [](Ctx& c) {
         return cmd(whole_in(c.at(0), 1, 3) && whole_in(c.at(1), 0, 3), [&] {
           c.card.modes().crd_start(static_cast<std::uint32_t>(c.at(0)), static_cast<std::uint32_t>(c.at(1))); });
       }},
      {"GT_CrdStatus", [](Ctx& c) {
         return read(crd_ok(c, 0) && fifo_ok(c, 1), "ii", [&] {
           const GucCrdStatus s = guc_crd_status(c.card, c.whole(0), c.whole(1));
           return V{double(s.run), double(s.segment)};
         });
       }},
      {"GT_SetOverride", [](Ctx& c) {
         const double r = c.at(1);
         return cmd(crd_ok(c, 0) && std::isfinite(r) && 0 < r && r <= 1, [&] {
           for (int k : {0, 1}) c.card.modes().crd(c.whole(0)).fifo(k).set_override(r); });
       }},
      {"GT_SetCrdStopDec", [](Ctx& c) {
         const bool ok = crd_ok(c, 0) && open_in(c.at(1), 0, 32767) && open_in(c.at(2), 0, 32767);
         return cmd(ok, [&] {
           for (int k : {0, 1}) c.card.modes().crd(c.whole(0)).fifo(k).set_stop_dec(c.at(1), c.at(2));
           c.gts().set_crd_stop_dec(c.whole(0), c.at(1), c.at(2));
         });
       }},
      {"GT_GetCrdPos", [](Ctx& c) {
         return read(crd_ok(c, 0), "l", [&] {
           const CrdPoint p = c.card.modes().crd_pos(c.whole(0));
           return V(p.begin(), p.begin() + c.card.modes().crd(c.whole(0)).coords().dim());
         });
       }},
      {"GT_GetCrdVel", [](Ctx& c) {
         return read(crd_ok(c, 0), "f", [&] { return V{c.card.modes().crd(c.whole(0)).state().speed}; }); }},
      // -- PVT (GUC §4.2 L1116-2100, iDEABOX §4.4)
      {"GT_PrfPvt", [](Ctx& c) { return cmd(c.axis_ok(0), [&] { c.card.modes().set_pvt(c.axis(0)); }); }},
      {"GT_PvtTableSelect", [](Ctx& c) {
         return cmd(c.axis_ok(0) && whole_in(c.at(1), 1, 32),
                    [&] { c.card.modes().pvt_select(c.axis(0), c.whole(1)); });
       }},
      {"GT_SetPvtLoop", [](Ctx& c) {
         return cmd(c.axis_ok(0) && whole_in(c.at(1), 0, kI32Max),
                    [&] { c.card.modes().pvt_loop(c.axis(0), c.at(1)); });
       }},
      {"GT_GetPvtLoop", [](Ctx& c) {
         return read(c.axis_ok(0), "ii", [&] {
           const motion::PvtAxis& a = c.card.modes().pvt(c.axis(0));
           return V{double(a.loop_count()), double(a.loop())};
         });
       }},
      {"GT_PvtStart", [](Ctx& c) {
         return cmd(c.mask_ok(0), [&] { c.card.modes().pvt_start(static_cast<std::uint32_t>(c.at(0))); }); }},
      {"GT_PvtStatus", [](Ctx& c) {
         return read(c.axis_ok(0), "if", [&] {
           const motion::PvtAxis& a = c.card.modes().pvt(c.axis(0));
           return V{double(a.table_id()), a.time_ms()};
         });
       }},
      // -- FollowEx (iDEABOX §2.1 L394-929, API L4612-5448, L7212-7417)
      {"GT_PrfFollowEx", [](Ctx& c) {  // the master is axis 1 (axis 2 for profile 1) until SetFollowMasterEx (V62)
         return cmd(c.axis_ok(0) && one_of(c.at(1), {-1, 0, 1}), [&] {
           motion::FollowExSetup s;
           s.dir = c.at(1);
           c.card.modes().set_follow(c.axis(0), s, machine::FollowMaster{c.axis(0) == 0 ? 1u : 0u});
         });
       }},
      {"GT_SetFollowMasterEx", [](Ctx& c) {
         const bool ok = c.axis_ok(0) && c.axis_ok(1) && one_of(c.at(2), {1, 2, 3}) && one_of(c.at(3), {0, 1});
         return cmd(ok, [&] {
           c.card.modes().follow_master(c.axis(0), machine::FollowMaster{c.axis(1)});
           follow_change(c, c.axis(0), [&](motion::FollowExSetup& s) {
             s.master_type = c.at(2), s.master_item = c.at(3); });
         });
       }},
      {"GT_GetFollowMasterEx", [](Ctx& c) {
         return read(c.axis_ok(0), "iii", [&] {
           const auto& s = c.card.modes().follow(c.axis(0)).setup();
           return V{double(c.card.modes().follow_master_of(c.axis(0)).master + 1), std::trunc(s.master_type),
                    std::trunc(s.master_item)};
         });
       }},
      {"GT_SetFollowMemoryEx", [](Ctx& c) {
         return cmd(c.axis_ok(0) && one_of(c.at(1), {0, 1, 2}), [&] {
           follow_change(c, c.axis(0), [&](motion::FollowExSetup& s) { s.memory = c.at(1); }); });
       }},
      {"GT_GetFollowMemoryEx", [](Ctx& c) {
         return read(c.axis_ok(0), "i", [&] { return V{std::trunc(c.card.modes().follow(c.axis(0)).setup().memory)}; });
       }},
      {"GT_SetFollowExMaxSegment", [](Ctx& c) {
         return cmd(c.axis_ok(0) && whole_in(c.at(1), 1, kI32Max), [&] {
           follow_change(c, c.axis(0), [&](motion::FollowExSetup& s) { s.max_segment = c.at(1); }); });
       }},
      {"GT_FollowClearEx", [](Ctx& c) {
         return cmd(c.axis_ok(0) && one_of(c.at(1), {0, 1}),
                    [&] { c.card.modes().follow(c.axis(0)).clear(c.whole(1)); });
       }},
      {"GT_FollowDataPercentEx", [](Ctx& c) {
         return cmd(c.axis_ok(0) && one_of(c.at(3), {0, 1, 2, 3}) && one_of(c.at(5), {0, 1}), [&] {
           c.card.modes().follow(c.axis(0)).data_percent(c.at(1), c.at(2), static_cast<motion::FollowSegmentType>(
                                                             c.whole(3)), c.at(4), c.whole(5));
         });
       }},
      {"GT_FollowSpaceEx", [](Ctx& c) {
         return read(c.axis_ok(0) && one_of(c.at(1), {0, 1}), "i", [&] {
           return counts(c.card.modes().follow(c.axis(0)).space(c.whole(1))); });
       }},
      {"GT_SetFollowEventEx", [](Ctx& c) {
         const bool ok = c.axis_ok(0) && one_of(c.at(1), {1, 2}) && one_of(c.at(2), {-1, 1}) &&
                         whole_in(c.at(3), kI32Min, kI32Max);
         return cmd(ok, [&] {
           follow_change(c, c.axis(0), [&](motion::FollowExSetup& s) {
             s.event = c.at(1), s.master_dir = c.at(2), s.event_pos = c.at(3); });
         });
       }},
      {"GT_GetFollowEventEx", [](Ctx& c) {
         return read(c.axis_ok(0), "iii", [&] {
           const auto& s = c.card.modes().follow(c.axis(0)).setup();
           return V{std::trunc(s.event), std::trunc(s.master_dir), std::trunc(s.event_pos)};
         });
       }},
      {"GT_SetFollowLoopEx", [](Ctx& c) {
         return cmd(c.axis_ok(0) && whole_in(c.at(1), -32768, 32767), [&] {
           follow_change(c, c.axis(0), [&](motion::FollowExSetup& s) { s.loop = c.at(1); }); });
       }},
      {"GT_GetFollowLoopEx", [](Ctx& c) {
         return read(c.axis_ok(0), "i", [&] { return counts(c.card.modes().follow(c.axis(0)).loop_count()); }); }},
      {"GT_FollowStartEx", [](Ctx& c) {
         const bool ok = c.mask_ok(0) && whole_in(c.at(1), 0, std::ldexp(1.0, static_cast<int>(c.n())) - 1);
         return cmd(ok, [&] {
           c.card.modes().follow_start(static_cast<std::uint32_t>(c.at(0)), static_cast<std::uint32_t>(c.at(1))); });
       }},
      {"GT_FollowSwitchEx", [](Ctx& c) {
         return cmd(c.mask_ok(0), [&] { c.card.modes().follow_switch(static_cast<std::uint32_t>(c.at(0))); }); }},
  };
  return table;
}

}  // namespace

std::vector<std::string> gts_command_names() {
  std::vector<std::string> names;
  for (const auto& [name, impl] : commands()) names.push_back(name);
  return names;
}

GtsReply gts_command(Card& card, const std::string& name, const std::vector<double>& args) {
  const auto it = commands().find(name);
  if (it == commands().end()) throw std::invalid_argument("gts_command: '" + name + "' is not a GTS card command");
  Ctx c{card, args};
  return it->second(c);
}

GucCode gts_follow_data_complete(Card& card, double profile, double fifo, double n, const std::vector<double>& master,
                                 const std::vector<double>& slave, double ratio_begin, double ratio_end) {
  if (!whole_in(profile, 1, static_cast<double>(card.axis_count())) || !one_of(fifo, {0, 1}) ||
      !whole_in(n, 2, kI32Max) || n > static_cast<double>(master.size()) || n > static_cast<double>(slave.size()))
    return GucCode::ParameterError;
  const auto k = static_cast<std::ptrdiff_t>(n);
  return run([&] {
    card.modes().follow(static_cast<std::size_t>(profile) - 1)
        .data_complete(std::vector<double>(master.begin(), master.begin() + k),
                       std::vector<double>(slave.begin(), slave.begin() + k), ratio_begin, ratio_end,
                       static_cast<int>(fifo));
  });
}

}  // namespace servobench::vendor::googol
