"""PVT tables and the FollowEx electronic cam (Googol GUC-ECAT and iDEABOX advanced manuals).

Units are the manuals': time ms, position pulse, velocity pulse/ms, acceleration pulse/ms^2. The sampled
outputs (``PvtAxis.run``, ``FollowEx.follow``, :func:`pvt_trajectory`, :func:`follow_trajectory`) are per tick,
as every generator's: pulse, pulse/tick, pulse/tick^2, pulse/tick^3.

PVT description modes, each returning a :class:`PvtCurve` to download into a :class:`PvtTables` slot:

* :func:`pvt_table` (t, p, v per point) and :func:`pvt_table_ex` (a begin and an end velocity per point);
* :func:`pvt_table_complete` (t, p; velocity and acceleration continuous, a clamped C2 spline);
* :func:`pvt_table_percent` (t, p, percent; node velocities by the linear-average recursion,
  :func:`pvt_percent_calculate`; percent shapes the acceleration without moving any point);
* :func:`pvt_table_continuous` / :func:`pvt_table_continuous_ex` (p, v, vel_max, acc, dec, percent and no
  times; :func:`pvt_continuous_calculate` gives the times).

A :class:`PvtAxis` runs a table at the tick: ``select`` (default table 1), ``set_loop`` (0 = infinite),
``start`` (the first point's time is a start delay, applied once), a ``select`` while moving takes effect at
the end of the pass. :class:`FollowEx` is the electronic cam in the master-position domain with the
segment types of :class:`FollowSegment`. Decisions M20-M33 in docs/decisions.md.
"""

from __future__ import annotations

import numpy as np

from ._core import (
    FollowEx,
    FollowExSetup,
    FollowSegment,
    GucCode as ReturnCode,  # the GUC-ECAT / iDEABOX codes' name before the vendor folder existed (decision GX4)
    PvtAxis,
    PvtCurve,
    PvtTables,
    follow_cam,
    pvt_complete_calculate,
    pvt_continuous_calculate,
    pvt_percent_calculate,
    pvt_start,
    pvt_table,
    pvt_table_complete,
    pvt_table_continuous,
    pvt_table_continuous_ex,
    pvt_table_ex,
    pvt_table_percent,
)
from ._serialise import dataframe
from .trajectory import Trajectory

__all__ = [
    "FollowEx", "FollowExSetup", "FollowSegment", "PvtAxis", "PvtCurve", "PvtTables", "ReturnCode",
    "follow_cam", "follow_trajectory", "pvt_complete_calculate", "pvt_continuous_calculate",
    "pvt_percent_calculate", "pvt_start", "pvt_table", "pvt_table_complete", "pvt_table_continuous",
    "pvt_table_continuous_ex", "pvt_table_ex", "pvt_table_percent", "pvt_trajectory",
]


def _pvt_curve_dataframe(self):
    """The table's points as a pandas DataFrame, one row per point: ``time_ms`` (ms), ``pos_pulse`` (pulse) and
    ``vel_pulse_per_ms`` (pulse/ms), as the manual's tables give them; ``df.attrs["units"]`` repeats the units. The
    cubic pieces between the points are :meth:`evaluate`'s (decision W25)."""
    return dataframe({"time_ms": self.time_ms, "pos_pulse": self.pos, "vel_pulse_per_ms": self.vel},
                     {"time_ms": "ms", "pos_pulse": "pulse", "vel_pulse_per_ms": "pulse/ms"})


PvtCurve.to_dataframe = _pvt_curve_dataframe  # a compiled result: the table lives here, not in the binding


def pvt_trajectory(table, *, period_s: float = 1e-3, table_id: int = 1, loop: int = 1, start_pos: float = 0.0,
                   dwell_after: int = 0, whole_pulses: bool = True, max_ticks: int | None = None) -> Trajectory:
    """Runs a PVT table on a fresh :class:`PvtAxis` at ticks of ``period_s`` seconds and returns the sampled
    :class:`~servobench.Trajectory` (sample 0 = the start, at rest at ``start_pos`` pulse; the start delay
    and ``loop`` passes follow, then ``dwell_after`` ticks at the end).

    ``table`` is a :class:`PvtCurve` (downloaded into a private table set as ``table_id``) or a
    :class:`PvtTables` whose ``table_id`` is used. ``loop`` = 0 (infinite) needs ``max_ticks``. Units: pulse,
    pulse/tick, pulse/tick^2, pulse/tick^3.
    """
    if loop == 0 and max_ticks is None:
        raise ValueError("pvt_trajectory: loop = 0 repeats the table forever; give max_ticks (ticks to sample)")
    if max_ticks is None:
        max_ticks = 10**8
    if isinstance(table, PvtCurve):
        tables = PvtTables()
        tables.download(table_id, table)
    else:
        tables = table
    axis = PvtAxis(tables, start_pos=start_pos, period_s=period_s)
    axis.select(table_id)
    axis.set_loop(loop)
    axis.start()
    body = axis.run_until_done(max_ticks)
    after = axis.run(dwell_after)
    key = "pos" if whole_pulses else "pos_exact"
    p0 = float(np.round(start_pos)) if whole_pulses else float(start_pos)
    cat = lambda k, first: np.concatenate([[first], body[k], after[k]])  # noqa: E731
    return Trajectory(pos=cat(key, p0), vel=cat("vel", 0.0), acc=cat("acc", 0.0), jerk=cat("jerk", 0.0))


def follow_trajectory(follow: FollowEx, master_pos, *, start: bool = True, fifo: int = 0,
                      whole_pulses: bool = True) -> Trajectory:
    """Drives a :class:`FollowEx` slave with a master position sequence (pulse, one sample per tick; the
    array the card would feed from the master selected by ``FollowExSetup.master_type``: 2 = the master
    axis's planned profile, 1 = an encoder, 3 = an axis's planned position or encoder by ``master_item``).

    With ``start`` the follow starts on ``fifo`` at ``master_pos[0]``; the slave is then stepped once per
    remaining sample. Returns the slave :class:`~servobench.Trajectory` (sample 0 = the start), pulse and
    pulse/tick; the jerk is the backward difference of the acceleration.
    """
    m = np.asarray(master_pos, dtype=float)
    if m.ndim != 1 or len(m) < 1:
        raise ValueError("follow_trajectory: master_pos must be a non-empty 1-D array of positions (pulse)")
    if start:
        follow.start(float(m[0]), fifo)
    s0 = follow.state
    out = follow.follow(m[1:])
    key = "pos" if whole_pulses else "pos_exact"
    p0 = float(np.round(s0[0])) if whole_pulses else s0[0]
    pos = np.concatenate([[p0], out[key]])
    vel = np.concatenate([[s0[1]], out["vel"]])
    acc = np.concatenate([[s0[2]], out["acc"]])
    jerk = np.diff(acc, prepend=acc[0])
    return Trajectory(pos=pos, vel=vel, acc=acc, jerk=jerk)
