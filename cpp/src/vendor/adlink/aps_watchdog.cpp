#include "servobench/vendor/adlink/aps_watchdog.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_outputs.hpp"

namespace servobench::vendor::adlink {

namespace {
bool whole(double v) { return std::isfinite(v) && v == std::floor(v); }
}  // namespace

void ApsWatchdog::power_on() {
  period_ = action_ = 0;
  deadline_.reset();
  fired_ = false;
  if (card_.has_scope()) card_.scope().clear_vendor_watch(*this);
}

AdlinkCode ApsWatchdog::check(double board, double timer) {
  return board == 0 && timer == 0 ? AdlinkCode::NoError : AdlinkCode::ParametersInvalid;  // only timer 0 (L4069)
}

long long ApsWatchdog::timeout_ticks() const {
  return std::llround(period_ * kWdtUnitS / card_.servo_period_s());
}

AdlinkCode ApsWatchdog::set_action(double board, double timer, double bits) {
  if (check(board, timer) != AdlinkCode::NoError || !whole(bits) || bits < 0 || bits > 7)
    return AdlinkCode::ParametersInvalid;
  action_ = static_cast<int>(bits);
  return AdlinkCode::NoError;
}

AdlinkCode ApsWatchdog::action(double board, double timer, int& bits) const {
  bits = 0;
  if (const AdlinkCode c = check(board, timer); c != AdlinkCode::NoError) return c;
  bits = action_;
  return AdlinkCode::NoError;
}

AdlinkCode ApsWatchdog::start(double board, double timer, double time_out) {
  if (check(board, timer) != AdlinkCode::NoError || !whole(time_out) || time_out < 0 || time_out > 2147483647.0)
    return AdlinkCode::ParametersInvalid;
  period_ = static_cast<int>(time_out);
  fired_ = false;
  if (period_ > 0) {
    deadline_ = card_.tick() + timeout_ticks();
    machine::EventWatch w;  // checked every motion cycle of 1 ms (AF16)
    w.timer_ticks = std::max<long long>(1, std::llround(1e-3 / card_.servo_period_s()));
    card_.scope().set_vendor_watch(*this, w);
  } else {
    deadline_.reset();
    if (card_.has_scope()) card_.scope().clear_vendor_watch(*this);
  }
  return AdlinkCode::NoError;
}

AdlinkCode ApsWatchdog::period(double board, double timer, int& time_out) const {
  time_out = 0;
  if (const AdlinkCode c = check(board, timer); c != AdlinkCode::NoError) return c;
  time_out = period_;
  return AdlinkCode::NoError;
}

AdlinkCode ApsWatchdog::reset_counter(double board, double timer) {
  if (const AdlinkCode c = check(board, timer); c != AdlinkCode::NoError) return c;
  if (!deadline_) return AdlinkCode::FunctionNotAvailable;
  deadline_ = card_.tick() + timeout_ticks();
  return AdlinkCode::NoError;
}

void ApsWatchdog::on_watch(const machine::FiredEvent& e) {
  if (e.word != machine::WatchWord::Timer || !deadline_ || e.tick + 1 < *deadline_) return;  // tick() after e.tick
  deadline_.reset();
  fired_ = true;
  card_.scope().clear_vendor_watch(*this);
  if (action_ & kWdtServoOff) {
    for (std::size_t i = 0; i < card_.axis_count(); ++i) {
      try {
        aps_stop_modes(card_, i, true);
        if (card_.servo_on(i)) card_.axis_off(i);
      } catch (const std::logic_error&) {
        // a refused stop leaves the axis as it is; the next axes still go off
      }
    }
  }
  if (action_ & kWdtDoOff) aps_outputs(card_).all_do_off();
  if (action_ & kWdtPwmOff) aps_outputs(card_).all_pwm_off();
}

ApsWatchdog& aps_watchdog(machine::Card& card) { return card.module<ApsWatchdog>(); }

}  // namespace servobench::vendor::adlink
