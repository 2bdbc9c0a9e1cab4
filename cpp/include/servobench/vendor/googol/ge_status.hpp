// The Googol GE series' status words as functions of the Card's state (GE manual seed 001; digest ge.md §1.5,
// §3.4, §5.7). Two card variants: -PX (point to point, 32-bit axis status) and -SX (continuous path, 16 bits).
//
// PX axis status register, 32 bits (Table 4-3, L902-932):
//   bit 1 drive alarm, 3 Index/Home (or probe) captured, 4 following error, 5 positive limit, 6 negative limit,
//   7 axis command error                                  -- latched events, cleared by GT_ClrSts / GT_RstSts
//   8 closed loop, 9 servo enabled, 10 profile in motion (or a motion update waiting for its commit at the next
//   tick), 11 limits enabled, 14 Home capture armed,
//   15 Index capture armed, 27 encoder abnormal, 30:28 axis number - 1; 0, 2, 12-13, 16-26, 31 reserved (0).
// SX axis status register, 16 bits (Table 4-2, L879-900): bits 1, 3, 4, 5, 6, 9, 10, 11, 14, 15 as PX,
//   13:12 axis number - 1; 0, 2, 7, 8 reserved (0).
// The card's soft limits (an ADLINK feature, never set by the GE dialect) would show in bits 5/6 (as GT, V15).
// PX mode register, 16 bits (Table 4-4, L938-945): bit 7 auto-stop on following error, bits 13:11 the profile
//   (000 trapezoid, 001 velocity, 010 S-curve); the others reserved (0; GE has no auto-update bit 10).
// Command-error register (GT_GetCmdSts): PX Table 2-3 (L301-322), SX Table 2-4 (L324-347); the bit of the last
//   refused command's cause (as GT, V7; decision V90).
#pragma once

#include <cstddef>
#include <cstdint>

#include "servobench/machine/card.hpp"

namespace servobench::vendor::googol {

enum class GeVariant : int { PX = 0, SX = 1 };

std::uint32_t ge_px_axis_status(const machine::Card& card, std::size_t axis);
std::uint16_t ge_sx_axis_status(const machine::Card& card, std::size_t axis);
std::uint16_t ge_mode_register(const machine::Card& card, std::size_t axis);
// The command-error bit of a refusal cause on each variant (0 where the table has no bit for it).
std::uint16_t ge_command_status_bit(GeVariant variant, machine::CommandFault fault);
std::uint16_t ge_command_status(GeVariant variant, const machine::Card& card);
// GT_RstSts(axis, mask) (L5423-5431): mask bit 1 keeps, 0 clears, bits 0-7 only; the card events to clear
// (mask 0 = GT_ClrSts). Reserved bits 0 and 2 clear the card's motion-complete and breakpoint events.
std::uint32_t ge_events_to_clear(std::uint16_t rst_sts_mask);

}  // namespace servobench::vendor::googol
