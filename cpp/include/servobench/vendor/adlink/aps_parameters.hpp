// ApsParameters: the ADLINK PCI-8254/8258 axis parameter table (APS_set_axis_param[_f] / APS_get_axis_param[_f],
// PRA_* numbers of manual seed 004 L1614, L1746-1762, L2236-2278, L2677, L2744-2751, L3284-3346, L3994-4019) as a
// card module. Session 11: AV5.
//
// It stores the parameters the next commands read (the motion PRA_SF/ACC/DEC/VS/VM/VE/SD_DEC, the home PRA_HOME_*,
// the jog PRA_JG_*, the gear PRA_GEAR_* / PRA_GANTRY_PROTECT_*, PRA_EL_MODE) and writes the others through to
// where they act: the servo law (90h-A0h, 120h-12Bh: staged and updated, effective at the next tick), the limit
// inputs (PRA_EL_LOGIC, PRA_SPEL/SMEL_EN/POS: the card's LimitConfig), the AdlinkAxes module (PRA_EL_MODE,
// PRA_PRE/POST_EVENT_DIST, PRA_ERR_POS_LEVEL), an engaged gear's ratio (ramped at PRA_GEAR_ENGAGE_RATE, L3311).
// Units: pulse, pulse/s, pulse/s^2, ratio/s (engage rate), us (jog delay), V (servo bias / limit).
// Defaults (V27, V29, V48, V120): the manual's home example (L2295-2303): SD_DEC/ACC/DEC 1e6, VM 1e5, SF/VS/VE 0;
// home mode 0, dir 1, acc 1e6, vm 1e5, vo 5e4; jog mode 0, dir 1, acc/dec 1e6, vm 1e5, offset 1000, delay 0;
// gear master 0, rate 0, ratio 1. Every function returns the APS code and never throws.
#pragma once

#include <cstddef>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/motion/adlink_jog.hpp"
#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/home_sequence.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

// The PRA_* numbers (APS_define.h; manual lines in aps_constants.cpp, whose table the dialect's constants are
// written from).
namespace pra {
enum Number : int {
  EL_LOGIC = 0x00, EL_MODE = 0x02, SD_DEC = 0x07, SPEL_EN = 0x08, SMEL_EN = 0x09, SPEL_POS = 0x0A, SMEL_POS = 0x0B,
  HOME_MODE = 0x10, HOME_DIR = 0x11, HOME_CURVE = 0x12, HOME_ACC = 0x13, HOME_VM = 0x15, HOME_SHIFT = 0x17,
  HOME_EZA = 0x18, HOME_VO = 0x19, HOME_POS = 0x1B, SF = 0x20, ACC = 0x21, DEC = 0x22, VS = 0x23, VM = 0x24,
  VE = 0x25, PRE_EVENT_DIST = 0x2A, POST_EVENT_DIST = 0x2B, JG_MODE = 0x40, JG_DIR = 0x41, JG_SF = 0x42,
  JG_ACC = 0x43, JG_DEC = 0x44, JG_VM = 0x45, JG_OFFSET = 0x46, JG_DELAY = 0x47, GEAR_MASTER = 0x60,
  GEAR_ENGAGE_RATE = 0x61, GEAR_RATIO = 0x62, GANTRY_PROTECT_1 = 0x63, GANTRY_PROTECT_2 = 0x64,
  JG_MAP_DI_EN = 0x48, JG_P_JOG_DI = 0x49, JG_N_JOG_DI = 0x4A, JG_JOG_DI = 0x4B, KP_GAIN = 0x90, KI_GAIN = 0x91,
  KD_GAIN = 0x92, KVFF_GAIN = 0x93, KAFF_GAIN = 0x9A, KP_SHIFT = 0x9B, KI_SHIFT = 0x9C, KD_SHIFT = 0x9D,
  KVFF_SHIFT = 0x9E, KAFF_SHIFT = 0x9F, PID_SHIFT = 0xA0, SERVO_V_BIAS = 0x120, SERVO_V_LIMIT = 0x123,
  ERR_POS_LEVEL = 0x124, SERVO_V_INVERSE = 0x125, INTEGRAL_LIMIT = 0x12B,
};
}  // namespace pra

// The stored PRA_* parameters of one axis.
struct ApsAxisRegisters {
  motion::AdlinkPtpParams motion{0.0, 0.0, 1e5, 0.0, 1e6, 1e6, 0.0, 1e6};  // pos, vs, vm, ve, acc, dec, sf, sd_dec
  motion::AdlinkHomeParams home{};
  motion::AdlinkJogParams jog{};
  double gear_master = 0;   // PRA_GEAR_MASTER 60h: master axis, 0..7
  double gear_rate = 0;     // PRA_GEAR_ENGAGE_RATE 61h: ratio/s; 0 = at once (V120)
  double gear_ratio = 1;    // PRA_GEAR_RATIO 62h: slave pulse per master pulse
  double protect_1 = 0;     // PRA_GANTRY_PROTECT_1 63h, pulse (gantry not simulated, V122)
  double protect_2 = 0;     // PRA_GANTRY_PROTECT_2 64h, pulse
  int el_mode = 0;          // PRA_EL_MODE 02h: 0 immediate stop, 1 decelerate at PRA_SD_DEC (V28)
};

class ApsParameters : public machine::CardHooks {
 public:
  explicit ApsParameters(machine::Card& card);

  // Every axis back to the defaults (APS_initial).
  void power_on();
  // The stored parameters of axis i (0-based; throws std::invalid_argument for another index).
  const ApsAxisRegisters& axis(std::size_t i) const;

  // APS_set_axis_param_f(axis, para, value): ParametersInvalid for an unknown number or a value out of its
  // range; FunctionNotAvailable for a law parameter on an axis with another law, a gear master change while the
  // gear is engaged, a DI-linked jog (V30) or a refused card command.
  AdlinkCode set(std::size_t i, double para, double value);
  // APS_get_axis_param_f(axis, para, &value).
  AdlinkCode get(std::size_t i, double para, double& value) const;

 private:
  AdlinkCode set_gear(std::size_t i, int para, double v);
  machine::Card& card_;
  std::vector<ApsAxisRegisters> axes_;
};

// The card's ADLINK parameter table, created and attached on first use (owned by the card).
ApsParameters& aps_parameters(machine::Card& card);

// What a refused card command returns to an APS program: EMG, ALM or a limit toward the move: ignored,
// ERR_NoError (L3931-4010, V47); a move shorter than its ramps: ERR_DistantNotEnough (M9); any other refusal
// ERR_FunctionNotAvailable.
AdlinkCode code_of(machine::CommandFault fault);

}  // namespace servobench::vendor::adlink
