// GeRegisters: the GE card's registers that the neutral kernel has no field for, as a card module (GE manual seed
// 001; digest ge.md §7.2, §7.8, §10; decisions V93-V95, GF7, GV6). Per axis: the output type (GT_CtrlMode, 0 analog
// / 1 pulse, L3907-3925), the pulse form (GT_StepDir / GT_StepPulse, L5805, L5840) and the encoder input
// (GT_EncOn / GT_EncOff, L3982-4000). Per card: the sense words (GT_LmtSns L4897-4907 -- applied to the kernel's
// limit polarity --, GT_HomeSns L4809-4837, GT_IndexSns L4869-4877, GT_EncSns L4025-4035), the simulated levels of
// the general inputs EXI0..15 (GT_ExInpt, L4074), the A/D channels converted (GT_SetAdcChn, L5447-5455) and the
// values the program wrote with GT_SetVel / SetAcc / SetMAcc / SetJerk in the GE's units (pulse/ms, pulse/ms^2,
// pulse/ms^3), so a Get returns them exactly while the staged per-tick value is the one they made.
//
// Axis numbers are the manual's, 1..axes (a bad one records IllegalControlParam and returns 7). Every command
// returns the GeCode of Table 2-1/2-2 and never throws; a refusal records the card's fault (axis status bit 7,
// GT_GetCmdSts) and leaves the registers unchanged. reset() (GT_Reset) returns the power-on values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/googol/ge_watch.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

struct GeAxisRegisters {
  int ctrl_mode = 0;        // GT_CtrlMode: 0 analog (default, L3915), 1 pulse
  bool step_pulse = false;  // GT_StepPulse (true) / GT_StepDir (false, default L701)
  bool encoder_on = true;   // GT_EncOn (default) / GT_EncOff: GT_GetAtlPos reads the profile position (L4180)
};

enum class GeSense { Limit = 0, Home = 1, Index = 2, Encoder = 3 };

// A motion register written in GE units: its exponent of ms in the unit (vel 1, acc / macc 2, jerk 3).
enum class GeMotionRegister { Vel = 1, Acc = 2, MAcc = 3, Jerk = 4 };

class GeRegisters : public machine::CardHooks {
 public:
  explicit GeRegisters(machine::Card& card);

  // The manual's axis number 1..axes as a card axis, or none after recording IllegalControlParam (return 7).
  std::optional<std::size_t> axis(double number);
  const GeAxisRegisters& at(std::size_t a) const { return axes_.at(a); }

  // Sense words: LmtSns sets the kernel's limit polarity (bit 2k positive, 2k+1 negative of axis k+1; 1 = low
  // level triggers, Table 3-3 L516-520); HomeSns / IndexSns / EncSns accept 0 bits for the card's axes (the
  // simulated wiring) and return 1 (not simulated, V93) for a set one.
  GeCode set_sense(GeSense which, double word);
  std::uint32_t sense(GeSense which) const { return sense_[static_cast<int>(which)]; }
  // EncOn / EncOff: with the servo off only (SX cmd bit 3).
  GeCode set_encoder(double axis, bool on);
  // CtrlMode: with the servo off (cmd bit 6); the simulated output is the axis's drive (a StepperDrive or
  // ServoPositionDrive takes pulses), so a mode that does not match it returns 1 (not simulated, V94).
  GeCode set_ctrl_mode(double axis, double mode);
  // StepDir / StepPulse: on a pulse axis only (cmd bit 6); recorded (the simulated drive counts pulses, V94).
  GeCode set_step_form(double axis, bool pulse);
  // A servo-law command on a pulse axis is refused (SX cmd bit 6, L333): records the fault; true if refused.
  bool refuse_on_pulse_axis(std::size_t a);

  // Input levels of every axis: GT_GetLmtSwt bit 2k Limit k+ (axis k+1), 2k+1 Limit k-, 1 = high = the switch is
  // hit with the default normally-closed wiring whatever LmtSns says (L2448-2456, L4510-4552); GT_GetHomeSwt bit
  // k = the axis is inside its home switch (V97, L2458-2460).
  std::uint32_t limit_levels() const;
  std::uint32_t home_levels();
  // GT_GetAtlVel: the encoder shaft's speed now in counts, pulse/ms (V96, L4203).
  double actual_vel(std::size_t a);

  // EXI0..EXI15 simulated levels (bit n = EXIn).
  void set_inputs(std::uint32_t word) { inputs_ = word & 0xFFFFu; }
  std::uint32_t inputs() const { return inputs_; }
  // GT_SetAdcChn 1..8 (default 8, GF7): SX converts 770 Hz x 8 / channels (L2939-2943).
  GeCode set_adc_channels(double n);
  int adc_channels() const { return adc_channels_; }

  // GT_SetVel / SetAcc / SetMAcc / SetJerk: `value` in GE units becomes value * (ms per tick)^order per tick,
  // staged on the card; remembered so read_motion returns `value` while the staged register still holds it.
  void stage_motion(std::size_t a, GeMotionRegister r, double value, double ms_per_tick);
  double read_motion(std::size_t a, GeMotionRegister r, double ms_per_tick) const;

  // The data watch (ge_watch.hpp), reset with the registers.
  GeWatch& watch() { return watch_; }

  void reset() override;

 private:
  machine::Card& card_;
  GeWatch watch_;
  std::vector<GeAxisRegisters> axes_;
  std::uint32_t sense_[4] = {0, 0, 0, 0};
  std::uint32_t inputs_ = 0;
  int adc_channels_ = 8;
  std::map<std::pair<std::size_t, int>, std::pair<double, double>> written_;  // (axis, reg) -> (GE, per tick)
};

// The card's GE registers, created and attached on first use (owned by the card).
GeRegisters& ge_registers(machine::Card& card);

}  // namespace servobench::vendor::googol
