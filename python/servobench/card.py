"""The virtual motion-control card: 4 or 8 axes on one servo clock, staged and active registers, events and safety.

A :class:`Card` runs every axis one servo tick at a time (pulse, pulse/tick, pulse/tick^2 units, the GT manual's
"per sample time"). Each tick (docs/card.md): the axes whose ``update`` is pending commit their staged registers
together; safety looks at the inputs (e-stop, drive alarm, hard and soft limits, direction inhibit); each axis's
profile advances and its servo tick runs (law, filters, DAC, drive, plant, encoder); capture and breakpoints
look at the actual position; the following error is checked against its limit. Axes are numbered from 0 here;
the vendor dialects (:mod:`servobench.dialects.gt`) number them as their manuals do.

Quick use::

    import servobench as sb
    card = sb.Card(4, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870))
    card.axis_on(0)
    card.stage_acc(0, 0.1); card.stage_vel(0, 5); card.stage_pos(0, 10000)
    card.update(0b0001)                  # committed at the next tick
    run = card.run(5000)
    run[0].actual_pos                    # pulse, one sample per tick
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from . import _core
from ._core import CardCommandRefused, CardLimits
from .axis import SIGNAL_UNITS, Axis

__all__ = ["Card", "CardCommandRefused", "CardLimits", "CardRun", "CARD_EVENTS", "events_named"]

#: Names of the card's latched events, in bit order (bits 0-7 in the GT status-register order).
CARD_EVENTS: tuple[str, ...] = tuple(_core.CARD_EVENTS)

_CARD_UNITS = {"events": "bits", "moving": "bool", "servo_on": "bool", "prf_vel": "pulse/tick"}


def events_named(bits: int) -> list[str]:
    """The names of the events set in ``bits`` (a value of :meth:`Card.events` or the ``events`` signal)."""
    bits = int(bits)
    return [name for k, name in enumerate(CARD_EVENTS) if bits & (1 << k)]


@dataclass(frozen=True)
class AxisSignals:
    """The signals of one card axis over a run: one NumPy array per signal (see :data:`Card.SIGNALS`)."""

    signals: Mapping[str, np.ndarray]

    def __getattr__(self, name: str) -> np.ndarray:
        signals = object.__getattribute__(self, "signals")
        if name in signals:
            return signals[name]
        raise AttributeError(f"signal '{name}' was not recorded in this run (see Card.run(signals=...))")

    def __getitem__(self, name: str) -> np.ndarray:
        return self.signals[name]

    def __len__(self) -> int:
        return len(next(iter(self.signals.values()))) if self.signals else 0


@dataclass(frozen=True)
class CardRun:
    """What a :meth:`Card.run` recorded: ``run[i]`` is axis i's :class:`AxisSignals` (0-based)."""

    axes: Sequence[AxisSignals]
    servo_period_s: float

    def __getitem__(self, i: int) -> AxisSignals:
        return self.axes[i]

    def __len__(self) -> int:
        return len(self.axes[0]) if self.axes else 0

    def __repr__(self) -> str:
        n = len(self)
        names = ", ".join(self.axes[0].signals) if self.axes else ""
        return f"CardRun({len(self.axes)} axes x {n} ticks at Ts = {self.servo_period_s * 1e6:.6g} us; {names})"

    def to_array(self, signal: str) -> np.ndarray:
        """One signal of every axis as a 2-D array, shape (axes, ticks)."""
        return np.vstack([a[signal] for a in self.axes])


class Card:
    """The virtual card (C++ ``machine::Card``): a thin Python face.

    axes
        4 or 8 (axes built from the keyword parts, as :class:`~servobench.Axis` takes them: ``law``, ``drive``,
        ``plant``, ``encoder``, ``dac``, ``switches``, ``servo_period_s``, ``substeps``, ``filters``), or a list of
        4 or 8 :class:`~servobench.Axis` objects sharing one servo period.
    motion_cycle_ticks
        the motion cycle in servo ticks (1..1000; the GT's profile runs every servo tick: 1). Updates commit at
        a motion-cycle boundary.
    host_cycle_ticks
        the host cycle in servo ticks, a multiple of the motion cycle (recorded; ADLINK 2 ms).

    Staged registers (units per tick; committed by :meth:`update` at the next tick): ``stage_pos`` (pulse),
    ``stage_vel`` (pulse/tick), ``stage_acc``/``stage_macc`` (pulse/tick^2), ``stage_jerk`` (pulse/tick^3),
    ``stage_brk_cn`` (pulse), ``stage_pos_err`` (pulse), ``stage_law`` (GtServoLaw/ApsServoLaw),
    ``stage_smooth_stop``, ``stage_synch_pos``; read back with ``staged(i)`` and ``active(i)``.
    Immediate: ``set_mode(i, "t_curve"|"s_curve"|"jog")``, ``abrupt_stop``, ``zero_pos``, ``set_actual_pos``,
    ``axis_on``/``axis_off``, ``drive_reset``, ``set_closed_loop``, ``set_mtr_cmd`` (counts), ``set_auto_stop``,
    ``set_auto_update``, ``arm_breakpoint(i, "pos"|"neg"|"motion"|"home"|"none")``, ``arm_capture(i,
    "home"|"index"|"none")``, ``home(i, GtHome)``. Safety: ``set_limits(i, CardLimits(...))``,
    ``set_alarm_input``, ``set_alarm_enabled``, ``set_error_level`` (pulse), ``emergency_stop``.
    Refused commands raise :class:`CardCommandRefused` (a RuntimeError) and leave the state unchanged; the
    cause is ``last_fault``. Events: ``events(i)`` (bits, :func:`events_named`), ``clear_events(i, bits)``.
    """

    #: Signals :meth:`run` can record: the axis signals, the loop signals and the card's own.
    SIGNALS: tuple[str, ...] = (tuple(name for name, _u, _d in _core.TRACE_SIGNALS)
                                + tuple(name for name, _u, _d in _core.LOOP_SIGNALS) + tuple(_CARD_UNITS))

    def __init__(self, axes=4, *, motion_cycle_ticks: int = 1, host_cycle_ticks: int = 1, **axis_parts):
        if isinstance(axes, (int, np.integer)) and not isinstance(axes, bool):
            if int(axes) not in (4, 8):
                raise ValueError(f"Card.axes = {axes} must be 4 or 8 (the cards' axis counts)")
            self.axes = [Axis(**axis_parts) for _ in range(int(axes))]
        else:
            if axis_parts:
                raise TypeError("give either Axis objects or the parts to build them from, not both")
            self.axes = list(axes)
            for a in self.axes:
                if not isinstance(a, Axis):
                    raise TypeError(f"axes must be servobench.Axis objects, got {type(a).__name__}")
        self._card = _core.Card([a._axis for a in self.axes], float(motion_cycle_ticks), float(host_cycle_ticks))

    def __getattr__(self, name):
        return getattr(object.__getattribute__(self, "_card"), name)

    def __setattr__(self, name, value):
        if name == "emergency_stop":
            self._card.emergency_stop = bool(value)
        else:
            object.__setattr__(self, name, value)

    def __repr__(self) -> str:
        return (f"Card({self._card.axis_count} axes, Ts = {self._card.servo_period_s * 1e6:.6g} us, "
                f"tick {self._card.tick}, motion cycle {self._card.motion_cycle_ticks:g} ticks)")

    def __len__(self) -> int:
        return self._card.axis_count

    def run(self, ticks: int, *, signals=None) -> CardRun:
        """Runs ``ticks`` servo ticks of every axis and returns the recorded signals (default: ``time_s`` s,
        ``pos``/``actual_pos``/``error`` pulse, ``volts`` V, ``prf_vel`` pulse/tick, ``events`` bits, ``moving``,
        ``servo_on``). Releases the GIL."""
        rec = self._card.run(ticks, None if signals is None else list(signals))
        return CardRun(axes=[AxisSignals(signals=d) for d in rec], servo_period_s=self._card.servo_period_s)

    def run_until(self, predicate, max_ticks: int = 10**7, chunk: int = 1) -> int:
        """Runs ``chunk`` ticks at a time until ``predicate(card)`` is true (checked before each chunk), at most
        ``max_ticks``; returns the ticks run."""
        done = 0
        while done < max_ticks and not predicate(self):
            n = min(chunk, max_ticks - done)
            self._card.run(n, [])
            done += n
        return done

    def snapshot(self) -> dict:
        """The card's observable state now, for "a refused command leaves the state unchanged" checks: per axis
        the staged and active registers, pending update, mode, latched events (without the command-error bit 7,
        which a refusal sets by design), drive and loop state, profile and actual position (pulse), profile
        velocity (pulse/tick), limits, breakpoint, capture and stop cause; and the e-stop. Two snapshots
        compare with ``==``."""
        c = self._card
        axes = []
        for i in range(c.axis_count):
            staged, active = dict(c.staged(i)), dict(c.active(i))
            staged["law"], active["law"] = repr(staged["law"]), repr(active["law"])
            axes.append({
                "staged": staged, "active": active, "update_pending": c.update_pending(i),
                "staged_changes": c.staged_changes(i), "mode": c.mode(i), "events": c.events(i) & ~(1 << 7),
                "servo_on": c.servo_on(i), "closed_loop": c.closed_loop(i), "moving": c.moving(i),
                "profile_pos": c.profile_pos(i), "profile_vel": c.profile_vel(i), "actual_pos": c.actual_pos(i),
                "limits": repr(c.limits(i)), "auto_stop": c.auto_stop(i), "auto_update": c.auto_update(i),
                "mtr_cmd": c.mtr_cmd(i), "error_level": c.error_level(i), "breakpoint": c.breakpoint_armed(i),
                "capture": c.capture_value(i), "stop_cause": c.stop_cause(i),
                "status_bits": _core.gt_axis_status(c, i) & ~(1 << 7)})
        return {"tick": c.tick, "emergency_stop": c.emergency_stop, "axes": axes}

    @staticmethod
    def units(signal: str) -> str:
        """Unit of a recorded signal."""
        from .homing import LOOP_SIGNAL_UNITS

        return SIGNAL_UNITS.get(signal) or LOOP_SIGNAL_UNITS.get(signal) or _CARD_UNITS[signal]
