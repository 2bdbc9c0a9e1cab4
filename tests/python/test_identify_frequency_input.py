"""fit_frequency reads a python-control FRD in rad/s and a Bode CSV in Hz/dB/deg with their units (issue 19.8):
the same response given three ways gives the same fit."""

from __future__ import annotations

import control
import numpy as np
import pandas as pd
import pytest

import servobench as sb
from servobench import _core

TS = 200e-6
RIGID = dict(inertia_kgm2=2e-4, viscous_nms=3e-4)


def _axis(plant):
    return sb.Axis(law=sb.GtServoLaw(kp=38, kd=830), plant=plant,
                   drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500.0),
                   encoder=sb.Encoder(counts_per_rev=10000), servo_period_s=TS)


def test_frd_and_bode_csv_are_read_in_their_units(tmp_path):
    ax = _axis(_core.RigidPlant(**RIGID))
    f = np.geomspace(5, 1000, 60)
    g = sb.analytic_response(ax, f).response("plant")
    guess = {"inertia_kgm2": 1e-4, "viscous_nms": 6e-4}
    ref = sb.fit_frequency((f, g), ax, "rigid", guess=guess)
    frd = control.FRD(g, 2 * np.pi * f)                       # python-control: rad/s
    by_frd = sb.fit_frequency(frd, ax, "rigid", guess=guess)
    path = tmp_path / "bode.csv"
    pd.DataFrame({"f [Hz]": f, "gain [dB]": 20 * np.log10(np.abs(g)),
                  "phase [deg]": np.degrees(np.angle(g))}).to_csv(path, index=False)
    by_csv = sb.fit_frequency(str(path), ax, "rigid", guess=guess)
    for fit in (ref, by_frd, by_csv):
        assert fit["inertia_kgm2"] == pytest.approx(RIGID["inertia_kgm2"], rel=1e-4)
        assert fit["viscous_nms"] == pytest.approx(RIGID["viscous_nms"], rel=0.02)   # within 2 % on exact data
    f2, g2, _ = sb.identify.frequency_input(frd)
    np.testing.assert_allclose(f2, f, rtol=1e-12)
    bad = tmp_path / "bad.csv"
    pd.DataFrame({"f [kHz]": f, "gain [dB]": f, "phase [deg]": f}).to_csv(bad, index=False)
    with pytest.raises(ValueError, match=r"column 'f': unit 'kHz' is not a Bode unit"):
        sb.fit_frequency(str(bad), ax, "rigid", guess=guess)
    none = tmp_path / "none.csv"
    pd.DataFrame({"f [Hz]": f, "gain [dB]": f}).to_csv(none, index=False)
    with pytest.raises(ValueError, match="no phase column"):
        sb.fit_frequency(str(none), ax, "rigid", guess=guess)


TWO_MASS = dict(jm_kgm2=1e-4, jl_kgm2=2e-4, k_nm_per_rad=300.0, c_nms_per_rad=0.01, motor_viscous_nms=2e-4)


def _two_mass_ss(p, *, speed=True):
    """Torque (N*m) -> motor speed (rad/s) or angle (rad) of a two-mass drive train, written out independently."""
    jm, jl, k, c, bm = (p[n] for n in ("jm_kgm2", "jl_kgm2", "k_nm_per_rad", "c_nms_per_rad", "motor_viscous_nms"))
    a = np.array([[0, 1, 0, 0], [-k / jm, -(c + bm) / jm, k / jm, c / jm], [0, 0, 0, 1], [k / jl, c / jl, -k / jl, -c / jl]])
    b = np.array([[0], [1 / jm], [0], [0]])
    return control.ss(a, b, [[0, 1, 0, 0]] if speed else [[1, 0, 0, 0]], [[0]])


def test_axis_free_fit_of_an_frd_of_the_mechanics(tmp_path):
    # What a drive's analyser gives: torque -> motor speed, continuous time, in rad/s, as a python-control FRD.
    omega = 2 * np.pi * np.geomspace(5, 2000, 150)
    frd = control.frd(_two_mass_ss(TWO_MASS), omega)
    guess = {k: v * f for (k, v), f in zip(TWO_MASS.items(), [1.3, 0.7, 1.3, 1.5, 0.6])}
    fit = sb.fit_frequency(frd, model="two_mass", io=sb.MechanicsIO(speed_output=True), guess=guess)
    for k, v in TWO_MASS.items():
        assert fit[k] == pytest.approx(v, rel=0.02 if k == "motor_viscous_nms" else 1e-4), k
    assert fit.converged and fit.nrmse < 1e-6
    # A Bode CSV of torque [N*m] -> angle in encoder counts (10000/rev), sampled at 200 us with one sample of delay:
    # the same mechanics, described by MechanicsIO.
    f = np.geomspace(5, 2000, 120)
    io = sb.MechanicsIO(sample_period_s=TS, delay_samples=1, counts_per_rev=10000)
    g = _core_response(io, f)
    path = tmp_path / "bode.csv"
    pd.DataFrame({"f [Hz]": f, "gain [dB]": 20 * np.log10(np.abs(g)), "phase [deg]": np.degrees(np.angle(g))}).to_csv(
        path, index=False)
    fit = sb.fit_frequency(str(path), model="two_mass", io=io, guess=guess)
    for k, v in TWO_MASS.items():
        assert fit[k] == pytest.approx(v, rel=0.02 if k == "motor_viscous_nms" else 1e-3), k


def _core_response(io, f):
    # The sampled response of the independent model: exact ZOH (scipy), z^-1 delay, counts per rad.
    d = control.c2d(_two_mass_ss(TWO_MASS, speed=False), TS, "zoh")
    return control.frequency_response(d, 2 * np.pi * f).complex.ravel() / np.exp(2j * np.pi * f * TS) * 10000 / (
        2 * np.pi)


def test_axis_free_equals_the_axis_fit():
    # MechanicsIO.of_axis describes a servobench axis's plant response (U counts -> Y pulse) without the axis: the
    # two fits are the same fit.
    ax = _axis(_core.TwoMassPlant(load_viscous_nms=0.0, **TWO_MASS))
    f = np.geomspace(5, 2000, 100)
    meas = sb.analytic_response(ax, f)
    guess = {k: v * f_ for (k, v), f_ in zip(TWO_MASS.items(), [1.3, 0.7, 1.3, 1.5, 0.6])}
    a = sb.fit_frequency(meas, ax, "two_mass", guess=guess)
    b = sb.fit_frequency(meas, model="two_mass", io=sb.MechanicsIO.of_axis(ax), guess=guess)
    for k, v in TWO_MASS.items():
        assert b[k] == pytest.approx(a[k], rel=1e-6), k
        assert a[k] == pytest.approx(v, rel=0.02 if k == "motor_viscous_nms" else 1e-4), k
    with pytest.raises(ValueError, match="exactly one of axis"):
        sb.fit_frequency(meas, ax, "two_mass", io=sb.MechanicsIO(), guess=guess)
    with pytest.raises(ValueError, match="exactly one of axis"):
        sb.fit_frequency(meas, model="two_mass", guess=guess)
    with pytest.raises(ValueError, match=r"MechanicsIO.delay_samples = 2 needs a sample_period_s"):
        sb.MechanicsIO(delay_samples=2)
    with pytest.raises(ValueError, match=r"MechanicsIO.torque_per_input = 0 must be non-zero"):
        sb.MechanicsIO(torque_per_input=0.0)
    with pytest.raises(ValueError, match=r"MechanicsIO.sample_period_s = -1"):
        sb.MechanicsIO(sample_period_s=-1.0)
    with pytest.raises(ValueError, match=r"freq_hz\[0\] = 3000 Hz is outside"):
        sb.fit_frequency(([3000.0, 10.0, 20.0], [1.0, 1.0, 1.0]), model="rigid",
                         io=sb.MechanicsIO(sample_period_s=TS), guess={"inertia_kgm2": 1e-4})


def test_the_docs_frequency_section_runs(tmp_path, monkeypatch):
    # docs/identify.md is not a guide page (tests/python/test_guides.py): its frequency section's code runs here.
    import pathlib
    import re

    text = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "identify.md").read_text()
    section = text[text.index("## Frequency identification"):]
    blocks = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    assert blocks
    monkeypatch.chdir(tmp_path)
    ns: dict = {}
    for code in blocks:
        exec(compile(code, "docs/identify.md", "exec"), ns)
    fit = ns["fit"]
    assert fit["c_nms_per_rad"] == pytest.approx(0.01, rel=1e-4)
    assert fit["motor_viscous_nms"] == pytest.approx(2e-4, rel=0.02)
