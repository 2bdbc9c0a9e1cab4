#include "param_class.hpp"
#include "servobench/drive/dac.hpp"
#include "servobench/drive/torque_drive.hpp"

namespace servobench::bindings {

void bind_drive(py::module_& m) {
  using drive::DacParams;
  using drive::TorqueDriveParams;

  ParamClass<DacParams>(m, "Dac",
      "Bipolar DAC: saturates at +-full_scale_v and (if quantize) rounds to the nearest of the symmetric codes\n"
      "-(2^(bits-1)-1)..+(2^(bits-1)-1). Default 16 bits, +-10 V as on the GT and ADLINK cards.")
      .field("bits", &DacParams::bits, "resolution, 8..24 bits")
      .field("full_scale_v", &DacParams::full_scale_v, "full scale, V, 0.001..100")
      .field("quantize", &DacParams::quantize, "False: ideal continuous DAC (saturation only)")
      .finish();

  ParamClass<TorqueDriveParams>(m, "TorqueDrive",
      "Servo amplifier in torque mode: i_cmd = clamp(amps_per_volt*V, +-current_limit_a); first-order current loop\n"
      "of bandwidth current_bw_hz (inf = ideal); torque = kt*i.")
      .field("amps_per_volt", &TorqueDriveParams::amps_per_volt, "current command per volt, A/V, > 0")
      .field("kt", &TorqueDriveParams::kt, "torque constant, N*m/A, > 0")
      .field("current_limit_a", &TorqueDriveParams::current_limit_a, "current command limit, A, > 0 (inf = none)")
      .field("current_bw_hz", &TorqueDriveParams::current_bw_hz, "current-loop bandwidth, Hz, > 0 (inf = ideal)")
      .finish();
}

}  // namespace servobench::bindings
