"""python-control both ways (issue 23.4): to_control() on laws, biquads, plants and the loop (discrete, one-tick
delay, dt explicit), FRD in and out (rad/s inside control.FRD), and control.margin on the exported loop agreeing
with servobench's margins -- on stable and unstable loops."""

from __future__ import annotations

import numpy as np
import pytest

control = pytest.importorskip("control")

import servobench as sb  # noqa: E402
from servobench import design, interop  # noqa: E402
from servobench import frequency as fr  # noqa: E402


def _at(sys, f_hz):
    """A python-control system's response at f_hz (Hz): s = j w or z = exp(j w dt)."""
    return np.array([complex(sys(np.exp(2j * np.pi * f * sys.dt) if sys.dt else 2j * np.pi * f)) for f in f_hz])


def _axes():
    """Stable loops of several kinds: GT and ADLINK laws, rigid, two-mass and user plants, filters."""
    tm = sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01)
    notch = design.notch(float(tm.resonance_hz), 250e-6, q=2)
    lti = sb.LtiPlant.from_control(control.tf([1], [1.5e-4, 2e-4, 0]))
    return {
        "gt_rigid": sb.demo_axis(),
        "gt_pd_rigid": sb.Axis(law=sb.GtServoLaw(kp=30, kd=700, ki=0, ilmt=0),
                               plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4)),
        "aps_two_mass_notch": sb.Axis(law=sb.ApsServoLaw(kp=30 * 1024, kd=9600),
                                      plant=tm, filters=(notch, notch.to_adlink())),
        "gt_lti_pid": sb.Axis(law=sb.GtServoLaw(kp=38, ki=60, kd=830), plant=lti,
                              drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500)),
    }


# -- parts out ----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", list(_axes()))
def test_parts_multiply_to_the_analytic_loop(name):
    ax = _axes()[name]
    ts = ax.servo_period_s
    f = np.geomspace(2, 0.45 / ts, 50)
    model = fr.analytic_response(ax, f)
    law = ax.law.to_control(servo_period_s=ts)
    assert law.dt == ts
    filt = 1
    for q in ax.filters:
        if q is not None:
            filt = filt * q.to_control(servo_period_s=ts)
    plant = ax.plant.to_control(servo_period_s=ts)  # torque N*m -> angle rad, ZOH at ts
    d = ax.drive
    # drive as an ideal or first-order current loop, then counts -> V, rad -> pulse and the one-tick delay
    bw = d.current_bw_hz
    drive = control.tf([d.amps_per_volt * d.kt], [1], 0) if bw == float("inf") else \
        control.tf([d.amps_per_volt * d.kt * 2 * np.pi * bw], [1, 2 * np.pi * bw])
    sign = -1.0 if isinstance(ax.law, sb.ApsServoLaw) and ax.law.v_inverse else 1.0
    p_ct = control.sample_system(drive * ax.plant.to_control(), ts, method="zoh")
    scale = sign * 10 / 32767 * ax.encoder.counts_per_rev / (2 * np.pi)
    p = p_ct * control.tf([1], [1, 0], ts) * scale
    loop = filt * law * p
    np.testing.assert_allclose(_at(loop, f), model.loop_gain, rtol=1e-7)
    np.testing.assert_allclose(_at(p, f), model.plant, rtol=1e-7)
    # the exported loop itself
    exported = ax.to_control()
    assert exported.dt == ts
    np.testing.assert_allclose(_at(exported, f), model.loop_gain, rtol=1e-7)
    if bw == float("inf"):
        np.testing.assert_allclose(_at(plant, f) * d.amps_per_volt * d.kt * scale * np.exp(-2j * np.pi * f * ts),
                                   model.plant, rtol=1e-7)


def test_biquads_and_plants_agree_with_their_own_responses():
    lp = design.lowpass(1000, 100e-6)
    f = np.array([10.0, 300.0, 1000.0, 3000.0])
    np.testing.assert_allclose(_at(lp.to_control(), f), lp.frequency_response(f), rtol=1e-12)
    ad = lp.to_adlink()
    np.testing.assert_allclose(_at(ad.to_control(servo_period_s=100e-6), f),
                               ad.to_float().frequency_response(f), rtol=1e-12)
    tm = sb.TwoMassPlant()
    f = f[f < 2500]  # below the Nyquist frequency of 200 us
    for out in ("motor", "load"):
        np.testing.assert_allclose(_at(tm.to_control(output=out), f), tm.frequency_response(f, output=out),
                                   rtol=1e-10)
        np.testing.assert_allclose(_at(tm.to_control(output=out, servo_period_s=200e-6), f),
                                   tm.frequency_response(f, output=out, period_s=200e-6), rtol=1e-9)
    g = control.tf([3.0], [1, 2, 5, 0])
    np.testing.assert_allclose(_at(sb.LtiPlant.from_control(g).to_control(), f), _at(g, f), rtol=1e-12)


def test_law_parts_and_sample_time():
    gt = sb.GtServoLaw(kp=38, ki=60, kd=830, kvff=10, kaff=100)
    c = gt.to_control()
    assert c.dt == sb.GtServoLaw.DEFAULT_PERIOD_S  # the card's default when not given
    z = np.exp(2j * np.pi * 100 * c.dt)
    want = 38 + 60 / 256 / (1 - 1 / z) + 830 * (1 - 1 / z)
    assert complex(c(z)) == pytest.approx(want, rel=1e-12)
    ff = gt.to_control(part="feedforward", servo_period_s=500e-6)
    zf = np.exp(2j * np.pi * 100 * 500e-6)
    assert complex(ff(zf)) == pytest.approx(10 * (1 - 1 / zf) + 100 * (1 - 1 / zf) ** 2, rel=1e-12)
    with pytest.raises(ValueError, match="part"):
        gt.to_control(part="x")
    with pytest.raises(ValueError, match="servo_period_s"):
        gt.to_control(servo_period_s=-1)
    with pytest.raises(ValueError, match="sample_time_s = 0"):
        sb.FloatBiquad(b0=1.0).to_control()
    with pytest.raises(ValueError, match="output"):
        sb.RigidPlant().to_control(output="load")
    with pytest.raises(TypeError, match="cannot export"):
        sb.to_control("axis")


# -- FRD both ways ------------------------------------------------------------------------------------------------
def test_frd_out_and_in():
    ax = _axes()["gt_rigid"]
    f = np.geomspace(5, 2000, 200)
    model = fr.analytic_response(ax, f)
    frd = interop.to_frd(model)
    np.testing.assert_allclose(frd.omega, 2 * np.pi * f)            # rad/s inside control.FRD
    back = interop.from_frd(frd, servo_period_s=ax.servo_period_s)
    np.testing.assert_allclose(back.freq_hz, f)                     # Hz in servobench
    np.testing.assert_allclose(back.open_loop, model.open_loop)
    m_back, m_model = back.margins(), fr.margins(f, model.loop_gain)
    assert m_back.stable and m_back.phase_margin_deg == pytest.approx(m_model.phase_margin_deg, abs=1e-9)
    meas = fr.sine_sweep(ax, start_hz=20, end_hz=500, points=6, update_s=0.05)
    mf = interop.to_frd(meas, "plant", usable_only=True)
    assert len(mf.omega) == int(meas.usable.sum())
    plant_in = interop.from_frd(interop.to_frd(model, "plant"), servo_period_s=ax.servo_period_s, which="plant")
    fit = sb.fit_frequency(plant_in, ax, "rigid", guess={"inertia_kgm2": 3e-4, "viscous_nms": 3e-4})
    assert fit.parameters["inertia_kgm2"].value == pytest.approx(ax.plant.inertia_kgm2, rel=1e-3)
    with pytest.raises(ValueError, match="Nyquist"):
        interop.from_frd(control.frd([1, 1], [1.0, 1e5]), servo_period_s=200e-6)
    with pytest.raises(TypeError, match="control.FRD"):
        interop.from_frd(model, servo_period_s=200e-6)


# -- margins agree ------------------------------------------------------------------------------------------------
def _sb_vs_control(ax):
    """servobench's margins and python-control's on the exported loop, read on a dense grid (an FRD, rad/s)."""
    m = fr.analytic_margins(ax)
    loop = ax.to_control()  # the loop gain, discrete state space, dt = the servo period
    w = 2 * np.pi * np.geomspace(1e-3, 0.49999 / ax.servo_period_s, 40000)
    frd = control.frd(loop, w)
    return m, loop, control.margin(frd), control.stability_margins(frd, returnall=True)


def _real_crossings(ax, GM, w180):
    """python-control's phase crossings without the phase jumps at singular points: root-finding on the loop's
    polynomials splits the double pole of the integrating plant at z = 1 by ~1e-6 and reports phase crossings near
    DC with |L| > 1e6 (GM < -120 dB), and it counts the 180 deg jump of the phase through a zero on the unit circle
    (the ADLINK notch's, |L| < 1e-6 there: GM > 120 dB) as a crossing; the loop's real crossings lie far inside."""
    GM, w180 = np.asarray(GM, dtype=float), np.asarray(w180, dtype=float)
    keep = (GM > 1e-6) & (GM < 1e6)
    return 20 * np.log10(GM[keep]), w180[keep] / (2 * np.pi)


@pytest.mark.parametrize("name", list(_axes()))
def test_control_margin_agrees_on_stable_loops(name):
    ax = _axes()[name]
    m, loop, (gm, pm, wcg, wcp), (GM, PM, _SM, w180, wc, _ws) = _sb_vs_control(ax)
    assert m.stable
    # the phase margin at the gain crossover nearest -1 (both libraries' rule) and where
    assert pm == pytest.approx(m.phase_margin_deg, abs=1e-4)
    assert wcp / (2 * np.pi) == pytest.approx(m.pm_freq_hz, rel=1e-6)
    # control.margin's gm is the phase crossover with the smallest |log GM|: servobench's upper or lower margin
    candidates = [x for x in (m.gain_margin_db, m.lower_gain_margin_db) if np.isfinite(x)]
    assert np.isfinite(gm) and min(abs(20 * np.log10(gm) - x) for x in candidates) < 1e-4
    # every crossing, both ways (servobench also lists the Nyquist frequency when the phase is -180 deg there)
    ct_gm, ct_f = _real_crossings(ax, GM, w180)
    sb_f = np.asarray(m.phase_crossovers["freq_hz"], dtype=float)
    sb_gm = np.asarray(m.phase_crossovers["gain_margin_db"], dtype=float)
    inside = sb_f < 0.5 / ax.servo_period_s * (1 - 1e-9)
    order = np.argsort(ct_f)
    np.testing.assert_allclose(ct_f[order], sb_f[inside], rtol=1e-6)
    np.testing.assert_allclose(ct_gm[order], sb_gm[inside], atol=1e-4)
    np.testing.assert_allclose(np.sort(np.asarray(wc, dtype=float)) / (2 * np.pi), m.gain_crossovers["freq_hz"],
                               rtol=1e-6)
    np.testing.assert_allclose(np.asarray(PM, dtype=float)[np.argsort(wc)], m.gain_crossovers["phase_margin_deg"],
                               atol=1e-4)
    # the transfer-function export read by control.margin directly, where python-control's polynomial method holds
    # (no integral action: the double pole at z = 1 only)
    if ax.law.ki == 0:
        gm_t, pm_t, _wcg_t, wcp_t = control.margin(ax.to_control(form="tf"))
        assert pm_t == pytest.approx(m.phase_margin_deg, abs=1e-3)


@pytest.mark.parametrize("plant", [sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4),
                                   sb.LtiPlant.from_control(control.tf([1], [1e-4, 1e-4, 0]))])
def test_both_say_unstable(plant):
    ax = sb.Axis(law=sb.GtServoLaw(kp=38, kd=30, ki=60), plant=plant)  # far too little damping
    m, loop, (gm, pm, _wcg, _wcp), _ = _sb_vs_control(ax)
    assert not m.stable and str(m).startswith("UNSTABLE")
    poles = control.feedback(ax.to_control(), 1).poles()
    assert np.max(np.abs(poles)) > 1.0
    assert m.stability["max_pole_radius"] == pytest.approx(np.max(np.abs(poles)), rel=1e-9)
    assert m.stability["unstable_poles"] == int(np.sum(np.abs(poles) > 1.0))
    assert pm < 0.0 and m.phase_margin_deg < 0.0  # python-control's margins say so too
    assert pm == pytest.approx(m.phase_margin_deg, abs=1e-4)
