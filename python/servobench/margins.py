"""Stability and margins of a position loop (issue 20: stability before margins): the :class:`Margins` every
frequency-response tool returns, :func:`margins` from frequency-response data (the Nyquist criterion for the
verdict), :func:`analytic_margins` of an axis's linear loop (closed-loop poles, crossings refined on the exact loop
gain) and :func:`closed_loop_poles`. Also available from :mod:`servobench.frequency`. C++:
``tuning/margins.hpp``, ``tuning/stability.hpp``; docs/bode.md, decisions Q1-Q4."""

from __future__ import annotations

from dataclasses import field
from typing import TYPE_CHECKING

import numpy as np

from . import _core
from . import _options as _opts
from ._serialise import JsonResult, dataframe

__all__ = ["Margins", "analytic_margins", "closed_loop_poles", "margins"]


def _core_axis(axis):
    return getattr(axis, "_axis", axis)


@_opts.described_result(_core.MARGINS_FIELDS, keys={"stability_keys": _core.STABILITY_FIELDS})
class Margins(JsonResult):
    """Stability first, then the margins and loop figures of merit (from :func:`margins`,
    :func:`analytic_margins` or :meth:`FrequencyResponse.margins`). ``str(m)`` starts with "UNSTABLE" for an
    unstable loop.

    stable, stability
        the verdict and how it was reached ("closed-loop poles" for the linear model, "Nyquist" for data).
        ``stable`` is False when unstable *or* undecided. The margins of a loop that is not stable are meaningless
        (python-control reports them all the same). ``stability`` is a dict:
        {stability_keys}.
    gain_crossovers, phase_crossovers
        every crossing (MATLAB's allmargin): {"freq_hz", "phase_margin_deg"} and {"freq_hz", "gain_margin_db",
        "kind"} arrays, by frequency; kind "upper" (``|L|`` < 1: the gain may rise) or "lower" (it may fall).
    {fields}
    source, note
        what the figures were read from ("analytic model", "measured (stepped sine)", ...) and what was left out.
    """

    # The single figures (gain_margin_db ... ms_freq_hz) come first, read at import from tuning::Margins::describe()
    # with their units and docs; static type checkers read these names (test_options_once checks they match).
    if TYPE_CHECKING:
        gain_margin_db: float
        gm_freq_hz: float
        lower_gain_margin_db: float
        lower_gm_freq_hz: float
        phase_margin_deg: float
        pm_freq_hz: float
        delay_margin_s: float
        bandwidth_hz: float
        ms: float
        ms_freq_hz: float
    stable: bool = False
    stability: dict = field(default_factory=dict)
    gain_crossovers: dict = field(default_factory=dict)
    phase_crossovers: dict = field(default_factory=dict)
    source: str = ""
    note: str = ""

    def to_dataframe(self):
        """Every crossing of the loop (MATLAB's allmargin) as a pandas DataFrame, by frequency: ``crossing``
        ("gain": ``|L|`` = 1, or "phase": angle L = -180 deg), ``freq_hz`` (Hz), ``phase_margin_deg`` (deg, at a gain
        crossing; NaN at a phase crossing), ``gain_margin_db`` (dB, at a phase crossing; NaN at a gain crossing) and
        ``kind`` ("upper"/"lower" at a phase crossing); ``df.attrs["units"]`` gives the units. The single-figure
        margins are fields (:meth:`to_json` writes them all)."""
        g, p = self.gain_crossovers, self.phase_crossovers
        fg = np.asarray(g.get("freq_hz", []), dtype=float)
        fp = np.asarray(p.get("freq_hz", []), dtype=float)
        cols = {"crossing": np.array(["gain"] * len(fg) + ["phase"] * len(fp), dtype=object),
                "freq_hz": np.concatenate([fg, fp]),
                "phase_margin_deg": np.concatenate([np.asarray(g.get("phase_margin_deg", np.full(len(fg), np.nan)),
                                                               dtype=float), np.full(len(fp), np.nan)]),
                "gain_margin_db": np.concatenate([np.full(len(fg), np.nan),
                                                  np.asarray(p.get("gain_margin_db", np.full(len(fp), np.nan)),
                                                             dtype=float)]),
                "kind": np.array([""] * len(fg) + [str(k) for k in p.get("kind", [""] * len(fp))], dtype=object)}
        order = np.argsort(cols["freq_hz"], kind="stable")
        df = dataframe({k: v[order] for k, v in cols.items()},
                       {"freq_hz": "Hz", "phase_margin_deg": "deg", "gain_margin_db": "dB"})
        return df

    @property
    def verdict(self) -> str:
        """"stable", "UNSTABLE" or "UNDECIDED"."""
        if self.stable:
            return "stable"
        return "UNSTABLE" if self.stability.get("decided", True) else "UNDECIDED"

    def __str__(self) -> str:
        def hz(x):
            return "-" if not np.isfinite(x) else f"{x:.4g} Hz"

        src = f" ({self.source})" if self.source else ""
        reason = self.stability.get("reason", "")
        lines = []
        if self.verdict == "UNSTABLE":
            lines.append(f"UNSTABLE{src}: {reason}")
            lines.append("the margins below are meaningless for an unstable loop")
        elif self.verdict == "UNDECIDED":
            lines.append(f"stability UNDECIDED{src}: {reason}")
            lines.append("the margins below are not backed by a stability verdict")
        else:
            lines.append(f"stable{src}: {reason}")
        lines += [
            f"phase margin {self.phase_margin_deg:.3g} deg at {hz(self.pm_freq_hz)} "
            f"(delay margin {self.delay_margin_s * 1e3:.3g} ms)" if np.isfinite(self.phase_margin_deg)
            else "phase margin: none found (|L| does not cross 1 in the data)",
            f"gain margin {self.gain_margin_db:.3g} dB at {hz(self.gm_freq_hz)}" if np.isfinite(self.gain_margin_db)
            else "gain margin: none found (no phase crossover with |L| < 1 in the data)",
        ]
        if np.isfinite(self.lower_gain_margin_db):
            lines.append(f"lower gain margin {self.lower_gain_margin_db:.3g} dB at {hz(self.lower_gm_freq_hz)}")
        gc, pc = self.gain_crossovers, self.phase_crossovers
        if len(gc.get("freq_hz", ())) > 1:
            lines.append("gain crossovers: " + ", ".join(
                f"{f:.4g} Hz (PM {p:.3g} deg)" for f, p in zip(gc["freq_hz"], gc["phase_margin_deg"])))
        if len(pc.get("freq_hz", ())) > 1:
            lines.append("phase crossovers: " + ", ".join(
                f"{f:.4g} Hz ({k} {g:.3g} dB)" for f, g, k in zip(pc["freq_hz"], pc["gain_margin_db"], pc["kind"])))
        lines.append(f"closed-loop bandwidth (-3 dB) {hz(self.bandwidth_hz)}")
        lines.append(f"peak sensitivity Ms {self.ms:.3g} at {hz(self.ms_freq_hz)}")
        if self.note:
            lines.append(f"note: {self.note}")
        return "\n".join(lines)


def _margins_from(d: dict, source: str = "", note: str = "") -> Margins:
    """A :class:`Margins` from the core's dict (adds the crossing kinds)."""
    d = dict(d)
    pc = dict(d.get("phase_crossovers", {}))
    if "gain_margin_db" in pc:
        pc["kind"] = ["lower" if g < 0 else "upper" for g in np.asarray(pc["gain_margin_db"])]
    d["phase_crossovers"] = pc
    st = dict(d.get("stability", {}))
    keep = {k: v for k, v in d.items() if k not in ("stability", "stable", "source", "note")}
    return Margins(**keep, stable=bool(st.get("stable", False)), stability=st, source=source, note=note)


_MARGINS_PYTHON_DEFAULTS = {
    "integrators": _opts.PythonDefault(None, -1, "None (default): inferred, as for -1"),
}


@_opts.takes_options(_core.MarginsOptions, python_defaults=_MARGINS_PYTHON_DEFAULTS, name="margins")
def _margins(freq_hz, loop_gain, closed_loop=None, *, source: str = "", **options) -> Margins:
    """Stability, gain, phase and delay margins (every crossing), closed-loop bandwidth and peak sensitivity from
    frequency-response data.

    freq_hz
        increasing frequencies, Hz.
    loop_gain
        the loop gain L (complex, pulse/pulse): the analytic ``loop_gain`` or a measured open loop Y/E taken with
        the feed-forward off.
    closed_loop
        Y/R for the bandwidth (complex); default L/(1 + L).
    {options}
    source
        what the data are, for the result's ``source`` ("measured (stepped sine)", ...).

    Crossings are interpolated linearly in log frequency (gain in dB, phase unwrapped between neighbours), so the
    figures are as good as the grid is dense around them. The phase margin is that of the crossover nearest to -1
    (the smallest ``|PM|``, python-control's rule) and the delay margin the smallest over all crossovers. For the
    linear model use :func:`analytic_margins` (closed-loop poles, exact crossings).
    """
    open_loop_unstable_poles, integrators = options["open_loop_unstable_poles"], options["integrators"]
    if isinstance(open_loop_unstable_poles, bool) or int(open_loop_unstable_poles) != open_loop_unstable_poles \
            or open_loop_unstable_poles < 0:
        raise ValueError(f"open_loop_unstable_poles = {open_loop_unstable_poles!r} must be an integer >= 0")
    if integrators is not None and (int(integrators) != integrators or not 0 <= integrators <= 10):
        raise ValueError(f"integrators = {integrators!r} must be None or an integer in 0..10")
    d = _core.margins(np.asarray(freq_hz, dtype=float), np.asarray(loop_gain, dtype=complex),
                      None if closed_loop is None else np.asarray(closed_loop, dtype=complex),
                      options=_opts.cpp_options(_core.MarginsOptions, options, _MARGINS_PYTHON_DEFAULTS))
    return _margins_from(d, source)


# typed signature of margins (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def margins(freq_hz, loop_gain, closed_loop=None, *, open_loop_unstable_poles: int = 0,
                integrators: int | None = None, source: str = '') -> Margins: ...
else:
    margins = _margins
# end of the typed signature of margins


@_opts.takes_options(_core.LoopOptions, only=["filters"], name="analytic_margins")
def _analytic_margins(axis, freq_hz=None, **options) -> Margins:
    """Margins of the axis's linear loop: stability from the closed-loop poles (the linear model), every crossing
    found on `freq_hz` (Hz, increasing, below Nyquist; None: 4000 log-spaced points from 1e-5/Ts to Nyquist, plus
    the Nyquist frequency itself) and refined on the exact loop gain to 1e-10 in log frequency; Ms by golden-section
    search. What python-control's ``stability_margins(..., returnall=True)`` gives on :func:`linear_model`.

    {options}
    """
    filters = options["filters"]
    f = None if freq_hz is None else np.asarray(freq_hz, dtype=float)
    return _margins_from(_core.analytic_margins(_core_axis(axis), f, bool(filters)), "analytic model")


# typed signature of analytic_margins (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def analytic_margins(axis, freq_hz=None, *, filters: bool = True) -> Margins: ...
else:
    analytic_margins = _analytic_margins
# end of the typed signature of analytic_margins


@_opts.takes_options(_core.LoopOptions, only=["filters"], name="closed_loop_poles")
def _closed_loop_poles(axis, **options) -> dict:
    """The axis's linear loop's poles (complex z): {"closed_loop", "open_loop", "max_radius", "integrators"
    (open-loop poles at z = 1), "open_loop_unstable"}.

    {options}
    """
    filters = options["filters"]
    return dict(_core.loop_poles(_core_axis(axis), bool(filters)))


# typed signature of closed_loop_poles (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def closed_loop_poles(axis, *, filters: bool = True) -> dict: ...
else:
    closed_loop_poles = _closed_loop_poles
# end of the typed signature of closed_loop_poles
