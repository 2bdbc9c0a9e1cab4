// The position encoder: motor angle (rad) -> feedback count (pulse).
//
//   count = angle * counts_per_rev / (2*pi)            (ideal, quantize = false)
//   count = floor(angle * counts_per_rev / (2*pi) + 1/2)   (quantised)
//
// counts_per_rev is after quadrature decoding (a 2500-line encoder read x4 gives 10000). The quantised
// encoder is taken to power up in the middle of a count, so the quantisation error is +-1/2 count around
// the angle (docs/decisions.md).
#pragma once

#include <cmath>

namespace servobench::plant {

struct EncoderParams {
  double counts_per_rev = 10000.0;  // counts per motor revolution after decoding, 1..2^31 whole number
  bool quantize = true;             // false: an ideal (continuous) encoder
  void validate() const;
};

class Encoder {
 public:
  explicit Encoder(const EncoderParams& params = {});
  const EncoderParams& params() const { return params_; }
  double counts_per_rad() const { return counts_per_rad_; }

  double read(double angle_rad) const {
    const double c = angle_rad * counts_per_rad_;
    return params_.quantize ? std::floor(c + 0.5) : c;
  }

 private:
  EncoderParams params_;
  double counts_per_rad_;
};

}  // namespace servobench::plant
