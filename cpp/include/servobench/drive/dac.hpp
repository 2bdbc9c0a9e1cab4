// The analog output: a bipolar DAC with saturation and optional quantisation.
//
// Both manuals' cards have a 16-bit +-10 V output (GT L829; ADLINK L327, L351-356). Codes are symmetric,
// -(2^(bits-1)-1) .. +(2^(bits-1)-1), so +32767 is exactly +10 V for 16 bits, matching GT's
// "+-32767 <-> +-max voltage" (L4960-4966). Quantisation rounds to the nearest code (docs/decisions.md).
#pragma once

#include "servobench/common/rounding.hpp"

#include <cmath>

namespace servobench::drive {

struct DacParams {
  double bits = 16;           // resolution, 8..24 bits (whole number)
  double full_scale_v = 10.0; // +-full scale, V, (0, 100]
  bool quantize = true;       // false: an ideal (continuous) DAC that only saturates
  void validate() const;
};

class Dac {
 public:
  explicit Dac(const DacParams& params = {});
  const DacParams& params() const { return params_; }

  // Volts actually produced for a requested voltage: saturated to +-full scale, then quantised. Round: the rounding
  // policy (common/rounding.hpp) of the kernel that inlines this; the same result with each.
  template <class Round = PortableRounding>
  double convert(double volts) const {
    const double fs = params_.full_scale_v;
    double v = volts > fs ? fs : (volts < -fs ? -fs : volts);
    if (params_.quantize) v = Round::nearbyint(v * codes_per_volt_) * volts_per_code_;
    return v;
  }
  double volts_per_code() const { return volts_per_code_; }
  double codes_per_volt() const { return codes_per_volt_; }
  double max_code() const { return max_code_; }

 private:
  DacParams params_;
  double max_code_ = 32767.0;
  double codes_per_volt_ = 3276.7;
  double volts_per_code_ = 1.0 / 3276.7;
};

}  // namespace servobench::drive
