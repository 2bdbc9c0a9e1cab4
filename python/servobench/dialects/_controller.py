"""What every dialect shares: a controller bound to one open :class:`~servobench.Card` that runs it in servo
ticks, and the module-level functions (the vendor's free functions) that call the module's default controller."""

from __future__ import annotations

from .._core import CardCommandRefused, MotionCommandRefused
from ..card import Card

# The Googol return codes the GT and GUC-ECAT/iDEABOX libraries share (GT Table 2-1 L393-408, GUC Tab 2-1 L165-180).
GOOGOL_SUCCESS, GOOGOL_COMMAND_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_COMM_ERROR = 0, 1, 7, -1


class DialectController:
    """Base of the dialect controllers: the open card and the ways a program lets it run."""

    def __init__(self):
        self._card: Card | None = None

    @property
    def card(self) -> Card | None:
        """The open card (None before the dialect's open call / after its close call)."""
        return self._card

    def run(self, ticks: int):
        """Runs the card ``ticks`` servo ticks; returns the :class:`~servobench.card.CardRun`."""
        return self._card.run(int(ticks))

    def run_ms(self, ms: float):
        """Runs the card ``ms`` milliseconds (rounded to whole servo ticks)."""
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
        """Runs ``chunk`` ticks at a time until ``predicate()`` is true, at most ``max_ticks``; returns the ticks."""
        return self._card.run_until(lambda _c: predicate(), max_ticks, chunk)


def export_functions(namespace: dict, default: DialectController, prefix: str) -> tuple[str, ...]:
    """Puts into the module `namespace` one free function per ``prefix*`` method of `default`'s class (same name
    and docstring, calling `default`), plus ``controller()``, ``card()``, ``run(ticks)`` and ``wait_until(...)``;
    returns the exported vendor names."""
    cls = type(default)

    def bind(name):
        def f(*args, **kwargs):
            return getattr(default, name)(*args, **kwargs)

        f.__name__ = f.__qualname__ = name
        f.__doc__ = getattr(cls, name).__doc__
        return f

    names = tuple(n for n in dir(cls) if n.startswith(prefix))
    for n in names + ("run", "wait_until"):
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
