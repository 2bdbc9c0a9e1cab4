"""Argument checks shared by the Python layer: one message format, naming the owner, the parameter and its range
(the C++ side's ``common/validate.hpp`` for the values that never reach C++)."""

from __future__ import annotations

import math
import numbers

import numpy as np


def flag(owner: str, name: str, value) -> bool:
    """`value` as a bool: True/False (or NumPy bools, or the integers 0/1); anything else (NaN, 2, "yes", None)
    raises TypeError naming ``owner.name``."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and int(value) in (0, 1):
        return bool(value)
    raise TypeError(f"{owner}.{name} must be True or False, got {value!r}")


def error_limit(owner: str, name: str, value, axis, span_pulse: float = 0.0) -> float:
    """A following-error limit argument, pulse: ``"auto"`` gives the axis's default, the larger of 2 revolutions
    of its encoder (2 x ``counts_per_rev``) and twice `span_pulse` (how far the command goes from where the axis
    stands, pulse), so a large commanded step is no trip but a loop that lags by more than its whole command is;
    ``None`` or 0 turns the protection off (0.0), else a finite value 0..1e15 (decision RB4). An axis whose law has
    no feedback gain (kp = ki = kd = 0: open loop) gets no automatic limit."""
    if isinstance(value, str) and value == "auto":
        law = axis.law
        if not (getattr(law, "kp", 1) or getattr(law, "ki", 1) or getattr(law, "kd", 1)):
            return 0.0  # no feedback gain: an open-loop axis (bias, injection) has no loop to lose
        return max(2.0 * float(axis.encoder.counts_per_rev), 2.0 * abs(float(span_pulse)))
    if value is None:
        return 0.0
    return real(owner, name, value, 0, 1e15, unit='pulse ("auto", None or 0 = off)')


def has(owner: str, name: str, value, *attributes: str):
    """TypeError naming ``owner.name`` unless `value` has every one of `attributes` (duck typing with a message:
    a number where an object is expected is a wrong type, not an AttributeError deep inside)."""
    missing = [a for a in attributes if not hasattr(value, a)]
    if missing:
        raise TypeError(f"{owner}.{name} must be an object with {', '.join(attributes)}, got {type(value).__name__}")
    return value


def real(owner: str, name: str, value, lo: float = -math.inf, hi: float = math.inf, *, unit: str = "") -> float:
    """`value` as a finite float within lo..hi (inclusive); TypeError for a non-number, ValueError naming
    ``owner.name`` and the range otherwise."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise TypeError(f"{owner}.{name} must be a number, got {type(value).__name__}")
    v = float(value)
    rng = f"{lo:g}..{hi:g}" + (f" {unit}" if unit else "")
    if not math.isfinite(v):
        raise ValueError(f"{owner}.{name} = {v} is not a finite number; the allowed range is {rng}")
    if not lo <= v <= hi:
        raise ValueError(f"{owner}.{name} = {v:g} is outside the allowed range {rng}")
    return v
