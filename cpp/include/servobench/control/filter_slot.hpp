// A filter slot after the servo law: the ADLINK card has two biquads in series there (adlink.md §3).
// Until the biquad issue lands, a slot is a pass-through; the Axis already calls both slots every tick and
// records their outputs (BIQUAD_0_CALC / BIQUAD_1_CALC), so the biquads only replace this type.
#pragma once

namespace servobench::control {

class FilterSlot {
 public:
  double step(double x) { return x; }
  void reset() {}
};

}  // namespace servobench::control
