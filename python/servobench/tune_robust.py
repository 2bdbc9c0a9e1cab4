"""Robust tuning: gains for the worst plant of a spread, not only for the nominal one (issue 22 point 3).

:func:`tune_robust` draws `n` plants around an axis (:func:`servobench.sample_spread`: ``{"plant.inertia_kgm2":
(low, high), ...}``, seeded), designs a ladder of candidate loops on the nominal axis with
:func:`servobench.model_based_tune` (the same method, its target phase margin raised step by step: each candidate
is more conservative than the one before), and scores every candidate on every drawn plant: the phase margin of the
plant's analytic loop (:func:`servobench.analytic_margins`; an unstable loop scores -inf) and the overshoot of its
step response (the plants run together in C++ by :func:`servobench.simulate_many`). It keeps the candidate with the
highest crossover whose *worst* plant meets the objective (decision P19). The result holds the per-plant
distributions of the nominal design ("before") and of the robust one ("after").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Mapping

import numpy as np

from . import _core
from ._serialise import JsonResult
from .axis import Axis

__all__ = ["RobustTuneResult", "tune_robust"]

_OBJECTIVES = ("phase_margin", "overshoot")


@dataclass(frozen=True)
class RobustTuneResult(JsonResult):
    """What :func:`tune_robust` returns.

    law, filters
        the robust design: the card law (integers, feed-forward 0) and the two biquads, as
        :meth:`servobench.ModelTuneResult.apply` writes them (:meth:`apply` does it).
    met
        True if the worst drawn plant meets the objective with this design; False: no candidate did, and this is the
        candidate whose worst plant came nearest (see :attr:`candidates`).
    objective, target
        ``"phase_margin"`` (worst phase margin >= target, deg), ``"overshoot"`` (worst overshoot <= target, %) or
        the name of the user's callable (worst score <= target... see :func:`tune_robust`).
    before, after
        pandas DataFrames, one row per drawn plant: the drawn parameters, ``phase_margin_deg`` (deg; -inf:
        unstable loop), ``overshoot_pct`` (%), ``settling_time_s`` (s) -- with the nominal design (the plain
        :func:`~servobench.model_based_tune` at the target phase margin) and with the robust one.
    candidates
        pandas DataFrame, one row per candidate design: ``design_pm_deg`` (the nominal target it was designed
        for, deg), ``crossover_hz`` (nominal, Hz), ``worst_pm_deg``, ``worst_overshoot_pct``, ``feasible``.
    nominal
        the :class:`~servobench.ModelTuneResult` of the robust design (crossover, margins on the nominal plant ...).
    """

    law: object
    filters: tuple
    met: bool
    objective: str
    target: float
    before: object
    after: object
    candidates: object
    nominal: object = field(repr=False)
    command_pulse: float = 0.0
    servo_period_s: float = 0.0

    def __str__(self) -> str:
        b, a = self.before, self.after
        return (f"robust tuning ({self.objective}, target {self.target:g}, {len(a)} plants): "
                f"{'met' if self.met else 'NOT met'}; crossover {self.nominal.crossover_hz:.1f} Hz; worst phase "
                f"margin {b.phase_margin_deg.min():.1f} -> {a.phase_margin_deg.min():.1f} deg, worst overshoot "
                f"{b.overshoot_pct.max():.1f} -> {a.overshoot_pct.max():.1f} %")

    def apply(self, axis: Axis) -> None:
        """Writes the robust law and filters to `axis` and turns its servo on (no verification sweep: the design was
        checked on the whole spread)."""
        axis.set_law(self.law)
        axis.set_filters(self.filters)
        axis.set_servo_on(True)

    def to_dataframe(self, which: str = "after"):
        """One of the result's tables (pandas DataFrames, units in the column names: deg, %, s, Hz):
        ``"after"`` (default; one row per drawn plant with the robust design), ``"before"`` (the same plants with
        the nominal design) or ``"candidates"`` (one row per candidate design)."""
        if which not in ("after", "before", "candidates"):
            raise ValueError(f"to_dataframe: which = {which!r} must be 'after', 'before' or 'candidates'")
        return getattr(self, which).copy()

    def plot(self, *, ax=None, bins: int = 20) -> dict:
        """Histograms of the phase margin (deg) and the overshoot (%) over the drawn plants, before and after.
        `ax`: two matplotlib axes (default: a new figure with two). Returns the data drawn:
        ``{"phase_margin_deg": (before, after), "overshoot_pct": (before, after)}``."""
        import matplotlib.pyplot as plt

        if ax is None:
            _fig, ax = plt.subplots(1, 2, figsize=(10, 3.5))
        data = {}
        for a, col, unit in zip(ax, ("phase_margin_deg", "overshoot_pct"), ("deg", "%")):
            before = np.asarray(self.before[col], dtype=float)
            after = np.asarray(self.after[col], dtype=float)
            finite = np.concatenate([before, after])
            finite = finite[np.isfinite(finite)]
            edges = np.histogram_bin_edges(finite if finite.size else [0.0, 1.0], bins=bins)
            a.hist(np.clip(before, edges[0], edges[-1]), bins=edges, alpha=0.6, label="nominal design")
            a.hist(np.clip(after, edges[0], edges[-1]), bins=edges, alpha=0.6, label="robust design")
            a.set_xlabel(f"{col} [{unit}]")
            a.set_ylabel("plants")
            a.legend()
            data[col] = (before, after)
        if self.objective == "phase_margin":
            ax[0].axvline(self.target, color="k", lw=1)
        elif self.objective == "overshoot":
            ax[1].axvline(self.target, color="k", lw=1)
        return data


def _plant_axes(axis: Axis, table) -> list[Axis]:
    """One Axis per row of a parameter table ("part.field" columns), the rest as `axis`."""
    from .batch import axis_spec

    spec = axis_spec(axis)
    out = []
    for row in table.itertuples(index=False):
        parts: dict[str, dict] = {}
        for name, value in zip(table.columns, row):
            part, fld = name.split(".", 1)
            parts.setdefault(part, {})[fld] = float(value)
        s = dict(spec)
        for part, kw in parts.items():
            s[part] = s[part].replace(**kw)
        out.append(Axis(**s))
    return out


def _score(axis: Axis, plants: list[Axis], table, law, filters, command, settle_band_pulse: float, threads: int,
           freq_hz: np.ndarray):
    """Per-plant phase margin (deg; -inf unstable), overshoot (%) and settling time (s) of one design."""
    import pandas as pd

    from .batch import axis_spec, simulate_many
    from .margins import analytic_margins

    pm = np.empty(len(plants))
    for i, p in enumerate(plants):
        p.set_law(law)
        p.set_filters(filters)
        m = analytic_margins(p, freq_hz)
        pm[i] = m.phase_margin_deg if m.stable else -math.inf
    base = Axis(**dict(axis_spec(axis), law=law, filters=filters))
    met = simulate_many(table, command, axis=base, signals=(), settle_band_pulse=settle_band_pulse,
                        threads=threads).metrics
    out = pd.DataFrame(table).copy()
    out["phase_margin_deg"] = pm
    out["overshoot_pct"] = np.where(np.isfinite(pm), met["overshoot_pct"].to_numpy(), math.inf)
    out["settling_time_s"] = met["settling_time_s"].to_numpy()
    return out


def tune_robust(axis: Axis, *, spread: Mapping[str, object], n: int = 100, seed: int = 0,
                objective: str | Callable = "phase_margin", target: float | None = None,
                phase_margin_deg: float = 50.0, design_pm_deg=(50, 55, 60, 65, 70, 75, 80),
                step_pulse: float = 1000.0, step_ticks: int = 2000, settle_band_pulse: float = 5.0,
                points: int = 600, threads: int = 0, **tune_kwargs) -> RobustTuneResult:
    """Tunes `axis` for the worst plant of a spread (issue 22 point 3).

    spread, n, seed
        the plant spread, drawn by :func:`servobench.sample_spread`: ``{"plant.inertia_kgm2": (low, high), ...}``
        (any numeric parameter of the plant, drive, encoder or DAC; uniform ranges, frozen scipy.stats
        distributions or ``callable(rng, n)``), `n` plants (1..10000) from ``numpy.random.default_rng(seed)``.
    objective, target
        what the worst plant must meet: ``"phase_margin"`` -- its phase margin >= `target` deg (default: the
        `phase_margin_deg`); ``"overshoot"`` -- its step overshoot <= `target` % (default 10 %); or a callable
        ``f(scores) -> float`` of one design's per-plant DataFrame (columns ``phase_margin_deg``,
        ``overshoot_pct``, ``settling_time_s``) whose value must be <= `target` (default 0). An unstable plant
        fails every built-in objective.
    phase_margin_deg
        the nominal design's target phase margin (deg, 10..89): the "before" design, and the first rung.
    design_pm_deg
        the ladder of nominal target phase margins (deg) the candidates are designed for; those below
        `phase_margin_deg` are dropped. The candidate with the highest nominal crossover whose worst plant meets the
        objective is kept (ties: the lower design margin).
    step_pulse, step_ticks, settle_band_pulse
        the step response each plant runs for the overshoot and settling time: a step of `step_pulse` pulse held
        for `step_ticks` ticks; in-position band of the settling time, pulse.
    points
        log-spaced frequencies (1e-5/Ts .. 0.4999/Ts, 50..100000) each plant's margins are searched on; every crossing
        found is refined on the exact loop (:func:`servobench.analytic_margins`), so the grid only has to separate
        the crossings.
    threads
        threads of the batch runs (0 = every core; results do not depend on it).
    tune_kwargs
        passed to :func:`servobench.model_based_tune` (``alpha``, ``notch``, ``min_gain_margin_db``, ...).

    Returns a :class:`RobustTuneResult` (``.apply(axis)`` writes the design; ``.plot()`` draws the distributions).
    Costs one :func:`~servobench.model_based_tune` per rung and, per rung, `n` analytic margins and one batch run.
    """
    import pandas as pd

    from .autotune import model_based_tune
    from .batch import sample_spread

    if not isinstance(axis, Axis):
        raise TypeError(f"tune_robust.axis must be a servobench.Axis, got {type(axis).__name__}")
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or not 1 <= n <= 10000:
        raise ValueError(f"tune_robust.n = {n!r} must be a whole number in 1..10000 (plants)")
    if not (isinstance(phase_margin_deg, (int, float)) and 10 <= phase_margin_deg <= 89):
        raise ValueError(f"tune_robust.phase_margin_deg = {phase_margin_deg!r} must be in 10..89 deg")
    if not (math.isfinite(step_pulse) and step_pulse != 0):
        raise ValueError(f"tune_robust.step_pulse = {step_pulse!r} must be a finite, non-zero number (pulse)")
    if not isinstance(step_ticks, (int, np.integer)) or isinstance(step_ticks, bool) or not 10 <= step_ticks <= 10**7:
        raise ValueError(f"tune_robust.step_ticks = {step_ticks!r} must be a whole number in 10..10^7 (ticks)")
    if callable(objective):
        name = getattr(objective, "__name__", "custom")
        tgt = 0.0 if target is None else float(target)

        def worst(scores):
            return float(objective(scores))

        def ok(w):
            return w <= tgt
    elif objective == "phase_margin":
        name, tgt = objective, float(phase_margin_deg if target is None else target)

        def worst(scores):
            return float(np.min(scores["phase_margin_deg"]))

        def ok(w):
            return w >= tgt
    elif objective == "overshoot":
        name, tgt = objective, float(10.0 if target is None else target)

        def worst(scores):
            return float(np.max(scores["overshoot_pct"]))

        def ok(w):
            return w <= tgt
    else:
        raise ValueError(f"tune_robust.objective = {objective!r} must be one of {', '.join(_OBJECTIVES)} or a "
                         "callable(scores) -> float")
    if not math.isfinite(tgt):
        raise ValueError(f"tune_robust.target = {target!r} must be a finite number")
    if not isinstance(points, (int, np.integer)) or isinstance(points, bool) or not 50 <= points <= 100000:
        raise ValueError(f"tune_robust.points = {points!r} must be a whole number in 50..100000")
    ts = axis.servo_period_s
    freq_hz = np.geomspace(1e-5 / ts, 0.4999 / ts, int(points))
    rungs = sorted({float(phase_margin_deg)} | {float(p) for p in np.atleast_1d(design_pm_deg)
                                                if float(phase_margin_deg) <= float(p) <= 89})

    table = sample_spread(axis, spread, int(n), seed)
    plants = _plant_axes(axis, table)
    command = np.concatenate([[0.0], np.full(int(step_ticks) - 1, float(step_pulse))])

    rows, scored = [], []
    for pm in rungs:
        try:
            design = model_based_tune(axis, phase_margin_deg=pm, **tune_kwargs)
        except ValueError as e:  # no crossover meets this rung's bounds: the ladder ends here
            rows.append(dict(design_pm_deg=pm, crossover_hz=math.nan, worst_pm_deg=math.nan,
                             worst_overshoot_pct=math.nan, worst_objective=math.nan, feasible=False,
                             note=str(e).splitlines()[0]))
            continue
        law = design.gt_law(axis.law) if isinstance(axis.law, _core.GtServoLaw) else design.aps_law(axis.law)
        scores = _score(axis, plants, table, law, design.filters, command, settle_band_pulse, threads, freq_hz)
        w = worst(scores)
        rows.append(dict(design_pm_deg=pm, crossover_hz=design.crossover_hz,
                         worst_pm_deg=float(scores["phase_margin_deg"].min()),
                         worst_overshoot_pct=float(scores["overshoot_pct"].max()), worst_objective=w,
                         feasible=bool(ok(w)), note=""))
        scored.append((pm, design, law, scores, w))
    if not scored:
        raise ValueError("tune_robust: model_based_tune found no design at any rung of design_pm_deg ("
                         + "; ".join(r["note"] for r in rows) + ")")
    candidates = pd.DataFrame(rows)
    feasible = [s for s in scored if ok(s[4])]
    if feasible:
        best = max(feasible, key=lambda s: (s[1].crossover_hz, -s[0]))
    else:  # nearest miss: the best worst-case objective
        best = max(scored, key=lambda s: s[4]) if name == "phase_margin" else min(scored, key=lambda s: s[4])
    before = scored[0]  # the nominal design: the first rung (phase_margin_deg) when model_based_tune found it
    return RobustTuneResult(law=best[2], filters=tuple(best[1].filters), met=bool(feasible), objective=name,
                            target=tgt, before=before[3], after=best[3], candidates=candidates, nominal=best[1],
                            command_pulse=float(step_pulse), servo_period_s=axis.servo_period_s)
