// ApsInterrupts: the ADLINK PCI-8254/8258 host interrupts as a card module (manual seed 004 L4090-4330; decisions
// V81-V83): the main switch (APS_int_enable), the interrupt factors (APS_set_int_factor: item 0..7 an axis, 8 the
// system; the interrupt number is item x 32 + factor bit, V82), the signaled flags (APS_wait_single_int /
// APS_wait_multiple_int / APS_reset_int / APS_set_int) and the wait in progress. Session 11: AV4.
//
// The module keeps the table and watches the card itself (session 12, AW4): its masks (msts_mask / mio_mask per
// axis, system_mask) are its own vendor watch on the card's scope (machine/card_scope.hpp set_vendor_watch), set
// again whenever a factor changes, apart from the host's Card.on_event subscriptions; each fired event comes to
// on_watch -> fired(), and a wait whose condition holds ends the run (request_stop). Axis factors (L4120-4160) and
// the words they watch:
//   IALM 0 -> MIO ALM, IPEL 1 -> PEL, IMEL 2 -> MEL, IORG 3 -> ORG, IEZ 4 -> EZ, IINP 5 -> INP, IEMG 6 -> EMG,
//   ICSTP 8 -> MSTS CSTP, IVM 9 -> VM, IACC 10 -> ACC, IDEC 11 -> DEC, IMDN 12 -> MDN, IASTP 13 -> ASTP,
//   ISPEL 15 -> MIO SPEL, ISMEL 16 -> SMEL; IPRED 18 / IPOSTD 19 are not simulated (FunctionNotAvailable).
// System factors (item 8, L4160-4180): ISYS_EMG 0, ILCF0/1 1-2, IFCF0/1 3-4 (the card's system word); IMOV 5 and
// IHOV 6 are accepted and never fire. Items 9/10 (DI edges): the card has no digital inputs (FunctionNotAvailable).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

class ApsInterrupts : public machine::CardHooks {
 public:
  explicit ApsInterrupts(machine::Card& card) : card_(card) {}

  // APS_initial (and APS_close): main switch off, no factor enabled, no interrupt number known, no watch.
  void power_on();

  // APS_int_enable: 0 off, 1 on (ParametersInvalid otherwise). No event signals while off.
  AdlinkCode set_main(double enable);
  // APS_set_int_factor: the interrupt number (item x 32 + bit) or a negative code. Factor_No is the bit number; a
  // one-bit mask such as the examples' (1 << 12) is read as its bit (L4271-4274, V82).
  int set_factor(double item, double factor, double enable);
  // APS_get_int_factor: whether the factor is enabled.
  AdlinkCode factor_enabled(double item, double factor, int& enabled) const;

  // The watch the dialect subscribes: per axis the MSTS / MIO bits of the enabled factors, the system bits.
  std::uint32_t msts_mask(std::size_t axis) const;
  std::uint32_t mio_mask(std::size_t axis) const;
  std::uint32_t system_mask() const;
  // A watched event fired on `axis` (-1 card-wide) in `word` ("msts", "mio", "system"): the enabled factors it
  // matches are signaled, while the main switch is on.
  void fired(int axis, const std::string& word, std::uint32_t bits);
  // The module's vendor watch fired: fired(), and the run ends when the wait in progress is done.
  void on_watch(const machine::FiredEvent& e) override;

  // APS_set_int (on) / APS_reset_int (off) of a known interrupt number (ParametersInvalid otherwise).
  AdlinkCode set_signaled(double int_no, bool on);
  // APS_wait_multiple_int's start: the first `count` numbers of `nos`, all (wait_all 1) or any (0), time_out_ms
  // of card time (-1: one simulated hour, V83). ParametersInvalid, InterruptNotEnable (main switch or a factor
  // off) or NoError with max_ticks the ticks the wait may run.
  AdlinkCode begin_wait(double count, const std::vector<double>& nos, double wait_all, double time_out_ms,
                        long long& max_ticks);
  // The wait's condition holds (all / any of its numbers signaled).
  bool wait_done() const;

 private:
  static bool bit_of(double factor, long long& bit);  // the factor's bit (a one-bit mask read as its bit)
  void rewatch();                                               // the vendor watch of the enabled factors
  int set_factor_(double item, double factor, double enable);  // set_factor without the rewatch
  machine::Card& card_;
  bool main_ = false;
  std::set<int> enabled_;          // enabled interrupt numbers
  std::map<int, bool> signaled_;   // every number enabled once -> signaled
  std::vector<int> waiting_;       // the wait in progress
  bool wait_all_ = true;
};

// The card's ADLINK interrupt module, created and attached on first use (owned by the card).
ApsInterrupts& aps_interrupts(machine::Card& card);

}  // namespace servobench::vendor::adlink
