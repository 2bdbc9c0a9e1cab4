// GtInterrupts: the GT interrupt registers and their request / service machine (GT manual §7, L2219-2410,
// L4534-4555, L4763-4801; gt.md §5, §7, §8.9; decisions V71-V85).
//
// Event interrupts (the default): an axis status bit 0-6 enabled by GT_SetIntrMsk requests an interrupt; the
// lowest axis with such a bit is the interrupting one (L2229); on a disabled axis only the motion-error (bit 4)
// and drive-alarm (bit 1) bits interrupt (L2257). The request stays pending until GT_RstIntr serves it; a
// condition that persists (a limit still pressed) requests again at once (L2235-2243). Timer interrupts
// (GT_TmrIntr): every GT_SetIntrTm servo periods, served by GT_ClearInt. A request calls the host's routine
// (GT_HookIsr, DOS form) and sets the host's event (GT_SetIntSyncEvent, Windows form, L2338); a routine that keeps
// re-raising at one instant is left pending after kRefireLimit calls (an interrupt storm).
//
// The card tells the machine of a watched event through the dialect's event subscription (Card.on_event, which
// the dialect renews from watch()); request() and timer() are what the subscriptions call.
#pragma once

#include <any>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

class GtCard;  // gt_card.hpp

enum class GtInterruptMode { Event, Timer };

struct GtInterruptRegs {
  GtInterruptMode mode = GtInterruptMode::Event;
  std::array<int, 4> mask{};        // GT_SetIntrMsk per axis, bits 0-6 (all masked after reset, L4765-4779)
  int timer = 0;                    // GT_SetIntrTm, servo periods, 0..32767 (0: no timer interrupt, V84)
  bool pending = false;             // a request not served yet
  std::size_t axis = 0;             // the interrupting axis (0-based)
  bool in_isr = false;              // the host's routine runs now
  bool recheck = false;             // GT_RstIntr inside the routine: look again when it returns
  long long storm_tick = -1;        // the tick of the last requests and how many at that tick
  int storm_count = 0;
  std::vector<long long> subscriptions;  // the dialect's Card.on_event ids that feed request() / timer()
};

class GtInterrupts {
 public:
  static constexpr int kRefireLimit = 16;        // re-raises at one instant before the request is left pending
  static constexpr int kDisabledAxisBits = 0x12; // bits 4 and 1 on a disabled axis (L2257)

  explicit GtInterrupts(GtCard& gt) : gt_(gt) {}

  const GtInterruptRegs& regs() const { return r_; }
  // Back to the power-on registers; the host's routine and event stay (they are the host's, not the card's).
  // The subscription ids stay for the dialect to remove (resubscribe).
  void reset() {
    std::vector<long long> subs = std::move(r_.subscriptions);
    r_ = GtInterruptRegs{};
    r_.subscriptions = std::move(subs);
  }

  // The host's side: the routine (GT_HookIsr) and the event (GT_SetIntSyncEvent); empty = none.
  std::function<void()> isr, sync;
  std::any isr_object;  // the routine as the host gave it (GT_HookIsr returns the previous one unchanged)
  // Set by the dialect: renews its Card.on_event subscriptions from watched_bits() / regs().timer (called after
  // every change of the mode, the mask or the period).
  std::function<void()> resubscribe;

  GtCode event_mode();                      // GT_EvntIntr (L2219-2223, L3361-3373)
  GtCode timer_mode();                      // GT_TmrIntr (L5054-5074)
  GtCode set_timer(double periods);         // GT_SetIntrTm, 0..32767 servo periods (L4787-4801)
  GtCode set_mask(double mask);             // GT_SetIntrMsk on the current axis, 0..0xFFFF (bits 0-6 used)
  int mask_of_current_axis() const;         // GT_GetIntrMsk
  // GT_GetIntr (L3787-3799): the status of the interrupting axis (of the current one with nothing pending); 0 in
  // timer mode.
  std::uint16_t status() const;
  GtCode reset_request(double mask);        // GT_RstIntr (Table 8-1, L2235-2243, L4534-4555)
  GtCode clear(double card_no);             // GT_ClearInt(CardNo) (L3089-3122): 0 only; serves a timer request
  std::optional<std::size_t> pending_axis() const;  // the interrupting axis, if an event request is pending

  // What the dialect subscribes to: in timer mode the period (0: nothing); in event mode, per axis, the enabled
  // status bits 0-6 (the dialect maps them to card events).
  bool timer_active() const { return r_.mode == GtInterruptMode::Timer; }
  std::array<int, 4> watched_bits() const;
  void set_subscriptions(std::vector<long long> ids) { r_.subscriptions = std::move(ids); }

  void request();   // a watched event latched (or the mask changed): raise while an enabled bit is set
  void timer();     // the timer subscription fired

 private:
  std::optional<std::size_t> level() const;  // the lowest axis with an enabled status bit set
  void call_isr();

  GtCard& gt_;
  GtInterruptRegs r_{};
};

}  // namespace servobench::vendor::googol
