// ADLINK PCI-8254/8258 interpolation (manual §4.8, seed 004 L2813-3150; digest adlink.md §6.7): moves of an
// axis array along SpaceSegment geometry, with the path (vector) profile of the reference axis, and the
// continuous-interpolation buffer with its seven transition ("Flag") modes.
//
//  - Reference axis (L2819-2825): the first axis of the array; its VS, VM, VE, ACC, DEC, SF (and SD_DEC)
//    define the vector profile (plan_adlink_ptp over the path length); APS_*_v overrides VM, APS_*_all all.
//  - Buffer (L3065-3091): same dimension and axes for every move; buffer_size pending moves (decision C40).
//  - Modes (L3085-3143), decided per new move (its "Flag"):
//    1 AbortBlend: the running moves decelerate at their own DEC along their paths, and the new move starts at
//      once, superposed on them (decision C41): smooth axis velocities, exact end point;
//    2 AbortForced: the new move starts at once from the present position at the present path speed (VS of
//      the new profile; capped at its VM), exact path, axis velocities may jump;
//    3 AbortStop: the running moves decelerate to rest at the new move's SD_DEC (0 = its DEC); then it starts;
//      a relative target is measured from where the abort was given, not where the axes stopped (L3111-3115);
//    4 Buffered: in sequence, each move's own VS and VE exactly (L3117-3122);
//    5 BlendDecel: starts when the running move starts its deceleration (L3124-3129);
//    6 BlendDistance: starts when the running move's remaining path length is < blend (L3131-3136);
//    7 BlendPercent: starts when its remaining length is < blend % of its length (L3138-3143).
//    In 5-7 the previous move finishes its own profile while the new one runs: the position is the sum of both
//    displacements (decision C42), so the path is smoothed and the end point exact. Modes 1-3 flush the pending
//    moves (L3087).
//  - Dwell (point table, APS_pt_dwell L3838): a move of Kind::Dwell holds the position dwell_s seconds; it is
//    always buffered (starts when the previous moves have ended) and the next move starts when it ends.
//  - stop_move (decelerate at the reference SD_DEC, flush) and emg_stop (halt at once, flush), L2570-2580.
// Units: the manual's, pulse (UF = 1), pulse/s, pulse/s^2; one step() = one motion cycle (1 ms, L1633-1647).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/space_segment.hpp"

namespace servobench::motion {

enum class BlendMode {
  AbortBlend = 1,
  AbortForced = 2,
  AbortStop = 3,
  Buffered = 4,
  BlendDecel = 5,
  BlendDistance = 6,
  BlendPercent = 7
};

// What a move describes; resolved into a SpaceSegment from its start point when it starts (relative
// coordinates from the reference point: its start, or in an abort mode the position at the abort).
struct AdlinkMoveSpec {
  enum class Kind { Line, Arc2Ca, Arc2Ce, Arc3Ca, Arc3Ce, SpiralCa, SpiralCe, Dwell };
  Kind kind = Kind::Line;
  bool relative = false;   // target and centre relative to the reference point
  SpacePoint target{};     // line / ce end point
  SpacePoint center{};     // arcs, spirals
  Vec3 normal{0, 0, 1};    // 3-D arcs and spirals
  double angle_deg = 0.0;  // ca forms
  int dir = 0;             // ce forms
  double height = 0.0, final_radius = 0.0;  // spiral_ca
  double dwell_s = 0.0;    // Dwell: how long the position is held, s (> 0)
  SpaceSegment build(const SpacePoint& start, const SpacePoint& ref, int dim) const;
};

struct AdlinkInterpSetup {
  double period_s = 1e-3;    // motion cycle, s (ADLINK L1633-1647: 1 ms)
  double buffer_size = 10;   // pending moves (decision C40; the PTP motion buffer holds 10, L2771)
  void validate() const;
};

struct AdlinkInterpState {
  double t_s = 0.0;
  SpacePoint pos{};          // axis positions (axis-array order), pulse
  SpacePoint vel{};          // axis velocities, pulse/s
  double speed = 0.0;        // vector speed, pulse/s
  long long moves_done = 0;  // finished moves
};

class AdlinkInterpolator {
 public:
  // axes: 2..6 distinct axis IDs 0..7, the first the reference axis. start: their positions, pulse.
  AdlinkInterpolator(const std::vector<int>& axes, const AdlinkInterpSetup& setup = {},
                     const std::vector<double>& start = {});
  // The axis parameters (PRA_VS/VM/VE/ACC/DEC/SF/SD_DEC, pulse/s units; pos unused) of an axis of the array.
  void set_axis_params(int axis, const AdlinkPtpParams& p);
  const AdlinkPtpParams& axis_params(int axis) const;

  // A move with the reference axis's parameters (vm > 0 overrides VM: the _v form) or all of `all` (the
  // _all form, when use_all). blend: mode 6 distance (pulse, > 0), mode 7 percent (0 < p < 100).
  void push(const AdlinkMoveSpec& spec, BlendMode mode = BlendMode::Buffered, double blend = 0.0, double vm = 0.0,
            const AdlinkPtpParams* all = nullptr);
  void stop_move();
  void emg_stop();

  const AdlinkInterpState& step();
  const AdlinkInterpState& state() const { return st_; }
  const std::vector<int>& axes() const { return axes_; }
  int dim() const { return static_cast<int>(axes_.size()); }
  // End point of the last buffered move (where the next buffered move starts).
  const SpacePoint& tail() const { return tail_; }
  std::size_t pending() const { return queue_.size(); }
  std::size_t running_moves() const { return run_.size(); }
  bool done() const { return run_.empty() && queue_.empty(); }

 private:
  struct Running {
    SpaceSegment geom;
    Profile prof;     // path length s (pulse) over ticks
    double t0;        // start, ticks
    AdlinkLimits lim; // per tick
    bool dwell = false;
  };
  struct Pending {
    AdlinkMoveSpec spec;
    SpaceSegment geom;  // built for Buffered / Blend modes
    bool built = false;
    BlendMode mode;
    double blend;
    AdlinkLimits lim;
    double arrival;     // ticks
    SpacePoint ref{};   // AbortStop: the position at the abort
    double dwell_ticks = 0.0;  // > 0: a dwell
  };
  double trigger_time(const Pending& p) const;
  void start_pending(double t0);
  void start_move(const SpaceSegment& g, const AdlinkLimits& lim, double t0);
  void position_at(double t, SpacePoint& pos, SpacePoint& vel) const;
  void stop_running(double sd_dec_per_tick, bool own_dec);
  void settle();
  AdlinkLimits limits_for(double vm, const AdlinkPtpParams* all, double* sd_dec) const;

  std::vector<int> axes_;
  AdlinkInterpSetup setup_;
  std::map<int, AdlinkPtpParams> params_;
  std::vector<Running> run_;
  std::deque<Pending> queue_;
  SpacePoint base_{}, tail_{};
  double t_ = 0.0;           // ticks
  double last_end_ = 0.0;    // ticks: when the last move finished
  AdlinkInterpState st_;
};

// Samples `ticks` cycles, or until done(): time s, positions (n x dim), vector speed pulse/s, moves done.
struct AdlinkInterpRecording {
  int dim = 0;
  std::vector<double> t_s, pos, speed, moves_done;
};
AdlinkInterpRecording record(AdlinkInterpolator& g, std::size_t ticks, bool until_done);

}  // namespace servobench::motion
