#include "servobench/machine/axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

void AxisConfig::validate_and_complete() {
  double lo = 0, hi = 0, def = 0;
  const char* source = "";
  std::visit(
      [&](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        p.validate();
        lo = P::kMinPeriodS;
        hi = P::kMaxPeriodS;
        def = P::kDefaultPeriodS;
        source = std::is_same_v<P, control::GtServoLawParams> ? "GT_SetSmplTm, GT manual L578-580"
                                                              : "ADLINK servo cycle, manual L1733";
      },
      law);
  std::visit([](const auto& d) { d.validate(); }, drive);
  std::visit([](const auto& p) { p.validate(); }, plant);
  encoder.validate();
  switches.validate();
  dac.validate();
  if (!servo_period_s) servo_period_s = def;
  check_range("Axis", "servo_period_s", *servo_period_s, lo, hi, source);
  check_integer("Axis", "substeps", substeps, 1, 1000);
  validate_filters(filters, *servo_period_s);
}

void validate_filters(const std::array<control::BiquadParams, 2>& filters, double servo_period_s) {
  for (std::size_t i = 0; i < filters.size(); ++i) {
    const std::string owner = "Axis.filters[" + std::to_string(i) + "]";
    std::visit([](const auto& f) { f.validate(); }, filters[i]);
    control::require_stable(filters[i], owner.c_str());
    const double ts = std::visit([](const auto& f) { return f.sample_time_s; }, filters[i]);
    if (ts != 0.0 && std::fabs(ts - servo_period_s) > 1e-9 * servo_period_s) {
      throw_invalid(owner.c_str(), "sample_time_s", ts,
                    "does not match the axis servo period " + format_value(servo_period_s) +
                        " s: the filter was designed for another sample time (redesign it for the axis period, or "
                        "use sample_time_s = 0 to apply the coefficients as they are)");
    }
  }
}

namespace {
AxisConfig completed(AxisConfig c) {
  c.validate_and_complete();
  return c;
}
plant::Mechanics make_mechanics(const PlantParams& p) {
  if (const auto* r = std::get_if<plant::RigidPlantParams>(&p)) return plant::rigid_mechanics(*r);
  if (const auto* l = std::get_if<plant::LtiPlantParams>(&p)) return plant::lti_mechanics(*l);
  return plant::two_mass_mechanics(std::get<plant::TwoMassPlantParams>(p));
}
std::variant<control::GtServoLaw, control::ApsServoLaw> make_law(const LawParams& p) {
  if (const auto* gt = std::get_if<control::GtServoLawParams>(&p)) return control::GtServoLaw(*gt);
  return control::ApsServoLaw(std::get<control::ApsServoLawParams>(p));
}
}  // namespace

Axis::Axis(AxisConfig config)
    : config_(completed(std::move(config))),
      law_(make_law(config_.law)),
      dac_(config_.dac),
      encoder_(config_.encoder),
      power_(config_.drive, make_mechanics(config_.plant), *config_.servo_period_s, config_.substeps) {
  for (std::size_t i = 0; i < biquads_.size(); ++i) biquads_[i].set_params(config_.filters[i]);
}

void Axis::reset(double angle_rad) {
  std::visit([](auto& law) { law.reset(); }, law_);
  for (auto& b : biquads_) b.reset();
  power_.reset(angle_rad);
  encoder_.reset();
  prev_encoder_angle_ = angle_rad;
  pending_volts_ = 0.0;
  prev_cmd_ = prev_vel_ = 0.0;
  primed_ = false;
  servo_on_ = true;
  tick_ = 0;
}

void Axis::reset_state(double motor_angle_rad, double motor_speed_rad_s, double load_angle_rad,
                       double load_speed_rad_s) {
  check_range("Axis.reset", "angle_rad", motor_angle_rad, -1e12, 1e12);
  check_range("Axis.reset", "speed_rad_s", motor_speed_rad_s, -1e12, 1e12);
  check_range("Axis.reset", "load_angle_rad", load_angle_rad, -1e12, 1e12);
  check_range("Axis.reset", "load_speed_rad_s", load_speed_rad_s, -1e12, 1e12);
  reset(motor_angle_rad);
  power_.set_state(motor_angle_rad, motor_speed_rad_s, load_angle_rad, load_speed_rad_s);
  prev_encoder_angle_ = encoder_angle();
}

void Axis::set_law(const LawParams& law) {
  if (law.index() != law_.index()) {
    // A different card's law: validate its period range too, then start it from power-on.
    AxisConfig c = config_;
    c.law = law;
    c.validate_and_complete();
    config_ = c;
    law_ = make_law(law);
    return;
  }
  std::visit(
      [&](auto& active) {
        using P = std::decay_t<decltype(active.params())>;
        active.set_params(std::get<P>(law));
      },
      law_);
  config_.law = law;
}

void Axis::set_filters(const std::array<control::BiquadParams, 2>& filters) {
  validate_filters(filters, *config_.servo_period_s);
  config_.filters = filters;
  for (std::size_t i = 0; i < biquads_.size(); ++i) biquads_[i].set_params(filters[i]);
}

void Axis::set_servo_on(bool on) {
  if (on && !servo_on_) {
    std::visit([](auto& law) { law.reset(); }, law_);
    for (auto& b : biquads_) b.reset();
  }
  servo_on_ = on;
}

RunOutcome Axis::run(const CommandInput& command, const Trace& trace, const RunGuard& guard) {
  RunOutcome fused;
  if (run_fused(command, trace, guard, fused)) return fused;
  return std::visit([&](auto& law) { return run_with(law, command, trace, guard); }, law_);
}

double Axis::step(double command_pulse, std::size_t n, const std::function<double(std::size_t, double, double)>* external) {
  if (external != nullptr) {  // one run per tick: the controller sees tick index 0 every time, as documented
    CommandInput in;
    in.pos = &command_pulse;
    in.n = 1;
    in.external = external;
    double fb = 0.0;
    Trace t;
    t.fb_pos = &fb;
    for (std::size_t k = 0; k < n; ++k) run(in, t);
    return fb;
  }
  // The law in place: runs of up to kChunk ticks over the held command (the same ticks as one run per tick; the
  // velocity and acceleration are the differences either way), so the fused tick's set-up is paid once per chunk.
  constexpr std::size_t kChunk = 512;
  std::array<double, kChunk> held, fb;
  std::fill_n(held.begin(), std::min(kChunk, n), command_pulse);  // one call per tick (the step API) fills one
  CommandInput in;
  in.pos = held.data();
  Trace t;
  t.fb_pos = fb.data();
  double last = 0.0;
  for (std::size_t done = 0; done < n;) {
    in.n = std::min(kChunk, n - done);
    run(in, t);
    last = fb[in.n - 1];
    done += in.n;
  }
  return last;
}

template <class Law>
RunOutcome Axis::run_with(Law& law, const CommandInput& command, const Trace& tr, const RunGuard& guard) {
  RunOutcome outcome;
  const bool guarded = guard.error_limit_pulse > 0.0 || guard.stop_on_alarm;
  const double ts = *config_.servo_period_s;
  const plant::SwitchParams& sw = config_.switches;
  const bool pulse_output = power_.pulse_input();
  for (std::size_t k = 0; k < command.n; ++k) {
    const double r = command.pos[k];
    if (!primed_) {
      prev_cmd_ = r;
      prev_vel_ = 0.0;
      primed_ = true;
    }
    const double v = command.vel ? command.vel[k] : r - prev_cmd_;
    const double a = command.acc ? command.acc[k] : v - prev_vel_;
    prev_cmd_ = r;
    prev_vel_ = v;

    const double enc_angle = encoder_angle();
    const double y = encoder_.read(enc_angle);
    outcome.last_error_pulse = r - y;
    bool trip = false;
    if (guarded) {
      if (guard.error_limit_pulse > 0.0 && servo_on_ && !(std::fabs(r - y) <= guard.error_limit_pulse)) {  // NaN trips
        trip = true;
        outcome.stop = RunStop::kErrorLimit;
      } else if (guard.stop_on_alarm && power_.alarm()) {
        trip = true;
        outcome.stop = RunStop::kDriveAlarm;
      }
      if (trip) {
        outcome.error_pulse = r - y;
        servo_on_ = false;
      }
    }
    control::LawTerms t;
    double f0 = 0.0, f1 = 0.0, volts = 0.0;
    if (!servo_on_ && !pulse_output) {
      // Servo off: no law, no filters; the output stage gives 0 V (plus any injection).
      power_.set_input(pending_volts_);
      t.vel = v;
      t.acc = a;
      if (command.volts_add) volts = dac_.convert(command.volts_add[k]);
    } else if (command.external) {
      power_.set_input(pending_volts_);
      t.vel = v;
      t.acc = a;
      const double request = (*command.external)(k, r, y);
      volts = dac_.convert(command.volts_add ? request + command.volts_add[k] : request);
    } else if (pulse_output) {
      // Pulse-output card: the command goes out as a step train of whole pulses; no servo law, no DAC.
      power_.set_pulse_input(std::nearbyint(r));
      t.vel = v;
      t.acc = a;
    } else {
      power_.set_input(pending_volts_);  // the previous tick's output reaches the drive now
      t = law.step(r, y, v, a);
      f0 = biquads_[0].step(t.total);
      f1 = biquads_[1].step(f0);
      const double request = law.counts_to_volts(f1);
      volts = dac_.convert(command.volts_add ? request + command.volts_add[k] : request);
    }

    if (tr.time_s) tr.time_s[k] = static_cast<double>(tick_) * ts;
    if (tr.cmd_pos) tr.cmd_pos[k] = r;
    if (tr.cmd_vel) tr.cmd_vel[k] = t.vel;
    if (tr.cmd_acc) tr.cmd_acc[k] = t.acc;
    if (tr.fb_pos) tr.fb_pos[k] = y;
    if (tr.error) tr.error[k] = r - y;
    if (tr.p) tr.p[k] = t.p;
    if (tr.i) tr.i[k] = t.i;
    if (tr.d) tr.d[k] = t.d;
    if (tr.vff) tr.vff[k] = t.vff;
    if (tr.aff) tr.aff[k] = t.aff;
    if (tr.bias) tr.bias[k] = t.bias;
    if (tr.u) tr.u[k] = t.total;
    if (tr.biquad0) tr.biquad0[k] = f0;
    if (tr.biquad1) tr.biquad1[k] = f1;
    if (tr.volts) tr.volts[k] = volts;
    if (tr.current_a) tr.current_a[k] = power_.current_a();
    if (tr.torque_nm) tr.torque_nm[k] = power_.torque_nm();
    if (tr.angle_rad) tr.angle_rad[k] = power_.motor_angle_rad();
    if (tr.speed_rad_s) tr.speed_rad_s[k] = power_.motor_speed_rad_s();
    if (tr.load_angle_rad) tr.load_angle_rad[k] = power_.load_angle_rad();
    if (tr.load_speed_rad_s) tr.load_speed_rad_s[k] = power_.load_speed_rad_s();
    if (tr.alarm) tr.alarm[k] = power_.alarm() ? 1.0 : 0.0;
    if (tr.index) tr.index[k] = encoder_.index_between(prev_encoder_angle_, enc_angle) ? 1.0 : 0.0;
    const double load = power_.load_angle_rad();
    if (tr.home_sw) tr.home_sw[k] = sw.home(load) ? 1.0 : 0.0;
    if (tr.pos_limit_sw) tr.pos_limit_sw[k] = sw.pos_limit(load) ? 1.0 : 0.0;
    if (tr.neg_limit_sw) tr.neg_limit_sw[k] = sw.neg_limit(load) ? 1.0 : 0.0;
    prev_encoder_angle_ = enc_angle;

    power_.advance_tick();
    pending_volts_ = volts;
    ++tick_;
    if (trip) {
      outcome.ticks = k + 1;
      return outcome;
    }
  }
  outcome.ticks = command.n;
  return outcome;
}

}  // namespace servobench::machine
