// The position encoder: shaft angle (rad) -> feedback count (pulse), with the index mark.
//
//   count = floor(angle * counts_per_rev / (2*pi) + noise + 1/2)    (quantize = true)
//   count = angle * counts_per_rev / (2*pi) + noise                  (quantize = false)
//
// counts_per_rev is after quadrature (x4) decoding: a 2500-line encoder gives 10000. The quantised encoder is
// taken to power up in the middle of a count (error +-1/2 count about the angle). `noise_counts` adds
// Gaussian noise of that standard deviation (counts) before quantisation, from a generator seeded with `seed`:
// identical seeds give identical runs. The index mark fires once per revolution when the shaft passes
// index_angle_rad (mod 2*pi). on_load mounts the encoder on the load (fully closed loop, e.g. a linear scale on
// a two-mass axis) instead of the motor (semi-closed loop).
#pragma once

#include "servobench/common/rounding.hpp"

#include <cmath>
#include <cstdint>
#include <random>

namespace servobench::plant {

struct EncoderParams {
  double counts_per_rev = 10000.0;  // counts per revolution after decoding, whole number 1..2^31
  bool quantize = true;             // false: an ideal (continuous) encoder
  double noise_counts = 0.0;        // standard deviation of additive noise, counts, >= 0
  double seed = 1.0;                // noise generator seed, whole number 0..2^32-1
  double index_angle_rad = 0.0;     // angle of the index mark, rad (finite)
  bool on_load = false;             // true: mounted on the load side (two-mass plants)
  void validate() const;
};

class Encoder {
 public:
  explicit Encoder(const EncoderParams& params = {});
  const EncoderParams& params() const { return params_; }
  double counts_per_rad() const { return counts_per_rad_; }
  // Restarts the noise generator from the seed.
  void reset();

  // Round: the rounding policy (common/rounding.hpp) of the kernel that inlines this; the same result with each.
  template <class Round = PortableRounding>
  double read(double angle_rad) {
    double c = angle_rad * counts_per_rad_;
    if (noisy_) c += params_.noise_counts * gauss_(rng_);
    return params_.quantize ? Round::floor(c + 0.5) : c;
  }
  // Noise-free reading (for status displays and tests).
  double read_ideal(double angle_rad) const {
    const double c = angle_rad * counts_per_rad_;
    return params_.quantize ? floor_inline(c + 0.5) : c;
  }
  // True if the index mark lies between two successive angles (one crossing per revolution).
  template <class Round = PortableRounding>
  bool index_between(double from_rad, double to_rad) const {
    constexpr double two_pi = 2.0 * M_PI;
    return Round::floor((from_rad - params_.index_angle_rad) / two_pi) !=
           Round::floor((to_rad - params_.index_angle_rad) / two_pi);
  }

 private:
  EncoderParams params_;
  double counts_per_rad_;
  bool noisy_ = false;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
};

}  // namespace servobench::plant
