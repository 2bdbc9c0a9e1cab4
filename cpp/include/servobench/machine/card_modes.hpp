// CardModes: the card's axis modes driven by an outside source instead of the axis's own profile: electronic
// gear (GT_PrflG), PVT (GT_PrfPvt), FollowEx cam (iDEABOX GT_PrfFollowEx) and coordinate systems (CardGroup:
// GUC-ECAT/iDEABOX GT_SetCrdPrm crd 1..2 with FIFO0/FIFO1, the GT's GT_MapAxis system). Each tick the card
// asks it, axis by axis in ascending order, for the command of every driven axis and hands that to the
// axis's profile generator (ProfileGenerator::follow); the axis then runs its servo tick as always. So a
// follower numbered below its master sees the master's previous tick (iDEABOX L487, decision V51).
// Owned by the Card (Card::modes()), created on first use: a card that never uses these modes ticks as before.
// Units are the card's (pulse, pulse/tick); the path interpolators run in their own (PathSetup.cycle_ms).
// Refusals go through the card (CardCommandRefused with a CommandFault, return code 1 in the dialects).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_group.hpp"
#include "servobench/motion/follow_ex.hpp"
#include "servobench/motion/gear.hpp"
#include "servobench/motion/pvt_table.hpp"

namespace servobench::machine {

// Group slots: GUC-ECAT / iDEABOX crd 1..2 are slots 0..1; the GT coordinate system (GT_MapAxis) is slot 2;
// slot 3 is the ADLINK interpolation group (vendor/adlink/adlink_group.hpp), slot 4 the GE SX crd (vendor/googol/ge_crd.hpp).
constexpr std::size_t kGroupSlots = 5;
constexpr std::size_t kGtCrdSlot = 2;

// The card's side of a hosted group: positions interpolated to the tick, fault state.
struct HostedGroup {
  std::shared_ptr<CardGroup> group;  // shared: a Python view of the group keeps it alive
  std::vector<double> prev, cur;     // motor positions at the start / end of the present motion cycle
  std::vector<double> vel;           // per group axis, pulse/tick, of the last tick fed
  bool feeding = false;              // the axes are fed this motion cycle
  bool fault_stopped = false;        // an axis fault stopped the group (GT/GE crd status bit 9)
  StopCause fault_cause = StopCause::None;
  int fault_axis = -1;               // 0-based card axis of that fault
  std::vector<std::pair<std::size_t, double>> aux_prev, aux_cur;  // outside axes moved by the buffer
};

// FollowEx master (GT_SetFollowMasterEx masterIndex, iDEABOX L7316-7343); which of its signals (encoder or
// planned position) is the FollowEx setup's master_type / master_item (L7345-7363).
struct FollowMaster {
  std::size_t master = 0;  // card axis, 0-based
};

class CardModes : public CardHooks {
 public:
  explicit CardModes(Card& card);
  CardModes(const CardModes&) = delete;
  CardModes& operator=(const CardModes&) = delete;

  // A group start refused because of `cause` (the e-stop): the axes record it as their stop cause, as a refused
  // single-axis Update does (ADLINK L3931-3936: the command is ignored, the stop code reads EMG).
  void note_refused_start(std::size_t axis, StopCause cause);
  // Whether every hosted group lets the card see this hard limit of `axis` (GUC BufLmtsOn/Off, V129).
  bool limit_enabled(std::size_t axis, bool positive) const override;

  // -- electronic gear (GT L1029-1090, L4407-4437) ---------------------------------------------------------
  // GT_PrflG(master): axis `slave` follows the profile position of axis `master` with the active ratio (the
  // staged GT_SetRatio becomes active at the next Update). Refused while the slave moves in another mode (cmd
  // bit 6) and for master == slave. Engages at the present positions (no jump).
  void set_gear(std::size_t slave, std::size_t master);
  std::size_t gear_master(std::size_t slave) const;
  // A move of `master` in direction dir would drive one of its slaves toward a latched limit (GT L2213: slave
  // negative limit + negative ratio -> the master may move only negative).
  bool gear_inhibits(std::size_t master, double dir) const;
  // A fault or GT_AbptStp halted the gear: the slave holds until the next PrflG or ratio Update (V53).
  bool gear_halted(std::size_t slave) const;
  // -- [aps] ADLINK gear (seed 004 L3294-3325, decisions V119-V121) -------------------------------------------
  // APS_start_gear: set_gear, then the ratio ramps from 0 to `ratio` at `rate_per_tick` (ratio per tick; 0 = at
  // once). A fault of the slave releases (halts) it without stopping the master (L3321-3324).
  void set_gear_ramp(std::size_t slave, std::size_t master, double ratio, double rate_per_tick);
  // On-the-fly PRA_GEAR_RATIO change, ramped at the engage rate (L3311).
  void gear_ramp_to(std::size_t slave, double ratio, double rate_per_tick);
  double gear_ratio(std::size_t slave) const;  // the ratio in effect now
  // -- [/aps] ------------------------------------------------------------------------------------------------

  // -- PVT (GUC §4.2 L1116-2100, iDEABOX §4.4) --------------------------------------------------------------
  motion::PvtTables& pvt_tables() { return tables_; }
  // GT_PvtTable*: replaces table 1..32 (refused while a moving axis uses it, or > 1024 blocks).
  void pvt_download(int table_id, const motion::PvtCurve& curve);
  // GT_PrfPvt: PVT mode (refused while moving, cmd bit 6).
  void set_pvt(std::size_t i);
  motion::PvtAxis& pvt(std::size_t i);
  const motion::PvtAxis& pvt(std::size_t i) const;
  void pvt_select(std::size_t i, int table_id);  // GT_PvtTableSelect (refused on an empty table)
  void pvt_loop(std::size_t i, double loop);     // GT_SetPvtLoop, 0 = infinite
  // GT_PvtStart(mask): bit k = axis k; every masked axis must be in PVT mode and at rest; all start this tick.
  void pvt_start(std::uint32_t mask);

  // -- FollowEx (iDEABOX §2.1 L394-929) ---------------------------------------------------------------------
  // GT_PrfFollowEx(profile, dir) with the rest of the setup (memory, event, loop) and the master.
  void set_follow(std::size_t i, const motion::FollowExSetup& setup, const FollowMaster& master);
  // GT_SetFollowMasterEx / MemoryEx / EventEx / LoopEx after the mode is set: refused while moving (and a
  // memory change once data is written, L514).
  void follow_configure(std::size_t i, const motion::FollowExSetup& setup);
  void follow_master(std::size_t i, const FollowMaster& master);
  const FollowMaster& follow_master_of(std::size_t i) const;
  motion::FollowEx& follow(std::size_t i);
  std::shared_ptr<motion::FollowEx> follow_shared(std::size_t i);
  const motion::FollowEx& follow(std::size_t i) const;
  // GT_FollowStartEx(mask, option): bit k = axis k; option bit k = FIFO 1 for axis k.
  void follow_start(std::uint32_t mask, std::uint32_t option);
  // GT_FollowSwitchEx(mask): only while moving, the other FIFO must hold data.
  void follow_switch(std::uint32_t mask);
  // The master position axis i's cam sees now (pulse).
  double follow_master_pos(std::size_t i) const;

  // -- coordinate systems (generic) -------------------------------------------------------------------------
  // Hosts `g` in `slot`: its axes must be at rest and not in another group; they enter AxisMode::Coordinated.
  // A group already in the slot is replaced (refused while it moves).
  void add_group(std::size_t slot, std::unique_ptr<CardGroup> g);
  void remove_group(std::size_t slot);
  CardGroup* group(std::size_t slot);
  const CardGroup* group(std::size_t slot) const { return hosted(slot).group.get(); }
  std::shared_ptr<CardGroup> group_shared(std::size_t slot) { return this->slot(slot).group; }
  const HostedGroup& hosted(std::size_t slot) const;
  int group_of(std::size_t axis) const { return group_of_[axis]; }
  // Before a group start: refused with the e-stop on or an axis alarm active / drive off; clears the fault
  // state, hands the outside axes' positions to the group.
  void before_group_start(std::size_t slot);
  // GT_Stop on a group (smooth or abrupt).
  void stop_group(std::size_t slot, bool abrupt);

  // -- GUC-ECAT / iDEABOX coordinate systems (GUC §4.1, iDEABOX §4.3) ----------------------------------------
  // GT_SetCrdPrm(crd, prm), crd 1..2: profile[k] != 0 puts card axis k into the crd; origin = the profiles'
  // positions now (set_origin 0) or origin_pos. Refused (1) while a mapped axis moves or is in the other crd.
  void set_crd_prm(int crd, const motion::CrdPrm& prm);
  const motion::CrdPrm& crd_prm(int crd) const;
  motion::CrdFifoPair& crd(int crd);
  // GT_CrdStart(mask, option): bit c-1 = crd c; option bit c-1 = FIFO1.
  void crd_start(std::uint32_t mask, std::uint32_t option);
  // GT_GetCrdPos: the crd coordinates (dimension values) of the FIFO that moves the crd.
  motion::CrdPoint crd_pos(int crd) const;

  // -- GT coordinate system (GT_MapAxis, GT L1519-1672) -------------------------------------------------------
  // Adds/replaces the map row of one axis (1..4); the system (slot kGtCrdSlot) is rebuilt at the present
  // positions. Refused while the mapped axis or the system moves.
  void gt_map_axis(const motion::GtAxisMap& row);
  motion::PathGenerator& gt_path();

  // -- hooks the Card calls (machine/card_hooks.hpp) --------------------------------------------------------
  bool active() const override { return n_driven_ > 0 || n_groups_ > 0; }
  void begin_tick(long long tick) override;
  void feed(std::size_t i) override;
  void on_fault(std::size_t i, StopCause cause) override;
  void on_abrupt_stop(std::size_t i) override;
  void on_ratio(std::size_t i, double ratio) override;
  bool inhibits_move(std::size_t i, double dir) const override { return gear_inhibits(i, dir); }
  // The axis leaves its driven mode (a mode select, or a reset when all = true).
  void leave(std::size_t i) override;
  void reset() override;
  // The driven modes' notion of "moving" (GT status bit 10) for axis i; nullopt = the card's own.
  std::optional<bool> moving(std::size_t i) const override;

 private:
  void feed_inputs(CardGroup& g) const;
  enum class Kind : std::uint8_t { None, Gear, Pvt, Follow, Group };
  struct GearSlave {
    std::size_t master = 0;
    std::optional<motion::ElectronicGear> gear;
    bool halted = false;
    double target = 0.0, rate = 0.0;  // [aps] ramp: ratio to reach, ratio per tick (0 = no ramp)
    bool keep_master = false;         // [aps] a slave fault does not stop the master
  };
  void check_at_rest(std::size_t i, const char* what);
  void set_kind(std::size_t i, Kind k);
  long long master_profile(std::size_t m) const;
  std::vector<double> profile_positions() const;
  void start_group_checks(std::size_t slot);
  HostedGroup& slot(std::size_t s);

  Card& card_;
  std::size_t n_ = 0;
  std::vector<Kind> kind_;
  std::size_t n_driven_ = 0, n_groups_ = 0;
  std::vector<GearSlave> gear_;
  motion::PvtTables tables_;
  std::vector<std::unique_ptr<motion::PvtAxis>> pvt_;
  std::vector<std::shared_ptr<motion::FollowEx>> follow_;
  std::vector<FollowMaster> follow_master_;
  std::array<HostedGroup, kGroupSlots> groups_;
  std::vector<int> group_of_;
  std::vector<motion::MotionState> cmd_;  // group axes: this tick's command
  std::vector<std::uint8_t> aux_fed_;     // outside axes fed by a group buffer this cycle
  std::array<motion::CrdPrm, 2> crd_prm_{};
  std::vector<motion::GtAxisMap> gt_rows_;
  double cycle_ticks_ = 1.0;
};

}  // namespace servobench::machine
