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

from . import _checks
from . import _core
from ._core import CardCommandRefused, CardLimits
from ._serialise import JsonResult, dataframe
from .axis import SIGNAL_UNITS, Axis

__all__ = ["AxisSignals",
           "Card", "CardCommandRefused", "CardLimits", "CardRun", "CARD_EVENTS", "events_named", "FiredEvent",
           "SAMPLE_SIGNALS", "ScopeData"]

#: Names of the card's latched events, in bit order (bits 0-7 in the GT status-register order).
CARD_EVENTS: tuple[str, ...] = tuple(_core.CARD_EVENTS)

_CARD_UNITS = {"events": "bits", "moving": "bool", "servo_on": "bool", "prf_vel": "pulse/tick"}


def events_named(bits: int) -> list[str]:
    """The names of the events set in ``bits`` (a value of :meth:`Card.events` or the ``events`` signal)."""
    bits = int(_checks.real("events_named", "bits", bits, 0, 2**32 - 1))
    return [name for k, name in enumerate(CARD_EVENTS) if bits & (1 << k)]


def _signal_unit(signal: str) -> str:
    """Unit of a signal a card run records (the Axis trace's, the motion loop's, the card's own); "" if unknown."""
    from .homing import LOOP_SIGNAL_UNITS

    return SIGNAL_UNITS.get(signal) or LOOP_SIGNAL_UNITS.get(signal) or _CARD_UNITS.get(signal, "")


@dataclass(frozen=True)
class AxisSignals(JsonResult):
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

    def to_dataframe(self):
        """The signals as a pandas DataFrame, one row per tick (index ``tick``), one column per signal named as
        recorded (``actual_pos``, ``volts``, ...); ``df.attrs["units"]`` gives each column's unit (pulse, V, ...)."""
        df = dataframe(dict(self.signals), {k: _signal_unit(k) for k in self.signals})
        df.index.name = "tick"
        return df


@dataclass(frozen=True)
class CardRun(JsonResult):
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

    def to_dataframe(self):
        """Every axis's signals in long form: one row per (axis, tick), columns ``axis`` (0-based), ``tick``,
        ``time_s`` (tick x servo period, s) and one per signal named as recorded; ``df.attrs["units"]`` gives each
        column's unit. ``df[df.axis == 1]`` is axis 1's run; ``df.pivot(index="tick", columns="axis",
        values="actual_pos")`` puts the axes side by side. :meth:`to_json` writes the run as standard JSON."""
        import pandas as pd

        n = len(self)
        ticks = np.arange(n)
        frames = []
        for k, a in enumerate(self.axes):
            frames.append(dataframe({"axis": np.full(n, k), "tick": ticks, "time_s": ticks * self.servo_period_s,
                                     **{s: np.asarray(v) for s, v in a.signals.items()}}))
        df = pd.concat(frames, ignore_index=True) if frames else dataframe({"axis": [], "tick": [], "time_s": []})
        names = list(self.axes[0].signals) if self.axes else []
        df.attrs["units"] = {"axis": "", "tick": "servo tick", "time_s": "s", **{k: _signal_unit(k) for k in names}}
        return df


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

    Thread safety: a Card may be shared between threads. One run at a time (:meth:`run`,
    ``run_until_event``; a second thread's run waits until the first has finished; the card's axes are locked
    with it). Every other call (commands, status reads, the scope: ``sampler_pop_block``, ``sampler_snapshot``,
    ...) runs between two chunks of the running card (about 20 ms of work each), as a host talks to a running
    card. Ctrl-C during a run raises KeyboardInterrupt within a chunk; the card stands at the last whole tick.
    A run may record at most 2 GB (ticks x axes x signals x 8 bytes), checked before allocating.
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
            if not isinstance(axes, (list, tuple)):
                raise TypeError(f"Card.axes must be 4 or 8, or a list of Axis objects, got {type(axes).__name__}")
            self.axes = list(axes)
            for a in self.axes:
                if not isinstance(a, Axis):
                    raise TypeError(f"axes must be servobench.Axis objects, got {type(a).__name__}")
        self._card = _core.Card([a._axis for a in self.axes], float(motion_cycle_ticks), float(host_cycle_ticks))
        self._bind_step()

    def _bind_step(self) -> None:
        # Without Python callbacks, card.step is the binding itself: one dispatch per call (decisions FV10, FV25);
        # with them (on_event), the method below, which stops where an event fires.
        if type(self).step is Card.step and not self._subs:
            object.__setattr__(self, "step", self._card.step)
        else:
            self.__dict__.pop("step", None)

    @property
    def kernel(self):
        """The C++ card kernel (``servobench._core.Card``, 0-based axes, card units) this wrapper drives: what the
        vendor status words and the dialects read (``_core.gt_axis_status(card.kernel, 0)``)."""
        return object.__getattribute__(self, "_card")

    def __getattr__(self, name):
        card = object.__getattribute__(self, "_card")
        value = getattr(card, name)
        if getattr(value, "__self__", None) is card:  # a method of the C++ card: kept, so the next call finds it
            object.__setattr__(self, name, value)     # directly (1.5 -> 0.35 us a call; decision FV10); never a value
        return value

    def __setattr__(self, name, value):
        if name == "emergency_stop":
            self._card.emergency_stop = _checks.flag("Card", "emergency_stop", value)
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
        if self._subs:  # Python callbacks (on_event): the run stops where an event fires (issue 10.3)
            return self._run_with_callbacks(ticks, signals)
        rec = self._card.run(ticks, None if signals is None else list(signals))
        return CardRun(axes=[AxisSignals(signals=d) for d in rec], servo_period_s=self._card.servo_period_s)

    # -- time modes (issue 25.1; docs/card.md "Time on the card"; servobench.card_clock) ---------------------------
    _clock = None  # the attached CardClock (None: step mode, nothing attached)

    @property
    def clock(self):
        """The :class:`~servobench.card_clock.CardClock` attached by :meth:`set_clock` (None: none attached, the
        step mode)."""
        return self._clock

    def set_clock(self, mode="step", **options):
        """Sets how time flows while a program talks to the card and returns the attached
        :class:`~servobench.card_clock.CardClock` (a context manager: leaving the block closes it). ``mode``:
        ``"step"`` (explicit :meth:`run`/:meth:`step`, the default), ``"program"`` (each vendor call advances the
        card by its bus time, a ``delay``/``Sleep`` by its argument), ``"realtime"`` (a background thread ticks the
        card at ``speed`` x real time), or a :class:`~servobench.card_clock.ClockOptions`; ``options`` are the
        ClockOptions fields (``call_cost_us``, ``call_costs_us``, ``speed``, ``period_ms``). A clock already
        attached is closed first (its thread joined)."""
        from .card_clock import CardClock, ClockOptions

        if isinstance(mode, ClockOptions):
            if options:
                raise TypeError("Card.set_clock: give a ClockOptions or the option keywords, not both")
            opts = mode
        else:
            opts = ClockOptions(mode=mode, **options)
        if self._clock is not None:
            self._clock.close()
        clock = CardClock(self, opts)
        object.__setattr__(self, "_clock", clock)
        return clock

    def step(self, n: int = 1) -> int:
        """Advances ``n`` servo ticks of every axis recording nothing, and returns the card's tick count: the step
        API for a program in the loop, which reads and writes the card (its registers, positions, the dialects)
        between calls. Event callbacks fire as in :meth:`run`. A one-tick call costs under a microsecond above the
        card's tick (``bench/results/batch.md``); from 256 ticks on, a step is a run: it releases the GIL, waits for
        another thread's run of this card and answers Ctrl-C between chunks of about 20 ms. ``n``: 0..1e9 ticks."""
        if self._subs:
            self._run_with_callbacks(n, ())
            return self._card.tick
        return self._card.step(n)  # what the binding does (checks, locks, ticks: decision FV10)

    def run_until(self, predicate, max_ticks: int = 10**7, chunk: int = 1) -> int:
        """Runs ``chunk`` ticks at a time until ``predicate(card)`` is true (checked before each chunk), at most
        ``max_ticks``; returns the ticks run."""
        done = 0
        while done < max_ticks and not predicate(self):
            n = min(chunk, max_ticks - done)
            if self._subs:  # Python callbacks (on_event, issue 10.3)
                self._run_with_callbacks(n, ())
            else:
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

        if not isinstance(signal, str) or not (signal in SIGNAL_UNITS or signal in LOOP_SIGNAL_UNITS
                                               or signal in _CARD_UNITS):
            raise ValueError(f"Card.units.signal = {signal!r} is not a signal; the signals are {Card.SIGNALS}")
        return SIGNAL_UNITS.get(signal) or LOOP_SIGNAL_UNITS.get(signal) or _CARD_UNITS[signal]

    # -- scope, events, compare, probe (issue 10 point 3; docs/card.md "Scope, events, compare") ----------------
    _subs: tuple = ()  # (id, _Subscription) of on_event, in registration order

    def sample(self, channels, *, every_ticks: int = 1, depth: int = 1000, trigger: str = "immediate",
               level: float = 0.0, trigger_channel: int = 0, event_axis: int = 0, events=("motion_complete",),
               pretrigger: int = 0, continuous: bool = False) -> None:
        """Starts the card's sampler (the tuning workbench's scope) from the next tick.

        channels
            a list of ``(axis, signal)`` (axis 0-based; for ``trg_pulses``/``trg_level`` the trigger output 0..3),
            1..16 of them; the signals are :data:`SAMPLE_SIGNALS` (the Axis trace, the loop's, the card's own).
        every_ticks
            one sample every N servo ticks (1..1e6); ``depth`` samples per block (1..1e7).
        trigger
            ``"immediate"``; ``"rising"``/``"falling"``: channel ``trigger_channel`` crossing ``level`` between two
            samples; ``"event"``: one of ``events`` (CARD_EVENTS names) latching on ``event_axis``.
        pretrigger
            samples kept before the trigger sample (0..depth-1); the trigger counts once they are there.
        continuous
            after a full block start the next one at once (the GE watch); otherwise one block (one-shot).

        Read the result with :meth:`scope_data`; :meth:`capture_scope` starts, runs and reads in one call."""
        mask = _event_mask(events, "events") if trigger == "event" else 1
        chans = [(float(a), str(sig)) for a, sig in channels]
        self._card.sampler_start(chans, float(every_ticks), float(depth), str(trigger), float(trigger_channel),
                                 float(level), float(event_axis), float(mask), float(pretrigger),
                                 _checks.flag("Card.sample", "continuous", continuous))
        object.__setattr__(self, "_scope_channels", tuple((int(a), s) for a, s in chans))

    @property
    def sampler_state(self) -> str:
        """``"idle"``, ``"armed"`` (waiting for the pre-trigger samples or the trigger), ``"filling"``, ``"done"``."""
        return self._card.sampler_state

    def scope_data(self, *, partial: bool = False):
        """The oldest finished block as :class:`ScopeData` (None if none is ready); ``partial=True`` returns what
        the sampler holds now instead (pre-trigger samples or the block being filled)."""
        got = self._card.sampler_snapshot() if partial else self._card.sampler_pop_block()
        if got is None:
            return None
        ticks, values, trig = got
        return ScopeData(ticks=np.asarray(ticks), values=np.asarray(values),
                         channels=getattr(self, "_scope_channels", ()), servo_period_s=self._card.servo_period_s,
                         trigger_tick=int(trig))

    def capture_scope(self, channels, *, max_ticks: int = 10**7, **options):
        """Starts the sampler (:meth:`sample` options), runs the card until the block is full (at most
        ``max_ticks``) and returns the :class:`ScopeData`; raises RuntimeError if the block did not fill."""
        self.sample(channels, **options)
        done = self.run_until(lambda c: c._card.sampler_blocks > 0, max_ticks=max_ticks,
                              chunk=max(1, int(options.get("every_ticks", 1))))
        data = self.scope_data()
        if data is None:
            raise RuntimeError(f"capture_scope: the block did not fill in {done} ticks "
                               f"(sampler {self._card.sampler_state}, {self._card.sampler_filled} samples)")
        return data

    def on_event(self, callback, *, axis=None, events=(), msts: int = 0, mio: int = 0, system: int = 0,
                 timer_ticks: int = 0) -> int:
        """Calls ``callback(card, fired)`` (a :class:`FiredEvent`) from :meth:`run` at the tick an event fires:
        ``events`` (CARD_EVENTS names) latching on ``axis`` (None: every axis), bits of the ADLINK motion status
        (``msts``) or motion I/O (``mio``) words turning on, the system word (bit 0 EMG, 1/2 linear compare 0/1
        ended, 3/4 table compare 0/1 ended) or a timer every ``timer_ticks`` ticks. The C++ run stops after that
        tick, the callback runs (it may command the card), then the run continues: deterministic. Without
        callbacks a run never returns to Python. Returns an id for :meth:`remove_event`."""
        if not callable(callback):
            raise TypeError("on_event: callback must be callable as callback(card, fired)")
        ev = _event_mask(events, "events")
        for name, v, hi in (("msts", msts, 0xFFFFFFFF), ("mio", mio, 0xFFFFFFFF), ("system", system, 31),
                            ("timer_ticks", timer_ticks, 10**9)):
            if not isinstance(v, (int, np.integer)) or not 0 <= int(v) <= hi:
                raise ValueError(f"Card.on_event.{name} = {v!r} is outside the allowed range 0..{hi}")
        if axis is not None and not (isinstance(axis, (int, np.integer)) and 0 <= int(axis) < len(self)):
            raise ValueError(f"Card.on_event.axis = {axis!r} is outside the allowed range 0..{len(self) - 1} (or None)")
        timers = {s.timer for _i, s in self._subs if s.timer} | ({int(timer_ticks)} if timer_ticks else set())
        if len(timers) > 1:
            raise ValueError(f"Card.on_event.timer_ticks = {timer_ticks}: the card has one timer, already set to "
                             f"{min(timers - {int(timer_ticks)})} ticks")
        sid = max((i for i, _s in self._subs), default=0) + 1
        sub = _Subscription(callback, None if axis is None else int(axis), ev, int(msts), int(mio), int(system),
                            int(timer_ticks))
        object.__setattr__(self, "_subs", self._subs + ((sid, sub),))
        self._bind_step()
        self._apply_watch()
        return sid

    def remove_event(self, sid: int) -> None:
        """Removes the callback registered under ``sid`` (an :meth:`on_event` id)."""
        object.__setattr__(self, "_subs", tuple((i, s) for i, s in self._subs if i != sid))
        self._bind_step()
        self._apply_watch()

    def _apply_watch(self) -> None:
        n = len(self)
        ev, ms, mi = [0] * n, [0] * n, [0] * n
        system, timer = 0, 0
        for _i, s in self._subs:
            for a in (range(n) if s.axis is None else (s.axis,)):
                ev[a] |= s.events
                ms[a] |= s.msts
                mi[a] |= s.mio
            system |= s.system
            timer = timer or s.timer
        for a in range(n):
            self._card.set_watch(a, ev[a], ms[a], mi[a])
        self._card.set_system_watch(system)
        if timer != getattr(self, "_timer_set", 0):
            self._card.set_timer(timer)
            object.__setattr__(self, "_timer_set", timer)

    def _run_with_callbacks(self, ticks: int, signals) -> CardRun:
        wanted = (["time_s", "pos", "actual_pos", "error", "volts", "prf_vel", "events", "moving", "servo_on"]
                  if signals is None else [str(s) for s in signals])
        unknown = [w for w in wanted if w not in Card.SIGNALS]
        if unknown:
            raise ValueError(f"signals: unknown signal '{unknown[0]}'; the signals are: {', '.join(Card.SIGNALS)}")
        if not isinstance(ticks, (int, np.integer)) or ticks < 0:
            raise ValueError(f"Card.run.ticks = {ticks!r} is outside the allowed range 0..1e9 (whole ticks)")
        parts, remaining = [], int(ticks)
        while remaining > 0:
            ran, rec, fired = self._card.run_until_event(remaining, wanted)
            parts.append(rec)
            remaining -= ran
            self._dispatch(fired)
            if ran == 0:
                break
        axes = []
        for a in range(len(self)):
            axes.append(AxisSignals(signals={w: np.concatenate([p[a][w] for p in parts]) if parts else np.zeros(0)
                                             for w in wanted}))
        return CardRun(axes=axes, servo_period_s=self._card.servo_period_s)

    def _dispatch(self, fired) -> None:
        for tick, axis, word, bits in fired:
            for _sid, sub in self._subs:
                hit = sub.matches(axis, word, bits)
                if hit:
                    sub.callback(self, FiredEvent(int(tick), int(axis), word, hit))

    def run_until_fired(self, predicate, max_ticks: int) -> int:
        """Runs with the :meth:`on_event` callbacks until ``predicate()`` is true after a callback or after a tick at
        which a vendor module's own watch ended the run (checked before the run too), at most ``max_ticks``; returns
        the ticks run. What a vendor's "wait for interrupt" does."""
        done = 0
        while done < max_ticks and not predicate():
            ran, _rec, fired = self._card.run_until_event(max_ticks - done, [])
            done += ran
            self._dispatch(fired)
            if ran == 0:
                break
        return done

    # position compare and probe: the C++ methods (compare_set_linear/table/output/source, compare_enable,
    # compare_count, compare_log, set_probe_time, set_probe_position) are reached through __getattr__.


#: Signals the sampler records: name -> (unit, description).
SAMPLE_SIGNALS: dict[str, tuple[str, str]] = {name: (unit, doc) for name, unit, doc in _core.SAMPLE_SIGNALS}

_SYSTEM_BITS = ("emg", "linear_compare_0_end", "linear_compare_1_end", "table_compare_0_end", "table_compare_1_end")
_MSTS_BITS = {0: "CSTP", 1: "VM", 2: "ACC", 3: "DEC", 4: "DIR", 5: "MDN", 6: "HMV", 16: "ASTP", 28: "GER"}
_MIO_BITS = {0: "ALM", 1: "PEL", 2: "MEL", 3: "ORG", 4: "EMG", 5: "EZ", 6: "INP", 7: "SVON", 11: "SPEL", 12: "SMEL"}


def _event_mask(events, what: str) -> int:
    if isinstance(events, str):
        events = (events,)
    mask = 0
    for e in events:
        if e not in CARD_EVENTS:
            raise ValueError(f"Card.{what}: '{e}' is not a card event; the events are: {', '.join(CARD_EVENTS)}")
        mask |= 1 << CARD_EVENTS.index(e)
    return mask


@dataclass(frozen=True)
class _Subscription:
    callback: object
    axis: int | None
    events: int
    msts: int
    mio: int
    system: int
    timer: int

    def matches(self, axis: int, word: str, bits: int) -> int:
        if word == "timer":
            return 1 if self.timer else 0
        if word == "system":
            return bits & self.system
        if self.axis is not None and axis != self.axis:
            return 0
        return bits & {"events": self.events, "msts": self.msts, "mio": self.mio}[word]


@dataclass(frozen=True)
class FiredEvent(JsonResult):
    """An event a :meth:`Card.on_event` callback receives: it fired during tick ``tick`` (the card's ``tick`` is
    ``tick + 1`` in the callback) on ``axis`` (-1 card-wide), in ``word`` (``"events"``, ``"msts"``, ``"mio"``,
    ``"system"``, ``"timer"``); ``bits`` those that turned on and this callback asked for."""

    tick: int
    axis: int
    word: str
    bits: int

    @property
    def names(self) -> list[str]:
        """The names of ``bits``: card events, system events, or the ADLINK MSTS/MIO bit names (MDN, INP, ...)."""
        if self.word == "events":
            return events_named(self.bits)
        if self.word == "system":
            return [n for k, n in enumerate(_SYSTEM_BITS) if self.bits >> k & 1]
        table = {"msts": _MSTS_BITS, "mio": _MIO_BITS}.get(self.word, {})
        return [n for k, n in sorted(table.items()) if self.bits >> k & 1]


@dataclass(frozen=True)
class ScopeData(JsonResult):
    """One block of the card's sampler: ``ticks`` (the card tick of each sample; the values are those after that
    tick), ``values`` (samples x channels), ``channels`` ((axis, signal) each), ``trigger_tick`` (-1: immediate).
    ``data["actual_pos"]`` (one channel of that signal), ``data[1, "volts"]`` (axis 1's) or ``data[2]`` (the
    third channel) give a channel's NumPy array; ``time_s`` is tick x Ts."""

    ticks: np.ndarray
    values: np.ndarray
    channels: tuple
    servo_period_s: float
    trigger_tick: int = -1

    @property
    def time_s(self) -> np.ndarray:
        """Time of each sample, s (tick x servo period)."""
        return self.ticks * self.servo_period_s

    @property
    def names(self) -> list[str]:
        """Channel labels ``signal[axis]``."""
        return [f"{sig}[{a}]" for a, sig in self.channels]

    @property
    def units(self) -> list[str]:
        """Unit of each channel."""
        return [SAMPLE_SIGNALS[sig][0] for _a, sig in self.channels]

    @property
    def trigger_index(self) -> int:
        """Index of the trigger sample (-1: immediate trigger)."""
        hit = np.flatnonzero(self.ticks == self.trigger_tick) if self.trigger_tick >= 0 else []
        return int(hit[0]) if len(hit) else -1

    def __len__(self) -> int:
        return len(self.ticks)

    def __getitem__(self, key) -> np.ndarray:
        if isinstance(key, (int, np.integer)):
            return self.values[:, int(key)]
        if isinstance(key, tuple):
            idx = [k for k, c in enumerate(self.channels) if c == (int(key[0]), key[1])]
        else:
            idx = [k for k, c in enumerate(self.channels) if c[1] == key or self.names[k] == key]
        if len(idx) != 1:
            raise KeyError(f"{key!r}: {'no' if not idx else 'more than one'} channel; the channels are {self.names}")
        return self.values[:, idx[0]]

    def to_dict(self) -> dict:
        """The block as a dict of NumPy arrays (``time_s``, ``tick`` and one per channel label)."""
        out = {"time_s": self.time_s, "tick": self.ticks}
        out.update({n: self.values[:, k] for k, n in enumerate(self.names)})
        return out

    def to_dataframe(self):
        """The block as a pandas DataFrame, one row per sample: ``tick`` (card tick), ``time_s`` (s) and one column
        per channel labelled ``signal[axis]``; ``df.attrs["units"]`` gives each column's unit."""
        units = {"tick": "servo tick", "time_s": "s", **dict(zip(self.names, self.units))}
        return dataframe({"tick": self.ticks, "time_s": self.time_s,
                          **{n: self.values[:, k] for k, n in enumerate(self.names)}}, units)

    def plot(self, *, path: str | None = None, title: str | None = None):
        """One panel per unit (:func:`servobench.plot.scope`); returns the Figure, writes ``path`` if given."""
        from . import plot

        return plot.scope(self, path=path, title=title)
