// FollowEx: the iDEABOX electronic cam in the master-position domain (seed 003 L394-929, API L4612-5448,
// L6173-6199, L7212-7417; digest ideabox.md §2.1).
//
// The slave's position is a function of the master's travel since the follow started, written as segments
// into one of two FIFOs per axis. Each segment (master displacement dM, slave displacement dS, type,
// percent) is planned like a PVT Percent segment with master travel in place of time: the velocity ratio
// r = dS/dM of the slave changes from r0 to r1 inside the segment with an S share `percent`, so that
// dS = (r0 + r1)/2 * dM (decision M30). The types set r0 and r1 (L516-530):
//   NORMAL   r0 = 0 for a FIFO's first segment, else the previous segment's r1; r1 = 2 dS/dM - r0
//   EVEN     r0 = r1 = dS/dM
//   STOP     r1 = 0, r0 = 2 dS/dM (independent of the previous segment)
//   CONTINUE as NORMAL, but a FIFO's first segment starts at the previous FIFO's end ratio.
// Complete data (GT_FollowDataCompleteEx) is a clamped C2 spline slave(master) through the given knots with
// the end ratios given (decision M31).
//
// Data values are cumulative positions (decision M30): the master/slave values of GT_FollowDataPercentEx are
// measured from the follow start point, a segment's displacement is the difference to the previous value
// written to the same FIFO (0 after a clear). Complete arrays are knots; the first knot is the curve start.
//
// FIFOs hold 16, 512 or max_segment segments (memory 0/1/2, L489-501); writing to a full FIFO is refused
// (the data is lost, return code 1, L532-534, L4740). Start events: START at FollowStart, PASS when the
// master crosses `event_pos` moving in `master_dir` (L536-542). Loops: loop < 1 infinite (L7302); each
// pass continues from the previous pass's end. dir: 0 follows both master directions, 1 only positive,
// -1 only negative master motion (L6185). GT_FollowSwitchEx: only while moving, the other FIFO must hold
// data; the switch happens at the end of the current pass (decision M33).
//
// The master is a position sequence in pulses, one sample per tick: which signal feeds it is the card's
// master selection (masterType 1 encoder, 2 planned profile, 3 axis with item 0 planned / 1 encoder,
// L7345-7363); here the caller passes the array. Output units: pulse, pulse/tick.
#pragma once

#include <array>
#include <vector>

#include "servobench/motion/profile.hpp"
#include "servobench/motion/pvt.hpp"

namespace servobench::motion {

enum class FollowSegmentType : int { Normal = 0, Even = 1, Stop = 2, Continue = 3 };
enum class FollowMasterType : int { Encoder = 1, Profile = 2, Axis = 3 };
enum class FollowEvent : int { Start = 1, Pass = 2 };

// GT_PrfFollowEx + GT_SetFollowMasterEx + GT_SetFollowMemoryEx/MaxSegment + GT_SetFollowEventEx +
// GT_SetFollowLoopEx, all values as doubles (validated, whole numbers where the manual's type is integer).
struct FollowExSetup {
  double dir = 0;           // 0 both master directions, 1 positive only, -1 negative only (L6185)
  double master_type = 2;   // 1 encoder, 2 profile (default), 3 axis (L7345-7363)
  double master_item = 0;   // axis master only: 0 planned position, 1 encoder
  double memory = 0;        // 0: 16 segments per FIFO, 1: 512, 2: dynamic = max_segment (L489-493)
  double max_segment = 0;   // dynamic FIFO size, 1..2147483647; 0 = not set (memory 2 then refused, L497-501)
  double event = 1;         // 1 START (at FollowStart), 2 PASS (master crosses event_pos) (L536-542)
  double master_dir = 1;    // PASS direction: 1 positive, -1 negative
  double event_pos = 0;     // PASS position, pulse (long)
  double loop = 1;          // passes; < 1 = infinite (L7302)
  void validate() const;
  long fifo_capacity() const;
};

// One segment as written (displacements), before its ratios are planned.
struct FollowSegmentData {
  double master = 0;  // master displacement, pulse (non-zero)
  double slave = 0;   // slave displacement, pulse
  FollowSegmentType type = FollowSegmentType::Normal;
  double percent = 0;  // 0..100
  bool explicit_ratios = false;  // Complete data: r0, r1 given
  double r0 = 0, r1 = 0;
};

// A planned cam: pieces over master travel x (>= 0, along the sign of the FIFO's master displacements),
// seg.p = slave position from the FIFO start, seg.v = d(slave)/dx, seg.a, seg.j per pulse of travel.
struct FollowCam {
  std::vector<PvtPiece> pieces;        // t0_ms holds the master travel at the piece start
  std::vector<double> segment_end_x;   // master travel at each segment end
  std::vector<double> ratio_begin, ratio_end;  // r0, r1 of each segment (slave/master velocity ratio)
  double master_sign = 1.0;
  double length = 0.0;  // total master travel of a pass
  double slave_length = 0.0;
  // Slave position at travel x (clamped to [0, length]).
  double slave_at(double x) const;
  // dS/dm at travel x (the velocity ratio).
  double ratio_at(double x) const;
};

// Plans the ratios of the segments (entry_ratio: the previous FIFO's end ratio, used by CONTINUE).
FollowCam plan_follow_cam(const std::vector<FollowSegmentData>& segs, double entry_ratio);

// Complete data as segments: knots master[i], slave[i] (cumulative; the first is the curve start), end
// ratios ratio_begin/ratio_end; interior ratios of the clamped C2 spline.
std::vector<FollowSegmentData> follow_complete_segments(const std::vector<double>& master,
                                                        const std::vector<double>& slave, double ratio_begin,
                                                        double ratio_end);

class FollowEx {
 public:
  explicit FollowEx(const FollowExSetup& setup = {}, double slave_pos = 0.0);

  // GT_FollowDataPercentEx with cumulative values (decision M30).
  void data_percent(double master, double slave, FollowSegmentType type, double percent, int fifo = 0);
  // GT_FollowDataCompleteEx: n knots -> n-1 segments, all or nothing.
  void data_complete(const std::vector<double>& master, const std::vector<double>& slave, double ratio_begin,
                     double ratio_end, int fifo = 0);
  // GT_SetFollowMasterEx / MemoryEx / EventEx / LoopEx / MaxSegment after construction: refused while moving,
  // and a FIFO-size change once a FIFO holds data (the size is set before the data, L514).
  void configure(const FollowExSetup& setup);
  // GT_FollowSpaceEx: free segments in a FIFO.
  long space(int fifo) const;
  long size(int fifo) const;
  // GT_FollowClearEx: refused while the FIFO is in use.
  void clear(int fifo);
  // GT_FollowStartEx for this axis on `fifo` with the master's current position (pulse).
  void start(double master_pos, int fifo = 0);
  // GT_FollowSwitchEx: switch to the other FIFO at the end of the current pass.
  void switch_fifo();
  // GT_Stop: the slave stops where it is.
  void stop();
  // One tick with the master's position now (pulse); returns the slave state (vel, acc per tick as
  // differences, as the gear).
  const MotionState& step(double master_pos);

  const FollowExSetup& setup() const { return setup_; }
  const MotionState& state() const { return state_; }
  long long reported_pos() const;
  bool moving() const { return running_; }
  // Started but waiting for the PASS event.
  bool waiting() const { return running_ && waiting_; }
  int active_fifo() const { return fifo_; }
  bool switch_pending() const { return switch_pending_; }
  // GT_GetFollowLoopEx: completed passes.
  long loop_count() const { return passes_done_; }
  // Velocity ratio d(slave)/d(master) at the current cam position (0 when not following).
  double ratio() const;
  // Master travel into the current pass, pulse.
  double travel() const { return x_; }

 private:
  void check_fifo(double fifo) const;
  void activate(int fifo, double entry_ratio);
  void check_writable(int fifo, long n) const;

  FollowExSetup setup_;
  std::array<std::vector<FollowSegmentData>, 2> fifo_data_;
  std::array<double, 2> last_master_{}, last_slave_{};
  FollowCam cam_;
  MotionState state_;
  int fifo_ = 0;
  bool running_ = false;
  bool waiting_ = false;
  bool switch_pending_ = false;
  double prev_master_ = 0.0;
  double x_ = 0.0;
  double slave_base_ = 0.0;
  long passes_done_ = 0;
};

}  // namespace servobench::motion
