// GtCard: the GT series' (GT-400 / GT-800, GT manual seed 000, digest gt.md) registers that the neutral card kernel
// does not hold, as a card module (machine/card_hooks.hpp): the current axis (GT_Axis), the limit sense word
// (GT_LmtSns), the GT_Index choice per axis, the coordinated-motion list (gt_crd_list.hpp), the interrupt
// registers and their request / service machine (gt_interrupts.hpp), the system registers of the I/O commands
// (encoder sense, pulse form, A/D channels) and the two auxiliary encoders (gt_aux_encoder.hpp). Every GT command
// returns the manual's code (GtCode, Table 2-1 L393-408), never throws; the dialect
// (servobench.dialects.gt) is a table of one-line adapters over it.
//
// Units are the manual's, per sample time ST (= the card's servo tick): pulse, pulse/ST, pulse/ST^2. Axis
// numbers in the arguments are the manual's 1..4; the current axis is kept 0-based. One card, one module:
// a PC with several GT cards (GT_SwitchtoCardNo) has one GtCard per Card, so switching cards switches
// every register with it. Get it with gt(card) (created and attached on first use, owned by the card).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/googol/gt_aux_encoder.hpp"
#include "servobench/vendor/googol/gt_crd_list.hpp"
#include "servobench/vendor/googol/gt_interrupts.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// What a GT argument may be (the manual's ranges are checked by GtCard::check).
enum class GtArg { Integer, Real, RealHalfOpen };

// The registers of the I/O and system commands (GT ch3 L480-780, ch9, ch11; decisions GF4-GF7).
struct GtSystemRegs {
  int enc_sns = 0;                        // GT_EncSns: bits 0-3 axes, 4-5 auxiliary encoders (Table 11-2)
  std::array<bool, 4> step_pulse{};       // GT_StepPulse (true, CW/CCW) / GT_StepDir (false, the default)
  int adc_chn = 8;                        // GT_SetAdcChn: channels converted, 1..8 (default 8, GF7)
};

class GtCard final : public machine::CardHooks {
 public:
  explicit GtCard(machine::Card& card);

  machine::Card& card() { return card_; }
  const machine::Card& card() const { return card_; }

  // -- arguments (Table 2-1: 7 for a value out of the manual's range) -------------------------------------------
  // Success if `value` is finite, in lo..hi (hi excluded for RealHalfOpen) and whole for Integer; else the
  // fault (IllegalControlParam, MotionParamOverflow ...) is recorded on the current axis and 7 returned.
  GtCode check(double value, double lo, double hi, GtArg kind = GtArg::Integer,
               machine::CommandFault fault = machine::CommandFault::IllegalControlParam);
  // Runs a card command the GT way: 1 when the card refuses it (the cause recorded), 7 for a value the kernel
  // rejects, else 0.
  GtCode run(const std::function<void()>& command);
  // Records `fault` on the current axis (command status) and returns 1.
  GtCode refuse(machine::CommandFault fault);

  // -- current axis (GT_Axis L2825-2846; axis 1 after power-on, L754) -------------------------------------------
  GtCode select_axis(double num);          // num 1..4
  // GT_AxisI (L2850-2882): the interrupting axis becomes current; 1 (cmd bit 4) with no event interrupt pending.
  GtCode select_interrupting_axis();
  std::size_t axis() const { return axis_; }

  // -- limits (L4215-4272, L3915-3938) ----------------------------------------------------------------------------
  // GT_LmtSns: bit 2(k-1) axis k positive, 2(k-1)+1 negative; 1 = triggers on a low level. All axes at once.
  GtCode set_limit_sense(double sense);
  int limit_sense() const { return lmt_sns_; }
  // GT_GetLmtSwt: bit 2(k-1) axis k positive, 2(k-1)+1 negative; 1 = the switch is hit, whatever LmtSns says.
  int limit_switches() const;

  // -- homing (GT_Index L4188-4213, GT_Home L4152-4168, decision V24) ------------------------------------------
  GtCode set_index(double value);          // 0 home only (default), 1 home + index, for the current axis
  int index(std::size_t i) const;
  // Automatic homing of the current axis toward pos (pulse) at the staged T-curve Vel and Acc (1 if either is 0).
  GtCode home(double pos);

  // -- status ---------------------------------------------------------------------------------------------------
  // GT_GetCmdSts (Table 2-2, L455-478): the kernel's word, or bit 12/13/15 when a coordinated command failed last.
  std::uint16_t command_status() const;
  // GT_CaptProb (L3008-3049, V85): arms the probe on every axis whose capture register is free; 1 if none is.
  GtCode capture_probe();

  // -- encoders (GT_EncSns L595-635, L3267-3300; the auxiliary encoders L3124-3136, L3241-3330, L3727-3759,
  // L4733-4747; gt_aux_encoder.hpp) ----------------------------------------------------------------------------
  // GT_EncSns: 7 outside 0..0x3F; 1 (not simulated) when bits 0-3 do not correct the axes' wiring (in.reversed:
  // the simulated axis cannot run with positive feedback, GF5); else the auxiliary reads stay where they are.
  GtCode set_encoder_sense(double sense, const AuxInputs& in);
  // GT_EncPos / GT_EncVel: (0, pulse / pulse per ST) of auxiliary encoder num 1..2; (7, 0) for another number.
  std::pair<GtCode, long long> aux_position(double num, const AuxInputs& in);
  std::pair<GtCode, double> aux_velocity(double num, const AuxInputs& in);
  // GT_ClrEncPos: 0, or -1 ("failure", L3130) for a number other than 1, 2.
  GtCode clear_aux_position(double num, const AuxInputs& in);
  // GT_SetEncCapt / GT_GetEncSts (bit 3 = captured) / GT_GetEncCapt (pulse).
  GtCode arm_aux_capture(const AuxInputs& in);
  std::pair<GtCode, int> aux_capture_status(const AuxInputs& in) {
    return {GtCode::Success, aux_.scan(sys_.enc_sns, in).captured ? 0x8 : 0};
  }
  std::pair<GtCode, long long> aux_capture_value(const AuxInputs& in) {
    return {GtCode::Success, aux_.scan(sys_.enc_sns, in).value};
  }
  const GtAuxEncoders& aux() const { return aux_; }

  // -- the parts -------------------------------------------------------------------------------------------------
  GtCrdList& crd() { return crd_; }
  const GtCrdList& crd() const { return crd_; }
  GtInterrupts& interrupts() { return intr_; }
  const GtInterrupts& interrupts() const { return intr_; }
  GtSystemRegs& system() { return sys_; }
  const GtSystemRegs& system() const { return sys_; }

  // GT_Reset / HardRst (L4124-4142): LmtSns, Index, the coordinate list, the interrupts (all masked, L4765-4779)
  // and the system registers (encoder sense, pulse form, A/D channels) back to their defaults; the current axis,
  // the auxiliary encoders' zero and capture, the host's ISR and event stay. Then the card's own reset.
  GtCode hard_reset();

 private:
  machine::Card& card_;
  std::size_t axis_ = 0;
  int lmt_sns_ = 0;
  std::array<int, 4> index_{};
  GtCrdList crd_;
  GtInterrupts intr_;
  GtSystemRegs sys_{};
  GtAuxEncoders aux_;
};

// The card's GT module (created and attached on first use).
GtCard& gt(machine::Card& card);

}  // namespace servobench::vendor::googol
