// GE look-ahead module A in the GE manual's units (GE §6.4, seed 001 L1666-1727, API L3370-3394, L3790-3800,
// L4879-4887; digest ge.md §4.6 (A)): GT_InitLookAhead(T s, acc_max mm/s^2, acc mm/s^2, vel mm/s, n, con
// pulse/mm), GT_AddLookData(code, plane_group, r, x, y, z, vel, cx, cy, i, n, flag), GT_CalVel(&vel, &number).
// The host then sends each segment to the card with GT_SetDccVel(end velocity in pulse/ms) (L1679).
//
// The planner is the path layer's LookAhead (decisions C10-C16) run in pulse and ms: lengths mm * con,
// speeds mm/s * con / 1000, accelerations mm/s^2 * con / 1e6, T s * 1000. Segments: code 0 G00 line (starts and
// ends at rest), 1 G01 line, 2 G02 clockwise arc, 3 G03 counter-clockwise arc; plane_group 17 XY, 18 ZX, 19 YZ
// with the centre (cx, cy) in that plane's coordinates ((x, y), (z, x), (y, z)); r must agree with the distance
// centre-start within 1 pulse (decision C34). The path starts at `start` (mm; module A has no Mv command).
// `flag`: the segment must end at rest (tool change). Return codes as the manual: add() 0 accepted, 1 the point
// equals the previous one (nothing added); cal_vel() 0 more segments follow, 1 this was the last one.
#pragma once

#include <deque>

#include "servobench/motion/lookahead.hpp"

namespace servobench::motion {

struct GeLookAheadParams {
  double t_s = 0.005;        // corner time T, s (empirically 0.001-0.01, GE L1691-1693)
  double acc_max = 1000.0;   // mm/s^2 (empirically 100-10000)
  double acc = 500.0;        // running acceleration, mm/s^2, < acc_max
  double vel = 50.0;         // feed, mm/s (used when a segment gives vel = 0)
  double n = 200;            // window, segments, 1..32766
  double con = 1000.0;       // pulse/mm
  void validate() const;
};

class GeLookAhead {
 public:
  explicit GeLookAhead(const GeLookAheadParams& p, const CrdPoint& start_mm = {});
  int add(int code, int plane_group, double r, double x, double y, double z, double vel, double cx, double cy,
          long long number, bool flag);
  // End velocity (mm/s) of the oldest segment not yet returned and its user number; 1 if it was the last.
  // Throws MotionCommandRefused (return code 1) when nothing is left.
  int cal_vel(double& vel_mm_s, long long& number);
  std::size_t pending() const { return done_.size() + numbers_.size(); }
  const GeLookAheadParams& params() const { return p_; }

 private:
  GeLookAheadParams p_;
  LookAhead la_;
  std::deque<long long> numbers_;                  // user numbers of the segments in the window
  std::deque<std::pair<double, long long>> done_;  // decided end speeds (pulse/ms) and numbers
  CrdPoint last_{};                                // pulse
  bool stop_next_ = false;
};

}  // namespace servobench::motion
