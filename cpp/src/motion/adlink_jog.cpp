#include "servobench/motion/adlink_jog.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"
#include "servobench/motion/stop.hpp"
#include "servobench/motion/units.hpp"

namespace servobench::motion {

const char* to_string(JogPhase phase) {
  switch (phase) {
    case JogPhase::Idle: return "idle";
    case JogPhase::Moving: return "moving";
    case JogPhase::Step: return "step";
    case JogPhase::Delay: return "delay";
    case JogPhase::Continuous: return "continuous";
    case JogPhase::Rounding: return "rounding";
  }
  return "?";
}

void AdlinkJogParams::validate() const {
  const char* src = "ADLINK L2677-2688";
  check_integer("AdlinkJog", "mode", mode, 0, 1, "PRA_JG_MODE: 0 continuous, 1 step; ADLINK L2677");
  check_integer("AdlinkJog", "dir", dir, 0, 1, "PRA_JG_DIR: 0 negative, 1 positive; ADLINK L2678");
  check_range("AdlinkJog", "sf", sf, 0.0, 1.0, "PRA_JG_SF; ADLINK L2679");
  check_motion_value("AdlinkJog", "acc", acc, 0.0, 1e12, src);
  check_motion_value("AdlinkJog", "dec", dec, 0.0, 1e12, src);
  check_motion_value("AdlinkJog", "vm", vm, 0.0, 1e9, src);
  check_motion_value("AdlinkJog", "offset", offset, 0.0, 2147483647.0, "PRA_JG_OFFSET; ADLINK L2683");
  check_range("AdlinkJog", "delay_us", delay_us, 0.0, 1e7, "PRA_JG_DELAY; ADLINK L2684");
}

AdlinkJog::AdlinkJog(const AdlinkJogParams& p, double period_s) : p_(p) {
  p.validate();
  check_period("AdlinkJog", period_s);
  lim_ = {0.0, per_s_to_per_tick(p.vm, period_s, 1), 0.0, per_s_to_per_tick(p.acc, period_s, 2),
          per_s_to_per_tick(p.dec, period_s, 2), p.sf};
  s_ = p.dir == 1 ? 1.0 : -1.0;
  delay_ticks_ = static_cast<long long>(std::ceil(p.delay_us * 1e-6 / period_s - 1e-9));
}

void AdlinkJog::round_up_and_stop(ProfileGenerator& gen) {
  // Where a plain deceleration would stop, then the next whole multiple of the offset at or beyond it.
  const MotionState& st = gen.state();
  const double stop_at = plan_adlink_stop(st, lim_.dec, lim_.sf).end().pos;
  const double n = std::ceil(s_ * (stop_at - origin_) / p_.offset - 1e-9);
  gen.move_adlink_ptp(origin_ + s_ * n * p_.offset, lim_);
  phase_ = JogPhase::Rounding;
}

void AdlinkJog::step(bool jog_on, ProfileGenerator& gen) {
  const bool rose = jog_on && !prev_on_;
  prev_on_ = jog_on;
  const bool moving = gen.moving();
  switch (phase_) {
    case JogPhase::Idle:
      if (rose && !moving) {
        origin_ = gen.state().pos;
        if (p_.mode == 0) {
          gen.move_adlink_velocity(s_ * lim_.vm, lim_);
          phase_ = JogPhase::Moving;
        } else {
          gen.move_adlink_ptp(origin_ + s_ * p_.offset, lim_);
          phase_ = JogPhase::Step;
        }
      }
      break;
    case JogPhase::Moving:  // continuous mode
      if (!jog_on && !gen.stopping()) {
        gen.smooth_stop_with(lim_.dec, adlink_ramp_jerk(gen.state().vel, lim_.dec, lim_.sf));
      }
      if (!jog_on && !gen.moving()) phase_ = JogPhase::Idle;
      break;
    case JogPhase::Step:
      if (!moving) {
        waited_ = 0;
        phase_ = JogPhase::Delay;
      }
      break;
    case JogPhase::Delay:
      if (!jog_on) {
        phase_ = JogPhase::Idle;
      } else if (++waited_ >= delay_ticks_) {
        gen.move_adlink_velocity(s_ * lim_.vm, lim_);
        phase_ = JogPhase::Continuous;
      }
      break;
    case JogPhase::Continuous:
      if (!jog_on && gen.state().acc == 0.0) round_up_and_stop(gen);
      break;
    case JogPhase::Rounding:
      if (!moving) phase_ = JogPhase::Idle;
      break;
  }
}

}  // namespace servobench::motion
