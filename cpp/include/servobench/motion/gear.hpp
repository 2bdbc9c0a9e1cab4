// Electronic gear: GT_PrflG (GT L1029-1090, L4407-4437). Slave increment = ratio x master increment (L1078).
//
// The master is any position source sampled once per tick in whole pulses: another axis's profile or encoder
// position, or an auxiliary encoder (masters 1-4 and 5-6 on the GT, L1042); wiring the source is the card's
// job. Drift-free: the slave position is computed from the master's whole-pulse travel since the last ratio
// change, slave = base + ratio * (master - master_base), so no per-tick rounding accumulates; the fraction
// of a pulse left over (the remainder) stays inside and the reported slave position is in whole pulses.
// A ratio change rebases at the current positions (no jump). Units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include "servobench/common/validate.hpp"
#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// GT_PrflG(Master) + GT_SetRatio parameters.
struct GtGearParams {
  static constexpr WholeRange kMasterRange{1, 6, "GT L1042"};
  int master = 1;  // master number: 1-4 axes, 5-6 auxiliary encoders (L1042)
  double ratio = 1;   // -16384..16384, negative reverses (L1043, L5020)
  void validate() const;
};

class ElectronicGear {
 public:
  // Engages at the current master position (pulse) with the slave at slave_pos (pulse).
  ElectronicGear(double ratio, long long master_pos, double slave_pos);

  // Changes the ratio from this tick on (GT_SetRatio + Update); rebases at master_pos.
  void set_ratio(double ratio, long long master_pos);
  // One tick: the master's position now (pulse); returns the slave state (vel and acc as backward
  // differences per tick).
  const MotionState& step(long long master_pos);

  double ratio() const { return ratio_; }
  const MotionState& state() const { return state_; }
  // The fraction of a pulse not yet reported: exact - reported.
  double remainder() const;
  long long reported_pos() const;

 private:
  double ratio_;
  long long master_base_;
  double slave_base_;
  MotionState state_;
};

}  // namespace servobench::motion
