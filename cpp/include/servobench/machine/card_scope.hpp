// CardScope: what the card does for the host besides motion (issue 10 point 3): the sampler (machine/sampler.hpp),
// the position compare with its trigger outputs (machine/position_compare.hpp), the event watch that ends a
// Card::run_until_event at the tick an enabled event fires (interrupts and Python callbacks), and the probe
// input EXI0 at a position. The Card creates it on first use and calls it once per tick after the axes (so a
// card that never uses it runs exactly as before, with one null-pointer test per tick).
//
// Event watch: per axis, masks over three words, each firing on a bit turning on (0 -> 1) between two ticks:
//   events  the latched CardEvent bits (GT status bits 0-7 order; GT event interrupts),
//   msts    the ADLINK motion status word (ICSTP, IVM, IACC, IDEC, IMDN, IASTP: MSTS bits 0-3, 5, 16),
//   mio     the ADLINK motion I/O word (IALM, IPEL, IMEL, IORG, IINP, IEMG, ISPEL, ISMEL: MIO bits 0-4, 6, 11, 12);
// card-wide the system word (ADLINK item 8: bit 0 EMG, 1/2 linear compare 0/1 ended, 3/4 table compare 0/1
// ended) and a timer (every N ticks: GT_TmrIntr). The vendor layouts of the interrupt factors are the dialects'.
// The vendor words (msts, mio, the GT status the sampler records) are functions a vendor module provides
// (set_words; vendor/scope_words.hpp): the scope calls them and knows no layout; unset words read 0.
//
// Vendor watches (session 12, decision AW4): a vendor module (a CardHooks) watches the same words with its own masks
// and timer (set_vendor_watch). Its events go to the module (CardHooks::on_watch) after every axis ran the tick they
// fired in -- not to fired(), and they do not end a run -- so a vendor's interrupt table or watchdog lives in C++
// beside the host's Card.on_event subscriptions without touching them. A module ends a run_until_event after the
// tick with request_stop() (the wait of an interrupt that came).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "servobench/machine/motion_loop.hpp"
#include "servobench/machine/position_compare.hpp"
#include "servobench/machine/sampler.hpp"
#include "servobench/machine/trace.hpp"

namespace servobench::machine {

class Card;
class CardHooks;

// A vendor status word of one card axis, a function of the card's state (vendor/adlink/aps_status.hpp ...).
using StatusWordFn = std::uint32_t (*)(const Card& card, std::size_t axis);
// The vendor words the scope samples (card_msts, card_mio, card_gt_status) and watches (msts, mio).
struct ScopeWords {
  StatusWordFn msts = nullptr;    // a motion status word (ADLINK MSTS)
  StatusWordFn mio = nullptr;     // a motion I/O word (ADLINK MIO)
  StatusWordFn status = nullptr;  // an axis status register (GT Table 4-14)
};

enum class WatchWord : int { Events = 0, Msts = 1, Mio = 2, System = 3, Timer = 4 };

// System word bits (ADLINK interrupt item 8, L4160-4180).
constexpr std::uint32_t kSysEmg = 1u << 0, kSysLcf0 = 1u << 1, kSysLcf1 = 1u << 2, kSysFcf0 = 1u << 3,
                        kSysFcf1 = 1u << 4;

// An event that fired: in the tick `tick` (counted from 0; the card's tick() is tick + 1 after it), on `axis`
// (-1: card-wide), in `word`, the bits that turned on (timer: 1).
struct FiredEvent {
  long long tick = 0;
  int axis = -1;
  WatchWord word = WatchWord::Events;
  std::uint32_t bits = 0;
};

// A vendor module's watch: per axis (shorter vectors: the missing axes 0) the bits of the three words, the system
// bits, and a timer event every timer_ticks ticks from when the watch is set (0: none), 0..1e9.
struct EventWatch {
  std::vector<std::uint32_t> events, msts, mio;
  std::uint32_t system = 0;
  long long timer_ticks = 0;
};

class CardScope {
 public:
  explicit CardScope(Card& card);

  Sampler& sampler() { return sampler_; }
  const Sampler& sampler() const { return sampler_; }
  // Starts the sampler now (the next tick run is its first candidate sample).
  void start_sampler(const SamplerConfig& config);
  PositionCompare& compare() { return compare_; }
  const PositionCompare& compare() const { return compare_; }

  // The vendor words (read again now for the watch); words() reports them.
  void set_words(const ScopeWords& words);
  const ScopeWords& words() const { return words_; }

  // -- event watch ------------------------------------------------------------------------------------------
  void set_watch(std::size_t axis, std::uint32_t events, std::uint32_t msts, std::uint32_t mio);
  void set_system_watch(std::uint32_t bits) { sys_mask_ = bits & 0x1Fu; }
  // A timer event every `ticks` servo ticks from now (0 = off), 0..1e9.
  void set_timer(double ticks);
  double timer_ticks() const { return static_cast<double>(timer_period_); }
  bool watching() const;
  const std::vector<FiredEvent>& fired() const { return fired_; }
  void clear_fired() { fired_.clear(); }

  // -- vendor watches (AW4) -----------------------------------------------------------------------------------
  // Sets (replaces) the watch of `owner` (a module attached to the card; it must outlive the watch or clear it).
  void set_vendor_watch(CardHooks& owner, const EventWatch& watch);
  void clear_vendor_watch(const CardHooks& owner);
  // Ends the present Card::run_until_event after this tick (called from CardHooks::on_watch).
  void request_stop() { stop_ = true; }
  // The run ends after this tick: a host event fired or a vendor module asked.
  bool run_ended() const { return stop_ || !fired_.empty(); }

  // -- probe input EXI0 at a position: fires when `axis`'s actual position passes `pos` (either direction) --
  void set_probe_position(std::size_t axis, double pos);
  void clear_probe_position() { probe_axis_ = -1; }
  int probe_axis() const { return probe_axis_; }
  double probe_pos() const { return probe_pos_; }

  // -- hooks (Card::tick_once) --------------------------------------------------------------------------------
  bool needs_signals(std::size_t axis) const { return sampler_.active() && any_need_[axis]; }
  // Points the trace fields the sampler needs at this tick's storage (the caller's buffer where it records).
  void bind_signals(std::size_t axis, Trace& tr, LoopTrace& lt);
  // The probe at a position (before the events are read): latches the axes armed for the probe. Returns the
  // axes whose capture latched (bit i).
  std::uint32_t probe(long long tick);
  // After every axis ran tick `tick`: compare, event watch, sampler.
  void after_tick(long long tick);
  // Re-reads the words the watch compares against (after the host changed the state between runs).
  void resync();
  // The card's reset (Card::reset): the sampler stops and drops its data, the position compare returns to its
  // power-on state (no points, outputs off, counters 0), the probe at a position and the fired list are cleared.
  // The event watch and the timer stay: they are the host's subscriptions (Python callbacks, a dialect's
  // interrupt masks, which the dialect's own reset clears), not card registers (V126).
  void reset_registers();

 private:
  double value(std::size_t axis, SampleSignal s) const;
  std::uint32_t word(StatusWordFn f, std::size_t axis) const { return f ? f(card_, axis) : 0u; }
  void refresh_need();
  void refresh_vendor();     // the union of the vendor masks, the words' reference values
  void dispatch_vendor(long long tick);

  Card& card_;
  std::size_t n_;
  ScopeWords words_{};
  Sampler sampler_;
  PositionCompare compare_;
  // per-axis scratch and read pointers for the sampled trace signals
  std::vector<std::array<double, kLoopSignalEnd>> scratch_;
  std::vector<std::array<const double*, kLoopSignalEnd>> ptr_;
  std::vector<bool> any_need_;
  std::vector<double> prev_actual_, prev_command_, prev_error_;
  std::vector<std::uint32_t> prev_events_, prev_msts_, prev_mio_;
  std::vector<std::uint32_t> w_events_, w_msts_, w_mio_;
  std::uint32_t sys_mask_ = 0;
  bool prev_estop_ = false;
  long long timer_period_ = 0, timer_start_ = 0;
  std::vector<FiredEvent> fired_;
  struct VendorWatch {
    CardHooks* owner = nullptr;
    EventWatch watch;
    long long timer_start = 0;
  };
  std::vector<VendorWatch> vendor_;
  std::vector<std::uint32_t> v_events_, v_msts_, v_mio_;  // union of the vendor masks per axis
  std::uint32_t v_sys_ = 0;
  std::vector<FiredEvent> vendor_fired_;                    // this tick's events for the vendor watches
  bool stop_ = false;
  int probe_axis_ = -1;
  double probe_pos_ = 0.0;
  std::vector<double> values_;
};

}  // namespace servobench::machine
