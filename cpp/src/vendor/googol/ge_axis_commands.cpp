// The GE per-axis and card commands on the kernel, with their argument checks (vendor/googol/ge_commands.hpp; GE
// manual seed 001 ch7, ranges L991, L5435-5786; decisions V87-V97, GW1-GW3). Each is a row name -> one function of
// (card, GE registers, variant, arguments); the checks come first, in the order the manual's code table implies: the
// axis number, then the value's range, then the card's own refusal.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <variant>

#include "servobench/machine/motion_loop.hpp"
#include "servobench/vendor/googol/ge_commands.hpp"
#include "servobench/vendor/googol/ge_list.hpp"
#include "servobench/vendor/googol/ge_registers.hpp"

namespace servobench::vendor::googol {

using machine::AxisMode;
using machine::Card;
using machine::CommandFault;

namespace {

struct Ctx {
  Card& card;
  GeRegisters& regs;
  GeVariant variant;
  const std::vector<double>& p;
};
using Impl = GeReply (*)(Ctx&);

bool int_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi && v == std::floor(v); }
bool real_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi; }

// Python's int(round(x)): to nearest, ties to even (the default rounding mode).
long long round_even(double x) { return static_cast<long long>(std::nearbyint(x)); }
// A position as the card's 32-bit register holds it: whole pulses wrapped two's-complement (issue 21.5).
double register32(double pulse) {
  return static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(round_even(pulse))));
}

// f() with the kernel's refusal as 1 and an invalid value as 7.
template <class F>
GeCode guarded(F&& f) {
  try {
    return f();
  } catch (const motion::MotionCommandRefused&) {  // machine::CardCommandRefused too: the kernel recorded it
    return GeCode::CommandError;
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  } catch (const std::domain_error&) {
    return GeCode::ParameterError;
  }
}

// A per-axis command: 7 for a bad axis number or for `ok` false (recording `fault` on the axis), else f(a).
template <class F>
GeReply axis_cmd(Ctx& c, F&& f, bool ok = true, CommandFault fault = CommandFault::IllegalControlParam) {
  const auto a = c.regs.axis(c.p.at(0));
  if (!a) return {GeCode::ParameterError};
  if (!ok) {
    c.card.record_fault(static_cast<int>(*a), fault);
    return {GeCode::ParameterError};
  }
  return {guarded([&] { return f(*a); })};
}

// A void kernel command of an axis.
template <class F>
GeReply axis_do(Ctx& c, F&& f, bool ok = true, CommandFault fault = CommandFault::IllegalControlParam) {
  return axis_cmd(c, [&](std::size_t a) { f(a); return GeCode::Success; }, ok, fault);
}

// A card-wide command: 7 for `ok` false (recording IllegalControlParam), else f().
template <class F>
GeReply card_do(Ctx& c, F&& f, bool ok = true) {
  if (!ok) {
    c.card.record_fault(-1, CommandFault::IllegalControlParam);
    return {GeCode::ParameterError};
  }
  return {guarded([&] { f(); return GeCode::Success; })};
}

// A read of an axis: (7, 0) for a bad axis number, else (0, f(a)).
template <class F>
GeReply axis_read(Ctx& c, F&& f, bool integer) {
  const auto a = c.regs.axis(c.p.at(0));
  if (!a) return {GeCode::ParameterError, 0.0, true, true};
  return {GeCode::Success, static_cast<double>(f(*a)), integer, true};
}

// A read of the card: (0, word).
GeReply card_read(double word) { return {GeCode::Success, word, true, true}; }

// A refusal decided here: the cause recorded (axis status bit 7, GT_GetCmdSts), 1.
GeCode refuse(Ctx& c, std::size_t a, CommandFault fault) {
  c.card.record_fault(static_cast<int>(a), fault);
  return GeCode::CommandError;
}

double ms_per_tick(const Card& card) { return card.servo_period_s() / 1e-3; }

control::GtServoLawParams staged_law(const Card& card, std::size_t a) {
  const auto* law = std::get_if<control::GtServoLawParams>(&card.state(a).staged.law);
  if (law == nullptr) throw std::invalid_argument("GE: the axis does not run the GT-lineage servo law (V87)");
  return *law;
}

// GT_SetKp ... GT_SetMtrBias: the staged law with one field changed (fractional gains, V87); refused on a pulse
// axis (SX cmd bit 6, L333).
GeReply set_law(Ctx& c, double control::GtServoLawParams::*field, bool ok) {
  return axis_cmd(c, [&](std::size_t a) {
    if (c.regs.refuse_on_pulse_axis(a)) return GeCode::CommandError;
    control::GtServoLawParams law = staged_law(c.card, a);
    law.fractional_gains = true;
    law.*field = c.p.at(1);
    c.card.stage_law(a, law);
    return GeCode::Success;
  }, ok);
}

GeReply get_law(Ctx& c, double control::GtServoLawParams::*field, bool integer) {
  return axis_read(c, [&](std::size_t a) {
    const double v = staged_law(c.card, a).*field;
    return integer ? std::trunc(v) : v;
  }, integer);
}

// GT_SetVel/Acc/MAcc/Jerk: GE units (pulse/ms^order), staged per tick (on Update).
GeReply set_motion(Ctx& c, GeMotionRegister r, double lo, double hi) {
  const double v = c.p.at(1);
  return axis_do(c, [&](std::size_t a) { c.regs.stage_motion(a, r, v, ms_per_tick(c.card)); }, real_in(v, lo, hi),
                 CommandFault::MotionParamOverflow);
}

GeReply get_motion(Ctx& c, GeMotionRegister r) {
  return axis_read(c, [&](std::size_t a) { return c.regs.read_motion(a, r, ms_per_tick(c.card)); }, false);
}

void set_limits_enabled(Card& card, std::size_t a, bool on) {
  machine::LimitConfig lim = card.state(a).limits;
  lim.enabled = on;
  card.set_limits(a, lim);
}

// [sx-path] ZeroPos / SetAtlPos on an SX crd axis at rest: the crd is rebuilt by the next path command (V112).
void leave_crd(Ctx& c, std::size_t a) {
  if (c.variant == GeVariant::SX) ge_list(c.card).leave_crd(a);
}

GeCode alarm(Ctx& c, std::size_t a, bool on) {
  // SX: illegal with the servo on (cmd bit 3)
  if (c.variant == GeVariant::SX && c.card.servo_on(a)) return refuse(c, a, CommandFault::MotorStateWhileEnabled);
  c.card.set_alarm_enabled(a, on);
  return GeCode::Success;
}

GeCode loop(Ctx& c, std::size_t a, bool closed) {
  if (c.card.servo_on(a)) return refuse(c, a, CommandFault::AxisStateError);  // the servo must be off
  c.card.set_closed_loop(a, closed);
  return GeCode::Success;
}

using L = control::GtServoLawParams;

const std::unordered_map<std::string, Impl>& commands() {
  static const std::unordered_map<std::string, Impl> table = {
      // -- 7.1 system
      {"GT_GetCmdSts", [](Ctx& c) { return card_read(double(ge_command_status(c.variant, c.card))); }},
      // -- 7.2 axis configuration
      {"GT_AxisOn", [](Ctx& c) { return axis_do(c, [&](std::size_t a) {
         c.card.axis_on(a);
         if (!c.card.moving(a)) c.card.synch_pos_now(a);
       }); }},
      {"GT_AxisOff", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.axis_off(a); }); }},
      {"GT_DrvRst", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.drive_reset(a); }); }},
      {"GT_AlarmOn", [](Ctx& c) { return axis_cmd(c, [&](std::size_t a) { return alarm(c, a, true); }); }},
      {"GT_AlarmOff", [](Ctx& c) { return axis_cmd(c, [&](std::size_t a) { return alarm(c, a, false); }); }},
      {"GT_LmtsOn", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { set_limits_enabled(c.card, a, true); }); }},
      {"GT_LmtsOff", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { set_limits_enabled(c.card, a, false); }); }},
      {"GT_LmtSns", [](Ctx& c) { return GeReply{c.regs.set_sense(GeSense::Limit, c.p.at(0))}; }},
      {"GT_HomeSns", [](Ctx& c) { return GeReply{c.regs.set_sense(GeSense::Home, c.p.at(0))}; }},
      {"GT_IndexSns", [](Ctx& c) { return GeReply{c.regs.set_sense(GeSense::Index, c.p.at(0))}; }},
      {"GT_EncSns", [](Ctx& c) { return GeReply{c.regs.set_sense(GeSense::Encoder, c.p.at(0))}; }},
      {"GT_EncOn", [](Ctx& c) { return GeReply{c.regs.set_encoder(c.p.at(0), true)}; }},
      {"GT_EncOff", [](Ctx& c) { return GeReply{c.regs.set_encoder(c.p.at(0), false)}; }},
      {"GT_CtrlMode", [](Ctx& c) { return GeReply{c.regs.set_ctrl_mode(c.p.at(0), c.p.at(1))}; }},
      {"GT_StepDir", [](Ctx& c) { return GeReply{c.regs.set_step_form(c.p.at(0), false)}; }},
      {"GT_StepPulse", [](Ctx& c) { return GeReply{c.regs.set_step_form(c.p.at(0), true)}; }},
      {"GT_CloseLp", [](Ctx& c) { return axis_cmd(c, [&](std::size_t a) { return loop(c, a, true); }); }},
      {"GT_OpenLp", [](Ctx& c) { return axis_cmd(c, [&](std::size_t a) { return loop(c, a, false); }); }},
      {"GT_SetMtrCmd", [](Ctx& c) {  // -32768 is driven as -32767 (V95)
         const double v = c.p.at(1);
         return axis_do(c, [&](std::size_t a) { c.card.set_mtr_cmd(a, std::max(v, -32767.0)); },
                        int_in(v, -32768, 32767));
       }},
      {"GT_GetMtrCmd", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return std::trunc(c.card.state(a).mtr_cmd); }, true); }},
      {"GT_AuStpOn", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.set_auto_stop(a, true); }); }},
      {"GT_AuStpOff", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.set_auto_stop(a, false); }); }},
      // -- 7.3 point-to-point profile (PX)
      {"GT_PrflT", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.set_mode(a, AxisMode::TCurve); }); }},
      {"GT_PrflS", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.set_mode(a, AxisMode::SCurve); }); }},
      {"GT_PrflV", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.set_mode(a, AxisMode::Jog); }); }},
      {"GT_SetPos", [](Ctx& c) {
         const double pos = c.p.at(1);
         return axis_do(c, [&](std::size_t a) { c.card.stage_pos(a, pos); }, int_in(pos, kGePosMin, kGePosMax),
                        CommandFault::MotionParamOverflow);
       }},
      {"GT_GetPos", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return std::trunc(c.card.state(a).staged.pos); }, true); }},
      {"GT_SetVel", [](Ctx& c) {  // -40958 only in velocity mode (L1202-1206)
         const auto a = c.regs.axis(c.p.at(0));
         if (!a) return GeReply{GeCode::ParameterError};
         const double lo = c.card.state(*a).mode == AxisMode::Jog ? kGeVelMinJog : 0.0;
         return set_motion(c, GeMotionRegister::Vel, lo, kGeVelMax);
       }},
      {"GT_GetVel", [](Ctx& c) { return get_motion(c, GeMotionRegister::Vel); }},
      {"GT_SetAcc", [](Ctx& c) { return set_motion(c, GeMotionRegister::Acc, 0, kGeAccMax); }},
      {"GT_GetAcc", [](Ctx& c) { return get_motion(c, GeMotionRegister::Acc); }},
      {"GT_SetMAcc", [](Ctx& c) { return set_motion(c, GeMotionRegister::MAcc, 0, kGeAccMax); }},
      {"GT_GetMAcc", [](Ctx& c) { return get_motion(c, GeMotionRegister::MAcc); }},
      {"GT_SetJerk", [](Ctx& c) { return set_motion(c, GeMotionRegister::Jerk, 0, kGeJerkMax); }},
      {"GT_GetJerk", [](Ctx& c) { return get_motion(c, GeMotionRegister::Jerk); }},
      {"GT_Update", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.update(1u << a); }); }},
      {"GT_MltiUpdt", [](Ctx& c) {
         const double mask = c.p.at(0);
         return card_do(c, [&] {
           c.card.update(static_cast<std::uint32_t>(mask) & ((1u << c.card.axis_count()) - 1u)); },
           int_in(mask, 0, 0xFFFF));
       }},
      {"GT_SmthStp", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.smooth_stop(a); }); }},
      {"GT_AbptStp", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { c.card.abrupt_stop(a); }); }},
      {"GT_GetMode", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return ge_mode_register(c.card, a); }, true); }},
      // -- 7.4 position, velocity and error feedback
      {"GT_ZeroPos", [](Ctx& c) { return axis_do(c, [&](std::size_t a) { leave_crd(c, a); c.card.zero_pos(a); }); }},
      {"GT_SetAtlPos", [](Ctx& c) {
         const double pos = c.p.at(1);
         return axis_do(c, [&](std::size_t a) { leave_crd(c, a); c.card.set_actual_pos(a, pos); },
                        int_in(pos, kGePosMin, kGePosMax), CommandFault::MotionParamOverflow);
       }},
      {"GT_GetAtlPos", [](Ctx& c) {  // with the encoder off, the profile position (L4180)
         return axis_read(c, [&](std::size_t a) {
           return register32(c.regs.at(a).encoder_on ? c.card.actual_pos(a) : double(c.card.profile_pos(a)));
         }, true);
       }},
      {"GT_GetPrfPos", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return register32(double(c.card.profile_pos(a))); }, true); }},
      {"GT_GetAtlErr", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return round_even(c.card.following_error(a)); }, true); }},
      {"GT_GetPrfVel", [](Ctx& c) {  // PX GT_GetPrfVel(axis), pulse/ms (L4713)
         return axis_read(c, [&](std::size_t a) { return c.card.profile_vel(a) / ms_per_tick(c.card); }, false); }},
      {"GT_GetAtlVel", [](Ctx& c) { return axis_read(c, [&](std::size_t a) { return c.regs.actual_vel(a); }, false); }},
      // -- 7.5 servo parameters (on Update)
      {"GT_SetKp", [](Ctx& c) { return set_law(c, &L::kp, real_in(c.p.at(1), 0, kGeGainMax)); }},
      {"GT_SetKi", [](Ctx& c) { return set_law(c, &L::ki, real_in(c.p.at(1), 0, kGeGainMax)); }},
      {"GT_SetKd", [](Ctx& c) { return set_law(c, &L::kd, real_in(c.p.at(1), 0, kGeGainMax)); }},
      {"GT_SetKvff", [](Ctx& c) { return set_law(c, &L::kvff, real_in(c.p.at(1), 0, kGeGainMax)); }},
      {"GT_SetKaff", [](Ctx& c) { return set_law(c, &L::kaff, real_in(c.p.at(1), 0, kGeGainMax)); }},
      {"GT_SetILmt", [](Ctx& c) { return set_law(c, &L::ilmt, int_in(c.p.at(1), 0, 32767)); }},
      {"GT_SetMtrLmt", [](Ctx& c) { return set_law(c, &L::mtr_lmt, int_in(c.p.at(1), 0, 32767)); }},
      {"GT_SetMtrBias", [](Ctx& c) { return set_law(c, &L::bias, int_in(c.p.at(1), -32768, 32767)); }},
      {"GT_SetPosErr", [](Ctx& c) {
         const double v = c.p.at(1);
         return axis_do(c, [&](std::size_t a) { c.card.stage_pos_err(a, v); }, int_in(v, 0, 32767));
       }},
      {"GT_GetKp", [](Ctx& c) { return get_law(c, &L::kp, false); }},
      {"GT_GetKi", [](Ctx& c) { return get_law(c, &L::ki, false); }},
      {"GT_GetKd", [](Ctx& c) { return get_law(c, &L::kd, false); }},
      {"GT_GetKvff", [](Ctx& c) { return get_law(c, &L::kvff, false); }},
      {"GT_GetKaff", [](Ctx& c) { return get_law(c, &L::kaff, false); }},
      {"GT_GetILmt", [](Ctx& c) { return get_law(c, &L::ilmt, true); }},
      {"GT_GetMtrLmt", [](Ctx& c) { return get_law(c, &L::mtr_lmt, true); }},
      {"GT_GetMtrBias", [](Ctx& c) { return get_law(c, &L::bias, true); }},
      {"GT_GetPosErr", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return std::trunc(c.card.state(a).staged.pos_err); }, true); }},
      {"GT_GetIntgr", [](Ctx& c) {  // the error integral as a short
         return axis_read(c, [&](std::size_t a) {
           return std::clamp<long long>(round_even(c.card.axis(a).law_error_sum()), -32768, 32767); }, true);
       }},
      // -- 7.6 status
      {"GT_GetSts", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) -> double {
           return c.variant == GeVariant::PX ? ge_px_axis_status(c.card, a) : ge_sx_axis_status(c.card, a); }, true);
       }},
      {"GT_ClrSts", [](Ctx& c) {
         return axis_do(c, [&](std::size_t a) { c.card.clear_events(a, ge_events_to_clear(0)); }); }},
      {"GT_RstSts", [](Ctx& c) {
         const double mask = c.p.at(1);
         return axis_do(c, [&](std::size_t a) {
           c.card.clear_events(a, ge_events_to_clear(static_cast<std::uint16_t>(mask))); }, int_in(mask, 0, 0xFFFF));
       }},
      // -- 7.7 capture
      {"GT_CaptHome", [](Ctx& c) {
         return axis_do(c, [&](std::size_t a) { c.card.arm_capture(a, machine::CaptureTrigger::Home); }); }},
      {"GT_CaptIndex", [](Ctx& c) {
         return axis_do(c, [&](std::size_t a) { c.card.arm_capture(a, machine::CaptureTrigger::Index); }); }},
      {"GT_CaptProb", [](Ctx& c) { return card_do(c, [&] { c.card.arm_probe(); }); }},
      {"GT_GetCapt", [](Ctx& c) {
         return axis_read(c, [&](std::size_t a) { return round_even(c.card.loop(a).capture().value()); }, true); }},
      // -- 7.8 digital I/O
      {"GT_ExInpt", [](Ctx& c) { return card_read(double(c.regs.inputs())); }},
      {"GT_ExOpt", [](Ctx& c) {
         const double v = c.p.at(0);
         return card_do(c, [&] { ge_list(c.card).set_outputs(static_cast<std::uint32_t>(v)); }, int_in(v, 0, 0xFFFF));
       }},
      {"GT_GetLmtSwt", [](Ctx& c) { return card_read(double(c.regs.limit_levels())); }},
      {"GT_GetHomeSwt", [](Ctx& c) { return card_read(double(c.regs.home_levels())); }},
      {"GT_SetAdcChn", [](Ctx& c) { return GeReply{c.regs.set_adc_channels(c.p.at(0))}; }},
  };
  return table;
}

}  // namespace

std::vector<std::string> ge_axis_command_names() {
  std::vector<std::string> names;
  for (const auto& [name, impl] : commands()) names.push_back(name);
  return names;
}

GeReply ge_command(Card& card, GeVariant variant, const std::string& name, const std::vector<double>& args) {
  const auto it = commands().find(name);
  if (it == commands().end()) throw std::invalid_argument("ge_command: '" + name + "' is not a GE card command");
  Ctx c{card, ge_registers(card), variant, args};
  return it->second(c);
}

}  // namespace servobench::vendor::googol
