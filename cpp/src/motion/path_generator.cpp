// The path generator (motion/path_generator.hpp): setup, configuration, the buffer of segments, run control.
// The buffered non-motion commands and stop inputs: path_buffer_io.cpp; the execution per tick: path_execution.cpp.
#include "servobench/motion/path_generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "path_detail.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"

namespace servobench::motion {

using detail::check_open;

namespace {
double dist(const CrdPoint& a, const CrdPoint& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s);
}
}  // namespace

void PathSetup::validate() const {
  const char* o = "PathSetup";
  check_range(o, "cycle_ms", cycle_ms, 0.01, 100, "motion cycle, ms");
  check_integer(o, "fifo_capacity", fifo_capacity, 1, 1e7, "entries; GUC L798: 4096");
  check_open(o, "syn_vel_max", syn_vel_max, 0, 1e9, "unit/ms; GUC L771");
  check_open(o, "syn_acc_max", syn_acc_max, 0, 1e9, "unit/ms^2; GUC L773");
  check_range(o, "even_time_ms", even_time_ms, 0, 32766, "ms; GUC L775");
  check_range(o, "stop_dec_smooth", stop_dec_smooth, 0, 32767, "unit/ms^2, 0 = segment acceleration; GUC L704-709");
  check_range(o, "stop_dec_abrupt", stop_dec_abrupt, 0, 32767, "unit/ms^2, 0 = at once; GUC L704-709");
  check_range(o, "corner_axis_acc", corner_axis_acc, 0, 1e9, "pulse/ms^2, 0 = off; GT L1956");
  check_range(o, "axis_acc_1", axis_acc_1, 0, 1e9, "pulse/ms^2, 0 = corner_axis_acc; GT L1956");
  check_range(o, "axis_acc_2", axis_acc_2, 0, 1e9, "pulse/ms^2, 0 = corner_axis_acc; GT L1956");
  check_range(o, "axis_acc_3", axis_acc_3, 0, 1e9, "pulse/ms^2, 0 = corner_axis_acc; GT L1956");
  check_range(o, "axis_acc_4", axis_acc_4, 0, 1e9, "pulse/ms^2, 0 = corner_axis_acc; GT L1956");
  check_range(o, "start_vel", start_vel, 0, 32767, "unit/ms, 0 = from rest; GE GT_SetStrtVel L1395-1399, L5748-5756");
  check_range(o, "resume_tolerance", resume_tolerance, 0, 1e6, "unit per coordinate; GUC L1005, iDEABOX L1648-1653");
}

void PathGenerator::admit() {
  if (gate_) gate_(PathGateEvent::Push);
}

double PathGenerator::floor_vs(double v, double cap) const {
  return v < setup_.start_vel ? std::min(setup_.start_vel, cap) : v;
}

void PathGenerator::refuse(const char* what) {
  throw MotionCommandRefused(std::string(what) + " (return code 1)");
}

PathGenerator::PathGenerator(const CoordSystem& coords, const PathSetup& setup, const CrdPoint& start)
    : coords_(coords), setup_(setup) {
  setup_.validate();
  for (double v : start)
    if (!std::isfinite(v)) throw_invalid("PathGenerator", "start", v, "is not a finite coordinate");
  st_.pos = start;
  tail_ = start;
  stop_dec_smooth_ = setup_.stop_dec_smooth;
  stop_dec_abrupt_ = setup_.stop_dec_abrupt;
}

// --- configuration ---------------------------------------------------------------------------------------------

void PathGenerator::init_lookahead(const LookAheadParams& p) {
  p.validate();
  if (!fifo_.empty() || !window_.empty() || busy())
    refuse("PathGenerator.init_lookahead: the buffer holds data or the path is moving");
  if (p.n == 0.0) {
    la_.reset();
    return;
  }
  if (coords_.dim() > 3)
    throw std::invalid_argument(
        "PathGenerator.init_lookahead: look-ahead supports at most 3 axes; this coordinate system has 4 "
        "(buffered commands would return 7, GUC L985, iDEABOX L2012-2014)");
  LookAheadParams q = p;
  q.axis_limits = axis_limits();
  la_ = std::make_unique<LookAhead>(q);
}

void PathGenerator::set_override(double ratio) {
  check_range("PathGenerator", "override", ratio, 0, 1000, "ratio, 1 = 100 %; GUC L701-703, GE L1952-1958");
  if (!(ratio > 0)) throw_invalid("PathGenerator", "override", ratio, "must be > 0");
  override_ = ratio;
  if (act_ == Act::Motion && !cur_.g0 && !stop_at_rest_) begin_motion(s_cur_);
}

void PathGenerator::set_g0_override(double ratio) {
  check_range("PathGenerator", "g0_override", ratio, 0, 1000, "ratio, 1 = 100 %; GE L5354-5362");
  if (!(ratio > 0)) throw_invalid("PathGenerator", "g0_override", ratio, "must be > 0");
  g0_override_ = ratio;
  if (act_ == Act::Motion && cur_.g0 && !stop_at_rest_) begin_motion(s_cur_);
}

void PathGenerator::set_stop_dec(double smooth, double abrupt) {
  check_range("PathGenerator", "stop_dec_smooth", smooth, 0, 32767, "unit/ms^2; GUC L704-709");
  check_range("PathGenerator", "stop_dec_abrupt", abrupt, 0, 32767, "unit/ms^2; GUC L704-709");
  stop_dec_smooth_ = smooth;
  stop_dec_abrupt_ = abrupt;
}

void PathGenerator::set_axis_acc(int axis, double acc) {
  check_range("PathGenerator", "axis", axis, 1, 4, "motor axis of the coordinate system");
  check_range("PathGenerator", "axis_acc", acc, 0, 1e9, "pulse/cycle^2, 0 = corner_axis_acc; GT L1956");
  double* own[4] = {&setup_.axis_acc_1, &setup_.axis_acc_2, &setup_.axis_acc_3, &setup_.axis_acc_4};
  *own[axis - 1] = acc;
}

PathGenerator::Aux& PathGenerator::aux(int axis) {
  auto it = aux_.find(axis);
  if (it != aux_.end()) return it->second;
  Aux a;
  a.gen = std::make_unique<ProfileGenerator>(0.0, setup_.cycle_ms * 1e-3);
  return aux_.emplace(axis, std::move(a)).first->second;
}

void PathGenerator::set_aux_position(int axis, double pos) {
  check_integer("PathGenerator", "aux_axis", axis, 1, 64, "iDEABOX L4660");
  for (int a : coords_.axes())
    if (a == axis) throw_invalid("PathGenerator", "aux_axis", axis, "is an axis of the coordinate system");
  Aux& x = aux(axis);
  if (x.gen->moving()) refuse("PathGenerator.set_aux_position: the axis is moving");
  x.gen->set_position(pos);
  x.gear_base = 0.0;
}

std::vector<int> PathGenerator::aux_axes() const {
  std::vector<int> v;
  for (const auto& kv : aux_) v.push_back(kv.first);
  return v;
}

double PathGenerator::aux_position(int axis) const {
  auto it = aux_.find(axis);
  if (it == aux_.end()) return 0.0;
  double p = it->second.gen->state().pos + it->second.gear_base;
  if (cur_valid_ && cur_.geom.length() > 0)
    for (const auto& g : gears_)
      if (g.axis == axis) p += g.distance * std::min(s_cur_ / cur_.geom.length(), 1.0);
  return p;
}

bool PathGenerator::aux_moving() const {
  for (const auto& kv : aux_)
    if (kv.second.gen->moving()) return true;
  return false;
}

// --- buffering -------------------------------------------------------------------------------------------------

long long PathGenerator::fifo_space() const {
  return static_cast<long long>(setup_.fifo_capacity) - static_cast<long long>(fifo_.size());
}

long long PathGenerator::remaining_segments() const {
  long long n = cur_valid_ ? 1 : 0;
  for (const auto& c : fifo_) n += c.type == PathCommandType::Motion;
  for (const auto& c : window_) n += c.type == PathCommandType::Motion;
  return n;
}

void PathGenerator::enqueue(PathCommand c) {
  const bool motion = c.type == PathCommandType::Motion;
  if (!la_) {
    if (fifo_space() <= 0) refuse("PathGenerator: the FIFO is full, send the command again later");
    fifo_.push_back(std::move(c));
    return;
  }
  // Look-ahead: a segment pushed into a full window sends the oldest segment (and the commands riding in
  // front of it) to the FIFO; if that does not fit, the push is refused and nothing changes.
  if (motion && window_motion_ >= la_->window()) {
    std::size_t riders = 0;
    while (window_[riders].type != PathCommandType::Motion) ++riders;
    if (fifo_space() < static_cast<long long>(riders + 1))
      refuse("PathGenerator: the look-ahead window and the FIFO are full, send the command again later");
  }
  if (motion) {
    auto s = lookahead_segment(c.geom, cap_of(c), acc_of(c), c.g0 || tail_stop_next_, c.g0 || c.stop_at_end);
    s.axes = demand_of(c);
    window_.push_back(std::move(c));
    ++window_motion_;
    if (la_->push(s)) release_window(false);
  } else {
    window_.push_back(std::move(c));
  }
}

void PathGenerator::release_window(bool all) {
  // Moves the riders and the oldest segment of the window to the FIFO with the segment's final end speed.
  while (!window_.empty()) {
    PathCommand c = std::move(window_.front());
    window_.pop_front();
    if (c.type == PathCommandType::Motion) {
      c.planned_end = la_->pop();
      c.planned = true;
      --window_motion_;
      fifo_.push_back(std::move(c));
      if (!all) return;
    } else {
      fifo_.push_back(std::move(c));
    }
  }
}

bool PathGenerator::flush() {
  if (!la_) return true;
  while (!window_.empty()) {
    std::size_t riders = 0;
    while (riders < window_.size() && window_[riders].type != PathCommandType::Motion) ++riders;
    const std::size_t need = riders < window_.size() ? riders + 1 : riders;
    if (fifo_space() < static_cast<long long>(need)) return false;
    if (riders == window_.size()) {
      while (!window_.empty()) {
        fifo_.push_back(std::move(window_.front()));
        window_.pop_front();
      }
    } else {
      release_window(false);
    }
  }
  return true;
}

void PathGenerator::push_segment(const PathSegmentGeometry& g, double vel, double acc, double vel_end, bool g0,
                                 bool auto_end, bool stop_at_end) {
  admit();
  const char* o = "PathSegment";
  check_open(o, "vel", vel, 0, 1e9, "synVel, unit/ms; GUC L449-481: (0, 32767)");
  check_open(o, "acc", acc, 0, 1e9, "synAcc, unit/ms^2; GUC L449-481: (0, 32767)");
  check_range(o, "vel_end", vel_end, 0, 1e9, "velEnd, unit/ms; GUC L449-481: [0, 32767)");
  if (dist(g.start(), tail_) > 1e-9 * std::max(1.0, g.length()))
    throw std::invalid_argument("PathSegment: the segment does not start at the end of the previous one");
  PathCommand c;
  c.type = PathCommandType::Motion;
  c.geom = g;
  c.vel = vel;
  c.acc = acc;
  c.vel_end = vel_end;
  c.g0 = g0;
  c.auto_end = auto_end;
  c.stop_at_end = stop_at_end;
  if (axis_limits().any() && tail_u_valid_ && g.length() > 0) {
    // VF8: a segment that starts with a corner lasts >= 2 motion cycles, so one cycle's second difference never
    // holds two corners.
    const CrdPoint a = to_axes_dir(tail_u_), b = to_axes_dir(g.tangent_at(0.0));
    double d = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::fabs(b[k] - a[k]));
    if (d >= 1e-12) c.axis_cap = g.length() / (2.0 * setup_.cycle_ms);
  }
  enqueue(std::move(c));
  tail_ = g.end();
  tail_stop_next_ = false;
  if (g.length() > 0) {
    tail_u_ = g.tangent_at(g.length());
    tail_u_valid_ = true;
  }
}

void PathGenerator::line(const CrdPoint& end, double vel, double acc, double vel_end, bool g0) {
  admit();
  push_segment(PathSegmentGeometry::line(tail_, end, coords_.dim()), vel, acc, vel_end, g0);
}

// --- run control -----------------------------------------------------------------------------------------------

bool PathGenerator::running() const {
  if (!started_ || stopped_) return false;
  return busy() || !fifo_.empty() || !window_.empty();
}

void PathGenerator::start() {
  if (gate_) gate_(PathGateEvent::Start);
  if (act_ == Act::Immediate) refuse("PathGenerator.start: an immediate move is running");
  if (started_ && !stopped_ && busy()) refuse("PathGenerator.start: the path is already running (GT command status bit 12)");
  if (stopped_ && has_brk_ && dist(st_.pos, brk_) > 1e-9) {
    double off = 0.0;
    for (std::size_t k = 0; k < brk_.size(); ++k) off = std::max(off, std::fabs(st_.pos[k] - brk_[k]));
    if (!setup_.return_to_stop_point && off > setup_.resume_tolerance)
      refuse("PathGenerator.start: the position is not the breakpoint (GUC L1005, iDEABOX L1648-1653)");
    // GT L1940 / GE L1660: back to the breakpoint along a line, ending at rest, then continue.
    aux_line_ = PathSegmentGeometry::line(st_.pos, brk_, coords_.dim());
    const double vel = cur_valid_ ? cap_of(cur_) : setup_.syn_vel_max;
    const double acc = cur_valid_ ? acc_of(cur_) : setup_.syn_acc_max;
    const double vs = std::min(setup_.start_vel, vel);
    feed_ = FeedProfile(aux_line_.length(), vs, vs, vel, acc);
    t_in_ = 0.0;
    act_ = Act::Return;
    stopped_ = false;
    started_ = true;
    if (gate_) gate_(PathGateEvent::Started);
    return;
  }
  started_ = true;
  stopped_ = false;
  stop_at_rest_ = false;
  if (cur_valid_ && act_ == Act::None) begin_motion(s_cur_);
  if (gate_) gate_(PathGateEvent::Started);
}

void PathGenerator::stop(bool abrupt) {
  if (act_ == Act::Immediate || act_ == Act::Return) {
    // Not allowed during the return move (GT L1948): treated as an abrupt halt of that line.
    const bool ret = act_ == Act::Return;
    act_ = Act::None;
    st_.speed = st_.acc = 0.0;
    if (ret) stopped_ = true;
    return;
  }
  if (!started_ || stopped_) return;
  if (act_ != Act::Motion) {  // at rest between segments, in a delay or a modal move: stop here
    enter_stopped();
    return;
  }
  const double dec = abrupt ? stop_dec_abrupt_ : (stop_dec_smooth_ > 0 ? stop_dec_smooth_ : acc_of(cur_));
  if (abrupt && dec == 0.0) {
    st_.speed = st_.acc = 0.0;
    act_ = Act::None;
    enter_stopped();
    return;
  }
  start_stop_ramp(dec);
}

void PathGenerator::start_stop_ramp(double dec) {
  stop_dec_ = dec;
  stop_at_rest_ = true;
  plan_stop_feed(s_cur_);
}

void PathGenerator::plan_stop_feed(double s_from) {
  // Decelerate at stop_dec_ from the present speed; if the segment is too short, brake to its end (never
  // above the speed the plan itself allows there) and keep braking in the next segments.
  const double v0 = act_ == Act::Motion ? feed_.at(t_in_).vel : st_.speed;
  const double room = cur_.geom.length() - s_from;
  const double vt = std::min(setup_.start_vel, v0);  // GE: down to the start velocity, then at rest
  const double need = (v0 * v0 - vt * vt) / (2.0 * stop_dec_);
  s_off_ = s_from;
  t_in_ = 0.0;
  act_ = Act::Motion;
  if (need <= room) {
    stop_inside_ = true;
    feed_ = need > 0.0 ? FeedProfile(need, v0, vt, v0, stop_dec_) : FeedProfile();
    return;
  }
  stop_inside_ = false;
  // A uniform ramp to the end of the segment: at stop_dec_, or steeper (never above the plan's own
  // acceleration) where the plan must be slower there.
  const double v_end = std::min(std::sqrt(v0 * v0 - 2.0 * stop_dec_ * room), exit_speed());
  const double dec = std::max((v0 * v0 - v_end * v_end) / (2.0 * room), stop_dec_);
  feed_ = FeedProfile(room, v0, v_end, v0, dec);
}

void PathGenerator::enter_stopped() {
  stopped_ = true;
  stop_at_rest_ = false;
  has_brk_ = true;
  brk_ = st_.pos;
  if (act_ == Act::Motion) act_ = Act::None;
}

void PathGenerator::clear() {
  if (busy()) refuse("PathGenerator.clear: the path is moving");
  fifo_.clear();
  window_.clear();
  window_motion_ = 0;
  if (la_) la_->reset();
  cur_valid_ = false;
  gears_.clear();
  pending_gears_.clear();
  started_ = stopped_ = has_brk_ = stop_at_rest_ = false;
  st_.segments_done = 0;
  tail_ = st_.pos;
  tail_stop_next_ = false;
  tail_u_valid_ = false;
}

void PathGenerator::move_immediate(const CrdPoint& end, double vel, double acc) {
  if (busy() || running())
    refuse("PathGenerator.move_immediate: the path is moving (GT command status bit 12, GE L1492)");
  check_open("PathImmediate", "vel", vel, 0, 1e9, "unit/ms");
  check_open("PathImmediate", "acc", acc, 0, 1e9, "unit/ms^2");
  aux_line_ = PathSegmentGeometry::line(st_.pos, end, coords_.dim());
  const double cap = std::min(vel * override_, setup_.syn_vel_max);
  const double vs = std::min(setup_.start_vel, cap);
  feed_ = FeedProfile(aux_line_.length(), vs, vs, cap, std::min(acc, setup_.syn_acc_max), 0.0);
  t_in_ = 0.0;
  act_ = Act::Immediate;
  if (!has_brk_ && fifo_.empty() && window_.empty() && !cur_valid_) {
    tail_ = end;
    tail_u_valid_ = false;
  }
}

}  // namespace servobench::motion
