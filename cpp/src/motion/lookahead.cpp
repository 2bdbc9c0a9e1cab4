#include "servobench/motion/lookahead.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

void LookAheadParams::validate() const {
  const char* o = "LookAheadParams";
  check_range(o, "t_ms", t_ms, 0, 1000, "corner time, ms; empirically 1-10 ms, GUC L967, iDEABOX L2079");
  if (!(t_ms > 0)) throw_invalid(o, "t_ms", t_ms, "is outside the allowed range 0..1000 (0 excluded; ms, GUC L967)");
  check_range(o, "acc_max", acc_max, 0, 32767, "pulse/ms^2; GUC L969-971");
  if (!(acc_max > 0)) throw_invalid(o, "acc_max", acc_max, "is outside the allowed range 0..32767 (0 excluded; pulse/ms^2, GUC L969-971)");
  check_integer(o, "n", n, 0, 32766, "segments, [0, 32767); iDEABOX L5871");
  for (double a : axis_limits.acc) check_range(o, "axis_limits.acc", a, 0, 1e9, "unit/ms^2 per axis, 0 = none");
  check_range(o, "axis_limits.cycle_ms", axis_limits.cycle_ms, 0.01, 100, "motion cycle, ms");
}

LookAheadSegment lookahead_segment(const PathSegmentGeometry& g, double vmax, double acc, bool stop_before,
                                   bool stop_after) {
  LookAheadSegment s;
  s.length = g.length();
  s.vmax = vmax;
  s.acc = acc;
  s.u_in = g.tangent_at(0.0);
  s.u_out = g.tangent_at(g.length());
  s.curvature_radius = g.curvature_radius();
  s.stop_before = stop_before;
  s.stop_after = stop_after;
  return s;
}

double corner_speed_limit(const CrdPoint& u_out, const CrdPoint& u_in, double t, double acc_max) {
  double sq = 0.0;
  for (std::size_t k = 0; k < u_in.size(); ++k) sq += (u_in[k] - u_out[k]) * (u_in[k] - u_out[k]);
  const double d = std::sqrt(sq);
  if (d < 1e-15) return std::numeric_limits<double>::infinity();
  return acc_max * t / d;
}

bool AxisAccLimits::any() const {
  for (double a : acc)
    if (a > 0) return true;
  return false;
}

double axis_corner_speed_limit(const AxisDemand& out, const AxisDemand& in, const AxisAccLimits& lim) {
  double v = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < lim.acc.size(); ++k) {
    if (!(lim.acc[k] > 0)) continue;
    const double d = std::fabs(in.u_in[k] - out.u_out[k]);
    if (d < 1e-12) continue;
    const double budget = lim.acc[k] - std::max(out.acc[k], in.acc[k]);
    if (!(budget > 0)) return 0.0;
    v = std::min(v, budget * lim.cycle_ms / d);
  }
  return v;
}

LookAhead::LookAhead(const LookAheadParams& p) : p_(p) { p_.validate(); }

void LookAhead::reset(double entry_speed) {
  q_.clear();
  mins_.clear();
  front_index_ = 0;
  w_total_ = 0.0;
  v_prev_ = entry_speed;
}

bool LookAhead::push(const LookAheadSegment& s) {
  const double vmax = std::min(s.vmax, std::sqrt(p_.acc_max * s.curvature_radius));
  const double acc = std::min(s.acc, p_.acc_max);
  if (!q_.empty()) {
    Entry& last = q_.back();
    if (std::isnan(last.cap_end))
      last.cap_end = s.stop_before ? 0.0
                                   : std::min({last.vmax, vmax, corner_speed_limit(last.u_out, s.u_in, p_.t_ms, p_.acc_max),
                                               axis_corner_speed_limit(last.axes, s.axes, p_.axis_limits)});
    // The previous last is closed now: its key joins the suffix minima.
    const Key k{front_index_ + q_.size() - 1, last.cap_end * last.cap_end + last.w_end};
    while (!mins_.empty() && mins_.back().key >= k.key) mins_.pop_back();
    mins_.push_back(k);
  }
  w_total_ += 2.0 * acc * s.length;
  q_.push_back(Entry{s.length, acc, vmax, w_total_, s.stop_after ? 0.0 : std::numeric_limits<double>::quiet_NaN(), s.u_out,
                     s.axes});
  return q_.size() > window();
}

double LookAhead::backward_limit(std::size_t i) const {
  const std::uint64_t idx = front_index_ + i;
  double m = w_total_;  // the window's end: speed 0 there
  for (const auto& k : mins_)
    if (k.index >= idx) {
      m = std::min(m, k.key);
      break;
    }
  if (!std::isnan(q_[i].cap_end) && i + 1 == q_.size()) m = std::min(m, q_[i].cap_end * q_[i].cap_end + q_[i].w_end);
  return std::sqrt(std::max(m - q_[i].w_end, 0.0));
}

double LookAhead::pop() {
  const double back = backward_limit(0);
  const Entry e = q_.front();
  q_.pop_front();
  if (!mins_.empty() && mins_.front().index == front_index_) mins_.pop_front();
  ++front_index_;
  const double v = std::min(back, std::sqrt(v_prev_ * v_prev_ + 2.0 * e.acc * e.length));
  v_prev_ = v;
  if (!q_.empty() && q_.front().w_end > 64.0 * (w_total_ - q_.front().w_end) + 1e6) rebase();
  return v;
}

void LookAhead::rebase() {
  // Keeps W small against the window's span so the squared speeds keep their precision.
  const double base = q_.front().w_end;
  for (auto& e : q_) e.w_end -= base;
  for (auto& k : mins_) k.key -= base;
  w_total_ -= base;
}

std::vector<double> plan_lookahead(const std::vector<LookAheadSegment>& segs, const LookAheadParams& p,
                                   double v_start) {
  LookAhead la(p);
  la.reset(v_start);
  std::vector<double> out;
  out.reserve(segs.size());
  for (const auto& s : segs) {
    if (la.push(s)) out.push_back(la.pop());
  }
  while (la.size() > 0) out.push_back(la.pop());
  return out;
}

std::vector<double> plan_polyline_lookahead(const double* points, std::size_t count, int dim, double vel, double acc,
                                            const LookAheadParams& p) {
  check_positive("plan_polyline_lookahead", "vel", vel);
  check_positive("plan_polyline_lookahead", "acc", acc);
  if (dim < 1 || dim > 4) throw_invalid("plan_polyline_lookahead", "dim", dim, "is outside the allowed range 1..4");
  LookAhead la(p);
  std::vector<double> out;
  out.reserve(count);
  const auto d = static_cast<std::size_t>(dim);
  LookAheadSegment s;
  s.vmax = vel;
  s.acc = acc;
  s.curvature_radius = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < count; ++i) {
    const double* a = points + (i - 1) * d;
    const double* b = points + i * d;
    double sq = 0.0;
    CrdPoint u{};
    for (std::size_t k = 0; k < d; ++k) {
      u[k] = b[k] - a[k];
      sq += u[k] * u[k];
    }
    if (!(sq > 0.0)) continue;
    const double L = std::sqrt(sq);
    for (std::size_t k = 0; k < d; ++k) u[k] /= L;
    s.length = L;
    s.u_in = u;
    s.u_out = u;
    if (la.push(s)) out.push_back(la.pop());
  }
  while (la.size() > 0) out.push_back(la.pop());
  return out;
}

}  // namespace servobench::motion
