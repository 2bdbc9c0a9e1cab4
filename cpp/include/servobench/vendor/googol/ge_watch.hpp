// GeWatch: the GE data watch (GE manual seed 001 §10.1, L2464-2884; digest ge.md §6.6; decisions V73-V75, GW4) over
// the card's sampler (machine/sampler.hpp), held by the card's GE registers module (ge_registers.hpp), which resets
// it with the registers (GT_Reset, GT_Open). It holds the watch's configuration and hands out the
// sampler's blocks in the GE's units:
//   set_watch(config, size)  GT_SetWatch: config[k] the watched signals of axis k+1 (Table 10-2: bit 0 profile
//                            position, 1 actual position, 2 profile velocity, 3 actual velocity, 6 control voltage;
//                            bits 4, 5, 7 reserved), `size` samples per block; 7 for a reserved bit, more words than
//                            axes, a size not whole >= 1, nothing watched, or a block beyond the watch memory
//                            (kWatchMemoryValues values, all axes, V75).
//   start(n)                 GT_StartWatch: one sample every n + 1 control periods (n whole 0..65535, L2878-2880,
//                            V74); blocks of `size` samples follow each other without a gap (continuous sampler).
//   next_block(block)        GT_GetWatch: the oldest full block, per channel in sampling order, converted: position
//                            pulse (whole, the C long), velocity pulse/ms (double), control voltage DAC counts
//                            (+10 V = 32767, clamped to the short, L5331-5337); false when no block is full yet.
//   stop()                   GT_StopWatch: the sampler stops, blocks not read are dropped.
// Codes (Table 2-1): 1 for StartWatch / GetWatch before a SetWatch, 7 for a bad argument; never throws.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

class GeWatch {
 public:
  static constexpr double kWatchMemoryValues = 32768;  // values (samples x watched signals), V75

  explicit GeWatch(machine::Card& card) : card_(card) {}

  GeCode set_watch(const std::vector<double>& config, double size);
  // The watched channels in sampling order: (axis 0-based, config bit); the block size.
  const std::vector<std::pair<std::size_t, int>>& channels() const { return channels_; }
  int size() const { return size_; }

  GeCode start(double n);
  // GT_GetWatch: 1 before SetWatch; else 0 with `block` filled (one vector per channel) or left empty.
  GeCode next_block(std::vector<std::vector<double>>& block);
  void stop();

  void reset() {  // forgets the configuration
    channels_.clear();
    size_ = 0;
  }

 private:
  machine::Card& card_;
  std::vector<std::pair<std::size_t, int>> channels_;
  int size_ = 0;
};

// The card's GE watch (its GE registers module's, created with it on first use).
GeWatch& ge_watch(machine::Card& card);

}  // namespace servobench::vendor::googol
