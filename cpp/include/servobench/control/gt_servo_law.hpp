// Googol GT series servo filter: PID + Kvff + Kaff + bias, exactly as printed in the GT manual
// (seed 000 L801-803, parameter Table 3-4 L784-793, output scale L829; digest gt.md §2).
//
//   E_n = P_target,n - P_actual,n                                    (pulse)
//   U_n = Kp*E_n + Kd*(E_n - E_{n-1}) + Ki*(Sum E)/256 + Kvff*V_target + Kaff*A_target + B
//
// Sum E includes E_n and is clamped to +-ILmt; ILmt = 0 clears it (the manual's bumpless Ki recipe, L819).
// U is clamped to +-MtrLmt; +-32767 counts <-> +-10 V (L829). Units: E pulse, V_target pulse/ST,
// A_target pulse/ST^2, U DAC counts. The gains are per servo tick: changing the sample time changes the loop.
#pragma once

#include <cmath>

#include "servobench/control/law_terms.hpp"

namespace servobench::control {

struct GtServoLawParams {
  double kp = 0;        // proportional gain, counts/pulse, 0..32767 (GT Table 3-4)
  double ki = 0;        // integral gain, the term is Ki*SumE/256, 0..32767
  double kd = 0;        // derivative gain on (E_n - E_{n-1}), 0..32767
  double kvff = 0;      // velocity feed-forward gain on V_target (pulse/ST), 0..32767
  double kaff = 0;      // acceleration feed-forward gain on A_target (pulse/ST^2), 0..32767
  double ilmt = 32767;  // integral limit: |SumE| <= ILmt (pulse*tick); 0 clears the sum; 0..32767
  double bias = 0;      // motor bias B, counts, -32768..32767 (closed loop only)
  double mtr_lmt = 32767;  // output saturation |U| <= MtrLmt, counts, 0..32767
  // GE series (seed 001 L5530-5620): the five gains are doubles in [0, 32767], not integers (decision V87).
  bool fractional_gains = false;

  // Servo sample time range and default of the GT cards (GT_SetSmplTm, L578-580, L5030-5036).
  static constexpr double kMinPeriodS = 48e-6;
  static constexpr double kMaxPeriodS = 1966.08e-6;
  static constexpr double kDefaultPeriodS = 200e-6;

  // Throws std::invalid_argument naming the field and its range.
  void validate() const;
};

class GtServoLaw {
 public:
  explicit GtServoLaw(const GtServoLawParams& params = {});

  const GtServoLawParams& params() const { return params_; }
  // Replaces the active parameters (the card's Update). The error sum and E_{n-1} are kept, except that
  // ILmt = 0 clears the sum and a smaller ILmt clamps it at the next tick, as on the card.
  void set_params(const GtServoLawParams& params);
  // Clears the error sum and the previous error (power-on state).
  void reset();

  // One servo tick. cmd_pos = P_target, fbk_pos = P_actual (pulse), vel = V_target (pulse/ST),
  // acc = A_target (pulse/ST^2): the profile's own velocity and acceleration, as the card feeds them (L776).
  // Always inlined: the fused tick's kernels carry a target attribute, across which GCC with LTO did not inline it
  // (decision TK3).
  __attribute__((always_inline)) LawTerms step(double cmd_pos, double fbk_pos, double vel, double acc) {
    const double error = cmd_pos - fbk_pos;
    const double lim = params_.ilmt;
    double sum = sum_ + error;
    sum = sum > lim ? lim : (sum < -lim ? -lim : sum);
    sum_ = sum;
    LawTerms t;
    t.p = params_.kp * error;
    // Ki*SumE/256 as (Ki/256)*SumE: one rounding fewer on the tick's path and the same double, since scaling by
    // 2^-8 is exact and commutes with rounding while the result is normal; below 2^-1021 (and where Ki/256 is not
    // exact: ki_256_ is NaN then) the written-out form is taken (decision FV26).
    double i = ki_256_ * sum;
    if (__builtin_expect(!(std::fabs(i) >= 0x1p-1021), 0)) i = params_.ki * sum * (1.0 / 256.0);
    t.i = i;
    t.d = params_.kd * (error - prev_error_);
    t.vff = params_.kvff * vel;
    t.aff = params_.kaff * acc;
    t.bias = params_.bias;
    const double u = t.p + t.i + t.d + t.vff + t.aff + t.bias;
    const double m = params_.mtr_lmt;
    t.total = u > m ? m : (u < -m ? -m : u);
    t.vel = vel;
    t.acc = acc;
    prev_error_ = error;
    return t;
  }

  // Converts the (filtered) controller output in counts to the commanded voltage: 32767 counts = 10 V.
  static double counts_to_volts(double counts) { return counts * (10.0 / 32767.0); }
  // The largest |counts_to_volts(U)| of an unfiltered output U (|U| <= MtrLmt), V.
  double max_volts() const { return counts_to_volts(params_.mtr_lmt); }

  double error_sum() const { return sum_; }        // the accumulator GT_GetIntgr reads (pulse*tick)
  double previous_error() const { return prev_error_; }

 private:
  GtServoLawParams params_;
  double ki_256_ = 0.0;  // Ki/256 if exact, else NaN (see step)
  double sum_ = 0.0;
  double prev_error_ = 0.0;
};

}  // namespace servobench::control
