// S-curve (jerk-limited, 7-phase) point-to-point profile: GT_PrflS (GT L839-912) and GE GT_PrflS (GE L1081-1188).
//
// Phases: jerk +J up to MAcc, hold MAcc, jerk -J down to 0 at the commanded velocity, cruise, and the mirror
// image down to rest at the target. Phases may be missing (the "deformed S", GT L909-912): MAcc not reached,
// velocity not reached. The profile is symmetric and time-optimal for the limits (bang-bang in jerk). Only
// the target position may change during motion (GT L909, GE L1179-1183): plan_s_curve() replans from any
// moving state; a new target behind the braking point decelerates to zero and reverses.
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

// Any state (|vel| may exceed lim.vel only by the caller's choice; |acc| <= lim.acc) to rest at `target`.
// Rest-to-rest calls the closed form; otherwise the peak velocity is found by bisection on the distance.
Profile plan_s_curve(const MotionState& from, double target, const SCurveLimits& lim);

// Minimal rest-to-rest duration (ticks) of a move of `distance` pulse (closed form, no profile built).
double s_curve_min_time(double distance, const SCurveLimits& lim);

// Plans n rest-to-rest moves (start[i] -> target[i], limits vel/acc/jerk[i]) and writes each duration (ticks)
// to duration[i]. The benchmark's batch entry point: builds every profile in full.
void plan_s_curve_batch(std::size_t n, const double* start, const double* target, const double* vel,
                        const double* acc, const double* jerk, double* duration);

// Plans n moves from a moving state (pos0, vel0, acc0 [i], pulse, pulse/tick, pulse/tick^2) to rest at target[i]
// with plan_s_curve and writes each duration (ticks): the benchmark's entry point for the general problem, the
// one Ruckig solves (issue 22 point 5).
void plan_s_curve_from_state_batch(std::size_t n, const double* pos0, const double* vel0, const double* acc0,
                                   const double* target, const double* vel, const double* acc, const double* jerk,
                                   double* duration);

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
