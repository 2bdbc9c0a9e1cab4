// ADLINK PCI-8254/8258 velocity profiles (ADLINK L2176-2244, PTP L2712-2767, velocity move L2560-2635).
//
// T-curve (S = 0) or S-curve with S-factor S = t1/(t1+t2) (0 <= S <= 1, L2211-2219; "t1 = t2" read as
// t1 = t3, decision M8). ACC is the peak acceleration: a velocity change dV takes t1 = t3 = S*dV/ACC (jerk
// phases) and t2 = (1-S)*dV/ACC (constant ACC), so its jerk is ACC^2/(S*dV). Moves start at VS (a step),
// ramp at ACC to VM, cruise, ramp at DEC to VE and end there (a step to rest). Short moves keep ACC, DEC and
// S and lower the peak to VM' (L2191-2197, L2223):
//   VM'^2 = (2*ACC*DEC*D/(1+S) + DEC*VS^2 + ACC*VE^2) / (ACC + DEC),
// so the jerk changes with the distance. Internal units: pulse, pulse/tick, pulse/tick^2.
#pragma once

#include "servobench/motion/profile.hpp"

namespace servobench::motion {

// ADLINK profile parameters per tick (see AdlinkPtpParams for the manual's per-second units).
struct AdlinkLimits {
  double vs = 0.0;   // start velocity, pulse/tick, 0 <= vs <= vm
  double vm = 0.0;   // maximum velocity, pulse/tick, > 0
  double ve = 0.0;   // end velocity, pulse/tick, 0 <= ve <= vm
  double acc = 0.0;  // peak acceleration, pulse/tick^2, > 0
  double dec = 0.0;  // peak deceleration, pulse/tick^2, > 0
  double sf = 0.0;   // S-factor 0..1
};

// Point to point from rest at start_pos to target (pulse). Throws std::invalid_argument if the move is
// shorter than the VS -> VE ramp needs (decision M9).
Profile plan_adlink_ptp(double start_pos, double target, const AdlinkLimits& lim);

// Velocity move (APS_vel) from any state to the signed velocity `vel` (pulse/tick): ramps at ACC when the
// speed grows, at DEC when it falls, S-factor shaped, then holds it (open-ended profile).
Profile plan_adlink_velocity(const MotionState& from, double vel, const AdlinkLimits& lim);

// APS_stop_move: decelerate to rest at PRA_SD_DEC `sd_dec` (pulse/tick^2) with the S-factor `sf`.
Profile plan_adlink_stop(const MotionState& from, double sd_dec, double sf);

// The jerk (pulse/tick^3) of an S-factor ramp of dV at peak acceleration acc; +inf for S = 0 (T ramp).
double adlink_ramp_jerk(double dv, double acc, double sf);

// APS_ptp_all / APS_vel parameters in the manual's units (pulse/s, pulse/s^2; UF = 1): PRA_VS 23h, PRA_VM 24h,
// PRA_VE 25h, PRA_ACC 21h, PRA_DEC 22h, PRA_SF 20h, PRA_SD_DEC 07h (L2744-2751).
struct AdlinkPtpParams {
  double pos = 0.0;     // target, pulse, |pos| <= 2^31-1
  double vs = 0.0;      // pulse/s, 0 <= vs <= vm
  double vm = 0.0;      // pulse/s, 0 < vm <= 1e9
  double ve = 0.0;      // pulse/s, 0 <= ve <= vm
  double acc = 0.0;     // pulse/s^2, 0 < acc <= 1e12
  double dec = 0.0;     // pulse/s^2, 0 < dec <= 1e12
  double sf = 0.0;      // 0..1
  double sd_dec = 0.0;  // stop_move deceleration, pulse/s^2, 0 (= use dec) .. 1e12
  void validate() const;
  AdlinkLimits limits(double period_s) const;
  double sd_dec_per_tick(double period_s) const;
};

}  // namespace servobench::motion
