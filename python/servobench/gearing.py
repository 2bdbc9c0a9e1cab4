"""Electronic gear fed from a chosen master source (GT_PrflG(master), GT manual L1029-1090, L4407-4437; gt.md §3.4).

The master is another axis's **profile** (its command position), its **encoder** (actual position), or an
**auxiliary encoder** (any array of counts): GT masters 1-4 are axes, 5-6 the auxiliary encoders (L1042).
The gear law (slave increment = ratio x master increment, drift-free) is :class:`~servobench.ElectronicGear`.

Composition used here, and by the future multi-axis card (decision M45): the master does not depend on the
slave, so the master axis is run first and its recorded profile or encoder samples, one per tick, feed the
slave's gear tick by tick with the same index -- at tick k the slave uses the master's profile position of
tick k (the profile advances before the encoders are sampled, gt.md §10) or the master encoder count read at
tick k. A card steps the axes in the order master -> slave inside each tick, which gives the same numbers.
"""

from __future__ import annotations

import numpy as np

from ._core import ElectronicGear, GtGear
from .trajectory import Trajectory

__all__ = ["gear_trajectory", "master_counts"]

_SOURCES = ("profile", "encoder", "aux")


def master_counts(master, source: str = "profile") -> np.ndarray:
    """The master's whole-pulse position per tick: ``source="profile"`` takes an AxisRun's ``cmd_pos`` (or a
    :class:`~servobench.Trajectory`'s ``pos``), ``"encoder"`` its ``fb_pos``, ``"aux"`` an array of auxiliary
    encoder counts (pulse)."""
    if source not in _SOURCES:
        raise ValueError(f"source = {source!r} must be one of {_SOURCES} (GT L1042: masters 1-4 axes, 5-6 aux encoders)")
    if source == "aux":
        counts = np.asarray(master, dtype=float)
    elif source == "profile":
        if not isinstance(master, Trajectory) and not hasattr(master, "cmd_pos"):
            raise TypeError(f"master_counts.master must be a Trajectory or an AxisRun, got {type(master).__name__}")
        counts = np.asarray(master.pos if isinstance(master, Trajectory) else master.cmd_pos, dtype=float)
    else:
        if not hasattr(master, "fb_pos"):
            raise TypeError(f"master_counts.master must be an AxisRun (with fb_pos), got {type(master).__name__}")
        counts = np.asarray(master.fb_pos, dtype=float)
    if counts.ndim != 1 or not np.all(np.isfinite(counts)):
        raise ValueError("the master positions must be a 1-D array of finite counts (pulse)")
    return np.rint(counts)


def gear_trajectory(master, *, gear: GtGear | None = None, ratio: float | None = None, source: str | None = None,
                    slave_start: float = 0.0) -> Trajectory:
    """The slave's command (whole pulses, one per master tick) for an electronic gear engaged at the first
    master sample. Give either ``gear`` (:class:`~servobench.GtGear`: master 1-4 -> an axis, ``source`` then
    "profile" by default or "encoder"; 5-6 -> "aux") or ``ratio`` (-16384..16384) and ``source``.
    ``slave_start`` is the slave's position (pulse) at engagement. Units: pulse, pulse/tick."""
    if gear is not None:
        if ratio is not None:
            raise ValueError("give either gear or ratio, not both")
        ratio = gear.ratio
        if gear.master >= 5:
            if source not in (None, "aux"):
                raise ValueError(f"GtGear.master = {gear.master:g} is an auxiliary encoder; source must be 'aux'")
            source = "aux"
        elif source == "aux":
            raise ValueError(f"GtGear.master = {gear.master:g} is an axis; source must be 'profile' or 'encoder'")
    if ratio is None:
        raise ValueError("ratio (or gear) is required")
    counts = master_counts(master, source or "profile").astype(np.int64)
    if counts.size == 0:
        raise ValueError("the master has no samples")
    g = ElectronicGear(ratio=float(ratio), master_pos=int(counts[0]), slave_pos=float(slave_start))
    pos = g.follow(counts)
    vel = np.diff(pos, prepend=pos[0])
    acc = np.diff(vel, prepend=vel[0])
    return Trajectory(pos=pos, vel=vel, acc=acc, jerk=np.diff(acc, prepend=acc[0]))
