// GT breakpoints (GT L1239-1397, L3443-3470, L4312-4353, L4393-4405, L4717-4731).
//
// A breakpoint is one-shot: armed with GT_PosBrk / GT_NegBrk / GT_MtnBrk / GT_ExtBrk, checked every servo
// period, and cleared when it fires (the host re-arms it); GT_BrkOff disarms it (L1257, L2937). Conditions:
//   position >=  : actual (encoder) position >= BrkCn (L1263, L4395-4401)
//   position <=  : actual position <= BrkCn (L1299, L4343-4349)
//   motion       : motion complete (status bit 0) becomes 1 (L1332, L4316)
//   home         : the home capture flag (status bit 3 after GT_CaptHome) becomes 1 (L1366, L3447)
// "Becomes" is an edge: a motion breakpoint armed at rest fires at the end of the next move (TV21). The
// caller (machine::MotionLoop) sets status bit 2 and, with auto-update on, commits the staged commands.
#pragma once

namespace servobench::motion {

enum class BreakKind { None, PositionAbove, PositionBelow, MotionComplete, Home };

const char* to_string(BreakKind kind);

class Breakpoint {
 public:
  // GT_SetBrkCn: the compare value, whole pulses, -1073741824..1073741823 (L4721-4727).
  void set_compare(double brk_cn);
  double compare() const { return compare_; }
  // GT_PosBrk / GT_NegBrk / GT_MtnBrk / GT_ExtBrk: arms (replacing an armed one). None = GT_BrkOff.
  void arm(BreakKind kind);
  void off() { kind_ = BreakKind::None; }
  BreakKind armed() const { return kind_; }

  // One servo period: the actual position (pulse), motion complete (status bit 0) and the home capture flag
  // now. Returns true if the armed breakpoint fires (it is then disarmed).
  bool check(double actual_pos, bool motion_complete, bool home_captured);

 private:
  BreakKind kind_ = BreakKind::None;
  double compare_ = 0.0;
  bool prev_complete_ = true, prev_home_ = false;
};

}  // namespace servobench::motion
