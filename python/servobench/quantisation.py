"""How far the ADLINK card's 16-bit biquad integers depart from the floating-point design (issue 25 point 4).

``FloatBiquad.to_adlink()`` quantises a design to the card's integers (ADLINK seed 004 L1869-1968; adlink.md §3.6:
the largest ``|coefficient|`` becomes +-32767, ``DIV = trunc(32767/max|coef|)``, the others ``trunc(coef*DIV)``).
Poles near z = 1 (a cutoff or a narrow notch far below the sample rate) need more than 16 bits, and the integers
then filter something else than the design: the manual's own 100 Hz notch nulls at 98.61 Hz (docs/filters.md).
:func:`adlink_quantisation` measures the departure and ``to_adlink()`` warns with
:class:`AdlinkQuantisationWarning` when it exceeds the issue's bounds:

* passband: the largest ``|20 log10(|H_int| / |H_float|)|`` (dB) over the float design's passband, the
  frequencies 0..0.999 Nyquist where ``|H_float|`` is within 3 dB of its largest value (decision VF12); bound 0.5 dB;
* notch null: for a design with a complex zero pair whose null lies >= 20 dB below that largest value, the move of
  the null (the zeros' angle, Hz) as a fraction of the design's -3 dB bandwidth around it (decision VF13);
  bound 10 %.

Frequencies in Hz for a filter bound to a sample time; for an unbound one (``sample_time_s`` 0) in cycles per
sample (Ts taken as 1 s).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from . import _core
from ._serialise import JsonResult

__all__ = ["AdlinkQuantisation", "AdlinkQuantisationWarning", "adlink_quantisation", "to_adlink",
           "MAX_PASSBAND_DB", "MAX_NULL_SHIFT"]

#: The passband bound, dB (issue 25 point 4).
MAX_PASSBAND_DB = 0.5
#: The notch-null bound, as a fraction of the -3 dB bandwidth (issue 25 point 4).
MAX_NULL_SHIFT = 0.10
_HALF_POWER = 1.0 / math.sqrt(2.0)
_NULL_DEPTH = 0.1  # a null 20 dB below the peak makes the design a notch


class AdlinkQuantisationWarning(UserWarning):
    """``to_adlink()``: the card's integers depart from the float design by more than 0.5 dB in the passband, or
    move its notch null by more than 10 % of the notch's bandwidth. The message names the measured figures; the
    :class:`AdlinkQuantisation` report is in ``.report``."""

    def __init__(self, message: str, report: "AdlinkQuantisation | None" = None):
        super().__init__(message)
        self.report = report


@dataclass(frozen=True)
class AdlinkQuantisation(JsonResult):
    """The measured departure of an :class:`~servobench.AdlinkBiquad` from the :class:`~servobench.FloatBiquad` it
    was quantised from. Frequencies in Hz (cycles per sample for an unbound filter), gains in dB.

    passband_db: largest absolute dB difference over the float design's passband (within 3 dB of its peak);
    worst_hz: where it occurs; passband_hz: (lowest, highest) passband frequency examined;
    null_hz / null_int_hz: the float design's and the integers' null (None: the design has no notch null);
    bandwidth_hz: the float notch's -3 dB bandwidth; null_shift: ``abs(null_int_hz - null_hz) / bandwidth_hz``;
    sample_time_s: the sample time the frequencies refer to.
    """

    passband_db: float
    worst_hz: float
    passband_hz: tuple[float, float]
    null_hz: float | None
    null_int_hz: float | None
    bandwidth_hz: float | None
    null_shift: float | None
    sample_time_s: float

    @property
    def departs(self) -> bool:
        """True if the passband departure exceeds 0.5 dB or the null moves by more than 10 % of the bandwidth."""
        return self.passband_db > MAX_PASSBAND_DB or (self.null_shift is not None and self.null_shift > MAX_NULL_SHIFT)

    def __str__(self) -> str:
        unit = "Hz" if self.sample_time_s != 1.0 else "cycles/sample"
        s = (f"passband departure {self.passband_db:.3g} dB at {self.worst_hz:.6g} {unit} "
             f"(bound {MAX_PASSBAND_DB} dB)")
        if self.null_hz is not None:
            s += (f"; notch null {self.null_hz:.6g} -> {self.null_int_hz:.6g} {unit}, "
                  f"{100 * self.null_shift:.3g} % of the {self.bandwidth_hz:.4g} {unit} bandwidth "
                  f"(bound {100 * MAX_NULL_SHIFT:.0f} %)")
        return s


def _null_of(b: np.ndarray) -> float | None:
    """The zero pair's angle (rad, 0..pi) of b0 + b1 z^-1 + b2 z^-2, or None without a complex pair."""
    if b[0] == 0.0:
        return None
    z = np.roots(b)
    if z.size != 2:
        return None
    if abs(z[0].imag) <= 1e-12 * max(1.0, abs(z[0])):
        return None
    return float(abs(np.angle(z[0])))


def _null_of_int(b: np.ndarray) -> float:
    """The integers' null angle: the complex pair's angle, or 0 / pi for real zeros (the null left the band)."""
    a = _null_of(b)
    if a is not None:
        return a
    z = np.roots(b) if b[0] != 0.0 else np.roots(b[1:])
    if z.size == 0:
        return math.pi
    return 0.0 if np.max(z.real) > 0 else math.pi


def adlink_quantisation(design, integers=None) -> AdlinkQuantisation:
    """Measures how far the ADLINK integers depart from a float design.

    design
        the :class:`~servobench.FloatBiquad` (its ``sample_time_s`` sets the frequency unit: Hz; 0 = cycles/sample).
    integers
        the :class:`~servobench.AdlinkBiquad` to compare; default: ``design``'s own quantisation (the integers
        ``to_adlink()`` returns, without its warning).

    Returns an :class:`AdlinkQuantisation` (``.departs`` applies the 0.5 dB / 10 % bounds; ``str()`` explains).
    Raises TypeError for a design that is not a FloatBiquad, and what ``to_adlink()`` raises for a design the
    integers cannot hold.
    """
    if not isinstance(design, _core.FloatBiquad):
        raise TypeError(f"adlink_quantisation.design must be a FloatBiquad, got {type(design).__name__}")
    q = _core.design.quantize_adlink(design) if integers is None else integers
    if not isinstance(q, _core.AdlinkBiquad):
        raise TypeError(f"adlink_quantisation.integers must be an AdlinkBiquad, got {type(q).__name__}")
    ts = design.sample_time_s if design.sample_time_s > 0 else 1.0
    nyq = 0.5 / ts
    bf = np.array([design.b0, design.b1, design.b2])
    bq = np.array([q.b0, q.b1, q.b2], dtype=float)
    theta = _null_of(bf)
    grid = [np.linspace(0.0, 0.999 * nyq, 4001), np.geomspace(nyq * 1e-6, 0.999 * nyq, 4001)]
    if theta is not None:
        f0 = theta / (2 * math.pi * ts)
        grid.append(np.clip(f0 + np.linspace(-0.05, 0.05, 2001) * nyq, 0.0, 0.999 * nyq))
    f = np.unique(np.concatenate(grid))

    def mag_f(x):
        return np.abs(design.frequency_response(x, ts))

    hf = mag_f(f)
    hq = np.abs(q.frequency_response(f, ts))
    peak = float(np.max(hf))
    band = hf >= peak * _HALF_POWER
    with np.errstate(divide="ignore"):
        diff = np.abs(20.0 * np.log10(np.maximum(hq[band], 1e-300) / hf[band]))
    k = int(np.argmax(diff))
    fb = f[band]
    null_hz = null_int_hz = bandwidth = shift = None
    if theta is not None:
        f0 = theta / (2 * math.pi * ts)
        if float(mag_f(f0)) <= _NULL_DEPTH * peak:
            from scipy.optimize import brentq  # here, not at import: scipy.optimize is 0.6 s of `import servobench`

            edge = peak * _HALF_POWER
            below, above = f[(f < f0) & (hf >= edge)], f[(f > f0) & (hf >= edge)]
            lo = brentq(lambda x: float(mag_f(x)) - edge, below.max(), f0) if below.size else 0.0
            hi = brentq(lambda x: float(mag_f(x)) - edge, f0, above.min()) if above.size else nyq
            null_hz, bandwidth = f0, hi - lo
            null_int_hz = _null_of_int(bq) / (2 * math.pi * ts)
            shift = abs(null_int_hz - null_hz) / bandwidth
    return AdlinkQuantisation(passband_db=float(diff[k]), worst_hz=float(fb[k]),
                              passband_hz=(float(fb.min()), float(fb.max())), null_hz=null_hz,
                              null_int_hz=null_int_hz, bandwidth_hz=bandwidth, null_shift=shift, sample_time_s=ts)


def to_adlink(design):
    """``FloatBiquad.to_adlink()``: the card's integers (``design.quantize_adlink``), with an
    :class:`AdlinkQuantisationWarning` naming the measured departure when it exceeds 0.5 dB in the passband or
    10 % of the notch bandwidth at the null (:func:`adlink_quantisation`)."""
    q = _core.design.quantize_adlink(design)
    report = adlink_quantisation(design, q)
    if report.departs:
        warnings.warn(AdlinkQuantisationWarning(
            f"to_adlink: the 16-bit integers depart from the float design: {report}. Lengthen the sample time, "
            f"lower q or raise the frequency (docs/filters.md, 'Choosing the sample time'), or run the FloatBiquad",
            report), stacklevel=2)
    return q
