#include "servobench/vendor/googol/ge_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/lookahead.hpp"
#include "servobench/motion/path_segment.hpp"
#include "servobench/vendor/googol/crd_status.hpp"
#include "servobench/vendor/googol/ge_crd.hpp"

namespace servobench::vendor::googol {

using machine::CommandFault;
using motion::CrdPoint;
using motion::PathGenerator;
using motion::PathSegmentGeometry;

namespace {

constexpr double kPosMin = -1073741824.0, kPosMax = 1073741823.0;  // L991, L5457-5463
constexpr double kVelMax = 40957.0;                                // L5780-5786
constexpr double kAccMax = 102400.0;                               // L5435-5437

bool real_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi; }
bool int_in(double v, double lo, double hi) { return real_in(v, lo, hi) && v == std::floor(v); }
bool feed_ok(double v, double hi) { return real_in(v, 0, hi) && v > 0; }  // 4 otherwise (L280)
bool pts_ok(const std::vector<double>& pts) {
  return std::all_of(pts.begin(), pts.end(), [](double p) { return real_in(p, kPosMin, kPosMax); });
}

motion::ArcPlane arc_plane(GePlane p) { return static_cast<motion::ArcPlane>(static_cast<int>(p)); }
std::pair<int, int> plane_index(GePlane p) {
  return p == GePlane::XY ? std::pair{0, 1} : p == GePlane::YZ ? std::pair{1, 2} : std::pair{2, 0};
}
int plane_dim(GePlane p) { return p == GePlane::XY ? 2 : 3; }

// A geometry the path layer refuses: (2/3/5 its GT code; 7 any other bad value).
template <class MakeFn>
std::optional<PathSegmentGeometry> geometry(MakeFn&& make, GeCode& code) {
  try {
    return make();
  } catch (const motion::PathGeometryError& e) {
    code = static_cast<GeCode>(e.gt_code());  // the SX geometry codes 2/3/5 (Table 2-2 L272-283)
  } catch (const std::invalid_argument&) {
    code = GeCode::ParameterError;
  }
  return std::nullopt;
}

}  // namespace

GeList::GeList(machine::Card& card) : card_(card) { reset(); }

void GeList::reset() {
  st_ = GeListState{};
  st_.offsets.assign(card_.axis_count(), 0.0);
}

GeCode GeList::fault(int bit) {
  card_.record_fault(-1, bit != 6 ? CommandFault::CrdStateError : CommandFault::AxisStateError);
  st_.cmd_bit = bit;
  return GeCode::CommandError;
}

std::optional<int> GeList::command_bit() const {
  if (st_.cmd_bit && card_.last_fault() == CommandFault::CrdStateError) return st_.cmd_bit;
  return std::nullopt;
}

// The crd's generator, (re)built at the present profile positions when asked and nothing is kept (V101).
PathGenerator& GeList::generator(bool rebuild) {
  if (!ge_crd_exists(card_) || (rebuild && st_.dirty)) {
    const int n = static_cast<int>(std::min<std::size_t>(st_.dim ? st_.dim : 4, card_.axis_count()));
    GeCrdSetup s;
    s.offsets.assign(st_.offsets.begin(), st_.offsets.begin() + n);
    s.start_vel = st_.strt_vel;
    s.max_vel = st_.max_vel;
    s.stop_acc = st_.stp_acc;
    s.fifo_capacity = st_.capacity;
    s.dim = n;
    ge_crd_setup(card_, s);
    outputs();  // the new crd's word against the old one's last merge (as the dialect did, V101)
    st_.gpo_seen = 0;
    st_.dirty = false;
    st_.mv_pushed = 0;
    PathGenerator& path = ge_path(card_);
    path.set_override(st_.override);
    path.set_g0_override(st_.override_g0);
  }
  return ge_path(card_);
}

// Empty, at the present profile positions: cleared, or rebuilt when a setting changed or an axis moved outside
// the path (ZeroPos, AxisOn) (V101).
PathGenerator& GeList::fresh() {
  st_.dim = 0;
  const int all = static_cast<int>(std::min<std::size_t>(4, card_.axis_count()));
  if (ge_crd_exists(card_) && !st_.dirty && !ge_path(card_).lookahead_on() && ge_path(card_).coords().dim() == all) {
    PathGenerator& path = ge_path(card_);
    bool here = true;
    for (int k = 0; k < all; ++k)
      here = here && std::abs(path.state().pos[k] + st_.offsets[k] -
                              static_cast<double>(card_.profile_pos(static_cast<std::size_t>(k)))) < 0.5;
    if (here) {
      path.clear();
      return path;
    }
  }
  st_.dirty = true;
  return generator(true);
}

bool GeList::moving(const PathGenerator& p) const {
  return p.busy() || (p.running() && p.remaining_segments() > 0) || (st_.started && st_.open && !p.stopped());
}

// A stopped buffer that RestoreMtn can resume (breakpoint and unexecuted segments); a stopped immediate move
// keeps none (L1654).
bool GeList::resumable(const PathGenerator& p) const {
  return st_.buffer && st_.started && p.has_breakpoint() && p.remaining_segments() > 0;
}

template <class Fn>
GeCode GeList::run(Fn&& fn) {
  try {
    fn();
  } catch (const motion::MotionCommandRefused&) {  // CardCommandRefused too
    return fault(8);
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  }
  return GeCode::Success;
}

// A line or arc (pulse, absolute): buffer mode appends it (the Mv dimension fixes the dimension, L5244),
// immediate mode runs it at once at SynVel/SynAcc (L1445-1492).
template <class MakeFn>
GeCode GeList::path_cmd(int dim, MakeFn&& make, bool g0) {
  GeCode code = GeCode::Success;
  if (st_.open) {
    if (!st_.mv || dim > st_.mv_dim) return fault(8);  // no Mv* after StrtList, or 3-D after MvXY (L335, L5244)
    PathGenerator& path = generator();
    if (path.fifo_space() < 1 + static_cast<long long>(st_.pending_io.size())) return fault(15);  // L1575, L347
    const int n = path.coords().dim();
    auto seg = geometry([&] { return make(path.tail(), n); }, code);
    if (!seg) return code;
    const double vel = st_.syn_vel > 0 ? st_.syn_vel : st_.mv_vel;
    for (const auto& [mask, value] : st_.pending_io) path.buf_io(0, mask, value);
    st_.pending_io.clear();
    if (st_.dcc_vel) path.push_segment(*seg, vel, st_.mv_acc, *st_.dcc_vel, g0);
    else path.push_segment(*seg, vel, st_.mv_acc, 0.0, g0, !g0);
    st_.dcc_vel.reset();
    st_.io_count = st_.delay_count = 0;
    ++st_.pushed;
    st_.ends.push_back(seg->end());
    st_.end_dims.push_back(seg->dim());
    return GeCode::Success;
  }
  PathGenerator* path = nullptr;
  try {
    path = &generator();
  } catch (const motion::MotionCommandRefused&) {
    return fault(8);
  }
  if (moving(*path)) return fault(8);                           // while the path moves (L1492, L335)
  if (!(st_.syn_vel > 0 && st_.syn_acc > 0)) return fault(8);    // no feed set: a bad path parameter
  const bool kept = resumable(*path);
  if (!kept) {
    try {
      path = &fresh();
    } catch (const motion::MotionCommandRefused&) {
      return fault(8);
    }
  }
  const CrdPoint start = path->state().pos;
  auto seg = geometry([&] { return make(start, 4); }, code);
  if (!seg) return code;
  if (kept) {
    // a stopped buffer waits for RestoreMtn; a line runs at once from where the path stands (L1652, V104)
    if (seg->kind() != motion::SegmentKind::Line) return fault(8);
    return run([&] {
      card_.modes().before_group_start(kGeCrdSlot);
      path->move_immediate(seg->end(), st_.syn_vel, st_.syn_acc);
    });
  }
  const GeCode rtn = run([&] {
    path->push_segment(*seg, st_.syn_vel, st_.syn_acc, 0.0, g0, false, true);
    st_.ends = {seg->end()};
    st_.end_dims = {seg->dim()};
    card_.modes().before_group_start(kGeCrdSlot);
    path->start();
  });
  if (rtn == GeCode::Success) {
    st_.buffer = false;  // immediate input mode again (crd bit 7, V103)
    st_.started = false;
    st_.mv_pushed = 0;
  }
  return rtn;
}

GeCode GeList::line(const std::vector<double>& point, bool g0) {
  if (!pts_ok(point)) return GeCode::LineLengthError;
  return path_cmd(static_cast<int>(point.size()), [&](const CrdPoint& t, int n) {
    if (static_cast<int>(point.size()) > n) throw std::invalid_argument("GE line: more coordinates than the crd");
    CrdPoint end = t;
    for (std::size_t k = 0; k < point.size(); ++k) end[k] = point[k];
    return PathSegmentGeometry::line(t, end, n);
  }, g0);
}

GeCode GeList::arc_center(GePlane plane, double c1, double c2, double angle) {
  if (!real_in(c1, kPosMin, kPosMax) || !real_in(c2, kPosMin, kPosMax)) return GeCode::LineLengthError;
  if (!real_in(angle, -360, 360)) return GeCode::ParameterError;
  return path_cmd(plane_dim(plane), [&](const CrdPoint& t, int n) {
    return PathSegmentGeometry::arc_center_angle(t, n, arc_plane(plane), c1, c2, angle);
  }, false);
}

GeCode GeList::arc_radius(GePlane plane, double e1, double e2, double r, double direction) {
  if (!pts_ok({e1, e2, r})) return GeCode::LineLengthError;
  if (!int_in(direction, -1, 1) || direction == 0) return GeCode::ParameterError;
  const auto [i, j] = plane_index(plane);
  return path_cmd(plane_dim(plane), [&, i = i, j = j](const CrdPoint& t, int n) {
    if (i >= n || j >= n) throw std::invalid_argument("GE arc: plane outside the crd");
    CrdPoint end = t;
    end[i] = e1;
    end[j] = e2;
    return PathSegmentGeometry::arc_end_radius(t, end, n, arc_plane(plane), r, direction == 1);
  }, false);
}

// -- feed ---------------------------------------------------------------------------------------------------------
GeCode GeList::set_syn_vel(double vel) {
  if (!feed_ok(vel, kVelMax)) return GeCode::SynParamError;
  st_.syn_vel = vel;
  return GeCode::Success;
}

GeCode GeList::set_syn_acc(double acc) {
  if (st_.open) return fault(8);  // immediate mode only (L1411-1413, L335)
  if (!feed_ok(acc, kAccMax)) return GeCode::SynParamError;
  st_.syn_acc = acc;
  return GeCode::Success;
}

// StrtVel / MaxVel / StpAcc: set-up commands, refused while the path moves (L335); 4 for a bad value.
template <class Set>
GeCode GeList::setting(double value, double hi, bool zero_ok, Set&& set) {
  if (ge_crd_exists(card_) && moving(ge_path(card_))) return fault(8);
  if (!real_in(value, 0, hi) || (value == 0 && !zero_ok)) return GeCode::SynParamError;
  set();
  st_.dirty = true;
  return GeCode::Success;
}

GeCode GeList::set_strt_vel(double vel) { return setting(vel, kVelMax, true, [&] { st_.strt_vel = vel; }); }
GeCode GeList::set_max_vel(double vel) { return setting(vel, kVelMax, false, [&] { st_.max_vel = vel; }); }
GeCode GeList::set_stp_acc(double acc) {
  return setting(acc, kAccMax, false, [&] {
    st_.stp_acc = acc;
    if (ge_crd_exists(card_)) ge_path(card_).set_stop_dec(0, acc);
  });
}

GeCode GeList::set_override(double ratio, bool g0) {
  if (!real_in(ratio, 0, 2) || ratio == 0) return GeCode::ParameterError;  // a multiplier, (0, 2] (V105)
  (g0 ? st_.override_g0 : st_.override) = ratio;
  if (ge_crd_exists(card_)) g0 ? ge_path(card_).set_g0_override(ratio) : ge_path(card_).set_override(ratio);
  return GeCode::Success;
}

GeCode GeList::set_dcc_vel(double vel) {
  if (!st_.open || !st_.mv) return fault(8);  // buffer only (L5492-5500)
  if (!real_in(vel, 0, kVelMax)) return GeCode::SynParamError;
  st_.dcc_vel = vel;
  return GeCode::Success;
}

GeCode GeList::map_cnt(double axis, double count) {
  if (!int_in(axis, 1, static_cast<double>(std::min<std::size_t>(4, card_.axis_count())))) {
    card_.record_fault(-1, CommandFault::IllegalControlParam);
    return GeCode::ParameterError;
  }
  bool any_moving = false;
  for (std::size_t a = 0; a < card_.axis_count(); ++a) any_moving = any_moving || card_.moving(a);
  if (any_moving || st_.open || !real_in(count, kPosMin, kPosMax)) return fault(6);  // L1960-1971
  st_.offsets[static_cast<std::size_t>(axis) - 1] = count;
  st_.dirty = true;
  return GeCode::Success;
}

// -- buffer -------------------------------------------------------------------------------------------------------
GeCode GeList::strt_list() {
  if (st_.open) return fault(9);
  if (ge_crd_exists(card_)) {
    const PathGenerator& path = ge_path(card_);
    if (path.busy() || (st_.started && path.running() && !path.stopped())) return fault(9);  // L1549, L5861
  }
  try {
    fresh();
  } catch (const motion::MotionCommandRefused&) {
    return fault(9);
  }
  st_.buffer = st_.open = true;
  st_.mv = st_.started = false;
  st_.mv_pushed = st_.pushed = 0;
  st_.io_count = st_.delay_count = 0;
  st_.dcc_vel.reset();
  st_.pending_io.clear();
  st_.ends.clear();
  st_.end_dims.clear();
  st_.ex_active = false;
  return GeCode::Success;
}

GeCode GeList::mv(const std::vector<double>& point, double vel, double acc) {
  if (!st_.open || st_.mv) return fault(8);  // Mv* only right after StrtList, once (L1551, L335)
  if (!pts_ok(point)) return GeCode::LineLengthError;
  if (!feed_ok(vel, kVelMax) || !feed_ok(acc, kAccMax)) return GeCode::SynParamError;
  PathGenerator& path = generator();
  const CrdPoint t = path.tail();
  const int n = path.coords().dim();
  if (static_cast<int>(point.size()) > n) return GeCode::ParameterError;
  CrdPoint end = t;
  for (std::size_t k = 0; k < point.size(); ++k) end[k] = point[k];
  if (end != t) {
    path.push_segment(PathSegmentGeometry::line(t, end, n), vel, acc, 0.0, true);
    st_.mv_pushed = 1;
    st_.ends.push_back(end);
    st_.end_dims.push_back(n);
  }
  st_.mv = true;
  st_.mv_dim = static_cast<int>(point.size());
  st_.mv_vel = vel;
  st_.mv_acc = acc;
  st_.syn_vel = vel;  // the feed of the later segments until SetSynVel (L1555)
  return GeCode::Success;
}

GeCode GeList::end_list() {
  if (!st_.open) return fault(9);
  st_.open = false;
  return GeCode::Success;
}

GeCode GeList::add_list() {
  if (st_.open || !st_.buffer || !st_.mv) return fault(9);
  st_.open = true;
  return GeCode::Success;
}

GeCode GeList::strt_mtn() {
  if (!st_.buffer || !st_.mv) return fault(9);
  PathGenerator& path = generator();
  if (path.busy() || st_.started) return fault(9);  // while path motion runs, or to resume (L1664)
  const GeCode rtn = run([&] {
    card_.modes().before_group_start(kGeCrdSlot);
    path.start();
  });
  if (rtn == GeCode::Success) st_.started = true;
  return rtn;
}

GeCode GeList::stp_mtn(bool abrupt) {
  if (!ge_crd_exists(card_)) return GeCode::Success;
  try {
    ge_path(card_).stop(abrupt);
  } catch (const motion::MotionCommandRefused&) {
    return fault(8);
  }
  if (st_.buffer) st_.open = false;  // both stops close the buffer; the breakpoint is kept (L1648-1650)
  return GeCode::Success;
}

GeCode GeList::restore_mtn() {
  if (!st_.started || !ge_crd_exists(card_)) return fault(9);
  PathGenerator& path = ge_path(card_);
  if (path.busy() || !path.stopped() || !resumable(path)) return fault(9);
  return run([&] {
    card_.modes().before_group_start(kGeCrdSlot);
    path.start();
  });
}

// -1 in immediate mode (L3754); bit 8 without Mv; none when the buffer takes it.
std::optional<GeCode> GeList::buf_gate() {
  if (!st_.open) return GeCode::CommError;
  if (!st_.mv) return fault(8);
  return std::nullopt;
}

GeCode GeList::buf_io(double word) {
  if (auto g = buf_gate()) return *g;
  if (!int_in(word, 0, 0xFFFF)) return GeCode::ParameterError;
  if (st_.io_count >= 2) return fault(8);  // at most two between motion commands (L3750-3756)
  PathGenerator& path = ge_path(card_);
  if (path.fifo_space() < 1) return fault(15);
  path.buf_io(0, 0xFFFF, static_cast<std::uint32_t>(word));
  ++st_.io_count;
  return GeCode::Success;
}

GeCode GeList::buf_io_bit(double bit, double level) {
  if (auto g = buf_gate()) return *g;
  if (!int_in(bit, 0, 15) || !int_in(level, 0, 1)) return GeCode::ParameterError;
  const int b = static_cast<int>(bit);
  st_.pending_io = {{1u << b, static_cast<std::uint32_t>(level) << b}};  // the one nearest the command wins
  return GeCode::Success;
}

GeCode GeList::delay(double ms) {
  if (auto g = buf_gate()) return *g;
  if (!int_in(ms, 1, 8191)) return GeCode::ParameterError;  // 0 < t < 8192 (V107)
  if (st_.delay_count >= 1) return fault(8);
  PathGenerator& path = ge_path(card_);
  if (path.fifo_space() < 1) return fault(15);
  path.buf_delay(ms);
  ++st_.delay_count;
  return GeCode::Success;
}

// -- feedback -----------------------------------------------------------------------------------------------------
std::uint16_t GeList::crd_status() {
  CrdStatusInputs in;
  in.buffer_closed = !st_.open;
  in.immediate_mode = !st_.buffer;
  if (ge_crd_exists(card_)) {
    const PathGenerator& path = ge_path(card_);
    in.moving = moving(path);
    in.segment_complete = !path.busy();
    in.fault_stopped = card_.modes().hosted(kGeCrdSlot).fault_stopped;
    in.buffer_empty = path.fifo_size() == 0 && path.window_size() == 0;
  }
  return ge_crd_status(in);
}

std::optional<std::vector<double>> GeList::point(int which) {
  if (!ge_crd_exists(card_)) {
    std::vector<double> p;
    for (std::size_t a = 0; a < std::min<std::size_t>(3, card_.axis_count()); ++a)
      p.push_back(static_cast<double>(card_.profile_pos(a)) - st_.offsets[a]);
    return p;
  }
  const PathGenerator& path = ge_path(card_);
  CrdPoint p{};
  int n = path.coords().dim();
  if (which == 0) {
    p = path.state().pos;
    n = 4;
  } else if (which == 1) {
    const auto i = static_cast<std::size_t>(path.state().segments_done);
    if (path.busy() && i < st_.ends.size()) {
      p = st_.ends[i];
      n = st_.end_dims[i];
    } else {
      p = path.tail();
    }
  } else {
    if (!path.has_breakpoint()) return std::nullopt;
    p = path.breakpoint();
  }
  return std::vector<double>(p.begin(), p.begin() + std::min(n, 3));
}

long long GeList::mtn_nm() {
  if (!ge_crd_exists(card_) || !st_.buffer) return 0;
  const PathGenerator& path = ge_path(card_);
  long long n = path.state().segments_done - st_.mv_pushed + (path.busy() && path.state().speed > 0 ? 1 : 0);
  n = std::max(0LL, std::min(n, st_.pushed));
  return n > 0 ? (n - 1) % 32767 + 1 : 0;  // wraps 32767 -> 1 (V109)
}

double GeList::prf_vel() { return ge_crd_exists(card_) ? ge_path(card_).state().speed : 0.0; }

// -- look-ahead module A ------------------------------------------------------------------------------------------
GeCode GeList::init_look_ahead(const motion::GeLookAheadParams& p) {
  try {
    CrdPoint start{};
    for (std::size_t a = 0; a < std::min<std::size_t>(3, card_.axis_count()); ++a)
      start[a] = (static_cast<double>(card_.profile_pos(a)) - st_.offsets[a]) / p.con;
    p.validate();
    st_.la = std::make_unique<motion::GeLookAhead>(p, start);
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  }
  return GeCode::Success;
}

int GeList::add_look_data(int code, int plane_group, double r, double x, double y, double z, double vel, double cx,
                          double cy, long long n, bool flag) {
  if (!st_.la) return static_cast<int>(fault(8));
  try {
    return st_.la->add(code, plane_group, r, x, y, z, vel, cx, cy, n, flag);
  } catch (const std::invalid_argument&) {
    return static_cast<int>(GeCode::ParameterError);
  }
}

int GeList::cal_vel(double& vel_mm_s, long long& number) {
  if (!st_.la || st_.la->pending() == 0) {
    fault(8);
    vel_mm_s = 0.0;
    number = 0;
    return static_cast<int>(GeCode::CommandError);
  }
  return st_.la->cal_vel(vel_mm_s, number);
}

GeList& ge_list(machine::Card& card) { return card.module<GeList>(); }
const GeList* ge_list_if_any(const machine::Card& card) { return card.module_if_any<GeList>(); }

}  // namespace servobench::vendor::googol
