#include "servobench/motion/breakpoint.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::motion {

const char* to_string(BreakKind kind) {
  switch (kind) {
    case BreakKind::None: return "none";
    case BreakKind::PositionAbove: return "position_above";
    case BreakKind::PositionBelow: return "position_below";
    case BreakKind::MotionComplete: return "motion_complete";
    case BreakKind::Home: return "home";
  }
  return "?";
}

void Breakpoint::set_compare(double brk_cn) {
  check_integer("Breakpoint", "brk_cn", brk_cn, -1073741824.0, 1073741823.0, "GT_SetBrkCn, GT L4721-4727");
  compare_ = brk_cn;
}

void Breakpoint::arm(BreakKind kind) { kind_ = kind; }

bool Breakpoint::check(double actual_pos, bool motion_complete, bool home_captured) {
  bool fire = false;
  switch (kind_) {
    case BreakKind::None: break;
    case BreakKind::PositionAbove: fire = actual_pos >= compare_; break;
    case BreakKind::PositionBelow: fire = actual_pos <= compare_; break;
    case BreakKind::MotionComplete: fire = motion_complete && !prev_complete_; break;
    case BreakKind::Home: fire = home_captured && !prev_home_; break;
  }
  prev_complete_ = motion_complete;
  prev_home_ = home_captured;
  if (fire) kind_ = BreakKind::None;
  return fire;
}

}  // namespace servobench::motion
