// ApsWatchdog: the ADLINK PCI-8254/8258 watchdog timer (manual seed 004 L4025-4084; decisions AF16, session 12:
// AW5) as a card module: its time-out, its action event and the deadline, checked by the module's own timer watch
// on the card's scope (machine/card_scope.hpp set_vendor_watch: every motion cycle, 1 ms of card time, AF16).
//
// APS_wdt_start(board, 0, time_out) arms it with a time-out of time_out x 100 ms of card time (10 -> 1 s, L4070);
// 0 disables it. If the program does not call APS_wdt_reset_counter within the time-out, the action event is carried
// out once and the watchdog stops (a reset after that: FunctionNotAvailable): bit 0 servo off on every axis (a moving
// interpolation group stops, a gear is released first), bit 1 the digital outputs off, bit 2 the PWM (VAO) outputs
// off (L4071-4074; vendor/adlink/aps_outputs.hpp). Only timer 0 (L4069). Every function returns the APS code and
// never throws.
#pragma once

#include <optional>

#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

constexpr int kWdtServoOff = 0x1, kWdtDoOff = 0x2, kWdtPwmOff = 0x4;  // WDT_ACTION_* (L4072-4074)
constexpr double kWdtUnitS = 0.1;                                       // time_out unit, s (L4070)

class ApsWatchdog : public machine::CardHooks {
 public:
  explicit ApsWatchdog(machine::Card& card) : card_(card) {}

  // APS_initial / APS_close: off, time-out 0, action 0, no watch.
  void power_on();
  // APS_wdt_set_action_event (L4037): bits 0..7 (WDT_ACTION_*).
  AdlinkCode set_action(double board, double timer, double bits);
  // APS_wdt_get_action_event (L4051).
  AdlinkCode action(double board, double timer, int& bits) const;
  // APS_wdt_start (L4041, L4053): time_out 0..2^31-1 x 100 ms; 0 disables.
  AdlinkCode start(double board, double timer, double time_out);
  // APS_wdt_get_timeout_period (L4043): x 100 ms.
  AdlinkCode period(double board, double timer, int& time_out) const;
  // APS_wdt_reset_counter (L4045, L4058): the time-out again from now; a watchdog off or fired: FunctionNotAvailable.
  AdlinkCode reset_counter(double board, double timer);
  bool armed() const { return deadline_.has_value(); }
  bool fired() const { return fired_; }

  void on_watch(const machine::FiredEvent& e) override;

 private:
  static AdlinkCode check(double board, double timer);
  long long timeout_ticks() const;
  machine::Card& card_;
  int period_ = 0;                       // x 100 ms
  int action_ = 0;
  std::optional<long long> deadline_;   // card tick at which the action is carried out
  bool fired_ = false;
};

// The card's ADLINK watchdog, created and attached on first use (owned by the card).
ApsWatchdog& aps_watchdog(machine::Card& card);

}  // namespace servobench::vendor::adlink
