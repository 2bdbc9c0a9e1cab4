"""Issue 24 points 3 and 6 for the GT and GTS (GUC-ECAT / iDEABOX) dialects: every public signature as it was
before the dialects were thinned (tests/data/dialect_signatures/{gt,gts}.json, dumped from main at the start of
session 11), and the layout the thin dialects keep (line counts against the aims, no private reach into the C++
card, no message parsing, no mutable state beyond the card handles)."""

from __future__ import annotations

import ast
import importlib
import inspect
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DIALECTS = ROOT / "python" / "servobench" / "dialects"
SIGNATURES = ROOT / "tests" / "data" / "dialect_signatures"


def _signatures(module: str, cls_name: str) -> dict[str, str | None]:
    """{qualified name: str(inspect.signature)} of every public callable of the module and its controller class,
    as tests/data/dialect_signatures/*.json was dumped."""
    mod = importlib.import_module(f"servobench.dialects.{module}")
    out: dict[str, str | None] = {}
    for prefix, owner, names in ((module, mod, dir(mod)), (cls_name, getattr(mod, cls_name), None)):
        for name in sorted(names if names is not None else dir(owner)):
            if name.startswith("_"):
                continue
            obj = getattr(owner, name)
            if inspect.ismodule(obj) or not callable(obj):
                continue
            if owner is mod and not str(getattr(obj, "__module__", "") or "").startswith("servobench.dialects"):
                continue
            try:
                out[f"{prefix}.{name}"] = str(inspect.signature(obj))
            except (TypeError, ValueError):
                out[f"{prefix}.{name}"] = None
    return out


@pytest.mark.parametrize("family, module, cls_name", [("gt", "gt", "GtController"), ("gts", "gts", "GtsController")])
def test_every_public_signature_is_unchanged(family, module, cls_name):
    before = json.loads((SIGNATURES / f"{family}.json").read_text())
    now = _signatures(module, cls_name)
    missing = sorted(set(before) - set(now))
    changed = {k: (before[k], now[k]) for k in before if k in now and before[k] != now[k]}
    assert not missing, f"public callables lost: {missing}"
    assert not changed, f"signatures changed (before, now): {changed}"
