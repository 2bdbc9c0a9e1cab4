// ADLINK jog (APS_jog_on, ADLINK L2639-2710; digest adlink.md §6.5), driven by the software JOG-ON signal.
//
// Continuous mode (PRA_JG_MODE 0): a rising edge of JOG-ON starts a velocity move at JG_VM in direction
// JG_DIR; a falling edge decelerates to rest (L2645). Step mode (1): a rising edge moves JG_OFFSET and stops;
// after JG_DELAY, if JOG-ON is still on, the axis moves continuously until it goes off, and the total
// displacement is then rounded up to a whole multiple of JG_OFFSET (L2657; test vector T36: final
// displacement = ceil(n) * offset). The rounding: when JOG-ON falls, the stop point of a plain deceleration is
// computed and the move ends instead, by an on-the-fly PTP change, at the next multiple of the offset at or
// beyond it (decision M43); if JOG-ON falls during an S-factor ramp the decision waits for the ramp to end.
// A rising edge while the previous jog is still running is ignored. Units: pulse, pulse/s, pulse/s^2, us.
#pragma once

#include "servobench/motion/generator.hpp"

namespace servobench::motion {

struct AdlinkJogParams {
  double mode = 0;       // PRA_JG_MODE 40h: 0 continuous, 1 step
  double dir = 1;        // PRA_JG_DIR 41h: 0 negative, 1 positive
  double sf = 0;         // PRA_JG_SF 42h: S-factor 0..1
  double acc = 1e6;      // PRA_JG_ACC 43h: pulse/s^2, 0 < acc <= 1e12
  double dec = 1e6;      // PRA_JG_DEC 44h: pulse/s^2, 0 < dec <= 1e12
  double vm = 1e5;       // PRA_JG_VM 45h: pulse/s, 0 < vm <= 1e9
  double offset = 1000;  // PRA_JG_OFFSET 46h: step, pulse, 0 < offset <= 2^31-1 (step mode)
  double delay_us = 0;   // PRA_JG_DELAY 47h: us, 0..10,000,000 (step mode)
  void validate() const;
};

enum class JogPhase { Idle, Moving, Step, Delay, Continuous, Rounding };
const char* to_string(JogPhase phase);

class AdlinkJog {
 public:
  AdlinkJog(const AdlinkJogParams& p, double period_s);
  // One tick with the present JOG-ON level; commands the generator.
  void step(bool jog_on, ProfileGenerator& gen);
  JogPhase phase() const { return phase_; }
  // Position (pulse) where the present jog started.
  double origin() const { return origin_; }
  const AdlinkJogParams& params() const { return p_; }

 private:
  void round_up_and_stop(ProfileGenerator& gen);
  AdlinkJogParams p_;
  AdlinkLimits lim_{};  // per tick
  double s_ = 1.0;
  long long delay_ticks_ = 0, waited_ = 0;
  JogPhase phase_ = JogPhase::Idle;
  bool prev_on_ = false;
  double origin_ = 0.0;
};

}  // namespace servobench::motion
