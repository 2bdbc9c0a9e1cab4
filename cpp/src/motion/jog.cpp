#include "servobench/motion/jog.hpp"

#include "servobench/motion/check.hpp"
#include "servobench/motion/units.hpp"
#include "servobench/motion/velocity_change.hpp"

namespace servobench::motion {

Profile plan_jog(const MotionState& from, double vel, double acc, double jerk) {
  MotionState start = from;
  start.jerk = 0.0;
  Profile prof(start);
  push_velocity_change(prof, vel, acc, jerk);
  prof.settle_acc();
  if (vel != 0.0) {
    prof.push(std::numeric_limits<double>::infinity(), 0.0);
  } else {
    prof.finish_at_rest(prof.end().pos);
  }
  return prof;
}

void GtJogParams::validate() const {
  check_range("GtJog", "vel", vel, -16384.0, 16384.0, "GT L994");
  check_motion_value("GtJog", "acc", acc, 0.0, 16384.0, "GT L995");
}

void GeJogParams::validate() const {
  check_range("GeJog", "vel", vel, -40958.0, 40957.0, "GE L1202-1206");
  check_motion_value("GeJog", "acc", acc, 0.0, 102400.0, "GE L1202-1206");
}

double GeJogParams::vel_per_tick(double period_s) const {
  check_period("GeJog", period_s);
  return per_ms_to_per_tick(vel, period_s, 1);
}

double GeJogParams::acc_per_tick(double period_s) const {
  check_period("GeJog", period_s);
  return per_ms_to_per_tick(acc, period_s, 2);
}

}  // namespace servobench::motion
