// CardGroup: a multi-axis motion source the Card hosts. It drives a group of card axes (AxisMode::Coordinated)
// on the card's tick clock: the card steps it once per motion cycle, interpolates its motor positions linearly
// down to the servo tick and feeds them to the axes' profile generators (ProfileGenerator::follow), so the
// axes run their servo loops on the simulated plant exactly as in the independent modes. Docs: docs/card.md
// "Modes and coordinate systems"; decisions V51-V70.
//
// The interface is generic: anything that yields motor positions per motion cycle can be a group. The card
// ships two kinds, both over the motion layer's path interpolators (units: coordinate unit = pulse for GUC/
// iDEABOX/GE, the user's unit for GT; time in the interpolator's unit, see PathSetup.cycle_ms):
//  - CrdPairGroup: a GUC-ECAT / iDEABOX coordinate system (GT_SetCrdPrm): a CrdFifoPair (FIFO0/FIFO1 with
//    look-ahead and the buffered commands), crd 1..2;
//  - PathGroup: one PathGenerator over any CoordSystem (the GT's GT_MapAxis system; the GE SX crd later).
// The ADLINK interpolation groups can implement CardGroup the same way (positions in pulse per motion cycle).
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/path_generator.hpp"

namespace servobench::machine {

class CardGroup {
 public:
  virtual ~CardGroup() = default;
  // The card axes the group drives (0-based, ascending).
  const std::vector<std::size_t>& axes() const { return axes_; }
  // One motion cycle; positions() are then the motor positions at the cycle's end.
  virtual void step_cycle() = 0;
  // Profile positions (card coordinates, pulse) of axes() after the last cycle.
  virtual void positions(double* out) const = 0;
  // Something moves now (the card feeds the axes while this holds or the positions changed in the cycle).
  virtual bool busy() const = 0;
  // An axis of the group faulted (limit, drive alarm, following-error auto-stop, e-stop, error level):
  // the group stops at once, keeping its breakpoint where the source supports one.
  virtual void fault_stop() = 0;
  // GT_AbptStp / GT_Stop on the group (abrupt) or its smooth stop.
  virtual void stop(bool abrupt) = 0;
  // Outside axes the group's buffer moves (BufMove / BufGear): (card axis 0-based, profile position, pulse).
  virtual void aux_positions(std::vector<std::pair<std::size_t, double>>& out) const { out.clear(); }
  // Before a start: the present profile positions of the card's axes outside the group (all axes, 0-based
  // index = card axis), so buffered moves of outside axes start where those axes stand.
  virtual void set_outside_positions(const std::vector<double>& /*profile_pos*/) {}
  // The card's inputs before each motion cycle, logical (sense applied): type motion::StopInput (limit +/-,
  // alarm, home), index = card axis + 1 (1..8). A group that maps inputs to stops (GUC BufSetStopIo) reads them.
  virtual void set_input(int /*type*/, int /*index*/, bool /*active*/) {}
  // Whether the group lets the card see a hard limit of card axis `axis` (0-based); a buffered BufLmtsOff
  // (GUC L609-624) turns it off from its place in the FIFO on.
  virtual bool limit_enabled(std::size_t /*axis*/, bool /*positive*/) const { return true; }

 protected:
  explicit CardGroup(std::vector<std::size_t> axes) : axes_(std::move(axes)) {}

 private:
  std::vector<std::size_t> axes_;
};

// Card axes (0-based) of a coordinate system's motor axes (1-based numbers).
std::vector<std::size_t> card_axes_of(const motion::CoordSystem& cs);

// A GUC-ECAT / iDEABOX coordinate system: the FIFO pair.
class CrdPairGroup final : public CardGroup {
 public:
  CrdPairGroup(const motion::CoordSystem& coords, const motion::PathSetup& setup, const motion::CrdPoint& start,
               double resume_tolerance);
  motion::CrdFifoPair& pair() { return pair_; }
  const motion::CrdFifoPair& pair() const { return pair_; }
  void step_cycle() override { pair_.step(); }
  void positions(double* out) const override { pair_.coords().to_axes(pair_.state().pos, out); }
  bool busy() const override { return pair_.fifo(0).busy() || pair_.fifo(1).busy(); }
  void fault_stop() override { pair_.stop(true); }
  void stop(bool abrupt) override { pair_.stop(abrupt); }
  void aux_positions(std::vector<std::pair<std::size_t, double>>& out) const override;
  void set_outside_positions(const std::vector<double>& profile_pos) override;
  void set_input(int type, int index, bool active) override;
  bool limit_enabled(std::size_t axis, bool positive) const override;

 private:
  motion::CrdFifoPair pair_;
};

// One path interpolator over any coordinate system (GT_MapAxis; GE later).
class PathGroup final : public CardGroup {
 public:
  PathGroup(const motion::CoordSystem& coords, const motion::PathSetup& setup, const motion::CrdPoint& start);
  motion::PathGenerator& path() { return gen_; }
  const motion::PathGenerator& path() const { return gen_; }
  void step_cycle() override { gen_.step(); }
  void positions(double* out) const override { gen_.coords().to_axes(gen_.state().pos, out); }
  bool busy() const override { return gen_.busy(); }
  void fault_stop() override { gen_.stop(true); }
  void stop(bool abrupt) override { gen_.stop(abrupt); }
  void aux_positions(std::vector<std::pair<std::size_t, double>>& out) const override;
  void set_outside_positions(const std::vector<double>& profile_pos) override;

 private:
  motion::PathGenerator gen_;
};

}  // namespace servobench::machine
