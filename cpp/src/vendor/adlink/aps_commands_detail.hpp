// What the chapters of the APS runner share (aps_commands.hpp): the call's view of its arguments and the card,
// the checks every function makes the same way, and the one mapping of a card's refusal to the APS code.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/motion/generator.hpp"
#include "servobench/vendor/adlink/aps_commands.hpp"
#include "servobench/vendor/adlink/aps_parameters.hpp"

namespace servobench::vendor::adlink::detail {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPosMax = 2147483647.0;  // I32 positions (L2728)
constexpr long long kMfWait = 0x100;       // Option bit 8, MF_WAIT (L3686-3691)

inline bool whole(double v) { return std::isfinite(v) && v == std::floor(v); }

// One call: the card (nullptr: none open) and the arguments.
struct Call {
  machine::Card* card;
  const ApsArgs& a;

  bool none(std::size_t k) const { return k >= a.size() || a[k].empty(); }
  // Argument k as a number: NaN when it is not one (absent, not a number, not finite, an array).
  double num(std::size_t k) const {
    return k < a.size() && a[k].size() == 1 && std::isfinite(a[k][0]) ? a[k][0] : kNaN;
  }
  const std::vector<double>& vec(std::size_t k) const { return a.at(k); }
  // Argument k is one of the values 0 / 1 (a flag: Servo_on, On, Dir, Option of APS_vel_all).
  bool flag(std::size_t k) const { return num(k) == 0.0 || num(k) == 1.0; }
  // ASYNCALL *Wait: only None or 0 (a synchronous call).
  bool wait_ok(std::size_t k) const { return none(k) || num(k) == 0.0; }
  // An axis ID 0..n-1 of the open card.
  std::optional<std::size_t> axis_of(double v) const {
    if (card == nullptr || !whole(v) || v < 0 || v >= static_cast<double>(card->axis_count())) return std::nullopt;
    return static_cast<std::size_t>(v);
  }
  std::optional<std::size_t> axis(std::size_t k) const { return axis_of(num(k)); }
  // A bad call: ERR_DeviceNotInitial without a card, else ERR_ParametersInvalid.
  AdlinkCode bad() const { return card == nullptr ? AdlinkCode::DeviceNotInitial : AdlinkCode::ParametersInvalid; }
  ApsParameters& prm() const { return aps_parameters(*card); }
};

// f() the APS way: a refusal as the fault the card recorded (code_of: EMG/ALM/limit ignored, M9 distance), a
// value the card rejects ERR_ParametersInvalid.
template <class F>
AdlinkCode run(machine::Card& card, F&& f) {
  try {
    f();
  } catch (const motion::MotionCommandRefused&) {  // machine::CardCommandRefused too
    return code_of(card.last_fault());
  } catch (const std::invalid_argument&) {
    return AdlinkCode::ParametersInvalid;
  } catch (const std::domain_error&) {
    return AdlinkCode::ParametersInvalid;
  } catch (const std::length_error&) {
    return AdlinkCode::ParametersInvalid;
  }
  return AdlinkCode::NoError;
}

// A parameter set checked as the manual's ranges (AdlinkPtpParams::validate ...): false when it throws.
template <class P>
bool valid(const P& p) {
  try {
    p.validate();
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

inline ApsReply code(AdlinkCode c) { return ApsReply{c, {}, {}}; }

using Impl = ApsReply (*)(const Call&);
struct Entry {
  Impl impl;
  const char* args;   // 'n' number / 'a' array per argument
  const char* reply;  // "" command, "w" word, else the read's kinds
};
struct Named {
  const char* name;
  Entry entry;
};

// The chapters' rows.
const std::vector<Named>& motion_commands();
const std::vector<Named>& interp_commands();
const std::vector<Named>& compare_commands();

}  // namespace servobench::vendor::adlink::detail
