// ApsOutputs: the ADLINK PCI-8254/8258 board outputs as a card module: the digital outputs DO0..7
// (APS_write_d_output / APS_read_d_output of the APS library), the board parameters (APS_set_board_param,
// PRS_EMG_LOGIC L1623, PRB_PWMx_MAP_DO Table 4-4 L3527-3533) and the VAO tables (velocity -> PWM power,
// APS_set_vao_param / APS_set_vao_table / APS_switch_vao_table / APS_start_vao, L3436-3542). Decisions AF17-AF21;
// session 11: AV9.
//
// Units: VAO speeds in pulse/s (the composite command speed of the table's VAO_TABLE_SRC axes), powers in the
// output type's unit (type 1: PWM duty in 0.05 %, 0..2000; types 2-3: frequency in Hz, 3..50e6; L3489-3495),
// the PWM configuration per type (1: Hz 3..50e6; 2: ns 20..335544320; 3: duty x 0.05 % 1..2000; L3462-3474).
// Every function returns the APS code and never throws (vao_output throws std::invalid_argument for ctrl).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

// What PWM output ctrl (0..1) gives now (the simulation helper vao_output).
struct VaoOutput {
  bool on = false;       // APS_start_vao, not switched off, its PRB_PWMx_MAP_DO output in the enabling state
  int table = 0;         // the controller's VAO table
  double speed = 0.0;    // composite command speed of the table's source axes, pulse/s
  double power = 0.0;    // interpolated between the table's points, held outside them; 0 when off
  std::string unit;      // "0.05 %" (duty) or "Hz"
};

class ApsOutputs : public machine::CardHooks {
 public:
  explicit ApsOutputs(machine::Card& card) : card_(card) { power_on(); }

  // APS_initial: outputs off, PRB_PWMx_MAP_DO -1 (no mapping), VAO tables empty, type 1 / input 0 / config 100 /
  // source axis 0 for every table, both controllers on table 0 and off.
  void power_on();

  // -- digital outputs (group 0: DO0..7 as bits) ----------------------------------------------------------------
  AdlinkCode write_do(double group, double data);
  AdlinkCode read_do(double group, int& data) const;
  void set_do_bit(int channel, bool on);   // a point table's instruction command (APS_pt_ext_set_do_ch)
  void all_do_off() { do_word_ = 0; }      // the watchdog's WDT_ACTION_DO_OFF

  // -- board parameters -----------------------------------------------------------------------------------------
  // PRB_PWMx_MAP_DO (110h-113h): -1 or bits 0-7 the DO channel (0..7), bit 8 the logic; PRS_EMG_LOGIC (00h): 0 only
  // (1: FunctionNotAvailable, AF17).
  AdlinkCode set_board_param(double para, double value);
  AdlinkCode board_param(double para, int& value) const;

  // -- VAO --------------------------------------------------------------------------------------------------------
  AdlinkCode set_vao_param(double para, double value);
  // Table 0..7 of count 1..32 points: point k at min_velocity + k x interval pulse/s with powers[k].
  AdlinkCode set_vao_table(double table, double min_velocity, double interval, double count,
                           const std::vector<double>& powers);
  AdlinkCode switch_vao_table(double table);    // controller 0 (AF21)
  void select_vao(int ctrl, int table);          // APS_pt_ext_set_table_no's instruction command
  AdlinkCode start_vao(double channel, double enable);
  void all_pwm_off() { on_ = {false, false}; }   // the watchdog's WDT_ACTION_PWM_OFF
  VaoOutput vao_output(int ctrl) const;

 private:
  struct Table {
    bool set = false;
    double vmin = 0, interval = 1;
    std::vector<double> powers;
  };
  int output_type(int table) const { return vao_[static_cast<std::size_t>(2 * table)]; }
  int input_type(int table) const { return vao_[static_cast<std::size_t>(2 * table + 1)]; }

  machine::Card& card_;
  int do_word_ = 0;
  int emg_logic_ = 0;
  std::array<int, 4> pwm_map_{};        // PRB_PWM0..3_MAP_DO
  std::array<int, 0x28> vao_{};         // VAO parameters 00h-27h (types, configs, sources)
  std::array<Table, 8> tables_{};
  std::array<int, 2> table_of_{};       // active table of VAO controllers 0..1
  std::array<bool, 2> on_{};
};

// The card's ADLINK output module, created and attached on first use (owned by the card).
ApsOutputs& aps_outputs(machine::Card& card);

}  // namespace servobench::vendor::adlink
