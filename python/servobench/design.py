"""Filter design: second-order sections (biquads) for the filter slots after the servo law.

Every function maps an analogue prototype to a :class:`~servobench.FloatBiquad` with the bilinear transform
``s = (2/Ts)(z-1)/(z+1)`` (optionally pre-warped) and returns it; ``.to_adlink()`` quantises it to the ADLINK card's
int16 integers (:class:`~servobench.AdlinkBiquad`), ``.frequency_response(freq_hz)`` evaluates it and ``.plot()``
draws it. Frequencies are in Hz, the sample time in s (use the axis's servo period). Bad arguments raise
ValueError naming the function, the parameter and its allowed range.

Without pre-warping (the default) the low-pass and the notch reproduce the ADLINK manual's worked integers exactly
(seed 004 L1919 and L1948; docs/decisions.md, section "Biquad filters")::

    >>> lowpass(1000, 100e-6).to_adlink()
    AdlinkBiquad(a1=32767, a2=-11896, b0=1794, b1=3588, b2=1794, div=28046, sample_time_s=0.0001)
    >>> notch(100, 100e-6, q=30).to_adlink()
    AdlinkBiquad(a1=32767, a2=-16398, b0=16415, b1=-32767, b2=16415, div=16433, sample_time_s=0.0001)
"""

from __future__ import annotations

import numbers

import numpy as np

from . import _checks
from . import _core
from .quantisation import AdlinkQuantisation, AdlinkQuantisationWarning, adlink_quantisation

_d = _core.design

__all__ = ["lowpass", "notch", "notch_q", "lead_lag", "from_s", "adlink_quantisation", "AdlinkQuantisation",
           "AdlinkQuantisationWarning"]


def _num(owner: str, name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise TypeError(f"{owner}.{name} must be a number, got {type(value).__name__}")
    return float(value)


def lowpass(cutoff_hz: float, sample_time_s: float, zeta: float = 0.707, *, prewarp: bool = False):
    """Second-order low-pass ``H(s) = wc^2 / (s^2 + 2 zeta wc s + wc^2)``, ``wc = 2 pi cutoff_hz``.

    cutoff_hz
        cutoff (natural) frequency in Hz, 0 < cutoff_hz < Nyquist = 1/(2 sample_time_s).
    sample_time_s
        sample time in s (the servo period of the axis that will run it), 0 < Ts <= 1.
    zeta
        damping ratio, > 0. The default 0.707 is what the ADLINK manual's integers imply (exactly 1/sqrt(2) gives
        DIV 28047 instead of 28046).
    prewarp
        pre-warp the bilinear transform at the cutoff (the response at cutoff_hz then equals the analogue one);
        off by default, as in the manual.

    Returns a :class:`~servobench.FloatBiquad` bound to `sample_time_s`.
    """
    return _d.lowpass(_num("lowpass", "cutoff_hz", cutoff_hz), _num("lowpass", "sample_time_s", sample_time_s),
                      _num("lowpass", "zeta", zeta), _checks.flag("design", "prewarp", prewarp))


def notch_q(center_hz: float, low_hz: float, high_hz: float, sample_time_s: float) -> float:
    """The quality factor ``q = center_hz / (high_hz - low_hz)`` of a notch whose -3 dB edges are low_hz and high_hz
    (Hz; 0 < low_hz < center_hz < high_hz < Nyquist). The standard definition; note that the ADLINK manual's
    example (100 Hz, edges 95/105 Hz, i.e. q = 10) printed integers that imply q ~ 30 (docs/decisions.md F4)."""
    o = "notch"
    return _d.notch_band_q(_num(o, "center_hz", center_hz), _num(o, "low_hz", low_hz), _num(o, "high_hz", high_hz),
                           _num(o, "sample_time_s", sample_time_s))


def notch(center_hz: float, sample_time_s: float, *, q: float | None = None, low_hz: float | None = None,
          high_hz: float | None = None, prewarp: bool = False):
    """Notch ``H(s) = (s^2 + w0^2) / (s^2 + (w0/q) s + w0^2)``, ``w0 = 2 pi center_hz``: unit gain far from the
    centre, a zero of transmission at it.

    center_hz
        notch centre in Hz, 0 < center_hz < Nyquist = 1/(2 sample_time_s).
    sample_time_s
        sample time in s.
    q
        quality factor > 0 (centre / -3 dB bandwidth). Give either `q` or both `low_hz` and `high_hz`.
    low_hz, high_hz
        the -3 dB edges in Hz; then ``q = center_hz / (high_hz - low_hz)`` (:func:`notch_q`). This is the standard
        definition, which the ADLINK manual's example does NOT follow: its 95/105 Hz edges (q = 10) give
        A2 = -16363, DIV = 16467, while its printed integers come from q ~ 30. Use ``q=30`` to reproduce them.
    prewarp
        pre-warp at the centre (the null then sits exactly at center_hz); off by default, as in the manual.

    Returns a :class:`~servobench.FloatBiquad`. Narrow notches far below the sample rate need more than 16-bit
    precision: ``to_adlink()`` then moves the null (the manual's own integers null at 98.61 Hz, not 100 Hz) or
    refuses the design if the quantised poles reach the unit circle.
    """
    o = "notch"
    ts = _num(o, "sample_time_s", sample_time_s)
    c = _num(o, "center_hz", center_hz)
    band = (low_hz is not None) or (high_hz is not None)
    if (q is not None) == band or (band and (low_hz is None or high_hz is None)):
        raise ValueError("notch: give either q (quality factor) or both low_hz and high_hz (the -3 dB edges, Hz)")
    if band:
        return _d.notch_band(c, _num(o, "low_hz", low_hz), _num(o, "high_hz", high_hz), ts, _checks.flag("design", "prewarp", prewarp))
    return _d.notch(c, _num(o, "q", q), ts, _checks.flag("design", "prewarp", prewarp))


def lead_lag(zero_hz: float, pole_hz: float, sample_time_s: float, *, gain: float = 1.0, prewarp: bool = False):
    """First-order lead/lag ``H(s) = gain (1 + s/wz) / (1 + s/wp)``, ``wz = 2 pi zero_hz``, ``wp = 2 pi pole_hz``.

    zero_hz < pole_hz is a lead (phase advance, largest at sqrt(zero_hz pole_hz), high-frequency gain
    gain*pole_hz/zero_hz); zero_hz > pole_hz a lag. Both in Hz, 0 < f < Nyquist. `gain` is the DC gain (> 0).
    `prewarp` pre-warps at sqrt(zero_hz pole_hz). Returns a :class:`~servobench.FloatBiquad` (b2 = a2 = 0).
    """
    o = "lead_lag"
    return _d.lead_lag(_num(o, "zero_hz", zero_hz), _num(o, "pole_hz", pole_hz),
                       _num(o, "sample_time_s", sample_time_s), _num(o, "gain", gain), _checks.flag("design", "prewarp", prewarp))


def _poly3(name: str, coefs) -> list[float]:
    arr = np.atleast_1d(np.asarray(coefs, dtype=float))
    if arr.ndim != 1 or arr.size == 0 or arr.size > 3:
        raise ValueError(f"from_s.{name} must hold 1 to 3 coefficients (highest power of s first: s^2, s, 1), "
                         f"got shape {arr.shape}")
    return [0.0] * (3 - arr.size) + [float(v) for v in arr]


def from_s(num, den, sample_time_s: float, *, prewarp_hz: float | None = None):
    """A general second-order section from s-domain coefficients, by the bilinear transform.

    num, den
        polynomial coefficients in s, highest power first (as numpy.polyval): up to 3 each, e.g.
        ``num=[1, 0, w0**2], den=[1, w0/q, w0**2]``. The denominator's degree must be >= the numerator's.
    sample_time_s
        sample time in s.
    prewarp_hz
        if given (0 < f < Nyquist, Hz), the transform is pre-warped so the response at that frequency is exact.

    Refuses (ValueError) a zero denominator, an improper transfer function and digital poles on or outside the unit
    circle (an unstable or marginal analogue prototype). Returns a :class:`~servobench.FloatBiquad`.
    """
    pw = 0.0 if prewarp_hz is None else _num("from_s", "prewarp_hz", prewarp_hz)
    if prewarp_hz is not None and pw == 0.0:
        raise ValueError("from_s.prewarp_hz = 0 is outside the allowed range 0 < f < Nyquist; use None for no pre-warping")
    return _d.from_s(_poly3("num", num), _poly3("den", den), _num("from_s", "sample_time_s", sample_time_s), pw)
