#include "servobench/vendor/googol/ge_crd.hpp"

#include <algorithm>
#include <memory>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card_group.hpp"
#include "servobench/machine/card_modes.hpp"

namespace servobench::vendor::googol {

using machine::Card;
using machine::CardCommandRefused;
using machine::CommandFault;
using machine::PathGroup;

void GeCrdSetup::validate() const {
  const char* o = "GeCrdSetup";
  check_range(o, "start_vel", start_vel, 0, 40957, "pulse/ms; GT_SetStrtVel L5748-5756");
  check_range(o, "max_vel", max_vel, 0, 40957, "pulse/ms; GT_SetMaxVel L5638-5644");
  if (!(max_vel > 0)) throw_invalid(o, "max_vel", max_vel, "is outside the allowed range 0..40957 (0 excluded; pulse/ms)");
  check_range(o, "stop_acc", stop_acc, 0, 102400, "pulse/ms^2; GT_SetStpAcc L5736-5744");
  check_integer(o, "fifo_capacity", fifo_capacity, 1, 1e6, "buffered commands; GE L1496");
  check_integer(o, "dim", dim, 0, 4, "coordinates X..A; 0 = all the card's axes up to 4");
  for (double v : offsets) check_range(o, "offsets[k]", v, -1073741824.0, 1073741823.0, "pulse; GT_MapCnt L5179-5187");
}

void ge_crd_setup(Card& card, const GeCrdSetup& s) {
  s.validate();
  const int all = static_cast<int>(std::min<std::size_t>(4, card.axis_count()));
  const int dim = s.dim > 0 ? std::min(all, static_cast<int>(s.dim)) : all;
  std::vector<double> offsets = s.offsets;
  offsets.resize(static_cast<std::size_t>(dim), 0.0);
  const motion::CoordSystem cs = motion::CoordSystem::identity(dim, offsets);
  motion::PathSetup setup;
  setup.cycle_ms = card.cycles().motion_cycle_ticks * card.servo_period_s() * 1e3;
  setup.fifo_capacity = s.fifo_capacity;
  setup.syn_vel_max = s.max_vel;
  setup.syn_acc_max = 102400;  // the GE acceleration range (L5435-5437)
  setup.start_vel = s.start_vel;
  setup.stop_dec_abrupt = s.stop_acc;
  setup.return_to_stop_point = true;  // GT_RestoreMtn returns to the breakpoint by a line (L1660)
  std::vector<double> axis_pos;
  for (int a : cs.axes()) axis_pos.push_back(static_cast<double>(card.profile_pos(static_cast<std::size_t>(a - 1))));
  card.modes().add_group(kGeCrdSlot, std::make_unique<PathGroup>(cs, setup, cs.to_crd(axis_pos)));
}

bool ge_crd_exists(Card& card) { return dynamic_cast<PathGroup*>(card.modes().group(kGeCrdSlot)) != nullptr; }

motion::PathGenerator& ge_path(Card& card) {
  auto* g = dynamic_cast<PathGroup*>(card.modes().group(kGeCrdSlot));
  if (!g) {
    card.record_fault(-1, CommandFault::CrdStateError);
    throw CardCommandRefused(CommandFault::CrdStateError, -1, "the GE crd is not set up [return code 1]");
  }
  return g->path();
}

}  // namespace servobench::vendor::googol
