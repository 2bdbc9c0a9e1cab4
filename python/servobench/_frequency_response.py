"""The result of a frequency measurement or analysis: :class:`FrequencyResponse` (the three responses of one
loop, its margins, plots and tables) and the resonance peaks read from a response (:func:`resonances`, :class:`Peak`).
Defined here, published by :mod:`servobench.frequency` (their home for pickles, saved results and the docs; decision
OR2); the measurements that produce them are there.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import _core
from . import _options as _opts
from ._serialise import JsonResult, dataframe
from .margins import Margins, margins


_RESPONSES = ("plant", "open_loop", "closed_loop")


# ----------------------------------------------------------------------------------------------------------------
# Figures of merit
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Peak(JsonResult):
    """A resonance (``kind = "resonance"``, a peak) or anti-resonance (``"antiresonance"``, a dip) of a response:
    its frequency (Hz), gain (dB) and prominence above/below the response's trend (dB)."""

    kind: str
    freq_hz: float
    gain_db: float
    prominence_db: float


def resonances(freq_hz, response, *, min_prominence_db: float = 3.0, max_width_decades: float = 0.5) -> list[Peak]:
    """Resonance peaks and anti-resonance dips of a response (typically the plant Y/U), sorted by frequency.

    The gain in dB is detrended by its least-squares line in log frequency (a rigid axis falls 40 dB/decade;
    what stands out of that line is mechanics), then every local maximum/minimum whose prominence exceeds
    `min_prominence_db` (dB, > 0) is reported. Prominence is measured as in ``scipy.signal.peak_prominences``:
    the height above the higher of the two lowest points that separate the peak from higher ground. Peaks wider
    than `max_width_decades` at half prominence are bends of the trend, not modes, and are left out.
    """
    f = np.asarray(freq_hz, dtype=float)
    h = np.asarray(response, dtype=complex)
    if f.ndim != 1 or f.shape != h.shape or f.size < 3:
        raise ValueError("freq_hz and response must be 1-D arrays of the same length (at least 3 points)")
    if not min_prominence_db > 0:
        raise ValueError(f"min_prominence_db = {min_prominence_db} must be > 0 dB")
    g = 20 * np.log10(np.abs(h))
    x = np.log10(f)
    slope, offset = np.polyfit(x, g, 1)
    flat = g - (slope * x + offset)
    out: list[Peak] = []
    for kind, sign in (("resonance", 1.0), ("antiresonance", -1.0)):
        y = sign * flat
        for i in range(1, len(y) - 1):
            if not (y[i] > y[i - 1] and y[i] >= y[i + 1]):
                continue
            left = y[: i + 1][::-1]
            higher = np.nonzero(left > y[i])[0]
            left_min = left[: higher[0]].min() if higher.size else left.min()
            right = y[i:]
            higher = np.nonzero(right > y[i])[0]
            right_min = right[: higher[0]].min() if higher.size else right.min()
            prom = y[i] - max(left_min, right_min)
            if prom < min_prominence_db:
                continue
            # Width at half prominence, in decades: a mechanical mode is sharp; a broad bend of the trend
            # (a current loop's lag, the hold) is not a resonance.
            level = y[i] - 0.5 * prom
            lo = i
            while lo > 0 and y[lo] > level:
                lo -= 1
            hi = i
            while hi < len(y) - 1 and y[hi] > level:
                hi += 1
            if x[hi] - x[lo] > max_width_decades:
                continue
            out.append(Peak(kind, float(f[i]), float(g[i]), float(prom)))
    return sorted(out, key=lambda p: p.freq_hz)


# ----------------------------------------------------------------------------------------------------------------
# The response container
# ----------------------------------------------------------------------------------------------------------------
# The stepped sine's per-point arrays and run figures kept in FrequencyResponse.signals: those of
# tuning::SineSweepResult::describe() that are not a field of their own (decision OR1).
_SWEEP_FIELDS_OWN = ("freq_hz", "coherence", "distortion", "flag")
_SWEEP_SIGNALS = tuple(f["name"] for f in _core.SINE_SWEEP_FIELDS if f["name"] not in _SWEEP_FIELDS_OWN)


@dataclass(frozen=True)
class FrequencyResponse(JsonResult):
    """The three responses of one loop at a set of frequencies, measured or analytic.

    freq_hz
        frequencies, Hz.
    plant, open_loop, closed_loop
        complex responses Y/U (pulse per DAC count), Y/E and Y/R (pulse/pulse).
    method
        ``"stepped sine"``, ``"multisine"``, ``"chirp"`` or ``"analytic"``.
    coherence
        measured: per point 0..1 (stepped sine: share of Y's variance explained by the fundamental; broadband:
        the magnitude-squared coherence between R and Y); None for analytic data.
    distortion
        stepped sine: harmonic distortion of Y (2nd..5th over the fundamental); else None.
    loop_gain, sensitivity
        analytic only: L = F C P and E/R.
    feedforward, filters
        whether the feed-forward and the biquads were in the loop.
    status, message
        how the measurement ended (``"completed"``, ``"deviation_exceeded"``, ``"drive_alarm"``, ``"stopped"``).
    signals
        stepped sine: {signal_keys}; broadband: the run's saturated ticks.
    flags
        measured: per point "" (good) or why the point fails the judge (saturation, coherence, distortion,
        quantisation; thresholds in :func:`sine_sweep`); flagged points are drawn hollow and left out of margins.
    integrators, open_loop_unstable_poles
        measured: the loop's open-loop poles at z = 1 and outside the unit circle, from the axis's structure, for
        the Nyquist criterion on the data.
    servo_period_s
        the servo period, s.
    """

    freq_hz: np.ndarray
    plant: np.ndarray
    open_loop: np.ndarray
    closed_loop: np.ndarray
    method: str
    servo_period_s: float
    feedforward: bool = False
    filters: bool = True
    coherence: np.ndarray | None = None
    distortion: np.ndarray | None = None
    loop_gain: np.ndarray | None = None
    sensitivity: np.ndarray | None = None
    status: str = "completed"
    message: str = ""
    signals: dict = field(default_factory=dict, repr=False)
    flags: list | None = None
    integrators: int | None = None
    open_loop_unstable_poles: int = 0
    model_margins: Margins | None = field(default=None, repr=False)

    @property
    def usable(self) -> np.ndarray:
        """Per point: True where the point passed the judge (no flag) and its response is finite and non-zero."""
        ok = np.isfinite(self.open_loop) & (self.open_loop != 0) & np.isfinite(self.closed_loop)
        if self.flags is not None:
            ok &= np.array([not f for f in self.flags], dtype=bool)
        return ok

    def __len__(self) -> int:
        return len(self.freq_hz)

    def __repr__(self) -> str:
        f = self.freq_hz
        span = f"{f[0]:.4g}..{f[-1]:.4g} Hz" if len(f) else "empty"
        return f"FrequencyResponse({self.method}, {len(f)} points, {span}, status={self.status!r})"

    def response(self, which: str) -> np.ndarray:
        """The complex response named `which`: "plant", "open_loop", "closed_loop" (or "loop_gain",
        "sensitivity" for analytic data)."""
        if which not in (*_RESPONSES, "loop_gain", "sensitivity"):
            raise ValueError(f"which = {which!r} must be one of plant, open_loop, closed_loop, loop_gain, sensitivity")
        h = getattr(self, which)
        if h is None:
            raise ValueError(f"{which} is only available from analytic data (servobench.frequency.analytic_response)")
        return h

    def to_dataframe(self):
        """One row per frequency (index ``freq_hz``, Hz): gain (``<which>_db``, dB) and phase (``<which>_deg``,
        deg) of plant, open loop and closed loop (and loop gain, sensitivity for analytic data), then coherence,
        distortion, the judge's flag and ``usable`` of a measurement. ``df.attrs["units"]`` names each unit;
        :meth:`to_json` keeps the complex values exactly."""
        cols: dict = {"freq_hz": self.freq_hz}
        units = {"freq_hz": "Hz"}
        for which in (*_RESPONSES, "loop_gain", "sensitivity"):
            h = getattr(self, which)
            if h is None:
                continue
            with np.errstate(divide="ignore"):
                cols[f"{which}_db"] = 20 * np.log10(np.abs(h))
            cols[f"{which}_deg"] = self.phase_deg(which)
            units.update({f"{which}_db": "dB", f"{which}_deg": "deg"})
        for name, unit in (("coherence", "1"), ("distortion", "1")):
            if getattr(self, name) is not None:
                cols[name], units[name] = np.asarray(getattr(self, name), dtype=float), unit
        if self.flags is not None:
            cols["flag"] = np.asarray(self.flags, dtype=object)
        cols["usable"] = self.usable
        return dataframe(cols, units, index="freq_hz")

    def gain_db(self, which: str = "open_loop") -> np.ndarray:
        """Gain of a response, dB."""
        return 20 * np.log10(np.abs(self.response(which)))

    def phase_deg(self, which: str = "open_loop") -> np.ndarray:
        """Phase of a response, deg, unwrapped point to point from the lowest frequency and shifted by whole
        turns so that the first point lies in (-270, 90] (as the Bode plots draw it)."""
        ph = np.asarray(_core.unwrapped_phase_deg(self.response(which)))
        return ph - 360.0 * np.ceil((ph[0] - 90.0) / 360.0) if ph.size else ph

    def margins(self) -> Margins:
        """Stability and margins of the loop. Analytic data: the closed-loop poles of the linear model and crossings
        refined on the exact loop gain (:func:`analytic_margins` over these frequencies). Measured: the Nyquist
        criterion and the crossings of Y/E (the loop gain only when the feed-forward was off, else ValueError) over
        the points that passed the judge (:attr:`usable`); the others are left out and named in ``note``.
        ValueError when fewer than 2 points remain: such a sweep cannot give a margin."""
        if self.model_margins is not None:
            return self.model_margins
        if self.loop_gain is not None:
            return margins(self.freq_hz, self.loop_gain, self.closed_loop, source=self.method)
        if self.feedforward:
            raise ValueError("this open loop Y/E was measured with the feed-forward on, so it is not the loop gain; "
                             "measure with feedforward=False to read margins")
        ol, cl = np.asarray(self.open_loop), np.asarray(self.closed_loop)
        ok = self.usable
        note = ""
        if not ok.all():
            reasons = {}
            for i in np.nonzero(~ok)[0]:
                why = (self.flags[i] if self.flags is not None and self.flags[i] else "no response (encoder saw no "
                       "motion)")
                for r in why.split("; "):
                    key = r.split(" (")[0] if r.startswith("no response") else \
                        (r.split(" ")[0] if r[:1] != "|" else r.split(" ")[0] + " floor")
                    reasons[key] = reasons.get(key, 0) + 1
            note = (f"{int((~ok).sum())} of {len(ok)} points left out: " +
                    ", ".join(f"{k} ({n})" for k, n in reasons.items()))
        if ok.sum() < 2:
            raise ValueError(f"no margin from this {self.method} measurement: only {int(ok.sum())} of {len(ok)} "
                             f"measured points passed the checks ({note or 'none measured'}); lower the amplitude if they saturate, "
                             "raise it if they sit at the quantisation floor")
        m = margins(self.freq_hz[ok], ol[ok], cl[ok], open_loop_unstable_poles=self.open_loop_unstable_poles,
                    integrators=self.integrators, source=f"measured ({self.method})")
        import dataclasses

        return dataclasses.replace(m, note=note)

    def resonances(self, which: str = "plant", *, min_prominence_db: float = 3.0) -> list[Peak]:
        """Resonances and anti-resonances of a response (default the plant); see :func:`resonances`."""
        return resonances(self.freq_hz, self.response(which), min_prominence_db=min_prominence_db)

    def to_frd(self, which: str = "open_loop"):
        """The response as a python-control ``FrequencyResponseData`` (frequencies in rad/s). Needs the
        ``control`` package (``pip install control``)."""
        try:
            import control
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise ImportError("to_frd needs python-control: pip install control") from exc
        return control.frd(self.response(which), 2 * np.pi * self.freq_hz)

    def plot(self, which=("plant", "open_loop", "closed_loop"), *, path: str | None = None, title: str | None = None):
        """Bode plot of the chosen responses (see :func:`servobench.plot.bode`); margins are annotated when the open
        loop is drawn. Returns the :class:`servobench.plot.Plot`."""
        from . import plot

        return plot.bode(self, which=which, path=path, title=title)


FrequencyResponse.__doc__ = _opts.fill_keys(FrequencyResponse.__doc__, {
    "signal_keys": tuple(f for f in _core.SINE_SWEEP_FIELDS if f["name"] in _SWEEP_SIGNALS)})
