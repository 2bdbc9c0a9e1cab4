"""What every dialect shares: a controller bound to one open :class:`~servobench.Card` that runs it in servo
ticks, and the module-level functions (the vendor's free functions) that call the module's default controller."""

from __future__ import annotations

import functools
import inspect
import math

from .._core import CardCommandRefused, MotionCommandRefused
from ..card import Card
from ..card_clock import VENDOR_CALL_COST_US

# The Googol return codes the GT and GUC-ECAT/iDEABOX libraries share (GT Table 2-1 L393-408, GUC Tab 2-1 L165-180).
GOOGOL_SUCCESS, GOOGOL_COMMAND_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_COMM_ERROR = 0, 1, 7, -1


def register32(pulse: float) -> int:
    """A position as the card's 32-bit position register holds it: the whole pulses, wrapped two's-complement
    into -2^31..2^31-1 the way the counter wraps (a C ``long`` on the GT/GE/GUC cards, ``I32`` on ADLINK; issue
    21.5). The simulated axis itself keeps moving; only the register reading wraps."""
    v = int(round(pulse))
    return ((v + 2**31) % 2**32) - 2**31


def wrap32(pulse: float) -> float:
    """:func:`register32` keeping the fraction (the GUC/iDEABOX ``double`` position reads): ``pulse`` shifted by
    the multiple of 2^32 that brings it into -2^31..2^31."""
    return float(pulse) - 2.0**32 * math.floor((float(pulse) + 2.0**31) / 2.0**32)


# The simulator's own setup step: GT_Open(card) binds a servobench Card (not a vendor argument), and a wrong Card
# is a programming error of the simulation, reported as a ValueError/TypeError naming it.
_SETUP_FUNCTIONS = frozenset({"GT_Open"})


def _vendor_call(fn, parameter_error: int, command_error: int, returns_code: bool):
    """`fn` as the vendor library behaves: whatever goes wrong inside comes back as the vendor's error code, never
    as a Python exception (issue 21.2). A refused card command gives `command_error`; any other failure (a value
    of the wrong type or out of range that slipped past the function's own checks) gives `parameter_error`. Read
    functions (not annotated ``-> int``) return ``(code, 0)``, their outputs untouched as in C."""

    name = fn.__name__

    def guarded(args, kwargs):
        try:
            return fn(*args, **kwargs)
        except (CardCommandRefused, MotionCommandRefused):
            code = command_error
        except Exception:  # noqa: BLE001 -- the vendor contract: an error code, never an exception
            code = parameter_error
        return code if returns_code else (code, 0)

    @functools.wraps(fn)
    def call(*args, **kwargs):
        # the card's clock (issue 25.1): program mode charges the call's bus time, realtime holds the card still
        card = getattr(args[0], "_card", None) if args else None
        clock = getattr(card, "_clock", None) if card is not None else None
        if clock is None:
            return guarded(args, kwargs)
        return clock.run_call(type(args[0])._CLOCK_VENDOR, name, guarded, (args, kwargs))

    call.__wrapped_vendor__ = True
    return call


def _wrap_vendor_methods(cls) -> None:
    """Wraps every ``GT_*``/``APS_*`` method of `cls` (its own, its mixins', those attached later) with
    :func:`_vendor_call`, once."""
    for name in dir(cls):
        fn = getattr(cls, name, None)
        if (name.startswith(("GT_", "APS_")) and callable(fn) and name not in _SETUP_FUNCTIONS
                and not getattr(fn, "__wrapped_vendor__", False)):
            returns_code = getattr(fn, "__annotations__", {}).get("return") in ("int", int)
            setattr(cls, name, _vendor_call(fn, cls._PARAMETER_ERROR, cls._COMMAND_ERROR, returns_code))


class DialectController:
    """Base of the dialect controllers: the open card and the ways a program lets it run.

    Every vendor function of a subclass (a method named ``GT_*`` or ``APS_*``) is wrapped once, here, so that it
    returns the vendor's error code instead of raising (:func:`_vendor_call`); a subclass states its codes in
    ``_PARAMETER_ERROR`` and ``_COMMAND_ERROR`` (default: the Googol 7 and 1)."""

    _PARAMETER_ERROR = GOOGOL_PARAMETER_ERROR
    _COMMAND_ERROR = GOOGOL_COMMAND_ERROR
    #: the dialect's key in :data:`~servobench.card_clock.VENDOR_CALL_COST_US` (its module's name: gt, ge, gts, aps)
    _CLOCK_VENDOR = "gt"

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        module = cls.__module__.rsplit(".", 1)[-1]
        if "_CLOCK_VENDOR" not in cls.__dict__ and module in VENDOR_CALL_COST_US:
            cls._CLOCK_VENDOR = module
        _wrap_vendor_methods(cls)

    def __init__(self):
        self._card: Card | None = None
        self._machine = None

    def use_machine(self, machine) -> None:
        """The simulated machine a vendor program runs against (issue 25.2): a :class:`~servobench.Card`, or a
        callable returning one, that the dialect's open call (``GT_Open()``, ``APS_initial(...)``) opens when the
        program passes no card, so a manual's program calls it exactly as printed. ``None`` forgets it."""
        if machine is not None and not (isinstance(machine, Card) or callable(machine)):
            raise TypeError(f"machine must be a servobench.Card or a callable returning one, not "
                            f"{type(machine).__name__}")
        self._machine = machine

    def _machine_card(self) -> Card | None:
        """The card :meth:`use_machine` set (built now if it is a factory), or None."""
        m = self._machine
        if m is None or isinstance(m, Card):
            return m
        card = m()
        if not isinstance(card, Card):
            raise TypeError(f"the machine factory returned {type(card).__name__}, not a servobench.Card")
        return card

    @property
    def card(self) -> Card | None:
        """The open card (None before the dialect's open call / after its close call)."""
        return self._card

    def _timed_clock(self):
        """The card's clock when it is in program or realtime mode, else None (issue 25.1)."""
        clock = getattr(self._card, "_clock", None) if self._card is not None else None
        return clock if clock is not None and clock.mode != "step" else None

    def run(self, ticks: int):
        """Runs the card ``ticks`` servo ticks; returns the :class:`~servobench.card.CardRun`. Not in realtime
        mode (the clock's thread runs the card; wait with ``delay``/``Sleep``/``wait_until``)."""
        clock = self._timed_clock()
        if clock is not None and clock.mode == "realtime":
            raise RuntimeError("run(ticks): the card ticks in real time (Card.set_clock('realtime')); wait with "
                               "delay/Sleep or wait_until instead")
        return self._card.run(int(ticks))

    def run_ms(self, ms: float):
        """Lets ``ms`` milliseconds pass on the card. Step mode (no clock): runs the nearest whole number of servo
        ticks and returns the :class:`~servobench.card.CardRun`; program mode: advances the card by exactly
        ``ms`` (fractions of a tick carried), realtime mode: waits until the card has run ``ms``; both return
        None (:meth:`~servobench.card_clock.CardClock.advance_ms`)."""
        clock = self._timed_clock()
        if clock is not None:
            return clock.advance_ms(ms)
        return self._card.run(int(round(ms * 1e-3 / self._card.servo_period_s)))

    def _googol_do(self, fn, *args) -> int:
        """Runs a Card command the Googol way: -1 without a card, 1 when the card refuses it (the cause is
        recorded), 7 for a value out of range, else 0."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        try:
            fn(*args)
        except (CardCommandRefused, MotionCommandRefused):
            return GOOGOL_COMMAND_ERROR
        except ValueError:
            return GOOGOL_PARAMETER_ERROR
        return GOOGOL_SUCCESS

    def wait_until(self, predicate, max_ticks: int = 10**7, chunk: int = 1) -> int:
        """Runs ``chunk`` ticks at a time until ``predicate()`` is true, at most ``max_ticks``; returns the ticks.
        Realtime mode: waits (the clock's thread runs the card) until ``predicate()`` holds or the card ran
        ``max_ticks`` more ticks (:meth:`~servobench.card_clock.CardClock.wait_until`)."""
        clock = self._timed_clock()
        if clock is not None and clock.mode == "realtime":
            return clock.wait_until(predicate, max_ticks)
        return self._card.run_until(lambda _c: predicate(), max_ticks, chunk)


def export_functions(namespace: dict, default: DialectController, prefix: str) -> tuple[str, ...]:
    """Puts into the module `namespace` one free function per ``prefix*`` method of `default`'s class (same name
    and docstring, calling `default`), plus ``controller()``, ``card()``, ``run(ticks)`` and ``wait_until(...)``;
    returns the exported vendor names."""
    cls = type(default)
    _wrap_vendor_methods(cls)  # methods attached after the class statement too

    def bind(name):
        def f(*args, **kwargs):
            return getattr(default, name)(*args, **kwargs)

        f.__name__ = f.__qualname__ = name
        f.__doc__ = getattr(cls, name).__doc__
        try:  # help() and completion show the vendor's argument names, not (*args, **kwargs)
            f.__signature__ = inspect.signature(getattr(default, name))  # type: ignore[attr-defined]
        except (TypeError, ValueError):  # a callable without a readable signature keeps the generic one
            pass
        return f

    names = tuple(n for n in dir(cls) if n.startswith(prefix))
    for n in names + ("run", "wait_until", "use_machine"):
        namespace[n] = bind(n)

    def controller():
        """The module's default controller (the one the module-level functions use)."""
        return default

    def card() -> Card | None:
        """The card the module's default controller has open."""
        return default.card

    namespace["controller"] = controller
    namespace["card"] = card
    return names
