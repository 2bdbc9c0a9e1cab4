"""Issue 20 point 4: tuning refuses what it cannot stand behind. apply() checks the designed loop on the linear
model (closed-loop poles, PM within 5 deg of the target, GM floor) and by a verification sweep; a failing design
raises TuningRefused with the report and leaves the axis alone; force=True applies anyway."""

import pytest

import servobench as sb
from servobench.examples import resonant_axis, velocity_axis
from servobench.tune_check import TuningRefused, check_design


def test_model_based_design_passes_its_check_on_model_and_sweep():
    axis = resonant_axis()
    design = sb.model_based_tune(axis)
    check = design.apply(axis)
    assert check.accepted and not check.failures
    assert check.model.stable and check.measured is not None and check.measured.stable
    assert abs(check.measured.phase_margin_deg - 60) < 5
    assert axis.law == design.aps_law(axis.law) and axis.servo_on


def test_relay_gains_on_a_different_machine_are_refused_and_the_axis_is_untouched():
    res = sb.relay_autotune(velocity_axis("rigid"), hysteresis_pulse=150, sampling_time_s=100e-6, data_length=30)
    assert res.status == "completed"
    # The same gains on a machine with 20x the inertia: the loop the design promised is not there.
    heavy = sb.Axis(law=sb.ApsServoLaw(), plant=sb.RigidPlant(inertia_kgm2=2e-3, viscous_nms=1e-4),
                    drive=sb.VelocityDrive(speed_per_volt_rad_s=31.4, current_limit_a=float("inf"),
                                           torque_limit_nm=1e9),
                    encoder=sb.Encoder(quantize=False), dac=sb.Dac(quantize=False), servo_period_s=100e-6)
    before = heavy.law
    with pytest.raises(TuningRefused) as info:
        res.apply(heavy)
    check = info.value.check
    assert not check.accepted and check.failures
    assert "REFUSED" in str(check) and "phase margin" in str(info.value)
    assert heavy.law == before  # nothing written
    forced = res.apply(heavy, force=True)
    assert not forced.accepted and heavy.law != before


def test_unstable_design_is_refused_on_the_model():
    axis = velocity_axis("rigid")
    hot = sb.ApsServoLaw(kp=60000, kp_shift=0, kd=0)
    check = check_design(axis, hot, (None, None), target_phase_margin_deg=60)
    assert not check.accepted and not check.model.stable
    assert any("UNSTABLE" in f for f in check.failures)
    assert "not swept" in check.measured_note
    with pytest.raises(ValueError, match="pm_tolerance_deg"):
        check_design(axis, hot, (None, None), target_phase_margin_deg=60, pm_tolerance_deg=0)
