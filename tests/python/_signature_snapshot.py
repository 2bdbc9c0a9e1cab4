"""Writes tests/data/s11_public_signatures.json: inspect.signature of every public function and class (and the
public methods of the public classes) of the tuning/identification modules, as the public API to keep (issue 24
point 4, decision OP2). Run: python tests/python/_signature_snapshot.py (from a directory where the installed
servobench is imported)."""

from __future__ import annotations

import importlib
import inspect
import json
import pathlib

MODULES = ("autotune", "frequency", "experiment", "margins", "tune_robust", "design", "identify", "oefit",
           "frequency_fit")
OUT = pathlib.Path(__file__).resolve().parents[1] / "data" / "s11_public_signatures.json"


def _sig(obj) -> list | None:
    """[[name, kind, repr(default) or None], ...]: what a caller relies on (annotations left out)."""
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return None
    return [[p.name, p.kind.name, None if p.default is inspect.Parameter.empty else repr(p.default)]
            for p in sig.parameters.values()]


def snapshot() -> dict:
    out: dict = {}
    for name in MODULES:
        mod = importlib.import_module(f"servobench.{name}")
        for attr in getattr(mod, "__all__", ()):
            obj = getattr(mod, attr)
            if getattr(obj, "__module__", "") != mod.__name__:
                continue  # re-exported from elsewhere: checked in its own module
            key = f"{name}.{attr}"
            if inspect.isclass(obj):
                out[key] = _sig(obj)
                for m, meth in vars(obj).items():
                    if m.startswith("_") or not callable(meth):
                        continue
                    out[f"{key}.{m}"] = _sig(meth)
            elif callable(obj):
                out[key] = _sig(obj)
    return out


if __name__ == "__main__":
    OUT.write_text(json.dumps(snapshot(), sort_keys=True).replace('], "', '],\n "') + "\n")
    print(f"wrote {OUT}")
