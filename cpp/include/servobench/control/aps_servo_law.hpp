// ADLINK PCI-8254/8258 (APS) servo law: PID + velocity/acceleration feed-forward with gain shifts,
// exactly as printed in the ADLINK manual (seed 004 L1723-1731, parameter table L1746-1762; adlink.md §2).
//
//   E(k)      = CmdPos(k) - FbkPos(k)                          (pulse)
//   CmdVel(k) = CmdPos(k) - CmdPos(k-1),  CmdAcc(k) = CmdVel(k) - CmdVel(k-1)
//   Sum(k)    = clamp(Sum(k-1) + E(k), +-INTEGRAL_LIMIT)
//   U(k) = 2^PID_SHIFT * ( KP*2^KP_SHIFT*E + KI*2^KI_SHIFT*Sum + KD*2^KD_SHIFT*(E(k)-E(k-1))
//                        + KVFF*2^KVFF_SHIFT*CmdVel + KAFF*2^KAFF_SHIFT*CmdAcc )
//
// The effective gain of a term is K * 2^(K_SHIFT + PID_SHIFT): the manual's worked example (L1733) reads
// "100 x 2^2 x 3 = 3200", which only holds as 100 x 2^2 x 2^3 (docs/decisions.md). U is in DAC counts; after the
// two biquads the output stage turns counts into volts (32767 counts = 10 V), adds V_BIAS, clamps to
// +-V_LIMIT and inverts if V_INVERSE.
#pragma once

#include <cmath>

#include "servobench/control/law_terms.hpp"

namespace servobench::control {

struct ApsServoLawParams {
  double kp = 0;      // PRA_KP_GAIN (90h), 0..65535
  double ki = 0;      // PRA_KI_GAIN (91h), 0..65535
  double kd = 0;      // PRA_KD_GAIN (92h), 0..65535
  double kvff = 0;    // PRA_KVFF_GAIN (93h), 0..65535
  double kaff = 0;    // PRA_KAFF_GAIN (9Ah), 0..65535
  double kp_shift = -5;     // PRA_KP_SHIFT (9Bh), -31..31
  double ki_shift = -15;    // PRA_KI_SHIFT (9Ch), -31..31
  double kd_shift = 0;      // PRA_KD_SHIFT (9Dh), -31..31
  double kvff_shift = 0;    // PRA_KVFF_SHIFT (9Eh), -31..31
  double kaff_shift = 0;    // PRA_KAFF_SHIFT (9Fh), -31..31
  double pid_shift = -5;    // PRA_PID_SHIFT (A0h), -31..31, scales every term
  double integral_limit = 2147483647.0;  // PRA_INTEGRAL_LIMIT (12Bh): |Sum| <= limit, pulse*tick, 0..2147483647
  double v_bias = 0.0;   // PRA_SERVO_V_BIAS (120h), V, 0..10
  double v_limit = 10.0; // PRA_SERVO_V_LIMIT (123h), V, 0..10
  bool v_inverse = false;  // PRA_SERVO_V_INVERSE (125h)

  // Servo period range and default (Setup Wizard, L1733).
  static constexpr double kMinPeriodS = 50e-6;
  static constexpr double kMaxPeriodS = 2000e-6;
  static constexpr double kDefaultPeriodS = 250e-6;

  void validate() const;

  // Effective per-tick gains K * 2^(K_SHIFT + PID_SHIFT), counts per pulse (or per pulse/tick, pulse/tick^2).
  double kp_eff() const { return std::ldexp(kp, static_cast<int>(kp_shift + pid_shift)); }
  double ki_eff() const { return std::ldexp(ki, static_cast<int>(ki_shift + pid_shift)); }
  double kd_eff() const { return std::ldexp(kd, static_cast<int>(kd_shift + pid_shift)); }
  double kvff_eff() const { return std::ldexp(kvff, static_cast<int>(kvff_shift + pid_shift)); }
  double kaff_eff() const { return std::ldexp(kaff, static_cast<int>(kaff_shift + pid_shift)); }
};

class ApsServoLaw {
 public:
  explicit ApsServoLaw(const ApsServoLawParams& params = {});

  const ApsServoLawParams& params() const { return params_; }
  // Replaces the parameters; the error sum and the previous error/command are kept (sum re-clamped next tick).
  void set_params(const ApsServoLawParams& params);
  // Power-on state: sum, E(k-1) cleared; the command history is taken from the next command (at rest).
  void reset();

  // One servo tick. The law computes CmdVel and CmdAcc from the command history itself, as the manual
  // defines them; the profile's velocity/acceleration arguments are ignored by this law.
  // Always inlined into the fused tick's kernels (TK3).
  __attribute__((always_inline)) LawTerms step(double cmd_pos, double fbk_pos, double /*profile_vel*/,
                                               double /*profile_acc*/) {
    if (!primed_) {
      prev_cmd_ = cmd_pos;
      prev_vel_ = 0.0;
      primed_ = true;
    }
    const double error = cmd_pos - fbk_pos;
    const double vel = cmd_pos - prev_cmd_;
    const double acc = vel - prev_vel_;
    const double lim = params_.integral_limit;
    double sum = sum_ + error;
    sum = sum > lim ? lim : (sum < -lim ? -lim : sum);
    sum_ = sum;
    LawTerms t;
    t.p = kp_ * error;
    t.i = ki_ * sum;
    t.d = kd_ * (error - prev_error_);
    t.vff = kvff_ * vel;
    t.aff = kaff_ * acc;
    t.total = t.p + t.i + t.d + t.vff + t.aff;
    t.vel = vel;
    t.acc = acc;
    prev_error_ = error;
    prev_cmd_ = cmd_pos;
    prev_vel_ = vel;
    return t;
  }

  // Output stage after the biquads: counts -> V (32767 counts = 10 V), + V_BIAS, clamp +-V_LIMIT, inverse.
  double counts_to_volts(double counts) const {
    double v = counts * (10.0 / 32767.0) + params_.v_bias;
    const double lim = params_.v_limit;
    v = v > lim ? lim : (v < -lim ? -lim : v);
    return params_.v_inverse ? -v : v;
  }

  // The largest |counts_to_volts(U)| of any output U: the output stage clamps to V_LIMIT, V.
  double max_volts() const { return params_.v_limit; }

  double error_sum() const { return sum_; }  // PID_ERR_POS_SUM_COUNT (pulse*tick)
  double previous_error() const { return prev_error_; }

 private:
  void cache_gains();
  ApsServoLawParams params_;
  double kp_ = 0, ki_ = 0, kd_ = 0, kvff_ = 0, kaff_ = 0;
  double sum_ = 0.0;
  double prev_error_ = 0.0;
  double prev_cmd_ = 0.0;
  double prev_vel_ = 0.0;
  bool primed_ = false;
};

}  // namespace servobench::control
