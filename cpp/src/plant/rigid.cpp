#include "servobench/plant/rigid.hpp"

#include "servobench/common/validate.hpp"

namespace servobench::plant {

void RigidPlantParams::validate() const {
  check_positive("RigidPlant", "inertia_kgm2", inertia_kgm2);
  check_nonnegative("RigidPlant", "viscous_nms", viscous_nms);
  check_nonnegative("RigidPlant", "coulomb_nm", coulomb_nm);
  check_range("RigidPlant", "load_nm", load_nm, -1e6, 1e6);
}

PlantLti rigid_plant_lti(const RigidPlantParams& p) {
  PlantLti m;
  const double j = p.inertia_kgm2;
  m.a.resize(2, 2);
  m.a << 0.0, 1.0,
         0.0, -p.viscous_nms / j;
  m.b.resize(2, 2);
  m.b << 0.0, 0.0,
         1.0 / j, 1.0 / j;
  return m;
}

}  // namespace servobench::plant
