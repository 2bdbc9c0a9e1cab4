// Homing sequences: the profile generator's side of a closed loop with the switches and the index mark.
//
// A sequence is a state machine stepped once per servo tick, before the generator: it reads what the
// mechanism did during the previous tick (HomeInputs: switch levels and edges, the index mark, each edge's
// actual position interpolated inside the tick) and commands the ProfileGenerator (velocity moves, stops,
// point-to-point moves). Data flows one way: sensors -> sequence -> generator -> axis. The driver that runs
// it against a simulated Axis is machine::MotionLoop.
//
// ADLINK home modes (ADLINK L2246-2556; digest adlink.md §6.3), positions and speeds in pulse and pulse/s
// (unit factor 1), s = +1 for HOME_DIR 0 (positive), -1 for HOME_DIR 1 (L2357, L2378):
//   mode 0, ORG (L2341-2457): search ORG at VM in direction s; on ORG decelerate to rest; move away at VM
//     (direction -s) until ORG turns off; search ORG again at VO in direction s; the edge where ORG turns on
//     is the reference: the (-s)-side edge of ORG (DIR 0 -> the MEL-side edge, DIR 1 -> the PEL-side edge,
//     L2370-2372). A limit met during the fast search reverses it once (start cases C, figure-only, M41).
//   mode 1, EL (L2459-2508): the same with the limit switch in direction s (PEL for DIR 0, MEL for DIR 1) in
//     place of ORG: search at VM, back off at VM until it turns off, approach at VO; the reference is the
//     limit's inner edge.
//   mode 2, single EZ (L2510-2556): search the index mark at VM in direction s (a limit reverses the search
//     once); the reference is the index position; EZA has no effect (L2556).
//   EZA = 1 (modes 0 and 1, L2391): after the reference edge, continue at VO to the first index mark (mode 0:
//     in direction s; mode 1: away from the limit, direction -s, decision M41) and take it as the reference.
// Then: decelerate to rest, move at VO to reference + HOME_SHIFT (L2436-2449), and redefine the position
// there as HOME_POS: "command position and feedback position reset" (L2252).
//
// GT automatic homing, GT_Home(pos) + GT_Index(0/1) (GT L4152-4213; the Example 6-1 / 6-2 pattern, L2021-2150),
// per-tick units: T-curve towards pos; if the home switch is already on, first move away from pos until it
// turns off (L4160); on the home edge retarget to the captured home position (on-the-fly T-curve target);
// with index = 1 continue towards pos and retarget to the captured index position; optionally ZeroPos.
#pragma once

#include "servobench/motion/generator.hpp"

namespace servobench::motion {

// One switch or mark during one tick: level at the tick's end, edges inside the tick and the actual
// position (pulse, the generator's coordinates) at the last edge, interpolated inside the tick.
struct SignalEvent {
  bool level = false;
  bool rose = false;  // turned on (the index mark: passed)
  bool fell = false;
  double edge_pos = 0.0;
};

struct HomeInputs {
  SignalEvent org;  // home switch (ORG)
  SignalEvent pel;  // positive limit
  SignalEvent mel;  // negative limit
  SignalEvent ez;   // encoder index mark (EZ)
  double actual_pos = 0.0;  // pulse
};

// What the driver must do after a sequence step: redefine the position (at rest).
struct HomeAction {
  bool set_position = false;
  double pos = 0.0;
};

// ADLINK homing parameters, manual units (pulse, pulse/s, pulse/s^2; unit factor 1). Defaults: the manual's
// example (L2295-2303).
struct AdlinkHomeParams {
  double mode = 0;        // PRA_HOME_MODE 10h: 0 ORG, 1 EL, 2 single EZ
  double dir = 1;         // PRA_HOME_DIR 11h: 0 positive, 1 negative
  double curve = 0;       // PRA_HOME_CURVE 12h: S-factor 0..1
  double acc = 1e6;       // PRA_HOME_ACC 13h: acceleration = deceleration, pulse/s^2, 0 < acc <= 1e12
  double vm = 1e5;        // PRA_HOME_VM 15h: search speed, pulse/s, 0 < vm <= 1e9
  double vo = 5e4;        // PRA_HOME_VO 19h: approach speed, pulse/s, 0 < vo <= vm
  double shift = 0;       // PRA_HOME_SHIFT 17h: final offset from the reference, pulse, |shift| <= 2^31-1
  bool eza = false;       // PRA_HOME_EZA 18h: align with the index mark
  double pos = 0;         // PRA_HOME_POS 1Bh: position set after homing, pulse, |pos| <= 2^31-1
  void validate() const;
};

// GT_Home(pos) + GT_Index(value) with the T-curve speed and acceleration the sequence uses (per tick).
struct GtHomeParams {
  double pos = 0;      // GT_Home target beyond the home switch, whole pulses, -2^30..2^30-1 (L4162)
  double vel = 4;      // pulse/ST, 0 < vel <= 16384 (Example 6-1 uses 4)
  double acc = 1;      // pulse/ST^2, 0 < acc <= 16384 (Example 6-1 uses 1)
  bool index = false;  // GT_Index: 0 home only (default), 1 home + index (L4190-4196)
  bool zero = true;    // GT_ZeroPos at the end (Examples 6-1, 6-2)
  void validate() const;
};

enum class HomePhase {
  Idle, Search, SearchReverse, StopAfterFind, Leave, StopAfterLeave, Approach, StopBeforeEz, AlignEz, StopAtEdge,
  MoveToEdge, Done, Failed
};
const char* to_string(HomePhase phase);

class HomeSequence {
 public:
  // ADLINK home move (APS_home_move) on a generator ticking at period_s seconds.
  HomeSequence(const AdlinkHomeParams& p, double period_s);
  // GT_Home / GT_Index.
  explicit HomeSequence(const GtHomeParams& p);

  // One tick: react to the previous tick's inputs by commanding the generator.
  HomeAction step(const HomeInputs& in, ProfileGenerator& gen);

  HomePhase phase() const { return phase_; }
  bool done() const { return phase_ == HomePhase::Done; }
  bool failed() const { return phase_ == HomePhase::Failed; }
  bool finished() const { return done() || failed(); }
  // ADLINK stop code on failure (4 PEL, 5 MEL, L3931-4023) or the GT example's return value (1 no home,
  // 2 no index); 0 otherwise.
  int error_code() const { return error_; }
  // The reference position found (pulse, coordinates before the reset) and whether it was found.
  bool reference_found() const { return found_; }
  double reference_pos() const { return reference_; }
  bool is_gt() const { return gt_; }

 private:
  HomeAction step_adlink(const HomeInputs& in, ProfileGenerator& gen);
  HomeAction step_gt(const HomeInputs& in, ProfileGenerator& gen);
  void velocity(ProfileGenerator& gen, double speed_per_tick, double sign);
  void stop(ProfileGenerator& gen);
  void fail(ProfileGenerator& gen, int code);
  void latch(double pos) {
    found_ = true;
    reference_ = pos;
  }

  bool gt_ = false;
  AdlinkHomeParams ad_{};
  GtHomeParams gtp_{};
  AdlinkLimits lim_{};  // per tick
  double vm_ = 0.0, vo_ = 0.0, acc_ = 0.0;  // per tick
  double s_ = 1.0;
  bool reversed_ = false;
  HomePhase phase_ = HomePhase::Idle;
  int error_ = 0;
  bool found_ = false;
  double reference_ = 0.0;
};

}  // namespace servobench::motion
