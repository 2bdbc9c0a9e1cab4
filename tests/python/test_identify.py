"""Plant identification (issue 7): the fit's model is the simulator's code, accuracy from 50 % guesses, bad data."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench import _core
from servobench.identify import IdentificationError, IdentificationLog, excitation

TS = 200e-6
RIGID_A = dict(inertia_kgm2=2e-4, viscous_nms=3e-4, coulomb_nm=0.03, static_nm=0.05, stribeck_speed_rad_s=2.0)
RIGID_B = dict(inertia_kgm2=5e-5, viscous_nms=1e-4, coulomb_nm=0.01, static_nm=0.018, stribeck_speed_rad_s=4.0)
TWO_MASS = dict(jm_kgm2=1e-4, jl_kgm2=2e-4, k_nm_per_rad=300.0, c_nms_per_rad=0.01, motor_viscous_nms=2e-4,
                motor_coulomb_nm=0.03)
OFF = [1.5, 0.5, 1.5, 1.5, 0.5, 0.5]  # every guess 50 % off, in alternating directions


def axis_with(plant, *, noise=0.0, seed=1, kp=38, kd=830):
    return sb.Axis(law=_core.GtServoLaw(kp=kp, kd=kd),
                   drive=_core.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500.0), plant=plant,
                   encoder=_core.Encoder(counts_per_rev=10000, noise_counts=noise, seed=seed), servo_period_s=TS)


def guesses(true):
    return {k: v * f for (k, v), f in zip(true.items(), OFF)}


def errors_pct(fit, true):
    return {k: 100 * (fit[k] / v - 1) for k, v in true.items()}


def test_fit_model_is_the_simulator():
    # The identification model, run on double, reproduces the simulator tick for tick (same matrices, same ZOH,
    # same dry-friction sub-step): stick-slip included, rigid and two-mass.
    for plant, model, p in [(_core.RigidPlant(**RIGID_A), "rigid", RIGID_A),
                            (_core.TwoMassPlant(load_viscous_nms=0.0, **TWO_MASS), "two_mass", TWO_MASS)]:
        ax = axis_with(plant, kp=20, kd=400)
        ax.set_servo_on(False)
        n = 5000
        volts = excitation("steps", n, amplitude=0.5, servo_period_s=TS, seed=3, step_samples=400)
        run = ax.run(np.zeros(n), injection_v=volts, signals=["volts", "angle_rad", "speed_rad_s"])
        torque = np.concatenate([[0.0], run.volts[:-1]]) * 0.4
        names = [q["name"] for q in sb.identify.model_parameters(model)]
        vec = np.array([p.get(k, 0.0) for k in names])
        if model == "rigid":
            vec[names.index("stribeck_speed_rad_s")] = p["stribeck_speed_rad_s"]
        else:
            vec[names.index("motor_stribeck_speed_rad_s")] = 0.01
        sim = _core.identify_simulate(torque, sample_period_s=TS, measured_is_speed=False, measured_on_load=False,
                                      model=model, parameters=vec, initial_state=np.zeros(2 if model == "rigid" else 4),
                                      substeps=1, current_bw_hz=1500.0, stribeck_exponent=2.0)
        assert np.any(np.abs(run.speed_rad_s) == 0.0) and np.any(np.abs(run.speed_rad_s) > 1.0)  # sticks and slides
        assert np.max(np.abs(sim - run.angle_rad)) <= 1e-9


@pytest.mark.parametrize("true", [RIGID_A, RIGID_B], ids=["rigid_a", "rigid_b"])
def test_rigid_within_2pct_from_50pct_guesses(true):
    # 5 s experiment, encoder quantisation only (10000 counts/rev): every parameter within 2 %.
    log = sb.run_experiment(axis_with(_core.RigidPlant(**true)), amplitude_v=0.1, seed=0)
    assert log.time_s[-1] == pytest.approx(5.0, abs=TS)
    fit = sb.fit_time(log, "rigid", guess=guesses(true))
    err = errors_pct(fit, true)
    assert fit.converged, fit.summary
    assert max(abs(e) for e in err.values()) < 2.0, err
    assert fit.residual_rms / log.count_rad < 0.35  # quantisation is 1/sqrt(12) = 0.29 count
    for k in true:  # the standard errors describe the errors
        e = fit.parameters[k]
        assert abs(e.value - true[k]) < 5 * e.std_error + 1e-6 * abs(true[k]), (k, e)


def test_a_best_start_at_the_resolution_floor_needs_no_twin_when_the_others_are_clearly_worse(monkeypatch):
    # RIGID_B with a PRBS held 4 ticks: the start from the guess ends at the quantisation floor (0.288 count RMS, the
    # truth within 0.01 %); two other starts that begin with the Stribeck peak flattened (static friction at the
    # Coulomb level, a 0.2 rad/s Stribeck speed) lose the peak and stop at 31-33 counts. J43 alone called this NOT
    # CONVERGED; J47: a point at the resolution floor with every other start >= 2x worse is the log's best and is
    # converged. (Until session 11 the seeded 1.5x perturbations of the guess did this by themselves; since the
    # continuation stages are warm-started (LK3) they reach the floor too, so the lost starts are made explicit.)
    perturbed = sb.oefit.perturbed_starts

    def peakless_others(guess, free, n_starts, seed=0, spread=1.5):
        starts = perturbed(guess, free, n_starts, seed, spread)
        return starts[:1] + [dict(g, static_nm=0.0101, stribeck_speed_rad_s=0.2) for g in starts[1:]]

    monkeypatch.setattr(sb.oefit, "perturbed_starts", peakless_others)
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_B)), amplitude_v=0.1, seed=0, hold_samples=4)
    fit = sb.fit_time(log, "rigid", guess=guesses(RIGID_B), strict=False)
    rms = sorted(s.residual_rms / log.measurement_count for s in fit.starts)
    assert rms[0] <= sb.identify.RESOLUTION_FLOOR_COUNTS and rms[1] >= 2 * rms[0]
    assert fit.converged, fit.summary
    assert "resolution floor" in fit.summary and "NOT CONVERGED" not in fit.summary
    assert max(abs(e) for e in errors_pct(fit, RIGID_B).values()) < 0.1
    assert not any("Joined start 1" in s.summary for s in fit.starts)  # the lost starts never reached start 1's point


@pytest.mark.parametrize("model", ["rigid", "two_mass"])
def test_later_starts_that_reach_the_first_starts_point_join_it_and_change_nothing(monkeypatch, model):
    # Decision FV15: a later start whose free parameters agree with the first start's within 1e-4 at the end of a
    # stage stops there and takes the first start's outcome. The answer is the one the starts give run to the end
    # (within 0.01 standard errors), and which starts join does not depend on start_threads.
    if model == "rigid":
        log, true = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, seed=0), RIGID_A
    else:
        log, true = two_mass_log(), TWO_MASS
    guess = guesses(true)
    fit = sb.fit_time(log, model, guess=guess, strict=False)
    joined = [s for s in fit.starts[1:] if "Joined start 1" in s.summary]
    assert joined and "joined start 1 at an intermediate stage" in fit.summary, fit.summary
    for s in joined:
        assert s.parameters == fit.starts[0].parameters and s.iterations < fit.starts[0].iterations + 30
    assert fit.converged and "NOT CONVERGED" not in fit.summary
    threaded = sb.fit_time(log, model, guess=guess, strict=False, start_threads=2)
    joins = lambda f: ["Joined start 1" in s.summary for s in f.starts]  # noqa: E731
    assert joins(threaded) == joins(fit)
    assert [s.parameters for s in threaded.starts] == [s.parameters for s in fit.starts]
    monkeypatch.setattr(sb.identify, "_JOIN_RTOL", 1e-300)  # no start joins: each runs every stage
    full = sb.fit_time(log, model, guess=guess, strict=False)
    assert not any("Joined start 1" in s.summary for s in full.starts)
    for k in true:
        e = full.parameters[k]
        assert abs(fit[k] - e.value) <= 0.01 * e.std_error, (k, fit[k], e)


def test_a_first_fit_in_a_fresh_process_does_not_import_scipy_stats():
    # Decision FV17: the p-values of the friction-asymmetry tests are erfc(sqrt(x / 2)) (idim._chi2_1_sf), SciPy's
    # chi-squared survival function with 1 degree of freedom: importing scipy.stats cost a process's first fit_time
    # 0.5 s of CPU time.
    from scipy import stats

    from servobench.idim import _chi2_1_sf
    x = np.concatenate(([0.0], np.logspace(-8, np.log10(3000.0), 400)))
    assert np.allclose([_chi2_1_sf(v) for v in x], stats.chi2.sf(x, 1), rtol=2e-13, atol=1e-300)
    import subprocess
    import sys
    import pathlib
    code = f"""
import sys
sys.path.insert(0, {str(pathlib.Path(__file__).resolve().parent)!r})
import servobench as sb
from servobench import _core
from test_identify import RIGID_A, axis_with, guesses
log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, duration_s=2.0, seed=0)
assert "scipy.stats" not in sys.modules, "imported before the fit"
fit = sb.fit_time(log, "rigid", guess=guesses(RIGID_A), strict=False)
assert 0.0 <= fit.asymmetry_p_value <= 1.0, fit.asymmetry_p_value
print("scipy.stats" in sys.modules)
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False", "fit_time imported scipy.stats"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_rigid_within_5pct_with_encoder_noise(seed):
    # The configured noise: 0.5 count rms on top of the quantisation, a different noise sequence per seed.
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A), noise=0.5, seed=seed + 1), amplitude_v=0.1,
                            seed=seed)
    fit = sb.fit_time(log, "rigid", guess=guesses(RIGID_A))
    err = errors_pct(fit, RIGID_A)
    assert max(abs(e) for e in err.values()) < 5.0, err


def two_mass_log(true=TWO_MASS, *, noise=0.0, seed=0):
    return sb.run_experiment(axis_with(_core.TwoMassPlant(load_viscous_nms=0.0, **true), kp=20, kd=400, noise=noise,
                                       seed=seed + 1), amplitude_v=0.3, seed=seed)


# "off_resonance" puts the guessed resonance sqrt(k (jm + jl) / (jm jl)) 35 % above the truth (jm x1.5, jl x0.5,
# k x1.5): started from the guess itself (start="guess") the fit ends in another local minimum; the default start
# reads the resonance off the log's spectrum first. All 64 sign patterns of +-50 % were checked the same way
# (docs/identify.md); three are tested here.
@pytest.mark.parametrize("pattern", [[1.5, 0.5, 1.5, 0.5, 1.5, 0.5], [0.5] * 6, [1.5, 0.5, 1.5, 1.5, 0.5, 0.5]],
                         ids=["alternating", "all_low", "off_resonance"])
def test_two_mass_within_2pct_from_50pct_guesses(pattern):
    log = two_mass_log()
    guess = {k: v * f for (k, v), f in zip(TWO_MASS.items(), pattern)}
    fit = sb.fit_time(log, "two_mass", guess=guess)
    err = errors_pct(fit, TWO_MASS)
    assert max(abs(e) for e in err.values()) < 2.0, err
    assert "from the log's spectrum" in fit.summary
    plant = fit.to_plant()  # usable for simulation
    assert isinstance(plant, _core.TwoMassPlant)
    assert plant.resonance_hz == pytest.approx(_core.TwoMassPlant(**TWO_MASS).resonance_hz, rel=0.01)
    sb.Axis(plant=plant).run(np.zeros(10))


def test_two_mass_soft_shaft_within_2pct():
    # A second two-mass plant: the shaft half as stiff (resonance 239 Hz), every guess 50 % off the other way.
    true = dict(TWO_MASS, k_nm_per_rad=150.0)
    fit = sb.fit_time(two_mass_log(true), "two_mass",
                      guess={k: v * f for (k, v), f in zip(true.items(), [0.5, 1.5, 0.5, 1.5, 0.5, 1.5])})
    err = errors_pct(fit, true)
    assert max(abs(e) for e in err.values()) < 2.0, err


@pytest.mark.parametrize("seed", [0, 1])
def test_two_mass_within_5pct_with_encoder_noise(seed):
    log = two_mass_log(noise=0.5, seed=seed)
    fit = sb.fit_time(log, "two_mass", guess=guesses(TWO_MASS))
    err = errors_pct(fit, TWO_MASS)
    assert max(abs(e) for e in err.values()) < 5.0, err


@pytest.mark.parametrize("k", [300.0, 150.0])
def test_resonance_guess_reads_the_mode_off_the_spectrum(k):
    true = dict(TWO_MASS, k_nm_per_rad=k)
    plant = _core.TwoMassPlant(load_viscous_nms=0.0, **true)
    rg = sb.identify.resonance_guess(two_mass_log(true))
    fa = math.sqrt(k / true["jl_kgm2"]) / (2 * math.pi)
    assert rg.anti_resonance_hz == pytest.approx(fa, rel=0.03)
    assert rg.resonance_hz == pytest.approx(plant.resonance_hz, rel=0.03)
    for name, value in rg.as_guess().items():
        assert value == pytest.approx(true[name], rel=0.1), name
    # A rigid body has no resonance to read: the spectrum is flat at its inertia, and the guess says so.
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.3, seed=0)
    sp = sb.identify.log_spectrum(log)
    band = (sp.freq_hz > 20) & (sp.freq_hz < 300) & (sp.coherence > 0.9)
    assert np.count_nonzero(band) > 20
    a = sp.apparent_inertia_kgm2[band]  # each bin a Welch average of 47 segments: a few % of scatter
    assert np.median(a) == pytest.approx(RIGID_A["inertia_kgm2"], rel=0.02)
    np.testing.assert_allclose(a, RIGID_A["inertia_kgm2"], rtol=0.10)
    with pytest.raises(IdentificationError, match="no two-mass resonance"):
        sb.identify.resonance_guess(log)


def test_shooting_residual_and_its_jacobian():
    # The residual handed to outside solvers (bench_identify.py) is the fit's: zero at the truth on a noise-free
    # log except for quantisation, and its automatic Jacobian agrees with central differences.
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, seed=0, duration_s=1.0)
    kw = dict(sample_period_s=TS, measured_is_speed=False, measured_on_load=False, model="rigid",
              current_bw_hz=1500.0, measurement_scale=log.count_rad, segment_samples=500)
    sp = _core.identify_shooting_problem(log.torque_nm, log.measured, **kw)
    p = np.array([2e-4, 3e-4, 0.03, 0.02, 2.0, 0.0])  # internal: the Stribeck excess 0.05 - 0.03
    x = sp["states"]
    r, (data, idx, ptr), shape = _core.identify_shooting_residual(
        log.torque_nm, log.measured, starts=sp["starts"], counts=sp["counts"], parameters=p, states=x,
        jacobian=True, **kw)
    assert shape == (len(r), len(p) + len(x)) and len(r) == sp["counts"].sum()
    jac = np.zeros(shape)
    for row in range(shape[0]):
        jac[row, idx[ptr[row]:ptr[row + 1]]] = data[ptr[row]:ptr[row + 1]]
    z = np.concatenate([p, x])
    for col in [0, 1, 2, 3, 4, 5, 6, 7]:
        h = 1e-6 * max(abs(z[col]), 1e-3)
        zp, zm = z.copy(), z.copy()
        zp[col] += h
        zm[col] -= h
        rp = _core.identify_shooting_residual(log.torque_nm, log.measured, starts=sp["starts"], counts=sp["counts"],
                                              parameters=zp[:6], states=zp[6:], **kw)
        rm = _core.identify_shooting_residual(log.torque_nm, log.measured, starts=sp["starts"], counts=sp["counts"],
                                              parameters=zm[:6], states=zm[6:], **kw)
        fd = (rp - rm) / (2 * h)
        assert np.max(np.abs(fd - jac[:, col])) <= 1e-4 * np.max(np.abs(jac[:, col])) + 1e-9, col


@pytest.mark.parametrize("model", ["rigid", "two_mass"])
def test_the_jacobian_by_forward_sensitivity_is_the_autodiff_one(model):
    # Decisions FU1 (rigid) and FV1 (two-mass): the segments' Jacobian in doubles (the default) is Ceres' automatic
    # differentiation of the same simulation (analytic_jacobian=False) to rounding, and central differences agree
    # with it; here at the truth and at a point with every parameter off and every third segment starting at rest.
    if model == "rigid":
        log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, seed=0, duration_s=1.0)
        truth = np.array([2e-4, 3e-4, 0.03, 0.02, 2.0, 0.0])  # internal: the Stribeck excess 0.05 - 0.03
        off = np.array([3e-4, 1e-4, 0.05, 0.01, 0.7, -0.004])
    else:
        log = sb.run_experiment(axis_with(_core.TwoMassPlant(load_viscous_nms=0.0, load_coulomb_nm=0.01,
                                                             **TWO_MASS), kp=20, kd=400),
                                amplitude_v=0.3, seed=0, duration_s=1.0)
        # jm, jl, k, c, motor viscous, load viscous, motor Coulomb, Stribeck excess, Stribeck speed, load Coulomb,
        # load
        truth = np.array([1e-4, 2e-4, 300.0, 0.01, 2e-4, 0.0, 0.03, 0.0, 1.0, 0.01, 0.0])
        off = np.array([1.5e-4, 1e-4, 450.0, 0.02, 1e-4, 5e-5, 0.04, 0.01, 0.7, 0.02, -0.004])
    kw = dict(sample_period_s=TS, measured_is_speed=False, measured_on_load=False, model=model,
              current_bw_hz=1500.0, measurement_scale=log.count_rad, segment_samples=500)
    sp = _core.identify_shooting_problem(log.torque_nm, log.measured, **kw)
    ns = 2 if model == "rigid" else 4
    stopped = sp["states"].copy()
    stopped[1::3 * ns] = 0.0
    if model == "two_mass":
        stopped[3::3 * ns] = 0.0  # the load body at rest too

    def residual(p, x, **extra):
        return _core.identify_shooting_residual(log.torque_nm, log.measured, starts=sp["starts"],
                                                counts=sp["counts"], parameters=p, states=x, **extra, **kw)

    for p, x in [(truth, sp["states"]), (off, stopped)]:
        got = []
        for analytic in (True, False):
            r, (data, idx, ptr), shape = residual(p, x, jacobian=True, analytic_jacobian=analytic)
            jac = np.zeros(shape)
            for row in range(shape[0]):
                jac[row, idx[ptr[row]:ptr[row + 1]]] = data[ptr[row]:ptr[row + 1]]
            got.append((r, jac))
        (ra, ja), (rb, jb) = got
        np.testing.assert_allclose(ra, rb, rtol=0, atol=1e-12 * max(1.0, np.max(np.abs(rb))))
        scale = np.max(np.abs(jb), axis=0)
        assert np.all(scale[:5] > 0)
        # Rounding: the two codes sum the same products in different orders, and a two-mass segment carries a
        # lightly damped resonance over hundreds of samples (up to 1.3e-11 measured without friction, see
        # test_segment_sensitivity.cpp); a wrong term shows at 1e-6 or more, and the central differences below check
        # the Jacobian independently.
        assert np.max(np.abs(ja - jb) / np.where(scale > 0, scale, 1.0)) <= (1e-12 if model == "rigid" else 1e-10)
    # Central differences at the truth, every parameter and the first segment's state.
    z = np.concatenate([truth, sp["states"]])
    np_ = len(truth)
    _, (data, idx, ptr), shape = residual(truth, sp["states"], jacobian=True)
    jac = np.zeros(shape)
    for row in range(shape[0]):
        jac[row, idx[ptr[row]:ptr[row + 1]]] = data[ptr[row]:ptr[row + 1]]
    for col in range(np_ + ns):
        if model == "two_mass" and col in (7, 8):
            continue  # no Stribeck peak at the truth: its speed has no derivative, its excess a one-sided one
        h = 1e-6 * max(abs(z[col]), 1e-3)
        zp, zm = z.copy(), z.copy()
        zp[col] += h
        zm[col] -= h
        fd = (residual(zp[:np_], zp[np_:]) - residual(zm[:np_], zm[np_:])) / (2 * h)
        assert np.max(np.abs(fd - jac[:, col])) <= 1e-4 * np.max(np.abs(jac[:, col])) + 1e-9, col


def test_the_fit_differentiates_along_its_free_parameters_only():
    # Decision FT5: the fit's segments carry Jet directions for the free parameters only (here 3 of 6 and the 2
    # state entries: Jets of 6 instead of 8). Its white-noise standard errors, from that Jacobian, are those of the
    # full Jacobian (every parameter differentiated, checked against central differences above) at the same point.
    from servobench import oefit
    from servobench.identify import _fit_once

    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, seed=0, duration_s=1.0)
    guess = dict(RIGID_A, inertia_kgm2=3e-4, viscous_nms=2e-4)
    fit = _fit_once(log, "rigid", guess=guess, fixed=("static_nm", "stribeck_speed_rad_s"),
                                segment_samples=500, initial_segment_samples=500, strict=False)
    kw = oefit.shooting_options(log, 500, {})
    sp = _core.identify_shooting_problem(log.torque_nm, log.measured, model="rigid", **kw)
    names = [q["name"] for q in _core.identify_parameters("rigid")]
    p = np.array([fit.values()[n] for n in names])
    p[3] -= p[2]  # internal: the Stribeck excess
    x = np.asarray(fit.segment_states, float).ravel()
    assert x.size == sp["states"].size
    r, (data, idx, ptr), shape = _core.identify_shooting_residual(
        log.torque_nm, log.measured, model="rigid", starts=sp["starts"], counts=sp["counts"], parameters=p, states=x,
        jacobian=True, **kw)
    jac = np.zeros(shape)
    for row in range(shape[0]):
        jac[row, idx[ptr[row]:ptr[row + 1]]] = data[ptr[row]:ptr[row + 1]]
    free = [0, 1, 2]
    j = jac[:, free + list(range(len(p), shape[1]))]
    s2 = float(r @ r) / (j.shape[0] - j.shape[1])
    se = np.sqrt(np.diag(s2 * np.linalg.inv(j.T @ j))[:len(free)])
    got = [fit.parameters[names[i]].std_error for i in free]
    np.testing.assert_allclose(got, se, rtol=1e-6)
    assert fit.parameters["stribeck_speed_rad_s"].std_error == 0.0  # held (static_nm's bar is Fc's: Fs = Fc + e)


def test_fit_is_deterministic_on_one_thread():
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, seed=0, duration_s=2.0)
    a = sb.fit_time(log, "rigid", guess=guesses(RIGID_A), strict=False)
    b = sb.fit_time(log, "rigid", guess=guesses(RIGID_A), strict=False)
    assert a.values() == b.values() and a.iterations == b.iterations


def test_frequency_fit_of_a_two_mass_response():
    ax = axis_with(_core.TwoMassPlant(load_viscous_nms=0.0, **TWO_MASS), kp=20, kd=400)
    f = np.geomspace(5, 2000, 120)
    measured = sb.analytic_response(ax, f)
    lin = {k: v for k, v in TWO_MASS.items() if k != "motor_coulomb_nm"}
    fit = sb.fit_frequency(measured, ax, "two_mass", guess=guesses(lin))
    err = errors_pct(fit, lin)
    assert max(abs(e) for e in err.values()) < 0.1, err
    assert fit.nrmse < 1e-6


def test_frequency_fit_with_delay():
    ax = axis_with(_core.RigidPlant(**RIGID_A))
    f = np.geomspace(5, 1000, 80)
    g = sb.analytic_response(ax, f).response("plant") * np.exp(-2j * np.pi * f * 150e-6)  # an unmodelled lag
    fit = sb.fit_frequency((f, g), ax, "rigid", guess={"inertia_kgm2": 1e-4, "viscous_nms": 6e-4}, fit_delay=True,
                           delay_s=50e-6)
    assert fit["delay_s"] == pytest.approx(150e-6, rel=1e-4)
    assert fit["inertia_kgm2"] == pytest.approx(2e-4, rel=1e-4)


def test_to_plant_and_csv_round_trip(tmp_path):
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, duration_s=1.0)
    path = tmp_path / "log.csv"
    log.to_csv(str(path))
    back = IdentificationLog.from_csv(str(path), current_bw_hz=1500.0)
    assert back.sample_period_s == pytest.approx(TS, rel=1e-9)
    np.testing.assert_allclose(back.measured, log.measured, rtol=0, atol=1e-15)
    np.testing.assert_allclose(back.torque_nm, log.torque_nm, rtol=0, atol=1e-15)


def test_log_from_dac_volts():
    # A trace of the DAC voltage (what a card records) instead of the torque: converted with the drive's A/V x kt.
    log = sb.run_experiment(axis_with(_core.RigidPlant(**RIGID_A)), amplitude_v=0.1, duration_s=0.5)
    tpv = log.extra["torque_per_volt"]
    assert tpv == pytest.approx(0.4)
    v = IdentificationLog.from_arrays(log.time_s, log.torque_nm / tpv, log.measured, command_unit="V",
                                      torque_per_volt=tpv, current_bw_hz=1500.0)
    np.testing.assert_allclose(v.torque_nm, log.torque_nm, rtol=1e-15, atol=0)
    with pytest.raises(ValueError, match="torque_per_volt = None must be > 0"):
        IdentificationLog.from_arrays(log.time_s, log.torque_nm, log.measured, command_unit="V")
    with pytest.raises(ValueError, match="command_unit = 'A'"):
        IdentificationLog.from_arrays(log.time_s, log.torque_nm, log.measured, command_unit="A")


def test_measurement_count_is_one_count_in_the_logs_unit():
    # One place says how big a count is in the unit of `measured` (the fits' residuals are reported in counts).
    t = np.arange(100) * 1e-3
    pos = IdentificationLog.from_arrays(t, np.zeros(100), np.zeros(100), counts_per_rev=10000)
    assert pos.measurement_count == pytest.approx(2 * np.pi / 10000, rel=1e-15)
    spd = IdentificationLog.from_arrays(t, np.zeros(100), np.zeros(100), counts_per_rev=10000, measured_unit="rad/s")
    assert spd.measurement_count == pytest.approx(2 * np.pi / 10000 / 1e-3, rel=1e-15)


def test_bad_logs_are_refused():
    n = 1000
    t = np.arange(n) * TS
    with pytest.raises(ValueError, match="same length"):
        IdentificationLog.from_arrays(t, np.zeros(n - 1), np.zeros(n))
    t_bad = t.copy()
    t_bad[500] = t_bad[499]
    with pytest.raises(ValueError, match="not increasing"):
        IdentificationLog.from_arrays(t_bad, np.zeros(n), np.zeros(n))
    y = np.zeros(n)
    y[10] = np.nan
    with pytest.raises(ValueError, match=r"measured\[10\] = nan is not a finite number"):
        IdentificationLog.from_arrays(t, np.zeros(n), y)
    t_uneven = t.copy()
    t_uneven[700:] += 1e-5
    with pytest.raises(ValueError, match="not uniformly sampled"):
        IdentificationLog.from_arrays(t_uneven, np.zeros(n), np.zeros(n))
    short = IdentificationLog(TS, np.zeros(30), np.zeros(30))
    with pytest.raises(ValueError, match="too short"):
        sb.fit_time(short, "rigid", guess={"inertia_kgm2": 1e-4})
    still = IdentificationLog(TS, np.zeros(5000), np.zeros(5000))
    with pytest.raises(ValueError, match="hardly moves"):
        sb.fit_time(still, "rigid", guess={"inertia_kgm2": 1e-4})
    with pytest.raises(ValueError, match="unknown parameter"):
        sb.fit_time(still, "rigid", guess={"inertia": 1e-4})
    with pytest.raises(ValueError, match="model = 'three_mass'"):
        sb.fit_time(still, "three_mass", guess={"inertia_kgm2": 1e-4})


def test_weak_excitation_names_the_parameters():
    # One-way motion at a nearly constant speed: a constant load torque and the Coulomb friction act alike.
    ax = axis_with(_core.RigidPlant(**RIGID_A))
    n = int(1.0 / TS)
    ref = np.cumsum(np.full(n, 20.0)) * TS * 10000 / (2 * np.pi)
    run = ax.run(ref, injection_v=excitation("prbs", n, amplitude=0.1, servo_period_s=TS), signals=["volts", "fb_pos"])
    torque = np.concatenate([[0.0], run.volts[:-1]]) * 0.4
    log = IdentificationLog(TS, torque, run.fb_pos * 2 * np.pi / 10000, current_bw_hz=1500.0)
    g = {"inertia_kgm2": 1e-4, "viscous_nms": 1e-4, "coulomb_nm": 0.02, "load_nm": 0.01}
    with pytest.raises(IdentificationError, match="coulomb_nm.*load_nm|load_nm.*coulomb_nm"):
        sb.fit_time(log, "rigid", guess=g)
    fit = sb.fit_time(log, "rigid", guess=g, strict=False)
    assert any("coulomb_nm" in s for s in fit.not_identifiable)


def test_excitations_are_seeded():
    for kind in ("prbs", "multisine", "chirp", "steps"):
        a = excitation(kind, 4000, amplitude=0.2, servo_period_s=TS, seed=7, start_hz=5.0, end_hz=500.0)
        b = excitation(kind, 4000, amplitude=0.2, servo_period_s=TS, seed=7, start_hz=5.0, end_hz=500.0)
        assert np.array_equal(a, b)
        assert np.max(np.abs(a)) == pytest.approx(0.2, rel=0.05)
    assert not np.array_equal(excitation("prbs", 4000, seed=1), excitation("prbs", 4000, seed=2))
    with pytest.raises(ValueError, match="kind = 'noise'"):
        excitation("noise", 10)
    with pytest.raises(ValueError, match="identification needs a torque-mode drive"):
        sb.run_experiment(sb.Axis(drive=_core.VelocityDrive()))
