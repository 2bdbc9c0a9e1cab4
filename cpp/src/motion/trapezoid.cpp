#include "servobench/motion/trapezoid.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::motion {

SampledProfile trapezoid_move(double start_pulse, double distance_pulse, double vel_max, double acc,
                              std::size_t dwell_before, std::size_t dwell_after) {
  check_range("trapezoid_move", "start_pulse", start_pulse, -1073741824.0, 1073741823.0);
  check_range("trapezoid_move", "distance_pulse", distance_pulse, -2147483647.0, 2147483647.0);
  check_positive("trapezoid_move", "vel_pulse_per_tick", vel_max);
  check_positive("trapezoid_move", "acc_pulse_per_tick2", acc);
  check_range("trapezoid_move", "dwell_before", static_cast<double>(dwell_before), 0, 1e8);
  check_range("trapezoid_move", "dwell_after", static_cast<double>(dwell_after), 0, 1e8);

  const double dist = std::fabs(distance_pulse);
  const double sign = distance_pulse < 0 ? -1.0 : 1.0;
  double vpk = vel_max;
  double t_acc = vel_max / acc;
  double d_acc = 0.5 * acc * t_acc * t_acc;
  double t_cruise;
  if (2.0 * d_acc >= dist) {  // triangle
    t_acc = std::sqrt(dist / acc);
    vpk = acc * t_acc;
    d_acc = 0.5 * dist;
    t_cruise = 0.0;
  } else {
    t_cruise = (dist - 2.0 * d_acc) / vel_max;
  }
  const double t_total = 2.0 * t_acc + t_cruise;
  const std::size_t move_ticks = static_cast<std::size_t>(std::ceil(t_total));
  if (move_ticks > 100000000) throw_invalid("trapezoid_move", "distance_pulse", distance_pulse,
                                            "gives a move longer than 1e8 ticks");
  const std::size_t n = dwell_before + move_ticks + 1 + dwell_after;
  SampledProfile out;
  out.pos.resize(n);
  out.vel.resize(n);
  out.acc.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) - static_cast<double>(dwell_before);
    double p, v, a;
    if (t <= 0.0) {
      p = 0.0; v = 0.0; a = 0.0;
    } else if (t < t_acc) {
      p = 0.5 * acc * t * t; v = acc * t; a = acc;
    } else if (t < t_acc + t_cruise) {
      p = d_acc + vpk * (t - t_acc); v = vpk; a = 0.0;
    } else if (t < t_total) {
      const double tr = t_total - t;
      p = dist - 0.5 * acc * tr * tr; v = acc * tr; a = -acc;
    } else {
      p = dist; v = 0.0; a = 0.0;
    }
    out.pos[k] = start_pulse + sign * p;
    out.vel[k] = sign * v;
    out.acc[k] = sign * a;
  }
  return out;
}

}  // namespace servobench::motion
