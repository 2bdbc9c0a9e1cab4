// The GUC-ECAT system-configuration calls (GUC §3.1 L185-300), the read-backs of the profile and stop parameters
// and the iDEABOX velocity-filter reads (§4.5 L3773-3801, L5450-5495), as vendor functions: each checks its
// arguments and returns the manual's GucCode (0, 1 the card cannot do it, 7 out of range; GUC Tab 2-1 L165-180),
// a read (code, value...) with zeros after a failed code. Axes/profiles from 1; pulse, ms, pulse/ms, pulse/ms^2.
// What the kernel holds (alarm and limit enables, limit polarity, the staged acceleration) is set on the Card;
// the rest is the card's GtsCard (gts_card.hpp). servobench.dialects._gts_config has one row per call.
#pragma once

#include <cstdint>
#include <tuple>
#include <utility>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// GT_AlarmOn / GT_AlarmOff (GUC L197-198, L213-215): the drive-alarm input stops the axis (on) or is ignored.
GucCode gts_alarm(machine::Card& card, double axis, bool on);
// GT_LmtsOn / GT_LmtsOff (GUC L199-200, L217-228): limit_type 0 positive, 1 negative, -1 both. The card has one
// limit enable per axis: one side alone returns 1 unless the axis is already in that state (decision GS3).
GucCode gts_limits(machine::Card& card, double axis, double limit_type, bool on);
// GT_LmtSns (GUC L294-305, Tab 3-4): bit 2k axis k+1 positive, 2k+1 negative, 1 = triggers on a low level.
GucCode gts_limit_sense(machine::Card& card, double sense);
// GT_EncSns (GUC L284-290): 0..0x1FF; a set bit (reversed count) returns 1 (positive feedback; GS4).
GucCode gts_enc_sense(machine::Card& card, double sense);
// GT_ProfileScale / GT_EncScale (GUC L201-202, L232-239): alpha, beta -32768..32767, beta != 0; only 1:1
// (alpha = beta) is the simulated axis, another ratio returns 1 (GS5).
GucCode gts_scale(machine::Card& card, double axis, double alpha, double beta);
// GT_GetDi (GUC L206, L253-276): the input word of MC_LIMIT_POSITIVE 0 .. MC_ARRIVE 5; 1 for MC_HOME / MC_ARRIVE
// (not wired, GS6).
std::pair<GucCode, std::uint32_t> gts_get_di(machine::Card& card, double type);
// GT_SetAdcFilter (GUC L207, L278-280): adc 1..8, filterTime 1..50; the card has no analog inputs: 1.
GucCode gts_set_adc_filter(machine::Card& card, double adc, double filter_time);
// GT_GetStopDec (GUC L244-247) / GT_GetCrdStopDec (L710-712): (code, smooth, abrupt) pulse/ms^2, (0, 0) unset.
std::tuple<GucCode, double, double> gts_get_stop_dec(machine::Card& card, double profile);
std::tuple<GucCode, double, double> gts_get_crd_stop_dec(machine::Card& card, double crd);
// GT_SetStopIo (GUC L248-266): axis 1..min(8, axes), the rest checked by GtsCard::set_stop_io.
GucCode gts_set_stop_io(machine::Card& card, double axis, double stop_type, double input_type, double index);
// GT_GetTrapPrm / GT_GetJogPrm: (code, the staged acceleration pulse/ms^2 = acc = dec (V61), jog smooth 0..1).
std::tuple<GucCode, double, double> gts_get_acc(machine::Card& card, double profile);
// GT_GetAxisPrfVelFilter / GT_GetAxisEncVelFilter (iDEABOX L5450-5495): (code, filterNumExp 0..7).
std::pair<GucCode, int> gts_get_vel_filter(machine::Card& card, double axis, bool encoder);
// GT_GetEncVel (iDEABOX L3793-3797): (code, encoder velocity pulse/ms over the filter window, GS9).
std::pair<GucCode, double> gts_get_enc_vel(machine::Card& card, double axis);

}  // namespace servobench::vendor::googol
