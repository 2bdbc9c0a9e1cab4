#include "servobench/plant/rigid.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void validate_disturbances(const char* owner, double load_nm, double unbalance_nm, double cogging_nm,
                           double cogging_periods) {
  check_range(owner, "load_nm", load_nm, -1e6, 1e6);
  check_range(owner, "unbalance_nm", unbalance_nm, -1e6, 1e6);
  check_range(owner, "cogging_nm", cogging_nm, 0, 1e6);
  check_integer(owner, "cogging_periods", cogging_periods, 0, 1000);
}

void check_inertia(const char* owner, const char* field, double j) {
  check_positive(owner, field, j, kMaxInertiaKgm2);
  if (j < kMinInertiaKgm2)
    throw_invalid(owner, field, j,
                  "must be > 0, at least " + format_value(kMinInertiaKgm2) +
                      " kg*m^2 (the floor the plant solver resolves; decision RB2) and <= " +
                      format_value(kMaxInertiaKgm2));
}

void RigidPlantParams::validate() const {
  check_inertia("RigidPlant", "inertia_kgm2", inertia_kgm2);
  friction().validate("RigidPlant", "");
  validate_disturbances("RigidPlant", load_nm, unbalance_nm, cogging_nm, cogging_periods);
}

Mechanics rigid_mechanics(const RigidPlantParams& p) {
  p.validate();
  Mechanics m;
  const double j = p.inertia_kgm2;
  m.a.resize(2, 2);
  m.b.resize(2, 3);
  rigid_linear(j, p.viscous_nms, m.a, m.b);
  Body body;
  body.angle_index = 0;
  body.speed_index = 1;
  body.torque_input = 1;
  body.inertia_kgm2 = j;
  body.friction = p.friction();
  m.bodies = {body};
  m.disturbances = Disturbances{p.load_nm, p.unbalance_nm, p.cogging_nm, p.cogging_periods};
  m.motor_angle = m.load_angle = 0;
  m.motor_speed = m.load_speed = 1;
  return m;
}

}  // namespace servobench::plant
