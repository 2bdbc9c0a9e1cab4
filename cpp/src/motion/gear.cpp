#include "servobench/motion/gear.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

void GtGearParams::validate() const {
  kMasterRange.check("GtGear", "master", master);
  check_range("GtGear", "ratio", ratio, -16384.0, 16384.0, "GT L1043");
}

ElectronicGear::ElectronicGear(double ratio, long long master_pos, double slave_pos)
    : ratio_(ratio), master_base_(master_pos), slave_base_(slave_pos) {
  check_range("ElectronicGear", "ratio", ratio, -16384.0, 16384.0, "GT L1043");
  if (!std::isfinite(slave_pos)) throw_invalid("ElectronicGear", "slave_pos", slave_pos, "must be a finite number");
  state_.pos = slave_pos;
}

void ElectronicGear::set_ratio(double ratio, long long master_pos) {
  check_range("ElectronicGear", "ratio", ratio, -16384.0, 16384.0, "GT L1043");
  slave_base_ = slave_base_ + ratio_ * static_cast<double>(master_pos - master_base_);
  master_base_ = master_pos;
  ratio_ = ratio;
}

const MotionState& ElectronicGear::step(long long master_pos) {
  const double pos = slave_base_ + ratio_ * static_cast<double>(master_pos - master_base_);
  const double vel = pos - state_.pos;
  const double acc = vel - state_.vel;
  state_ = {pos, vel, acc, acc - state_.acc};
  return state_;
}

double ElectronicGear::remainder() const { return state_.pos - static_cast<double>(reported_pos()); }

long long ElectronicGear::reported_pos() const { return std::llround(state_.pos); }

}  // namespace servobench::motion
