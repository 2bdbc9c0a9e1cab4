// GtsCard: the GUC-ECAT / iDEABOX (GTS library; GUC manual seed 002, iDEABOX manual seed 003, digests guc.md,
// ideabox.md) registers that the neutral card kernel does not hold, as a card module (machine/card_hooks.hpp):
//   - the look-ahead window of each (crd, fifo) (GT_InitLookAhead; no look-ahead on a 4-D crd: GUC L985,
//     iDEABOX L2012-2014), dropped by GT_SetCrdPrm of that crd and by GT_Reset;
//   - the general-input levels (the machine's) and their polarity (GT_GpiSns, GUC L206, L267-276);
//   - the stop decelerations per profile and per crd (GT_SetStopDec GUC L240-243, GT_SetCrdStopDec L704-712) and
//     the stop-input map (GT_SetStopIo L248-266), checked at the end of every tick while one is set (GS8);
//   - the velocity filters (GT_SetAxisPrfVelFilter / EncVelFilter, iDEABOX L3793-3801, L5450-5495) and the
//     history of profile velocities and actual positions they average, recorded at the end of every tick from
//     the first filter setting or filtered read (decision GS9);
//   - the jog smoothing (TJogPrmExt.smooth, GS17).
// Units: pulse, ms, pulse/ms, pulse/ms^2 in the arguments; the kernel's pulse/tick through the servo period.
// Axes and profiles from 1 in the arguments. Commands return GucCode (GUC Tab 2-1 L165-180, iDEABOX Table 3-1).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

// Digital input types of GT_GetDi / GT_SetStopIo (GUC L253-266; MC_ARRIVE GTS-400-PX only, L259).
enum class GtsInput : int { LimitPositive = 0, LimitNegative = 1, Alarm = 2, Home = 3, Gpi = 4, Arrive = 5 };

struct GtsStopIo {
  int stop_type = 0;   // 0 emergency (the abrupt deceleration), 1 smooth
  GtsInput input = GtsInput::Gpi;
  int index = 1;       // 1..8 (GPI 1..16)
};

class GtsCard final : public machine::CardHooks {
 public:
  static constexpr int kFilterExpMax = 7;  // window 2^n ticks, n 0..7 (iDEABOX L3795-3797, L5462)

  explicit GtsCard(machine::Card& card);

  // -- look-ahead (GT_InitLookAhead / GT_SetCrdPrm) -------------------------------------------------------------
  void set_lookahead(int crd, int fifo, int n);   // crd 1..2, fifo 0..1, window n (0 = off)
  int lookahead(int crd, int fifo) const;
  void drop_lookahead(int crd);                   // a new GT_SetCrdPrm of crd
  // Whether a buffered command may go into (crd, fifo): 7 with look-ahead on a 4-D crd, 1 when the crd is not set
  // up (the card refuses it), else 0.
  GucCode check_push(int crd, int fifo);

  // -- general inputs ---------------------------------------------------------------------------------------------
  void set_inputs(std::uint32_t levels);          // the machine's GPI 1..16 levels (bit k = GPI k+1)
  GucCode set_gpi_sense(double sense);            // GT_GpiSns, 0..0xFFFF
  // GT_GetDi word: limits (polarity applied), the latched drive alarm, GPI after GpiSns; nullopt for MC_HOME /
  // MC_ARRIVE (not wired in the simulated machine, GS6).
  std::optional<std::uint32_t> input_word(GtsInput type) const;

  // -- stops ------------------------------------------------------------------------------------------------------
  GucCode set_stop_dec(double profile, double smooth, double abrupt);  // (0, 32767] pulse/ms^2 each
  std::pair<double, double> stop_dec(std::size_t profile) const;       // (0, 0) before (GUC L244-247)
  void set_crd_stop_dec(int crd, double smooth, double abrupt);
  std::pair<double, double> crd_stop_dec(int crd) const;
  // GT_Stop of one point-to-point / jog axis (0-based): at its GT_SetStopDec deceleration when set, else the
  // card's smooth stop (the move's acc) or abrupt stop (at once) (GS7).
  void stop_axis(std::size_t a, bool abrupt);
  // GT_SetStopIo(axis 1..8, stopType, inputType, inputIndex): 7 out of range, 1 for MC_HOME / MC_ARRIVE.
  GucCode set_stop_io(double axis, double stop_type, double input_type, double index);

  // -- velocity filters (GS9) ---------------------------------------------------------------------------------------
  GucCode set_prf_vel_filter(double axis, double exp);
  GucCode set_enc_vel_filter(double axis, double exp);
  int prf_vel_filter(std::size_t axis) const;     // 0-based axis
  int enc_vel_filter(std::size_t axis) const;
  // pulse/ms over the last 2^exp ticks recorded (the history starts now if it has not): profile velocity (mean)
  // or encoder velocity (position change / ticks).
  double filtered_prf_vel(std::size_t a);
  double filtered_enc_vel(std::size_t a);

  void set_jog_smooth(std::size_t axis, double smooth) { jog_smooth_.at(axis) = smooth; }
  double jog_smooth(std::size_t axis) const { return jog_smooth_.at(axis); }

  // -- hooks --------------------------------------------------------------------------------------------------------
  void after_axis(std::size_t i, const machine::LoopTick& r) override;  // the end of the tick: history, stop inputs
  void reset() override;                                                // look-ahead windows dropped (GT_Reset)

 private:
  bool valid_axis(double axis, double hi = 1e9) const;
  void start_history();
  void record();
  void check_stop_inputs();
  double ms() const;  // the servo tick in ms

  machine::Card& card_;
  std::array<std::array<int, 2>, 2> la_{};
  std::uint32_t gpi_ = 0, gpi_sns_ = 0;
  std::vector<std::optional<std::pair<double, double>>> stop_dec_;
  std::array<std::optional<std::pair<double, double>>, 2> crd_stop_dec_{};
  std::vector<std::optional<GtsStopIo>> stop_io_;
  bool any_stop_io_ = false;
  std::vector<int> prf_exp_, enc_exp_;
  std::vector<double> jog_smooth_;
  bool history_on_ = false;
  std::deque<std::vector<std::pair<double, double>>> history_;  // per tick: (profile vel pulse/tick, actual pos)
};

// The card's GTS module (created and attached on first use).
GtsCard& gts(machine::Card& card);

}  // namespace servobench::vendor::googol
