// The GE SX coordinate system on the card (GE §6 L1445-2040; digest ge.md §4): the fixed identity X = axis 1,
// Y = axis 2, Z = axis 3, A = axis 4 (L1471, L5236-5240) with the GT_MapCnt work offsets (axis = coordinate +
// offset, L1960-1971), one PathGenerator hosted by the card as a PathGroup in slot kGeCrdSlot. Units: pulse and
// ms (the GE time base, L991-996): the generator's cycle is the card's motion cycle in ms. The GE feed rules go
// to PathSetup: start velocity (GT_SetStrtVel, default 0.5 pulse/ms, L1395-1399), the MaxVel clamp (GT_SetMaxVel,
// default 256 pulse/ms, L1401-1405), the abnormal-stop deceleration (GT_SetStpAcc, used by GT_EStpMtn, L1648;
// 0 = speed 0 at once), resume by a line to the breakpoint (GT_RestoreMtn, L1660). The list bookkeeping
// (immediate / buffer mode, open / closed, Mv, segment number, look-ahead module B) is vendor/googol/ge_list.hpp's
// GeList module, which builds this crd. Decisions V100-V112, GV1-GV3.
#pragma once

#include <cstddef>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/path_generator.hpp"

namespace servobench::vendor::googol {

// Slot 4 of the card's group slots (card_modes.hpp; slot 3 is the ADLINK interpolation group).
constexpr std::size_t kGeCrdSlot = 4;

struct GeCrdSetup {
  std::vector<double> offsets;  // GT_MapCnt work offsets per coordinate, pulse (empty: 0); one per axis 1..dim
  double start_vel = 0.5;       // pulse/ms, GT_SetStrtVel (L1399)
  double max_vel = 256.0;       // pulse/ms, GT_SetMaxVel (L1405)
  double stop_acc = 0.0;        // pulse/ms^2, GT_SetStpAcc (0: stop at once)
  double fifo_capacity = 4096;  // buffered commands (the 8 k-word buffer, L1496; cost per command unstated: V102)
  double dim = 0;               // coordinates X..A used, 1..4; 0 = min(4, axes). The look-ahead needs <= 3 (L1679)
  void validate() const;
};

// (Re)builds the GE crd at the present profile positions of axes 1..dim (dim 0: min(4, axis_count)): refused (CardCommandRefused,
// return code 1) while the crd or one of its axes moves. Anything buffered in a previous crd is dropped.
void ge_crd_setup(machine::Card& card, const GeCrdSetup& setup);
// The GE crd's generator; refused when ge_crd_setup was never called on this card.
motion::PathGenerator& ge_path(machine::Card& card);
bool ge_crd_exists(machine::Card& card);

}  // namespace servobench::vendor::googol
