"""Figures of merit of a point-to-point move."""

from __future__ import annotations

__all__ = ["MoveMetrics", "move_metrics"]

from dataclasses import dataclass, asdict

import numpy as np

from . import _checks
from ._serialise import JsonResult, dataframe


@dataclass(frozen=True)
class MoveMetrics(JsonResult):
    """Step/move figures of merit, read from a recorded run.

    rise_time_s
        time for the feedback to go from 10 % to 90 % of the move distance (s).
    overshoot_pulse, overshoot_pct
        largest excursion of the feedback beyond the target, in pulse and in % of the distance (>= 0).
    settling_time_s
        time from the end of the command until the feedback enters, and stays inside, target +- band (s);
        NaN if it never settles within the record.
    peak_following_error_pulse
        largest ``|cmd_pos - fb_pos|`` over the whole run (pulse).
    final_error_pulse
        cmd_pos - fb_pos at the last tick (pulse).
    settle_band_pulse
        the band used for the settling time (pulse).
    """

    distance_pulse: float
    rise_time_s: float
    overshoot_pulse: float
    overshoot_pct: float
    settling_time_s: float
    peak_following_error_pulse: float
    final_error_pulse: float
    settle_band_pulse: float

    def to_dict(self) -> dict:
        return asdict(self)

    def __str__(self) -> str:
        return (f"move {self.distance_pulse:g} pulse: rise time {self.rise_time_s * 1e3:.3f} ms, "
                f"overshoot {self.overshoot_pulse:.3g} pulse ({self.overshoot_pct:.3g} %), "
                f"settling time {self.settling_time_s * 1e3:.3f} ms (band +-{self.settle_band_pulse:g} pulse), "
                f"peak following error {self.peak_following_error_pulse:.4g} pulse, "
                f"final error {self.final_error_pulse:.4g} pulse")


def move_metrics(run, *, settle_band_pulse: float = 5.0) -> MoveMetrics:
    """Figures of merit of a move recorded by :meth:`Axis.run` (needs time_s, cmd_pos and fb_pos).

    settle_band_pulse: the in-position band for the settling time, pulse (> 0).
    """
    _checks.has("move_metrics", "run", run, "time_s")
    if not np.isfinite(settle_band_pulse) or settle_band_pulse <= 0:
        raise ValueError(f"settle_band_pulse = {settle_band_pulse} must be a finite number > 0 (pulse)")
    t = np.asarray(run.time_s, dtype=float)
    cmd = np.asarray(run.cmd_pos, dtype=float)
    fb = np.asarray(run.fb_pos, dtype=float)
    if len(t) < 2:
        raise ValueError("move_metrics needs a run of at least 2 ticks")
    start, target = cmd[0], cmd[-1]
    distance = target - start
    if distance == 0:
        raise ValueError("move_metrics: the command does not move (cmd_pos[0] == cmd_pos[-1])")
    sgn = np.sign(distance)
    progress = (fb - start) / distance  # 0 at start, 1 at target

    def first_crossing(level: float) -> float:
        idx = np.flatnonzero(progress >= level)
        return t[idx[0]] if idx.size else np.nan

    rise = first_crossing(0.9) - first_crossing(0.1)
    over = max(0.0, float(np.max((fb - target) * sgn)))
    moving = np.flatnonzero(cmd != target)
    t_end_index = moving[-1] + 1 if moving.size else 0
    outside = np.flatnonzero(np.abs(fb[t_end_index:] - target) > settle_band_pulse)
    if outside.size == 0:
        settling = 0.0
    elif outside[-1] + t_end_index == len(t) - 1:
        settling = np.nan
    else:
        settling = t[t_end_index + outside[-1] + 1] - t[t_end_index]
    err = cmd - fb
    return MoveMetrics(
        distance_pulse=float(distance),
        rise_time_s=float(rise),
        overshoot_pulse=over,
        overshoot_pct=100.0 * over / abs(distance),
        settling_time_s=float(settling),
        peak_following_error_pulse=float(np.max(np.abs(err))),
        final_error_pulse=float(err[-1]),
        settle_band_pulse=float(settle_band_pulse),
    )
