#include "servobench/tuning/loop_response.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "servobench/common/validate.hpp"

namespace servobench::tuning {

namespace {

struct LawGains {
  double kp, ki, kd, kvff, kaff;  // effective per-tick gains, counts per pulse (ki per pulse*tick)
  double volts_per_count;         // output stage: 10/32767, negative with ADLINK V_INVERSE
};

LawGains gains_of(const machine::LawParams& law) {
  if (const auto* gt = std::get_if<control::GtServoLawParams>(&law)) {
    return {gt->kp, gt->ilmt == 0 ? 0.0 : gt->ki / 256.0, gt->kd, gt->kvff, gt->kaff, 10.0 / 32767.0};
  }
  const auto& a = std::get<control::ApsServoLawParams>(law);
  return {a.kp_eff(), a.integral_limit == 0 ? 0.0 : a.ki_eff(), a.kd_eff(), a.kvff_eff(), a.kaff_eff(),
          (a.v_inverse ? -1.0 : 1.0) * 10.0 / 32767.0};
}

Complex unit_delay(double freq_hz, double ts) { return std::exp(Complex(0.0, -2.0 * M_PI * freq_hz * ts)); }

void check_frequency(double f, double ts) {
  if (!(f > 0) || !std::isfinite(f)) throw_invalid("loop_response", "freq_hz", f, "must be finite and > 0");
  if (f >= 0.5 / ts)
    throw_invalid("loop_response", "freq_hz", f,
                  "must be below the Nyquist frequency 1/(2 Ts) = " + format_value(0.5 / ts) + " Hz");
}

}  // namespace

Complex law_feedback_response(const machine::LawParams& law, double freq_hz, double ts) {
  const LawGains g = gains_of(law);
  const Complex diff = 1.0 - unit_delay(freq_hz, ts);  // 1 - z^-1
  return g.kp + g.ki / diff + g.kd * diff;
}

Complex law_feedforward_response(const machine::LawParams& law, double freq_hz, double ts) {
  const LawGains g = gains_of(law);
  const Complex diff = 1.0 - unit_delay(freq_hz, ts);
  return g.kvff * diff + g.kaff * diff * diff;
}

machine::LawParams law_for_measurement(const machine::LawParams& law, const LoopOptions& options) {
  if (options.feedforward) return law;
  return std::visit(
      [](auto p) -> machine::LawParams {
        p.kvff = 0;
        p.kaff = 0;
        return p;
      },
      law);
}

std::array<control::BiquadParams, 2> filters_for_measurement(const std::array<control::BiquadParams, 2>& filters,
                                                             const LoopOptions& options) {
  if (options.filters) return filters;
  return {control::AdlinkBiquadParams{}, control::AdlinkBiquadParams{}};
}

LoopResponse loop_response(const machine::AxisConfig& config_in, const std::vector<double>& freq_hz,
                           const LoopOptions& options) {
  machine::AxisConfig config = config_in;
  config.validate_and_complete();
  const double ts = *config.servo_period_s;
  for (double f : freq_hz) check_frequency(f, ts);

  const machine::Axis axis(config);  // the same composition the simulator runs
  if (axis.power_train().pulse_input())
    throw std::invalid_argument(
        "loop_response: a pulse-output axis (stepper or servo in position mode) has no position loop on the card");
  const machine::TickModel tm = axis.power_train().linear_tick_model();
  const double counts_per_rad = config.encoder.counts_per_rev / (2.0 * M_PI);
  const Eigen::MatrixXd& c_side = config.encoder.on_load ? tm.c_load : tm.c_motor;
  const machine::LawParams law = law_for_measurement(config.law, options);
  const LawGains g = gains_of(law);
  const auto filters = filters_for_measurement(config.filters, options);

  const std::size_t n = freq_hz.size();
  LoopResponse r;
  r.freq_hz = freq_hz;
  for (auto* v : {&r.controller, &r.feedforward, &r.filters, &r.plant, &r.loop_gain, &r.open_loop, &r.closed_loop,
                  &r.sensitivity})
    v->resize(n);
  const Eigen::Index ns = tm.a.rows();
  const Eigen::MatrixXcd a = tm.a.cast<Complex>();
  const Eigen::VectorXcd b = tm.b.col(0).cast<Complex>();
  for (std::size_t k = 0; k < n; ++k) {
    const double f = freq_hz[k];
    const Complex z = std::exp(Complex(0.0, 2.0 * M_PI * f * ts));
    const Eigen::VectorXcd x = (z * Eigen::MatrixXcd::Identity(ns, ns) - a).partialPivLu().solve(b);
    const Complex y_per_volt = counts_per_rad * (c_side.cast<Complex>() * x)(0, 0) / z;  // one-tick delay
    const Complex p = g.volts_per_count * y_per_volt;
    Complex fz = 1.0;
    for (const auto& flt : filters)
      fz *= std::visit([&](const auto& q) { return control::frequency_response(q, f, ts); }, flt);
    const Complex c = law_feedback_response(law, f, ts);
    const Complex cff = law_feedforward_response(law, f, ts);
    const Complex l = fz * c * p;
    const Complex t = fz * (c + cff) * p / (1.0 + l);
    const Complex s = (1.0 - fz * cff * p) / (1.0 + l);
    r.controller[k] = c;
    r.feedforward[k] = cff;
    r.filters[k] = fz;
    r.plant[k] = p;
    r.loop_gain[k] = l;
    r.closed_loop[k] = t;
    r.sensitivity[k] = s;
    r.open_loop[k] = t / s;
  }
  return r;
}

}  // namespace servobench::tuning
