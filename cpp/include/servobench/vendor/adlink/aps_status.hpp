// The ADLINK PCI-8254/8258 status words as functions of the Card's state (ADLINK manual seed 004; digest
// adlink.md §7.1-7.3). Decisions V41-V48 (docs/decisions.md).
//
// Motion status APS_motion_status (MSTS, L3164-3206 = Note 2 L3633-3665):
//   bit 0 CSTP  the profile issues no command (but the axis "could be in motion": a homing sequence between moves)
//   bit 1 VM    at the maximum velocity (profile moving with zero acceleration: cruise, or a held velocity move)
//   bit 2 ACC   speeding up;   bit 3 DEC  slowing down
//   bit 4 DIR   1 positive / 0 negative, the last motion's direction kept after the stop (L3218)
//   bit 5 MDN   motion done: no profile and no homing sequence (also after an abnormal stop, L3229-3231)
//   bit 6 HMV   a homing sequence runs
//   bit 7 NSTP  not stopped: the complement of MDN, in the first reserved bit (L3174); the manual's home example
//               waits `while ((msts >> MTS_NSTP) & 1)` for "motion done" (L2313-2317) but its status table
//               has no such bit (decision AF1)
//   bit 10 WAIT a move issued with MF_WAIT waits for APS_move_trigger (L3669-3720)
//   bit 15 JOG  a jog sequence runs (JOG-ON on, or its step/delay/stop still running)
//   bit 16 ASTP abnormal stop: the card recorded a stop cause; cleared when the next motion starts (L3652)
//   bit 18 PRED / 19 POSTD  pre-/post-distance event of the point-to-point move (L3284-3292, cleared at the next start)
//   bit 28 GER  slave of a gear (the card's gear mode)
//   PTB (11) and BLD (17): set by the interpolation group's view (adlink_group.hpp; AF4, V118).
// Motion I/O status APS_motion_io_status (MIO, L3611-3631):
//   bit 0 ALM, 1 PEL, 2 MEL (inputs as triggered, polarity applied), 3 ORG (home switch), 4 EMG (card-wide),
//   5 EZ (0: the index mark is an instant, not a level; V44), 6 INP (servo on, at rest, |E| <= the band; V46),
//   7 SVON (servo-on output), 11 SPEL / 12 SMEL (soft-limit condition met now, when enabled).
// Stop code APS_get_stop_code (L3922-4023): 0 none, 1 STOP_EMG, 2 STOP_ALM, 3 STOP_SVNO (following-error
// auto-stop, V42), 4 STOP_PEL, 5 STOP_MEL, 6 STOP_SPEL, 7 STOP_SMEL, 13 STOP_ERROR_LEVEL (the manual prints
// 6, colliding with STOP_SPEL; 13 is the value of the APS library header APS_define.h, V41).
#pragma once

#include <cstddef>
#include <cstdint>

#include "servobench/machine/card.hpp"

namespace servobench::vendor::adlink {

// Bit numbers of the motion status word (MSTS).
enum class ApsMsts : int { CSTP = 0, VM = 1, ACC = 2, DEC = 3, DIR = 4, MDN = 5, HMV = 6, NSTP = 7, WAIT = 10, PTB = 11,
                           JOG = 15, ASTP = 16, BLD = 17, PRED = 18, POSTD = 19, GER = 28 };
// Bit numbers of the motion I/O status word (MIO).
enum class ApsMio : int { ALM = 0, PEL = 1, MEL = 2, ORG = 3, EMG = 4, EZ = 5, INP = 6, SVON = 7, SPEL = 11,
                          SMEL = 12 };

// Stop codes (APS_define.h STOP_*).
constexpr int kApsStopNormal = 0, kApsStopEmg = 1, kApsStopAlm = 2, kApsStopSvno = 3, kApsStopPel = 4,
              kApsStopMel = 5, kApsStopSpel = 6, kApsStopSmel = 7, kApsStopErrorLevel = 13;

std::uint32_t aps_motion_status(const machine::Card& card, std::size_t axis);
std::uint32_t aps_motion_io_status(const machine::Card& card, std::size_t axis);
int aps_stop_code(machine::StopCause cause);
int aps_stop_code(const machine::Card& card, std::size_t axis);

}  // namespace servobench::vendor::adlink
