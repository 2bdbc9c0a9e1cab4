"""Relay auto-tuning (issue 6, in progress): ADLINK auto servo tuning, seed 004 L1764-1847 (adlink.md §4)."""

import numpy as np
import pytest

import servobench as sb
from servobench import frequency as fr
from servobench.examples import resonant_axis, velocity_axis




def test_defaults_are_the_manuals_T10():
    # adlink.md §10 T10 (L1842-1847): deviation 2000 pulse, amplitude 1 V, data length 200, hysteresis 50 pulse,
    # sampling 500 us.
    import inspect
    sig = inspect.signature(sb.relay_autotune)
    assert sig.parameters["deviation_limit_pulse"].default == 2000
    assert sig.parameters["amplitude_v"].default == 1.0
    assert sig.parameters["data_length"].default == 200
    assert sig.parameters["hysteresis_pulse"].default == 50
    assert sig.parameters["sampling_time_s"].default == 500e-6
    assert sig.parameters["max_spread"].default == 0.10  # T11, L1794


@pytest.mark.parametrize("plant", ["rigid", "two_mass"])
@pytest.mark.parametrize("eps", [150, 450])
def test_tuned_loop_has_sixty_degrees_measured_by_the_bode_sweep(plant, eps):
    axis = velocity_axis(plant)
    res = sb.relay_autotune(axis, hysteresis_pulse=eps, sampling_time_s=100e-6)
    assert res.status == "completed", res.message
    assert len(res.cycles["kp"]) == 200
    res.apply(axis)
    # "Set final" (L1820): gains written, feed-forward and filters off, servo on.
    assert axis.servo_on and axis.law.kvff == 0 and axis.law.kaff == 0
    assert axis.filters == (sb.AdlinkBiquad(), sb.AdlinkBiquad())
    meas = fr.sine_sweep(axis, start_hz=5, end_hz=2000, amplitude_pulse=2, points=150, update_s=0.4)
    assert meas.status == "completed"
    pm = meas.margins().phase_margin_deg
    assert pm == pytest.approx(60, abs=5)


def test_bandwidth_falls_as_hysteresis_rises():
    # The manual's trend (L1796-1802): larger hysteresis, lower bandwidth, phase margin kept.
    bws = []
    for eps in (50, 150, 250, 450):
        axis = velocity_axis()
        res = sb.relay_autotune(axis, hysteresis_pulse=eps, sampling_time_s=100e-6, data_length=20)
        res.apply(axis)
        bws.append(fr.analytic_response(axis, np.geomspace(1, 4000, 4000)).margins().bandwidth_hz)
    assert all(b1 > b2 for b1, b2 in zip(bws, bws[1:])), bws


def test_card_laws_from_the_result():
    res = sb.relay_autotune(velocity_axis(), hysteresis_pulse=150, sampling_time_s=100e-6, data_length=10)
    aps = res.aps_law()
    assert aps.kp <= 65535 and aps.pid_shift == -5 and aps.kvff == 0
    assert aps.kp * 2.0 ** (aps.kp_shift + aps.pid_shift) == pytest.approx(res.kp, rel=2e-5)
    gt = res.gt_law()
    assert gt.kp == round(res.kp) and gt.ki == round(256 * res.ki)
    assert res.ti_s == pytest.approx(4 * res.td_s)


def test_stop_reasons_and_bad_input():
    axis = velocity_axis(servo_period_s=250e-6)
    res = sb.relay_autotune(axis, deviation_limit_pulse=100)
    assert res.status == "deviation_exceeded" and not axis.servo_on
    res = sb.relay_autotune(velocity_axis(servo_period_s=250e-6), progress=lambda done, total: done < 3)
    assert res.status == "user_stop" and len(res.cycles["kp"]) == 3
    for kw, name in ((dict(amplitude_v=0), "amplitude_v"), (dict(amplitude_v=10.5), "amplitude_v"),
                     (dict(hysteresis_pulse=0), "hysteresis_pulse"), (dict(data_length=0), "data_length"),
                     (dict(sampling_time_s=50e-6), "sampling_time_s"),
                     (dict(sampling_time_s=2e-3), "sampling_time_s"),
                     (dict(deviation_limit_pulse=-1), "deviation_limit_pulse"),
                     (dict(phase_margin_deg=95), "phase_margin_deg")):
        with pytest.raises(ValueError, match=name):
            sb.relay_autotune(velocity_axis(), **kw)


def test_torque_mode_double_integrator_has_no_steady_cycle():
    # A relay with hysteresis needs phase above -180 deg: an undamped double integrator never settles.
    axis = sb.Axis(law=sb.ApsServoLaw(), plant=sb.TwoMassPlant(jm_kgm2=5e-4, jl_kgm2=5e-4, k_nm_per_rad=3000),
                   drive=sb.TorqueDrive(current_limit_a=float("inf")),
                   encoder=sb.Encoder(quantize=False), dac=sb.Dac(quantize=False), servo_period_s=250e-6)
    res = sb.relay_autotune(axis, amplitude_v=0.5, hysteresis_pulse=150, deviation_limit_pulse=0, data_length=20)
    assert res.status == "spread_too_large"
    assert np.all(np.diff(res.cycles["amplitude_pulse"]) > 0)  # the oscillation grows cycle after cycle


@pytest.mark.parametrize("plant", ["rigid", "two_mass"])
@pytest.mark.parametrize("eps", [150, 450])
def test_identified_ultimate_point_matches_the_analytic_prediction(plant, eps):
    # Issue 6 point 5: estimated ultimate gain within 2 %, frequency within 1 % of the simulated loop's analytic
    # values (the describing-function prediction from the analytic plant). At 100 us sampling on a 10 kHz axis.
    axis = velocity_axis(plant)
    pred = sb.autotune.predicted_limit_cycle(axis, amplitude_v=1.0, hysteresis_pulse=eps, sampling_time_s=100e-6)
    res = sb.relay_autotune(axis, hysteresis_pulse=eps, sampling_time_s=100e-6, data_length=50)
    assert res.status == "completed"
    assert res.ultimate_freq_hz == pytest.approx(pred["freq_hz"], rel=0.01)
    assert res.ultimate_gain_v_per_pulse == pytest.approx(pred["ultimate_gain_v_per_pulse"], rel=0.02)
    assert np.mean(res.cycles["amplitude_pulse"]) == pytest.approx(pred["amplitude_pulse"], rel=0.02)


def test_no_limit_cycle_predicted_for_an_undamped_double_integrator():
    axis = sb.Axis(law=sb.ApsServoLaw(), plant=sb.TwoMassPlant(jm_kgm2=5e-4, jl_kgm2=5e-4, k_nm_per_rad=3000,
                                                                motor_viscous_nms=0, load_viscous_nms=0),
                   drive=sb.TorqueDrive(current_limit_a=float("inf")), encoder=sb.Encoder(quantize=False),
                   dac=sb.Dac(quantize=False), servo_period_s=250e-6)
    with pytest.raises(ValueError, match="no limit cycle"):
        sb.autotune.predicted_limit_cycle(axis, hysteresis_pulse=150)


def test_classic_rules_from_the_same_experiment():
    axis = velocity_axis()
    res = sb.relay_autotune(axis, hysteresis_pulse=150, sampling_time_s=100e-6, data_length=20)
    ku = res.ultimate_gain_v_per_pulse * 3276.7
    tu = 1 / res.ultimate_freq_hz
    zn, tl = res.rule("ziegler_nichols"), res.rule("tyreus_luyben")
    assert zn.kc == pytest.approx(0.6 * ku) and zn.ti_s == pytest.approx(tu / 2) and zn.td_s == pytest.approx(tu / 8)
    assert tl.kc == pytest.approx(ku / 2.2) and tl.ti_s == pytest.approx(2.2 * tu)
    assert zn.kd == pytest.approx(zn.kc * zn.td_s / 100e-6) and zn.ki == pytest.approx(zn.kc * 100e-6 / zn.ti_s)
    assert res.rule("phase_margin") is res
    margins = {}
    for name, r in (("pm", res), ("zn", zn), ("tl", tl)):
        a = velocity_axis()
        r.apply(a)
        margins[name] = fr.analytic_response(a, np.geomspace(1, 4900, 4000)).margins().phase_margin_deg
    # The designed loop sits at 60 deg; the classic rules land wherever the identified point puts them (they ignore
    # the hysteresis's phase shift asin(eps/a)): here ZN 62 deg, TL 95 deg.
    assert margins["pm"] == pytest.approx(60, abs=5)
    assert all(np.isfinite(v) for v in margins.values()) and len({round(v, 1) for v in margins.values()}) == 3
    with pytest.raises(ValueError, match="rule"):
        res.rule("cohen_coon")


# ---------------------------------------------------------------------------------------------------------------
# Model-based design (issue 6: "crossover for the target margin, notch at the resonance")
# ---------------------------------------------------------------------------------------------------------------


MODEL_AXES = {"rigid": lambda: velocity_axis("rigid"), "two_mass": resonant_axis,
              "two_mass_torque": lambda: resonant_axis("torque"),
              "two_mass_gt": lambda: resonant_axis(law=sb.GtServoLaw(), servo_period_s=200e-6)}


@pytest.mark.parametrize("name", list(MODEL_AXES))
def test_model_based_tune_measured_phase_margin_and_crossover(name):
    axis = MODEL_AXES[name]()
    res = sb.model_based_tune(axis)
    res.apply(axis)
    assert axis.servo_on and axis.filters == res.filters
    meas = fr.sine_sweep(axis, start_hz=5, end_hz=0.4 / axis.servo_period_s, amplitude_pulse=2, points=150,
                         update_s=0.4)
    assert meas.status == "completed"
    m = meas.margins()
    print(f"{name}: designed {res.crossover_hz:.1f} Hz; measured PM {m.phase_margin_deg:.1f} deg at "
          f"{m.pm_freq_hz:.1f} Hz, GM {m.gain_margin_db:.1f} dB, Ms {m.ms:.2f}; notch {res.notch['used']}")
    assert m.phase_margin_deg == pytest.approx(60, abs=5)
    assert m.pm_freq_hz == pytest.approx(res.crossover_hz, rel=0.03)
    assert m.gain_margin_db >= 10 - 0.5 and m.ms <= 2.0 + 0.05
    # The prediction is the loop the sweep measures.
    assert m.phase_margin_deg == pytest.approx(res.margins.phase_margin_deg, abs=1)
    if name != "rigid":
        assert res.notch["used"] and res.crossover_hz > res.crossover_without_notch_hz


def test_model_based_notch_lowers_the_measured_resonance_peak():
    with_notch, without = resonant_axis(), resonant_axis()
    r1 = sb.model_based_tune(with_notch)
    r0 = sb.model_based_tune(without, notch=False)
    r1.apply(with_notch)
    r0.apply(without)
    assert not r0.notch["used"] and r1.notch["used"]
    fres = r1.notch["center_hz"]
    # The resonance found lies within 5 % of the mechanical one (moved by the drive's speed loop).
    assert fres == pytest.approx(with_notch.plant.resonance_hz, rel=0.05)
    # 11 log-spaced points, the middle one on the resonance.
    kw = dict(start_hz=fres / 1.1, end_hz=fres * 1.1, amplitude_pulse=2, points=11, update_s=0.05)
    g1 = fr.sine_sweep(with_notch, **kw).gain_db("open_loop")
    g0 = fr.sine_sweep(without, **kw).gain_db("open_loop")
    print(f"open loop at the resonance {fres:.1f} Hz: {g0[5]:.1f} dB without notch, {g1[5]:.1f} dB with "
          f"(q {r1.notch['q']}, depth {r1.notch['depth_db']:.1f} dB); crossover {r0.crossover_hz:.1f} -> "
          f"{r1.crossover_hz:.1f} Hz")
    assert g0[5] - g1[5] > 20
    assert np.argmax(g0) == 5 or g0[5] > g0[0]  # without the notch the open loop peaks there
    assert r1.crossover_hz > r0.crossover_hz


@pytest.mark.parametrize("name", ["rigid", "two_mass"])
def test_model_based_reaches_at_least_the_relay_crossover(name):
    axis = MODEL_AXES[name]()
    relay = sb.relay_autotune(axis, hysteresis_pulse=150, sampling_time_s=100e-6)
    assert relay.status == "completed"
    relay.apply(axis)
    m_relay = fr.analytic_response(axis, np.geomspace(1, 4900, 4000)).margins()
    model = sb.model_based_tune(MODEL_AXES[name]())
    print(f"{name}: relay crossover {m_relay.pm_freq_hz:.1f} Hz (BW {m_relay.bandwidth_hz:.1f} Hz), model-based "
          f"{model.crossover_hz:.1f} Hz (BW {model.margins.bandwidth_hz:.1f} Hz)")
    assert model.crossover_hz >= m_relay.pm_freq_hz
    assert model.margins.bandwidth_hz >= m_relay.bandwidth_hz


def test_model_based_result_conversions_and_summary():
    res = sb.model_based_tune(resonant_axis())
    assert res.ti_s == pytest.approx(4 * res.td_s)
    assert res.kd == pytest.approx(res.kc * res.td_s / 100e-6) and res.ki == pytest.approx(res.kc * 100e-6 / res.ti_s)
    aps = res.aps_law()
    assert aps.kp * 2.0 ** (aps.kp_shift + aps.pid_shift) == pytest.approx(res.kp, rel=2e-5)
    assert res.law == aps
    gt = res.gt_law()
    assert gt.kp == round(res.kp) and gt.kd == round(res.kd)
    n = res.notch
    assert n["adlink_biquad"] == res.filters[0] and res.filters[1] == sb.AdlinkBiquad()
    assert n["low_hz"] < n["center_hz"] < n["high_hz"]
    assert n["high_hz"] - n["low_hz"] == pytest.approx(n["center_hz"] / n["q"])
    assert np.all(np.diff(res.scan["freq_hz"]) > 0) and res.scan["feasible"].any()
    s = str(res)
    for word in ("resonances", "notch chosen", "crossover: raised from", "limited by", "predicted"):
        assert word in s, s
    assert repr(res).startswith("ModelTuneResult(")


def test_model_based_refusals():
    pulse = sb.Axis(law=sb.ApsServoLaw(), drive=sb.ServoPositionDrive(), plant=sb.RigidPlant())
    with pytest.raises(ValueError, match="pulse-input"):
        sb.model_based_tune(pulse)
    with pytest.raises(ValueError, match="min_gain_margin_db.*nearest|nearest.*min_gain_margin_db"):
        sb.model_based_tune(velocity_axis(), min_gain_margin_db=45)
    for kw, name in ((dict(phase_margin_deg=95), "phase_margin_deg"), (dict(alpha=0.5), "alpha"),
                     (dict(max_ms=1.0), "max_ms"), (dict(resonance_hz=0), "resonance_hz"),
                     (dict(resonance_hz=6000), "resonance_hz"), (dict(max_pid_lead_deg=95), "max_pid_lead_deg"),
                     (dict(law="xyz"), "law"), (dict(candidates=2), "candidates")):
        with pytest.raises(ValueError, match=name):
            sb.model_based_tune(velocity_axis(), **kw)
