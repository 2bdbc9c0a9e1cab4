// Parameter validation shared by every layer: one message format, one exception type.
//
// Every parameter object of servobench validates on construction. A bad value raises
// std::invalid_argument (ValueError in Python) whose text names the owner, the field, the value and the
// allowed range, e.g. "GtServoLaw.kp = 40000 is outside the allowed range 0..32767 (GT manual Table 3-4)".
#pragma once

#include <string>

namespace servobench {

// Formats a double the way a user typed it (no trailing zeros; "nan", "inf").
std::string format_value(double value);

// Throws std::invalid_argument: "<owner>.<field> = <value> <problem>".
[[noreturn]] void throw_invalid(const char* owner, const char* field, double value, const std::string& problem);

// value finite and lo <= value <= hi. `source` (may be empty) names the manual table that sets the range.
void check_range(const char* owner, const char* field, double value, double lo, double hi, const char* source = "");

// value finite, a whole number, and lo <= value <= hi.
void check_integer(const char* owner, const char* field, double value, double lo, double hi, const char* source = "");

// The allowed range of a whole-number field and the manual line stating it: one description used by the struct's
// validate() and by the Python binding before a value becomes an int, so both give check_integer's message.
struct WholeRange {
  double lo;
  double hi;
  const char* source;
  void check(const char* owner, const char* field, double value) const {
    check_integer(owner, field, value, lo, hi, source);
  }
};

// The largest magnitude a parameter without a stated physical range may take (decision RB1): above it a value is
// a typo or an overflow (1e308, 2^63), never a setting.
inline constexpr double kMaxMagnitude = 1e12;

// value finite and 0 < value <= hi.
void check_positive(const char* owner, const char* field, double value, double hi = kMaxMagnitude);

// value finite and 0 <= value <= hi.
void check_nonnegative(const char* owner, const char* field, double value, double hi = kMaxMagnitude);

// 0 < value <= hi, or +infinity (it means "none", e.g. no current limit). NaN rejected.
void check_positive_or_inf(const char* owner, const char* field, double value, double hi = kMaxMagnitude);

}  // namespace servobench
