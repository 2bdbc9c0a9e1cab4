// What the path generator's source files share (path_generator.cpp, path_buffer_io.cpp): not public.
#pragma once

#include "servobench/common/validate.hpp"

namespace servobench::motion::detail {

// check_range, and v strictly inside (lo, hi) (src: the manual's line).
inline void check_open(const char* owner, const char* field, double v, double lo, double hi, const char* src) {
  check_range(owner, field, v, lo, hi, src);
  if (!(v > lo) || !(v < hi))
    throw_invalid(owner, field, v, "must be in the open interval (" + format_value(lo) + ", " + format_value(hi) +
                                       ") (" + src + ")");
}

}  // namespace servobench::motion::detail
