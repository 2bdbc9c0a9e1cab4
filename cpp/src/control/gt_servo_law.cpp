#include "servobench/control/gt_servo_law.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::control {

void GtServoLawParams::validate() const {
  constexpr const char* owner = "GtServoLaw";
  constexpr const char* table = "GT manual Table 3-4";
  if (fractional_gains) {
    constexpr const char* ge = "GE manual L5530-5620";
    check_range(owner, "kp", kp, 0, 32767, ge);
    check_range(owner, "ki", ki, 0, 32767, ge);
    check_range(owner, "kd", kd, 0, 32767, ge);
    check_range(owner, "kvff", kvff, 0, 32767, ge);
    check_range(owner, "kaff", kaff, 0, 32767, ge);
  } else {
    check_integer(owner, "kp", kp, 0, 32767, table);
    check_integer(owner, "ki", ki, 0, 32767, table);
    check_integer(owner, "kd", kd, 0, 32767, table);
    check_integer(owner, "kvff", kvff, 0, 32767, table);
    check_integer(owner, "kaff", kaff, 0, 32767, table);
  }
  check_integer(owner, "ilmt", ilmt, 0, 32767, table);
  check_integer(owner, "bias", bias, -32768, 32767, table);
  check_integer(owner, "mtr_lmt", mtr_lmt, 0, 32767, "GT manual L829");
}

namespace {
// Ki/256 where that division is exact (Ki >= 2^-1014 or 0), else NaN: step() then takes the written-out form.
double exact_ki_256(double ki) {
  const double k = ki * (1.0 / 256.0);
  return k * 256.0 == ki ? k : std::nan("");
}
}  // namespace

GtServoLaw::GtServoLaw(const GtServoLawParams& params) : params_(params) {
  params_.validate();
  ki_256_ = exact_ki_256(params_.ki);
}

void GtServoLaw::set_params(const GtServoLawParams& params) {
  params.validate();
  params_ = params;
  ki_256_ = exact_ki_256(params_.ki);
  if (params_.ilmt == 0) sum_ = 0.0;
}

void GtServoLaw::reset() {
  sum_ = 0.0;
  prev_error_ = 0.0;
}

}  // namespace servobench::control
