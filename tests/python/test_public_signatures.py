"""The public API of the tuning/identification modules keeps working (issue 24 point 6, for point 4): every public
function, class and method has the parameters it had before the options moved to C++ -- the same positional
parameters in the same order, the same keyword arguments with the same defaults (tests/data/s11_public_signatures.json,
snapshot of main before session 11 by tests/python/_signature_snapshot.py; decision OP2)."""

from __future__ import annotations

import importlib
import json
import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from _signature_snapshot import _sig  # noqa: E402

SNAPSHOT = json.loads((pathlib.Path(__file__).resolve().parents[1] / "data" / "s11_public_signatures.json").read_text())


def _resolve(key: str):
    parts = key.split(".")
    obj = importlib.import_module(f"servobench.{parts[0]}")
    for p in parts[1:]:
        obj = getattr(obj, p)
    return obj


def _split(params):
    positional = [p for p in params if p[1] in ("POSITIONAL_ONLY", "POSITIONAL_OR_KEYWORD")]
    keyword = {p[0]: p[2] for p in params if p[1] == "KEYWORD_ONLY"}
    var = sorted(p[1] for p in params if p[1].startswith("VAR_"))
    return positional, keyword, var


@pytest.mark.parametrize("key", sorted(SNAPSHOT))
def test_signature_kept(key):
    before = SNAPSHOT[key]
    now = _sig(_resolve(key))
    if before is None:
        return
    assert now is not None, f"{key}: no signature any more"
    pos0, kw0, var0 = _split(before)
    pos1, kw1, var1 = _split(now)
    assert pos1 == pos0, f"{key}: positional parameters changed"
    assert kw1 == kw0, f"{key}: keyword arguments or their defaults changed"
    assert var1 == var0, f"{key}: *args/**kwargs changed"
