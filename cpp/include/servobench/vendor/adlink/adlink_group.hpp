// AdlinkGroup: the ADLINK PCI-8254/8258 interpolation (manual §4.8, seed 004 L2813-3150; digest adlink.md §6.7) as
// a CardGroup of the ADLINK vendor module (moved from machine/ in session 11, decision AV1): a
// motion::AdlinkInterpolator over an axis array of the card (the first axis the reference axis, whose
// PRA_VS/VM/VE/ACC/DEC/SF/SD_DEC define the vector profile), stepped once per motion cycle of the card, positions
// in pulse. The card hosts it in group slot kAdlinkGroupSlot (3); the APS dialect (servobench.dialects.aps:
// APS_line, APS_arc2_ca, ...) drives it through adlink_group_move.
//
// Life cycle (decisions V113-V116): an interpolation command on axes at rest hosts a new group at the present
// profile positions (the axes enter AxisMode::Coordinated); further commands on the same axis array while it
// moves go to its buffer with their transition mode (the "Flag", L3085); a command on other axes while it
// moves is refused. An idle group is released (the axes back to the T-curve mode) by the next single-axis
// command (the dialect calls Card::set_mode). MF_WAIT (Option bit 8) holds the group until the move trigger
// names its reference axis (V115). Any axis fault stops the whole group at once (machine::CardModes::on_fault),
// and every axis of the group reports the fault's stop code (V117).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_group.hpp"
#include "servobench/motion/adlink_interpolation.hpp"

namespace servobench::vendor::adlink {

constexpr std::size_t kAdlinkGroupSlot = 3;

class AdlinkGroup final : public machine::CardGroup {
 public:
  // array: the axis array (card axes, 0-based; the first is the reference axis); start: their profile positions
  // (pulse); period_s: the card's motion cycle, s.
  // buffer_size: pending moves (10, decision C40; a point table: 50, L3796); point_table: MTS PTB while it moves.
  AdlinkGroup(const std::vector<std::size_t>& array, double period_s, const std::vector<double>& start,
              double buffer_size = 10, bool point_table = false);
  motion::AdlinkInterpolator& interp() { return interp_; }
  const motion::AdlinkInterpolator& interp() const { return interp_; }
  const std::vector<std::size_t>& array() const { return array_; }

  void step_cycle() override;
  void positions(double* out) const override;
  bool busy() const override { return !interp_.done(); }
  void fault_stop() override;
  void stop(bool abrupt) override;

  bool waiting() const { return waiting_; }  // MF_WAIT: holds until trigger()
  void set_waiting(bool w) { waiting_ = w; }
  // More than one move runs now (a blend or an abort-blend transition): MTS BLD (V118).
  bool blending() const { return interp_.running_moves() > 1; }
  bool point_table() const { return point_table_; }  // an APS_pt_* table: MTS PTB, not MDN, while it runs (L3656)

 private:
  static std::vector<std::size_t> sorted(std::vector<std::size_t> a);
  std::vector<std::size_t> array_;
  std::vector<std::size_t> slot_of_;  // axes() index k -> array index
  motion::AdlinkInterpolator interp_;
  bool waiting_ = false;
  bool point_table_ = false;
};

// One APS interpolation command (APS_line, APS_arc2_ca, ...).
struct AdlinkGroupMove {
  std::vector<std::size_t> array;                // axis array, first = reference axis
  std::vector<motion::AdlinkPtpParams> params;   // PRA_* motion parameters of each array axis
  motion::AdlinkMoveSpec spec;
  motion::BlendMode mode = motion::BlendMode::AbortBlend;
  double blend = 0.0;                            // TransPara: mode 6 pulse, mode 7 %
  double vm = 0.0;                               // the _v form's Vm (0 = PRA_VM)
  std::optional<motion::AdlinkPtpParams> all;    // the _all form's speeds
  bool wait = false;                             // Option bit 8 (MF_WAIT)
  double buffer_size = 10;                       // pending moves of a group this move hosts (point table: 50)
  bool point_table = false;                      // hosted for an APS_pt_* point table (MTS PTB)
};

// Starts or buffers an interpolation on the card. Refused (CardCommandRefused, nothing changed) when an axis of
// the array moves outside the running group (ModeChangeInMotion), another array's group moves
// (ChangeInMotion), the e-stop or an axis alarm is active (EmergencyStopActive / DriveAlarmActive), or the
// buffer is full (ChangeInMotion); bad geometry or speeds throw std::invalid_argument before anything changes.
void adlink_group_move(machine::Card& card, const AdlinkGroupMove& m);
// The hosted AdlinkGroup (nullptr when none).
AdlinkGroup* adlink_group(machine::Card& card);
const AdlinkGroup* adlink_group(const machine::Card& card);
// APS_move_trigger: starts a waiting group whose reference axis is in mask (bit k = axis k); true if it did.
bool adlink_group_trigger(machine::Card& card, std::uint32_t mask);
// The APS words of axis i with the group's view: WAIT, BLD, and while the group's motion is the axis's, CSTP /
// MDN / ASTP / the stop code of a group fault (V117).
std::uint32_t aps_group_motion_status(const machine::Card& card, std::size_t axis);
int aps_group_stop_code(const machine::Card& card, std::size_t axis);

// Before a single-axis command on axis i (V116, V121): an idle interpolation group holding i, or a gear released by
// a fault of its slave, hands the axis back to the T-curve mode.
void aps_release_modes(machine::Card& card, std::size_t i);
// aps_release_modes, then the latched limit events of axis i whose input is no longer active end: ADLINK limits are
// level inputs (V31), so the direction inhibit lasts exactly while the limit is active.
void aps_release_axis(machine::Card& card, std::size_t i);
// APS_stop_move / APS_emg_stop / servo off on axis i: a moving group holding i stops whole (L2570-2580, V117); a
// gear slave is released, holding where it is (L3325, V121). True if axis i was such an axis.
bool aps_stop_modes(machine::Card& card, std::size_t i, bool abrupt);

}  // namespace servobench::vendor::adlink
