// The capture register of one axis (GT L2013-2150, L2958-3049, L3640-3674; GE L2332-2340, L3802-3862).
//
// Armed for one trigger (home switch, index mark or probe input EXI0), it latches the actual position at
// the trigger edge (interpolated inside the tick, machine/sensing.hpp) and sets the captured flag (GT status
// bit 3; arming sets bit 14 home / 15 index, cleared on capture). One arm gives one capture: arming again
// while armed, or while the captured flag is still set (clear it with clear(), GT_ClrSts), is refused
// (GT command status bits 7/8, L465-471; GE L2334-2336). The value holds until the next capture (L3644).
// The home trigger is the switch turning on (entering the home window, decision M40).
#pragma once

#include "servobench/motion/generator.hpp"
#include "servobench/motion/home_sequence.hpp"

namespace servobench::machine {

enum class CaptureTrigger { None, Home, Index, Probe };
const char* to_string(CaptureTrigger trigger);

class CaptureUnit {
 public:
  // GT_CaptHome / GT_CaptIndex / GT_CaptProb. Throws motion::MotionCommandRefused if armed or captured.
  void arm(CaptureTrigger trigger);
  // GT_ClrSts on bit 3: clears the captured flag (the value is kept).
  void clear() { captured_ = false; }
  // One tick: home and index events (positions in the caller's coordinates) and the probe, if it fired
  // (probe_pos its interpolated position). Returns true if it captured now.
  bool update(const motion::SignalEvent& home, const motion::SignalEvent& index, bool probe, double probe_pos);
  // Shifts a held value into new coordinates (after a position redefinition).
  void shift(double delta) { value_ += delta; }

  CaptureTrigger armed() const { return armed_; }
  bool captured() const { return captured_; }
  CaptureTrigger source() const { return source_; }
  double value() const { return value_; }

 private:
  CaptureTrigger armed_ = CaptureTrigger::None;
  CaptureTrigger source_ = CaptureTrigger::None;
  bool captured_ = false;
  double value_ = 0.0;
};

}  // namespace servobench::machine
