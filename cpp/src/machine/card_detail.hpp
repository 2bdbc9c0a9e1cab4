// What the card kernel's source files share (card.cpp, card_registers.cpp, card_commands.cpp, card_tick.cpp):
// not part of the public interface.
#pragma once

#include <cstddef>
#include <string>

#include "servobench/machine/trace.hpp"
#include "servobench/machine/motion_loop.hpp"

namespace servobench::machine::detail {

constexpr double kPosMin = -1073741824.0;  // -2^30 (GT L854, GE L991), whole pulses
constexpr double kPosMax = 1073741823.0;   // 2^30 - 1

// "axis k" with the 1-based number the manuals use.
inline std::string axis_name(std::size_t i) { return "axis " + std::to_string(i + 1); }

// The trace pointers advanced to tick k of a run (null stays null).
inline Trace shifted(const Trace& t, std::size_t k) {
  Trace out;
#define SERVOBENCH_SHIFT(name, unit, doc) out.name = t.name ? t.name + k : nullptr;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return out;
}

inline LoopTrace shifted(const LoopTrace& t, std::size_t k) {
  LoopTrace out;
#define SERVOBENCH_SHIFT(name, unit, doc) out.name = t.name ? t.name + k : nullptr;
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_SHIFT)
#undef SERVOBENCH_SHIFT
  return out;
}

}  // namespace servobench::machine::detail
