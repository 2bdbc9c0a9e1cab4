// Range checks for motion parameters, on top of servobench/common/validate.hpp.
#pragma once

#include <cmath>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

// lo <= value <= hi (or < hi if `open_hi`), finite; and value != 0 when `nonzero` (a zero velocity or
// acceleration is inside the manuals' ranges but a move planned with it never finishes).
inline void check_motion_value(const char* owner, const char* field, double value, double lo, double hi,
                               const char* source, bool nonzero = true, bool open_hi = false) {
  const std::string range = format_value(lo) + (open_hi ? " <= x < " : "..") + format_value(hi) + " (" + source + ")";
  if (!std::isfinite(value)) throw_invalid(owner, field, value, "is not a finite number; the allowed range is " + range);
  if (value < lo || value > hi || (open_hi && value >= hi))
    throw_invalid(owner, field, value, "is outside the allowed range " + range);
  if (nonzero && value == 0.0)
    throw_invalid(owner, field, value, "must be non-zero for a move to finish; the manual's range is " + range);
}

// A profile position in whole pulses within the GT/GE range -2^30..2^30-1 (GT L854, GE L991).
inline void check_profile_position(const char* owner, const char* field, double value, const char* source) {
  check_integer(owner, field, value, -1073741824.0, 1073741823.0, source);
}

// A tick period in seconds for unit conversion: 1 us .. 1 s.
inline void check_period(const char* owner, double period_s) {
  check_range(owner, "period_s", period_s, 1e-6, 1.0, "s");
}

}  // namespace servobench::motion
