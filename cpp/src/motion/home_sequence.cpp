#include "servobench/motion/home_sequence.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"
#include "servobench/motion/check.hpp"
#include "servobench/motion/units.hpp"

namespace servobench::motion {

const char* to_string(HomePhase phase) {
  switch (phase) {
    case HomePhase::Idle: return "idle";
    case HomePhase::Search: return "search";
    case HomePhase::SearchReverse: return "search_reverse";
    case HomePhase::StopAfterFind: return "stop_after_find";
    case HomePhase::Leave: return "leave";
    case HomePhase::StopAfterLeave: return "stop_after_leave";
    case HomePhase::Approach: return "approach";
    case HomePhase::StopBeforeEz: return "stop_before_ez";
    case HomePhase::AlignEz: return "align_ez";
    case HomePhase::StopAtEdge: return "stop_at_edge";
    case HomePhase::MoveToEdge: return "move_to_edge";
    case HomePhase::Done: return "done";
    case HomePhase::Failed: return "failed";
  }
  return "?";
}

void AdlinkHomeParams::validate() const {
  const char* src = "ADLINK L2268-2278";
  check_integer("AdlinkHome", "mode", mode, 0, 2, "PRA_HOME_MODE: 0 ORG, 1 EL, 2 EZ; ADLINK L2333-2337");
  check_integer("AdlinkHome", "dir", dir, 0, 1, "PRA_HOME_DIR: 0 positive, 1 negative; ADLINK L2357, L2378");
  check_range("AdlinkHome", "curve", curve, 0.0, 1.0, "PRA_HOME_CURVE S-factor; ADLINK L2213-2219");
  check_motion_value("AdlinkHome", "acc", acc, 0.0, 1e12, src);
  check_motion_value("AdlinkHome", "vm", vm, 0.0, 1e9, src);
  check_motion_value("AdlinkHome", "vo", vo, 0.0, vm, "ADLINK L2277, L2455: the approach speed, 0 < vo <= vm");
  check_range("AdlinkHome", "shift", shift, -2147483647.0, 2147483647.0, src);
  check_range("AdlinkHome", "pos", pos, -2147483647.0, 2147483647.0, src);
}

void GtHomeParams::validate() const {
  check_profile_position("GtHome", "pos", pos, "GT_Home, GT L854, L4152-4168");
  check_motion_value("GtHome", "vel", vel, 0.0, 16384.0, "GT L930");
  check_motion_value("GtHome", "acc", acc, 0.0, 16384.0, "GT L929");
}

HomeSequence::HomeSequence(const AdlinkHomeParams& p, double period_s) : ad_(p) {
  p.validate();
  check_period("AdlinkHome", period_s);
  vm_ = per_s_to_per_tick(p.vm, period_s, 1);
  vo_ = per_s_to_per_tick(p.vo, period_s, 1);
  acc_ = per_s_to_per_tick(p.acc, period_s, 2);
  lim_ = {0.0, vm_, 0.0, acc_, acc_, p.curve};
  s_ = p.dir == 0 ? 1.0 : -1.0;
}

HomeSequence::HomeSequence(const GtHomeParams& p) : gt_(true), gtp_(p) { p.validate(); }

void HomeSequence::velocity(ProfileGenerator& gen, double speed, double sign) {
  AdlinkLimits lim = lim_;
  lim.vm = speed;
  gen.move_adlink_velocity(sign * speed, lim);
}

void HomeSequence::stop(ProfileGenerator& gen) {
  if (gt_) {
    gen.smooth_stop();
    return;
  }
  gen.smooth_stop_with(acc_, adlink_ramp_jerk(gen.state().vel, acc_, lim_.sf));
}

void HomeSequence::fail(ProfileGenerator& gen, int code) {
  gen.abrupt_stop();
  error_ = code;
  phase_ = HomePhase::Failed;
}

HomeAction HomeSequence::step(const HomeInputs& in, ProfileGenerator& gen) {
  if (finished()) return {};
  return gt_ ? step_gt(in, gen) : step_adlink(in, gen);
}

HomeAction HomeSequence::step_adlink(const HomeInputs& in, ProfileGenerator& gen) {
  const int mode = static_cast<int>(ad_.mode);
  const SignalEvent& ahead_limit = s_ > 0 ? in.pel : in.mel;   // the limit in the home direction
  const SignalEvent& behind_limit = s_ > 0 ? in.mel : in.pel;  // the limit behind
  const int ahead_code = s_ > 0 ? 4 : 5, behind_code = s_ > 0 ? 5 : 4;  // STOP_PEL 4, STOP_MEL 5
  // The reference signal of modes 0 and 1.
  const SignalEvent& ref = mode == 1 ? ahead_limit : in.org;
  const bool moving = gen.moving();
  switch (phase_) {
    case HomePhase::Idle:
      if (mode != 2 && ref.level) {
        phase_ = HomePhase::Leave;  // start case B: on the reference signal, leave it first
        velocity(gen, vm_, -s_);
      } else {
        phase_ = HomePhase::Search;
        velocity(gen, vm_, s_);
      }
      break;
    case HomePhase::Search:
      if (mode == 2 && in.ez.rose) {
        latch(in.ez.edge_pos);
        stop(gen);
        phase_ = HomePhase::StopAtEdge;
      } else if (mode != 2 && ref.level) {
        stop(gen);
        phase_ = HomePhase::StopAfterFind;
      } else if (ahead_limit.level) {
        // Start case C: the reference lies behind; reverse the search once (M41).
        if (reversed_) return fail(gen, ahead_code), HomeAction{};
        reversed_ = true;
        velocity(gen, vm_, -s_);
        phase_ = HomePhase::SearchReverse;
      }
      break;
    case HomePhase::SearchReverse:
      if (mode == 2 && in.ez.rose) {
        latch(in.ez.edge_pos);
        stop(gen);
        phase_ = HomePhase::StopAtEdge;
      } else if (mode == 0 && in.org.rose) {
        phase_ = HomePhase::Leave;  // already moving away in direction -s: leave ORG on its far side
      } else if (behind_limit.level) {
        fail(gen, behind_code);
      }
      break;
    case HomePhase::StopAfterFind:
      if (!moving) {
        velocity(gen, vm_, -s_);
        phase_ = HomePhase::Leave;
      }
      break;
    case HomePhase::Leave:
      if (ref.fell) {
        stop(gen);
        phase_ = HomePhase::StopAfterLeave;
      } else if (behind_limit.level && !(mode == 1 && ref.level)) {
        fail(gen, behind_code);
      }
      break;
    case HomePhase::StopAfterLeave:
      if (!moving) {
        velocity(gen, vo_, s_);
        phase_ = HomePhase::Approach;
      }
      break;
    case HomePhase::Approach:
      if (ref.rose) {
        latch(ref.edge_pos);
        if (ad_.eza && mode == 0) {
          phase_ = HomePhase::AlignEz;  // keep moving at VO to the first index mark (L2391)
        } else {
          stop(gen);
          phase_ = ad_.eza ? HomePhase::StopBeforeEz : HomePhase::StopAtEdge;
        }
      } else if (mode == 0 && ahead_limit.level) {
        fail(gen, ahead_code);
      }
      break;
    case HomePhase::StopBeforeEz:
      if (!moving) {
        velocity(gen, vo_, -s_);  // mode 1: the index mark away from the limit (M41)
        phase_ = HomePhase::AlignEz;
      }
      break;
    case HomePhase::AlignEz:
      if (in.ez.rose) {
        latch(in.ez.edge_pos);
        stop(gen);
        phase_ = HomePhase::StopAtEdge;
      } else if ((mode == 0 && ahead_limit.level) || (mode == 1 && behind_limit.level)) {
        fail(gen, mode == 0 ? ahead_code : behind_code);
      }
      break;
    case HomePhase::StopAtEdge:
      if (!moving) {
        AdlinkLimits lim = lim_;
        lim.vm = vo_;
        const double target = std::nearbyint(reference_ + ad_.shift);
        if (target != gen.state().pos) gen.move_adlink_ptp(target, lim);
        phase_ = HomePhase::MoveToEdge;
      }
      break;
    case HomePhase::MoveToEdge:
      if (!moving) {
        phase_ = HomePhase::Done;
        return {true, ad_.pos};
      }
      break;
    case HomePhase::Done:
    case HomePhase::Failed: break;
  }
  return {};
}

HomeAction HomeSequence::step_gt(const HomeInputs& in, ProfileGenerator& gen) {
  const bool moving = gen.moving();
  const TCurveLimits lim{gtp_.vel, gtp_.acc};
  switch (phase_) {
    case HomePhase::Idle:
      s_ = gtp_.pos >= gen.state().pos ? 1.0 : -1.0;
      if (in.org.level) {
        gen.jog(-s_ * gtp_.vel, gtp_.acc);  // the home signal is on: move away from pos until it is off (L4160)
        phase_ = HomePhase::Leave;
      } else {
        gen.move_t_curve(gtp_.pos, lim);
        phase_ = HomePhase::Search;
      }
      break;
    case HomePhase::Leave:
      if (!in.org.level) {
        gen.smooth_stop();
        phase_ = HomePhase::StopAfterLeave;
      }
      break;
    case HomePhase::StopAfterLeave:
      if (!moving) {
        gen.move_t_curve(gtp_.pos, lim);
        phase_ = HomePhase::Search;
      }
      break;
    case HomePhase::Search:
      if (in.org.rose) {
        latch(in.org.edge_pos);
        gen.move_t_curve(std::nearbyint(reference_), lim);  // back to the captured home position (Ex. 6-1 step 3)
        phase_ = HomePhase::StopAtEdge;
      } else if (!moving) {
        error_ = 1;  // motion complete before the home capture: no home (Ex. 6-1 step 2)
        phase_ = HomePhase::Failed;
      }
      break;
    case HomePhase::StopAtEdge:
      if (!moving) {
        if (gtp_.index) {
          gen.move_t_curve(gtp_.pos, lim);
          phase_ = HomePhase::AlignEz;
        } else {
          phase_ = HomePhase::MoveToEdge;
        }
      }
      break;
    case HomePhase::AlignEz:
      if (in.ez.rose) {
        latch(in.ez.edge_pos);
        gen.move_t_curve(std::nearbyint(reference_), lim);
        phase_ = HomePhase::MoveToEdge;
      } else if (!moving) {
        error_ = 2;  // no index before pos
        phase_ = HomePhase::Failed;
      }
      break;
    case HomePhase::MoveToEdge:
      if (!moving) {
        phase_ = HomePhase::Done;
        if (gtp_.zero) return {true, 0.0};
      }
      break;
    default: break;
  }
  return {};
}

}  // namespace servobench::motion
