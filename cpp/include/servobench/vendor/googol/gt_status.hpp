// The GT series' status words as functions of the Card's state (GT manual seed 000; digest gt.md §1.5, §6.1-6.2).
//
// Axis status register, 16 bits (Table 4-14, L1439-1464 = Table 11-1 L3163-3187):
//   bit 0 motion complete, 1 drive alarm, 2 breakpoint, 3 index/home captured, 4 following (motion) error,
//   5 positive limit, 6 negative limit, 7 command error   -- latched events, cleared by GT_ClrSts / GT_RstSts
//   8 closed loop, 9 drive enabled, 10 profile in motion, 11 limits monitored, 12-13 axis number - 1,
//   14 home capture armed, 15 index capture armed        -- the controller's state (L1468)
// The card's soft limits (an ADLINK feature) show in bits 5/6 too (decision V15).
// Mode register (Table 4-15, L1493-1511): bit 7 auto-stop on following error, bit 10 auto-update at a
// breakpoint, bits 11-13 the profile mode (000 T, 001 jog, 010 S, 011 gear, 101 coordinated).
// Command status register (Table 2-2, L455-478): one bit per refusal cause (the last refused command, V16).
#pragma once

#include <cstddef>
#include <cstdint>

#include "servobench/machine/card.hpp"

namespace servobench::vendor::googol {

std::uint16_t gt_axis_status(const machine::Card& card, std::size_t axis);
std::uint16_t gt_mode_register(const machine::Card& card, std::size_t axis);
// The mode register's bits 11-13 for a kernel mode: T 0, jog 1, S 2, gear 3, coordinated 5 (L1500-1511); the PVT
// and FollowEx modes, which the GT manual has no code for, read 6 and 7 (decision VK11).
std::uint16_t gt_mode_code(machine::AxisMode mode);
// The latched events as status bits 0-7 (Table 4-14) and back; the soft limits show as the hard ones (V15).
std::uint32_t gt_event_bits(std::uint32_t events);
// The command-status bit of a refusal cause (0 for causes the GT register has no bit for).
std::uint16_t gt_command_status_bit(machine::CommandFault fault);
std::uint16_t gt_command_status(const machine::Card& card);
// GT_RstSts(mask): mask bit 1 keeps, 0 clears, bits 0-7 (L4557-4569); the card events to clear.
std::uint32_t gt_events_to_clear(std::uint16_t rst_sts_mask);

}  // namespace servobench::vendor::googol
