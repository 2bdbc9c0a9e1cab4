#include "servobench/motion/stop.hpp"

#include "servobench/motion/velocity_change.hpp"

namespace servobench::motion {

Profile plan_smooth_stop(const MotionState& from, double acc, double jerk) {
  MotionState start = from;
  start.jerk = 0.0;
  if (std::isinf(jerk)) start.acc = 0.0;
  Profile prof(start);
  push_velocity_change(prof, 0.0, acc, jerk);
  return prof.finish_at_rest(prof.end().pos);
}

Profile plan_abrupt_stop(const MotionState& from) { return Profile::rest(from.pos); }

}  // namespace servobench::motion
