#include "servobench/motion/pvt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

namespace {

std::string idx(const char* name, std::size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

void check_length(const char* owner, const char* name, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::invalid_argument(std::string(owner) + "." + name + " has " + std::to_string(got) +
                                " values; expected " + std::to_string(want) + " (one per point)");
}

void check_finite_array(const char* owner, const char* name, const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) throw_invalid(owner, idx(name, i).c_str(), v[i], "is not a finite number");
}

void check_count(const char* owner, std::size_t n) {
  if (n < 2)
    throw std::invalid_argument(std::string(owner) + ".count = " + std::to_string(n) +
                                " is outside the allowed range 2..1024 (a table needs two points for a segment)");
}

void check_times(const char* owner, const std::vector<double>& t) {
  check_finite_array(owner, "time_ms", t);
  if (t[0] < 0) throw_invalid(owner, "time_ms[0]", t[0], "must be >= 0 (it is the start delay, GUC L1310)");
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw_invalid(owner, idx("time_ms", i).c_str(), t[i],
                    "must be greater than time_ms[" + std::to_string(i - 1) + "] = " + format_value(t[i - 1]) +
                        " (times strictly increase)");
}

void check_percent_array(const char* owner, const char* name, const std::vector<double>& q) {
  for (std::size_t i = 0; i < q.size(); ++i)
    check_range(owner, idx(name, i).c_str(), q[i], 0.0, 100.0, "GUC Tab 4-10, iDEABOX L6949");
}

void check_common(const char* owner, const std::vector<double>& time_ms, const std::vector<double>& pos) {
  check_count(owner, time_ms.size());
  check_length(owner, "pos", pos.size(), time_ms.size());
  check_times(owner, time_ms);
  check_finite_array(owner, "pos", pos);
}

// Hermite cubic from (p0, v0) to (p1, v1) over T (guc-ecat.md §3.1).
PvtPiece hermite(double t0, double T, double p0, double v0, double p1, double v1) {
  const double D = p1 - p0;
  const double b = 3.0 * D / (T * T) - (2.0 * v0 + v1) / T;
  const double a = (v0 + v1) / (T * T) - 2.0 * D / (T * T * T);
  return {t0, Segment{T, p0, v0, 2.0 * b, 6.0 * a}};
}

PvtCurve hermite_curve(PvtMode mode, const std::vector<double>& t, const std::vector<double>& p,
                       const std::vector<double>& v_begin, const std::vector<double>& v_end) {
  PvtCurve c;
  c.mode = mode;
  c.time_ms = t;
  c.pos = p;
  c.vel = v_end;
  c.vel[0] = v_begin[0];
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    c.pieces.push_back(hermite(t[i], t[i + 1] - t[i], p[i], v_begin[i], p[i + 1], v_end[i + 1]));
  c.blocks_per_point.assign(t.size(), 1);
  return c;
}

}  // namespace

const char* to_string(PvtMode mode) {
  switch (mode) {
    case PvtMode::Pvt: return "pvt";
    case PvtMode::PvtEx: return "pvt_ex";
    case PvtMode::Complete: return "complete";
    case PvtMode::Percent: return "percent";
    case PvtMode::Continuous: return "continuous";
    case PvtMode::ContinuousEx: return "continuous_ex";
  }
  return "?";
}

int PvtCurve::blocks() const {
  int n = 0;
  for (int b : blocks_per_point) n += b;
  return n;
}

MotionState PvtCurve::at(double t_ms) const {
  if (pieces.empty() || t_ms < pieces.front().t0_ms) return {pos.front(), 0.0, 0.0, 0.0};
  auto it = std::upper_bound(pieces.begin(), pieces.end(), t_ms,
                             [](double t, const PvtPiece& pc) { return t < pc.t0_ms; });
  const PvtPiece& pc = *(it - 1);
  const double tau = std::min(t_ms - pc.t0_ms, pc.seg.duration);
  MotionState s = pc.seg.at(tau);
  if (it == pieces.end() && t_ms >= t_last()) s.pos = pos.back();  // the last point exactly
  return s;
}

int append_percent_ramp(std::vector<PvtPiece>& out, double t0, double T, double p0, double v0, double v1,
                        double q) {
  if (!(T > 0.0)) return 0;
  const double dv = v1 - v0;
  if (dv == 0.0 || q <= 0.0) {
    out.push_back({t0, Segment{T, p0, v0, dv / T, 0.0}});
    return 1;
  }
  const double ta = q * T / 2.0;
  const double te = T - 2.0 * ta;
  const double A = dv / (T - ta);
  const double J = A / ta;
  int n = 0;
  Segment s{ta, p0, v0, 0.0, J};
  out.push_back({t0, s});
  ++n;
  MotionState e = s.at(ta);
  double t = t0 + ta;
  if (te > 1e-12 * T) {
    Segment c{te, e.pos, e.vel, A, 0.0};
    out.push_back({t, c});
    ++n;
    e = c.at(te);
    t += te;
  }
  out.push_back({t, Segment{ta, e.pos, e.vel, A, -J}});
  return n + 1;
}

PvtCurve pvt_table(const std::vector<double>& time_ms, const std::vector<double>& pos,
                   const std::vector<double>& vel) {
  const char* owner = "PvtTable";
  check_common(owner, time_ms, pos);
  check_length(owner, "vel", vel.size(), time_ms.size());
  check_finite_array(owner, "vel", vel);
  return hermite_curve(PvtMode::Pvt, time_ms, pos, vel, vel);
}

PvtCurve pvt_table_ex(const std::vector<double>& time_ms, const std::vector<double>& pos,
                      const std::vector<double>& vel_begin, const std::vector<double>& vel_end) {
  const char* owner = "PvtTableEx";
  check_common(owner, time_ms, pos);
  check_length(owner, "vel_begin", vel_begin.size(), time_ms.size());
  check_length(owner, "vel_end", vel_end.size(), time_ms.size());
  check_finite_array(owner, "vel_begin", vel_begin);
  check_finite_array(owner, "vel_end", vel_end);
  return hermite_curve(PvtMode::PvtEx, time_ms, pos, vel_begin, vel_end);
}

std::vector<double> pvt_complete_velocities(const std::vector<double>& t, const std::vector<double>& p,
                                            double vel_begin, double vel_end) {
  const char* owner = "PvtTableComplete";
  check_common(owner, t, p);
  if (!std::isfinite(vel_begin)) throw_invalid(owner, "vel_begin", vel_begin, "is not a finite number");
  if (!std::isfinite(vel_end)) throw_invalid(owner, "vel_end", vel_end, "is not a finite number");
  const std::size_t n = t.size();
  std::vector<double> v(n, 0.0);
  v[0] = vel_begin;
  v[n - 1] = vel_end;
  if (n == 2) return v;
  // Tridiagonal system for v_1..v_{n-2} (guc-ecat.md §3.2), Thomas algorithm; the pA/pB/pC of the manual.
  const std::size_t m = n - 2;
  std::vector<double> lo(m), di(m), up(m), rhs(m);
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = k + 1;
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    lo[k] = h1;
    di[k] = 2.0 * (h0 + h1);
    up[k] = h0;
    rhs[k] = 3.0 * (h1 * (p[i] - p[i - 1]) / h0 + h0 * (p[i + 1] - p[i]) / h1);
  }
  rhs[0] -= lo[0] * vel_begin;
  rhs[m - 1] -= up[m - 1] * vel_end;
  for (std::size_t k = 1; k < m; ++k) {
    const double w = lo[k] / di[k - 1];
    di[k] -= w * up[k - 1];
    rhs[k] -= w * rhs[k - 1];
  }
  v[m] = rhs[m - 1] / di[m - 1];
  for (std::size_t k = m - 1; k-- > 0;) v[k + 1] = (rhs[k] - up[k] * v[k + 2]) / di[k];
  return v;
}

PvtCurve pvt_table_complete(const std::vector<double>& time_ms, const std::vector<double>& pos, double vel_begin,
                            double vel_end) {
  const auto v = pvt_complete_velocities(time_ms, pos, vel_begin, vel_end);
  return hermite_curve(PvtMode::Complete, time_ms, pos, v, v);
}

std::vector<double> pvt_percent_calculate(const std::vector<double>& t, const std::vector<double>& p,
                                          const std::vector<double>& percent, double vel_begin) {
  const char* owner = "PvtTablePercent";
  check_common(owner, t, p);
  check_length(owner, "percent", percent.size(), t.size());
  check_percent_array(owner, "percent", percent);
  if (!std::isfinite(vel_begin)) throw_invalid(owner, "vel_begin", vel_begin, "is not a finite number");
  std::vector<double> v(t.size());
  v[0] = vel_begin;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) v[i + 1] = 2.0 * (p[i + 1] - p[i]) / (t[i + 1] - t[i]) - v[i];
  return v;
}

PvtCurve pvt_table_percent(const std::vector<double>& t, const std::vector<double>& p,
                           const std::vector<double>& percent, double vel_begin) {
  PvtCurve c;
  c.mode = PvtMode::Percent;
  c.time_ms = t;
  c.pos = p;
  c.vel = pvt_percent_calculate(t, p, percent, vel_begin);
  c.blocks_per_point.assign(t.size(), 1);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    c.blocks_per_point[i] =
        append_percent_ramp(c.pieces, t[i], t[i + 1] - t[i], p[i], c.vel[i], c.vel[i + 1], percent[i] / 100.0);
  }
  return c;
}

namespace {

struct ContinuousSegmentPlan {
  double t_acc = 0, t_cruise = 0, t_dec = 0, v_peak = 0;
};

// Average acceleration of an S ramp whose peak (or average) is `acc` with jerk share q.
double mean_acc(double acc, double q, ContinuousAcc meaning) {
  return meaning == ContinuousAcc::Peak ? acc * (1.0 - q / 2.0) : acc;
}

ContinuousSegmentPlan plan_continuous_segment(const ContinuousPoints& P, std::size_t i, ContinuousAcc meaning) {
  const char* owner = "PvtTableContinuous";
  const double L = std::fabs(P.pos[i + 1] - P.pos[i]);
  const double s = P.pos[i + 1] >= P.pos[i] ? 1.0 : -1.0;
  if (L == 0.0)
    throw_invalid(owner, idx("pos", i + 1).c_str(), P.pos[i + 1],
                  "equals pos[" + std::to_string(i) + "]: a continuous segment needs a distance (no times are given)");
  const double vmax = P.vel_max[i];
  const double vs = s * P.vel[i], ve = s * P.vel[i + 1];
  auto check_v = [&](std::size_t k, double vdir) {
    if (vdir < 0.0 || vdir > vmax)
      throw_invalid(owner, idx("vel", k).c_str(), P.vel[k],
                    "must point along the move pos[" + std::to_string(i) + "] -> pos[" + std::to_string(i + 1) +
                        "] with |vel| <= vel_max[" + std::to_string(i) + "] = " + format_value(vmax));
  };
  check_v(i, vs);
  check_v(i + 1, ve);
  const double qa = P.acc_percent[i] / 100.0, qd = P.dec_percent[i] / 100.0;
  const double aa = mean_acc(P.acc[i], qa, meaning), ad = mean_acc(P.dec[i], qd, meaning);
  const double d_acc = (vmax * vmax - vs * vs) / (2.0 * aa), d_dec = (vmax * vmax - ve * ve) / (2.0 * ad);
  ContinuousSegmentPlan r;
  if (d_acc + d_dec <= L) {
    r.v_peak = vmax;
    r.t_cruise = (L - d_acc - d_dec) / vmax;
  } else {
    const double vp2 = (L + vs * vs / (2.0 * aa) + ve * ve / (2.0 * ad)) / (1.0 / (2.0 * aa) + 1.0 / (2.0 * ad));
    const double vp = std::sqrt(std::max(vp2, 0.0));
    const double vmin = std::max(vs, ve);
    if (vp < vmin * (1.0 - 1e-12))
      throw_invalid(owner, idx("pos", i + 1).c_str(), P.pos[i + 1],
                    "is too close to pos[" + std::to_string(i) + "]: the velocity change " + format_value(P.vel[i]) +
                        " -> " + format_value(P.vel[i + 1]) + " pulse/ms needs " +
                        format_value(std::fabs(vs * vs - ve * ve) / (2.0 * (vs > ve ? ad : aa))) + " pulse");
    r.v_peak = std::max(vp, vmin);
  }
  r.t_acc = (r.v_peak - vs) / aa;
  r.t_dec = (r.v_peak - ve) / ad;
  return r;
}

void validate_continuous(const ContinuousPoints& P) {
  const char* owner = "PvtTableContinuous";
  const std::size_t n = P.pos.size();
  check_count(owner, n);
  check_length(owner, "vel", P.vel.size(), n);
  check_length(owner, "acc_percent", P.acc_percent.size(), n);
  check_length(owner, "dec_percent", P.dec_percent.size(), n);
  check_length(owner, "vel_max", P.vel_max.size(), n);
  check_length(owner, "acc", P.acc.size(), n);
  check_length(owner, "dec", P.dec.size(), n);
  check_finite_array(owner, "pos", P.pos);
  check_finite_array(owner, "vel", P.vel);
  check_percent_array(owner, "acc_percent", P.acc_percent);
  check_percent_array(owner, "dec_percent", P.dec_percent);
  for (std::size_t i = 0; i + 1 < n; ++i) {  // the last point's limits are unused
    check_positive(owner, idx("vel_max", i).c_str(), P.vel_max[i]);
    check_positive(owner, idx("acc", i).c_str(), P.acc[i]);
    check_positive(owner, idx("dec", i).c_str(), P.dec[i]);
  }
}

}  // namespace

std::vector<double> pvt_continuous_calculate(const ContinuousPoints& P, ContinuousAcc meaning) {
  validate_continuous(P);
  std::vector<double> t(P.pos.size(), 0.0);
  for (std::size_t i = 0; i + 1 < P.pos.size(); ++i) {
    const auto r = plan_continuous_segment(P, i, meaning);
    t[i + 1] = t[i] + r.t_acc + r.t_cruise + r.t_dec;
  }
  return t;
}

PvtCurve pvt_table_continuous(const ContinuousPoints& P, double time_begin_ms, ContinuousAcc meaning, bool ex) {
  validate_continuous(P);
  check_range("PvtTableContinuous", "time_begin_ms", time_begin_ms, 0.0, 1e9, "ms, the start delay, GUC L1242");
  PvtCurve c;
  c.mode = ex ? PvtMode::ContinuousEx : PvtMode::Continuous;
  const std::size_t n = P.pos.size();
  c.pos = P.pos;
  c.vel = P.vel;
  c.time_ms.assign(n, time_begin_ms);
  c.blocks_per_point.assign(n, 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const auto r = plan_continuous_segment(P, i, meaning);
    const double s = P.pos[i + 1] >= P.pos[i] ? 1.0 : -1.0;
    double t = c.time_ms[i];
    double p = P.pos[i];
    const double vp = s * r.v_peak;
    int k = append_percent_ramp(c.pieces, t, r.t_acc, p, P.vel[i], vp, P.acc_percent[i] / 100.0);
    if (k > 0) {
      const Segment& last = c.pieces.back().seg;
      p = last.at(last.duration).pos;
      t += r.t_acc;
    }
    if (r.t_cruise > 0.0) {
      c.pieces.push_back({t, Segment{r.t_cruise, p, vp, 0.0, 0.0}});
      p += vp * r.t_cruise;
      t += r.t_cruise;
      ++k;
    }
    k += append_percent_ramp(c.pieces, t, r.t_dec, p, vp, P.vel[i + 1], P.dec_percent[i] / 100.0);
    c.time_ms[i + 1] = c.time_ms[i] + r.t_acc + r.t_cruise + r.t_dec;
    c.blocks_per_point[i] = std::max(k, 1);
  }
  return c;
}

}  // namespace servobench::motion
