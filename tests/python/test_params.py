"""Bad input on every parameter object gets a ValueError naming the parameter, the value and the range.

Ranges: GT manual (seed 000) Table 3-4 L784-793, L829, sample time L578-580; ADLINK manual (seed 004)
L1733 (servo period) and L1746-1762 (law parameters)."""

import math
import pickle

import numpy as np
import pytest

import servobench as sb

NAN, INF = math.nan, math.inf

# (class, field, bad values, text expected in the message)
BAD = [
    (sb.GtServoLaw, "kp", [-1, 32768, 1.5, NAN, INF], "0..32767"),
    (sb.GtServoLaw, "ki", [-1, 32768, 0.25, NAN, -INF], "0..32767"),
    (sb.GtServoLaw, "kd", [-1, 32768, NAN], "0..32767"),
    (sb.GtServoLaw, "kvff", [-1, 32768, INF], "0..32767"),
    (sb.GtServoLaw, "kaff", [-1, 32768, NAN], "0..32767"),
    (sb.GtServoLaw, "ilmt", [-1, 32768, NAN], "0..32767"),
    (sb.GtServoLaw, "bias", [-32769, 32768, 0.5, NAN], "-32768..32767"),
    (sb.GtServoLaw, "mtr_lmt", [-1, 32768, INF], "0..32767"),
    (sb.GtServoLaw, "fractional_gains", [2, -1, 0.5], "0/False or 1/True"),
    (sb.ApsServoLaw, "kp", [-1, 65536, 2.5, NAN], "0..65535"),
    (sb.ApsServoLaw, "ki", [-1, 65536, INF], "0..65535"),
    (sb.ApsServoLaw, "kd", [-1, 65536, NAN], "0..65535"),
    (sb.ApsServoLaw, "kvff", [-1, 65536, NAN], "0..65535"),
    (sb.ApsServoLaw, "kaff", [-1, 65536, NAN], "0..65535"),
    (sb.ApsServoLaw, "kp_shift", [-32, 32, 0.5, NAN], "-31..31"),
    (sb.ApsServoLaw, "ki_shift", [-32, 32, NAN], "-31..31"),
    (sb.ApsServoLaw, "kd_shift", [-32, 32, INF], "-31..31"),
    (sb.ApsServoLaw, "kvff_shift", [-32, 32, NAN], "-31..31"),
    (sb.ApsServoLaw, "kaff_shift", [-32, 32, NAN], "-31..31"),
    (sb.ApsServoLaw, "pid_shift", [-32, 32, NAN], "-31..31"),
    (sb.ApsServoLaw, "integral_limit", [-1, 2147483648, 0.5, NAN], "0..2147483647"),
    (sb.ApsServoLaw, "v_bias", [-0.1, 10.1, NAN, INF], "0..10"),
    (sb.ApsServoLaw, "v_limit", [-0.1, 10.1, NAN], "0..10"),
    (sb.ApsServoLaw, "v_inverse", [2, -1, 0.5], "0/False or 1/True"),
    (sb.TorqueDrive, "amps_per_volt", [0, -1, NAN, INF], "> 0"),
    (sb.TorqueDrive, "kt", [0, -0.1, NAN, INF], "> 0"),
    (sb.TorqueDrive, "current_limit_a", [0, -1, NAN], "> 0"),
    (sb.TorqueDrive, "current_bw_hz", [0, -5, NAN], "> 0"),
    (sb.TorqueDrive, "torque_limit_nm", [0, -1, NAN], "> 0"),
    (sb.TorqueDrive, "alarm_at_s", [-1, NAN], ">= 0"),
    (sb.VelocityDrive, "speed_per_volt_rad_s", [0, -1, NAN, INF], "> 0"),
    (sb.VelocityDrive, "kp_nms", [-1, NAN, INF], ">= 0"),
    (sb.VelocityDrive, "ki_nm_per_rad", [-1, NAN, INF], ">= 0"),
    (sb.VelocityDrive, "loop_rate_hz", [50, 2e6, NAN], "100..1000000"),
    (sb.VelocityDrive, "kt", [0, NAN], "> 0"),
    (sb.VelocityDrive, "current_limit_a", [0, NAN], "> 0"),
    (sb.VelocityDrive, "torque_limit_nm", [0, -2, NAN], "> 0"),
    (sb.VelocityDrive, "current_bw_hz", [0, NAN], "> 0"),
    (sb.VelocityDrive, "alarm_at_s", [-1, NAN], ">= 0"),
    (sb.StepperDrive, "full_steps_per_rev", [3, 10004, 200.5, NAN], "4..10000"),
    (sb.StepperDrive, "full_steps_per_rev", [202], "multiple of 4"),
    (sb.StepperDrive, "microsteps", [0, 257, 1.5, NAN], "1..256"),
    (sb.StepperDrive, "holding_torque_nm", [0, -1, NAN, INF], "> 0"),
    (sb.StepperDrive, "alarm_at_s", [-1, NAN], ">= 0"),
    (sb.ServoPositionDrive, "pulses_per_rev", [0, -1, NAN, INF], "> 0"),
    (sb.ServoPositionDrive, "kpp_per_s", [-1, NAN, INF], ">= 0"),
    (sb.ServoPositionDrive, "speed_feedforward", [-0.1, 1.1, NAN], "0..1"),
    (sb.ServoPositionDrive, "kp_nms", [-1, NAN], ">= 0"),
    (sb.ServoPositionDrive, "ki_nm_per_rad", [-1, NAN], ">= 0"),
    (sb.ServoPositionDrive, "loop_rate_hz", [50, 2e6, NAN], "100..1000000"),
    (sb.ServoPositionDrive, "kt", [0, NAN], "> 0"),
    (sb.ServoPositionDrive, "current_limit_a", [0, NAN], "> 0"),
    (sb.ServoPositionDrive, "torque_limit_nm", [0, NAN], "> 0"),
    (sb.ServoPositionDrive, "current_bw_hz", [0, NAN], "> 0"),
    (sb.ServoPositionDrive, "alarm_at_s", [-1, NAN], ">= 0"),
    (sb.RigidPlant, "inertia_kgm2", [0, -1e-4, NAN, INF], "> 0"),
    (sb.RigidPlant, "viscous_nms", [-1e-3, NAN, INF], ">= 0"),
    (sb.RigidPlant, "coulomb_nm", [-0.1, NAN, INF], ">= 0"),
    (sb.RigidPlant, "load_nm", [NAN, INF, 2e6], "-1000000..1000000"),
    (sb.RigidPlant, "static_nm", [-1, NAN], ">= 0"),
    (sb.RigidPlant, "stribeck_speed_rad_s", [0, -1, NAN], "> 0"),
    (sb.RigidPlant, "stribeck_exponent", [0.4, 5, NAN], "0.5..4"),
    (sb.RigidPlant, "unbalance_nm", [NAN, INF], "-1000000..1000000"),
    (sb.RigidPlant, "coulomb_asym_nm", [0.1, -0.1, NAN, INF], "|coulomb_asym_nm| <= coulomb_nm"),
    (sb.RigidPlant, "viscous_asym_nms", [1.0, -1.0, NAN], "|viscous_asym_nms| <= viscous_nms"),
    (sb.RigidPlant, "cogging_nm", [-1, NAN], "0..1000000"),
    (sb.RigidPlant, "cogging_periods", [-1, 1001, 2.5, NAN], "0..1000"),
    (sb.TwoMassPlant, "jm_kgm2", [0, -1, NAN], "> 0"),
    (sb.TwoMassPlant, "jl_kgm2", [0, NAN, INF], "> 0"),
    (sb.TwoMassPlant, "k_nm_per_rad", [0, -5, NAN], "> 0"),
    (sb.TwoMassPlant, "c_nms_per_rad", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "motor_viscous_nms", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "motor_coulomb_nm", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "motor_static_nm", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "motor_stribeck_speed_rad_s", [0, NAN], "> 0"),
    (sb.TwoMassPlant, "motor_stribeck_exponent", [0, 9, NAN], "0.5..4"),
    (sb.TwoMassPlant, "load_viscous_nms", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "load_coulomb_nm", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "load_static_nm", [-1, NAN], ">= 0"),
    (sb.TwoMassPlant, "load_stribeck_speed_rad_s", [0, NAN], "> 0"),
    (sb.TwoMassPlant, "load_stribeck_exponent", [0, 9, NAN], "0.5..4"),
    (sb.TwoMassPlant, "load_nm", [NAN, 2e6], "-1000000..1000000"),
    (sb.TwoMassPlant, "unbalance_nm", [NAN], "-1000000..1000000"),
    (sb.TwoMassPlant, "motor_coulomb_asym_nm", [0.1, NAN], "|motor_coulomb_asym_nm| <= motor_coulomb_nm"),
    (sb.TwoMassPlant, "motor_viscous_asym_nms", [1.0, NAN], "|motor_viscous_asym_nms| <= motor_viscous_nms"),
    (sb.TwoMassPlant, "load_coulomb_asym_nm", [-0.1, INF], "|load_coulomb_asym_nm| <= load_coulomb_nm"),
    (sb.TwoMassPlant, "load_viscous_asym_nms", [-1.0, NAN], "|load_viscous_asym_nms| <= load_viscous_nms"),
    (sb.TwoMassPlant, "cogging_nm", [-1, NAN], "0..1000000"),
    (sb.TwoMassPlant, "cogging_periods", [-1, 0.5], "0..1000"),
    (sb.Switches, "home_min_rad", [NAN], "not a number"),
    (sb.Switches, "home_max_rad", [NAN], "not a number"),
    (sb.Switches, "pos_limit_rad", [NAN, -INF], "+inf"),
    (sb.Switches, "neg_limit_rad", [NAN, INF], "-inf"),
    (sb.Encoder, "counts_per_rev", [0, -4, 1000.5, NAN, INF, 2**31 + 1], "1..2147483648"),
    (sb.Encoder, "quantize", [3], "0/False or 1/True"),
    (sb.Encoder, "noise_counts", [-0.1, NAN, INF], ">= 0"),
    (sb.Encoder, "seed", [-1, 2**32, 1.5, NAN], "0..4294967295"),
    (sb.Encoder, "index_angle_rad", [NAN, INF], "-1000000..1000000"),
    (sb.Encoder, "on_load", [2], "0/False or 1/True"),
    (sb.Dac, "bits", [7, 25, 16.5, NAN], "8..24"),
    (sb.Dac, "full_scale_v", [0, -10, 101, NAN], "0.001..100"),
    (sb.Dac, "quantize", [2, NAN], "0/False or 1/True"),
    # Homing and jog: ADLINK L2268-2278, L2333-2337, L2677-2688; GT L4152-4213, L854, L929-930.
    (sb.AdlinkHome, "mode", [-1, 3, 0.5, NAN], "0..2"),
    (sb.AdlinkHome, "dir", [-1, 2, 0.5, NAN], "0..1"),
    (sb.AdlinkHome, "curve", [-0.1, 1.1, NAN], "0..1"),
    (sb.AdlinkHome, "acc", [0, -1, 2e12, NAN, INF], "0..1e+12"),
    (sb.AdlinkHome, "vm", [0, -1, 2e9, NAN], "0..1000000000"),
    (sb.AdlinkHome, "vo", [0, -1, 2e5, NAN], "0..100000"),
    (sb.AdlinkHome, "shift", [3e9, -3e9, NAN], "-2147483647..2147483647"),
    (sb.AdlinkHome, "eza", [2, -1, 0.5], "0/False or 1/True"),
    (sb.AdlinkHome, "pos", [3e9, NAN, INF], "-2147483647..2147483647"),
    (sb.GtHome, "pos", [2**30, -(2**30) - 1, 0.5, NAN], "-1073741824..1073741823"),
    (sb.GtHome, "vel", [0, -1, 16385, NAN], "0..16384"),
    (sb.GtHome, "acc", [0, -1, 16385, NAN], "0..16384"),
    (sb.GtHome, "index", [2, 0.5], "0/False or 1/True"),
    (sb.GtHome, "zero", [2, -1], "0/False or 1/True"),
    (sb.AdlinkJog, "mode", [-1, 2, 0.5, NAN], "0..1"),
    (sb.AdlinkJog, "dir", [-1, 2, NAN], "0..1"),
    (sb.AdlinkJog, "sf", [-0.1, 1.5, NAN], "0..1"),
    (sb.AdlinkJog, "acc", [0, -1, 2e12, NAN], "0..1e+12"),
    (sb.AdlinkJog, "dec", [0, -1, 2e12, NAN], "0..1e+12"),
    (sb.AdlinkJog, "vm", [0, -1, 2e9, NAN], "0..1000000000"),
    (sb.AdlinkJog, "offset", [0, -1, 3e9, NAN], "0..2147483647"),
    (sb.AdlinkJog, "delay_us", [-1, 1e7 + 1, NAN], "0..10000000"),
    # FollowEx set-up, iDEABOX (seed 003) L475-550, L6173-6199, L7212-7417
    (sb.FollowExSetup, "dir", [2, -2, 0.5, NAN], "-1..1 (0 both, 1 positive, -1 negative; iDEABOX L6185)"),
    (sb.FollowExSetup, "master_type", [0, 4, 1.5, NAN], "1..3"),
    (sb.FollowExSetup, "master_item", [-1, 2, 0.5, NAN], "0..1"),
    (sb.FollowExSetup, "memory", [-1, 3, 0.5, NAN], "0..2 (0: 16, 1: 512, 2: dynamic"),
    (sb.FollowExSetup, "max_segment", [-1, 2**31, 1.5, NAN], "0..2147483647"),
    (sb.FollowExSetup, "event", [0, 3, 1.5, NAN], "1..2 (1 START, 2 PASS"),
    (sb.FollowExSetup, "master_dir", [2, -2, NAN], "-1..1"),
    (sb.FollowExSetup, "master_dir", [0], "must be 1 or -1"),
    (sb.FollowExSetup, "event_pos", [2**31, -(2**31) - 1, 0.5, NAN], "-2147483648..2147483647"),
    (sb.FollowExSetup, "loop", [32768, -32769, 1.5, INF], "-32768..32767"),
    # Coordinated paths: GUC (seed 002) L704-709, L725-732, L771-798; iDEABOX (seed 003) L5871; GT L1956
    (sb.PathSetup, "cycle_ms", [0, 101, NAN], "0.01..100"),
    (sb.PathSetup, "fifo_capacity", [0, 1.5, NAN], "1..10000000"),
    (sb.PathSetup, "syn_vel_max", [0, -1, NAN, INF], "1000000000"),
    (sb.PathSetup, "syn_acc_max", [0, -1, NAN], "1000000000"),
    (sb.PathSetup, "even_time_ms", [-1, 32767, NAN], "0..32766"),
    (sb.PathSetup, "stop_dec_smooth", [-1, 32768, NAN], "0..32767"),
    (sb.PathSetup, "stop_dec_abrupt", [-1, 32768, NAN], "0..32767"),
    (sb.PathSetup, "corner_axis_acc", [-1, NAN, INF], "0..1000000000"),
    (sb.PathSetup, "axis_acc_1", [-1, NAN, INF], "0..1000000000"),
    (sb.PathSetup, "axis_acc_2", [-1, NAN, INF], "0..1000000000"),
    (sb.PathSetup, "axis_acc_3", [-1, NAN, INF], "0..1000000000"),
    (sb.PathSetup, "axis_acc_4", [-1, NAN, INF], "0..1000000000"),
    (sb.PathSetup, "return_to_stop_point", [2], "0/False or 1/True"),
    (sb.PathSetup, "start_vel", [-1, 32768, NAN], "0..32767"),
    (sb.PathSetup, "resume_tolerance", [-1, 1e7, NAN], "0..1000000"),
    (sb.GeLookAheadParams, "t_s", [0, -1, 2, NAN], "0..1"),
    (sb.GeLookAheadParams, "acc_max", [0, -1, NAN], "0..1000000000"),
    (sb.GeLookAheadParams, "acc", [0, 1000, 2000, NAN], "open interval (0, acc_max"),
    (sb.GeLookAheadParams, "vel", [0, -1, NAN], "0..1000000000"),
    (sb.GeLookAheadParams, "n", [0, 32767, 1.5, NAN], "1..32766"),
    (sb.GeLookAheadParams, "con", [0, -1, NAN], "0..1000000000"),
    (sb.AdlinkInterpSetup, "period_s", [0, 1, NAN], "0.0001..0.1"),
    (sb.AdlinkInterpSetup, "buffer_size", [0, 1.5, NAN], "1..1000000"),
    (sb.LookAheadParams, "t_ms", [0, -1, 1001, NAN], "0..1000"),
    (sb.LookAheadParams, "acc_max", [0, -1, 32768, NAN], "0..32767"),
    (sb.LookAheadParams, "n", [-1, 32767, 1.5, NAN], "0..32766"),
    (sb.CardLimits, "enabled", [2, 0.5], "0/False or 1/True"),
    (sb.CardLimits, "pos_active_low", [2, -1], "0/False or 1/True"),
    (sb.CardLimits, "neg_active_low", [2, -1], "0/False or 1/True"),
    (sb.CardLimits, "soft_pos_enabled", [2, -1], "0/False or 1/True"),
    (sb.CardLimits, "soft_neg_enabled", [2, -1], "0/False or 1/True"),
    (sb.CardLimits, "soft_pos_pulse", [NAN, INF], "must be finite"),
    (sb.CardLimits, "soft_neg_pulse", [NAN, -INF], "must be finite"),
]


@pytest.mark.parametrize("cls,field,bad,expect", [(c, f, v, e) for c, f, vals, e in BAD for v in vals],
                         ids=lambda x: repr(x) if not isinstance(x, type) else x.__name__)
def test_constructor_rejects(cls, field, bad, expect):
    with pytest.raises(ValueError) as info:
        cls(**{field: bad})
    msg = str(info.value)
    assert f"{cls.__name__}.{field} = " in msg
    assert expect in msg


@pytest.mark.parametrize("cls,field,bad,expect", [(c, f, vals[0], e) for c, f, vals, e in BAD],
                         ids=lambda x: repr(x) if not isinstance(x, type) else x.__name__)
def test_setter_rejects_and_keeps_the_old_value(cls, field, bad, expect):
    obj = cls()
    before = obj.to_dict()
    with pytest.raises(ValueError, match=field):
        setattr(obj, field, bad)
    assert obj.to_dict() == before


def test_every_field_is_covered_by_a_bad_input_test():
    covered = {(c, f) for c, f, _v, _e in BAD}
    for cls in (sb.GtServoLaw, sb.ApsServoLaw, sb.TorqueDrive, sb.VelocityDrive, sb.StepperDrive,
                sb.ServoPositionDrive, sb.RigidPlant, sb.TwoMassPlant,
                sb.Encoder, sb.Dac, sb.Switches, sb.AdlinkHome, sb.GtHome, sb.AdlinkJog, sb.FollowExSetup, sb.PathSetup, sb.LookAheadParams,
                sb.GeLookAheadParams, sb.AdlinkInterpSetup, sb.CardLimits):
        for field in cls.FIELDS:
            assert (cls, field) in covered, f"{cls.__name__}.{field} has no bad-input test"


def test_wrong_types_and_unknown_fields():
    with pytest.raises(TypeError, match="kp must be a number"):
        sb.GtServoLaw(kp="100")
    with pytest.raises(TypeError, match="unexpected keyword argument 'kpp'.*kp, ki, kd"):
        sb.GtServoLaw(kpp=1)
    with pytest.raises(TypeError):
        sb.GtServoLaw(10)  # keyword arguments only


def test_value_type_protocol():
    law = sb.ApsServoLaw(kp=100, kp_shift=2, pid_shift=3)
    assert law.effective_gains()["kp"] == 3200.0  # ADLINK manual L1733 worked example, see decisions.md
    assert law == sb.ApsServoLaw(kp=100, kp_shift=2, pid_shift=3)
    assert law != law.replace(kp=101)
    assert pickle.loads(pickle.dumps(law)) == law
    assert repr(law).startswith("ApsServoLaw(kp=100, ki=0, kd=0, kvff=0, kaff=0, kp_shift=2, ki_shift=-15")
    assert "v_inverse=False" in repr(law)
    assert np.isinf(sb.TorqueDrive(current_bw_hz=INF).current_bw_hz)  # inf = ideal current loop


@pytest.mark.parametrize("law,period", [
    (sb.GtServoLaw(), 47e-6), (sb.GtServoLaw(), 1967e-6), (sb.GtServoLaw(), NAN), (sb.GtServoLaw(), 0.0),
    (sb.ApsServoLaw(), 49e-6), (sb.ApsServoLaw(), 2001e-6), (sb.ApsServoLaw(), INF), (sb.ApsServoLaw(), -1.0),
])
def test_axis_servo_period_range_is_the_cards(law, period):
    with pytest.raises(ValueError, match="Axis.servo_period_s = .* (allowed range|finite)"):
        sb.Axis(law=law, servo_period_s=period)


def test_axis_default_periods_and_ranges():
    assert sb.Axis().servo_period_s == pytest.approx(200e-6)  # GT manual L578-580
    assert sb.Axis(law=sb.ApsServoLaw()).servo_period_s == pytest.approx(250e-6)  # ADLINK manual L1733
    sb.Axis(servo_period_s=48e-6)
    sb.Axis(servo_period_s=1966.08e-6)
    sb.Axis(law=sb.ApsServoLaw(), servo_period_s=50e-6)
    sb.Axis(law=sb.ApsServoLaw(), servo_period_s=2000e-6)


@pytest.mark.parametrize("substeps", [0, 1001, 1.5, NAN])
def test_axis_substeps(substeps):
    with pytest.raises(ValueError, match="Axis.substeps"):
        sb.Axis(substeps=substeps)


def test_axis_rejects_a_part_of_the_wrong_kind():
    with pytest.raises(TypeError, match="law must be a GtServoLaw or an ApsServoLaw"):
        sb.Axis(law=sb.RigidPlant())
    with pytest.raises(TypeError, match="plant must be a RigidPlant, a TwoMassPlant or an LtiPlant"):
        sb.Axis(plant=sb.TorqueDrive())
    with pytest.raises(TypeError, match="drive must be a TorqueDrive, VelocityDrive, StepperDrive or ServoPositionDrive"):
        sb.Axis(drive=sb.RigidPlant())


def test_cross_field_rules():
    with pytest.raises(ValueError, match="RigidPlant.static_nm = 0.01 must be 0 .* >= coulomb_nm"):
        sb.RigidPlant(coulomb_nm=0.02, static_nm=0.01)
    with pytest.raises(ValueError, match="TwoMassPlant.load_static_nm"):
        sb.TwoMassPlant(load_coulomb_nm=0.02, load_static_nm=0.01)
    with pytest.raises(ValueError, match="Switches.home_min_rad = 2 must be <= home_max_rad"):
        sb.Switches(home_min_rad=2.0, home_max_rad=1.0)
    with pytest.raises(ValueError, match="Switches.home_max_rad"):
        sb.Switches(home_min_rad=1.0)
    with pytest.raises(ValueError, match="Switches.neg_limit_rad = 5 must be below pos_limit_rad"):
        sb.Switches(neg_limit_rad=5.0, pos_limit_rad=1.0)
    with pytest.raises(ValueError, match="CardLimits.soft_neg_pulse = 5 must be below soft_pos_pulse"):
        sb.CardLimits(soft_pos_enabled=True, soft_neg_enabled=True, soft_pos_pulse=1, soft_neg_pulse=5)
    with pytest.raises(ValueError, match="VelocityDrive.torque_limit_nm .* cannot both be inf"):
        sb.VelocityDrive(current_limit_a=INF)
    # The speed loop must run a whole number of times per servo tick: 20 kHz fits 200 us and 250 us, 3 kHz does not.
    sb.Axis(drive=sb.VelocityDrive(loop_rate_hz=20000), servo_period_s=200e-6)
    sb.Axis(law=sb.ApsServoLaw(), drive=sb.VelocityDrive(loop_rate_hz=20000))
    with pytest.raises(ValueError, match="VelocityDrive.loop_rate_hz = 3000 must be a whole multiple of the servo rate"):
        sb.Axis(drive=sb.VelocityDrive(loop_rate_hz=3000), servo_period_s=250e-6)


@pytest.mark.parametrize("kwargs,field", [
    (dict(distance_pulse=100, vel_pulse_per_tick=0, acc_pulse_per_tick2=1), "vel_pulse_per_tick"),
    (dict(distance_pulse=100, vel_pulse_per_tick=1, acc_pulse_per_tick2=-1), "acc_pulse_per_tick2"),
    (dict(distance_pulse=NAN, vel_pulse_per_tick=1, acc_pulse_per_tick2=1), "distance_pulse"),
    (dict(distance_pulse=10, vel_pulse_per_tick=1, acc_pulse_per_tick2=1, dwell_after=-1), "dwell_after"),
    (dict(distance_pulse=10, vel_pulse_per_tick=1, acc_pulse_per_tick2=1, dwell_before=2.5), "dwell_before"),
    (dict(distance_pulse=1e9, vel_pulse_per_tick=1e-3, acc_pulse_per_tick2=1), "distance_pulse"),
])
def test_trapezoid_move_rejects(kwargs, field):
    with pytest.raises(ValueError, match=field):
        sb.trapezoid_move(**kwargs)


def test_run_rejects_bad_commands():
    axis = sb.Axis()
    with pytest.raises(ValueError, match=r"positions\[2\] = nan is not a finite number"):
        axis.run([0.0, 1.0, NAN])
    with pytest.raises(ValueError, match="1-D"):
        axis.run(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="velocities has 2 samples; expected 3"):
        axis.run([0.0, 1.0, 2.0], velocities=[0.0, 1.0])
    with pytest.raises(ValueError, match="unknown signal 'speed'"):
        axis.run([0.0, 1.0], signals=["speed"])
    assert axis.tick == 0  # nothing ran
