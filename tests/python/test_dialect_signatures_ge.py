"""The GE dialect's public API keeps its signatures while it is thinned (issue 24 points 3 and 6): every public
callable of ``servobench.dialects.ge`` and every public method of ``GeController`` has the signature it had on main
before session 11 (tests/data/dialect_signatures/ge.json, dumped with ``inspect.signature``)."""

from __future__ import annotations

import inspect
import json
from pathlib import Path

from servobench.dialects import ge

SNAPSHOT = Path(__file__).resolve().parents[1] / "data" / "dialect_signatures" / "ge.json"


def _signature(name: str) -> str:
    if name.startswith("GeController."):
        return str(inspect.signature(getattr(ge.GeController, name.split(".", 1)[1])))
    return str(inspect.signature(getattr(ge, name)))


def test_every_public_signature_is_unchanged():
    want = json.loads(SNAPSHOT.read_text())
    assert len(want) > 300
    changed = {n: (s, _signature(n)) for n, s in want.items() if _signature(n) != s}
    assert not changed, changed


def test_every_public_function_keeps_its_docstring():
    want = json.loads(SNAPSHOT.read_text())
    bare = [n for n in want if n.split(".")[-1].startswith("GT_") and not (getattr(ge, n.split(".")[-1]).__doc__ or "").strip()]
    assert not bare, bare
