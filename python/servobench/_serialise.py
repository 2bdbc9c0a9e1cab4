"""Results to standard JSON and to pandas (issue 23.5), one helper for every result class.

JSON (RFC 8259) has no NaN or infinity: a non-finite number is written as ``null`` and its place is listed under
``"nonfinite"`` (``{"path": "nan" | "inf" | "-inf"}`` for a number, ``{"path": {"nan": [flat indices], ...}}`` for
an array), so nothing reads ``-Infinity`` and :func:`from_json` restores the exact values. The document is::

    {"type": "servobench.autotune:RelayTuneResult", "format": 1, "data": {...},
     "nonfinite": {...}, "arrays": [paths], "complex": [paths], "types": {path: "module:Class"}, "tuples": [paths]}

``data`` holds the result's fields with plain JSON values (arrays as nested lists; a complex array as
``{"real": [...], "imag": [...]}``); the other keys say how to rebuild the Python objects. Paths are the keys
joined by ``/`` (list items by their index). Decisions W4-W6.
"""

from __future__ import annotations

import dataclasses
import importlib
import json
import math
from typing import Any

import numpy as np

__all__ = ["FORMAT", "JsonResult", "dataframe", "dumps", "from_json", "jsonable", "loads_document", "to_json"]

#: Version of the document layout written by :func:`to_json`.
FORMAT = 1


class _Encoder:
    def __init__(self):
        self.nonfinite: dict[str, Any] = {}
        self.arrays: list[str] = []
        self.complex: list[str] = []
        self.types: dict[str, str] = {}
        self.tuples: list[str] = []
        self.shapes: dict[str, list[int]] = {}  # empty arrays (a nested list cannot show their shape)

    def _float(self, v: float, path: str):
        if math.isfinite(v):
            return v
        self.nonfinite[path] = "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
        return None

    def _real_array(self, a: np.ndarray, path: str):
        a = np.asarray(a, dtype=float)
        bad = ~np.isfinite(a)
        if bad.any():
            flat = a.ravel()
            idx = np.flatnonzero(bad.ravel())
            kinds: dict[str, list[int]] = {}
            for i in idx:
                x = flat[i]
                kinds.setdefault("nan" if np.isnan(x) else ("inf" if x > 0 else "-inf"), []).append(int(i))
            self.nonfinite[path] = kinds
            a = np.where(bad, 0.0, a)
            out = a.astype(object)
            out[bad] = None
            return out.tolist()
        return a.tolist()

    def encode(self, v, path: str = ""):
        if v is None or isinstance(v, (str, bool)):
            return v
        if isinstance(v, np.bool_):
            return bool(v)
        if isinstance(v, (int, np.integer)):
            return int(v)
        if isinstance(v, (float, np.floating)):
            return self._float(float(v), path)
        if isinstance(v, (complex, np.complexfloating)):
            self.complex.append(path)
            return {"real": self._float(float(v.real), f"{path}/real"),
                    "imag": self._float(float(v.imag), f"{path}/imag")}
        if isinstance(v, np.ndarray):
            self.arrays.append(path)
            if v.size == 0 and v.ndim != 1:
                self.shapes[path] = list(v.shape)
            if np.iscomplexobj(v):
                self.complex.append(path)
                return {"real": self._real_array(v.real, f"{path}/real"),
                        "imag": self._real_array(v.imag, f"{path}/imag")}
            if v.dtype == bool:
                self.types[path] = "numpy:bool_"
                return v.tolist()
            if np.issubdtype(v.dtype, np.integer):
                self.types[path] = "numpy:int64"
                return v.tolist()
            if v.dtype.kind in "OUS":
                self.types[path] = "numpy:object"
                return [self.encode(x, f"{path}/{i}") for i, x in enumerate(v.tolist())]
            return self._real_array(v, path)
        if dataclasses.is_dataclass(v) and not isinstance(v, type):
            self.types[path] = _qualname(v)
            return {f.name: self.encode(getattr(v, f.name), f"{path}/{f.name}") for f in dataclasses.fields(v)
                    if f.init and not _private_with_default(f)}
        if type(v).__module__.startswith("pandas"):
            import pandas as pd

            if isinstance(v, pd.DataFrame):  # its columns, in order; the index is a RangeIndex (checked)
                if not isinstance(v.index, pd.RangeIndex) or v.index.start != 0 or v.index.step != 1:
                    raise TypeError(f"to_json: the DataFrame at '{path or '/'}' has an index; reset_index() first")
                self.types[path] = "pandas:DataFrame"
                return {str(c): self.encode(v[c].to_numpy(), f"{path}/{c}") for c in v.columns}
            if isinstance(v, pd.Series):
                return self.encode(v.to_numpy(), path)
        if isinstance(v, dict) or (hasattr(v, "keys") and hasattr(v, "__getitem__") and not hasattr(v, "FIELDS")):
            return {str(k): self.encode(v[k], f"{path}/{k}") for k in v.keys()}
        if isinstance(v, (list, tuple)):
            if isinstance(v, tuple):
                self.tuples.append(path)
            return [self.encode(x, f"{path}/{i}") for i, x in enumerate(v)]
        if hasattr(v, "to_dict") and hasattr(type(v), "FIELDS"):  # a C++ parameter object (law, drive, biquad ...)
            self.types[path] = _qualname(v)
            return {k: self.encode(x, f"{path}/{k}") for k, x in v.to_dict().items()}
        if hasattr(v, "to_dict"):
            return self.encode(v.to_dict(), path)
        raise TypeError(f"to_json: cannot write {type(v).__name__} at '{path or '/'}' as JSON")


def _qualname(v) -> str:
    t = type(v)
    mod = t.__module__
    if mod.startswith("servobench._core") or mod == "_core":
        mod = "servobench._core"
    return f"{mod}:{t.__qualname__}"


def jsonable(obj) -> tuple[Any, dict]:
    """(plain JSON value, non-finite map) of `obj`: NaN and +-inf become ``None`` and their paths are listed."""
    enc = _Encoder()
    return enc.encode(obj), enc.nonfinite


def dumps(obj, *, indent: int | None = None) -> str:
    """`obj` (dicts, lists, numbers, arrays) as strict JSON: non-finite numbers as null, listed under a top-level
    ``"nonfinite"`` key when `obj` is a dict and any were found. Never writes NaN or Infinity."""
    data, nonfinite = jsonable(obj)
    if isinstance(data, dict) and nonfinite:
        data = {**data, "nonfinite": nonfinite}
    return json.dumps(data, indent=indent, allow_nan=False)


def _private_with_default(f) -> bool:
    """A dataclass field that is a live object, not data, and has a default: private (e.g. AxisRun's lazy replay of
    the signals it did not record) or marked ``metadata={"json": False}`` (HomingResult's motion loop); left out of
    the document and rebuilt as its default."""
    has_default = f.default is not dataclasses.MISSING or f.default_factory is not dataclasses.MISSING
    return has_default and (f.name.startswith("_") or f.metadata.get("json", True) is False)


def to_json(obj, *, indent: int | None = None) -> str:
    """The result `obj` (a dataclass of servobench) as a standard JSON document (see the module's docstring)."""
    enc = _Encoder()
    data = enc.encode(obj)
    doc = {"type": _qualname(obj), "format": FORMAT, "data": data, "nonfinite": enc.nonfinite,
           "arrays": enc.arrays, "complex": enc.complex, "types": {k: t for k, t in enc.types.items() if k},
           "tuples": enc.tuples}
    if enc.shapes:
        doc["shapes"] = enc.shapes
    return json.dumps(doc, indent=indent, allow_nan=False)


def loads_document(text: str) -> dict:
    """The parsed document of :func:`to_json`, checked (ValueError naming what is wrong)."""
    if not isinstance(text, (str, bytes, bytearray)):
        raise TypeError(f"from_json: text must be a JSON string, got {type(text).__name__}")
    doc = json.loads(text)
    if not isinstance(doc, dict) or "type" not in doc or "data" not in doc:
        raise ValueError("from_json: not a servobench result document (needs 'type' and 'data')")
    if doc.get("format") != FORMAT:
        raise ValueError(f"from_json: format = {doc.get('format')!r}, this version reads format {FORMAT}")
    return doc


def _resolve(name: str):
    mod, _, qual = name.partition(":")
    if mod == "numpy" or mod == "pandas":
        return None
    if mod != "servobench" and not mod.startswith("servobench."):
        raise ValueError(f"from_json: type {name!r} is not a servobench class")
    obj = importlib.import_module(mod)
    for part in qual.split("."):
        obj = getattr(obj, part)
    return obj


def _get(data, path: str):
    cur = data
    for key in path.split("/")[1:]:
        cur = cur[int(key)] if isinstance(cur, list) else cur[key]
    return cur


def _set(data, path: str, value):
    keys = path.split("/")[1:]
    if not keys:
        return value
    cur = data
    for key in keys[:-1]:
        cur = cur[int(key)] if isinstance(cur, list) else cur[key]
    last = keys[-1]
    if isinstance(cur, list):
        cur[int(last)] = value
    else:
        cur[last] = value
    return data


def from_json(text: str, cls=None):
    """Rebuilds the result written by :func:`to_json` (its arrays as NumPy arrays, non-finite values restored, its
    nested results and parameter objects as their classes). `cls`, if given, must be the document's type."""
    doc = loads_document(text)
    data = doc["data"]
    top = _resolve(doc["type"])
    if cls is not None and top is not cls:
        raise ValueError(f"from_json: the document holds a {doc['type']}, not a {cls.__module__}:{cls.__qualname__}")
    # numbers first (before arrays are built), deepest paths first for the rest
    for path, kind in doc.get("nonfinite", {}).items():
        if isinstance(kind, str):
            data = _set(data, path, float(kind))
    arrays = set(doc.get("arrays", []))
    cplx = set(doc.get("complex", []))
    types = doc.get("types", {})
    for path in sorted(arrays | set(doc.get("tuples", [])) | set(types) | cplx, key=lambda p: -p.count("/")):
        v = _get(data, path)
        if path in arrays:
            if path in cplx:
                re_, im_ = (_array(v[k], doc, f"{path}/{k}") for k in ("real", "imag"))
                v = re_ + 1j * im_
            else:
                t = types.get(path)
                dtype = {"numpy:bool_": bool, "numpy:int64": np.int64, "numpy:object": object}.get(t, float)
                v = _array(v, doc, path) if dtype is float else np.array(v, dtype=dtype)
                if path in doc.get("shapes", {}):
                    v = v.reshape(doc["shapes"][path])
        elif path in cplx:
            v = complex(v["real"], v["imag"])
        elif path in types:
            v = _build(types[path], v)
        if path in doc.get("tuples", []) and isinstance(v, list):
            v = tuple(v)
        data = _set(data, path, v)
    return _build(doc["type"], data)


def _array(values, doc, path: str) -> np.ndarray:
    a = np.array(values, dtype=float)  # null -> NaN, then the listed places get their exact value
    kinds = doc.get("nonfinite", {}).get(path)
    if isinstance(kinds, dict):
        flat = a.reshape(-1)
        for kind, idx in kinds.items():
            flat[np.asarray(idx, dtype=int)] = float(kind)
    return a


def _build(name: str, data):
    if name == "pandas:DataFrame":
        import pandas as pd

        return pd.DataFrame(data)
    cls = _resolve(name)
    if cls is None:
        return data
    if dataclasses.is_dataclass(cls):
        return cls(**data)
    return cls(**data)  # a C++ parameter object from its fields


class JsonResult:
    """Mixin of the result dataclasses: :meth:`to_json` and :meth:`from_json` (standard JSON, non-finite values as
    null with their places listed, round trip exact)."""

    __slots__ = ()

    def to_json(self, *, indent: int | None = None) -> str:
        """This result as a standard JSON document (no NaN/Infinity: they are null and listed under
        ``"nonfinite"``); :meth:`from_json` reads it back. See :mod:`servobench._serialise`."""
        return to_json(self, indent=indent)

    @classmethod
    def from_json(cls, text: str):
        """The result written by :meth:`to_json` (arrays as NumPy arrays, non-finite values restored)."""
        return from_json(text, cls)


def dataframe(columns: dict, units: dict | None = None, *, index: str | None = None):
    """A pandas DataFrame of equal-length 1-D columns (name -> array); ``df.attrs["units"]`` holds each column's
    unit, `index` names the column to use as the index (kept with its unit)."""
    import pandas as pd

    df = pd.DataFrame({k: np.asarray(v) for k, v in columns.items()})
    if index is not None:
        df = df.set_index(index)
    df.attrs["units"] = {k: u for k, u in (units or {}).items() if k in columns}
    return df
