"""sb.LtiPlant (issue 23.3): any linear plant in the loop, from python-control or (A, B, C, D) arrays; exact ZOH
inside the tick, friction at the motor, every analysis; the relay on 1/(s+1)^3 and a three-mass model against
python-control."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

control = pytest.importorskip("control")

import servobench as sb  # noqa: E402
from servobench import frequency as fr  # noqa: E402

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830)  # the demo axis's gains (GT units, per 200 us tick)
UNIT_DRIVE = dict(amps_per_volt=1.0, kt=1.0, current_limit_a=float("inf"), current_bw_hz=float("inf"))


def three_mass(j=(2e-5, 3e-5, 4e-5), k=(300.0, 200.0), c=(0.002, 0.001), b=(1e-5, 0.0, 2e-5)):
    """Three inertias on two shafts, x = [th1, w1, th2, w2, th3, w3] (rad, rad/s), torque on body 1 (N*m)."""
    a = np.zeros((6, 6))
    for i in range(3):
        a[2 * i, 2 * i + 1] = 1.0
    springs = [(0, 1, k[0], c[0]), (1, 2, k[1], c[1])]
    for i in range(3):
        a[2 * i + 1, 2 * i + 1] -= b[i] / j[i]
    for p, q, kk, cc in springs:
        for me, other, s in ((p, q, 1), (q, p, 1)):
            a[2 * me + 1, 2 * me] -= kk / j[me]
            a[2 * me + 1, 2 * other] += kk / j[me]
            a[2 * me + 1, 2 * me + 1] -= cc / j[me]
            a[2 * me + 1, 2 * other + 1] += cc / j[me]
    bm = np.zeros((6, 1))
    bm[1, 0] = 1 / j[0]
    cm = np.zeros((1, 6))
    cm[0, 0] = 1.0
    return control.ss(a, bm, cm, 0)


# -- construction and validation ---------------------------------------------------------------------------------
def test_from_transfer_function_and_arrays_agree():
    g = control.tf([1], [1, 3, 3, 1])
    p = sb.LtiPlant.from_control(g)
    assert p.states == 3 and p.stability == "stable" and p.d == 0
    ss = control.ss(g)
    q = sb.LtiPlant(a=ss.A, b=ss.B, c=ss.C)
    assert q == p
    f = np.array([0.1, 0.3, 1.0])
    want = g(2j * np.pi * f)
    np.testing.assert_allclose(p.frequency_response(f), want, rtol=1e-12)
    assert pickle.loads(pickle.dumps(p)) == p
    r = p.replace(coulomb_nm=0.0, load_nm=0.5)
    assert r.load_nm == 0.5 and r != p
    assert set(p.to_dict()) == set(sb.LtiPlant.FIELDS)
    assert "LtiPlant(states=3, stable" in repr(p)


@pytest.mark.parametrize("sys, word", [
    (control.tf([1], [1, 1]), "relative degree"),             # angle would jump with torque
    (control.tf([1, 0, 0], [1, 2, 1]), "relative degree"),    # improper-ish: degree 0
    (control.tf([1], [1, 1], 0.001), "dt"),                  # discrete
    (control.ss(np.diag(-np.arange(1.0, 9.0)), np.ones((8, 1)), np.eye(8)[:1], 0), "states"),
])
def test_rejects_with_the_reason(sys, word):
    with pytest.raises(ValueError, match=word):
        sb.LtiPlant.from_control(sys)


def test_array_validation_names_the_parameter():
    a = [[0.0, 1.0], [0.0, -1.0]]
    with pytest.raises(ValueError, match="LtiPlant.d"):
        sb.LtiPlant(a=a, b=[0.0, 1.0], c=[1.0, 0.0], d=0.1)
    with pytest.raises(ValueError, match="LtiPlant.a"):
        sb.LtiPlant(a=[[0.0, np.nan], [0.0, -1.0]], b=[0.0, 1.0], c=[1.0, 0.0])
    with pytest.raises(ValueError, match="LtiPlant.b"):
        sb.LtiPlant(a=a, b=[0.0, 1.0, 2.0], c=[1.0, 0.0])
    with pytest.raises(ValueError, match="LtiPlant.c @ b"):
        sb.LtiPlant(a=a, b=[1.0, 1.0], c=[1.0, 0.0])
    with pytest.raises(ValueError, match="stribeck_exponent"):
        sb.LtiPlant(a=a, b=[0.0, 1.0], c=[1.0, 0.0], coulomb_nm=0.1, stribeck_exponent=9)
    # dry friction needs a finite inertia 1/(c a b): not on a relative-degree-3 plant
    with pytest.raises(ValueError, match="coulomb_nm"):
        sb.LtiPlant.from_control(control.tf([1], [1, 3, 3, 1]), coulomb_nm=0.01)
    with pytest.raises(TypeError, match="unknown parameter"):
        sb.LtiPlant(a=a, b=[0.0, 1.0], c=[1.0, 0.0]).replace(inertia=1)
    with pytest.raises(ValueError, match="inputs"):
        sb.LtiPlant.from_control(control.ss(-np.eye(2), np.eye(2), np.eye(2), np.zeros((2, 2))))


def test_stability_is_reported_not_refused():
    assert sb.LtiPlant.from_control(control.tf([1], [1e-4, 1e-4, 0])).stability.startswith("marginal (1")
    unstable = sb.LtiPlant.from_control(control.tf([1], [1, 1, -2]))  # poles 1, -2
    assert unstable.stability == "unstable (1 poles in Re s > 0)"
    assert sb.Axis(plant=unstable).plant == unstable  # accepted into an axis


# -- the same as the built-in plants ------------------------------------------------------------------------------
def _run_pair(p1, p2, **axis_kw):
    move = sb.trapezoid_move(distance_pulse=4000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.1, dwell_after=800)
    enc = sb.Encoder(counts_per_rev=10000, quantize=False)
    runs = []
    for p in (p1, p2):
        ax = sb.Axis(law=LAW, plant=p, encoder=enc, **axis_kw)
        runs.append(ax.run(move))
    return runs


def test_rigid_plant_as_lti_runs_identically_with_friction():
    rig = sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, coulomb_nm=0.02, static_nm=0.03, load_nm=0.01)
    a, b, c, _ = sb._core.plant_linear(rig)
    lti = sb.LtiPlant(a=a, b=b, c=c, coulomb_nm=0.02, static_nm=0.03, load_nm=0.01)
    assert lti.inertia_kgm2 == pytest.approx(1e-4, rel=1e-12)
    r1, r2 = _run_pair(rig, lti, substeps=4)
    np.testing.assert_allclose(r2.angle_rad, r1.angle_rad, rtol=0, atol=1e-12)
    np.testing.assert_allclose(r2.speed_rad_s, r1.speed_rad_s, rtol=0, atol=1e-9)
    assert np.ptp(r1.error) > 1  # it moved; friction held it somewhere
    # friction acts: without it the run differs
    r3 = sb.Axis(law=LAW, plant=lti.replace(coulomb_nm=0.0, static_nm=0.0, load_nm=0.0),
                 encoder=sb.Encoder(counts_per_rev=10000, quantize=False), substeps=4).run(
        sb.trapezoid_move(distance_pulse=4000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.1, dwell_after=800))
    assert np.max(np.abs(r3.angle_rad - r1.angle_rad)) > 1e-4


def test_two_mass_as_lti_same_run_and_analysis():
    tm = sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01)
    lti = sb.LtiPlant.from_control(tm.to_control())
    r1, r2 = _run_pair(tm, lti, drive=sb.TorqueDrive(current_bw_hz=1500))
    scale = np.max(np.abs(r1.angle_rad))
    np.testing.assert_allclose(r2.angle_rad, r1.angle_rad, rtol=0, atol=1e-9 * scale)
    f = np.geomspace(5, 2000, 60)
    a1, a2 = sb.Axis(law=LAW, plant=tm), sb.Axis(law=LAW, plant=lti)
    m1, m2 = fr.analytic_response(a1, f), fr.analytic_response(a2, f)
    np.testing.assert_allclose(m2.open_loop, m1.open_loop, rtol=1e-8)
    g1, g2 = sb.frequency.analytic_margins(a1), sb.frequency.analytic_margins(a2)
    assert g2.stable == g1.stable
    assert g2.phase_margin_deg == pytest.approx(g1.phase_margin_deg, abs=1e-6)


def test_linear_axis_with_lead_is_a_rigid_body():
    mass, visc, lead = 2.0, 5.0, 0.01  # kg, N*s/m, m/rev
    p = sb.LtiPlant.from_control(control.tf([1], [mass, visc, 0]), lead_m_per_rev=lead)
    k = lead / (2 * np.pi)
    rig = sb.RigidPlant(inertia_kgm2=mass * k ** 2, viscous_nms=visc * k ** 2)
    f = np.array([1.0, 10.0, 100.0])
    np.testing.assert_allclose(p.frequency_response(f), rig.frequency_response(f), rtol=1e-10)
    assert p.inertia_kgm2 == pytest.approx(mass * k ** 2, rel=1e-12)


# -- rest states ---------------------------------------------------------------------------------------------------
def test_reset_puts_every_body_at_rest():
    ax = sb.Axis(plant=sb.LtiPlant.from_control(three_mass()), drive=sb.TorqueDrive(**UNIT_DRIVE),
                 encoder=sb.Encoder(quantize=False))
    ax.reset(1.25)
    ax.set_servo_on(False)
    run = ax.run(np.zeros(2000) + ax.feedback_pulse, error_limit_pulse=None)
    # at rest to rounding (the rest direction and the discretisation agree to ~1e-16 of |A| = 1.5e7 1/s^2 per tick);
    # the motor alone at 1.25 rad would twist both shafts by 1.25 rad and ring
    np.testing.assert_allclose(run.angle_rad, 1.25, rtol=0, atol=1e-9)
    np.testing.assert_allclose(run.load_angle_rad, 1.25, rtol=0, atol=1e-9)
    no_integrator = sb.Axis(plant=sb.LtiPlant.from_control(control.tf([1], [1, 3, 3, 1])))
    with pytest.raises(ValueError, match="no rest state"):
        no_integrator.reset(1.0)


# -- against python-control ----------------------------------------------------------------------------------------
def test_three_mass_matches_python_control_forced_response():
    """Plant alone: the torque the drive applied, tick by tick, through python-control's own ZOH discretisation
    (control.sample_system) and forced_response, against the simulated motor angle: 1e-9 of the motion."""
    g = three_mass()
    ts = 200e-6
    ax = sb.Axis(plant=sb.LtiPlant.from_control(g), drive=sb.TorqueDrive(**UNIT_DRIVE),
                 encoder=sb.Encoder(quantize=False), servo_period_s=ts, substeps=3)
    ax.set_servo_on(False)
    n = 3000
    rng = np.random.default_rng(4)
    lsb = 10.0 / 32767.0
    inj = np.round(rng.normal(0, 0.5, n) / lsb) * lsb  # exact DAC levels (V)
    run = ax.run(np.zeros(n), injection_v=inj, error_limit_pulse=None)
    u = run.torque_nm
    assert np.ptp(u) > 0.5
    gd = control.sample_system(g, ts, method="zoh")
    y = control.forced_response(gd, U=u).outputs
    # the angle recorded at tick k was read before that tick's torque acted: y[k] = C x[k], x[k+1] = Phi x[k] + G u[k]
    scale = np.max(np.abs(y))
    assert scale > 1e-3
    np.testing.assert_allclose(run.angle_rad, y, rtol=0, atol=1e-9 * scale)


def test_three_mass_closed_loop_matches_python_control():
    """The closed position loop, exported with to_control(axis) (discrete, one-tick delay) and stepped with
    control.forced_response, against the simulator. The only nonlinearity left is the DAC (24 bits here; the step
    keeps the law inside +-10 V): its rounding, at most half a step per tick, reaches the encoder through P/(1 + L)
    with impulse response h, so the two agree within (LSB/2) sum|h| for sure, and within 6 LSB/sqrt(12) ||h||_2 for
    independent roundings (6 sigma)."""
    g = three_mass(c=(0.01, 0.01))
    ax = sb.Axis(law=sb.GtServoLaw(kp=10, kd=300, ki=0, ilmt=0), plant=sb.LtiPlant.from_control(g),
                 drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=float("inf"), current_bw_hz=2000),
                 encoder=sb.Encoder(quantize=False, counts_per_rev=10000), dac=sb.Dac(bits=24))
    assert sb.frequency.analytic_margins(ax).stable
    t = ax.to_control(which="closed_loop", form="ss")
    assert t.dt == ax.servo_period_s
    n = 3000
    r = np.r_[np.zeros(10), np.full(n - 10, 50.0)]
    y = control.forced_response(t, U=r).outputs
    run = ax.run(r, error_limit_pulse=None)
    assert np.max(np.abs(run.u)) < 32767  # linear: no clamp
    lsb = 10.0 / (2 ** 23 - 1)
    p_volt = ax.to_control(which="plant", form="ss") * (32767.0 / 10.0)  # pulse per volt at the DAC input, one-tick delay
    fc = ax.to_control(which="filters", form="ss") * ax.to_control(which="controller", form="ss") * (10.0 / 32767.0)
    h = control.impulse_response(control.feedback(p_volt, fc), T=np.arange(n) * ax.servo_period_s).outputs
    err = np.max(np.abs(run.fb_pos - y))
    assert err <= lsb / 2 * np.sum(np.abs(h)) + 1e-9 * 50, err
    assert err <= 6 * lsb / np.sqrt(12) * np.sqrt(np.sum(h ** 2)) + 1e-9 * 50, err


# -- every analysis ------------------------------------------------------------------------------------------------
def _rigid_lti_axis():
    p = sb.LtiPlant.from_control(control.tf([1], [1e-4, 1e-4, 0]))  # J = 1e-4 kg*m^2, b = 1e-4 N*m*s/rad
    return sb.Axis(law=sb.GtServoLaw(kp=38, ki=60, kd=830), plant=p,
                   drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=8, current_bw_hz=1500))


def test_sweep_margins_and_identification_by_frequency():
    ax = _rigid_lti_axis()
    m = fr.analytic_margins(ax)
    assert m.stable and 20 < m.phase_margin_deg < 80
    meas = fr.sine_sweep(ax, start_hz=20, end_hz=400, points=8, update_s=0.05)
    model = fr.analytic_response(ax, meas.freq_hz)
    ok = meas.usable
    assert ok.sum() >= 6
    np.testing.assert_allclose(np.abs(meas.plant[ok]), np.abs(model.plant[ok]), rtol=0.05)
    fit = sb.fit_frequency(meas, ax, "rigid", guess={"inertia_kgm2": 3e-4, "viscous_nms": 1e-4},
                           fixed=["viscous_nms"])  # 20-400 Hz sees the inertia, not the viscous friction
    assert fit.parameters["inertia_kgm2"].value == pytest.approx(1e-4, rel=0.05)


def test_relay_on_textbook_third_order_plant():
    """1/(s+1)^3: the textbook relay experiment gives wu = sqrt(3) rad/s, Ku = 8 (N*m/rad). The describing function
    is exact for the fundamental; the error comes from the harmonics moving the switching instants. To first order
    (docs/lti-plant.md): |d phase| <= asin(eps) + w (tr + 1.5 Ts) + asin(h / a), eps = sum over odd k >= 3 of
    |G(jkw)| / (k |G(jw)|); |d w| <= |d phase| / |d arg G/d w|; |d Ku / Ku| <= |d ln|G| / d w| |d w|."""
    g = control.tf([1], [1, 3, 3, 1])
    cpr = 2 ** 20
    ax = sb.Axis(plant=sb.LtiPlant.from_control(g), drive=sb.TorqueDrive(**UNIT_DRIVE),
                 encoder=sb.Encoder(counts_per_rev=cpr))
    res = sb.relay_autotune(ax, amplitude_v=1.0, hysteresis_pulse=1.0, data_length=4, settle_cycles=2,
                            deviation_limit_pulse=0, max_cycle_s=10.0)
    pulse_per_rad = cpr / (2 * np.pi)
    wu = 2 * np.pi * res.ultimate_freq_hz
    ku = res.ultimate_gain_v_per_pulse * pulse_per_rad / (UNIT_DRIVE["amps_per_volt"] * UNIT_DRIVE["kt"])
    w0 = np.sqrt(3.0)
    G = lambda w: g(1j * w)  # noqa: E731
    eps = sum(abs(G(k * w0)) / (k * abs(G(w0))) for k in range(3, 400, 2))
    a_rad = 4 / np.pi * abs(G(w0))
    dphi = np.arcsin(eps) + w0 * (max(500e-6, ax.servo_period_s) + 1.5 * ax.servo_period_s) + \
        np.arcsin(1.0 / (a_rad * pulse_per_rad))
    dw = dphi / (3 / (1 + w0 ** 2))           # |d arg G / dw| = 3 / (1 + w^2)
    dku = (3 * w0 / (1 + w0 ** 2)) * dw         # |d ln|G| / dw| = 3 w / (1 + w^2)
    assert 0.015 < eps < 0.03 and dw < 0.035 and dku < 0.05  # the bound the docs state: 2.2 % and 4.2 %
    assert abs(wu - w0) <= dw, (wu, w0, dw)
    assert abs(ku - 8.0) / 8.0 <= dku, (ku, dku)


def test_free_drive_trains_are_marginal_not_unstable():
    """A double pole at s = 0 (no viscous friction) comes out of the eigenvalue solver split by ~sqrt(eps |A|)."""
    j1, j2, k, c = 2e-5, 6e-5, 400.0, 0.005
    a = [[0, 1, 0, 0], [-k / j1, -c / j1, k / j1, c / j1], [0, 0, 0, 1], [k / j2, c / j2, -k / j2, -c / j2]]
    assert sb.LtiPlant(a=a, b=[0, 1 / j1, 0, 0], c=[1, 0, 0, 0]).stability == \
        "marginal (2 poles on the imaginary axis)"
    assert sb.LtiPlant.from_control(three_mass(b=(0.0, 0.0, 0.0))).stability.startswith("marginal (2")
