// The two FIFOs of one GUC-ECAT / iDEABOX coordinate system: FIFO0 (principal) and FIFO1 (auxiliary), each a
// PathGenerator with its own 4096-entry FIFO and its own look-ahead (GUC L997-1005, L999; iDEABOX L1608-1653,
// Fig 4-10, L1673-1675). Only one of them moves the coordinate system at a time.
//
// Rules (the manuals'; return code 1 = MotionCommandRefused):
//  - data may go to FIFO1 only while FIFO0 does not move (GUC L1003; iDEABOX L1640, L3858-3866: return 1);
//  - GT_CrdStart of a FIFO is refused while the other FIFO moves (iDEABOX L4558-4566: "the crd is moving");
//  - FIFO0 resumes only at its breakpoint: a start away from it is refused (GUC L1005, iDEABOX L1648-1653,
//    L4560); "the same position" is taken within `resume_tolerance` per coordinate (decision C26: the
//    manual's own Ex 4-6 returns to a DINT-rounded stop position), the sub-pulse gap closed by a line;
//  - starting FIFO0 clears FIFO1 (a suspended FIFO1 "is cleared and cannot resume", GUC L1003, iDEABOX
//    L1640-1642; a finished one has nothing left to lose);
//  - starting FIFO1 suspends FIFO0 where it is (decision C25: so that data streamed into FIFO0 meanwhile
//    waits for its GT_CrdStart instead of moving the coordinate system under FIFO1).
// The coordinate position is the position of the FIFO that moved last; both generators are stepped every
// cycle (outside axes moved by either FIFO's BufMove keep moving when their FIFO is stopped, GUC L1053).
#pragma once

#include <array>

#include "servobench/motion/path_generator.hpp"

namespace servobench::motion {

class CrdFifoPair {
 public:
  CrdFifoPair(const CoordSystem& coords, const PathSetup& setup = {}, const CrdPoint& start = {},
              double resume_tolerance = 0.5);
  CrdFifoPair(const CrdFifoPair&) = delete;
  CrdFifoPair& operator=(const CrdFifoPair&) = delete;

  // FIFO k (0 or 1). For FIFO1 at rest with nothing buffered, its position (and so its tail, the start of
  // the next segment) follows the coordinate system first. Commands pushed to it go through the rules.
  PathGenerator& fifo(int k);
  const PathGenerator& fifo(int k) const;
  // GT_CrdStart(mask, option) for this coordinate system: option bit = the FIFO (0 or 1).
  void start(int fifo);
  // GT_Stop of the coordinate system: stops the FIFO that moves it.
  void stop(bool abrupt);
  const PathState& step();
  // The FIFO that moved the coordinate system last.
  int active() const { return active_; }
  const PathState& state() const { return g_[static_cast<std::size_t>(active_)].state(); }
  const CoordSystem& coords() const { return g_[0].coords(); }
  bool done() const { return g_[0].done() && g_[1].done(); }
  bool running() const { return g_[0].running() || g_[1].running(); }
  // Outside axes of both FIFOs (FIFO0's position first when both moved the same axis).
  std::vector<int> aux_axes() const;
  double aux_position(int axis) const;

 private:
  void gate(int k, PathGateEvent e);
  void follow(int k);
  std::array<PathGenerator, 2> g_;
  int active_ = 0;
};

}  // namespace servobench::motion

namespace servobench::motion {
// Records the coordinate system (the active FIFO's state each cycle); see path_recording.hpp.
PathRecording record(CrdFifoPair& pair, std::size_t ticks, bool until_done);
}  // namespace servobench::motion
