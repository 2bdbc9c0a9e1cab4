// Look-ahead (trajectory pre-processing) for coordinated paths: the end speed of every segment, from a
// window of the n segments that follow it.
//
// Parameters are the manuals' (GUC L725-732, L908-995; iDEABOX L1902-2126, L5848-5879; GE L1666-1941): the
// corner ("turning") time T, the maximum acceleration accMax, the window n. The manuals give no algorithm;
// ours (decisions C10-C16 in docs/decisions.md):
//  1. segment cap: vmax_i = the segment's cruise speed, and on arcs sqrt(accMax * curvature radius) so the
//     centripetal acceleration stays <= accMax; a_i = min(segment acceleration, accMax);
//  2. corner cap between i and i+1 (unit tangents u_out_i, u_in_{i+1}): the change of the velocity vector
//     v*|u_in - u_out| spread over T at accMax: v_c = accMax*T / |u_in - u_out|; also <= vmax_i, vmax_{i+1};
//     0 before a G0 segment, a delay or a modal move and after a forced stop (dccFlag / velEndZero);
//  3. the window's last segment ends at 0 (the future is unknown), so the path can always stop;
//  4. backward pass v_i <= sqrt(v_{i+1}^2 + 2 a_{i+1} L_{i+1}). In squared speeds with W_j = sum of 2 a_k L_k up
//     to the end of segment j this is v_i^2 = min_{j >= i}(cap_j^2 + W_j) - W_i (the window end counting as a
//     cap of 0): a sliding-window minimum, kept in a monotonic deque, O(1) amortised per segment whatever
//     the window n or the segment lengths;
//  5. a segment leaves the window when n newer ones are behind it (or on flush); its end speed is fixed
//     then by the forward pass v_i = min(backward_i, sqrt(v_{i-1}^2 + 2 a_i L_i)).
// Every pair of consecutive end speeds is then reachable within the segment at a_i <= accMax, so a trapezoid
// feed (path_feed.hpp) never exceeds accMax along the path. Units: coordinate unit and ms.
//
// Per-axis limits (issue 25 point 4; GT AccLmt L1956-1963, decisions VF5-VF10), when the path generator sets
// them (PathSetup axis_acc_1..4 / corner_axis_acc): axis k's acceleration, as the second difference of its
// position over one motion cycle h, stays <= A_k. The second difference is the integral of the axis's
// acceleration against a hat of width 2h and area h^2; a corner is a velocity step v_c |du_k| under it (weight
// <= h), the ramps around it contribute <= max(side_out_k, side_in_k) h^2 (side = what the segment asks of the
// axis: a |u_k| on lines, plus v_max^2/R on arcs). Hence the cap 6. below, and a segment that starts with a
// corner runs at <= L/(2h) so that two corners are never inside one hat (the path generator's cap):
//  6. v_c <= min_k (A_k - max(side_out_k, side_in_k)) h / |du_k| (0 when a budget is <= 0), with du and u taken
//     through the coordinate map in motor-axis units. The path-level cap 2. (T) still applies (GUC L967).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "servobench/motion/path_segment.hpp"

namespace servobench::motion {

// Per-axis acceleration limits (issue 25 point 4; GT AccLmt L1956): acc[k] > 0 bounds motor axis k's
// acceleration, unit/ms^2, as the second difference of its position over one motion cycle of cycle_ms; 0 = none.
struct AxisAccLimits {
  std::array<double, 4> acc{};
  double cycle_ms = 1.0;
  bool any() const;
};

// What a segment asks of each motor axis: the unit tangents at both ends through the coordinate map, and the bound
// on each axis's acceleration anywhere inside the segment (ramp and centripetal), unit/ms^2.
struct AxisDemand {
  CrdPoint u_in{}, u_out{};
  CrdPoint acc{};
};

// Corner cap (rule 6.): min over limited axes of (A_k - max(out.acc_k, in.acc_k)) * cycle / |in.u_in_k - out.u_out_k|,
// 0 if a budget is <= 0 on an axis whose velocity direction changes; inf without limits or without a change.
double axis_corner_speed_limit(const AxisDemand& out, const AxisDemand& in, const AxisAccLimits& lim);

// GT_InitLookAhead(crd, fifo, T, accMax, n, buf) (GUC L725-732; iDEABOX L5848-5879).
struct LookAheadParams {
  double t_ms = 5.0;       // corner time T, ms (0 < T <= 1000; the manuals' empirical range is 1-10 ms)
  double acc_max = 1.0;    // maximum acceleration, coordinate unit/ms^2 (0 < accMax < 32767)
  double n = 200.0;        // window, segments (0..32766; 0 = look-ahead off; GE requires >= 200)
  AxisAccLimits axis_limits;  // set by the path generator from its PathSetup (not a GT_InitLookAhead argument)
  void validate() const;
};

// What the planner needs of one segment.
struct LookAheadSegment {
  double length = 0.0;            // > 0
  double vmax = 0.0;              // cruise speed (override, synVelMax applied)
  double acc = 0.0;               // segment acceleration (synAcc, synAccMax applied)
  CrdPoint u_in{}, u_out{};       // unit tangents at the start and the end
  double curvature_radius = 0.0;  // inf for lines
  bool stop_before = false;       // the previous segment must end at 0 (G0 here, delay or modal move before)
  bool stop_after = false;        // this segment must end at 0 (G0, dccFlag / velEndZero)
  AxisDemand axes{};              // per-axis demand (used when the params carry axis limits)
};

LookAheadSegment lookahead_segment(const PathSegmentGeometry& g, double vmax, double acc, bool stop_before = false,
                                   bool stop_after = false);

// Corner speed cap for the tangent change u_out -> u_in: acc_max * t / |u_in - u_out| (inf when collinear).
double corner_speed_limit(const CrdPoint& u_out, const CrdPoint& u_in, double t, double acc_max);

class LookAhead {
 public:
  explicit LookAhead(const LookAheadParams& p);
  const LookAheadParams& params() const { return p_; }
  std::size_t window() const { return static_cast<std::size_t>(p_.n); }

  // Adds a segment. Returns true if the oldest segment left the window (take it with pop()).
  bool push(const LookAheadSegment& s);
  // Segments in the window.
  std::size_t size() const { return q_.size(); }
  // Removes the oldest segment and returns its final end speed.
  double pop();
  // The current backward limit (end speed bound) of the i-th oldest segment in the window.
  double backward_limit(std::size_t i) const;
  // The end speed of the last segment that left the window (the entry speed of the next one).
  double entry_speed() const { return v_prev_; }
  void reset(double entry_speed = 0.0);

 private:
  struct Entry {
    double length, acc, vmax, w_end, cap_end;  // cap_end NaN while the segment is the window's last
    CrdPoint u_out;
    AxisDemand axes;
  };
  struct Key {
    std::uint64_t index;
    double key;  // cap_end^2 + w_end
  };
  void rebase();
  LookAheadParams p_;
  std::deque<Entry> q_;
  std::deque<Key> mins_;   // increasing keys, increasing indices: the suffix minima of the closed entries
  std::uint64_t front_index_ = 0;  // global index of q_.front()
  double w_total_ = 0.0;   // W at the end of the last segment
  double v_prev_ = 0.0;
};

// The end speed of every segment, as the streaming window gives it (segments pushed one by one, the rest
// flushed at the end: the last ends at 0). v_start: entry speed of the first segment.
std::vector<double> plan_lookahead(const std::vector<LookAheadSegment>& segs, const LookAheadParams& p,
                                   double v_start = 0.0);

// A polyline through `points` (row-major, count x dim) at speed vel and acceleration acc for every segment
// (zero-length steps are skipped: GE AddLookData returns 1 for a repeated point, L3370-3394): end speeds.
std::vector<double> plan_polyline_lookahead(const double* points, std::size_t count, int dim, double vel, double acc,
                                            const LookAheadParams& p);

}  // namespace servobench::motion
