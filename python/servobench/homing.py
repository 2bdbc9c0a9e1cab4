"""Homing, capture, breakpoints and the ADLINK jog: motion that reacts to the simulated mechanism.

A :class:`MotionLoop` couples a profile generator to an :class:`~servobench.Axis` and runs them tick by tick:
each tick the active sequence (homing or jog) reacts to what the switches, the index mark and the encoder
did during the previous tick, the generator advances, the axis runs one servo tick, and the capture register
and the breakpoint look at the result. Units: positions in pulse (the card's coordinates, which a homing
resets), ADLINK speeds in pulse/s and pulse/s^2, GT speeds per servo tick (pulse/ST, pulse/ST^2).

Parameter sets:

* :class:`AdlinkHome` -- ADLINK ``APS_home_move`` modes 0 (ORG), 1 (EL), 2 (single EZ) with direction, EZ
  alignment, shift and the final position (ADLINK manual L2246-2556).
* :class:`GtHome` -- GT ``GT_Home(pos)`` + ``GT_Index`` (GT manual L4152-4213).
* :class:`AdlinkJog` -- ADLINK jog, continuous or step mode (ADLINK manual L2639-2710).

The switches are placed on the axis with :class:`~servobench.Switches` (load angle, rad) and the index mark
with ``Encoder(index_angle_rad=...)``; :func:`pulse_to_rad` converts positions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import _core
from ._core import AdlinkHome, AdlinkJog, GtHome
from ._serialise import JsonResult
from .axis import SIGNAL_UNITS, Axis, AxisRun

__all__ = ["AdlinkHome", "AdlinkJog", "GtHome", "HomingResult", "LOOP_SIGNAL_UNITS", "LoopRun", "MotionLoop",
           "home", "pulse_to_rad"]

#: Unit of each signal the loop records besides the axis signals.
LOOP_SIGNAL_UNITS: dict[str, str] = {name: unit for name, unit, _doc in _core.LOOP_SIGNALS}

#: Homing phase codes recorded in the ``phase`` signal during a homing.
HOME_PHASES = ("idle", "search", "search_reverse", "stop_after_find", "leave", "stop_after_leave", "approach",
               "stop_before_ez", "align_ez", "stop_at_edge", "move_to_edge", "done", "failed")
#: Jog phase codes recorded in the ``phase`` signal while a jog is installed.
JOG_PHASES = ("idle", "moving", "step", "delay", "continuous", "rounding")


def pulse_to_rad(pulse: float, counts_per_rev: float = 10000.0) -> float:
    """Converts a position in pulse (encoder counts) to the shaft angle in rad (2*pi per ``counts_per_rev``)."""
    return float(pulse) * 2.0 * math.pi / float(counts_per_rev)


@dataclass(frozen=True)
class LoopRun(AxisRun):
    """What a :class:`MotionLoop` recorded: the axis signals of :class:`~servobench.AxisRun` (raw encoder
    counts) plus the loop's own, in the card's coordinates: ``pos`` (command, pulse), ``actual_pos``
    (pulse), ``offset`` (raw - card, pulse), ``phase`` (sequence phase code, see :data:`HOME_PHASES`,
    :data:`JOG_PHASES`), ``captured`` and ``breakpoint`` (0/1 flags, GT status bits 3 and 2)."""

    @property
    def units(self) -> dict[str, str]:
        """Unit of each recorded signal."""
        return {k: SIGNAL_UNITS.get(k, LOOP_SIGNAL_UNITS.get(k, "")) for k in self.signals}

    def __getattr__(self, name: str) -> np.ndarray:
        signals = object.__getattribute__(self, "signals")
        if name in signals:
            return signals[name]
        if name in SIGNAL_UNITS or name in LOOP_SIGNAL_UNITS:
            raise AttributeError(f"signal '{name}' was not recorded in this run")
        raise AttributeError(name)


class MotionLoop:
    """A profile generator driving an :class:`~servobench.Axis` tick by tick, reacting to its switches, index
    mark and encoder: homing, capture, GT breakpoints with auto-update, and the ADLINK jog.

    Thread safety: like its Axis, a MotionLoop runs one :meth:`run` at a time (a second thread's run, or a run of
    its Axis, waits); every other call waits for the running chunk (about 20 ms of work). Ctrl-C during a run
    raises KeyboardInterrupt within a chunk, the loop standing at the last whole tick.

    Commands (``command``: the card's Set* + Update, immediate): :class:`~servobench.GtTCurve`,
    :class:`~servobench.GtSCurve`, :class:`~servobench.GtJog`, the GE sets and :class:`~servobench.AdlinkPtp`
    (on the fly where the manuals allow it). ``stage(params)`` / ``stage_smooth_stop()`` hold a
    double-buffered command until :meth:`update` or a breakpoint fires with ``auto_update = True``
    (GT L1150-1263).

    Capture (GT L2013-2150): ``capt_home()``, ``capt_index()``, ``capt_probe(at_s)`` arm one capture of the actual
    position (pulse) at the home switch turning on, the index mark, or the probe instant (s); ``captured``,
    ``capture_value``, ``capture_source``; ``clear_status()`` clears the captured and breakpoint flags.

    Breakpoints (GT L1239-1397): ``set_brk_cn(pulse)``, then ``pos_brk()`` (actual >= BrkCn), ``neg_brk()``
    (actual <= BrkCn), ``mtn_brk()`` (motion complete), ``ext_brk()`` (home captured); one-shot; ``brk_off()``.

    Homing: :meth:`home` with :class:`AdlinkHome` or :class:`GtHome`; jog: :meth:`jog` with :class:`AdlinkJog`,
    then set ``jog_on``. ``run(ticks)`` and ``run_until_done(max_ticks)`` return a :class:`LoopRun`.
    """

    def __init__(self, axis: Axis):
        if not isinstance(axis, Axis):
            raise TypeError(f"axis must be a servobench.Axis, got {type(axis).__name__}")
        self.axis = axis
        self._loop = _core.MotionLoop(axis._axis)

    def __getattr__(self, name):
        return getattr(object.__getattribute__(self, "_loop"), name)

    def __setattr__(self, name, value):
        if name in ("auto_update", "jog_on"):
            setattr(self._loop, name, value)
        else:
            object.__setattr__(self, name, value)

    def __repr__(self) -> str:
        return (f"MotionLoop(pos={self._loop.pos} pulse, actual_pos={self._loop.actual_pos:g} pulse, "
                f"mode={self._loop.mode}, moving={self._loop.moving}, home_phase={self._loop.home_phase}, "
                f"captured={self._loop.captured})")

    def run(self, ticks: int, *, signals=None) -> LoopRun:
        """Runs ``ticks`` servo ticks; records the axis and loop signals (all by default). Releases the GIL."""
        rec = self._loop.run(ticks, None if signals is None else list(signals))
        return LoopRun(signals=rec, servo_period_s=self.axis.servo_period_s, law=self.axis.law)

    def run_until_done(self, max_ticks: int = 10**7, *, signals=None) -> LoopRun:
        """Runs until the homing or jog sequence ends (or, with none, the motion completes), at most
        ``max_ticks`` ticks."""
        rec = self._loop.run_until_done(max_ticks, None if signals is None else list(signals))
        return LoopRun(signals=rec, servo_period_s=self.axis.servo_period_s, law=self.axis.law)


@dataclass(frozen=True)
class HomingResult(JsonResult):
    """The outcome of :func:`home`: ``done`` (bool), ``error_code`` (ADLINK stop code 4 PEL / 5 MEL, GT example
    return 1 no home / 2 no index, else 0), ``reference_pulse`` (the captured edge or index, pulse, in the
    coordinates before the reset), ``offset_pulse`` (raw encoder count - card position after homing),
    ``ticks`` and the recorded ``run`` (:class:`LoopRun`); ``loop`` to continue from there (None in a result read
    back by :meth:`from_json`: the live loop is not data)."""

    done: bool
    error_code: int
    reference_pulse: float | None
    offset_pulse: float
    ticks: int
    run: LoopRun
    loop: MotionLoop | None = field(default=None, repr=False, compare=False, metadata={"json": False})

    def to_dataframe(self):
        """The recorded run as a pandas DataFrame (:meth:`LoopRun.to_dataframe`: one row per tick, units in
        ``df.attrs["units"]``). The outcome's figures are fields; :meth:`to_json` writes them and the run, not the
        live ``loop`` (decision W24)."""
        return self.run.to_dataframe()


def home(axis: Axis, params, *, max_ticks: int = 10**7, signals=None) -> HomingResult:
    """Homes ``axis`` with :class:`AdlinkHome` (ADLINK modes 0/1/2) or :class:`GtHome` (GT_Home/GT_Index) and
    returns a :class:`HomingResult`. ``max_ticks`` bounds the run (servo ticks)."""
    loop = MotionLoop(axis)
    loop.home(params)
    run = loop.run_until_done(max_ticks, signals=signals)
    return HomingResult(done=loop.home_phase == "done", error_code=loop.home_error_code,
                        reference_pulse=loop.home_reference, offset_pulse=loop.offset, ticks=len(run), run=run,
                        loop=loop)
