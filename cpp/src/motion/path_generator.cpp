#include "servobench/motion/path_generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"

namespace servobench::motion {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

void check_open(const char* owner, const char* field, double v, double lo, double hi, const char* src) {
  check_range(owner, field, v, lo, hi, src);
  if (!(v > lo) || !(v < hi))
    throw_invalid(owner, field, v, "must be in the open interval (" + format_value(lo) + ", " + format_value(hi) +
                                       ") (" + src + ")");
}

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

void PathGenerator::buf_io(int io_type, std::uint32_t mask, std::uint32_t value) {
  admit();
  check_integer("BufIO", "do_type", io_type, 0, 2, "0 GPO, 1 drive enable, 2 alarm clear; GUC L588-597");
  check_integer("BufIO", "mask", mask, 0, 65535, "16 channels; GUC L588-597");
  check_integer("BufIO", "value", value, 0, 65535, "16 channels; GUC L588-597");
  PathCommand c;
  c.type = PathCommandType::Io;
  c.io_type = io_type;
  c.mask = mask;
  c.value = value;
  enqueue(std::move(c));
}

void PathGenerator::buf_delay(double ms) {
  admit();
  check_integer("BufDelay", "delay_ms", ms, 0, 16383, "ms; GUC L598-602, iDEABOX L4212");
  PathCommand c;
  c.type = PathCommandType::Delay;
  c.delay_ms = ms;
  enqueue(std::move(c));
  tail_stop_next_ = true;
}

void PathGenerator::buf_da(int channel, double value) {
  admit();
  check_integer("BufDA", "channel", channel, 1, 8, "GUC L603-608");
  check_integer("BufDA", "value", value, -32768, 32767, "counts, -10..+10 V; GUC L603-608");
  PathCommand c;
  c.type = PathCommandType::Da;
  c.channel = channel;
  c.da = value;
  enqueue(std::move(c));
}

void PathGenerator::buf_move(int axis, double pos, double vel, double acc, bool modal) {
  admit();
  check_integer("BufMove", "axis", axis, 1, 64, "GUC L646-656, iDEABOX L4373");
  for (int a : coords_.axes())
    if (a == axis) throw_invalid("BufMove", "axis", axis, "is an axis of the coordinate system (GUC L1013)");
  check_integer("BufMove", "pos", pos, -2147483648.0, 2147483647.0, "absolute, pulse; GUC L646-656");
  check_open("BufMove", "vel", vel, 0, 1e9, "pulse/ms, > 0; GUC L646-656");
  check_open("BufMove", "acc", acc, 0, 1e9, "pulse/ms^2, > 0; GUC L646-656");
  aux(axis);
  PathCommand c;
  c.type = PathCommandType::Move;
  c.axis = axis;
  c.pos = pos;
  c.vel = vel;
  c.acc = acc;
  c.modal = modal;
  enqueue(std::move(c));
  if (modal) tail_stop_next_ = true;
}

void PathGenerator::buf_gear(int axis, double distance) {
  admit();
  check_integer("BufGear", "axis", axis, 1, 64, "GUC L657-661, iDEABOX L4234-4248");
  for (int a : coords_.axes())
    if (a == axis) throw_invalid("BufGear", "axis", axis, "is an axis of the coordinate system (GUC L657-661)");
  check_integer("BufGear", "pos", distance, -2147483648.0, 2147483647.0, "relative, pulse; GUC L657-661");
  aux(axis);
  PathCommand c;
  c.type = PathCommandType::Gear;
  c.axis = axis;
  c.pos = distance;
  enqueue(std::move(c));
}

void PathGenerator::set_user_seg_num(long long n) {
  admit();
  check_integer("SetUserSegNum", "seg_num", static_cast<double>(n), -2147483648.0, 2147483647.0, "GUC L662-665");
  PathCommand c;
  c.type = PathCommandType::UserSegNum;
  c.user_seg = n;
  enqueue(std::move(c));
}

void PathGenerator::buf_lmts(int axis, int limit_type, bool on) {
  admit();
  const char* o = on ? "BufLmtsOn" : "BufLmtsOff";
  check_integer(o, "axis", axis, 1, 16, "GUC L609-624: 1..8; iDEABOX L4292-4300: 1..12 (core 1), 1..16 (core 2)");
  check_integer(o, "limit_type", limit_type, -1, 1, "0 positive, 1 negative, -1 both; GUC L609-624, iDEABOX L4292-4300");
  PathCommand c;
  c.type = PathCommandType::Lmts;
  c.axis = axis;
  c.limit_type = limit_type;
  c.limits_on = on;
  enqueue(std::move(c));
}

namespace {
void check_input(const char* o, int input_type, int index) {
  check_integer(o, "input_type", input_type, 0, 4, "0 +limit, 1 -limit, 2 alarm, 3 home, 4 GPI; GUC L625-645");
  check_integer(o, "input_index", index, 1, input_type == 4 ? 16 : 8,
                input_type == 4 ? "GPI 1..16; GUC L625-645 (OCR prints [1,6])" : "1..8; GUC L625-645");
}
}  // namespace

void PathGenerator::buf_set_stop_io(int axis, int stop_type, int input_type, int input_index) {
  admit();
  const char* o = "BufSetStopIo";
  check_integer(o, "axis", axis, 1, 8, "GUC L625-645");
  check_integer(o, "stop_type", stop_type, 0, 1, "0 emergency, 1 smooth; GUC L625-645");
  check_input(o, input_type, input_index);
  PathCommand c;
  c.type = PathCommandType::StopIo;
  c.axis = axis;
  c.stop_io = StopIoMapping{true, stop_type, input_type, input_index};
  enqueue(std::move(c));
}

void PathGenerator::set_input(int input_type, int index, bool active) {
  check_input("PathGenerator.set_input", input_type, index);
  auto& w = inputs_[static_cast<std::size_t>(input_type)];
  const std::uint32_t bit = 1u << (index - 1);
  w = active ? (w | bit) : (w & ~bit);
}

bool PathGenerator::input(int input_type, int index) const {
  check_input("PathGenerator.input", input_type, index);
  return (inputs_[static_cast<std::size_t>(input_type)] >> (index - 1)) & 1u;
}

const StopIoMapping& PathGenerator::stop_io(int axis) const {
  check_integer("PathGenerator.stop_io", "axis", axis, 1, 8, "GUC L625-645");
  return stop_io_[static_cast<std::size_t>(axis - 1)];
}

void PathGenerator::relocate(const CrdPoint& pos) {
  for (double v : pos)
    if (!std::isfinite(v)) throw_invalid("PathGenerator", "position", v, "is not a finite coordinate");
  if (busy()) refuse("PathGenerator.relocate: the path is moving");
  st_.pos = pos;
  if (fifo_.empty() && window_.empty() && !cur_valid_ && !has_brk_) {
    tail_ = pos;
    tail_u_valid_ = false;
  }
}

void PathGenerator::check_stop_inputs() {
  for (std::size_t k = 0; k < stop_io_.size(); ++k) {
    const StopIoMapping& m = stop_io_[k];
    if (!m.armed) continue;
    const std::uint32_t bit = 1u << (m.input_index - 1);
    bool active = (inputs_[static_cast<std::size_t>(m.input_type)] & bit) != 0;
    // A limit input counts only while that limit is enabled (BufLmtsOn / BufLmtsOff, decision C28).
    if (m.input_type == 0) active = active && (st_.limits_pos & bit);
    if (m.input_type == 1) active = active && (st_.limits_neg & bit);
    if (!active) continue;
    const int axis = static_cast<int>(k) + 1;
    const bool abrupt = m.stop_type == 0;
    bool in_crd = false;
    for (int a : coords_.axes()) in_crd = in_crd || a == axis;
    if (in_crd) {
      if ((running() || act_ == Act::Immediate) && !stop_at_rest_) {
        st_.io_stop_axis = axis;
        stop(abrupt);
      }
      continue;
    }
    auto it = aux_.find(axis);
    if (it == aux_.end() || !it->second.gen->moving() || it->second.gen->stopping()) continue;
    st_.io_stop_axis = axis;
    if (abrupt) {
      it->second.gen->abrupt_stop();
    } else {
      it->second.gen->smooth_stop();
    }
    // A modal move aborted by its stop input halts the FIFO (GUC L1055, iDEABOX L2344-2348).
    if (act_ == Act::WaitMove && wait_axis_ == axis) {
      act_ = Act::None;
      enter_stopped();
    }
  }
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

// --- execution -------------------------------------------------------------------------------------------------

AxisAccLimits PathGenerator::axis_limits() const {
  AxisAccLimits lim;
  lim.cycle_ms = setup_.cycle_ms;
  const double own[4] = {setup_.axis_acc_1, setup_.axis_acc_2, setup_.axis_acc_3, setup_.axis_acc_4};
  bool any = setup_.corner_axis_acc > 0;
  for (double a : own) any = any || a > 0;
  if (!any) return lim;  // no per-axis limit: the rules of C9-C11 alone
  const std::size_t n = std::min<std::size_t>(coords_.axes().size(), 4);
  for (std::size_t k = 0; k < n; ++k) lim.acc[k] = own[k] > 0 ? own[k] : setup_.corner_axis_acc;
  return lim;
}

CrdPoint PathGenerator::to_axes_dir(const CrdPoint& v) const {
  std::vector<double> m(coords_.axes().size());
  coords_.map_vector(v, m.data());
  CrdPoint out{};
  for (std::size_t k = 0; k < std::min<std::size_t>(m.size(), out.size()); ++k) out[k] = m[k];
  return out;
}

namespace {
// Per motor axis k, the largest |(M w)_k| over unit coordinate vectors w: the row norm of the map (arcs).
CrdPoint row_norms(const CoordSystem& cs) {
  CrdPoint sq{};
  std::vector<double> col(cs.axes().size());
  for (int j = 0; j < cs.dim(); ++j) {
    CrdPoint e{};
    e[static_cast<std::size_t>(j)] = 1.0;
    cs.map_vector(e, col.data());
    for (std::size_t k = 0; k < std::min<std::size_t>(col.size(), sq.size()); ++k) sq[k] += col[k] * col[k];
  }
  for (double& x : sq) x = std::sqrt(x);
  return sq;
}
}  // namespace

double PathGenerator::cap_of(const PathCommand& c) const {
  double v = std::min(c.vel * (c.g0 ? g0_override_ : override_), setup_.syn_vel_max);
  if (la_) v = std::min(v, std::sqrt(la_->params().acc_max * c.geom.curvature_radius()));
  if (c.axis_cap > 0) v = std::min(v, c.axis_cap);
  const AxisAccLimits lim = axis_limits();
  if (lim.any() && std::isfinite(c.geom.curvature_radius())) {
    // VF7: on an arc or helix the centripetal part gets half of every axis's limit.
    const CrdPoint r = row_norms(coords_);
    for (std::size_t k = 0; k < lim.acc.size(); ++k)
      if (lim.acc[k] > 0 && r[k] > 0) v = std::min(v, std::sqrt(0.5 * lim.acc[k] / r[k] * c.geom.curvature_radius()));
  }
  return v;
}

double PathGenerator::acc_of(const PathCommand& c) const {
  double a = std::min(c.acc, setup_.syn_acc_max);
  if (la_) a = std::min(a, la_->params().acc_max);
  const AxisAccLimits lim = axis_limits();
  if (!lim.any()) return a;
  // VF6: the ramp along the path asks axis k for a |u_k| (lines; u through the map) or up to a |M_k| (arcs, with
  // half of the limit left for the centripetal part).
  const bool arc = std::isfinite(c.geom.curvature_radius());
  const CrdPoint u = arc ? row_norms(coords_) : to_axes_dir(c.geom.tangent_at(0.0));
  for (std::size_t k = 0; k < lim.acc.size(); ++k) {
    const double uk = std::fabs(u[k]);
    if (lim.acc[k] > 0 && uk > 1e-15) a = std::min(a, (arc ? 0.5 : 1.0) * lim.acc[k] / uk);
  }
  return a;
}

AxisDemand PathGenerator::demand_of(const PathCommand& c) const {
  AxisDemand d;
  d.u_in = to_axes_dir(c.geom.tangent_at(0.0));
  d.u_out = to_axes_dir(c.geom.tangent_at(c.geom.length()));
  const double a = acc_of(c);
  if (std::isfinite(c.geom.curvature_radius())) {
    const CrdPoint r = row_norms(coords_);
    const double v = cap_of(c);
    for (std::size_t k = 0; k < d.acc.size(); ++k) d.acc[k] = (a + v * v / c.geom.curvature_radius()) * r[k];
  } else {
    for (std::size_t k = 0; k < d.acc.size(); ++k) d.acc[k] = a * std::fabs(d.u_in[k]);
  }
  return d;
}

double PathGenerator::exit_speed() const {
  if (cur_.g0 || cur_.stop_at_end) return 0.0;
  // The next segment, past the commands that execute between segments without stopping.
  const PathCommand* next = nullptr;
  for (const auto& c : fifo_) {
    if (c.type == PathCommandType::Motion) {
      next = &c;
      break;
    }
    if (c.type == PathCommandType::Delay || (c.type == PathCommandType::Move && c.modal)) return 0.0;
  }
  if (next == nullptr || next->g0) return 0.0;  // starved, or a rapid follows
  const double cap_next = cap_of(*next);
  const double stop_next = std::sqrt(2.0 * acc_of(*next) * next->geom.length());
  if (cur_.planned) return std::min({cur_.planned_end, cap_next, cap_of(cur_)});
  double v = std::min({cap_of(cur_), cap_next, stop_next});
  if (cur_.auto_end) {
    // GT one-joint rule with per-axis AccLmt (C9, VF5): no motor axis's second difference above its limit.
    const AxisAccLimits lim = axis_limits();
    if (lim.any()) v = std::min(v, axis_corner_speed_limit(demand_of(cur_), demand_of(*next), lim));
    return v;
  }
  // VF9: the user's velEnd (look-ahead off), lowered where it would ask an axis for more than its limit.
  const AxisAccLimits lim = axis_limits();
  if (lim.any()) v = std::min(v, axis_corner_speed_limit(demand_of(cur_), demand_of(*next), lim));
  return std::min(v, cur_.vel_end);
}

void PathGenerator::begin_motion(double s_from) {
  const double L = cur_.geom.length() - s_from;
  const double v0 = act_ == Act::Motion ? feed_.at(t_in_).vel : st_.speed;
  if (L <= 0.0) {
    act_ = Act::Motion;
    s_off_ = s_from;
    feed_ = FeedProfile(1e-300, v0, v0, std::max(v0, 1e-300), 1.0);
    t_in_ = 0.0;
    return;
  }
  const double cap = cap_of(cur_);
  feed_ = FeedProfile(L, floor_vs(v0, cap), floor_vs(exit_speed(), cap), cap, acc_of(cur_),
                      cur_.g0 ? 0.0 : setup_.even_time_ms);
  s_off_ = s_from;
  t_in_ = 0.0;
  act_ = Act::Motion;
}

void PathGenerator::execute_instant(const PathCommand& c) {
  switch (c.type) {
    case PathCommandType::Io: {
      auto& w = st_.do_words[static_cast<std::size_t>(c.io_type)];
      w = (w & ~c.mask) | (c.value & c.mask);
      break;
    }
    case PathCommandType::Da: st_.da[static_cast<std::size_t>(c.channel - 1)] = c.da; break;
    case PathCommandType::UserSegNum: st_.user_seg_num = c.user_seg; break;
    case PathCommandType::Lmts: {
      const std::uint32_t bit = 1u << (c.axis - 1);
      auto apply = [&](std::uint32_t& w) { w = c.limits_on ? (w | bit) : (w & ~bit); };
      if (c.limit_type != 1) apply(st_.limits_pos);
      if (c.limit_type != 0) apply(st_.limits_neg);
      break;
    }
    case PathCommandType::StopIo: stop_io_[static_cast<std::size_t>(c.axis - 1)] = c.stop_io; break;
    case PathCommandType::Gear: pending_gears_.push_back({c.axis, c.pos}); break;
    case PathCommandType::Move: {
      Aux& a = aux(c.axis);
      const double tick = setup_.cycle_ms;
      if (!a.gen->moving()) a.acc = c.acc;  // a re-target keeps the running acceleration (T-curve rule)
      a.gen->move_t_curve(c.pos - a.gear_base, TCurveLimits{c.vel * tick, a.acc * tick * tick});
      break;
    }
    default: break;
  }
}

void PathGenerator::finish_motion() {
  st_.pos = cur_.geom.end();
  st_.speed = feed_.exit_speed();
  ++st_.segments_done;
  for (const auto& g : gears_) aux(g.axis).gear_base += g.distance;
  gears_.clear();
  cur_valid_ = false;
  s_cur_ = 0.0;
  act_ = Act::None;
}

bool PathGenerator::advance(double& budget) {
  switch (act_) {
    case Act::None: {
      if (stop_at_rest_ && st_.speed == 0.0) {
        enter_stopped();
        return false;
      }
      if (!started_ || stopped_ || fifo_.empty()) {
        if (fifo_.empty() && started_ && !stopped_) st_.speed = 0.0;  // starved: the path waits at rest
        if (stop_at_rest_ && fifo_.empty()) enter_stopped();
        return false;
      }
      PathCommand c = std::move(fifo_.front());
      fifo_.pop_front();
      switch (c.type) {
        case PathCommandType::Motion:
          cur_ = std::move(c);
          cur_valid_ = true;
          s_cur_ = 0.0;
          gears_ = std::move(pending_gears_);
          pending_gears_.clear();
          if (stop_at_rest_) {
            plan_stop_feed(0.0);  // a stop ramp crossing into this segment
          } else {
            begin_motion(0.0);
          }
          return true;
        case PathCommandType::Delay:
          st_.speed = 0.0;
          if (c.delay_ms > 0) {
            delay_left_ = c.delay_ms;
            act_ = Act::Delay;
          }
          return true;
        case PathCommandType::Move:
          execute_instant(c);
          if (c.modal) {
            wait_axis_ = c.axis;
            act_ = Act::WaitMove;
            st_.speed = 0.0;
          }
          return true;
        default:
          execute_instant(c);
          return true;
      }
    }
    case Act::Motion: {
      const double t = t_in_ + budget;
      if (t >= feed_.duration() && stop_inside_ && stop_at_rest_) {
        budget = 0.0;
        s_cur_ = s_off_ + feed_.length();
        st_.pos = cur_.geom.point_at(s_cur_);
        st_.speed = st_.acc = 0.0;
        stop_inside_ = false;
        enter_stopped();
        return false;
      }
      if (t >= feed_.duration()) {
        budget = t - feed_.duration();
        const bool halt = stop_at_rest_ && feed_.exit_speed() == 0.0;
        finish_motion();
        if (halt) {
          enter_stopped();
          return false;
        }
        return true;
      }
      t_in_ = t;
      budget = 0.0;
      const MotionState m = feed_.at(t);
      s_cur_ = s_off_ + m.pos;
      st_.speed = m.vel;
      st_.acc = m.acc;
      st_.pos = cur_.geom.point_at(s_cur_);
      return false;
    }
    case Act::Delay:
      if (delay_left_ > budget) {
        delay_left_ -= budget;
        budget = 0.0;
        return false;
      }
      budget -= delay_left_;
      delay_left_ = 0.0;
      act_ = Act::None;
      return true;
    case Act::WaitMove:
      if (aux(wait_axis_).gen->moving()) {
        budget = 0.0;
        return false;
      }
      act_ = Act::None;
      return true;
    case Act::Return:
    case Act::Immediate: {
      const double t = t_in_ + budget;
      if (t >= feed_.duration()) {
        budget = 0.0;  // the line ends at rest; the rest of the cycle is spent there
        st_.pos = aux_line_.end();
        st_.speed = st_.acc = 0.0;
        const bool ret = act_ == Act::Return;
        act_ = Act::None;
        if (ret) {
          stopped_ = false;
          stop_at_rest_ = false;
          if (cur_valid_) begin_motion(s_cur_);
        }
        return false;
      }
      t_in_ = t;
      budget = 0.0;
      const MotionState m = feed_.at(t);
      st_.speed = m.vel;
      st_.acc = m.acc;
      st_.pos = aux_line_.point_at(m.pos);
      return false;
    }
  }
  return false;
}

const PathState& PathGenerator::step() {
  double budget = setup_.cycle_ms;
  st_.t_ms += setup_.cycle_ms;
  check_stop_inputs();
  for (int guard = 0; guard < 1000000 && advance(budget);) ++guard;
  if (act_ != Act::Motion && act_ != Act::Return && act_ != Act::Immediate) st_.speed = st_.acc = 0.0;
  for (auto& kv : aux_) kv.second.gen->step();
  return st_;
}

PathRecording record(PathGenerator& g, std::size_t ticks, bool until_done) {
  return record_path(g, ticks, until_done);
}

}  // namespace servobench::motion
