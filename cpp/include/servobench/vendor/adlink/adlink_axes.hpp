// AdlinkAxes: the ADLINK PCI-8254/8258 single-axis machinery as a card module (machine/card_hooks.hpp): the
// immediate moves (APS_ptp / APS_vel / APS_stop_move), the synchronous start (MF_WAIT + APS_move_trigger), the
// limit stop mode (PRA_EL_MODE), the pre/post-distance events (PRA_PRE/POST_EVENT_DIST), the position-error level
// (PRA_ERR_POS_LEVEL), the in-position band (MIO INP) and the homing / jog sequences with the PRA_HOME_* / PRA_JG_*
// parameters. ADLINK manual seed 004, digest adlink.md §6.3-6.8, §7; decisions V27-V33, V41-V48.
//
// Units: the parameters are the manual's (pulse, pulse/s, pulse/s^2), converted to the kernel's pulse/tick with
// the card's servo period. The kernel (machine::Card) keeps none of this state: the module holds it per axis and
// plugs in through three hooks:
//   after_axis(i, r)  the error level (|E_n| of r above PRA_ERR_POS_LEVEL: servo off, stop cause ERROR_LEVEL),
//                     the end of a decelerating limit stop, the distance events of the running point-to-point move;
//   on_limit(i, c)    PRA_EL_MODE 1: a latched limit stops the axis at PRA_SD_DEC instead of at once;
//   reset()           back to the power-on values (GT_Reset / APS_initial of the whole card).
// It reaches the kernel through the card's public kernel services only (check_axis, refuse, check_move_allowed,
// fault_stop, latch_event, set_stop_cause, set_target_pos, loop, state). Get it with adlink(card) (created and
// attached on first use, owned by the card); read-only status functions take the card and use the defaults while
// no ADLINK command has created it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/motion/adlink_jog.hpp"
#include "servobench/motion/adlink_profile.hpp"
#include "servobench/motion/home_sequence.hpp"

namespace servobench::vendor::adlink {

// The ADLINK state of one axis (APS dialect; decisions V27-V33, V46).
struct AdlinkAxisState {
  bool wait_trigger = false;          // an APS_ptp with MF_WAIT waits for APS_move_trigger (MTS WAIT, bit 10)
  motion::AdlinkPtpParams waiting{};  // the move it will start
  bool limit_decelerate = false;      // PRA_EL_MODE 1: a limit stops at limit_dec (0: at once, the default)
  double limit_dec = 1e6;             // PRA_SD_DEC at the time PRA_EL_MODE was set, pulse/s^2
  bool limit_stopping = false;        // a decelerating limit stop runs
  double pre_event_dist = 0.0;        // PRA_PRE_EVENT_DIST (2Ah), pulse; 0 = off
  double post_event_dist = 0.0;       // PRA_POST_EVENT_DIST (2Bh), pulse; 0 = off
  bool ptp_active = false;            // a point-to-point move runs: the distance events are measured on it
  double move_start = 0.0, move_target = 0.0;  // its start and target, pulse
  bool pre_event = false, post_event = false;  // MTS PRED (bit 18) / POSTD (bit 19), cleared at the next start
  double error_level_pulse = 0.0;     // PRA_ERR_POS_LEVEL: |E| above it turns the servo off; 0 = off (L4012-4023)
  double in_position_pulse = 10.0;    // in-position band |E| (the drive's INP output, MIO bit 6; V46)
};

class AdlinkAxes : public machine::CardHooks {
 public:
  explicit AdlinkAxes(machine::Card& card);

  const AdlinkAxisState& state(std::size_t i) const;

  // -- immediate moves (no Update; pulse/s units in p, converted with the servo period) -------------------------
  // Point to point to p.pos (APS_ptp / relative / absolute move, on the fly during a PTP or velocity move).
  // Motion while the e-stop, the alarm input or a latched limit in the move's direction is active is refused and
  // records that cause as the stop cause (ADLINK L3931-4010: ignored, stop code, ASTP).
  void move_ptp(std::size_t i, const motion::AdlinkPtpParams& p);
  // Velocity move to the signed vel_pulse_per_s (APS_vel / APS_velocity_move), |v| <= p.vm.
  void move_velocity(std::size_t i, double vel_pulse_per_s, const motion::AdlinkPtpParams& p);
  // Decelerating stop at p.sd_dec (or p.dec), pulse/s^2 (APS_stop_move); a homing or jog sequence ends.
  void stop_move(std::size_t i, const motion::AdlinkPtpParams& p);
  // APS_ptp with Option bit 8 (MF_WAIT): the move is checked now and waits for move_trigger (L3669-3720).
  void move_ptp_wait(std::size_t i, const motion::AdlinkPtpParams& p);
  // APS_move_trigger: starts every waiting move of the masked axes (bit k = axis k) in this same tick (L3787-3790).
  void move_trigger(std::uint32_t mask);
  bool waiting_trigger(std::size_t i) const { return state(i).wait_trigger; }

  // -- sequences --------------------------------------------------------------------------------------------
  // APS_home_move with the PRA_HOME_* parameters (modes 0 ORG, 1 EL, 2 EZ; L2246-2556). Refused while moving.
  void home(std::size_t i, const motion::AdlinkHomeParams& p);
  // Installs the PRA_JG_* jog parameters (JOG-ON off). Ignored (refused) while another motion runs (L2708).
  void jog(std::size_t i, const motion::AdlinkJogParams& p);
  // The JOG-ON signal (APS_jog_on): continuous mode moves while on; step mode steps, waits, then moves.
  void set_jog_on(std::size_t i, bool on);

  // -- parameters ---------------------------------------------------------------------------------------------
  // PRA_EL_MODE: false stops at once on a limit (default), true decelerates at dec_pulse_per_s2 (PRA_SD_DEC).
  void set_limit_stop_mode(std::size_t i, bool decelerate, double dec_pulse_per_s2);
  // PRA_PRE_EVENT_DIST / PRA_POST_EVENT_DIST (L3284-3292), pulse, 0 = off.
  void set_move_event_distances(std::size_t i, double pre_pulse, double post_pulse);
  // PRA_ERR_POS_LEVEL, pulse, 0 = off.
  void set_error_level(std::size_t i, double pulse);
  // |E| <= band at rest counts as in position (MIO INP), pulse.
  void set_in_position_band(std::size_t i, double pulse);

  // -- hooks --------------------------------------------------------------------------------------------------
  void after_axis(std::size_t i, const machine::LoopTick& r) override;
  bool on_limit(std::size_t i, machine::StopCause cause) override;
  void reset() override;

 private:
  AdlinkAxisState& at(std::size_t i);
  void start_ptp(std::size_t i, const motion::AdlinkPtpParams& p);
  void motion_started(std::size_t i);  // a new motion: stop cause and distance events cleared (L3652, L3661)
  template <class F>
  void checked(std::size_t i, F&& check);

  machine::Card& card_;
  std::vector<AdlinkAxisState> st_;
};

// The card's ADLINK module, created and attached on first use (owned by the card).
AdlinkAxes& adlink(machine::Card& card);
// The card's ADLINK module if an ADLINK command created it, else null.
const AdlinkAxes* adlink_if_any(const machine::Card& card);
// The ADLINK state of axis i: the module's, or the power-on values.
const AdlinkAxisState& adlink_state(const machine::Card& card, std::size_t i);

// Servo on, at rest, |E| <= the in-position band (MIO INP, V46).
bool in_position(const machine::Card& card, std::size_t i);
// A jog sequence is installed and running: JOG-ON on, or its step / delay / stop still running (MTS JOG, bit 15).
bool jogging(const machine::Card& card, std::size_t i);

}  // namespace servobench::vendor::adlink
