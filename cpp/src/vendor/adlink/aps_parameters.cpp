#include "servobench/vendor/adlink/aps_parameters.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include "servobench/machine/card_modes.hpp"
#include "servobench/vendor/adlink/adlink_axes.hpp"

namespace servobench::vendor::adlink {

namespace {

constexpr double kPosMax = 2147483647.0;

using namespace pra;  // the PRA_* numbers (aps_parameters.hpp)

// A stored parameter: its field, range, whole numbers only?
struct Field {
  int para;
  double lo, hi;
  bool integer;
};
constexpr Field kStored[] = {
    {SD_DEC, 0, 1e12, false}, {SF, 0, 1, false}, {ACC, 0, 1e12, false}, {DEC, 0, 1e12, false},
    {VS, 0, 1e9, false}, {VM, 0, 1e9, false}, {VE, 0, 1e9, false},
    {HOME_MODE, 0, 2, true}, {HOME_DIR, 0, 1, true}, {HOME_CURVE, 0, 1, false}, {HOME_ACC, 0, 1e12, false},
    {HOME_VM, 0, 1e9, false}, {HOME_SHIFT, -kPosMax, kPosMax, true}, {HOME_EZA, 0, 1, true},
    {HOME_VO, 0, 1e9, false}, {HOME_POS, -kPosMax, kPosMax, true},
    {JG_MODE, 0, 1, true}, {JG_DIR, 0, 1, true}, {JG_SF, 0, 1, false}, {JG_ACC, 0, 1e12, false},
    {JG_DEC, 0, 1e12, false}, {JG_VM, 0, 1e9, false}, {JG_OFFSET, 0, kPosMax, false}, {JG_DELAY, 0, 1e7, false},
    {GEAR_MASTER, 0, 7, true}, {GEAR_ENGAGE_RATE, 0, 1e9, false}, {GEAR_RATIO, -1e6, 1e6, false},
    {GANTRY_PROTECT_1, 0, kPosMax, true}, {GANTRY_PROTECT_2, 0, kPosMax, true},
};
const Field* stored(int para) {
  for (const Field& f : kStored)
    if (f.para == para) return &f;
  return nullptr;
}

// The stored value of a parameter of r (para one of kStored).
double* slot(ApsAxisRegisters& r, int para) {
  switch (para) {
    case SD_DEC: return &r.motion.sd_dec;
    case SF: return &r.motion.sf;
    case ACC: return &r.motion.acc;
    case DEC: return &r.motion.dec;
    case VS: return &r.motion.vs;
    case VM: return &r.motion.vm;
    case VE: return &r.motion.ve;
    case HOME_MODE: return &r.home.mode;
    case HOME_DIR: return &r.home.dir;
    case HOME_CURVE: return &r.home.curve;
    case HOME_ACC: return &r.home.acc;
    case HOME_VM: return &r.home.vm;
    case HOME_SHIFT: return &r.home.shift;
    case HOME_VO: return &r.home.vo;
    case HOME_POS: return &r.home.pos;
    case JG_MODE: return &r.jog.mode;
    case JG_DIR: return &r.jog.dir;
    case JG_SF: return &r.jog.sf;
    case JG_ACC: return &r.jog.acc;
    case JG_DEC: return &r.jog.dec;
    case JG_VM: return &r.jog.vm;
    case JG_OFFSET: return &r.jog.offset;
    case JG_DELAY: return &r.jog.delay_us;
    case GEAR_MASTER: return &r.gear_master;
    case GEAR_ENGAGE_RATE: return &r.gear_rate;
    case GEAR_RATIO: return &r.gear_ratio;
    case GANTRY_PROTECT_1: return &r.protect_1;
    case GANTRY_PROTECT_2: return &r.protect_2;
    default: return nullptr;
  }
}

// The servo-law parameters (L1746-1762): the ApsServoLawParams field, range, whole numbers only?
struct LawField {
  int para;
  double control::ApsServoLawParams::*field;
  double lo, hi;
  bool integer;
};
constexpr double kGainMax = 65535, kShift = 31;
const LawField kLaw[] = {
    {KP_GAIN, &control::ApsServoLawParams::kp, 0, kGainMax, true},
    {KI_GAIN, &control::ApsServoLawParams::ki, 0, kGainMax, true},
    {KD_GAIN, &control::ApsServoLawParams::kd, 0, kGainMax, true},
    {KVFF_GAIN, &control::ApsServoLawParams::kvff, 0, kGainMax, true},
    {KAFF_GAIN, &control::ApsServoLawParams::kaff, 0, kGainMax, true},
    {KP_SHIFT, &control::ApsServoLawParams::kp_shift, -kShift, kShift, true},
    {KI_SHIFT, &control::ApsServoLawParams::ki_shift, -kShift, kShift, true},
    {KD_SHIFT, &control::ApsServoLawParams::kd_shift, -kShift, kShift, true},
    {KVFF_SHIFT, &control::ApsServoLawParams::kvff_shift, -kShift, kShift, true},
    {KAFF_SHIFT, &control::ApsServoLawParams::kaff_shift, -kShift, kShift, true},
    {PID_SHIFT, &control::ApsServoLawParams::pid_shift, -kShift, kShift, true},
    {INTEGRAL_LIMIT, &control::ApsServoLawParams::integral_limit, 0, kPosMax, true},
    {SERVO_V_BIAS, &control::ApsServoLawParams::v_bias, 0, 10, false},
    {SERVO_V_LIMIT, &control::ApsServoLawParams::v_limit, 0, 10, false},
    {SERVO_V_INVERSE, nullptr, 0, 1, true},  // PRA_SERVO_V_INVERSE: the bool field
};
const LawField* law_field(int para) {
  for (const LawField& f : kLaw)
    if (f.para == para) return &f;
  return nullptr;
}

bool whole(double v) { return v == std::floor(v); }
bool in(double v, double lo, double hi, bool integer) { return v >= lo && v <= hi && (!integer || whole(v)); }

// Runs a card command: its refusal or bad argument as the APS code.
template <class F>
AdlinkCode run(F&& command) {
  try {
    command();
  } catch (const machine::CardCommandRefused& e) {
    return code_of(e.fault());
  } catch (const motion::MotionCommandRefused&) {
    return AdlinkCode::FunctionNotAvailable;
  } catch (const std::invalid_argument&) {
    return AdlinkCode::ParametersInvalid;
  }
  return AdlinkCode::NoError;
}

}  // namespace

AdlinkCode code_of(machine::CommandFault fault) {
  using machine::CommandFault;
  switch (fault) {
    case CommandFault::EmergencyStopActive:
    case CommandFault::DirectionInhibited:
    case CommandFault::DriveAlarmActive: return AdlinkCode::NoError;  // ignored (L3931-4010, V47)
    case CommandFault::DistanceTooShort: return AdlinkCode::DistantNotEnough;
    default: return AdlinkCode::FunctionNotAvailable;
  }
}

ApsParameters::ApsParameters(machine::Card& card) : card_(card) { power_on(); }

void ApsParameters::power_on() { axes_.assign(card_.axis_count(), ApsAxisRegisters{}); }

const ApsAxisRegisters& ApsParameters::axis(std::size_t i) const {
  card_.check_axis(i);
  return axes_[i];
}

AdlinkCode ApsParameters::set(std::size_t i, double para_f, double v) {
  if (i >= axes_.size() || !std::isfinite(v) || !std::isfinite(para_f) || !whole(para_f))
    return AdlinkCode::ParametersInvalid;
  const int para = static_cast<int>(para_f);
  ApsAxisRegisters& r = axes_[i];
  if (const LawField* f = law_field(para)) {
    if (!in(v, f->lo, f->hi, f->integer)) return AdlinkCode::ParametersInvalid;
    const auto* law = std::get_if<control::ApsServoLawParams>(&card_.state(i).staged.law);
    if (law == nullptr) return AdlinkCode::FunctionNotAvailable;  // an axis with the GT law has no PRA gains
    control::ApsServoLawParams p = *law;
    if (f->field != nullptr) p.*(f->field) = v;
    else p.v_inverse = v != 0;
    return run([&] {
      card_.stage_law(i, p);
      card_.update(1u << i);
    });
  }
  if (para >= GEAR_MASTER && para <= GANTRY_PROTECT_2) return set_gear(i, para, v);
  if (const Field* f = stored(para)) {
    if (!in(v, f->lo, f->hi, f->integer)) return AdlinkCode::ParametersInvalid;
    if (para == HOME_EZA) r.home.eza = v != 0;
    else *slot(r, para) = v;
    if (para == SD_DEC && v > 0) adlink(card_).set_limit_stop_mode(i, r.el_mode != 0, v);
    return AdlinkCode::NoError;
  }
  if (para >= JG_MAP_DI_EN && para <= JG_JOG_DI)  // DI-linked jog is not simulated: only 0 (V30)
    return v == 0 ? AdlinkCode::NoError : AdlinkCode::FunctionNotAvailable;
  if (para == EL_MODE) {
    if (v != 0 && v != 1) return AdlinkCode::ParametersInvalid;
    r.el_mode = static_cast<int>(v);
    const double dec = r.motion.sd_dec != 0 ? r.motion.sd_dec : 1e6;
    return run([&] { adlink(card_).set_limit_stop_mode(i, v != 0, dec); });
  }
  if (para == PRE_EVENT_DIST || para == POST_EVENT_DIST) {
    if (!in(v, 0, kPosMax, true)) return AdlinkCode::ParametersInvalid;
    const AdlinkAxisState& s = adlink_state(card_, i);
    const double pre = para == PRE_EVENT_DIST ? v : s.pre_event_dist;
    const double post = para == POST_EVENT_DIST ? v : s.post_event_dist;
    return run([&] { adlink(card_).set_move_event_distances(i, pre, post); });
  }
  if (para == ERR_POS_LEVEL) {
    if (!in(v, 0, kPosMax, true)) return AdlinkCode::ParametersInvalid;
    return run([&] { adlink(card_).set_error_level(i, v); });
  }
  if (para == EL_LOGIC || para == SPEL_EN || para == SMEL_EN || para == SPEL_POS || para == SMEL_POS) {
    const bool flag = para == EL_LOGIC || para == SPEL_EN || para == SMEL_EN;
    if (flag ? (v != 0 && v != 1) : !in(v, -kPosMax, kPosMax, true)) return AdlinkCode::ParametersInvalid;
    machine::LimitConfig l = card_.state(i).limits;
    if (para == EL_LOGIC) l.pos_active_low = l.neg_active_low = v != 0;
    if (para == SPEL_EN) l.soft_pos_enabled = v != 0;
    if (para == SMEL_EN) l.soft_neg_enabled = v != 0;
    if (para == SPEL_POS) l.soft_pos_pulse = v;
    if (para == SMEL_POS) l.soft_neg_pulse = v;
    return run([&] { card_.set_limits(i, l); });
  }
  return AdlinkCode::ParametersInvalid;
}

AdlinkCode ApsParameters::set_gear(std::size_t i, int para, double v) {
  const Field* f = stored(para);
  if (f == nullptr || !in(v, f->lo, f->hi, f->integer)) return AdlinkCode::ParametersInvalid;
  if (para == GEAR_MASTER && v >= static_cast<double>(card_.axis_count())) return AdlinkCode::ParametersInvalid;
  const machine::CardModes* modes = card_.modes_if_any();
  const bool engaged =
      card_.state(i).mode == machine::AxisMode::Gear && !(modes != nullptr && modes->gear_halted(i));
  if (para == GEAR_MASTER && engaged) return AdlinkCode::FunctionNotAvailable;  // the master stays (V119)
  ApsAxisRegisters& r = axes_[i];
  *slot(r, para) = v;
  if (para == GEAR_RATIO && engaged)  // on the fly, ramped (L3311)
    return run([&] { card_.modes().gear_ramp_to(i, v, r.gear_rate * card_.servo_period_s()); });
  return AdlinkCode::NoError;
}

AdlinkCode ApsParameters::get(std::size_t i, double para_f, double& value) const {
  if (i >= axes_.size() || !std::isfinite(para_f) || !whole(para_f)) return AdlinkCode::ParametersInvalid;
  const int para = static_cast<int>(para_f);
  const ApsAxisRegisters& r = axes_[i];
  if (const LawField* f = law_field(para)) {
    const auto* law = std::get_if<control::ApsServoLawParams>(&card_.state(i).staged.law);
    if (law == nullptr) return AdlinkCode::FunctionNotAvailable;
    value = f->field != nullptr ? law->*(f->field) : (law->v_inverse ? 1.0 : 0.0);
    return AdlinkCode::NoError;
  }
  if (stored(para) != nullptr) {
    value = para == HOME_EZA ? (r.home.eza ? 1.0 : 0.0) : *slot(const_cast<ApsAxisRegisters&>(r), para);
    return AdlinkCode::NoError;
  }
  const machine::LimitConfig& l = card_.state(i).limits;
  const AdlinkAxisState& s = adlink_state(card_, i);
  switch (para) {
    case JG_MAP_DI_EN: case JG_MAP_DI_EN + 1: case JG_MAP_DI_EN + 2: case JG_JOG_DI: value = 0; break;
    case EL_MODE: value = r.el_mode; break;
    case PRE_EVENT_DIST: value = s.pre_event_dist; break;
    case POST_EVENT_DIST: value = s.post_event_dist; break;
    case ERR_POS_LEVEL: value = s.error_level_pulse; break;
    case EL_LOGIC: value = l.pos_active_low ? 1 : 0; break;
    case SPEL_EN: value = l.soft_pos_enabled ? 1 : 0; break;
    case SMEL_EN: value = l.soft_neg_enabled ? 1 : 0; break;
    case SPEL_POS: value = l.soft_pos_pulse; break;
    case SMEL_POS: value = l.soft_neg_pulse; break;
    default: return AdlinkCode::ParametersInvalid;
  }
  return AdlinkCode::NoError;
}

ApsParameters& aps_parameters(machine::Card& card) { return card.module<ApsParameters>(); }

}  // namespace servobench::vendor::adlink
