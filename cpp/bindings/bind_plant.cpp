#include "param_class.hpp"
#include "servobench/plant/encoder.hpp"
#include "servobench/plant/rigid.hpp"

namespace servobench::bindings {

void bind_plant(py::module_& m) {
  using plant::EncoderParams;
  using plant::RigidPlantParams;

  ParamClass<RigidPlantParams>(m, "RigidPlant",
      "Rigid single-inertia mechanics in SI units: J*dw/dt = torque - viscous*w - coulomb*sign(w) - load,\n"
      "with stiction (at rest while |torque - load| <= coulomb).")
      .field("inertia_kgm2", &RigidPlantParams::inertia_kgm2, "total inertia at the motor, kg*m^2, > 0")
      .field("viscous_nms", &RigidPlantParams::viscous_nms, "viscous friction, N*m*s/rad, >= 0")
      .field("coulomb_nm", &RigidPlantParams::coulomb_nm, "Coulomb/static friction level, N*m, >= 0")
      .field("load_nm", &RigidPlantParams::load_nm, "constant load torque, N*m (positive opposes positive motion)")
      .finish();

  ParamClass<EncoderParams>(m, "Encoder",
      "Position encoder on the motor: count = floor(angle*counts_per_rev/(2*pi) + 1/2) (quantize=True) or the\n"
      "continuous value. counts_per_rev is after quadrature decoding (2500 lines x4 = 10000).")
      .field("counts_per_rev", &EncoderParams::counts_per_rev, "counts per revolution, whole number 1..2^31")
      .field("quantize", &EncoderParams::quantize, "False: ideal continuous encoder")
      .finish();
}

}  // namespace servobench::bindings
