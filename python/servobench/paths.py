"""Coordinated paths: coordinate systems, line / arc / helix segments, the FIFO with buffered commands, and
look-ahead (Googol GT, GE, GUC-ECAT and iDEABOX manuals), the GUC/iDEABOX FIFO0/FIFO1 pair
(:class:`CrdFifoPair`), GE look-ahead module A in mm/s (:class:`GeLookAhead`), and ADLINK interpolation with its
seven transition modes (:class:`AdlinkInterpolator`, units pulse, pulse/s, s).

Units are the path's: coordinate unit (pulse on GE/GUC-ECAT/iDEABOX), time ms, speed unit/ms, acceleration
unit/ms^2. A :class:`PathGenerator` is stepped once per motion cycle (``PathSetup.cycle_ms``, default 1 ms)::

    import servobench as sb
    g = sb.PathGenerator(sb.CoordSystem.identity(2))
    g.init_lookahead(sb.LookAheadParams(t_ms=5, acc_max=1, n=200))
    g.line([200000, 0], vel=100, acc=0.8)
    g.arc_center("xy", [200000, 0], center_offset=(-100000, 0), ccw=False, vel=100, acc=0.8)
    g.flush(); g.start()
    run = sb.run_path(g)               # PathRun: t_ms, pos (n, dim), axis_pos, speed, acc, segments, ...
    run.plot_xy()                      # the XY path coloured by speed

Geometry errors raise :class:`PathGeometryError` (a ValueError) naming the GT/GE return code; a full FIFO or
a command in the wrong state raises :class:`~servobench.MotionCommandRefused` (return code 1). The look-ahead
algorithm is ours (the manuals give none): decisions C10-C16 in docs/decisions.md, explained in docs/paths.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import _checks
from ._serialise import JsonResult, dataframe
from ._core import (
    AdlinkInterpolator,
    AdlinkInterpSetup,
    BlendMode,
    CoordSystem,
    CrdFifoPair,
    GeLookAhead,
    GeLookAheadParams,
    LookAheadParams,
    PathGenerator,
    PathGeometryError,
    PathSegment,
    PathSetup,
    PathState,
    corner_speed_limit,
    plan_polyline_lookahead,
)

__all__ = [
    "AdlinkInterpolator", "AdlinkInterpSetup", "AdlinkRun", "BlendMode", "CrdFifoPair", "GeLookAhead",
    "GeLookAheadParams", "run_adlink", "CoordSystem", "LookAheadParams", "PathGenerator", "PathGeometryError", "PathRun", "PathSegment", "PathSetup",
    "PathState", "corner_speed_limit", "plan_polyline_lookahead", "run_path",
]


@dataclass
class PathRun(JsonResult):
    """A recorded path, one row per motion cycle.

    t_ms: time at the end of each cycle, ms. pos: coordinate positions (n, dim), unit. axis_pos: motor positions
    (n, len(axes)), pulse, for the motor axes ``axes``. speed: path speed, unit/ms. acc: path (tangential)
    acceleration, unit/ms^2. segments: completed segments. gpo: general output word. aux: positions (n, k) of
    the outside axes ``aux_axes`` moved by BufMove / BufGear, pulse.
    """

    t_ms: np.ndarray
    pos: np.ndarray
    axis_pos: np.ndarray
    speed: np.ndarray
    acc: np.ndarray
    segments: np.ndarray
    gpo: np.ndarray
    aux: np.ndarray
    axes: list = field(default_factory=list)
    aux_axes: list = field(default_factory=list)

    def __len__(self) -> int:
        return len(self.t_ms)

    def __repr__(self) -> str:
        dur = self.t_ms[-1] if len(self) else 0.0
        return (f"PathRun({len(self)} cycles, {dur:g} ms, {int(self.segments[-1]) if len(self) else 0} segments, "
                f"peak speed {self.speed.max() if len(self) else 0:g} unit/ms)")

    def to_dataframe(self):
        """One row per motion cycle: t_ms (ms), pos_0.. (the coordinates, unit), axis_<n> (motor axis n, pulse),
        speed (unit/ms), acc (unit/ms^2), segments, gpo, aux_<n> (outside axis n, pulse); units in
        ``df.attrs["units"]``."""
        cols = {"t_ms": self.t_ms}
        units = {"t_ms": "ms", "speed": "unit/ms", "acc": "unit/ms^2"}
        pos = np.asarray(self.pos).reshape(len(self), -1)
        for i in range(pos.shape[1]):
            cols[f"pos_{i}"], units[f"pos_{i}"] = pos[:, i], "unit"
        ap = np.asarray(self.axis_pos).reshape(len(self), -1)
        for i in range(ap.shape[1]):
            name = f"axis_{self.axes[i]}" if i < len(self.axes) else f"axis_pos_{i}"
            cols[name], units[name] = ap[:, i], "pulse"
        cols.update({"speed": self.speed, "acc": self.acc, "segments": self.segments, "gpo": self.gpo})
        aux = np.asarray(self.aux).reshape(len(self), -1)
        for i in range(aux.shape[1]):
            name = f"aux_{self.aux_axes[i]}" if i < len(self.aux_axes) else f"aux_{i}"
            cols[name], units[name] = aux[:, i], "pulse"
        return dataframe(cols, units)

    def aux_position(self, axis: int) -> np.ndarray:
        """Positions (pulse) of outside axis ``axis`` (1-based) per cycle."""
        return self.aux[:, self.aux_axes.index(axis)]

    def plot_xy(self, ax=None, *, title: str | None = None, cmap: str = "viridis", path: str | None = None,
                vmax: float | None = None):
        """Draws the XY path coloured by the path speed (unit/ms); returns the matplotlib Axes."""
        import matplotlib.pyplot as plt
        from matplotlib.collections import LineCollection

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 5))
        xy = self.pos[:, :2]
        seg = np.stack([xy[:-1], xy[1:]], axis=1)
        lc = LineCollection(seg, cmap=cmap)
        lc.set_array(0.5 * (self.speed[:-1] + self.speed[1:]))
        if vmax is not None:
            lc.set_clim(0, vmax)
        ax.add_collection(lc)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_xlabel("X [unit]")
        ax.set_ylabel("Y [unit]")
        ax.figure.colorbar(lc, ax=ax, label="path speed [unit/ms]")
        if title:
            ax.set_title(title)
        if path:
            ax.figure.savefig(path, dpi=120, bbox_inches="tight")
        return ax


def run_path(gen, *, max_ticks: int = 10**7, ticks: int | None = None) -> PathRun:
    """Steps ``gen`` (a :class:`PathGenerator` or a :class:`CrdFifoPair`) until it is done (path finished and outside axes at rest; at most ``max_ticks`` cycles),
    or exactly ``ticks`` cycles if given, and returns the :class:`PathRun`. The GIL is released while stepping."""
    _checks.has("run_path", "gen", gen, "record")
    d = gen.record(ticks if ticks is not None else max_ticks, until_done=ticks is None)
    return PathRun(t_ms=d["t_ms"], pos=d["pos"], axis_pos=d["axis_pos"], speed=d["speed"], acc=d["acc"],
                   segments=d["segments"], gpo=d["gpo"], aux=d["aux"], axes=list(d["axes"]),
                   aux_axes=list(d["aux_axes"]))


@dataclass
class AdlinkRun(JsonResult):
    """A recorded ADLINK interpolation, one row per motion cycle: t_s (s), pos (n, len(axes)) axis positions in
    the axis-array order (pulse), speed (vector speed, pulse/s), moves_done (finished moves)."""

    t_s: np.ndarray
    pos: np.ndarray
    speed: np.ndarray
    moves_done: np.ndarray

    def __len__(self) -> int:
        return len(self.t_s)

    def to_dataframe(self):
        """One row per motion cycle: t_s (s), pos_0.. (axis positions in the axis-array order, pulse), speed
        (pulse/s), moves_done; units in ``df.attrs["units"]``."""
        cols = {"t_s": self.t_s}
        units = {"t_s": "s", "speed": "pulse/s"}
        pos = np.asarray(self.pos).reshape(len(self), -1)
        for i in range(pos.shape[1]):
            cols[f"pos_{i}"], units[f"pos_{i}"] = pos[:, i], "pulse"
        cols.update({"speed": self.speed, "moves_done": self.moves_done})
        return dataframe(cols, units)

    def __repr__(self) -> str:
        dur = self.t_s[-1] if len(self) else 0.0
        return f"AdlinkRun({len(self)} cycles, {dur:g} s, peak speed {self.speed.max() if len(self) else 0:g} pulse/s)"


def run_adlink(interp: AdlinkInterpolator, *, max_ticks: int = 10**7, ticks: int | None = None) -> AdlinkRun:
    """Steps the ADLINK interpolator until every move is done (at most ``max_ticks`` motion cycles), or exactly
    ``ticks`` cycles, and returns the :class:`AdlinkRun` (s, pulse, pulse/s). Moves are pushed with
    ``interp.push(kind, target=..., center=..., normal=..., angle_deg=..., dir=..., height=..., final_radius=...,
    relative=False, mode=BlendMode.BUFFERED, blend=0, vm=0, params=None)``; kind is one of line, arc2_ca,
    arc2_ce, arc3_ca, arc3_ce, spiral_ca, spiral_ce (ADLINK L2813-3150). The GIL is released while stepping."""
    _checks.has("run_adlink", "interp", interp, "record")
    d = interp.record(ticks if ticks is not None else max_ticks, until_done=ticks is None)
    return AdlinkRun(t_s=d["t_s"], pos=d["pos"], speed=d["speed"], moves_done=d["moves_done"])
