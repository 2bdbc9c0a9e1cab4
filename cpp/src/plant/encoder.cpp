#include "servobench/plant/encoder.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void EncoderParams::validate() const {
  check_integer("Encoder", "counts_per_rev", counts_per_rev, 1, 2147483648.0);
}

Encoder::Encoder(const EncoderParams& params) : params_(params) {
  params_.validate();
  counts_per_rad_ = params_.counts_per_rev / (2.0 * M_PI);
}

}  // namespace servobench::plant
