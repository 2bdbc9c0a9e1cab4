// MotionLoop: an Axis driven tick by tick by a profile generator that reacts to the mechanism.
//
// Homing, capture, breakpoints and the ADLINK jog need the profile to react to what the simulated mechanism
// does (switches, index mark, actual position), so they cannot be planned ahead like a plain move. The loop
// couples one motion::ProfileGenerator to one Axis (which it does not own) and, every tick:
//   1. the active sequence (homing or jog) reads the previous tick's events and commands the generator;
//   2. the generator advances; its whole-pulse position (+ the coordinate offset) is the Axis command, its
//      velocity and acceleration feed the law's feed-forward;
//   3. the Axis runs one tick (encoder read, law, DAC, drive and mechanics over Ts);
//   4. the tick's events are sensed (machine/sensing.hpp), the capture register latches, the breakpoint is
//      checked against the actual position; a fired breakpoint sets its flag and, with auto-update on, commits
//      the staged (double-buffered) commands, which take effect at the next tick (GT L1156, L1263).
// So the profile reacts to an event one tick after the tick in which it happened (decision M42).
// Coordinates: the generator, captures and breakpoints work in the card's coordinates, which a homing's
// position reset or set_position() shifts against the Axis's raw encoder counts (raw = card + offset);
// the Axis itself is never reset. The Axis's own tick is untouched: the loop calls Axis::run one tick at a time.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/machine/capture.hpp"
#include "servobench/machine/sensing.hpp"
#include "servobench/motion/adlink_jog.hpp"
#include "servobench/motion/breakpoint.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/motion/home_sequence.hpp"

// X(name, unit, description): the loop's own signals, recorded next to the Axis trace.
#define SERVOBENCH_LOOP_SIGNALS(X)                                                             \
  X(pos, "pulse", "command position in the card's coordinates (whole pulses)")                 \
  X(actual_pos, "pulse", "actual (encoder) position in the card's coordinates, end of the tick") \
  X(offset, "pulse", "raw encoder count minus the card's coordinate (changes at a position reset)") \
  X(phase, "code", "phase of the active sequence (homing: HomePhase, jog: JogPhase), -1 none")   \
  X(captured, "bool", "capture flag (GT status bit 3)")                                         \
  X(breakpoint, "bool", "breakpoint flag (GT status bit 2)")

namespace servobench::machine {

struct LoopTrace {
#define SERVOBENCH_LOOP_FIELD(name, unit, doc) double* name = nullptr;
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_LOOP_FIELD)
#undef SERVOBENCH_LOOP_FIELD
};

// What one step of the loop returns: every signal the card's checks after the law need (machine/card.hpp).
struct LoopTick {
  double error_pulse = 0.0;       // the law's error E_n of this tick: command - encoder read, pulse
  bool breakpoint_fired = false;  // the armed breakpoint fired in this tick (it is disarmed now)
};

class MotionLoop {
 public:
  using Staged = std::function<void(motion::ProfileGenerator&)>;

  // Couples to `axis` (kept by reference; it must outlive the loop). The generator starts at rest at the
  // axis's present encoder count.
  explicit MotionLoop(Axis& axis);

  Axis& axis() { return axis_; }
  const Axis& axis() const { return axis_; }
  motion::ProfileGenerator& generator() { return gen_; }
  const motion::ProfileGenerator& generator() const { return gen_; }
  CaptureUnit& capture() { return capture_; }
  const CaptureUnit& capture() const { return capture_; }
  motion::Breakpoint& breakpoint() { return brk_; }
  const motion::Breakpoint& breakpoint() const { return brk_; }

  // Double buffering (GT L1150-1239): stage a command; update() commits all staged commands (GT_Update);
  // a breakpoint with auto-update on commits them too (GT_AuUpdtOn, L1255-1263).
  void stage(Staged command) { staged_.push_back(std::move(command)); }
  void update();
  std::size_t staged_count() const { return staged_.size(); }
  void set_auto_update(bool on) { auto_update_ = on; }
  bool auto_update() const { return auto_update_; }

  // Starts a homing sequence (refused while the generator moves or another sequence runs).
  void home(const motion::AdlinkHomeParams& p);
  void home(const motion::GtHomeParams& p);
  const std::optional<motion::HomeSequence>& homing() const { return homing_; }
  // Installs the ADLINK jog (APS_jog_on parameters) and sets its JOG-ON signal.
  void jog(const motion::AdlinkJogParams& p);
  void set_jog_on(bool on) { jog_on_ = on; }
  bool jog_on() const { return jog_on_; }
  const std::optional<motion::AdlinkJog>& jogger() const { return jog_; }
  // True while a homing or jog sequence is running.
  bool sequence_active() const;

  // The probe input (EXI0) fires at time t_s (s, the axis's clock); NaN: never.
  void set_probe_time(double t_s) { probe_time_s_ = t_s; }
  // Shifts the card's coordinates so that the profile position becomes `pos` (pulse; at rest); the actual
  // position moves by the same amount. The homing sequences' position reset (the GT examples' ZeroPos after the
  // axis settled, ADLINK HOME_POS), taken when the profile ends: once the axis settles it stands at `pos` (VF1).
  void set_position(double pos);
  // GT_SetAtlPos / GT_ZeroPos (GT L4613-4622, GE L5457-5463): the actual (encoder) and the profile position both
  // become `pos` (pulse; at rest); a following error left at rest is dropped, the mechanism does not move.
  void set_actual_position(double pos);
  double offset() const { return offset_; }
  // Actual position in the card's coordinates (encoder count now minus the offset), pulse.
  double actual_pos() const { return inputs_.actual_pos; }
  // The last tick's sensed inputs and edges (card coordinates): home, limits, index (the card's IEZ interrupt).
  const motion::HomeInputs& inputs() const { return inputs_; }
  bool breakpoint_flag() const { return brk_flag_; }
  // GT_ClrSts: clears the breakpoint (bit 2) and capture (bit 3) flags.
  void clear_status();
  // Clears the breakpoint flag only (GT_RstSts with bit 2 cleared).
  void clear_breakpoint_flag() { brk_flag_ = false; }
  // Ends a homing or jog sequence at once (a card reset); the generator is left as it is.
  void cancel_sequence();
  // A voltage added to the output stage every tick (V; the open-loop output GT_SetMtrCmd with the servo law
  // off); `on` false removes it.
  void set_output_add(bool on, double volts = 0.0) {
    add_on_ = on;
    add_volts_ = volts;
  }

  // One tick (steps 1-4 above): fills entry k of the non-null buffers of both traces and returns what the card
  // checks after the law. The card's tick calls this directly: Card -> MotionLoop::step -> Axis::run.
  LoopTick step(const Trace& axis_trace, const LoopTrace& loop_trace, std::size_t k = 0);
  // Runs n ticks; fills the non-null buffers of both traces (n doubles each).
  void run(std::size_t n, const Trace& axis_trace, const LoopTrace& loop_trace);
  // Runs until the active sequence ends (or, with none, the generator stops), at most max_ticks; returns
  // the ticks run. Buffers must hold max_ticks doubles.
  std::size_t run_until_done(std::size_t max_ticks, const Trace& axis_trace, const LoopTrace& loop_trace);

 private:
  double phase_code() const;

  Axis& axis_;
  Sensing sensing_;
  motion::ProfileGenerator gen_;
  CaptureUnit capture_;
  motion::Breakpoint brk_;
  std::vector<Staged> staged_;
  bool auto_update_ = false;  // GT default off (L1255)
  bool brk_flag_ = false;
  std::optional<motion::HomeSequence> homing_;
  std::optional<motion::AdlinkJog> jog_;
  bool jog_on_ = false;
  double probe_time_s_ = std::numeric_limits<double>::quiet_NaN();
  double offset_ = 0.0;
  bool add_on_ = false;
  double add_volts_ = 0.0;
  motion::HomeInputs inputs_;  // the last tick's events, card coordinates
};

}  // namespace servobench::machine
