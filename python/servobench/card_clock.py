"""How time flows on a :class:`~servobench.Card` while a program talks to it (issue 25 point 1; docs/card.md "Time
on the card"; decisions CT1-CT19).

Three modes (:class:`ClockOptions` ``mode``):

``"step"`` (default, no clock attached)
    the card stands still between explicit :meth:`Card.run`/:meth:`Card.step` calls; a dialect's ``delay``/``Sleep``
    runs whole servo ticks. What every program did before this module.
``"program"``
    every vendor call (a dialect's ``GT_*``/``APS_*`` function) advances the card by the time that call takes on
    the real bus, ``call_cost_us`` (µs; default per vendor, :data:`VENDOR_CALL_COST_US`, overridable per call name
    in ``call_costs_us``); ``delay(ms)``/``Sleep(ms)`` advance it by their argument. Time is counted in whole
    picoseconds, so fractions of a tick accumulate exactly: the card runs a tick each time a whole servo period
    has been used up (``ticks = floor(accumulated_ps / Ts_ps)``, the rest carried). A polling loop written for
    the card (``while GT_GetSts()[1] & 0x400: pass``) therefore ends, at the manual's position, and the same
    program gives the same result bit for bit.
``"realtime"``
    a background thread ticks the card at ``speed`` x real time (simulated s per wall s) while the program calls
    in from any thread; each vendor call holds the clock's lock, so it sees and changes the card between two
    chunks of ticks, never inside one. ``delay``/``Sleep`` wait until the card has run that long.

Quick use::

    import servobench as sb
    from servobench.dialects import gt
    card = sb.Card(4, law=sb.GtServoLaw(kp=38, kd=830, kaff=12870))
    gt.GT_Open(card)
    card.set_clock("program")                      # 20 us per GT call (VENDOR_CALL_COST_US["gt"])
    ...
    with card.set_clock("realtime", speed=2.0):    # the card ticks at 2x real time until the block ends
        ...
"""

from __future__ import annotations

import atexit
import contextlib
import math
import numbers
import threading
import time
import weakref
from dataclasses import dataclass, field
from typing import Mapping

from ._serialise import JsonResult

__all__ = ["CLOCK_MODES", "CardClock", "ClockOptions", "ClockStats", "VENDOR_CALL_COST_US"]

#: The clock modes (see the module docstring).
CLOCK_MODES: tuple[str, ...] = ("step", "program", "realtime")

#: Default time one vendor call takes on the bus, µs, per dialect module (decisions CT3-CT6; docs/card.md table).
#: The manuals give no per-call time; these are stated choices.
VENDOR_CALL_COST_US: dict[str, float] = {
    "gt": 20.0,   # GT series, ISA/PCI host port of the DSP (GT L379, L559): a few words + handshake per call
    "ge": 20.0,   # GE series, PCI, same host-port protocol as the GT (GE L483)
    "gts": 20.0,  # GUC-ECAT / iDEABOX: library on the controller's PC, local bus to the motion core (GUC L147)
    "aps": 10.0,  # ADLINK PCI-8254/8258: PCI 2.2 33 MHz 32-bit (L318-319), shared memory read by the DSP
}

_PS_PER_S = 10**12
_PS_PER_US = 10**6
_PS_PER_MS = 10**9
_MAX_COST_US = 1e6      # a call costs at most 1 s
_SPEED_RANGE = (1e-3, 1e3)
_PERIOD_MS_RANGE = (0.1, 100.0)
_KEPT_UP_S = 0.05       # realtime: a card never more than 50 ms of wall time (+ 2 chunks) behind "kept up"


def _real(owner: str, name: str, value, lo: float, hi: float) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) and not hasattr(value, "__float__"):
        raise TypeError(f"{owner}.{name} must be a number in {lo:g}..{hi:g}, got {type(value).__name__}")
    v = float(value)
    if not (math.isfinite(v) and lo <= v <= hi):
        raise ValueError(f"{owner}.{name} = {value!r} is outside the allowed range {lo:g}..{hi:g}")
    return v


@dataclass(frozen=True)
class ClockOptions:
    """How a card's time flows (validated on construction; ValueError/TypeError name the field).

    mode
        ``"step"`` (default), ``"program"`` or ``"realtime"`` (:data:`CLOCK_MODES`).
    call_cost_us
        µs one vendor call advances the card in program mode, 0..1e6; None: the vendor's default
        (:data:`VENDOR_CALL_COST_US`).
    call_costs_us
        per call name (``{"GT_GetSts": 5.0}``), µs 0..1e6; wins over ``call_cost_us``.
    speed
        realtime only: simulated seconds per wall-clock second (k), 0.001..1000.
    period_ms
        realtime only: wall-clock ms the ticking thread sleeps between two chunks of ticks, 0.1..100 (the
        granularity at which the program sees the card move; each chunk is ``period_ms * speed / Ts`` ticks).
    """

    mode: str = "step"
    call_cost_us: float | None = None
    call_costs_us: Mapping[str, float] = field(default_factory=dict)
    speed: float = 1.0
    period_ms: float = 1.0

    def __post_init__(self):
        if self.mode not in CLOCK_MODES:
            raise ValueError(f"ClockOptions.mode = {self.mode!r} is not one of {', '.join(CLOCK_MODES)}")
        if self.call_cost_us is not None:
            object.__setattr__(self, "call_cost_us", _real("ClockOptions", "call_cost_us", self.call_cost_us,
                                                           0.0, _MAX_COST_US))
        if not isinstance(self.call_costs_us, Mapping):
            raise TypeError("ClockOptions.call_costs_us must be a mapping call name -> µs, got "
                            f"{type(self.call_costs_us).__name__}")
        costs = {}
        for name, us in self.call_costs_us.items():
            if not isinstance(name, str) or not name.startswith(("GT_", "APS_")):
                raise ValueError(f"ClockOptions.call_costs_us: {name!r} is not a vendor call name (GT_*, APS_*)")
            costs[name] = _real("ClockOptions", f"call_costs_us[{name!r}]", us, 0.0, _MAX_COST_US)
        object.__setattr__(self, "call_costs_us", costs)
        object.__setattr__(self, "speed", _real("ClockOptions", "speed", self.speed, *_SPEED_RANGE))
        object.__setattr__(self, "period_ms", _real("ClockOptions", "period_ms", self.period_ms, *_PERIOD_MS_RANGE))

    def cost_us(self, vendor: str, name: str) -> float:
        """µs the vendor call ``name`` of dialect ``vendor`` (``"gt"``, ``"ge"``, ``"gts"``, ``"aps"``) costs."""
        if name in self.call_costs_us:
            return self.call_costs_us[name]
        if self.call_cost_us is not None:
            return self.call_cost_us
        return VENDOR_CALL_COST_US[vendor]


@dataclass(frozen=True)
class ClockStats(JsonResult):
    """What a clock did: ``calls`` vendor calls charged, ``ticks`` servo ticks the clock ran (pulse units untouched),
    ``simulated_s`` = ticks x Ts; realtime also ``wall_s`` (s the thread ran), ``speed_measured`` =
    simulated_s / wall_s, ``max_lag_ticks`` (the most ticks the card was ever behind its wall-clock schedule) and
    ``kept_up`` (that lag never exceeded 50 ms of wall time plus two chunks: the card ran on schedule, up to an
    operating-system hiccup, so the measured speed is the clock's, not the CPU's)."""

    mode: str
    calls: int
    ticks: int
    simulated_s: float
    wall_s: float
    speed: float
    speed_measured: float
    max_lag_ticks: int
    kept_up: bool

    def to_dict(self) -> dict:
        """The fields as a dict."""
        return dict(self.__dict__)

    def __repr__(self) -> str:
        s = f"ClockStats({self.mode}: {self.calls} calls, {self.ticks} ticks = {self.simulated_s:.6g} s simulated"
        if self.mode == "realtime":
            s += (f", {self.wall_s:.4g} s wall, speed {self.speed_measured:.4g} (asked {self.speed:g}), max lag "
                  f"{self.max_lag_ticks} ticks, {'kept up' if self.kept_up else 'fell behind'}")
        return s + ")"


_LIVE: "weakref.WeakSet[CardClock]" = weakref.WeakSet()


@atexit.register
def _close_all() -> None:  # the ticking threads are joined at interpreter exit
    for clock in list(_LIVE):
        with contextlib.suppress(Exception):
            clock.close()


class CardClock:
    """The clock attached to one card (:meth:`Card.set_clock` makes and attaches it; one per card).

    The dialects call :meth:`vendor_call` around every vendor function and :meth:`advance_ms` for ``delay``/
    ``Sleep``; a program may call :meth:`advance_ms` itself. In realtime mode the ticking thread starts on
    construction and stops on :meth:`close` (also on leaving a ``with`` block, on Ctrl-C there, and at interpreter
    exit); the thread is joined each time. Errors of the ticking thread (an event callback that raised) stop it
    and are raised again by :meth:`close`, :meth:`advance_ms` and :meth:`wait_until`."""

    def __init__(self, card, options: ClockOptions | None = None):
        if options is None:
            options = ClockOptions()
        if not isinstance(options, ClockOptions):
            raise TypeError(f"CardClock.options must be a ClockOptions, got {type(options).__name__}")
        self.card = card
        self.options = options
        self._ts_s = float(card.servo_period_s)
        self._ts_ps = int(round(self._ts_s * _PS_PER_S))
        if self._ts_ps <= 0:
            raise ValueError(f"CardClock: the card's servo period {self._ts_s} s is below 1 ps")
        self._lock = threading.RLock()       # held by a vendor call and by each chunk of ticks
        self._local = threading.local()      # depth of nested vendor calls per thread
        self._acc_ps = 0                     # program mode: time used and not yet run as whole ticks
        self._calls = 0
        self._ticks = 0
        self._waiting = 0                    # callers waiting for the lock (the ticker lets them in first)
        self._meta = threading.Condition()   # guards _waiting, _ticks in realtime; notifies tick progress
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._error: BaseException | None = None
        self._wall_s = 0.0
        self._max_lag = 0
        self._closed = False
        self._step, self._program = options.mode == "step", options.mode == "program"
        self._cost_ps: dict = {}             # (vendor, call name) -> ps, filled on first use
        if options.mode == "realtime":
            self._start()

    # -- what the mode is ---------------------------------------------------------------------------------------
    @property
    def mode(self) -> str:
        """``"step"``, ``"program"`` or ``"realtime"``."""
        return self.options.mode

    @property
    def running(self) -> bool:
        """True while the realtime ticking thread runs."""
        return self._thread is not None and self._thread.is_alive()

    @property
    def pending_us(self) -> float:
        """Program mode: µs used by calls and delays and not yet run as a whole tick (0 <= pending < Ts)."""
        return self._acc_ps / _PS_PER_US

    def stats(self) -> ClockStats:
        """What the clock did so far (:class:`ClockStats`)."""
        with self._meta:
            ticks, wall = self._ticks, self._wall_s
            if self.running:
                wall = time.perf_counter() - self._t0
        sim = ticks * self._ts_s
        chunk = self._chunk_ticks()
        return ClockStats(mode=self.mode, calls=self._calls, ticks=ticks, simulated_s=sim, wall_s=wall,
                          speed=self.options.speed, speed_measured=sim / wall if wall > 0 else 0.0,
                          max_lag_ticks=self._max_lag,
                          kept_up=self._max_lag <= 2 * chunk + _KEPT_UP_S * self.options.speed / self._ts_s)

    def __repr__(self) -> str:
        return f"CardClock({self.mode}, Ts = {self._ts_s * 1e6:.6g} us, {self.stats()!r})"

    # -- the hooks the dialects call ------------------------------------------------------------------------------
    @contextlib.contextmanager
    def vendor_call(self, vendor: str, name: str):
        """Around one vendor call: holds the clock's lock (realtime: the card does not tick during the call);
        in program mode, after the outermost call of this thread returns, runs the card for the call's cost
        (a call made inside another one, or from an event callback, is part of it and costs nothing)."""
        if self.mode == "step":
            yield
            return
        self._acquire()
        depth = getattr(self._local, "depth", 0)
        self._local.depth = depth + 1
        try:
            yield
        finally:
            try:  # charged while the depth still counts this call: callbacks fired by these ticks cost nothing
                if depth == 0:
                    self._calls += 1
                    if self.mode == "program":
                        self._advance_ps(int(round(self.options.cost_us(vendor, name) * _PS_PER_US)))
            finally:
                self._local.depth = depth
                self._lock.release()

    def run_call(self, vendor: str, name: str, call, args=(), kwargs=None):
        """``call(*args, **kwargs)`` as one vendor call (what :meth:`vendor_call` does, without a context manager's
        cost: the dialects' wrapper calls this for every ``GT_*``/``APS_*`` function)."""
        if self._step:
            return call(*args, **(kwargs or {}))
        if not self._lock.acquire(blocking=False):
            self._acquire()
        local = self._local
        depth = getattr(local, "depth", 0)
        local.depth = depth + 1
        try:
            return call(*args, **(kwargs or {}))
        finally:
            try:
                if depth == 0:
                    self._calls += 1
                    if self._program:
                        key = (vendor, name)
                        ps = self._cost_ps.get(key)
                        if ps is None:
                            ps = self._cost_ps[key] = int(round(self.options.cost_us(vendor, name) * _PS_PER_US))
                        self._advance_ps(ps)
            finally:
                local.depth = depth
                self._lock.release()

    @contextlib.contextmanager
    def inside_tick(self):
        """Vendor calls made inside this block count as made inside the servo tick, as calls from an event callback
        do: no bus time is charged for them (the GUC motion program's threads run on the card, decision GS13)."""
        local = self._local
        depth = getattr(local, "depth", 0)
        local.depth = depth + 1
        try:
            yield
        finally:
            local.depth = depth

    @contextlib.contextmanager
    def hold(self):
        """Holds the card still (realtime: no tick runs) for a group of calls a program wants to see at one tick
        (``with clock.hold(): pos = GT_GetAtlPos(); sts = GT_GetSts()``). The calls inside still cost their time
        in program mode."""
        with self._held():
            yield self

    def advance_ms(self, ms: float) -> None:
        """Lets ``ms`` milliseconds (0..1e9) pass on the card: program mode runs it exactly (fractions of a tick
        carried to the next call), realtime mode waits until the ticking thread has run that many ticks, step
        mode runs the whole ticks nearest to it."""
        ms = _real("delay", "ms", ms, 0.0, 1e9)
        if self.mode == "realtime" and (self._lock._is_owned() or threading.current_thread() is self._thread):
            raise RuntimeError("delay/Sleep inside a vendor call or an event callback of a realtime card would wait "
                               "for ticks that cannot run; wait outside the call")
        if self.mode == "program":
            with self._held():
                self._advance_ps(int(round(ms * _PS_PER_MS)))
        elif self.mode == "realtime":
            n = int(round(ms * 1e-3 / self._ts_s))
            with self._held(), self._meta:  # the count of the ticks run so far, not of a chunk in flight
                target = self._ticks + n
            self.wait_until(lambda: False, max_ticks=n, _target=target)
        else:
            self.card.step(int(round(ms * 1e-3 / self._ts_s)))

    def wait_until(self, predicate, max_ticks: int = 10**7, *, _target: int | None = None) -> int:
        """Realtime: waits (without burning a core) until ``predicate()`` is true, checked under the clock's lock
        after each chunk of ticks, or the card has run ``max_ticks`` more ticks; returns the ticks it waited.
        Other modes: runs ``card.run_until`` one tick at a time."""
        if isinstance(max_ticks, bool) or not isinstance(max_ticks, numbers.Integral) or not 0 <= max_ticks <= 10**12:
            raise ValueError(f"wait_until.max_ticks = {max_ticks!r} is outside the allowed range 0..1e12 (whole ticks)")
        if self.mode != "realtime":
            return self.card.run_until(lambda _c: predicate(), max_ticks, 1)
        with self._held(), self._meta:
            start = self._ticks
        target = start + int(max_ticks) if _target is None else _target
        while True:
            with self._held():
                if predicate():
                    break
            with self._meta:
                self._raise_error()
                if self._ticks >= target:
                    break
                if not self.running:
                    raise RuntimeError("CardClock.wait_until: the realtime clock is closed; the card no longer ticks")
                seen = self._ticks
                self._meta.wait_for(lambda: self._ticks != seen or self._error is not None or not self.running,
                                    timeout=0.5)
        with self._meta:
            return self._ticks - start

    # -- start, stop ------------------------------------------------------------------------------------------------
    def close(self) -> None:
        """Stops the ticking thread (realtime) and joins it; detaches the clock from its card. Raises what the
        thread raised, if it did. Idempotent."""
        self._stop.set()
        with self._meta:
            self._meta.notify_all()
        t = self._thread
        if t is not None and t is not threading.current_thread():
            t.join()
        if not self._closed:
            self._closed = True
            _LIVE.discard(self)
            if getattr(self.card, "_clock", None) is self:
                object.__setattr__(self.card, "_clock", None)
        self._raise_error()

    def __enter__(self) -> "CardClock":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # -- internals ----------------------------------------------------------------------------------------------------
    def _raise_error(self) -> None:
        err, self._error = self._error, None
        if err is not None:
            raise RuntimeError(f"the card's realtime clock stopped: {err!r}") from err

    def _acquire(self) -> None:
        if self._lock.acquire(blocking=False):
            return
        with self._meta:
            self._waiting += 1
        try:
            self._lock.acquire()
        finally:
            with self._meta:
                self._waiting -= 1
                self._meta.notify_all()

    @contextlib.contextmanager
    def _held(self):
        self._acquire()
        try:
            yield
        finally:
            self._lock.release()

    def _advance_ps(self, ps: int) -> None:
        """Program mode, lock held: adds ``ps`` picoseconds and runs the whole ticks they complete."""
        self._acc_ps += ps
        n, self._acc_ps = divmod(self._acc_ps, self._ts_ps)
        if n:
            self._ticks += n
            self.card.step(int(n))

    def _chunk_ticks(self) -> int:
        """Realtime: the ticks one period of the thread should run (at least 1)."""
        return max(1, int(math.ceil(self.options.period_ms * 1e-3 * self.options.speed / self._ts_s)))

    def _start(self) -> None:
        self._t0 = time.perf_counter()
        self._thread = threading.Thread(target=self._tick_loop, name="servobench-card-clock", daemon=True)
        _LIVE.add(self)
        self._thread.start()

    def _tick_loop(self) -> None:
        """The realtime thread: every ``period_ms`` of wall time, runs the ticks the schedule (wall time x speed /
        Ts) asks for, in chunks of at most eight periods' worth, each under the lock; between chunks callers that
        wait for the lock go first (for at most half a period). Sleeps on an Event between periods (no busy wait)."""
        period = self.options.period_ms * 1e-3
        per_tick_wall = self._ts_s / self.options.speed
        cap = 8 * self._chunk_ticks()
        ran = 0
        try:
            while not self._stop.is_set():
                due = int((time.perf_counter() - self._t0) / per_tick_wall)
                if due <= ran:
                    self._stop.wait(min(period, (ran + 1) * per_tick_wall - (time.perf_counter() - self._t0)
                                        + 1e-6))
                    continue
                with self._meta:  # program threads waiting for the card go first (best effort)
                    self._meta.wait_for(lambda: self._waiting == 0 or self._stop.is_set(), timeout=period / 2)
                n = min(due - ran, cap)
                with self._lock:
                    if self._stop.is_set():
                        break
                    self.card.step(n)
                    ran += n
                    with self._meta:  # counted before the lock is released: a caller holding it sees the count
                        self._ticks += n
                        self._max_lag = max(self._max_lag, due - ran)
                        self._meta.notify_all()
                if due - ran <= 0:
                    self._stop.wait(period)
        except BaseException as exc:  # noqa: BLE001 -- handed to the program thread (close/wait raise it)
            self._error = exc
        finally:
            with self._meta:
                self._wall_s = time.perf_counter() - self._t0
                self._meta.notify_all()
