#include "servobench/common/validate.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace servobench {

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

void throw_invalid(const char* owner, const char* field, double value, const std::string& problem) {
  throw std::invalid_argument(std::string(owner) + "." + field + " = " + format_value(value) + " " + problem);
}

static std::string range_text(double lo, double hi, const char* source) {
  std::string text = format_value(lo) + ".." + format_value(hi);
  if (source != nullptr && source[0] != '\0') text += std::string(" (") + source + ")";
  return text;
}

void check_range(const char* owner, const char* field, double value, double lo, double hi, const char* source) {
  if (!std::isfinite(value)) throw_invalid(owner, field, value, "is not a finite number; the allowed range is " + range_text(lo, hi, source));
  if (value < lo || value > hi) throw_invalid(owner, field, value, "is outside the allowed range " + range_text(lo, hi, source));
}

void check_integer(const char* owner, const char* field, double value, double lo, double hi, const char* source) {
  check_range(owner, field, value, lo, hi, source);
  if (value != std::floor(value)) throw_invalid(owner, field, value, "is not a whole number; the allowed range is " + range_text(lo, hi, source));
}

// The messages below are formatted only when a check fails: a valid value costs its compares alone (building an
// axis validates some twenty values; a batch builds one axis per plant: decision FV27).
void check_positive(const char* owner, const char* field, double value, double hi) {
  if (std::isfinite(value) && value > 0 && value <= hi) return;
  const std::string range = "must be > 0 and <= " + format_value(hi);
  if (!std::isfinite(value)) throw_invalid(owner, field, value, "is not a finite number; it " + range);
  throw_invalid(owner, field, value, range);
}

void check_nonnegative(const char* owner, const char* field, double value, double hi) {
  if (std::isfinite(value) && value >= 0 && value <= hi) return;
  const std::string range = "must be >= 0 and <= " + format_value(hi);
  if (!std::isfinite(value)) throw_invalid(owner, field, value, "is not a finite number; it " + range);
  throw_invalid(owner, field, value, range);
}

void check_positive_or_inf(const char* owner, const char* field, double value, double hi) {
  if (value > 0 && (value <= hi || value == INFINITY)) return;
  const std::string range = "must be > 0 and <= " + format_value(hi) + " (inf = none)";
  if (std::isnan(value)) throw_invalid(owner, field, value, "is not a number; it " + range);
  throw_invalid(owner, field, value, range);
}

}  // namespace servobench
