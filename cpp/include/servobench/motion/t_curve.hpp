// T-curve (trapezoidal velocity) point-to-point profile: GT_PrflT (GT L914-978) and GE GT_PrflT (GE L978-1079).
//
// Accelerate at Acc to Vel, cruise, decelerate at the same Acc to rest at the target; no cruise for short
// moves (a triangle). Velocity and target may change during motion (GT L974-978, GE L1067-1071): from any
// moving state plan_t_curve() accelerates or decelerates to the (new) velocity, and a target behind the
// braking point decelerates to zero and reverses. Internal units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// Limits of a trapezoidal profile, both > 0: pulse/tick, pulse/tick^2 (one value for acc and dec).
struct TCurveLimits {
  double vel = 0.0;
  double acc = 0.0;
  void validate() const;
};

// Any state (vel; acc is ignored, a T-curve's acceleration steps) to rest at `target` (pulse), time-optimal.
Profile plan_t_curve(const MotionState& from, double target, const TCurveLimits& lim);

// Minimal rest-to-rest duration (ticks) of a move of `distance` pulse (closed form).
double t_curve_min_time(double distance, const TCurveLimits& lim);

// GT_PrflT parameters, per sample time (the tick): GT L929-930, L854.
struct GtTCurveParams {
  double pos = 0.0;  // target, whole pulses, -2^30..2^30-1 (L854)
  double vel = 0.0;  // pulse/ST, 0 < vel <= 16384 (L930)
  double acc = 0.0;  // pulse/ST^2, 0 < acc <= 16384 (L929)
  void validate() const;
  TCurveLimits limits() const { return {vel, acc}; }
};

// GE / GUC-ECAT / iDEABOX GT_PrflT parameters in pulse/ms units (GE Table 5-2, L991-996).
struct GeTCurveParams {
  double pos = 0.0;  // target, whole pulses, -2^30..2^30-1
  double vel = 0.0;  // pulse/ms, 0 < vel <= 40957
  double acc = 0.0;  // pulse/ms^2, 0 < acc <= 102400
  void validate() const;
  TCurveLimits limits(double period_s) const;
};

}  // namespace servobench::motion
