// GeList, part 2: look-ahead module B, the Ex family (GE Tables 6-9..6-12 L1729-1812; L5147-5177): the card's
// look-ahead window (PathGenerator::init_lookahead, the same planner as module A in pulse and ms) in front of the
// buffer (V111); the commands in mm and mm/s with con pulse/mm. Also the crd's hand-over to ZeroPos / SetAtlPos
// and the EXO word. (vendor/googol/ge_list.hpp)
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/motion/lookahead.hpp"
#include "servobench/motion/path_segment.hpp"
#include "servobench/vendor/googol/ge_crd.hpp"
#include "servobench/vendor/googol/ge_list.hpp"

namespace servobench::vendor::googol {

using motion::CrdPoint;
using motion::PathGenerator;
using motion::PathSegmentGeometry;

namespace {

constexpr double kPosMin = -1073741824.0, kPosMax = 1073741823.0;  // L991, L5457-5463

bool real_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi; }
bool int_in(double v, double lo, double hi) { return real_in(v, lo, hi) && v == std::floor(v); }
motion::ArcPlane arc_plane(GePlane p) { return static_cast<motion::ArcPlane>(static_cast<int>(p)); }

}  // namespace

GeCode GeList::init_look_ahead_ex(double t_s, double amax, double am, double n, double con) {
  if (!int_in(n, 200, 32766)) return GeCode::ParameterError;  // n >= 200 (L1729-1785)
  motion::GeLookAheadParams p;
  p.t_s = t_s;
  p.acc_max = amax;
  p.acc = am;
  p.vel = 1.0;
  p.n = n;
  p.con = con;
  try {
    p.validate();
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  }
  st_.ex = p;
  st_.ex_active = false;
  return GeCode::Success;
}

GeCode GeList::mv_ex(const std::vector<double>& point_mm, double vel) {
  if (!st_.ex) return fault(8);
  const double c = st_.ex->con;
  for (double v : point_mm)
    if (!real_in(v, -1e12, 1e12) || !real_in(v * c, kPosMin, kPosMax)) return GeCode::LineLengthError;
  if (!real_in(vel, 0, 1e9) || vel <= 0) return GeCode::SynParamError;
  if (!st_.open || st_.mv) return fault(8);
  st_.dim = 3;  // the look-ahead plans X, Y, Z (L1679): a 3-D crd
  st_.dirty = true;
  PathGenerator* path = nullptr;
  try {
    path = &generator(true);
  } catch (const motion::MotionCommandRefused&) {
    return fault(8);
  }
  motion::LookAheadParams la;
  la.t_ms = st_.ex->t_s * 1000.0;
  la.acc_max = st_.ex->acc_max * c / 1e6;
  la.n = st_.ex->n;
  try {
    path->init_lookahead(la);
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  }
  std::vector<double> point;
  for (double v : point_mm) point.push_back(v * c);
  const GeCode rtn = mv(point, vel * c / 1000.0, st_.ex->acc * c / 1e6);
  if (rtn == GeCode::Success) {
    st_.ex_active = true;
    st_.mv_dim = static_cast<int>(point_mm.size());
  }
  return rtn;
}

// The path when an Ex command may be buffered now, else null after filling msg and code.
PathGenerator* GeList::ex_gate(GeLookAheadMsg& msg, long long number, GeCode& code) {
  if (!st_.ex || !st_.ex_active || !st_.open || !ge_crd_exists(card_)) {
    msg = {number, 0, 8};
    code = fault(8);
    return nullptr;
  }
  PathGenerator& path = ge_path(card_);
  if (static_cast<double>(path.window_size()) >= st_.ex->n && path.fifo_space() < 1) {
    msg = {number, static_cast<long long>(path.window_size()), 3};  // buffer full: re-send (L5147-5169)
    fault(15);
    code = GeCode::CommandError;
    return nullptr;
  }
  return &path;
}

// One Ex motion command (mm, mm/s) into the card's look-ahead window; make(tail pulse, dim) gives the segment or
// none for a point equal to the previous one (rtn 1, msg.error 1, L3374).
template <class MakeFn>
GeCode GeList::ex_motion(GeLookAheadMsg& msg, double number, double f, double dcc, MakeFn&& make, bool g0) {
  if (!int_in(number, -2147483648.0, 2147483647.0) || !int_in(dcc, 0, 1)) return GeCode::ParameterError;
  if (!real_in(f, 0, 1e9) || f <= 0) return GeCode::SynParamError;
  const auto num = static_cast<long long>(number);
  GeCode code = GeCode::Success;
  PathGenerator* path = ex_gate(msg, num, code);
  if (!path) return code;
  const double c = st_.ex->con;
  const int n = path->coords().dim();
  CrdPoint tail{};
  for (int k = 0; k < n; ++k) tail[k] = path->tail()[k] / c * c;  // the host's mm, back in pulse
  std::optional<PathSegmentGeometry> seg;
  try {
    seg = make(tail, n);
  } catch (const motion::PathGeometryError& e) {
    msg = {num, 0, 8};
    return ge_geometry_code(e.gt_code());  // a zero-length line is a duplicate point: 1 (L3374)
  } catch (const std::invalid_argument&) {
    msg = {num, 0, 8};
    return GeCode::ParameterError;
  }
  if (!seg) {
    msg = {num, 0, 1};  // the point equals the previous one (L3374)
    return GeCode::CommandError;
  }
  path->push_segment(*seg, f * c / 1000.0, st_.ex->acc * c / 1e6, 0.0, g0, false, dcc == 1);
  ++st_.pushed;
  st_.ends.push_back(seg->end());
  st_.end_dims.push_back(seg->dim());
  msg = {num, 0, 0};
  return GeCode::Success;
}

GeCode GeList::line_ex(const std::vector<double>& point_mm, double f, double dcc, double number, bool g0,
                       GeLookAheadMsg& msg) {
  return ex_motion(msg, number, f, dcc, [&](const CrdPoint& tail, int n) -> std::optional<PathSegmentGeometry> {
    if (static_cast<int>(point_mm.size()) > n) throw std::invalid_argument("GE Ex line: more coordinates than the crd");
    const double c = st_.ex->con;
    CrdPoint end = tail;
    for (std::size_t k = 0; k < point_mm.size(); ++k) end[k] = point_mm[k] * c;
    bool same = true;
    for (int k = 0; k < n; ++k) same = same && std::abs(end[k] - tail[k]) < 0.5;
    if (same) return std::nullopt;
    return PathSegmentGeometry::line(tail, end, n);
  }, g0);
}

GeCode GeList::arc_center_ex(GePlane plane, double c1, double c2, double angle, double f, double dcc,
                             double number, GeLookAheadMsg& msg) {
  if (!real_in(angle, -360, 360)) return GeCode::ParameterError;
  return ex_motion(msg, number, f, dcc, [&](const CrdPoint& tail, int n) -> std::optional<PathSegmentGeometry> {
    const double c = st_.ex->con;
    return PathSegmentGeometry::arc_center_angle(tail, n, arc_plane(plane), c1 * c, c2 * c, angle);
  }, false);
}

GeCode GeList::arc_radius_ex(GePlane plane, double e1, double e2, double r, double direction, double f, double dcc,
                             double number, GeLookAheadMsg& msg) {
  if (!int_in(direction, -1, 1) || direction == 0) return GeCode::ParameterError;
  const int i = plane == GePlane::XY ? 0 : plane == GePlane::YZ ? 1 : 2;
  const int j = plane == GePlane::XY ? 1 : plane == GePlane::YZ ? 2 : 0;
  return ex_motion(msg, number, f, dcc, [&](const CrdPoint& tail, int n) -> std::optional<PathSegmentGeometry> {
    if (i >= n || j >= n) throw std::invalid_argument("GE Ex arc: plane outside the crd");
    const double c = st_.ex->con;
    CrdPoint end = tail;
    end[i] = e1 * c;
    end[j] = e2 * c;
    return PathSegmentGeometry::arc_end_radius(tail, end, n, arc_plane(plane), r * c, direction == 1);
  }, false);
}

template <class Push>
GeCode GeList::ex_plain(Push&& push) {
  if (!st_.open) return GeCode::CommError;  // immediate mode (L3758-3762)
  GeLookAheadMsg msg;
  GeCode code = GeCode::Success;
  PathGenerator* path = ex_gate(msg, 0, code);
  if (!path) return code;
  push(*path);
  return GeCode::Success;
}

GeCode GeList::buf_io_ex(double word) {
  if (!int_in(word, 0, 0xFFFF)) return GeCode::ParameterError;
  return ex_plain([&](PathGenerator& p) { p.buf_io(0, 0xFFFF, static_cast<std::uint32_t>(word)); });
}

GeCode GeList::buf_io_bit_ex(double bit, double level) {
  if (!int_in(bit, 0, 15) || !int_in(level, 0, 1)) return GeCode::ParameterError;
  const int b = static_cast<int>(bit);
  return ex_plain([&](PathGenerator& p) { p.buf_io(0, 1u << b, static_cast<std::uint32_t>(level) << b); });
}

GeCode GeList::delay_ex(double ms) {
  if (!int_in(ms, 1, 8191)) return GeCode::ParameterError;  // 0 < t < 8192 (Table 6-10 L1761; V107)
  return ex_plain([&](PathGenerator& p) { p.buf_delay(ms); });
}

GeCode GeList::m30(GeLookAheadMsg& msg) {
  if (!st_.ex || !st_.ex_active || !st_.open || !ge_crd_exists(card_)) {
    msg.error = 8;
    return fault(8);
  }
  PathGenerator& path = ge_path(card_);
  if (path.flush()) {
    msg.error = 0;
    msg.num = 0;
    return GeCode::Success;
  }
  msg.error = 3;  // the buffer is full: let the card run and call again (L1793-1795, L5171-5177)
  msg.num = static_cast<long long>(path.window_size());
  return GeCode::ProgramRunning;
}

void GeList::leave_crd(std::size_t a) {
  if (a >= 4 || !ge_crd_exists(card_)) return;
  const PathGenerator& path = ge_path(card_);
  if (path.busy() || st_.open || resumable(path) || card_.moving(a)) return;
  card_.set_mode(a, machine::AxisMode::TCurve);
  st_.dirty = true;
}

std::uint32_t GeList::outputs() {
  if (!ge_crd_exists(card_)) return st_.exo;
  const std::uint32_t gpo = ge_path(card_).state().do_words[0] & 0xFFFFu;
  if (gpo != st_.gpo_seen) {
    const std::uint32_t changed = gpo ^ st_.gpo_seen;
    st_.exo = (st_.exo & ~changed) | (gpo & changed);
    st_.gpo_seen = gpo;
  }
  return st_.exo;
}

}  // namespace servobench::vendor::googol
