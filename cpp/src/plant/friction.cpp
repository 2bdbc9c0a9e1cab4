#include "servobench/plant/friction.hpp"

#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void FrictionParams::validate(const char* owner, const char* prefix) const {
  const std::string p(prefix);
  check_nonnegative(owner, (p + "viscous_nms").c_str(), viscous_nms);
  check_nonnegative(owner, (p + "coulomb_nm").c_str(), coulomb_nm);
  check_nonnegative(owner, (p + "static_nm").c_str(), static_nm);
  if (static_nm != 0.0 && static_nm < coulomb_nm)
    throw_invalid(owner, (p + "static_nm").c_str(), static_nm,
                  "must be 0 (= coulomb) or >= " + p + "coulomb_nm = " + format_value(coulomb_nm) +
                      " (the breakaway level cannot be below the sliding level)");
  check_positive(owner, (p + "stribeck_speed_rad_s").c_str(), stribeck_speed_rad_s);
  check_range(owner, (p + "stribeck_exponent").c_str(), stribeck_exponent, 0.5, 4.0);
  // asymmetry: both directions' levels stay >= 0 (issue 19)
  check_range(owner, (p + "coulomb_asym_nm").c_str(), coulomb_asym_nm, -coulomb_nm, coulomb_nm,
              ("|" + p + "coulomb_asym_nm| <= " + p + "coulomb_nm").c_str());
  check_range(owner, (p + "viscous_asym_nms").c_str(), viscous_asym_nms, -viscous_nms, viscous_nms,
              ("|" + p + "viscous_asym_nms| <= " + p + "viscous_nms").c_str());
}

}  // namespace servobench::plant
