"""Many plants at once: :func:`simulate_many` and :func:`monte_carlo`, locally on every core or on a Dask cluster.

Every plant is a copy of one base :class:`~servobench.Axis` with some parameters changed (a *parameter table*:
one column per parameter, named ``"part.field"`` such as ``"plant.inertia_kgm2"`` or ``"law.kp"``; one row per
plant). All plants run from power-on over the same command, in C++, across threads with the GIL released.
Plants share nothing, so plant *i*'s result does not depend on the thread count, the chunking or the machine it
ran on: a Dask run (``client=``) returns exactly what the local run returns.
"""

from __future__ import annotations

__all__ = ["BatchResult", "METRICS", "simulate_many", "monte_carlo", "sample_spread", "axis_spec", "parameter_names"]

import os
from dataclasses import dataclass, field
from typing import Callable, Iterable, Mapping, Sequence

import numpy as np

from . import _core
from ._serialise import JsonResult, dataframe
from .axis import Axis, SIGNALS, SIGNAL_UNITS
from .trajectory import Trajectory

#: Per-plant move metrics (columns of :attr:`BatchResult.metrics`), as :func:`servobench.move_metrics` defines them.
METRICS: tuple[str, ...] = ("rise_time_s", "overshoot_pulse", "overshoot_pct", "settling_time_s",
                            "peak_following_error_pulse", "final_error_pulse")

_PARTS = ("law", "drive", "plant", "encoder", "dac", "switches")


@dataclass(frozen=True)
class BatchResult(JsonResult):
    """What :func:`simulate_many` returns.

    parameters
        the parameter table that was run (pandas DataFrame, one row per plant; empty columns for a list of axes
        that differ in more than numbers).
    metrics
        pandas DataFrame of per-plant move metrics (:data:`METRICS`: s, pulse, %), the parameter columns first;
        ``None`` if ``metrics=False``.
    signals
        ``{name: array (plants x ticks)}`` for each recorded signal (units in :data:`servobench.SIGNAL_UNITS`).
    servo_period_s
        the servo period Ts, s.
    threads
        worker threads used per process (the largest used by any chunk).
    chunks
        the number of chunks the plants were split into (1 for a local run).
    """

    parameters: object
    metrics: object
    signals: Mapping[str, np.ndarray]
    servo_period_s: float
    threads: int = 1
    chunks: int = 1
    units: Mapping[str, str] = field(default_factory=dict, repr=False)

    def __len__(self) -> int:
        return len(self.parameters)

    def to_dataframe(self, which: str = "metrics"):
        """A pandas DataFrame: ``"metrics"`` (default) the per-plant table (parameters then move metrics; the
        parameters alone when run with ``metrics=False``), or ``"signals"`` the recorded signals in long form,
        one row per plant and tick (columns plant, tick, time_s (s), then one per signal)."""
        if which == "metrics":
            return (self.metrics if self.metrics is not None else self.parameters).copy()
        if which == "signals":
            if not self.signals:
                raise ValueError("to_dataframe: no signal was recorded in this batch")
            first = next(iter(self.signals.values()))
            n, ticks = np.shape(first)
            cols = {"plant": np.repeat(np.arange(n), ticks), "tick": np.tile(np.arange(ticks), n),
                    "time_s": np.tile((np.arange(ticks) + 1) * self.servo_period_s, n)}
            cols.update({k: np.asarray(v).reshape(-1) for k, v in self.signals.items()})
            return dataframe(cols, {"time_s": "s", **dict(self.units)})
        raise ValueError(f"to_dataframe: which = {which!r} must be 'metrics' or 'signals'")

    def __repr__(self) -> str:
        return (f"BatchResult({len(self)} plants, signals: {', '.join(self.signals) or 'none'}, "
                f"metrics: {'yes' if self.metrics is not None else 'no'}, threads {self.threads}, "
                f"chunks {self.chunks})")


def axis_spec(axis: Axis) -> dict:
    """The constructor arguments of `axis` (picklable parameter objects): ``Axis(**axis_spec(axis))`` rebuilds it
    at power-on. Used to ship a base axis to Dask workers."""
    return dict(law=axis.law, drive=axis.drive, plant=axis.plant, encoder=axis.encoder, dac=axis.dac,
                switches=axis.switches, servo_period_s=axis.servo_period_s, substeps=axis.substeps,
                filters=axis.filters)


def parameter_names(axis: Axis) -> list[str]:
    """The parameter names a parameter table may set on copies of `axis` (``"law.kp"``, ``"plant.inertia_kgm2"``
    ...): the numeric fields of its law, drive, plant, encoder and DAC."""
    return list(_core.axis_parameter_names(axis._axis))


def _command_arrays(command):
    if isinstance(command, Trajectory):
        return (np.asarray(command.pos, float), np.asarray(command.vel, float), np.asarray(command.acc, float))
    pos = np.asarray(command, dtype=float)
    if pos.ndim != 1 or pos.size == 0:
        raise ValueError("command must be a non-empty 1-D array of positions (pulse), one per tick, or a Trajectory")
    return pos, None, None


def _table_from_axes(axes: Sequence[Axis]):
    """A base axis and a parameter table for a list of axes: the numeric fields that differ become columns; any
    other difference (part types, switches, period, sub-steps, filters, flags) raises ValueError."""
    import pandas as pd

    base = axes[0]
    names = parameter_names(base)
    base_spec = axis_spec(base)
    rows = []
    for i, ax in enumerate(axes):
        if not isinstance(ax, Axis):
            raise TypeError(f"axes[{i}] must be a servobench.Axis, got {type(ax).__name__}")
        spec = axis_spec(ax)
        for key in ("servo_period_s", "substeps", "filters", "switches"):
            if spec[key] != base_spec[key]:
                raise ValueError(f"axes[{i}].{key} differs from axes[0]: simulate_many runs copies of one axis that "
                                 "differ in numeric law/drive/plant/encoder/DAC fields only")
        for part in ("law", "drive", "plant", "encoder", "dac"):
            a, b = spec[part].to_dict(), base_spec[part].to_dict()
            if type(spec[part]) is not type(base_spec[part]) or any(
                    isinstance(v, bool) and v != b[k] for k, v in a.items()):
                raise ValueError(f"axes[{i}].{part} is of another kind or has another flag than axes[0].{part}: "
                                 "simulate_many runs copies of one axis that differ in numeric fields only")
        rows.append([_field(spec, n) for n in names])
    table = pd.DataFrame(rows, columns=names)
    varying = [c for c in names if table[c].nunique() > 1]
    return base, table[varying]


def _field(spec: dict, name: str) -> float:
    part, fld = name.split(".", 1)
    return float(getattr(spec[part], fld))


def _run_local(spec: dict, names: list[str], values: np.ndarray, pos, vel, acc, signals, metrics: bool,
               settle_band_pulse: float, threads: int):
    base = Axis(**spec)
    return _core.run_batch(base._axis, names, values, pos, vel, acc, signals, metrics, settle_band_pulse, threads)


def simulate_many(axes_or_table, command, *, axis: Axis | None = None, signals: Iterable[str] = ("fb_pos",),
                  metrics: bool = True, settle_band_pulse: float = 5.0, threads: int = 0, client=None,
                  scheduler=None, chunk_size: int | None = None, progress="auto") -> BatchResult:
    """Runs many independent copies of an axis over one command, in C++ across all cores (GIL released).

    axes_or_table
        a list of :class:`Axis` (copies of one axis differing in numeric parameters), or a parameter table: a
        pandas DataFrame or a ``{name: values}`` mapping, one column per parameter (``"plant.inertia_kgm2"``,
        ``"law.kp"``, ...; see :func:`parameter_names`), one row per plant, applied to copies of `axis`.
    command
        command positions (pulse, one per tick) or a :class:`Trajectory`; every plant starts at power-on.
    axis
        the base axis for a parameter table (default :func:`servobench.demo_axis`).
    signals
        signals to record per plant, each a (plants x ticks) array; default the feedback ``fb_pos`` only
        (``()``: none, metrics only). See :data:`servobench.SIGNALS`.
    metrics
        compute the per-plant move metrics (:data:`METRICS`) in C++; the command must move.
    settle_band_pulse
        in-position band of the settling time, pulse (> 0).
    threads
        worker threads per process, 0 = every core. Results do not depend on it.
    client, scheduler
        run on Dask: a ``dask.distributed.Client`` (``client=``), or any Dask scheduler (``scheduler=``: an
        address such as ``"tcp://10.0.0.5:8786"``, ``"threads"``, ``"processes"``, ``"sync"``). The plants are split
        into chunks of `chunk_size` rows (default: about 4 per worker), each chunk runs with :func:`simulate_many`
        on a worker, and the chunks are joined in order: the result equals the local run's.
    chunk_size
        plants per Dask chunk (>= 1).
    progress
        a local run's progress over its plants: ``"auto"`` (a tqdm bar when stderr is a terminal), True (a bar),
        None/False, or a callable ``(done, total) -> bool`` (False stops the batch: RuntimeError). A local run
        answers Ctrl-C within about 50 ms (KeyboardInterrupt; the plants not started are not run). Dask shows its
        own progress (``dask.distributed.progress``).

    Returns a :class:`BatchResult`: per-plant metrics as a pandas DataFrame and the recorded signals as arrays.
    """
    import pandas as pd

    if isinstance(axes_or_table, (list, tuple)) and axes_or_table and isinstance(axes_or_table[0], Axis):
        if axis is not None:
            raise ValueError("axis= is for a parameter table; a list of axes carries its own parameters")
        base, table = _table_from_axes(list(axes_or_table))
    elif isinstance(axes_or_table, (pd.DataFrame, Mapping)):
        table = pd.DataFrame(axes_or_table).reset_index(drop=True)
        if axis is None:
            from .examples import demo_axis
            base = demo_axis()
        elif isinstance(axis, Axis):
            base = axis
        else:
            raise TypeError(f"axis must be a servobench.Axis, got {type(axis).__name__}")
    else:
        raise TypeError("axes_or_table must be a non-empty list of servobench.Axis, a pandas DataFrame or a "
                        f"{{name: values}} mapping, got {type(axes_or_table).__name__}")
    if len(table) == 0:
        raise ValueError("axes_or_table holds no plants")
    signals = [str(s) for s in signals]
    for s in signals:
        if s not in SIGNAL_UNITS:
            raise ValueError(f"signals: unknown signal '{s}'; the signals are: {', '.join(SIGNALS)}")
    if not (isinstance(threads, (int, np.integer)) and not isinstance(threads, bool)) or threads < 0:
        raise ValueError(f"threads = {threads!r} must be a whole number >= 0 (0 = every core)")
    if not np.isfinite(settle_band_pulse) or settle_band_pulse <= 0:
        raise ValueError(f"settle_band_pulse = {settle_band_pulse} must be a finite number > 0 (pulse)")
    if client is not None and scheduler is not None:
        raise ValueError("give client= or scheduler=, not both")
    pos, vel, acc = _command_arrays(command)
    names = [str(c) for c in table.columns]
    known = set(parameter_names(base))
    for c in names:
        if c not in known:
            raise ValueError(f"parameters: unknown parameter '{c}' for this axis; the parameters are: "
                             f"{', '.join(sorted(known))}")
    values = np.ascontiguousarray(table.to_numpy(dtype=float)).reshape(len(table), len(names))
    spec = axis_spec(base)
    args = (pos, vel, acc, signals, bool(metrics), float(settle_band_pulse), int(threads))

    from ._progress import counter

    bar = counter(progress, "simulate_many", unit="plant", owner="simulate_many")  # checks `progress` (a bar: lazily)
    if client is None and scheduler is None:
        rec, met, used = _core.run_batch(base._axis, names, values, *args, bar)
        parts = [(rec, met, used)]
    else:
        parts = _run_dask(spec, names, values, args, client, scheduler, chunk_size)
    rec = {s: np.concatenate([p[0][s] for p in parts], axis=0) for s in signals}
    met_df = None
    if metrics:
        met = np.concatenate([p[1] for p in parts], axis=0)
        met_df = pd.concat([table, pd.DataFrame(met, columns=list(METRICS))], axis=1)
    return BatchResult(parameters=table, metrics=met_df, signals=rec, servo_period_s=base.servo_period_s,
                       threads=max(p[2] for p in parts), chunks=len(parts),
                       units={s: SIGNAL_UNITS[s] for s in signals})


def _run_dask(spec, names, values, args, client, scheduler, chunk_size):
    """Splits the rows into chunks and runs each chunk with the local batch on a Dask worker (dask.delayed)."""
    import dask

    n = len(values)
    if chunk_size is None:
        workers = 2
        if client is not None:
            try:
                workers = max(1, len(client.scheduler_info()["workers"]))
            except Exception:  # a client without the info (e.g. a test double): the default split
                workers = 2
        chunk_size = max(1, -(-n // (4 * workers)))
    if not isinstance(chunk_size, (int, np.integer)) or isinstance(chunk_size, bool) or chunk_size < 1:
        raise ValueError(f"chunk_size = {chunk_size!r} must be a whole number >= 1 (plants per Dask chunk)")
    task = dask.delayed(_run_local, pure=True)
    tasks = [task(spec, names, values[i:i + chunk_size], *args) for i in range(0, n, chunk_size)]
    if client is not None:
        return list(client.gather(client.compute(tasks)))
    if isinstance(scheduler, str) and "://" in scheduler:
        from dask.distributed import Client

        with Client(scheduler) as c:
            return list(c.gather(c.compute(tasks)))
    return list(dask.compute(*tasks, scheduler=scheduler))


def _sample(spec_value, rng: np.random.Generator, n: int, name: str) -> np.ndarray:
    if callable(spec_value):
        out = np.asarray(spec_value(rng, n), dtype=float)
    elif hasattr(spec_value, "rvs"):  # a frozen scipy.stats distribution
        out = np.asarray(spec_value.rvs(size=n, random_state=rng), dtype=float)
    elif isinstance(spec_value, tuple) and len(spec_value) == 2:
        lo, hi = float(spec_value[0]), float(spec_value[1])
        if not (np.isfinite(lo) and np.isfinite(hi) and lo <= hi):
            raise ValueError(f"spread['{name}'] = {spec_value}: a (low, high) uniform range needs finite low <= high")
        out = rng.uniform(lo, hi, n)
    else:
        raise TypeError(f"spread['{name}'] must be a (low, high) uniform range, a frozen scipy.stats distribution or "
                        "a callable(rng, n) -> n values")
    if out.shape != (n,):
        raise ValueError(f"spread['{name}'] gave an array of shape {out.shape}; expected ({n},)")
    return out


def sample_spread(axis: Axis, spread: Mapping[str, object], n: int, seed: int = 0):
    """A parameter table of `n` plants drawn around `axis` (pandas DataFrame).

    spread maps a parameter name (:func:`parameter_names`) to a ``(low, high)`` uniform range in that parameter's
    unit, a frozen ``scipy.stats`` distribution, or ``callable(rng, n)`` returning n values. The draws come from
    ``numpy.random.default_rng(seed)``, parameter by parameter in the order given: the same seed gives the same
    table.
    """
    import pandas as pd

    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise ValueError(f"n = {n!r} must be a whole number >= 1 (plants)")
    if not isinstance(spread, Mapping) or not spread:
        raise ValueError("spread must be a non-empty {parameter name: distribution} mapping")
    known = set(parameter_names(axis))
    rng = np.random.default_rng(seed)
    cols = {}
    for name, dist in spread.items():
        if name not in known:
            raise ValueError(f"spread: unknown parameter '{name}'; the parameters are: {', '.join(sorted(known))}")
        cols[name] = _sample(dist, rng, int(n), name)
    return pd.DataFrame(cols)


def monte_carlo(axis: Axis, command, *, spread: Mapping[str, object], n: int, seed: int = 0, **kwargs) -> BatchResult:
    """Monte Carlo over a plant spread: `n` copies of `axis` with parameters drawn by :func:`sample_spread`
    (seeded: the same `seed` gives the same plants and results, whatever the threads or the Dask cluster), each
    run over `command` (pulse) by :func:`simulate_many` (keyword arguments passed on: ``signals``, ``metrics``,
    ``threads``, ``client``, ...)."""
    if not isinstance(axis, Axis):
        raise TypeError(f"axis must be a servobench.Axis, got {type(axis).__name__}")
    table = sample_spread(axis, spread, n, seed)
    return simulate_many(table, command, axis=axis, **kwargs)
