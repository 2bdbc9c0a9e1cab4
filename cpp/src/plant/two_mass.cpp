#include "servobench/plant/two_mass.hpp"

#include <cmath>

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void validate_disturbances(const char* owner, double load_nm, double unbalance_nm, double cogging_nm,
                           double cogging_periods);

void TwoMassPlantParams::validate() const {
  constexpr const char* owner = "TwoMassPlant";
  check_inertia(owner, "jm_kgm2", jm_kgm2);
  check_inertia(owner, "jl_kgm2", jl_kgm2);
  check_positive(owner, "k_nm_per_rad", k_nm_per_rad, 1e9);
  check_nonnegative(owner, "c_nms_per_rad", c_nms_per_rad, 1e6);
  motor_friction().validate(owner, "motor_");
  load_friction().validate(owner, "load_");
  validate_disturbances(owner, load_nm, unbalance_nm, cogging_nm, cogging_periods);
}

double TwoMassPlantParams::antiresonance_hz() const { return std::sqrt(k_nm_per_rad / jl_kgm2) / (2.0 * M_PI); }

double TwoMassPlantParams::resonance_hz() const {
  return std::sqrt(k_nm_per_rad * (jm_kgm2 + jl_kgm2) / (jm_kgm2 * jl_kgm2)) / (2.0 * M_PI);
}

Mechanics two_mass_mechanics(const TwoMassPlantParams& p) {
  p.validate();
  Mechanics m;
  const double jm = p.jm_kgm2, jl = p.jl_kgm2, k = p.k_nm_per_rad, c = p.c_nms_per_rad;
  const double bm = p.motor_viscous_nms, bl = p.load_viscous_nms;
  // x = [theta_m, w_m, theta_l, w_l]
  m.a.resize(4, 4);
  m.b.resize(4, 3);
  two_mass_linear(jm, jl, k, c, bm, bl, m.a, m.b);
  Body motor{0, 1, 1, jm, p.motor_friction()};
  Body load{2, 3, 2, jl, p.load_friction()};
  m.bodies = {motor, load};
  m.disturbances = Disturbances{p.load_nm, p.unbalance_nm, p.cogging_nm, p.cogging_periods};
  m.motor_angle = 0;
  m.motor_speed = 1;
  m.load_angle = 2;
  m.load_speed = 3;
  return m;
}

}  // namespace servobench::plant
