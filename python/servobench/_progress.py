"""Progress bars for work a person waits for (issue 23.5): one tqdm bar per sweep, relay experiment, fit or batch.

``progress=`` of the library's long functions takes ``"auto"`` (the default: a bar when stderr is a terminal, none
in a pipe, a log, a test or a notebook), ``True`` (a bar whatever stderr is: ``tqdm.auto`` draws a widget in
Jupyter and text elsewhere), ``None``/``False`` (none) or a callable of your own. Decision W7.
"""

from __future__ import annotations

import sys
from typing import Callable

__all__ = ["wanted", "counter", "iterations"]


def wanted(progress) -> bool:
    """Whether `progress` asks for a bar: True; "auto" when stderr is a terminal; never for None/False."""
    if progress is None or progress is False:
        return False
    if progress is True:
        return True
    if isinstance(progress, str) and progress == "auto":
        stream = sys.stderr
        return bool(getattr(stream, "isatty", lambda: False)())
    return False


def _check(progress, owner: str) -> None:
    if progress is None or isinstance(progress, bool) or callable(progress) or \
            (isinstance(progress, str) and progress == "auto"):
        return
    raise TypeError(f"{owner}: progress = {progress!r} must be 'auto' (a bar when stderr is a terminal), True (a "
                    f"bar), None/False (none) or a callable")


def _tqdm(**kwargs):
    from tqdm.auto import tqdm

    return tqdm(**kwargs)


def counter(progress, label: str, *, unit: str = "point", owner: str = "progress") -> Callable[[int, int], bool] | None:
    """A ``callback(done, total) -> bool`` (True: go on) for `progress`: the user's callable as it is, a tqdm bar
    (created at the first call, closed when done reaches total), or None when no bar is wanted."""
    _check(progress, owner)
    if callable(progress) and not isinstance(progress, bool):
        return progress
    if not wanted(progress):
        return None
    state: dict = {}

    def bar(done: int, total: int) -> bool:
        b = state.get("bar")
        if b is None:
            b = state["bar"] = _tqdm(total=int(total), desc=label, unit=unit, leave=True)
        b.update(int(done) - b.n)
        if done >= total:
            b.close()
        return True
    return bar


def iterations(progress, label: str, *, owner: str = "progress") -> Callable[[int, float], bool] | None:
    """A ``callback(iteration, cost) -> bool`` for a solver: the user's callable, a tqdm counter of iterations with
    the cost shown (close it with ``callback.close()``), or None."""
    _check(progress, owner)
    if callable(progress) and not isinstance(progress, bool):
        return progress
    if not wanted(progress):
        return None
    b = _tqdm(desc=label, unit="it", leave=True)

    def cb(iteration: int, cost: float) -> bool:
        b.update(max(0, int(iteration) + 1 - b.n))
        b.set_postfix(cost=f"{float(cost):.6g}", refresh=False)
        return True
    cb.close = b.close  # type: ignore[attr-defined]
    return cb
