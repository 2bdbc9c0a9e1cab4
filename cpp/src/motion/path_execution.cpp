// The path generator's execution, one servo tick at a time: per-axis limits of a segment, the exit speed, the
// motion of a segment and the instants between segments (motion/path_generator.hpp).
#include "servobench/motion/path_generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"

namespace servobench::motion {

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
