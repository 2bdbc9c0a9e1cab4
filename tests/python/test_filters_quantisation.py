"""to_adlink() warns when the 16-bit integers depart from the float design (issue 25 point 4; decisions VF12-VF16):
by more than 0.5 dB in the passband, or a notch null moved by more than 10 % of the notch's bandwidth."""

import math
import warnings

import numpy as np
import pytest

import servobench as sb
from servobench import design
from servobench.quantisation import AdlinkQuantisationWarning


def quiet(f):
    with warnings.catch_warnings():
        warnings.simplefilter("error", AdlinkQuantisationWarning)
        return f.to_adlink()


def test_the_manuals_notch_warns_with_its_measured_null_shift():
    # ADLINK L1948: notch 100 Hz, Ts 100 us (q ~ 30): the integers null at 98.61 Hz (docs/filters.md); the
    # unwarped float design nulls at 99.967 Hz (the bilinear transform's warping).
    f = design.notch(100, 100e-6, q=30)
    with pytest.warns(AdlinkQuantisationWarning, match=r"notch null 99\.96\d* -> 98\.61\d* Hz") as rec:
        q = f.to_adlink()
    assert (q.b0, q.a2, q.div) == (16415, -16398, 16433)     # the integers are still returned, unchanged
    r = rec[0].message.report
    assert r.null_hz == pytest.approx(100 * 0.99967, rel=1e-5)
    assert math.tan(math.pi * r.null_hz * 1e-4) == pytest.approx(math.pi * 100 * 1e-4, rel=1e-9)  # bilinear warp
    assert r.null_int_hz == pytest.approx(98.61, abs=0.01)
    # the -3 dB bandwidth of the q=30 design is f0/q (bilinear, unwarped: within 1 %)
    assert r.bandwidth_hz == pytest.approx(100 / 30, rel=0.01)
    assert r.null_shift == pytest.approx(abs(r.null_int_hz - r.null_hz) / r.bandwidth_hz)
    assert r.null_shift > 0.1 and r.departs
    assert f"{100 * r.null_shift:.3g} %" in str(rec[0].message)


def test_the_manuals_lowpass_does_not_warn_and_its_departure_is_measured():
    # ADLINK L1919: low-pass 1000 Hz at 100 us: integers close to the design.
    f = design.lowpass(1000, 100e-6)
    q = quiet(f)
    assert (q.a1, q.a2, q.div) == (32767, -11896, 28046)
    r = design.adlink_quantisation(f)
    assert r.null_hz is None and r.passband_db < 0.5 and not r.departs
    # the measure is what it says: the largest |dB| difference over the float passband, checked on a fine grid
    fr = np.linspace(1, 0.999 * 5000, 20001)
    hf = np.abs(f.frequency_response(fr))
    band = hf >= hf.max() / math.sqrt(2)
    d = np.abs(20 * np.log10(np.abs(q.frequency_response(fr[band])) / hf[band]))
    assert r.passband_db == pytest.approx(d.max(), rel=0.02, abs=1e-6)


def test_a_low_cutoff_lowpass_warns_on_its_passband():
    # poles near z = 1: 20 Hz at 100 us; a design whose passband departs > 0.5 dB warns, naming the figure.
    f = design.lowpass(20, 100e-6)
    r = design.adlink_quantisation(f)
    assert r.passband_db > 0.5
    with pytest.warns(AdlinkQuantisationWarning, match=r"passband departure [0-9.]+ dB"):
        f.to_adlink()


@pytest.mark.parametrize("f0,q_,ts", [(100, 30, 100e-6), (100, 30, 1e-3), (800, 2, 250e-6), (300, 5, 250e-6),
                                      (50, 10, 50e-6), (1500, 1, 100e-6), (200, 50, 500e-6)])
def test_warning_iff_a_bound_is_exceeded(f0, q_, ts):
    # The warning fires exactly when the report departs; the report's null shift is the zeros' move over the
    # bandwidth, computed here independently from the integer zeros.
    f = design.notch(f0, ts, q=q_, prewarp=True)
    r = design.adlink_quantisation(f)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        q = f.to_adlink()
    assert (len([w for w in rec if issubclass(w.category, AdlinkQuantisationWarning)]) == 1) == r.departs
    z = np.roots([q.b0, q.b1, q.b2])
    null_int = abs(np.angle(z[0])) / (2 * math.pi * ts) if abs(z[0].imag) > 0 else None
    if null_int is not None:
        assert r.null_int_hz == pytest.approx(null_int, rel=1e-9)
        assert r.null_hz == pytest.approx(f0, rel=1e-6)      # prewarped: the float null sits on f0
    assert r.departs == (r.passband_db > 0.5 or r.null_shift > 0.1)


def test_documented_sample_time_choice_removes_the_warning():
    # docs/filters.md: lengthening the sample time moves the poles away from z = 1.
    reports = [design.adlink_quantisation(design.notch(100, ts, q=30, prewarp=True))
               for ts in (100e-6, 200e-6, 500e-6, 1000e-6)]
    shifts = [r.null_shift for r in reports]
    assert shifts == sorted(shifts, reverse=True)            # 41.6, 8.2, 1.1, 0.39 % (docs/filters.md table)
    assert shifts[0] == pytest.approx(0.416, abs=0.005) and shifts[2] == pytest.approx(0.011, abs=0.001)
    assert [r.departs for r in reports] == [True, True, False, False]   # 200 us: 1.27 dB in the passband


def test_bad_arguments():
    with pytest.raises(TypeError, match="FloatBiquad"):
        design.adlink_quantisation(sb.AdlinkBiquad())
    with pytest.raises(TypeError, match="AdlinkBiquad"):
        design.adlink_quantisation(design.lowpass(1000, 1e-4), integers=design.lowpass(1000, 1e-4))
    assert issubclass(AdlinkQuantisationWarning, UserWarning)
    assert design.AdlinkQuantisationWarning is AdlinkQuantisationWarning
