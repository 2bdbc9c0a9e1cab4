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
