#include "servobench/control/aps_servo_law.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::control {

void ApsServoLawParams::validate() const {
  constexpr const char* owner = "ApsServoLaw";
  constexpr const char* table = "ADLINK manual L1746-1762";
  check_integer(owner, "kp", kp, 0, 65535, table);
  check_integer(owner, "ki", ki, 0, 65535, table);
  check_integer(owner, "kd", kd, 0, 65535, table);
  check_integer(owner, "kvff", kvff, 0, 65535, table);
  check_integer(owner, "kaff", kaff, 0, 65535, table);
  check_integer(owner, "kp_shift", kp_shift, -31, 31, table);
  check_integer(owner, "ki_shift", ki_shift, -31, 31, table);
  check_integer(owner, "kd_shift", kd_shift, -31, 31, table);
  check_integer(owner, "kvff_shift", kvff_shift, -31, 31, table);
  check_integer(owner, "kaff_shift", kaff_shift, -31, 31, table);
  check_integer(owner, "pid_shift", pid_shift, -31, 31, table);
  check_integer(owner, "integral_limit", integral_limit, 0, 2147483647.0, table);
  check_range(owner, "v_bias", v_bias, 0, 10, table);
  check_range(owner, "v_limit", v_limit, 0, 10, table);
}

ApsServoLaw::ApsServoLaw(const ApsServoLawParams& params) : params_(params) {
  params_.validate();
  cache_gains();
}

void ApsServoLaw::set_params(const ApsServoLawParams& params) {
  params.validate();
  params_ = params;
  cache_gains();
}

void ApsServoLaw::cache_gains() {
  kp_ = params_.kp_eff();
  ki_ = params_.ki_eff();
  kd_ = params_.kd_eff();
  kvff_ = params_.kvff_eff();
  kaff_ = params_.kaff_eff();
}

void ApsServoLaw::reset() {
  sum_ = 0.0;
  prev_error_ = 0.0;
  prev_cmd_ = 0.0;
  prev_vel_ = 0.0;
  primed_ = false;
}

}  // namespace servobench::control
