#include "servobench/motion/adlink_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"
#include "servobench/motion/generator.hpp"

namespace servobench::motion {

namespace {
// Time (ticks from the profile start) at which the path length first reaches s.
double time_at_s(const Profile& p, double s) {
  if (s <= p.start().pos) return 0.0;
  double lo = 0.0, hi = p.duration();
  for (int it = 0; it < 100 && hi - lo > 1e-12 * (1.0 + hi); ++it) {
    const double mid = 0.5 * (lo + hi);
    (p.at(mid).pos >= s ? hi : lo) = mid;
  }
  return hi;
}

// Start of the final deceleration: the trailing segments along which the speed falls.
double decel_start(const Profile& p) {
  double t = p.duration();
  for (int i = p.size() - 1; i >= 0; --i) {
    const Segment& s = p.segment(i);
    if (!(s.at(s.duration).vel < s.v - 1e-15)) break;
    t -= s.duration;
  }
  return t;
}

SpacePoint add(const SpacePoint& a, const SpacePoint& b, int dim) {
  SpacePoint r = a;
  for (int k = 0; k < dim; ++k) r[static_cast<std::size_t>(k)] += b[static_cast<std::size_t>(k)];
  return r;
}
}  // namespace

SpaceSegment AdlinkMoveSpec::build(const SpacePoint& start, const SpacePoint& ref, int dim) const {
  const SpacePoint tgt = relative ? add(ref, target, dim) : target;
  const SpacePoint ctr = relative ? add(ref, center, dim) : center;
  switch (kind) {
    case Kind::Line:
      check_integer("AdlinkLine", "dim", dim, 2, kSpaceMaxDim, "axes; ADLINK L2817, L2829");
      return SpaceSegment::line(start, tgt, dim);
    case Kind::Arc2Ca: return SpaceSegment::arc2_ca(start, ctr, angle_deg);
    case Kind::Arc2Ce: return SpaceSegment::arc2_ce(start, ctr, tgt, dir);
    case Kind::Arc3Ca: return SpaceSegment::arc3_ca(start, ctr, normal, angle_deg);
    case Kind::Arc3Ce: return SpaceSegment::arc3_ce(start, ctr, tgt, dir);
    case Kind::SpiralCa: return SpaceSegment::spiral_ca(start, ctr, normal, angle_deg, height, final_radius);
    case Kind::SpiralCe: return SpaceSegment::spiral_ce(start, ctr, normal, tgt, dir);
    case Kind::Dwell: return SpaceSegment::hold(start, dim);
  }
  throw std::invalid_argument("AdlinkMoveSpec: unknown kind");
}

void AdlinkInterpSetup::validate() const {
  check_range("AdlinkInterpSetup", "period_s", period_s, 1e-4, 0.1, "motion cycle, s; ADLINK L1633-1647: 1 ms");
  check_integer("AdlinkInterpSetup", "buffer_size", buffer_size, 1, 1e6, "pending moves; decision C40 (PTP: 10, L2771)");
}

AdlinkInterpolator::AdlinkInterpolator(const std::vector<int>& axes, const AdlinkInterpSetup& setup,
                                       const std::vector<double>& start)
    : axes_(axes), setup_(setup) {
  setup_.validate();
  const char* o = "AdlinkInterpolator";
  if (axes.size() < 2 || axes.size() > 6)
    throw_invalid(o, "axes", static_cast<double>(axes.size()), "must name 2..6 axes (ADLINK L2817, L2829)");
  for (std::size_t i = 0; i < axes.size(); ++i) {
    check_integer(o, "axes[k]", axes[i], 0, 7, "axis IDs of a PCI-8258");
    for (std::size_t j = 0; j < i; ++j)
      if (axes[j] == axes[i]) throw_invalid(o, "axes[k]", axes[i], "appears twice in the axis array");
  }
  if (!start.empty() && start.size() != axes.size())
    throw_invalid(o, "start", static_cast<double>(start.size()), "must have one position per axis");
  for (std::size_t i = 0; i < start.size(); ++i) {
    check_range(o, "start[k]", start[i], -2147483647.0, 2147483647.0, "pulse");
    base_[i] = start[i];
  }
  tail_ = base_;
  st_.pos = base_;
}

void AdlinkInterpolator::set_axis_params(int axis, const AdlinkPtpParams& p) {
  if (std::find(axes_.begin(), axes_.end(), axis) == axes_.end())
    throw_invalid("AdlinkInterpolator", "axis", axis, "is not in the axis array");
  p.validate();
  params_[axis] = p;
}

const AdlinkPtpParams& AdlinkInterpolator::axis_params(int axis) const {
  auto it = params_.find(axis);
  if (it == params_.end()) throw_invalid("AdlinkInterpolator", "axis", axis, "has no parameters set");
  return it->second;
}

AdlinkLimits AdlinkInterpolator::limits_for(double vm, const AdlinkPtpParams* all, double* sd_dec) const {
  AdlinkPtpParams p;
  if (all != nullptr) {
    p = *all;
  } else {
    auto it = params_.find(axes_[0]);
    if (it == params_.end())
      throw std::invalid_argument("AdlinkInterpolator: set_axis_params(reference axis " + std::to_string(axes_[0]) +
                                  ") first: the reference axis's profile drives the path (ADLINK L2819-2825)");
    p = it->second;
  }
  if (vm != 0.0) {
    check_range("AdlinkInterpolator", "vm", vm, 0.0, 1e9, "pulse/s, the _v form's maximum speed; ADLINK L2744-2751");
    if (!(vm > 0.0)) throw_invalid("AdlinkInterpolator", "vm", vm, "must be > 0 (pulse/s)");
    p.vm = vm;
    p.vs = std::min(p.vs, vm);
    p.ve = std::min(p.ve, vm);
  }
  p.validate();
  if (sd_dec != nullptr) *sd_dec = p.sd_dec_per_tick(setup_.period_s);
  return p.limits(setup_.period_s);
}

void AdlinkInterpolator::position_at(double t, SpacePoint& pos, SpacePoint& vel) const {
  pos = base_;
  vel = SpacePoint{};
  const int d = dim();
  for (const auto& r : run_) {
    const MotionState m = r.prof.at(std::max(t - r.t0, 0.0));
    const SpacePoint p = r.geom.point_at(m.pos);
    const SpacePoint u = r.geom.tangent_at(m.pos);
    for (int k = 0; k < d; ++k) {
      const auto i = static_cast<std::size_t>(k);
      pos[i] += p[i] - r.geom.start()[i];
      vel[i] += u[i] * m.vel;
    }
  }
}

void AdlinkInterpolator::stop_running(double sd_dec, bool own_dec) {
  // Every running move decelerates to rest along its own path, never beyond its end.
  for (auto& r : run_) {
    const MotionState m = r.prof.at(std::max(t_ - r.t0, 0.0));
    const double rate = own_dec ? r.lim.dec : sd_dec;
    const double room = r.geom.length() - m.pos;
    double dec = rate;
    if (m.vel > 0.0 && room > 0.0) dec = std::max(dec, (1.0 + r.lim.sf) * m.vel * m.vel / (2.0 * room));
    Profile p = m.vel > 0.0 ? plan_adlink_stop(m, dec, r.lim.sf) : Profile::rest(m.pos);
    if (p.end().pos > r.geom.length()) p.finish_at_rest(r.geom.length());
    r.prof = p;
    r.t0 = t_;
  }
}

void AdlinkInterpolator::push(const AdlinkMoveSpec& spec, BlendMode mode, double blend, double vm,
                              const AdlinkPtpParams* all) {
  const char* o = "AdlinkInterpolator";
  const int m = static_cast<int>(mode);
  check_integer(o, "mode", m, 1, 7, "transition mode (Flag); ADLINK L3085-3143");
  if (mode == BlendMode::BlendDistance) {
    check_range(o, "blend", blend, 0, 1e12, "residual distance, pulse; ADLINK L3131-3136");
    if (!(blend > 0)) throw_invalid(o, "blend", blend, "must be > 0 (residual distance, pulse)");
  } else if (mode == BlendMode::BlendPercent) {
    check_range(o, "blend", blend, 0, 100, "residual distance, % of the move; ADLINK L3138-3143");
    if (!(blend > 0 && blend < 100)) throw_invalid(o, "blend", blend, "must be in the open interval (0, 100) %");
  }
  double sd = 0.0;
  AdlinkLimits lim = limits_for(vm, all, &sd);
  const int d = dim();
  if (spec.kind == AdlinkMoveSpec::Kind::Dwell) {  // always buffered (APS_pt_dwell, L3838)
    check_range(o, "dwell_s", spec.dwell_s, 0.0, 1e6, "s, the dwell time");
    if (!(spec.dwell_s > 0.0)) throw_invalid(o, "dwell_s", spec.dwell_s, "must be > 0 (s)");
    if (static_cast<double>(queue_.size()) >= setup_.buffer_size)
      throw MotionCommandRefused("AdlinkInterpolator: the interpolation buffer is full (return code: buffer full)");
    Pending p{spec, spec.build(tail_, tail_, d), true, BlendMode::Buffered, 0.0, lim, t_, tail_,
              std::max(1.0, std::round(spec.dwell_s / setup_.period_s))};
    queue_.push_back(std::move(p));
    return;
  }
  const bool abort = m <= 3;
  if (!abort) {
    if (static_cast<double>(queue_.size()) >= setup_.buffer_size)
      throw MotionCommandRefused("AdlinkInterpolator: the interpolation buffer is full (return code: buffer full)");
    Pending p{spec, spec.build(tail_, tail_, d), true, mode, blend, lim, t_, tail_, 0.0};
    plan_adlink_ptp(0.0, p.geom.length(), lim);  // refuses a VS -> VE ramp longer than the move (decision M9)
    tail_ = p.geom.end();
    queue_.push_back(std::move(p));
    return;
  }
  SpacePoint P, V;
  position_at(t_, P, V);
  if (mode == BlendMode::AbortForced) {
    const SpaceSegment g = spec.build(P, P, d);
    double v = 0.0;
    for (int k = 0; k < d; ++k) v += V[static_cast<std::size_t>(k)] * V[static_cast<std::size_t>(k)];
    lim.vs = std::min(std::sqrt(v), lim.vm);
    const Profile prof = plan_adlink_ptp(0.0, g.length(), lim);
    queue_.clear();
    run_.clear();
    base_ = P;
    run_.push_back({g, prof, t_, lim, false});
    tail_ = g.end();
    return;
  }
  // AbortBlend / AbortStop: predict where the decelerating moves come to rest (S2) first, then commit.
  auto saved = run_;
  stop_running(sd, mode == BlendMode::AbortBlend);
  SpacePoint S2 = base_;
  double t_stop = t_;
  for (const auto& r : run_) {
    const SpacePoint e = r.geom.point_at(r.prof.end().pos);
    for (int k = 0; k < d; ++k) S2[static_cast<std::size_t>(k)] += e[static_cast<std::size_t>(k)] - r.geom.start()[static_cast<std::size_t>(k)];
    t_stop = std::max(t_stop, r.t0 + r.prof.duration());
  }
  try {
    const SpaceSegment g = spec.build(S2, P, d);
    const Profile prof = plan_adlink_ptp(0.0, g.length(), lim);
    queue_.clear();
    tail_ = g.end();
    if (mode == BlendMode::AbortBlend) {
      run_.push_back({g, prof, t_, lim, false});
    } else {
      queue_.push_back(Pending{spec, g, true, mode, 0.0, lim, t_stop, P, 0.0});
    }
  } catch (...) {
    run_ = std::move(saved);
    throw;
  }
}

void AdlinkInterpolator::stop_move() {
  double sd = 0.0;
  limits_for(0.0, nullptr, &sd);
  queue_.clear();
  stop_running(sd, false);
  SpacePoint S2 = base_;
  for (const auto& r : run_) {
    const SpacePoint e = r.geom.point_at(r.prof.end().pos);
    for (int k = 0; k < dim(); ++k) S2[static_cast<std::size_t>(k)] += e[static_cast<std::size_t>(k)] - r.geom.start()[static_cast<std::size_t>(k)];
  }
  tail_ = S2;
}

void AdlinkInterpolator::emg_stop() {
  SpacePoint P, V;
  position_at(t_, P, V);
  queue_.clear();
  run_.clear();
  base_ = P;
  tail_ = P;
  st_.vel = SpacePoint{};
  st_.speed = 0.0;
}

double AdlinkInterpolator::trigger_time(const Pending& p) const {
  if (run_.empty()) return last_end_;
  if (p.mode == BlendMode::AbortStop) {
    double t = 0.0;
    for (const auto& r : run_) t = std::max(t, r.t0 + r.prof.duration());
    return t;
  }
  const Running& b = run_.back();
  if (b.dwell || p.dwell_ticks > 0.0) {  // a dwell follows, and is followed by, the end of the moves before it
    double t = 0.0;
    for (const auto& r : run_) t = std::max(t, r.t0 + r.prof.duration());
    return t;
  }
  const double L = b.geom.length();
  switch (p.mode) {
    case BlendMode::BlendDecel: return b.t0 + decel_start(b.prof);
    case BlendMode::BlendDistance: return b.t0 + (p.blend >= L ? 0.0 : time_at_s(b.prof, L - p.blend));
    case BlendMode::BlendPercent: return b.t0 + time_at_s(b.prof, L * (1.0 - p.blend / 100.0));
    default: return b.t0 + b.prof.duration();
  }
}

void AdlinkInterpolator::settle() {
  const int d = dim();
  for (std::size_t i = 0; i < run_.size();) {
    Running& r = run_[i];
    const double t_end = r.t0 + r.prof.duration();
    if (t_ >= t_end) {
      const SpacePoint e = r.geom.point_at(r.prof.end().pos);
      for (int k = 0; k < d; ++k) base_[static_cast<std::size_t>(k)] += e[static_cast<std::size_t>(k)] - r.geom.start()[static_cast<std::size_t>(k)];
      last_end_ = std::max(last_end_, t_end);
      ++st_.moves_done;
      run_.erase(run_.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      ++i;
    }
  }
}

const AdlinkInterpState& AdlinkInterpolator::step() {
  t_ += 1.0;
  for (int guard = 0; guard < 100000 && !queue_.empty(); ++guard) {
    const double t0 = std::max(trigger_time(queue_.front()), queue_.front().arrival);
    if (t0 > t_) break;
    Pending p = std::move(queue_.front());
    queue_.pop_front();
    if (p.dwell_ticks > 0.0)
      run_.push_back({p.geom, Profile(MotionState{}).push(p.dwell_ticks, 0.0), t0, p.lim, true});
    else
      run_.push_back({p.geom, plan_adlink_ptp(0.0, p.geom.length(), p.lim), t0, p.lim, false});
  }
  settle();
  SpacePoint V;
  position_at(t_, st_.pos, V);
  double sq = 0.0;
  for (int k = 0; k < dim(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    st_.vel[i] = V[i] / setup_.period_s;
    sq += st_.vel[i] * st_.vel[i];
  }
  st_.speed = std::sqrt(sq);
  st_.t_s = t_ * setup_.period_s;
  return st_;
}

AdlinkInterpRecording record(AdlinkInterpolator& g, std::size_t ticks, bool until_done) {
  AdlinkInterpRecording r;
  r.dim = g.dim();
  for (std::size_t k = 0; k < ticks; ++k) {
    if (until_done && g.done()) break;
    const auto& s = g.step();
    r.t_s.push_back(s.t_s);
    for (int i = 0; i < r.dim; ++i) r.pos.push_back(s.pos[static_cast<std::size_t>(i)]);
    r.speed.push_back(s.speed);
    r.moves_done.push_back(static_cast<double>(s.moves_done));
  }
  return r;
}

}  // namespace servobench::motion
