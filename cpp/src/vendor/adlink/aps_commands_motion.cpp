// The APS runner's motion chapter (aps_commands.hpp): servo on/off (L1603), the axis parameters (PRA_*, L1746-1762),
// point to point (APS_ptp / _v / _all, relative / absolute move, L2716-2767, L3686-3691), the synchronous start
// (L3787-3790), homing (L2246-2556), jog (L2645-2708), velocity moves and stops (L2566-2584), the gear (L3294-3346),
// positions and counters (L2056-2099) and the status reads (L3168, L3611). Decisions AY1-AY3; the checks are the
// ones the dialect made (AF1-AF24, V27-V49), in the same order.
#include <cmath>
#include <cstdint>

#include "aps_commands_detail.hpp"
#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"

namespace servobench::vendor::adlink::detail {

namespace {

using C = AdlinkCode;
using machine::AxisMode;
using machine::Card;
using motion::AdlinkPtpParams;

// A position register as the card's I32 holds it: whole pulses, wrapped two's-complement (issue 21.5).
double register32(double pulse) {
  const auto v = static_cast<long long>(std::nearbyint(pulse));
  return static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(v))));
}

// An axis read: (code, value) with 0 when the axis is bad.
template <class F>
ApsReply read_axis(const Call& c, const char* kind, F&& value) {
  const auto i = c.axis(0);
  if (!i) return ApsReply{c.bad(), {0.0}, kind};
  return ApsReply{C::NoError, {value(*c.card, *i)}, kind};
}

// -- axis parameters ----------------------------------------------------------------------------------------------
ApsReply set_param_f(const Call& c) {
  const auto i = c.axis(0);
  const double v = c.num(2);
  if (!i || !std::isfinite(v)) return code(c.bad());
  return code(c.prm().set(*i, c.num(1), v));
}
ApsReply set_param(const Call& c) { return whole(c.num(2)) ? set_param_f(c) : code(c.bad()); }
ApsReply get_param(const Call& c, const char* kind) {
  const auto i = c.axis(0);
  if (!i) return ApsReply{c.bad(), {0.0}, kind};
  double v = 0.0;
  const C rtn = c.prm().get(*i, c.num(1), v);
  return ApsReply{rtn, {kind[0] == 'i' ? std::trunc(v) : v}, kind};
}

// -- point to point -----------------------------------------------------------------------------------------------
struct Speeds {  // an APS_ptp_all call's speeds (pulse/s, pulse/s^2, S-factor), NaN where not given
  double vs = kNaN, ve = kNaN, acc = kNaN, dec = kNaN, sf = kNaN;
  bool given = false;
};

// One PTP of axis i to target at vm (pulse/s), every check before anything changes.
C ptp(const Call& c, std::size_t i, double target, double vm, bool wait, const Speeds& s = {}) {
  if (!whole(target) || std::fabs(target) > kPosMax) return C::ParametersInvalid;
  if (!std::isfinite(vm) || !(vm > 0 && vm <= 1e9)) return C::ParametersInvalid;
  AdlinkPtpParams p = c.prm().axis(i).motion;
  if (s.given) {
    auto in = [](double v, double hi) { return std::isfinite(v) && v >= 0 && v <= hi; };
    if (!in(s.vs, 1e9) || !in(s.ve, 1e9) || !in(s.acc, 1e12) || !in(s.dec, 1e12) || !in(s.sf, 1.0))
      return C::ParametersInvalid;
    p.vs = s.vs, p.ve = s.ve, p.acc = s.acc, p.dec = s.dec, p.sf = s.sf;
  }
  p.pos = target;
  p.vm = vm;
  if (!valid(p)) return C::ParametersInvalid;
  Card& k = *c.card;
  aps_release_axis(k, i);
  return run(k, [&] { wait ? adlink(k).move_ptp_wait(i, p) : adlink(k).move_ptp(i, p); });
}

ApsReply relative_move(const Call& c) {
  const auto i = c.axis(0);
  const double d = c.num(1);
  if (!i || !std::isfinite(d)) return code(c.bad());
  const double target = whole(d) ? static_cast<double>(c.card->profile_pos(*i)) + d : kNaN;
  return code(ptp(c, *i, target, c.num(2), false));
}

ApsReply absolute_move(const Call& c) {
  const auto i = c.axis(0);
  return i ? code(ptp(c, *i, c.num(1), c.num(2), false)) : code(c.bad());
}

// APS_ptp*(Axis_ID, Option, Position, ..., Wait): the axis, the target and MF_WAIT, or the code.
struct Option {
  C rtn = C::NoError;
  std::size_t i = 0;
  double target = 0.0;
  bool wait = false;
};
Option option(const Call& c, std::size_t wait_arg) {
  const auto i = c.axis(0);
  const double o = c.num(1), pos = c.num(2);
  if (!i || !whole(o) || !std::isfinite(pos) || !c.wait_ok(wait_arg)) return {c.bad()};
  const auto bits = std::fabs(o) > 4294967295.0 ? ~0LL : static_cast<long long>(o);
  if (bits & ~(1LL | kMfWait)) return {C::FunctionNotAvailable};  // the buffer modes (bits 12-15) (V32)
  if (!whole(pos) || std::fabs(pos) > kPosMax) return {C::ParametersInvalid};
  const double target = (bits & 1) ? static_cast<double>(c.card->profile_pos(*i)) + pos : pos;
  return {C::NoError, *i, target, (bits & kMfWait) != 0};
}

ApsReply ptp_prm(const Call& c) {
  const Option o = option(c, 3);
  if (o.rtn != C::NoError) return code(o.rtn);
  return code(ptp(c, o.i, o.target, c.prm().axis(o.i).motion.vm, o.wait));
}
ApsReply ptp_v(const Call& c) {
  const Option o = option(c, 4);
  return o.rtn != C::NoError ? code(o.rtn) : code(ptp(c, o.i, o.target, c.num(3), o.wait));
}
ApsReply ptp_all(const Call& c) {  // Axis_ID, Option, Position, Vs, Vm, Ve, Acc, Dec, SFac, Wait
  const Option o = option(c, 9);
  if (o.rtn != C::NoError) return code(o.rtn);
  Speeds s{c.num(3), c.num(5), c.num(6), c.num(7), c.num(8), true};
  return code(ptp(c, o.i, o.target, c.num(4), o.wait, s));
}

ApsReply move_trigger(const Call& c) {  // Dimension, Axis_ID_Array
  if (c.card == nullptr) return code(C::DeviceNotInitial);
  Card& k = *c.card;
  const double d = c.num(0);
  const std::vector<double>& ids = c.vec(1);
  if (!whole(d) || d < 1 || d > static_cast<double>(k.axis_count()) || static_cast<double>(ids.size()) < d)
    return code(C::ParametersInvalid);
  std::uint32_t mask = 0;
  for (std::size_t n = 0; n < static_cast<std::size_t>(d); ++n) {
    const auto i = c.axis_of(ids[n]);
    if (!i) return code(C::ParametersInvalid);
    mask |= 1u << *i;
  }
  if (adlink_group_trigger(k, mask)) {  // a waiting interpolation starts with its reference axis (V115)
    for (std::size_t a : adlink_group(k)->array()) mask &= ~(1u << a);
    if (mask == 0) return code(C::NoError);
  }
  return code(run(k, [&] { adlink(k).move_trigger(mask); }));
}

// -- homing, jog, velocity, stops ---------------------------------------------------------------------------------
ApsReply home_move(const Call& c) {
  const auto i = c.axis(0);
  if (!i) return code(c.bad());
  const motion::AdlinkHomeParams p = c.prm().axis(*i).home;
  if (!valid(p)) return code(C::ParametersInvalid);  // validated before anything changes
  Card& k = *c.card;
  aps_release_axis(k, *i);
  return code(run(k, [&] { adlink(k).home(*i, p); }));
}

ApsReply jog_on(const Call& c) {
  const auto i = c.axis(0);
  if (!i || !c.flag(1)) return code(c.bad());
  Card& k = *c.card;
  const bool on = c.num(1) == 1.0;
  if (on && !k.loop(*i).jog_on()) {
    if (!jogging(k, *i)) {
      const motion::AdlinkJogParams p = c.prm().axis(*i).jog;
      if (!valid(p)) return code(C::ParametersInvalid);
      aps_release_axis(k, *i);
      const C rtn = run(k, [&] { adlink(k).jog(*i, p); });
      if (rtn != C::NoError) return code(rtn);
    }
    return code(run(k, [&] { adlink(k).set_jog_on(*i, true); }));
  }
  if (!on && k.loop(*i).jog_on()) return code(run(k, [&] { adlink(k).set_jog_on(*i, false); }));
  return code(C::NoError);
}

// A velocity move of axis i at the signed vel (pulse/s) with the PRA_* parameters p.
C velocity(const Call& c, std::size_t i, double vel, const AdlinkPtpParams& p) {
  Card& k = *c.card;
  aps_release_axis(k, i);
  if (!valid(p)) return C::ParametersInvalid;
  return run(k, [&] { adlink(k).move_velocity(i, vel, p); });
}

ApsReply velocity_move(const Call& c) {
  const auto i = c.axis(0);
  const double v = c.num(1);
  if (!i || !std::isfinite(v)) return code(c.bad());
  if (v == 0 || std::fabs(v) > 1e9) return code(C::ParametersInvalid);
  AdlinkPtpParams p = c.prm().axis(*i).motion;
  p.vm = std::fabs(v);
  return code(velocity(c, *i, v, p));
}

ApsReply vel(const Call& c) {  // Axis_ID, Dir, Vel, Wait
  const auto i = c.axis(0);
  const double v = c.num(2);
  if (!i || !std::isfinite(v) || !c.flag(1) || !c.wait_ok(3) || !(v > 0 && v <= 1e9)) return code(c.bad());
  AdlinkPtpParams p = c.prm().axis(*i).motion;
  p.vm = v;
  return code(velocity(c, *i, c.num(1) == 1.0 ? -v : v, p));
}

ApsReply vel_all(const Call& c) {  // Axis_ID, Option, Vs, Vm, Ve, Acc, Dec, SFac, Wait
  const auto i = c.axis(0);
  const double vs = c.num(2), vm = c.num(3), ve = c.num(4), acc = c.num(5), dec = c.num(6), sf = c.num(7);
  for (double x : {vs, vm, ve, acc, dec, sf})
    if (!std::isfinite(x)) return code(c.bad());
  if (!i || !c.flag(1) || !c.wait_ok(8)) return code(c.bad());
  if (!(vm > 0 && vm <= 1e9) || !(vs >= 0 && vs <= vm) || !(ve >= 0 && ve <= 1e9) || !(acc > 0 && acc <= 1e12) ||
      !(dec > 0 && dec <= 1e12) || !(sf >= 0 && sf <= 1))
    return code(C::ParametersInvalid);
  AdlinkPtpParams p = c.prm().axis(*i).motion;
  p.vs = vs, p.vm = vm, p.acc = acc, p.dec = dec, p.sf = sf;
  return code(velocity(c, *i, c.num(1) == 1.0 ? -vm : vm, p));
}

C stop_axis(Card& k, std::size_t i, bool abrupt) {
  if (aps_stop_modes(k, i, abrupt)) return C::NoError;  // a moving group stops whole, a gear slave releases
  if (abrupt) return run(k, [&] { k.abrupt_stop(i); });
  const AdlinkPtpParams p = aps_parameters(k).axis(i).motion;
  if (!valid(p)) return C::ParametersInvalid;
  return run(k, [&] { adlink(k).stop_move(i, p); });
}

template <bool Abrupt>
ApsReply stop(const Call& c) {
  const auto i = c.axis(0);
  return i ? code(stop_axis(*c.card, *i, Abrupt)) : code(c.bad());
}

template <bool Abrupt>
ApsReply stop_multi(const Call& c) {  // Dimension, Axis_ID_Array: every axis in the same tick
  if (c.card == nullptr) return code(C::DeviceNotInitial);
  const double d = c.num(0);
  const std::vector<double>& ids = c.vec(1);
  if (!whole(d) || d < 1 || d > static_cast<double>(c.card->axis_count()) || static_cast<double>(ids.size()) < d)
    return code(C::ParametersInvalid);
  std::vector<std::size_t> axes;
  for (std::size_t n = 0; n < static_cast<std::size_t>(d); ++n) {
    const auto i = c.axis_of(ids[n]);
    if (!i) return code(C::ParametersInvalid);
    axes.push_back(*i);
  }
  C rtn = C::NoError;
  for (std::size_t i : axes) {
    const C r = stop_axis(*c.card, i, Abrupt);
    if (r != C::NoError) rtn = r;
  }
  return code(rtn);
}

ApsReply servo_on(const Call& c) {
  const auto i = c.axis(0);
  if (!i || !c.flag(1)) return code(c.bad());
  Card& k = *c.card;
  if (c.num(1) == 0.0) {
    aps_stop_modes(k, *i, true);  // servo off releases a gear / stops an interpolation (L3325)
    return code(run(k, [&] { k.axis_off(*i); }));
  }
  return code(run(k, [&] { k.axis_on(*i); }));
}

ApsReply start_gear(const Call& c) {  // Axis_ID, Mode 0 off / 1 on / 2 gantry (not simulated)
  const auto i = c.axis(0);
  const double mode = c.num(1);
  if (!i || !(mode == 0 || mode == 1 || mode == 2)) return code(c.bad());
  Card& k = *c.card;
  if (mode == 0) {
    if (k.state(*i).mode != AxisMode::Gear) return code(C::NoError);
    return code(run(k, [&] { k.set_mode(*i, AxisMode::TCurve); }));
  }
  if (mode == 2) return code(C::FunctionNotAvailable);
  const ApsAxisRegisters& r = c.prm().axis(*i);
  const double master = std::trunc(r.gear_master);
  if (master == static_cast<double>(*i)) return code(C::ParametersInvalid);
  aps_release_modes(k, *i);
  const auto m = c.axis_of(master);  // a master that is no axis of the card: the card rejects it
  if (!m) return code(C::ParametersInvalid);
  const double ratio = r.gear_ratio, rate = r.gear_rate * k.servo_period_s();
  return code(run(k, [&] { k.modes().set_gear_ramp(*i, *m, ratio, rate); }));
}

// -- positions ----------------------------------------------------------------------------------------------------
ApsReply set_position(const Call& c) {
  const auto i = c.axis(0);
  const double p = c.num(1);
  if (!i || !whole(p) || std::fabs(p) > kPosMax) return code(c.bad());
  Card& k = *c.card;
  aps_release_modes(k, *i);
  return code(run(k, [&] { k.set_actual_pos(*i, p); }));
}

ApsReply set_command(const Call& c) {  // the command position set: the actual position moves with it (AF14)
  const auto i = c.axis(0);
  const double p = c.num(1);
  if (!i || !whole(p) || std::fabs(p) > kPosMax) return code(c.bad());
  Card& k = *c.card;
  aps_release_modes(k, *i);
  const double actual = k.actual_pos(*i) + (p - static_cast<double>(k.profile_pos(*i)));
  return code(run(k, [&] { k.set_actual_pos(*i, actual); }));
}

double actual32(Card& k, std::size_t i) { return register32(k.actual_pos(i)); }
double command32(Card& k, std::size_t i) { return register32(static_cast<double>(k.profile_pos(i))); }

ApsReply word(const Call& c, std::uint32_t (*w)(const Card&, std::size_t)) {
  const auto i = c.axis(0);
  return ApsReply{C::NoError, {i ? static_cast<double>(w(*c.card, *i)) : static_cast<double>(c.bad())}, "w"};
}

}  // namespace

const std::vector<Named>& motion_commands() {
  static const std::vector<Named> kRows = {
      {"APS_set_axis_param", {&set_param, "nnn", ""}},
      {"APS_set_axis_param_f", {&set_param_f, "nnn", ""}},
      {"APS_get_axis_param_f", {[](const Call& c) { return get_param(c, "f"); }, "nn", "f"}},
      {"APS_get_axis_param", {[](const Call& c) { return get_param(c, "i"); }, "nn", "i"}},
      {"APS_set_servo_on", {&servo_on, "nn", ""}},
      {"APS_relative_move", {&relative_move, "nnn", ""}},
      {"APS_absolute_move", {&absolute_move, "nnn", ""}},
      {"APS_ptp", {&ptp_prm, "nnnn", ""}},
      {"APS_ptp_v", {&ptp_v, "nnnnn", ""}},
      {"APS_ptp_all", {&ptp_all, "nnnnnnnnnn", ""}},
      {"APS_move_trigger", {&move_trigger, "na", ""}},
      {"APS_home_move", {&home_move, "n", ""}},
      {"APS_jog_on", {&jog_on, "nn", ""}},
      {"APS_velocity_move", {&velocity_move, "nn", ""}},
      {"APS_vel", {&vel, "nnnn", ""}},
      {"APS_vel_all", {&vel_all, "nnnnnnnnn", ""}},
      {"APS_stop_move", {&stop<false>, "n", ""}},
      {"APS_emg_stop", {&stop<true>, "n", ""}},
      {"APS_stop_move_multi", {&stop_multi<false>, "na", ""}},
      {"APS_emg_stop_multi", {&stop_multi<true>, "na", ""}},
      {"APS_start_gear", {&start_gear, "nn", ""}},
      {"APS_set_position", {&set_position, "nn", ""}},
      {"APS_set_command", {&set_command, "nn", ""}},
      {"APS_get_position", {[](const Call& c) { return read_axis(c, "i", actual32); }, "n", "i"}},
      {"APS_get_encoder", {[](const Call& c) { return read_axis(c, "i", actual32); }, "n", "i"}},
      {"APS_get_command", {[](const Call& c) { return read_axis(c, "i", command32); }, "n", "i"}},
      {"APS_get_command_counter", {[](const Call& c) { return read_axis(c, "i", command32); }, "n", "i"}},
      {"APS_get_command_f",
       {[](const Call& c) {
          return read_axis(c, "f", [](Card& k, std::size_t i) { return static_cast<double>(k.profile_pos(i)); });
        }, "n", "f"}},
      {"APS_get_error_position",
       {[](const Call& c) {
          return read_axis(c, "i", [](Card& k, std::size_t i) { return std::nearbyint(k.following_error(i)); });
        }, "n", "i"}},
      {"APS_get_stop_code",
       {[](const Call& c) {
          return read_axis(c, "i", [](Card& k, std::size_t i) { return double(aps_group_stop_code(k, i)); });
        }, "n", "i"}},
      {"APS_motion_status", {[](const Call& c) { return word(c, &aps_group_motion_status); }, "n", "w"}},
      {"APS_motion_io_status", {[](const Call& c) { return word(c, &aps_motion_io_status); }, "n", "w"}},
  };
  return kRows;
}

}  // namespace servobench::vendor::adlink::detail
