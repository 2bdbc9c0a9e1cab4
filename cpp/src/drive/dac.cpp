#include "servobench/drive/dac.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::drive {

void DacParams::validate() const {
  check_integer("Dac", "bits", bits, 8, 24);
  check_range("Dac", "full_scale_v", full_scale_v, 1e-3, 100.0);
}

Dac::Dac(const DacParams& params) : params_(params) {
  params_.validate();
  max_code_ = std::ldexp(1.0, static_cast<int>(params_.bits) - 1) - 1.0;
  codes_per_volt_ = max_code_ / params_.full_scale_v;
  volts_per_code_ = params_.full_scale_v / max_code_;
}

}  // namespace servobench::drive
