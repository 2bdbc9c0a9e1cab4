"""The ADLINK dialect's public signatures do not change while it is thinned (issue 24 point 6): every public
callable of ``servobench.dialects.aps`` and every public method of ``ApsController`` has the signature it had on
main before session 11 (tests/data/dialect_signatures/aps.json, written from main's code with
``python tests/python/test_dialect_signatures_aps.py --write``)."""

from __future__ import annotations

import functools
import inspect
import json
import sys
from pathlib import Path

import pytest

from servobench.dialects import aps

SNAPSHOT = Path(__file__).resolve().parents[1] / "data" / "dialect_signatures" / "aps.json"
WANT: dict[str, str] = json.loads(SNAPSHOT.read_text()) if SNAPSHOT.exists() else {}


def signatures(module, controller_cls) -> dict[str, str]:
    """The public callables of ``module`` (its functions and classes; the controller's methods as ``Cls.name``)
    -> their ``inspect.signature`` as text; callables without a readable signature are left out."""
    out: dict[str, str] = {}
    for name in sorted(dir(module)):
        f = getattr(module, name)
        if name.startswith("_") or not callable(f) or inspect.ismodule(f):
            continue
        if not getattr(f, "__module__", "").startswith("servobench") and not name.startswith("APS_"):
            continue  # numpy and the like imported into the module
        try:
            out[name] = str(inspect.signature(f))
        except (TypeError, ValueError):
            continue
    for name in sorted(dir(controller_cls)):
        f = getattr(controller_cls, name)
        if name.startswith("_") or not callable(f):
            continue
        try:
            out[f"{controller_cls.__name__}.{name}"] = str(inspect.signature(f))
        except (TypeError, ValueError):
            continue
    return out


@functools.lru_cache(maxsize=1)
def _signatures() -> dict[str, str]:
    return signatures(aps, aps.ApsController)


def test_snapshot_covers_every_function():
    want = json.loads(SNAPSHOT.read_text())  # the snapshot is there
    assert len([n for n in want if n.startswith("APS_")]) >= 100
    assert "use_machine" in want and "ApsController.APS_initial" in want


@pytest.mark.parametrize("name", sorted(WANT))
def test_signature_unchanged(name):
    want = WANT[name]
    got = _signatures()
    assert name in got, f"{name} is gone from servobench.dialects.aps"
    assert got[name] == want, f"{name}{got[name]} was {name}{want}"


if __name__ == "__main__" and sys.argv[1:] == ["--write"]:
    SNAPSHOT.parent.mkdir(parents=True, exist_ok=True)
    SNAPSHOT.write_text(json.dumps(_signatures(), indent=1, sort_keys=True) + "\n")
