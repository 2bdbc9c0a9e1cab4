"""Single-axis motion generators with the manuals' semantics: T-curve, S-curve, jog, stops.

Parameter sets carry the manual's units:

* ``GtTCurve``, ``GtSCurve``, ``GtJog``: Googol GT, per servo sample time ST (= the tick): pulse, pulse/ST,
  pulse/ST^2, pulse/ST^3 (GT manual L854-858).
* ``GeTCurve``, ``GeSCurve``, ``GeJog``: Googol GE / GUC-ECAT / iDEABOX, pulse/ms, pulse/ms^2, pulse/ms^3
  (GE manual L991-996); converted with the tick ``period_s``.
* ``AdlinkPtp``: ADLINK PCI-8254/8258, pulse/s and pulse/s^2 with an S-factor (ADLINK manual L2176-2244).

``ProfileGenerator`` is stepped once per tick (``step()`` or ``run(ticks)``) and accepts commands during
motion exactly where the manuals allow them. The functions below sample a whole move into a
:class:`~servobench.Trajectory` (positions in whole pulses, as the card reports them, unless
``whole_pulses=False``), ready for ``Axis.run``.
"""

from __future__ import annotations

import numpy as np

from . import _core
from ._core import (
    AdlinkPtp,
    ElectronicGear,
    GtGear,
    GeJog,
    GeSCurve,
    GeTCurve,
    GtJog,
    GtSCurve,
    GtTCurve,
    MotionCommandRefused,
    ProfileGenerator,
    plan_s_curve_batch,
    plan_s_curve_replan_batch,
    s_curve_min_time,
    t_curve_min_time,
)
from .trajectory import Trajectory

__all__ = [
    "AdlinkPtp", "ElectronicGear", "GtGear", "GeJog", "GeSCurve", "GeTCurve", "GtJog", "GtSCurve", "GtTCurve", "MotionCommandRefused",
    "ProfileGenerator", "jog_trajectory", "move_trajectory", "plan_s_curve_batch", "plan_s_curve_replan_batch",
    "s_curve_min_time",
    "t_curve_min_time", "trajectory_from_samples",
]

_GT = (GtTCurve, GtSCurve, GtJog)


def _period(params, period_s):
    if period_s is not None:
        return float(period_s)
    if isinstance(params, _GT):
        return 200e-6  # GT default sample time (GT_SetSmplTm, GT L578-580); GT units are per tick anyway
    raise ValueError(f"{type(params).__name__}: period_s (the tick in seconds) is required to convert the "
                     "manual's per-ms / per-s units to ticks")


def trajectory_from_samples(samples: dict, *, whole_pulses: bool = True) -> Trajectory:
    """Builds a :class:`Trajectory` from the dict returned by ``ProfileGenerator.run``: pos in pulse (whole
    pulses if ``whole_pulses``, else the fractional profile position), vel pulse/tick, acc pulse/tick^2,
    jerk pulse/tick^3."""
    pos = samples["pos"] if whole_pulses else samples["pos_exact"]
    return Trajectory(pos=np.asarray(pos), vel=np.asarray(samples["vel"]), acc=np.asarray(samples["acc"]),
                      jerk=np.asarray(samples["jerk"]))


def move_trajectory(params, *, period_s: float | None = None, start_pos: float = 0.0, dwell_before: int = 0,
                    dwell_after: int = 0, whole_pulses: bool = True, max_ticks: int = 10**8) -> Trajectory:
    """A point-to-point move (``GtTCurve``, ``GtSCurve``, ``GeTCurve``, ``GeSCurve`` or ``AdlinkPtp``) from rest
    at ``start_pos`` (pulse), sampled once per tick of ``period_s`` seconds (required for GE and ADLINK units;
    GT defaults to 200 us). Sample 0 is the start; the move ends on the tick after the profile's end, held for
    ``dwell_after`` ticks, preceded by ``dwell_before`` ticks at rest. Units: pulse, pulse/tick, pulse/tick^2,
    pulse/tick^3."""
    if isinstance(params, (GtJog, GeJog)):
        raise ValueError("move_trajectory: a jog never ends; use jog_trajectory(params, ticks=...)")
    gen = ProfileGenerator(start_pos=start_pos, period_s=_period(params, period_s))
    gen.command(params)
    s0 = gen.state
    body = gen.run_until_done(max_ticks)
    after = gen.run(dwell_after)
    return _assemble(s0, [body, after], dwell_before, whole_pulses)


def jog_trajectory(params, *, ticks: int, period_s: float | None = None, start_pos: float = 0.0,
                   whole_pulses: bool = True) -> Trajectory:
    """A jog (``GtJog`` or ``GeJog``) from rest at ``start_pos`` for ``ticks`` ticks (``ticks + 1`` samples,
    sample 0 the start). Units: pulse, pulse/tick, pulse/tick^2."""
    gen = ProfileGenerator(start_pos=start_pos, period_s=_period(params, period_s))
    gen.command(params)
    s0 = gen.state
    return _assemble(s0, [gen.run(ticks)], 0, whole_pulses)


def _assemble(s0, parts, dwell_before, whole_pulses):
    """Sample 0 (state s0, preceded by dwell_before copies at rest) followed by the stepped parts."""
    key = "pos" if whole_pulses else "pos_exact"
    p0 = float(np.round(s0[0])) if whole_pulses else s0[0]
    pre = dwell_before
    pos = np.concatenate([np.full(pre + 1, p0)] + [np.asarray(p[key]) for p in parts])
    pre_zero = np.zeros(pre)
    vel = np.concatenate([pre_zero, [s0[1]]] + [np.asarray(p["vel"]) for p in parts])
    acc = np.concatenate([pre_zero, [s0[2]]] + [np.asarray(p["acc"]) for p in parts])
    jerk = np.concatenate([pre_zero, [s0[3]]] + [np.asarray(p["jerk"]) for p in parts])
    return Trajectory(pos=pos, vel=vel, acc=acc, jerk=jerk)
