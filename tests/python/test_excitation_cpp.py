"""Chirp and multisine in C++ (issue 24 point 4): the excitations (tuning/chirp, tuning/multisine) and the broadband
H1 estimate (tuning/spectral_lines) give what the Python implementations gave before the move, kept verbatim in
tests/python/_broadband_reference.py: equal within 1e-9 relative to the largest magnitude of each array, and the
same DFT lines exactly (decision OP5)."""

from __future__ import annotations

import pathlib
import sys

import numpy as np
import pytest

import servobench as sb
from servobench import experiment, frequency as fr

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import _broadband_reference as ref  # noqa: E402

RTOL = 1e-9


def close(a, b, what="", per_element=False):
    """Signals: within RTOL of their largest magnitude; responses (per_element): each value within RTOL of itself."""
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, f"{what}: shape {a.shape} != {b.shape}"
    if a.size == 0:
        return
    scale = np.abs(b) if per_element else np.max(np.abs(b))
    err = np.abs(a - b)
    worst = np.max(err / scale)
    assert np.all(err <= RTOL * scale), f"{what}: |C++ - Python| up to {worst:.3g} relative"


@pytest.mark.parametrize("kind", ["log", "linear"])
@pytest.mark.parametrize("band, duration, ts, amp", [((10, 2000), 1.0, 100e-6, 2.0), ((1, 400), 3.3, 1e-3, 0.5),
                                                     ((5.5, 2400.5), 0.37, 200e-6, 300.0)])
def test_chirp_equals_python(kind, band, duration, ts, amp):
    kw = dict(start_hz=band[0], end_hz=band[1], duration_s=duration, servo_period_s=ts, amplitude=amp, kind=kind)
    close(fr.chirp(**kw), ref.chirp_reference(**kw), f"chirp {kind}")


@pytest.mark.parametrize("lines", [None, 1, 37, 1000])
@pytest.mark.parametrize("band, n, ts", [((10, 4000), 16667, 100e-6), ((3, 90), 1000, 1e-3), ((50, 60), 2001, 200e-6)])
def test_multisine_equals_python(lines, band, n, ts):
    kw = dict(start_hz=band[0], end_hz=band[1], period_ticks=n, servo_period_s=ts, amplitude=1.5, lines=lines,
              periods=2)
    x, bins = fr.multisine(**kw)
    x0, bins0 = ref.multisine_reference(**kw)
    np.testing.assert_array_equal(bins, bins0)
    close(x, x0, "multisine")


def test_multisine_refuses_an_empty_band():
    with pytest.raises(ValueError, match="period_ticks"):
        fr.multisine(start_hz=10.2, end_hz=10.4, period_ticks=100, servo_period_s=1e-3)


@pytest.mark.parametrize("kind", ["chirp", "multisine"])
@pytest.mark.parametrize("n, band", [(4000, (5.0, 500.0)), (25000, (0.2, 1000.0)), (999, (3.0, None))])
def test_experiment_excitation_equals_python(kind, n, band):
    kw = dict(amplitude=0.2, servo_period_s=200e-6, seed=7, start_hz=band[0], end_hz=band[1])
    close(experiment.excitation(kind, n, **kw), ref.excitation_reference(kind, n, **kw), f"excitation {kind}")


def _axis(noise=False, quantize=False):
    return sb.Axis(law=sb.GtServoLaw(kp=38, ki=30, kd=1660),
                   plant=sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01),
                   drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=float("inf"), current_bw_hz=1500),
                   encoder=sb.Encoder(counts_per_rev=10000, quantize=quantize, noise_counts=0.5 if noise else 0.0,
                                      seed=3),
                   dac=sb.Dac(quantize=quantize), servo_period_s=100e-6)


@pytest.mark.parametrize("excitation", ["multisine", "chirp"])
@pytest.mark.parametrize("case", [dict(lines=300, amplitude_pulse=2.0),
                                  dict(lines=None, start_hz=50, end_hz=800, amplitude_pulse=5.0, periods=1),
                                  dict(lines=120, amplitude_pulse=3.0, periods=3, noise=True, quantize=True)])
def test_broadband_equals_python(excitation, case):
    case = dict(case)
    noise, quantize = case.pop("noise", False), case.pop("quantize", False)
    a, b = _axis(noise, quantize), _axis(noise, quantize)
    got = fr.broadband_response(a, excitation=excitation, **case)
    want = ref.broadband_response_reference(b, excitation=excitation, **case)
    np.testing.assert_array_equal(got.freq_hz.size, want.freq_hz.size)
    close(got.freq_hz, want.freq_hz, "freq_hz", per_element=True)
    for which in ("plant", "open_loop", "closed_loop", "coherence"):
        close(getattr(got, which), getattr(want, which), which, per_element=True)
    assert got.flags == want.flags
    assert got.message == want.message
