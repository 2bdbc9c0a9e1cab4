"""Command trajectories sampled at the servo ticks."""

from __future__ import annotations

__all__ = ["Trajectory", "trapezoid_move"]

from dataclasses import dataclass
from typing import Optional

import numpy as np

from . import _core
from ._serialise import JsonResult, dataframe


@dataclass(frozen=True)
class Trajectory(JsonResult):
    """A command sampled once per servo tick: position (pulse), velocity (pulse/tick), acceleration
    (pulse/tick^2), as NumPy arrays of equal length; optionally the jerk (pulse/tick^3) for the motion
    generators' trajectories."""

    pos: np.ndarray
    vel: np.ndarray
    acc: np.ndarray
    jerk: Optional[np.ndarray] = None

    def __post_init__(self):
        n = len(self.pos)
        if len(self.vel) != n or len(self.acc) != n or (self.jerk is not None and len(self.jerk) != n):
            raise ValueError(f"Trajectory: pos, vel and acc must have equal lengths, got {n}, {len(self.vel)}, "
                             f"{len(self.acc)}")

    def __len__(self) -> int:
        return len(self.pos)

    def to_dataframe(self):
        """The command as a pandas DataFrame, one row per servo tick (index ``tick``): ``pos_pulse``,
        ``vel_pulse_per_tick``, ``acc_pulse_per_tick2`` and, when present, ``jerk_pulse_per_tick3``;
        ``df.attrs["units"]`` repeats the units."""
        cols = {"pos_pulse": self.pos, "vel_pulse_per_tick": self.vel, "acc_pulse_per_tick2": self.acc}
        if self.jerk is not None:
            cols["jerk_pulse_per_tick3"] = self.jerk
        df = dataframe(cols, {"pos_pulse": "pulse", "vel_pulse_per_tick": "pulse/tick",
                              "acc_pulse_per_tick2": "pulse/tick^2", "jerk_pulse_per_tick3": "pulse/tick^3"})
        df.index.name = "tick"
        return df

    def __repr__(self) -> str:
        return (f"Trajectory({len(self)} ticks, {self.pos[0]:.6g} -> {self.pos[-1]:.6g} pulse, "
                f"peak vel {np.max(np.abs(self.vel)):.6g} pulse/tick)")


def trapezoid_move(*, distance_pulse: float, vel_pulse_per_tick: float, acc_pulse_per_tick2: float,
                   start_pulse: float = 0.0, dwell_before: int = 0, dwell_after: int = 0) -> Trajectory:
    """A trapezoidal point-to-point move sampled at the ticks (triangular if `vel` is not reached).

    distance_pulse: signed move length, pulse. vel_pulse_per_tick > 0: cruise velocity, pulse/tick.
    acc_pulse_per_tick2 > 0: acceleration and deceleration, pulse/tick^2. start_pulse: initial position,
    pulse. dwell_before / dwell_after: ticks at rest before and after the move. The last sample of the move is
    exactly start + distance; positions are fractional in between (the manuals' T-curve generators with
    integer semantics are a separate feature).
    """
    pos, vel, acc = _core.trapezoid_move(start_pulse=start_pulse, distance_pulse=distance_pulse,
                                         vel_pulse_per_tick=vel_pulse_per_tick,
                                         acc_pulse_per_tick2=acc_pulse_per_tick2, dwell_before=dwell_before,
                                         dwell_after=dwell_after)
    return Trajectory(pos=pos, vel=vel, acc=acc)
