// S-curve (jerk-limited, 7-phase) point-to-point profile: GT_PrflS (GT L839-912) and GE GT_PrflS (GE L1081-1188).
//
// Phases: jerk +J up to MAcc, hold MAcc, jerk -J down to 0 at the commanded velocity, cruise, and the mirror
// image down to rest at the target. Phases may be missing (the "deformed S", GT L909-912): MAcc not reached,
// velocity not reached. The profile is symmetric and time-optimal for the limits (bang-bang in jerk). Only
// the target position may change during motion (GT L909, GE L1179-1183): plan_s_curve() replans from any
// moving state, with the move's own limits, time-optimally (M2, MO1-MO3); a new target behind the braking
// point decelerates to zero and reverses (M3).
//
// Replanning (MO1), in the frame where the move after the change goes towards + (the sign s of target minus the
// stopping point): jerk +J from a0 to a1 (t1 = (a1 - a0)/J), a hold at a1 = A (t2), jerk -J from a1 through the
// peak velocity vpk (where a = 0; a cruise at V there if the distance asks for it) down to a3 >= -A, a hold at
// -A (t4), jerk +J to rest: at most 7 phases. With a1 < 0 (the axis was braking, a0 < 0) a never returns to 0
// before the end and vpk = v0 + (2 a1^2 - a0^2)/(2J) + a1 t2 is virtual. The members form one family in
// u = a1 (u <= A) or u = A + J t2 whose distance grows with u, from the time-optimal stop (u = a0, or vpk = 0)
// to vpk = V; the u that covers the distance is found by Illinois regula falsi (~5 evaluations of the closed
// form distance). Duration equals Ruckig's within 1e-13 relative on 20,000 seeded random states (test).
// Internal units: pulse, pulse/tick, pulse/tick^2, pulse/tick^3.
#pragma once

#include <cstddef>

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// Limits of a jerk-limited profile, all > 0: pulse/tick, pulse/tick^2, pulse/tick^3.
struct SCurveLimits {
  double vel = 0.0;
  double acc = 0.0;
  double jerk = 0.0;
  void validate() const;
};

// Rest at `start_pos` to rest at `target` (pulse), time-optimal, closed form.
Profile plan_s_curve_rest_to_rest(double start_pos, double target, const SCurveLimits& lim);

// Any state to rest at `target` (pulse), time-optimal (see above) from a state the limits reach (|acc| <=
// lim.acc, |vel + acc*|acc|/(2 jerk)| <= lim.vel: every state of a profile planned with these limits).
// Otherwise a brake pre-phase (MO2) first brings the state inside at full jerk. Rest-to-rest calls the
// closed form. Inputs are not checked here (the generator's are); see check_replan_input.
Profile plan_s_curve(const MotionState& from, double target, const SCurveLimits& lim);

// ValueError-style checks for plan_s_curve's inputs: limits > 0 and finite, state and target finite.
void check_replan_input(const MotionState& from, double target, const SCurveLimits& lim);

// Plans n replans (state pos/vel/acc[i] -> rest at target[i], limits vmax/amax/jmax[i], units as above) and
// writes each duration (ticks) to duration[i]. The replan benchmark's batch entry point.
void plan_s_curve_replan_batch(std::size_t n, const double* pos, const double* vel, const double* acc,
                               const double* target, const double* vmax, const double* amax, const double* jmax,
                               double* duration);

// Minimal rest-to-rest duration (ticks) of a move of `distance` pulse (closed form, no profile built).
double s_curve_min_time(double distance, const SCurveLimits& lim);

// Plans n rest-to-rest moves (start[i] -> target[i], limits vel/acc/jerk[i]) and writes each duration (ticks)
// to duration[i]. The benchmark's batch entry point: builds every profile in full.
void plan_s_curve_batch(std::size_t n, const double* start, const double* target, const double* vel,
                        const double* acc, const double* jerk, double* duration);

// GT_PrflS parameters in the GT units (per sample time ST = the tick): GT L854-858, L4852, L4936.
struct GtSCurveParams {
  double pos = 0.0;   // target, whole pulses, -2^30..2^30-1 (L854)
  double vel = 0.0;   // pulse/ST, 0 < vel <= 16384 (L858)
  double macc = 0.0;  // pulse/ST^2, 0 < macc < 0.5 (L857)
  double jerk = 0.0;  // pulse/ST^3, 0 < jerk < 0.5 (L856)
  void validate() const;
  SCurveLimits limits() const { return {vel, macc, jerk}; }
};

// GE / GUC-ECAT / iDEABOX GT_PrflS parameters in pulse/ms units (GE Table 5-4, L1095-1101).
struct GeSCurveParams {
  double pos = 0.0;   // target, whole pulses, -2^30..2^30-1
  double vel = 0.0;   // pulse/ms, 0 < vel <= 40957
  double macc = 0.0;  // pulse/ms^2, 0 < macc <= 102400
  double jerk = 0.0;  // pulse/ms^3, 0 < jerk <= 256000
  void validate() const;
  // Limits per tick of `period_s` seconds.
  SCurveLimits limits(double period_s) const;
};

}  // namespace servobench::motion
