"""Axis description files: one simulated axis in TOML or JSON (the same schema; the file's extension chooses).

A file maps 1:1 onto the constructors of :class:`servobench.Axis` and its parts (docs/cli.md has the full table,
generated from :func:`schema`)::

    description = "400 W servo on a rigid load"   # optional, free text
    servo_period_s = 200e-6        # s; absent: the law's card default (GT 200 us, ADLINK 250 us)
    substeps = 1                   # plant integration sub-steps per tick, 1..1000

    [law]                          # type = "gt" (GtServoLaw) or "aps" (ApsServoLaw); the manual's names
    type = "gt"
    kp = 38
    kd = 830

    [drive]                        # mode = "torque" | "velocity" | "position" | "stepper"
    mode = "torque"
    amps_per_volt = 0.8

    [plant]                        # type = "rigid" | "two_mass" ("two-mass" is accepted)
    type = "rigid"
    inertia_kgm2 = 1e-4

    [encoder]                      # Encoder; [dac] Dac; [switches] Switches
    counts_per_rev = 10000

    [[filters]]                    # up to two biquads after the law, in order (biquad 0, biquad 1)
    type = "notch"                 # none | lowpass | notch | lead_lag (designed, Hz) | float | adlink (coefficients)
    center_hz = 300
    q = 2

Every key absent takes the constructor's default (= the manual's). Errors raise :class:`AxisFileError` (a
ValueError) whose text names the file, the key path (``law.kp``, ``filters[0].center_hz``) and the library's own
message with the allowed range; unknown keys get a "did you mean" suggestion; syntax errors give the line and column.
"""

from __future__ import annotations

import difflib
import json
import math
import numbers
import os
import re
from dataclasses import dataclass, field

from . import _checks
from . import _core, design
from .axis import Axis

try:  # Python 3.11+
    import tomllib as _toml
except ModuleNotFoundError:  # pragma: no cover - Python 3.9/3.10: the tomli backport (a dependency there)
    import tomli as _toml

__all__ = ["Key", "Table", "Variant", "dumps_toml",
           "AxisFileError", "axis_from_dict", "axis_to_dict", "load_axis", "read_axis", "save_axis", "schema",
           "schema_markdown", "FORMATS"]

#: File extensions and their format.
FORMATS = {".toml": "toml", ".json": "json"}


class AxisFileError(ValueError):
    """A bad axis file: ``str(e)`` is ``"<file>: <key>: <message>"``; the parts are ``path``, ``key``, ``message``."""

    def __init__(self, path: str, key: str, message: str):
        self.path, self.key, self.message = str(path), key, message
        super().__init__(f"{self.path}: {key}: {message}" if key else f"{self.path}: {message}")


# ----------------------------------------------------------------------------------------------------------------
# The schema
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Key:
    """One key of a table: name, kind ("number", "bool", "string"), doc (meaning, unit, range), default (None:
    required; for a choice key the default variant)."""

    name: str
    kind: str
    doc: str
    default: object = None
    required: bool = False


@dataclass(frozen=True)
class Variant:
    """One form of a table: the constructor it maps onto and its keys."""

    name: str
    target: str
    keys: tuple
    build: object = field(default=None, repr=False, compare=False)


@dataclass(frozen=True)
class Table:
    """A table of the file: its choice key (``type``/``mode``, None if one form) and its forms."""

    name: str
    doc: str
    selector: str | None
    default_variant: str
    variants: dict
    aliases: dict = field(default_factory=dict)


def _param_keys(cls) -> tuple:
    defaults = cls().to_dict()
    keys = []
    for name in cls.FIELDS:
        d = defaults[name]
        keys.append(Key(name, "bool" if isinstance(d, bool) else "number", getattr(cls, name).__doc__ or "", d))
    return tuple(keys)


def _param_variant(name, cls) -> Variant:
    return Variant(name, cls.__name__, _param_keys(cls), cls)


_PRE = Key("prewarp", "bool", "pre-warp the bilinear transform (at the cutoff / centre / sqrt(zero*pole))", False)
_ADL = Key("adlink", "bool", "quantise to the ADLINK card's int16 integers (AdlinkBiquad; FloatBiquad.to_adlink)", False)
_TS = Key("sample_time_s", "number", "sample time the coefficients were designed for, s; absent: the axis's servo "
          "period", None)

_FILTER_VARIANTS = {
    "none": Variant("none", "pass-through (B0 = DIV = 1)", ()),
    "lowpass": Variant("lowpass", "design.lowpass", (
        Key("cutoff_hz", "number", "cutoff (natural) frequency, Hz, 0 < f < Nyquist", required=True),
        Key("zeta", "number", "damping ratio, > 0", 0.707), _PRE, _ADL)),
    "notch": Variant("notch", "design.notch", (
        Key("center_hz", "number", "notch centre, Hz, 0 < f < Nyquist", required=True),
        Key("q", "number", "quality factor (centre / -3 dB width), > 0; or give low_hz and high_hz", None),
        Key("low_hz", "number", "lower -3 dB edge, Hz (with high_hz, instead of q)", None),
        Key("high_hz", "number", "upper -3 dB edge, Hz (with low_hz, instead of q)", None), _PRE, _ADL)),
    "lead_lag": Variant("lead_lag", "design.lead_lag", (
        Key("zero_hz", "number", "zero, Hz, 0 < f < Nyquist (below pole_hz: lead)", required=True),
        Key("pole_hz", "number", "pole, Hz, 0 < f < Nyquist", required=True),
        Key("gain", "number", "DC gain, > 0", 1.0), _PRE, _ADL)),
    "float": Variant("float", "FloatBiquad", tuple(k for k in _param_keys(_core.FloatBiquad)
                                                   if k.name != "sample_time_s") + (_TS,)),
    "adlink": Variant("adlink", "AdlinkBiquad", tuple(k for k in _param_keys(_core.AdlinkBiquad)
                                                     if k.name != "sample_time_s") + (_TS,)),
}

TABLES = {
    "law": Table("law", "servo law after the position error", "type", "gt",
                 {"gt": _param_variant("gt", _core.GtServoLaw), "aps": _param_variant("aps", _core.ApsServoLaw)}),
    "drive": Table("drive", "the drive the card's output commands", "mode", "torque",
                   {"torque": _param_variant("torque", _core.TorqueDrive),
                    "velocity": _param_variant("velocity", _core.VelocityDrive),
                    "position": _param_variant("position", _core.ServoPositionDrive),
                    "stepper": _param_variant("stepper", _core.StepperDrive)}),
    "plant": Table("plant", "the mechanics", "type", "rigid",
                   {"rigid": _param_variant("rigid", _core.RigidPlant),
                    "two_mass": _param_variant("two_mass", _core.TwoMassPlant)}, aliases={"two-mass": "two_mass"}),
    "encoder": Table("encoder", "the position encoder", None, "", {"": _param_variant("", _core.Encoder)}),
    "dac": Table("dac", "the card's DAC", None, "", {"": _param_variant("", _core.Dac)}),
    "switches": Table("switches", "home and limit switches (load angle)", None, "",
                      {"": _param_variant("", _core.Switches)}),
    "filters": Table("filters", "up to two biquads after the law (an array of tables: biquad 0, biquad 1)", "type",
                     "none", _FILTER_VARIANTS, aliases={"lead-lag": "lead_lag"}),
}

TOP_KEYS = (
    Key("description", "string", "free text, kept for the reader", ""),
    Key("servo_period_s", "number", "servo period Ts, s (GT 48e-6..1966.08e-6, ADLINK 50e-6..2000e-6)", None),
    Key("substeps", "number", "plant integration sub-steps per tick, 1..1000", 1),
)


def schema() -> list[dict]:
    """Every key of the axis file: {"key", "kind", "doc", "default", "required"} with key paths as in error
    messages (``law.kp`` when law.type = "gt" ...); the choice keys (``law.type`` ...) list their forms."""
    rows = [dict(key=k.name, kind=k.kind, doc=k.doc, default=k.default, required=k.required) for k in TOP_KEYS]
    for t in TABLES.values():
        base = "filters[i]" if t.name == "filters" else t.name
        if t.selector:
            rows.append(dict(key=f"{base}.{t.selector}", kind="string", required=False, default=t.default_variant,
                             doc=t.doc + ": " + " | ".join(f'"{v}"' for v in t.variants)))
        for v in t.variants.values():
            for k in v.keys:
                rows.append(dict(key=f"{base}.{k.name}", kind=k.kind, doc=k.doc, default=k.default, required=k.required,
                                 variant=v.name, target=v.target))
    return rows


def _fmt_default(v) -> str:
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, float) and v.is_integer():
        return str(int(v))
    if isinstance(v, float) and math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return f"{v:.10g}" if isinstance(v, float) else str(v)


def schema_markdown() -> str:
    """The schema as Markdown tables (one per table and form), as docs/cli.md shows it."""
    out = ["| key | meaning, unit, allowed range | default |", "|---|---|---|"]
    for k in TOP_KEYS:
        out.append(f"| `{k.name}` | {k.doc} | {_fmt_default(k.default) or 'card default'} |")
    for t in TABLES.values():
        base = "filters[i]" if t.name == "filters" else t.name
        out.append("")
        for v in t.variants.values():
            if t.selector:
                head = f"`[{'[filters]]' if t.name == 'filters' else t.name + ']'}` with `{t.selector} = \"{v.name}\"`"
                out += [f"{head} ({v.target}):", ""]
            else:
                out += [f"`[{t.name}]` ({v.target}): {t.doc}", ""]
            if not v.keys:
                out += ["no keys", ""]
                continue
            out += ["| key | meaning, unit, allowed range | default |", "|---|---|---|"]
            for k in v.keys:
                default = "required" if k.required else (_fmt_default(k.default) or "-")
                if k.name == "sample_time_s" and t.name == "filters":
                    default = "servo period"
                doc = k.doc.replace("``", "`").replace("|", "\\|")  # RST literals as Markdown code; a literal | escaped in a table cell
                out.append(f"| `{base}.{k.name}` | {doc} | {default} |")
            out.append("")
    return "\n".join(out).rstrip() + "\n"


# ----------------------------------------------------------------------------------------------------------------
# Reading
# ----------------------------------------------------------------------------------------------------------------
def _format_of(path: str) -> str:
    ext = os.path.splitext(str(path))[1].lower()
    if ext not in FORMATS:
        raise AxisFileError(path, "", f"unknown file type '{ext or '(none)'}': an axis file ends in .toml or .json")
    return FORMATS[ext]


def read_axis(path) -> dict:
    """The parsed content of an axis file (a dict), syntax checked; :func:`axis_from_dict` checks the rest.
    Raises :class:`AxisFileError` for a missing file, an unknown extension or a syntax error (line and column)."""
    path = str(path)
    fmt = _format_of(path)
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except FileNotFoundError:
        raise AxisFileError(path, "", "no such file") from None
    except OSError as e:
        raise AxisFileError(path, "", f"cannot read it ({e.strerror or e})") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise AxisFileError(path, "", f"not UTF-8 text ({e})") from None
    if fmt == "toml":
        try:
            data = _toml.loads(text)
        except _toml.TOMLDecodeError as e:
            msg = str(e)
            m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
            where = f"line {m.group(1)}, column {m.group(2)}" if m else "syntax"
            raise AxisFileError(path, where, "invalid TOML: " + re.sub(r"\s*\(at line.*\)$", "", msg)) from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as e:
            raise AxisFileError(path, f"line {e.lineno}, column {e.colno}", f"invalid JSON: {e.msg}") from None
        if not isinstance(data, dict):
            raise AxisFileError(path, "", f"the top level must be an object, got {_type_name(data)}")
    return data


def _type_name(v) -> str:
    return {bool: "a boolean", str: "a string", list: "an array", dict: "a table", type(None): "null"}.get(
        type(v), "a number" if isinstance(v, numbers.Number) else type(v).__name__)


def _suggest(word: str, choices) -> str:
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""


def _unknown(path, where, key, allowed, what="key"):
    allowed = list(allowed)
    raise AxisFileError(path, f"{where}.{key}" if where else key,
                        f"unknown {what}{_suggest(key, allowed)} (allowed: {', '.join(allowed) or 'none'})")


def _number(path, key, v) -> float:
    if isinstance(v, str) and v.strip().lower() in ("inf", "+inf", "infinity", "-inf", "-infinity"):
        return float(v.strip().lower().replace("infinity", "inf"))
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise AxisFileError(path, key, f"must be a number, got {_type_name(v)} {json.dumps(v, default=str)}")
    return float(v)


def _value(path, keypath, key: Key, v):
    if key.kind == "number":
        return _number(path, keypath, v)
    if key.kind == "bool":
        if not isinstance(v, bool):
            raise AxisFileError(path, keypath, f"must be true or false, got {_type_name(v)} {json.dumps(v, default=str)}")
        return v
    if not isinstance(v, str):
        raise AxisFileError(path, keypath, f"must be a string, got {_type_name(v)}")
    return v


def _library_error(path, where: str, names, exc: Exception) -> AxisFileError:
    """The library's ValueError/TypeError text, prefixed with the key path of the field it names."""
    msg = str(exc)
    m = re.search(r"\bAxis\.(filters\[\d\])", msg)
    if m:
        return AxisFileError(path, m.group(1), msg)
    for m in re.finditer(r"\b\w+\.(\w+)\b", msg):
        if m.group(1) in names:
            return AxisFileError(path, f"{where}.{m.group(1)}" if where else m.group(1), msg)
    return AxisFileError(path, where or "axis", msg)


def _table_values(path, where: str, table: Table, data) -> tuple:
    """(variant name, {key: value}) of one table, types checked, unknown keys refused."""
    if not isinstance(data, dict):
        raise AxisFileError(path, where, f"must be a table, got {_type_name(data)}")
    variant = table.default_variant
    if table.selector:
        if table.selector in data:
            variant = _value(path, f"{where}.{table.selector}", Key(table.selector, "string", ""),
                             data[table.selector])
            variant = table.aliases.get(variant, variant)
            if variant not in table.variants:
                raise AxisFileError(path, f"{where}.{table.selector}",
                                    f"'{variant}' is not one of {', '.join(table.variants)}"
                                    f"{_suggest(variant, list(table.variants) + list(table.aliases))}")
    v = table.variants[variant]
    by_name = {k.name: k for k in v.keys}
    values = {}
    for name, raw in data.items():
        if name == table.selector:
            continue
        if name not in by_name:
            other = [n for n, ov in table.variants.items() if n != variant and name in {k.name for k in ov.keys}]
            if other and not _suggest(name, by_name):
                raise AxisFileError(path, f"{where}.{name}", f"is not a key of {where}.{table.selector} = "
                                    f"\"{variant}\" ({v.target}); it belongs to {table.selector} = \"{other[0]}\"")
            _unknown(path, where, name, by_name)
        values[name] = _value(path, f"{where}.{name}", by_name[name], raw)
    for k in v.keys:
        if k.required and k.name not in values:
            raise AxisFileError(path, f"{where}.{k.name}", f"missing: a {variant} needs {k.name} ({k.doc})")
    return variant, values


def _build_param(path, where, table, data):
    variant, values = _table_values(path, where, table, data)
    v = table.variants[variant]
    try:
        return v.build(**values)
    except (ValueError, TypeError) as e:
        raise _library_error(path, where, values, e) from None


def _build_filter(path, where, data, period_s):
    variant, values = _table_values(path, where, TABLES["filters"], data)
    if variant == "none":
        return None
    try:
        if variant in ("float", "adlink"):
            cls = _core.FloatBiquad if variant == "float" else _core.AdlinkBiquad
            values.setdefault("sample_time_s", period_s)
            return cls(**values)
        adlink = values.pop("adlink", False)
        prewarp = values.pop("prewarp", False)
        if variant == "lowpass":
            f = design.lowpass(values["cutoff_hz"], period_s, values.get("zeta", 0.707), prewarp=prewarp)
        elif variant == "notch":
            f = design.notch(values["center_hz"], period_s, q=values.get("q"), low_hz=values.get("low_hz"),
                             high_hz=values.get("high_hz"), prewarp=prewarp)
        else:
            f = design.lead_lag(values["zero_hz"], values["pole_hz"], period_s, gain=values.get("gain", 1.0),
                                prewarp=prewarp)
        return f.to_adlink() if adlink else f
    except (ValueError, TypeError) as e:
        if variant == "notch" and "give either q" in str(e):
            raise AxisFileError(path, f"{where}.q", str(e)) from None
        raise _library_error(path, where, values, e) from None


def axis_from_dict(data: dict, source: str = "<dict>") -> Axis:
    """Builds the :class:`Axis` an axis-file dict describes (`source` names it in errors)."""
    path = source
    if not isinstance(data, dict):
        raise AxisFileError(path, "", f"the top level must be a table, got {_type_name(data)}")
    top = {k.name: k for k in TOP_KEYS}
    for name in data:
        if name not in top and name not in TABLES:
            _unknown(path, "", name, list(top) + list(TABLES), "key or table")
    for name, key in top.items():
        if name in data:
            _value(path, name, key, data[name])
    parts = {}
    for name in ("law", "drive", "plant", "encoder", "dac", "switches"):
        if name in data:
            parts[name] = _build_param(path, name, TABLES[name], data[name])
    period = None if "servo_period_s" not in data else _number(path, "servo_period_s", data["servo_period_s"])
    substeps = data.get("substeps", 1)
    substeps = _number(path, "substeps", substeps)
    if substeps != int(substeps):
        raise AxisFileError(path, "substeps", f"Axis.substeps = {substeps:g} is not a whole number; the allowed "
                                              "range is 1..1000")
    try:
        axis = Axis(servo_period_s=period, substeps=int(substeps), **parts)
    except (ValueError, TypeError) as e:
        raise _library_error(path, "", {"servo_period_s", "substeps"}, e) from None
    filters = data.get("filters", [])
    if isinstance(filters, dict):
        filters = [filters]
    if not isinstance(filters, list):
        raise AxisFileError(path, "filters", f"must be an array of tables ([[filters]] in TOML), got "
                                             f"{_type_name(filters)}")
    if len(filters) > 2:
        raise AxisFileError(path, "filters", f"{len(filters)} filters given; the card has two biquads (0 and 1)")
    if filters:
        built = [_build_filter(path, f"filters[{i}]", f, axis.servo_period_s) for i, f in enumerate(filters)]
        built += [None] * (2 - len(built))
        try:
            axis = Axis(servo_period_s=period, substeps=int(substeps), filters=tuple(built), **parts)
        except (ValueError, TypeError) as e:
            raise _library_error(path, "filters", set(), e) from None
    return axis


def load_axis(path) -> Axis:
    """The :class:`Axis` described by a TOML (.toml) or JSON (.json) axis file; :class:`AxisFileError` if it is
    bad (file, key path, value and allowed range in the message)."""
    return axis_from_dict(read_axis(path), str(path))


# ----------------------------------------------------------------------------------------------------------------
# Writing
# ----------------------------------------------------------------------------------------------------------------
def _plain(v):
    if isinstance(v, float) and v.is_integer() and abs(v) < 2**53:
        return int(v)
    return v


def _variant_of(table: Table, obj) -> str:
    for name, v in table.variants.items():
        if v.build is not None and type(obj) is v.build:
            return name
    raise TypeError(f"{type(obj).__name__} has no place in the axis file's [{table.name}]")


def _param_dict(table: Table, obj) -> dict:
    d = {}
    if table.selector:
        d[table.selector] = _variant_of(table, obj)
    d.update({k: _plain(v) for k, v in obj.to_dict().items()})
    return d


def _is_pass_through(f) -> bool:
    if f is None:
        return True
    d = f.to_dict()
    if isinstance(f, _core.AdlinkBiquad):
        return d["b0"] == d["div"] and d["a1"] == d["a2"] == d["b1"] == d["b2"] == 0
    return d["b0"] == 1 and d["a1"] == d["a2"] == d["b1"] == d["b2"] == 0


def _filter_dict(f, period_s, spec=None) -> dict:
    if _is_pass_through(f):
        return {"type": "none"}
    if spec is not None and spec.get("type") not in (None, "none", "float", "adlink"):
        try:
            again = _build_filter("<spec>", "filter", dict(spec), period_s)
        except AxisFileError:
            again = None
        if again is not None and type(again) is type(f) and again.to_dict() == f.to_dict():
            return {k: _plain(v) for k, v in spec.items()}
    d = {"type": "adlink" if isinstance(f, _core.AdlinkBiquad) else "float"}
    for k, v in f.to_dict().items():
        if k == "sample_time_s" and v == period_s:
            continue
        d[k] = _plain(v)
    return d


def axis_to_dict(axis: Axis, *, filter_specs=None, description: str | None = None) -> dict:
    """The axis-file dict of `axis`: servo period, substeps, every key of law, drive, plant and encoder; dac and
    switches when not at their defaults; the filters that are not pass-through. A filter is written in its design
    form (``type = "notch"``, ``center_hz`` ...) when the matching entry of `filter_specs` (a list of filter tables,
    e.g. from the file it was loaded from) designs exactly these coefficients, else as coefficients."""
    _checks.has("axis_to_dict", "axis", axis, "servo_period_s", "law")
    d = {}
    if description:
        d["description"] = description
    d["servo_period_s"] = axis.servo_period_s
    if axis.substeps != 1:
        d["substeps"] = axis.substeps
    for name in ("law", "drive", "plant", "encoder"):
        d[name] = _param_dict(TABLES[name], getattr(axis, name))
    for name in ("dac", "switches"):
        obj = getattr(axis, name)
        if obj != type(obj)():
            d[name] = _param_dict(TABLES[name], obj)
    specs = list(filter_specs or [])
    filters = [_filter_dict(f, axis.servo_period_s, specs[i] if i < len(specs) else None)
               for i, f in enumerate(axis.filters)]
    while filters and filters[-1] == {"type": "none"}:
        filters.pop()
    if filters:
        d["filters"] = filters
    return d


def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        if math.isnan(v):
            return "nan"
        return repr(v)
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def dumps_toml(d: dict, header: str = "") -> str:
    """An axis-file dict as TOML text (scalars first, then tables, then [[filters]])."""
    lines = [f"# {line}" for line in header.splitlines()]
    for k, v in d.items():
        if not isinstance(v, (dict, list)):
            lines.append(f"{k} = {_toml_value(v)}")
    for k, v in d.items():
        if isinstance(v, dict):
            lines += ["", f"[{k}]"] + [f"{kk} = {_toml_value(vv)}" for kk, vv in v.items()]
    for k, v in d.items():
        if isinstance(v, list):
            for item in v:
                lines += ["", f"[[{k}]]"] + [f"{kk} = {_toml_value(vv)}" for kk, vv in item.items()]
    return "\n".join(lines) + "\n"


def _json_safe(v):
    if isinstance(v, dict):
        return {k: _json_safe(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_json_safe(x) for x in v]
    if isinstance(v, float) and math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return v


def save_axis(axis: Axis, path, *, filter_specs=None, description: str | None = None, header: str = "") -> str:
    """Writes `axis` as an axis file, TOML or JSON by the extension of `path` (JSON writes infinity as the string
    "inf", which the loader reads back); returns the path. See :func:`axis_to_dict`."""
    path = str(path)
    fmt = _format_of(path)
    d = axis_to_dict(axis, filter_specs=filter_specs, description=description)
    text = dumps_toml(d, header) if fmt == "toml" else json.dumps(_json_safe(d), indent=2) + "\n"
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def _main(argv=None) -> int:  # python -m servobench.axisfile --schema-markdown
    import sys

    argv = sys.argv[1:] if argv is None else argv
    if argv == ["--schema-markdown"]:
        sys.stdout.write(schema_markdown())
        return 0
    print("usage: python -m servobench.axisfile --schema-markdown", file=sys.stderr)
    return 2


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(_main())
