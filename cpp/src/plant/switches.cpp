#include "servobench/plant/switches.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void SwitchParams::validate() const {
  constexpr const char* owner = "Switches";
  if (std::isnan(home_min_rad)) throw_invalid(owner, "home_min_rad", home_min_rad, "is not a number; it must be finite or inf (no home switch)");
  if (std::isnan(home_max_rad)) throw_invalid(owner, "home_max_rad", home_max_rad, "is not a number; it must be finite or inf (no home switch)");
  if (std::isnan(pos_limit_rad)) throw_invalid(owner, "pos_limit_rad", pos_limit_rad, "is not a number; it must be finite or +inf (none)");
  if (std::isnan(neg_limit_rad)) throw_invalid(owner, "neg_limit_rad", neg_limit_rad, "is not a number; it must be finite or -inf (none)");
  if (std::isinf(home_min_rad) != std::isinf(home_max_rad))
    throw_invalid(owner, "home_max_rad", home_max_rad, "and home_min_rad must both be finite (a window) or both inf (none)");
  if (std::isfinite(home_min_rad) && home_min_rad > home_max_rad)
    throw_invalid(owner, "home_min_rad", home_min_rad, "must be <= home_max_rad = " + format_value(home_max_rad));
  if (pos_limit_rad == -std::numeric_limits<double>::infinity())
    throw_invalid(owner, "pos_limit_rad", pos_limit_rad, "must be finite or +inf (none)");
  if (neg_limit_rad == std::numeric_limits<double>::infinity())
    throw_invalid(owner, "neg_limit_rad", neg_limit_rad, "must be finite or -inf (none)");
  if (neg_limit_rad >= pos_limit_rad)
    throw_invalid(owner, "neg_limit_rad", neg_limit_rad, "must be below pos_limit_rad = " + format_value(pos_limit_rad));
}

}  // namespace servobench::plant
