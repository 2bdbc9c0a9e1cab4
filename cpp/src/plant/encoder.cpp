#include "servobench/plant/encoder.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void EncoderParams::validate() const {
  check_integer("Encoder", "counts_per_rev", counts_per_rev, 1, 2147483648.0);
  check_nonnegative("Encoder", "noise_counts", noise_counts);
  check_integer("Encoder", "seed", seed, 0, 4294967295.0);
  check_range("Encoder", "index_angle_rad", index_angle_rad, -1e6, 1e6);
}

Encoder::Encoder(const EncoderParams& params) : params_(params) {
  params_.validate();
  counts_per_rad_ = params_.counts_per_rev / (2.0 * M_PI);
  noisy_ = params_.noise_counts > 0.0;
  reset();
}

void Encoder::reset() {
  rng_.seed(static_cast<std::uint64_t>(params_.seed));
  gauss_.reset();
}

}  // namespace servobench::plant
