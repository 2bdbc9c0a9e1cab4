"""Biquad filters and their design (ADLINK manual, seed 004 L1869-1968; adlink.md §3; docs/decisions.md F1-F9).

Manual test vectors: low-pass integers seed 004 L1919, notch integers seed 004 L1948 (T6, T8 of adlink.md §10); their
responses (T7, T9) are derived from the printed integers with the manual's own difference equation L1873-1887."""

import math
import pickle

import numpy as np
import pytest

import servobench as sb
from servobench import design

NAN, INF = math.nan, math.inf
TS = 100e-6  # the manual's examples: "100 microseconds sampling time" (L1919, L1948)
MANUAL_LP = dict(a1=32767, a2=-11896, b0=1794, b1=3588, b2=1794, div=28046)    # seed 004 L1919
MANUAL_NOTCH = dict(a1=32767, a2=-16398, b0=16415, b1=-32767, b2=16415, div=16433)  # seed 004 L1948


def ints(f):
    d = f.to_dict()
    d.pop("sample_time_s")
    return d


# -- the manual's integers ---------------------------------------------------------------------------------------

def test_lowpass_reproduces_the_manual_integers_L1919():
    f = design.lowpass(1000, TS)  # "1000 Hz cutoff frequency, 100 microseconds sampling time" (L1919)
    q = f.to_adlink()
    assert ints(q) == MANUAL_LP
    assert all(float(v).is_integer() for v in ints(q).values())
    assert q.sample_time_s == TS
    assert q == sb.AdlinkBiquad(**MANUAL_LP, sample_time_s=TS)
    # zeta = 1/sqrt(2) exactly is 1 LSB off (adlink.md §3.3): the manual's tool used 0.707.
    exact = design.lowpass(1000, TS, zeta=1 / math.sqrt(2)).to_adlink()
    assert (exact.div, exact.a2) == (28047, -11895)


def test_notch_reproduces_the_manual_integers_L1948_with_q_30():
    assert ints(design.notch(100, TS, q=30).to_adlink()) == MANUAL_NOTCH  # seed 004 L1948


def test_notch_band_95_105_is_q_10_and_does_not_give_the_manual_integers():
    """L1948 states Fl = 95 Hz, Fh = 105 Hz. With the standard -3 dB definition q = f0/(fh - fl) = 10, and q = 10
    gives A2 = -16363, DIV = 16467, not the printed -16398/16433 (docs/decisions.md F4)."""
    assert design.notch_q(100, 95, 105, TS) == 10.0
    got = ints(design.notch(100, TS, low_hz=95, high_hz=105).to_adlink())
    assert got == dict(MANUAL_NOTCH, a2=-16363, div=16467)
    assert got != MANUAL_NOTCH


def test_q_interval_that_reproduces_the_notch_integers():
    """At f0 = 100 Hz exactly, q in 29.44..30.079 reproduces L1948 (scan in steps of 0.001); the digest's scan over
    f0 and bandwidth together gives 29.5..30.3."""
    qs = np.round(np.arange(29.0, 30.5, 0.001), 3)
    ok = [q for q in qs if ints(design.notch(100, TS, q=float(q)).to_adlink()) == MANUAL_NOTCH]
    assert min(ok) == pytest.approx(29.440) and max(ok) == pytest.approx(30.079)
    assert len(ok) == 640  # one contiguous interval


# -- responses -------------------------------------------------------------------------------------------------

def test_integer_notch_quantisation_effect():
    """adlink.md §3.4 [!]: the printed integers null at 98.61 Hz (zeros at cos(theta) = 32767/(2*16415)), give only
    -2.34 dB at 100 Hz, and a DC gain of 63/64; the unquantised q = 30 design gives ~ -34 dB at 100 Hz."""
    q = sb.AdlinkBiquad(**MANUAL_NOTCH, sample_time_s=TS)
    f_null = math.acos(32767 / (2 * 16415)) / (2 * math.pi * TS)
    assert f_null == pytest.approx(98.61, abs=0.005)
    assert abs(q.frequency_response(f_null)) < 1e-9
    db100 = 20 * math.log10(abs(q.frequency_response(100.0)))
    assert db100 == pytest.approx(-2.34, abs=0.005)
    assert math.degrees(np.angle(q.frequency_response(100.0))) == pytest.approx(70.4, abs=0.05)
    assert q.frequency_response(0.0) == pytest.approx(63 / 64, abs=1e-15)
    assert 20 * math.log10(abs(design.notch(100, TS, q=30).frequency_response(100.0))) < -30
    # Table of adlink.md §3.5: |H| at 50 / 95 / 105 / 200 Hz.
    for f, mag in [(50, 0.9788), (95, 0.7667), (105, 1.0833), (200, 1.0048)]:
        assert abs(q.frequency_response(f)) == pytest.approx(mag, abs=5e-5)


def test_integer_lowpass_response_table():
    q = sb.AdlinkBiquad(**MANUAL_LP, sample_time_s=TS)
    assert q.frequency_response(0.0) == pytest.approx(7176 / 7175, abs=1e-15)  # DC gain (B0+B1+B2)/(DIV-A1-A2)
    for f, mag, deg in [(30, 1.0001, -2.4), (1000, 0.6830, -92.7), (1200, 0.5328, -108.3)]:
        h = q.frequency_response(f)
        assert abs(h) == pytest.approx(mag, abs=5e-5)
        assert math.degrees(np.angle(h)) == pytest.approx(deg, abs=0.05)


def test_frequency_response_shapes_and_period():
    f = design.lowpass(1000, TS)
    assert isinstance(f.frequency_response(100.0), complex)
    assert f.frequency_response(np.zeros((2, 3))).shape == (2, 3)
    assert f.frequency_response([0.0])[0] == pytest.approx(1.0, abs=1e-14)
    with pytest.raises(ValueError, match="sample time"):
        sb.FloatBiquad(b0=0.5).frequency_response(10.0)  # not bound to a period, none given
    assert sb.FloatBiquad(b0=0.5).frequency_response(10.0, sample_time_s=1e-3) == 0.5
    # float and integer forms of the same integers agree
    q = sb.AdlinkBiquad(**MANUAL_NOTCH, sample_time_s=TS)
    fr = np.linspace(0, 4999, 777)
    np.testing.assert_allclose(q.to_float().frequency_response(fr), q.frequency_response(fr), rtol=1e-10)


def single_bin(y, f_hz, ts):
    """Complex amplitude of the f_hz component of y by a single-bin DFT (y spans whole periods of f_hz)."""
    k = np.arange(len(y))
    return 2.0 / len(y) * np.sum(y * np.exp(-2j * np.pi * f_hz * ts * k))


# The manual's sine cases: low-pass 30 / 1200 Hz (L1919, Fig 4-9) and notch 50 / 100 / 200 Hz (L1948, Fig 4-13).
SINE_CASES = [(MANUAL_LP, 30.0), (MANUAL_LP, 1200.0), (MANUAL_NOTCH, 50.0), (MANUAL_NOTCH, 100.0),
              (MANUAL_NOTCH, 200.0)]


@pytest.mark.parametrize("coefs,f_hz", SINE_CASES, ids=lambda x: str(x) if isinstance(x, float) else "")
@pytest.mark.parametrize("form", ["integer", "float"])
def test_time_domain_sine_matches_frequency_response(coefs, f_hz, form):
    """A sine of amplitude 1000 counts through the filter, 60000 ticks; the last 20000 (whole periods of every test
    frequency at 10 kHz: 60, 2400, 100, 200, 400 periods) go into a single-bin DFT, which is then leakage-free.
    What remains is the start-up transient, decaying as |p|^k: the notch's poles have |p| = 0.99893, so after 40000
    ticks it is 0.99893^40000 = 3e-19 of the input, and double rounding (~1e-16 per operation, amplified by at most
    1/(1-|p|) ~ 1e3 in the recursion). A relative tolerance of 1e-9 in the complex response (amplitude and phase
    together: 1e-9 rad) is therefore ~1e4 above what should remain, and ~1e5 below a one-LSB coefficient change."""
    q = sb.AdlinkBiquad(**coefs, sample_time_s=TS)
    filt = q if form == "integer" else q.to_float()
    k = np.arange(60000)
    x = 1000.0 * np.sin(2 * np.pi * f_hz * TS * k)
    y = filt.filter(x)
    h_measured = single_bin(y[40000:], f_hz, TS) / single_bin(x[40000:], f_hz, TS)
    h = filt.frequency_response(f_hz)
    assert abs(h_measured - h) < 1e-9 * abs(h), (h_measured, h)


def test_integer_filter_state_is_not_truncated():
    """decisions.md F1: the DSP is floating point (L322), the division by DIV is exact double arithmetic."""
    q = sb.AdlinkBiquad(**MANUAL_LP)
    y = q.filter([1000.0, 0.0, 0.0])
    assert y[0] == 1794 * 1000 / 28046  # 63.966..., not 63
    assert y[1] == (3588 * 1000 + 32767 * y[0]) / 28046
    assert y[2] == (1794 * 1000 + 32767 * y[1] - 11896 * y[0]) / 28046
    assert not float(y[0]).is_integer()


def test_float_filter_is_the_usual_sign_convention():
    f = sb.FloatBiquad(b0=0.5, b1=0.25, b2=0.125, a1=-0.5, a2=0.25)
    x = np.zeros(50)
    x[0] = 1.0
    y = f.filter(x)
    # impulse response by the textbook recursion y = b x - a y
    ref = np.zeros(50)
    b, a = [0.5, 0.25, 0.125], [1.0, -0.5, 0.25]
    for n in range(50):
        ref[n] = sum(b[i] * x[n - i] for i in range(3) if n >= i) - sum(a[i] * ref[n - i] for i in (1, 2) if n >= i)
    np.testing.assert_allclose(y, ref, rtol=0, atol=1e-15)


# -- other designs -------------------------------------------------------------------------------------------------

def test_lead_lag():
    ts = 250e-6
    lead = design.lead_lag(50, 200, ts, gain=2.0)
    assert lead.b2 == 0 and lead.a2 == 0
    assert lead.frequency_response(0.0) == pytest.approx(2.0, abs=1e-13)
    # Pre-warped at sqrt(50*200) = 100 Hz the phase there is the analogue maximum asin((200-50)/(200+50)).
    pw = design.lead_lag(50, 200, ts, gain=2.0, prewarp=True)
    assert math.degrees(np.angle(pw.frequency_response(100.0))) == pytest.approx(math.degrees(math.asin(0.6)), abs=1e-9)
    # High-frequency gain of a lead -> gain * pole/zero (at Nyquist the bilinear map reaches s = infinity)
    assert abs(lead.frequency_response(1999.999)) == pytest.approx(8.0, rel=1e-6)
    lag = design.lead_lag(200, 50, ts)
    assert np.angle(lag.frequency_response(100.0)) < 0


def test_from_s_equals_the_named_designs():
    w = 2 * math.pi * 1000
    a = design.from_s([w * w], [1, 2 * 0.707 * w, w * w], TS)
    b = design.lowpass(1000, TS)
    for k in ("b0", "b1", "b2", "a1", "a2"):
        assert getattr(a, k) == pytest.approx(getattr(b, k), rel=1e-15)
    # pre-warped second-order: exact analogue response at the pre-warp frequency
    w0, q = 2 * math.pi * 300, 5.0
    f = design.from_s([1, 0, w0 * w0], [1, w0 / q, w0 * w0], TS, prewarp_hz=300)
    assert abs(f.frequency_response(300.0)) < 1e-12
    s = 2j * math.pi * 250
    h_analog = (s * s + w0 * w0) / (s * s + w0 / q * s + w0 * w0)
    f2 = design.from_s([1, 0, w0 * w0], [1, w0 / q, w0 * w0], TS, prewarp_hz=250)
    assert f2.frequency_response(250.0) == pytest.approx(h_analog, abs=1e-12)


# -- bad designs ------------------------------------------------------------------------------------------------

BAD_DESIGNS = [
    (lambda: design.lowpass(0, TS), "lowpass.cutoff_hz = 0 is outside the allowed range 0 < f < 5000 Hz"),
    (lambda: design.lowpass(-5, TS), "lowpass.cutoff_hz = -5 is outside"),
    (lambda: design.lowpass(5000, TS), "lowpass.cutoff_hz = 5000 is outside the allowed range 0 < f < 5000 Hz"),
    (lambda: design.lowpass(7000, TS), "lowpass.cutoff_hz = 7000"),
    (lambda: design.lowpass(NAN, TS), "lowpass.cutoff_hz = nan is not a finite number"),
    (lambda: design.lowpass(INF, TS), "lowpass.cutoff_hz = inf is not a finite number"),
    (lambda: design.lowpass(100, TS, zeta=0), "lowpass.zeta = 0 must be > 0"),
    (lambda: design.lowpass(100, TS, zeta=-0.5), "lowpass.zeta = -0.5 must be > 0"),
    (lambda: design.lowpass(100, TS, zeta=NAN), "lowpass.zeta = nan is not a finite number"),
    (lambda: design.lowpass(100, 0), "lowpass.sample_time_s = 0 must be > 0 s"),
    (lambda: design.lowpass(100, -1e-4), "lowpass.sample_time_s = -0.0001 must be > 0 s"),
    (lambda: design.lowpass(100, NAN), "lowpass.sample_time_s = nan is not a finite number"),
    (lambda: design.notch(0, TS, q=30), "notch.center_hz = 0 is outside"),
    (lambda: design.notch(5000, TS, q=30), "notch.center_hz = 5000 is outside"),
    (lambda: design.notch(INF, TS, q=30), "notch.center_hz = inf is not a finite number"),
    (lambda: design.notch(100, TS, q=0), "notch.q = 0 must be > 0"),
    (lambda: design.notch(100, TS, q=-3), "notch.q = -3 must be > 0"),
    (lambda: design.notch(100, TS, q=NAN), "notch.q = nan is not a finite number"),
    (lambda: design.notch(100, TS, low_hz=100, high_hz=105), "notch.low_hz = 100 must be below center_hz = 100 Hz"),
    (lambda: design.notch(100, TS, low_hz=95, high_hz=99), "notch.high_hz = 99 must be above center_hz"),
    (lambda: design.notch(100, TS, low_hz=0, high_hz=105), "notch.low_hz = 0 is outside"),
    (lambda: design.notch(100, TS, low_hz=95, high_hz=6000), "notch.high_hz = 6000 is outside"),
    (lambda: design.notch(100, TS), "notch: give either q"),
    (lambda: design.notch(100, TS, q=3, low_hz=95, high_hz=105), "notch: give either q"),
    (lambda: design.lead_lag(0, 100, TS), "lead_lag.zero_hz = 0 is outside"),
    (lambda: design.lead_lag(10, 5000, TS), "lead_lag.pole_hz = 5000 is outside"),
    (lambda: design.lead_lag(10, 100, TS, gain=0), "lead_lag.gain = 0 must be > 0"),
    (lambda: design.lead_lag(10, NAN, TS), "lead_lag.pole_hz = nan is not a finite number"),
    (lambda: design.from_s([1], [0, 0, 0], TS), "from_s.den = [0, 0, 0]"),
    (lambda: design.from_s([1, 0, 0], [1, 1], TS), "from_s.num: numerator degree 2 > denominator degree 1"),
    (lambda: design.from_s([1], [1, -10, 100], TS), "from_s.den: the poles have |z|"),   # unstable prototype
    (lambda: design.from_s([1], [1, 0, 100], TS), "from_s.den: the poles have |z| = 1"),  # on the jw axis
    (lambda: design.from_s([NAN], [1, 1], TS), "from_s.num[2] = nan is not a finite number"),
    (lambda: design.from_s([1], [1, 2, 3, 4], TS), "from_s.den must hold 1 to 3 coefficients"),
    (lambda: design.from_s([1], [1, 1], TS, prewarp_hz=5000), "from_s.prewarp_hz = 5000 is outside"),
    (lambda: design.from_s([1], [1, 1], TS, prewarp_hz=0), "from_s.prewarp_hz = 0"),
    # quantised poles on / outside the unit circle, numerator lost, coefficient too large
    (lambda: design.notch(5, TS, q=1000).to_adlink(), "to_adlink: the quantised poles"),
    (lambda: design.lowpass(2, TS).to_adlink(), "to_adlink: b0, b1, b2 = "),
    (lambda: sb.FloatBiquad(b0=40000).to_adlink(), "to_adlink.b0 = 40000 is too large"),
    (lambda: sb.FloatBiquad(a1=-2.5, a2=1.2).to_adlink(), "to_adlink: the floating-point biquad: the poles have"),
]


@pytest.mark.parametrize("call,expect", BAD_DESIGNS, ids=[e for _c, e in BAD_DESIGNS])
def test_bad_designs_are_refused_naming_the_cause(call, expect):
    with pytest.raises(ValueError) as info:
        call()
    assert expect in str(info.value)


def test_quantised_poles_that_sit_on_the_unit_circle_are_detected_exactly():
    # Float: a1 = -32767/16384, a2 = 0.99995 is stable (|a1| < 1 + a2, two real poles just inside z = 1).
    f = sb.FloatBiquad(b0=0.001, a1=-32767 / 16384, a2=0.99995)
    assert f.is_stable()
    # Quantised: DIV = 16384, A1 = 32767, A2 = trunc(-0.99995*16384) = -16383, so DIV - A1 - A2 = 0: a pole at z = 1
    # exactly (16384 z^2 - 32767 z + 16383 = (z - 1)(16384 z - 16383)). The integer Jury test catches it exactly.
    with pytest.raises(ValueError, match=r"A1 = 32767, A2 = -16383, DIV = 16384\) have \|z\| = 1 and 0.99993"):
        f.to_adlink()
    # A sharp notch far below the sample rate: the float design is stable, the quantised poles leave the circle.
    n = design.notch(5, TS, q=1000)
    assert n.is_stable() and max(abs(p) for p in n.poles()) < 1
    with pytest.raises(ValueError, match=r"have \|z\| = 1.011.* on or outside the unit circle"):
        n.to_adlink()


def test_wrong_argument_types():
    with pytest.raises(TypeError, match="lowpass.cutoff_hz must be a number"):
        design.lowpass("1000", TS)
    with pytest.raises(TypeError, match="notch.q must be a number"):
        design.notch(100, TS, q=True)


# -- value types ---------------------------------------------------------------------------------------------------

BAD_FIELDS = [
    (sb.AdlinkBiquad, "a1", [-32769, 32768, 0.5, NAN, INF], "-32768..32767"),
    (sb.AdlinkBiquad, "a2", [-32769, 32768, 1.5, NAN], "-32768..32767"),
    (sb.AdlinkBiquad, "b0", [-32769, 32768, 0.1, NAN], "-32768..32767"),
    (sb.AdlinkBiquad, "b1", [-32769, 32768, NAN], "-32768..32767"),
    (sb.AdlinkBiquad, "b2", [-32769, 32768, INF], "-32768..32767"),
    (sb.AdlinkBiquad, "div", [0, -32769, 32768, 2.5, NAN], "-32768"),
    (sb.AdlinkBiquad, "sample_time_s", [-1e-4, 2.0, NAN], "0..1"),
    (sb.FloatBiquad, "b0", [NAN, INF], "not a finite number"),
    (sb.FloatBiquad, "b1", [NAN, -INF], "not a finite number"),
    (sb.FloatBiquad, "b2", [INF], "not a finite number"),
    (sb.FloatBiquad, "a1", [NAN], "not a finite number"),
    (sb.FloatBiquad, "a2", [INF], "not a finite number"),
    (sb.FloatBiquad, "sample_time_s", [-1.0, 1.5, NAN], "0..1"),
]


@pytest.mark.parametrize("cls,field,bad,expect", [(c, f, v, e) for c, f, vals, e in BAD_FIELDS for v in vals],
                         ids=lambda x: repr(x) if not isinstance(x, type) else x.__name__)
def test_value_types_reject(cls, field, bad, expect):
    with pytest.raises(ValueError) as info:
        cls(**{field: bad})
    assert f"{cls.__name__}.{field} = " in str(info.value)
    assert expect in str(info.value)
    obj = cls()
    with pytest.raises(ValueError, match=field):
        setattr(obj, field, bad)
    assert obj == cls()


def test_every_filter_field_has_a_bad_input_test():
    covered = {(c, f) for c, f, _v, _e in BAD_FIELDS}
    for cls in (sb.AdlinkBiquad, sb.FloatBiquad):
        for field in cls.FIELDS:
            assert (cls, field) in covered


def test_div_zero_message():
    with pytest.raises(ValueError, match=r"AdlinkBiquad.div = 0 is not allowed: DIV divides .* -32768..-1 or 1..32767"):
        sb.AdlinkBiquad(div=0)


def test_value_type_protocol():
    q = sb.AdlinkBiquad(**MANUAL_NOTCH, sample_time_s=TS)
    assert repr(q) == ("AdlinkBiquad(a1=32767, a2=-16398, b0=16415, b1=-32767, b2=16415, div=16433, "
                       "sample_time_s=0.0001)")
    assert q.to_dict() == dict(MANUAL_NOTCH, sample_time_s=TS)
    assert pickle.loads(pickle.dumps(q)) == q
    assert q.replace(a2=-16363) != q
    assert sb.AdlinkBiquad().to_dict() == dict(a1=0, a2=0, b0=1, b1=0, b2=0, div=1, sample_time_s=0)  # L1897-1911
    assert sb.AdlinkBiquad.FIELDS == ("a1", "a2", "b0", "b1", "b2", "div", "sample_time_s")
    f = design.lowpass(1000, TS)
    assert isinstance(f, sb.FloatBiquad) and pickle.loads(pickle.dumps(f)) == f
    assert repr(f).startswith("FloatBiquad(b0=0.06396716")
    assert q.is_stable() and abs(q.poles()[0]) == pytest.approx(0.99893, abs=5e-6)
    assert not sb.AdlinkBiquad(a1=100, div=100).is_stable()  # pole at z = 1
    with pytest.raises(TypeError, match="unexpected keyword argument 'A1'"):
        sb.AdlinkBiquad(A1=3)


def test_plots_return_figures(tmp_path):
    import matplotlib.figure

    fig = design.notch(100, TS, q=30).plot(title="notch")  # a servobench.plot.Plot: figure, axes, data drawn
    assert isinstance(fig.figure, matplotlib.figure.Figure) and len(fig.axes) == 2
    assert len(fig.data["FloatBiquad 0"]["gain_db"]) == 2000
    q = sb.AdlinkBiquad(**MANUAL_NOTCH, sample_time_s=TS)
    fig2 = sb.plot.filter_response(design.notch(100, TS, q=30), q, labels=["float", "integer"],
                                   path=str(tmp_path / "n.png"))
    assert (tmp_path / "n.png").stat().st_size > 1000
    line = fig2.axes[0].lines[1]
    assert len(line.get_xdata()) == 2000
    with pytest.raises(ValueError, match="sample_time_s"):
        sb.plot.filter_response(sb.FloatBiquad())


# -- on the axis ----------------------------------------------------------------------------------------------------

def aps_axis(filters=None):
    """The demo axis (ADLINK law, 200 us, about 60 Hz crossover) with the given filters."""
    d = sb.demo_axis(law="aps")
    return sb.Axis(law=d.law, drive=d.drive, plant=d.plant, encoder=d.encoder, servo_period_s=200e-6, filters=filters)


def test_axis_records_each_stage_and_runs_both_forms():
    ts = 200e-6
    f0 = design.lowpass(800, ts)
    f1 = design.notch(300, ts, q=3).to_adlink()
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=1000)
    axis = aps_axis(filters=(f0, f1))
    assert axis.filters == (f0, f1)
    run = axis.run(move)
    # The trace's stages are exactly the standalone filters applied in series to the law output.
    np.testing.assert_array_equal(run.biquad0, f0.filter(run.u))
    np.testing.assert_array_equal(run.biquad1, f1.filter(run.biquad0))
    assert np.max(np.abs(run.biquad1 - run.u)) > 100.0  # the filters did something
    assert run.fb_pos[-1] == 10000  # and the loop still settles on target
    # The integer form of f0 (DC gain off by 1e-4) moves the axis within one encoder count of the float form.
    run2 = aps_axis(filters=(f0.to_adlink(), f1)).run(move)
    np.testing.assert_array_equal(run2.biquad0, f0.to_adlink().filter(run2.u))
    assert np.max(np.abs(run2.fb_pos - run.fb_pos)) <= 1.0
    assert np.max(np.abs(run2.biquad0 - run.biquad0)) > 0  # not the same arithmetic


def test_axis_default_filters_are_pass_through():
    axis = aps_axis()
    assert axis.filters == (sb.AdlinkBiquad(), sb.AdlinkBiquad())
    run = axis.run(np.linspace(0, 500, 300))
    np.testing.assert_array_equal(run.biquad0, run.u)
    np.testing.assert_array_equal(run.biquad1, run.u)


def test_axis_set_filters_and_rejections():
    axis = aps_axis()
    axis.set_filters((None, sb.AdlinkBiquad(**MANUAL_LP)))
    assert axis.filters[1] == sb.AdlinkBiquad(**MANUAL_LP)
    with pytest.raises(ValueError, match=r"Axis.filters\[0\]: the poles have \|z\| = 1"):
        aps_axis(filters=(sb.AdlinkBiquad(a1=100, div=100), None))
    with pytest.raises(ValueError, match=r"Axis.filters\[1\].sample_time_s = 0.0001 does not match the axis servo "
                                         r"period 0.0002 s"):
        aps_axis(filters=(None, design.lowpass(1000, TS)))
    with pytest.raises(ValueError, match="exactly 2 entries"):
        aps_axis(filters=(None,))
    with pytest.raises(TypeError, match=r"filters\[1\] must be None, a FloatBiquad or an AdlinkBiquad"):
        aps_axis(filters=(None, 3.0))
    with pytest.raises(ValueError, match=r"Axis.filters\[0\]"):
        axis.set_filters((sb.FloatBiquad(a1=-2.0, a2=1.0), None))
    assert axis.filters[1] == sb.AdlinkBiquad(**MANUAL_LP)  # unchanged after a refused update
