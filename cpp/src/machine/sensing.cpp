#include "servobench/machine/sensing.hpp"

#include <cmath>

namespace servobench::machine {

MechSample sample_mechanism(const Axis& axis) {
  MechSample m;
  const bool on_load = axis.config().encoder.on_load;
  m.load_angle = axis.load_angle_rad();
  m.load_speed = axis.load_speed_rad_s();
  m.enc_angle = on_load ? m.load_angle : axis.angle_rad();
  m.enc_speed = on_load ? m.load_speed : axis.speed_rad_s();
  return m;
}

double hermite_angle(double x0, double v0, double x1, double v1, double h, double tau) {
  const double t2 = tau * tau, t3 = t2 * tau;
  return (2 * t3 - 3 * t2 + 1) * x0 + (t3 - 2 * t2 + tau) * h * v0 + (-2 * t3 + 3 * t2) * x1 + (t3 - t2) * h * v1;
}

double crossing_fraction(double x0, double v0, double x1, double v1, double h, double level) {
  double lo = 0.0, hi = 1.0;
  const bool rising = x1 > x0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double x = hermite_angle(x0, v0, x1, v1, h, mid);
    if ((x < level) == rising) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

Sensing::Sensing(const Axis& axis) : sw_(axis.config().switches), enc_(axis.encoder()) {}

motion::HomeInputs Sensing::levels(const MechSample& now) const {
  motion::HomeInputs in;
  in.org.level = sw_.home(now.load_angle);
  in.pel.level = sw_.pos_limit(now.load_angle);
  in.mel.level = sw_.neg_limit(now.load_angle);
  in.actual_pos = enc_.read_ideal(now.enc_angle);
  return in;
}

double Sensing::pulse_at(const MechSample& b, const MechSample& a, double h, double tau) const {
  return enc_.read_ideal(hermite_angle(b.enc_angle, b.enc_speed, a.enc_angle, a.enc_speed, h, tau));
}

void Sensing::switch_event(motion::SignalEvent& e, bool was, bool is, double bound_lo, double bound_hi,
                           const MechSample& b, const MechSample& a, double h, double* tau_out) const {
  if (was == is) return;
  e.rose = is;
  e.fell = !is;
  // The boundary crossed: the one lying between the two load angles.
  const double x0 = b.load_angle, x1 = a.load_angle;
  const bool lo_between = (x0 < bound_lo) != (x1 < bound_lo);
  const double bound = lo_between || !std::isfinite(bound_hi) ? bound_lo : bound_hi;
  const double tau = crossing_fraction(x0, b.load_speed, x1, a.load_speed, h, bound);
  e.edge_pos = pulse_at(b, a, h, tau);
  if (tau_out) *tau_out = tau;
}

TickSense Sensing::between(const MechSample& b, const MechSample& a, double h) const {
  TickSense t;
  const motion::HomeInputs was = levels(b);
  t.in = levels(a);
  switch_event(t.in.org, was.org.level, t.in.org.level, sw_.home_min_rad, sw_.home_max_rad, b, a, h, &t.home_tau);
  switch_event(t.in.pel, was.pel.level, t.in.pel.level, sw_.pos_limit_rad, INFINITY, b, a, h, nullptr);
  switch_event(t.in.mel, was.mel.level, t.in.mel.level, sw_.neg_limit_rad, INFINITY, b, a, h, nullptr);
  if (enc_.index_between(b.enc_angle, a.enc_angle)) {
    constexpr double two_pi = 2.0 * M_PI;
    const double idx = enc_.params().index_angle_rad;
    const double top = std::max(b.enc_angle, a.enc_angle);
    const double level = idx + two_pi * std::floor((top - idx) / two_pi);
    t.index_tau = crossing_fraction(b.enc_angle, b.enc_speed, a.enc_angle, a.enc_speed, h, level);
    t.in.ez.rose = true;
    t.in.ez.edge_pos = pulse_at(b, a, h, t.index_tau);
  }
  return t;
}

}  // namespace servobench::machine
