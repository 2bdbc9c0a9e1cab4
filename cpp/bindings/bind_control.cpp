#include "param_class.hpp"
#include "servobench/control/aps_servo_law.hpp"
#include "servobench/control/gt_servo_law.hpp"

namespace servobench::bindings {

void bind_control(py::module_& m) {
  using control::ApsServoLawParams;
  using control::GtServoLawParams;

  ParamClass<GtServoLawParams>(m, "GtServoLaw",
      "Googol GT servo filter (GT manual L801-829): U = Kp*E + Kd*(E-E_prev) + Ki*SumE/256 + Kvff*V + Kaff*A + B,\n"
      "SumE clamped to +-ilmt (0 clears it), U clamped to +-mtr_lmt, 32767 counts = 10 V.\n"
      "Units: E pulse, V pulse/tick, A pulse/tick^2, U DAC counts. Keyword arguments only; defaults are the\n"
      "manual's (Table 3-4): gains 0, ilmt 32767, bias 0, mtr_lmt 32767. Servo period 48..1966.08 us, default 200 us.")
      .field("kp", &GtServoLawParams::kp, "proportional gain, counts/pulse, 0..32767")
      .field("ki", &GtServoLawParams::ki, "integral gain (term = ki*SumE/256), 0..32767")
      .field("kd", &GtServoLawParams::kd, "derivative gain on E_n - E_{n-1}, 0..32767")
      .field("kvff", &GtServoLawParams::kvff, "velocity feed-forward gain on V_target (pulse/tick), 0..32767")
      .field("kaff", &GtServoLawParams::kaff, "acceleration feed-forward gain on A_target (pulse/tick^2), 0..32767")
      .field("ilmt", &GtServoLawParams::ilmt, "integral limit ``|SumE| <= ilmt`` (pulse*tick), 0..32767; 0 clears the sum")
      .field("bias", &GtServoLawParams::bias, "motor bias B, counts, -32768..32767")
      .field("mtr_lmt", &GtServoLawParams::mtr_lmt, "output limit ``|U| <= mtr_lmt``, counts, 0..32767")
      .field("fractional_gains", &GtServoLawParams::fractional_gains,
             "GE series: kp..kaff may be fractional doubles in 0..32767 (GE L5530-5620); default False (GT integers)")
      .finish()
      .def_property_readonly_static("PERIOD_RANGE_S", [](py::object) {
        return py::make_tuple(GtServoLawParams::kMinPeriodS, GtServoLawParams::kMaxPeriodS);
      }, "allowed servo period range, s")
      .def_property_readonly_static("DEFAULT_PERIOD_S", [](py::object) { return GtServoLawParams::kDefaultPeriodS; },
                                    "the card's default servo period, s");

  ParamClass<ApsServoLawParams>(m, "ApsServoLaw",
      "ADLINK PCI-8254/8258 servo law (ADLINK manual L1723-1762): U = 2^PID_SHIFT*(KP*2^KP_SHIFT*E + KI*2^KI_SHIFT*Sum\n"
      "+ KD*2^KD_SHIFT*(E-E_prev) + KVFF*2^KVFF_SHIFT*CmdVel + KAFF*2^KAFF_SHIFT*CmdAcc), Sum clamped to\n"
      "+-integral_limit, then (after the biquads) V = counts*10/32767 + v_bias, clamped to +-v_limit, inverted if\n"
      "v_inverse. Keyword arguments only; defaults are the manual's: gains 0, shifts KP -5, KI -15, KD/KVFF/KAFF 0,\n"
      "PID -5, integral_limit 2147483647, v_bias 0 V, v_limit 10 V. Servo period 50..2000 us, default 250 us.")
      .field("kp", &ApsServoLawParams::kp, "PRA_KP_GAIN, 0..65535")
      .field("ki", &ApsServoLawParams::ki, "PRA_KI_GAIN, 0..65535")
      .field("kd", &ApsServoLawParams::kd, "PRA_KD_GAIN, 0..65535")
      .field("kvff", &ApsServoLawParams::kvff, "PRA_KVFF_GAIN, 0..65535")
      .field("kaff", &ApsServoLawParams::kaff, "PRA_KAFF_GAIN, 0..65535")
      .field("kp_shift", &ApsServoLawParams::kp_shift, "PRA_KP_SHIFT, -31..31")
      .field("ki_shift", &ApsServoLawParams::ki_shift, "PRA_KI_SHIFT, -31..31")
      .field("kd_shift", &ApsServoLawParams::kd_shift, "PRA_KD_SHIFT, -31..31")
      .field("kvff_shift", &ApsServoLawParams::kvff_shift, "PRA_KVFF_SHIFT, -31..31")
      .field("kaff_shift", &ApsServoLawParams::kaff_shift, "PRA_KAFF_SHIFT, -31..31")
      .field("pid_shift", &ApsServoLawParams::pid_shift, "PRA_PID_SHIFT, -31..31 (scales every term)")
      .field("integral_limit", &ApsServoLawParams::integral_limit, "PRA_INTEGRAL_LIMIT, pulse*tick, 0..2147483647")
      .field("v_bias", &ApsServoLawParams::v_bias, "PRA_SERVO_V_BIAS, V, 0..10")
      .field("v_limit", &ApsServoLawParams::v_limit, "PRA_SERVO_V_LIMIT, V, 0..10")
      .field("v_inverse", &ApsServoLawParams::v_inverse, "PRA_SERVO_V_INVERSE, bool")
      .finish()
      .def("effective_gains", [](const ApsServoLawParams& p) {
        py::dict d;
        d["kp"] = p.kp_eff();
        d["ki"] = p.ki_eff();
        d["kd"] = p.kd_eff();
        d["kvff"] = p.kvff_eff();
        d["kaff"] = p.kaff_eff();
        return d;
      }, "Per-tick gains K*2^(K_SHIFT+PID_SHIFT) in counts per pulse (kvff: per pulse/tick, kaff: per pulse/tick^2).")
      .def_property_readonly_static("PERIOD_RANGE_S", [](py::object) {
        return py::make_tuple(ApsServoLawParams::kMinPeriodS, ApsServoLawParams::kMaxPeriodS);
      }, "allowed servo period range, s")
      .def_property_readonly_static("DEFAULT_PERIOD_S", [](py::object) { return ApsServoLawParams::kDefaultPeriodS; },
                                    "the card's default servo period, s");
}

}  // namespace servobench::bindings
