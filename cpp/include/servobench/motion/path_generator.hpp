// PathGenerator: one coordinate system's path interpolator, stepped once per motion cycle.
//
// It owns the FIFO of buffered commands (segments, buffered IO, delay, DA, point-to-point moves and gears of
// axes outside the coordinate system, user segment numbers), the optional look-ahead window in front of the
// FIFO, the segment being executed, and the outside axes moved from the buffer. step() advances one motion
// cycle and returns the state (coordinate position, path speed and acceleration, counters, outputs); the
// card (issue 10) drives it tick by tick and maps positions to motor axes with coords().to_axes(); Python
// gets the same through record().
//
// Manual rules (GT §5 L1513-2011; GE §6 L1445-2040; GUC §4.1 L313-1114; iDEABOX §4.3 L933-2711):
//  - segments run in FIFO order with a trapezoidal path speed (path_feed.hpp); synVel / synAcc of each
//    segment clamped by synVelMax / synAccMax (GUC L771-773) and scaled by the override (G0 by the G0
//    override, GE L1952-1958, L5342-5362);
//  - end speeds: with look-ahead, the look-ahead's (lookahead.hpp; velEnd ignored, GUC L981-983); without,
//    the segment's velEnd (GUC/iDEABOX) or, for `auto_end` segments, GT's one-joint rule (GT L1950-1965:
//    min of both feeds, the per-axis acceleration limit at the corner, and a stop within the next segment);
//    always 0 for G0, before a delay or a modal move, and when no next segment is in the FIFO yet (starved);
//  - buffered IO, DA, user segment numbers and gears execute between segments in FIFO order; a delay dwells
//    at rest; a modal BufMove blocks the FIFO until its axis stops, a non-modal one runs alongside; a BufGear
//    makes its axis travel its distance in proportion to the path length of the next segment (GUC L646-661,
//    L1052-1060; iDEABOX L2128-2522);
//  - stop (smooth: stop_dec_smooth, 0 = the segment's acceleration; abrupt: stop_dec_abrupt, 0 = speed 0 at
//    once, GT EStpMtn L3336) keeps the breakpoint and the rest of the buffer; start() resumes. A resume away
//    from the breakpoint returns to it first by a line ending at rest (GT L1940, GE GT_RestoreMtn L1660) or,
//    with return_to_stop_point = false, is refused (GUC/iDEABOX L1648-1653, return code 1);
//  - a full FIFO refuses the command (MotionCommandRefused, return code 1; GT command status bit 15);
//  - BufLmtsOn / BufLmtsOff change the limit-enable flags of an axis, BufSetStopIo arms an input as a stop
//    source of an axis, at their FIFO position (GUC L609-645, iDEABOX L4270-4330). The card's limit logic is
//    not here (issue 10): set_input() provides the (sense-applied) inputs and an armed, active input stops the
//    path (coordinate-system axis) or the outside axis (BufMove / BufGear axis) with the armed stop type;
//  - GE start velocity (GT_SetStrtVel, GE L1395-1399, L1473-1477, L1660): segments leave rest at start_vel
//    and come back to rest from it (a step at both ends); 0 = from and to rest (GT/GUC/iDEABOX).
// Units: coordinate unit (pulse), ms, unit/ms, unit/ms^2. Decisions C1-C24, C25-C33 in docs/decisions.md.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "servobench/motion/coord_system.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/lookahead.hpp"
#include "servobench/motion/path_feed.hpp"
#include "servobench/motion/path_recording.hpp"
#include "servobench/motion/path_segment.hpp"

namespace servobench::motion {

// The interpolator's configuration.
struct PathSetup {
  double cycle_ms = 1.0;              // motion cycle, ms (0.01..100)
  double fifo_capacity = 4096;        // entries per FIFO (GUC L798, iDEABOX L1610-1612: 4096 segments)
  double syn_vel_max = 32767;         // unit/ms: clamps every synVel (GUC L771; GE MaxVel L1401-1405)
  double syn_acc_max = 32767;         // unit/ms^2: clamps every synAcc (GUC L773)
  double even_time_ms = 0;            // minimum cruise time per segment, ms (GUC L775)
  double stop_dec_smooth = 0;         // unit/ms^2; 0 = the running segment's acceleration (GT StpMtn)
  double stop_dec_abrupt = 0;         // unit/ms^2; 0 = speed 0 at once (GT EStpMtn L3336)
  double corner_axis_acc = 0;         // pulse/ms^2 per motor axis at a corner (GT AccLmt L1956); 0 = off
  // Per-axis acceleration limits of the coordinate system's 1st..4th motor axis, pulse/ms^2 (GT_SetAccLmt is one
  // per axis, L1956); 0 = corner_axis_acc. With any limit set, every motor axis's position second difference
  // over a motion cycle stays <= its limit, at corners too, with and without look-ahead (issue 25.4; VF5-VF10).
  double axis_acc_1 = 0, axis_acc_2 = 0, axis_acc_3 = 0, axis_acc_4 = 0;
  bool return_to_stop_point = true;   // GT/GE resume; false: GUC/iDEABOX (resume only at the breakpoint)
  double start_vel = 0;               // unit/ms: GE GT_SetStrtVel (GE default 0.5 pulse/ms); 0 = from rest
  double resume_tolerance = 0;        // unit, per coordinate: a resume this close to the breakpoint is accepted
                                      // even when !return_to_stop_point (closing the gap by a return line)
  void validate() const;
};

// BufSetStopIo / set_input input types (GUC L625-645: MC_LIMIT_POSITIVE 0, MC_LIMIT_NEGATIVE 1, MC_ALARM 2,
// MC_HOME 3, MC_GPI 4) and stop types (0 emergency, 1 smooth).
enum class StopInput { LimitPositive = 0, LimitNegative = 1, Alarm = 2, Home = 3, Gpi = 4 };
struct StopIoMapping {
  bool armed = false;
  int stop_type = 0;    // 0 emergency (abrupt), 1 smooth
  int input_type = 0;   // StopInput
  int input_index = 1;  // 1..8 (GPI 1..16)
};

enum class PathCommandType { Motion, Io, Delay, Da, Move, Gear, UserSegNum, Lmts, StopIo };

struct PathCommand {
  PathCommandType type = PathCommandType::Motion;
  // Motion
  PathSegmentGeometry geom;
  double vel = 0.0, acc = 0.0, vel_end = 0.0;  // synVel, synAcc, velEnd
  bool g0 = false;          // rapid (G0): starts and ends at rest, scaled by the G0 override
  bool auto_end = false;    // GT/GE: end speed by the one-joint rule instead of vel_end
  bool stop_at_end = false; // forced stop at the end (dccFlag / velEndZero)
  double axis_cap = 0.0;    // per-axis limits: speed cap L/(2 cycle) of a segment that starts with a corner (0 = none)
  double planned_end = 0.0; // end speed fixed by the look-ahead
  bool planned = false;
  // Io: type 0 GPO, 1 drive enable, 2 alarm clear (GUC doType); bits where mask is 1 take value's bits.
  int io_type = 0;
  std::uint32_t mask = 0, value = 0;
  double delay_ms = 0.0;
  int channel = 0;          // Da 1..8
  double da = 0.0;          // Da value -32768..32767
  int axis = 0;             // Move / Gear: an axis outside the coordinate system
  double pos = 0.0;         // Move: absolute target; Gear: relative distance (pulse)
  bool modal = false;
  long long user_seg = 0;
  bool limits_on = false;   // Lmts: BufLmtsOn (true) / BufLmtsOff (false)
  int limit_type = -1;      // Lmts: 0 positive, 1 negative, -1 both
  StopIoMapping stop_io;    // StopIo (axis in `axis`)
};

struct PathState {
  double t_ms = 0.0;
  CrdPoint pos{};                 // coordinate position
  double speed = 0.0;             // path speed, unit/ms
  double acc = 0.0;               // path acceleration (along the path), unit/ms^2
  long long segments_done = 0;    // completed motion segments (GUC/iDEABOX GT_CrdStatus segment)
  long long user_seg_num = 0;     // GT_GetUserSegNum
  std::array<std::uint32_t, 3> do_words{};  // GPO, drive enable, alarm clear outputs (16 bits used)
  std::array<double, 8> da{};     // DA channels 1..8, counts
  std::uint32_t limits_pos = 0xFFFF;  // bit k: positive limit of axis k+1 enabled (BufLmtsOn/Off)
  std::uint32_t limits_neg = 0xFFFF;  // bit k: negative limit of axis k+1 enabled
  int io_stop_axis = 0;           // the axis whose armed stop input stopped motion last (0: none)
};

// What a coordinate system's owner (CrdFifoPair) is told before a buffered command or a start, and after a
// successful start (it refuses by throwing MotionCommandRefused).
enum class PathGateEvent { Push, Start, Started };

class PathGenerator {
 public:
  explicit PathGenerator(const CoordSystem& coords, const PathSetup& setup = {}, const CrdPoint& start = {});

  // --- configuration -------------------------------------------------------------------------------------
  // Look-ahead (GT_InitLookAhead); n = 0 turns it off. Refused while anything is buffered.
  void init_lookahead(const LookAheadParams& p);
  bool lookahead_on() const { return static_cast<bool>(la_); }
  // Override of the programmed feed, > 0 (GUC/iDEABOX (0, 1], GE 0..2 with the MaxVel clamp: the facade
  // checks its card's range). Acts on the running segment and all later ones (GE L1952-1958).
  void set_override(double ratio);
  void set_g0_override(double ratio);
  // Stop decelerations (GT_SetCrdStopDec, GUC L704-709): > 0, or 0 for the defaults of PathSetup.
  void set_stop_dec(double smooth, double abrupt);
  // Acceleration limit of motor axis `axis` (1..4) at the joints, as PathSetup::axis_acc_k (pulse per cycle^2,
  // 0..1e9, 0 = corner_axis_acc): GT_SetAccLmt, "a command for each motor axis" (GT L1956). Joints planned
  // from now on use it.
  void set_axis_acc(int axis, double acc);
  // Position of an axis outside the coordinate system (pulse) before BufMove / BufGear use it (at rest).
  void set_aux_position(int axis, double pos);

  // --- buffered commands (FIFO, or the look-ahead window first) -------------------------------------------
  // The start point of the next buffered segment: the end of the last buffered one, else the position.
  const CrdPoint& tail() const { return tail_; }
  void push_segment(const PathSegmentGeometry& g, double vel, double acc, double vel_end = 0.0, bool g0 = false,
                    bool auto_end = false, bool stop_at_end = false);
  void line(const CrdPoint& end, double vel, double acc, double vel_end = 0.0, bool g0 = false);
  void buf_io(int io_type, std::uint32_t mask, std::uint32_t value);
  void buf_delay(double ms);
  void buf_da(int channel, double value);
  void buf_move(int axis, double pos, double vel, double acc, bool modal);
  void buf_gear(int axis, double distance);
  void set_user_seg_num(long long n);
  // GT_BufLmtsOn / GT_BufLmtsOff: axis 1..16, limit_type 0 positive, 1 negative, -1 both.
  void buf_lmts(int axis, int limit_type, bool on);
  // GT_BufSetStopIo: axis 1..8, stop_type 0 emergency / 1 smooth, input_type 0..4 (StopInput), input_index
  // 1..8 (GPI 1..16).
  void buf_set_stop_io(int axis, int stop_type, int input_type, int input_index);
  // GT_CrdData(NULL): moves the look-ahead window into the FIFO. False if the FIFO filled first (call again).
  bool flush();

  // --- run control -------------------------------------------------------------------------------------------
  // GT_CrdStart / GT_StrtMtn: start, or resume after a stop (see the class comment).
  void start();
  void stop(bool abrupt);
  // GT_CrdClear: empties the FIFO and the window, resets the counters (refused while moving).
  void clear();
  // A single line from the current position at rest to `end` (GT/GE immediate mode, also how an axis
  // leaves the breakpoint while stopped). Refused while the path or another immediate move runs.
  void move_immediate(const CrdPoint& end, double vel, double acc);

  // --- inputs and owner hooks (not buffered) -------------------------------------------------------------
  // The logical state of an input (after the card's sense/polarity): input_type 0..4, index 1..8 (GPI 1..16).
  void set_input(int input_type, int index, bool active);
  bool input(int input_type, int index) const;
  const StopIoMapping& stop_io(int axis) const;
  // The coordinate position was changed by someone else (the other FIFO of the coordinate system): refused
  // while this generator moves. The tail follows only when nothing is buffered and no breakpoint is kept.
  void relocate(const CrdPoint& pos);
  void set_gate(std::function<void(PathGateEvent)> gate) { gate_ = std::move(gate); }

  // --- stepping and state ------------------------------------------------------------------------------------
  const PathState& step();
  const PathState& state() const { return st_; }
  const CoordSystem& coords() const { return coords_; }
  const PathSetup& setup() const { return setup_; }
  // Started and neither stopped nor out of work (a starved buffer still counts as running, as on GT L1977).
  bool running() const;
  // Something moves now: a segment, a delay or a modal move in progress, an immediate move, a stop ramp.
  bool busy() const { return act_ != Act::None; }
  bool stopped() const { return stopped_; }
  bool has_breakpoint() const { return has_brk_; }
  const CrdPoint& breakpoint() const { return brk_; }
  // Motion segments buffered (FIFO + window) and not finished, the running one included.
  long long remaining_segments() const;
  // Free FIFO entries (GT_CrdSpace).
  long long fifo_space() const;
  std::size_t fifo_size() const { return fifo_.size(); }
  std::size_t window_size() const { return window_.size(); }
  // Axes outside the coordinate system that the buffer moved: number -> position (pulse).
  std::vector<int> aux_axes() const;
  double aux_position(int axis) const;
  bool aux_moving() const;
  // Everything finished: not running or stopped, no aux axis moving.
  bool done() const { return !busy() && !running() && !aux_moving(); }

 private:
  enum class Act { None, Motion, Delay, WaitMove, Return, Immediate };
  struct Aux {
    std::unique_ptr<ProfileGenerator> gen;
    double gear_base = 0.0;  // displacement added by finished gears
    double acc = 0.0;        // acceleration of the running move (kept on a re-target)
  };
  struct Gear {
    int axis;
    double distance;
  };

  void enqueue(PathCommand c);
  void release_window(bool all);
  bool advance(double& budget);
  void begin_motion(double s_from);
  double exit_speed() const;
  double cap_of(const PathCommand& c) const;
  double acc_of(const PathCommand& c) const;
  AxisAccLimits axis_limits() const;
  CrdPoint to_axes_dir(const CrdPoint& v) const;  // a coordinate vector through the map, per motor axis
  AxisDemand demand_of(const PathCommand& c) const;
  void finish_motion();
  void execute_instant(const PathCommand& c);
  void start_stop_ramp(double dec);
  void plan_stop_feed(double s_from);
  void enter_stopped();
  Aux& aux(int axis);
  void update_position();
  void admit();
  void check_stop_inputs();
  double floor_vs(double v, double cap) const;
  static void refuse(const char* what);

  CoordSystem coords_;
  PathSetup setup_;
  PathState st_;
  std::deque<PathCommand> fifo_, window_;
  std::size_t window_motion_ = 0;
  std::unique_ptr<LookAhead> la_;
  CrdPoint tail_{};
  bool tail_stop_next_ = false;  // a delay / modal move was buffered since the last segment
  CrdPoint tail_u_{};            // end tangent of the last buffered segment (per-axis corner caps)
  bool tail_u_valid_ = false;

  Act act_ = Act::None;
  PathCommand cur_;
  bool cur_valid_ = false;   // cur_ holds an unfinished motion segment
  FeedProfile feed_;
  double t_in_ = 0.0;        // time into feed_, ms
  double s_off_ = 0.0;       // path length of cur_ done before feed_ started
  double s_cur_ = 0.0;       // path length of cur_ done
  double delay_left_ = 0.0;
  int wait_axis_ = 0;
  std::vector<Gear> gears_, pending_gears_;
  PathSegmentGeometry aux_line_;  // Return / Immediate line
  bool started_ = false, stopped_ = false, stop_at_rest_ = false, stop_inside_ = false;
  double stop_dec_ = 0.0;
  bool has_brk_ = false;
  CrdPoint brk_{};
  double override_ = 1.0, g0_override_ = 1.0;
  double stop_dec_smooth_ = 0.0, stop_dec_abrupt_ = 0.0;
  std::map<int, Aux> aux_;
  std::array<StopIoMapping, 8> stop_io_{};
  std::array<std::uint32_t, 5> inputs_{};
  std::function<void(PathGateEvent)> gate_;
};

// Samples `ticks` cycles (or until done() when until_done): see path_recording.hpp.
PathRecording record(PathGenerator& g, std::size_t ticks, bool until_done);

}  // namespace servobench::motion
