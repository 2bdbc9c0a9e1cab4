"""Options described once: the Python signatures and "Parameters" docs of the tuning functions, read from the C++
option structs (issue 24 point 4; decisions OP3-OP4).

Each options struct of the C++ core (``SineSweepOptions``, ``RelayTuneOptions``, ``ModelTuneOptions``, ...) states
every option once -- its name, default (the default member initialiser), unit and meaning with its range
(``describe()`` in the header) -- and is bound as a parameter class whose ``FIELD_INFO`` is that table.
:func:`takes_options` builds a public function's keyword arguments, their defaults and their documentation from it,
so nothing is retyped in Python. A Python function may give an option a Python-side default that means what the C++
value means (``None`` for "automatic", where the struct writes 0): it declares it in ``python_defaults`` with the C++
value it stands for, and the test (tests/python/test_options_once.py) checks every other default against the
struct.
"""

from __future__ import annotations

import functools
import inspect
import re
import textwrap
import typing
import dataclasses
from dataclasses import dataclass
from typing import Any, Callable

__all__ = ["OptionField", "PythonDefault", "cpp_options", "default", "described_result", "described_options",
           "documents_options", "fill_keys", "keys_doc", "option_fields", "options_doc", "result_fields",
           "takes_options"]


@dataclass(frozen=True)
class OptionField:
    """One option of a C++ options struct: name, Python type, default, unit ("" for none) and meaning."""

    name: str
    type: str
    default: Any
    unit: str
    doc: str


@dataclass(frozen=True)
class PythonDefault:
    """A Python-side default of an option: ``value`` (e.g. None) stands for the C++ value ``cpp`` (e.g. 0.0, the
    struct's "automatic"), explained by ``doc`` in the generated documentation."""

    value: Any
    cpp: Any
    doc: str


def option_fields(options_class, only=None, rename: dict[str, str] | None = None) -> tuple[OptionField, ...]:
    """The option table of a bound C++ options class (its ``FIELD_INFO``). A whole-number field has type "int"
    (the class itself shows it as a float, like every number of a parameter class, decision Y2). `only`: the
    fields a Python function takes (in the struct's order; None: all); `rename`: C++ name -> the Python keyword
    that has long named it (decision OQ2)."""
    rename = rename or {}
    fields = [OptionField(**d) for d in options_class.FIELD_INFO]
    if only is not None:
        only = list(only)
        missing = set(only) - {f.name for f in fields}
        if missing:
            raise TypeError(f"{options_class.__name__} has no field {sorted(missing)}")
        fields = [f for f in fields if f.name in only]
    return tuple(dataclasses.replace(f, name=rename.get(f.name, f.name),
                                     default=int(f.default) if f.type == "int" else f.default) for f in fields)


def default(options_class, name: str):
    """The default of one option, read from the default-constructed C++ struct (an int field as an int)."""
    for f in option_fields(options_class):
        if f.name == name:
            return f.default
    raise TypeError(f"{options_class.__name__} has no field {name!r}")


_ABS = re.compile(r"(?<![\w`])(\|[^|\n]+?\|)(?![\w`])")


def _rst(text: str) -> str:
    """C++ doc text for a reStructuredText docstring: ``|x|`` (an absolute value, not a substitution)."""
    return _ABS.sub(r"``\1``", text)


def _entry(f: OptionField, note: str = "") -> str:
    unit = f", {f.unit}" if f.unit else ""
    text = _rst(f.doc) + (f". {note}" if note else "")
    return f"{f.name} ({f.type}{unit})\n" + textwrap.indent(textwrap.fill(text, 112), "    ")


def options_doc(options_class, python_defaults: dict | None = None, only=None,
                rename: dict[str, str] | None = None, units: dict[str, str] | None = None,
                notes: dict[str, str] | None = None) -> str:
    """The "Parameters" entries of an options class, numpydoc style, from its table (`only`, `rename` as in
    :func:`option_fields`; `units`: Python name -> the unit a Python caller gives it in, where the struct's is
    relative, e.g. "counts" for the time fit's "scale"; `notes`: Python name -> what the Python function adds)."""
    python_defaults = python_defaults or {}
    units = units or {}
    notes = notes or {}
    out = []
    for f in option_fields(options_class, only, rename):
        if f.name in units:
            f = dataclasses.replace(f, unit=units[f.name])
        pd = python_defaults.get(f.name)
        extra = " ".join(x for x in (pd.doc if pd is not None else "", notes.get(f.name, "")) if x)
        out.append(_entry(f, extra))
    return "\n".join(out)


def documents_options(options_class, *, only, rename: dict[str, str] | None = None,
                      units: dict[str, str] | None = None, python_defaults: dict[str, PythonDefault] | None = None,
                      notes: dict[str, str] | None = None, name: str | None = None):
    """Decorator for a function that keeps its options in ``**options`` (its public signature, decision OP2): the
    ``{options}`` placeholder of its docstring becomes the documentation of the struct's fields named in `only`
    (under their Python names, `rename`), read from the struct; the function's explicit keyword defaults are read
    with :func:`default` (decision OQ2)."""
    def decorate(func: Callable) -> Callable:
        if func.__doc__ and "{options}" in func.__doc__:
            indent = func.__doc__.split("{options}")[0].rsplit("\n", 1)[-1]
            body = options_doc(options_class, python_defaults, only, rename, units, notes)
            func.__doc__ = func.__doc__.replace("{options}", textwrap.indent(body, indent)[len(indent):])
        if name is not None:  # the public name of a function defined under a private one (decision OQ5)
            func.__name__ = func.__qualname__ = name
        func.options_class = options_class
        func.options_only = tuple(only)
        func.options_rename = dict(rename or {})
        func.options_units = dict(units or {})
        func.python_defaults = dict(python_defaults or {})
        return func

    return decorate


def takes_options(options_class, *, python_defaults: dict[str, PythonDefault] | None = None, only=None,
                  name: str | None = None):
    """Decorator: the function ``f(..., *, <its own keyword arguments>, **options)`` gets every field of
    `options_class` (or those named in `only`) as a keyword-only argument whose default is the struct's (or the
    declared :class:`PythonDefault`), a ``__signature__`` saying so, and the ``{options}`` placeholder of its
    docstring replaced by the fields' documentation (unit, range, meaning). Unknown keywords raise TypeError. The
    function receives every option by keyword, filled with its default. `name`: the public name of a function
    defined under a private one (its typed signature for static checkers is generated beside it, decision OQ5)."""
    python_defaults = dict(python_defaults or {})
    fields = option_fields(options_class, only)
    names = {f.name for f in fields}
    unknown = set(python_defaults) - names
    if unknown:
        raise TypeError(f"python_defaults name no field of {options_class.__name__}: {sorted(unknown)}")

    def decorate(func: Callable) -> Callable:
        sig = inspect.signature(func)
        own = [p for p in sig.parameters.values() if p.kind is not inspect.Parameter.VAR_KEYWORD]
        positional = [p for p in own if p.kind is not inspect.Parameter.KEYWORD_ONLY]
        keyword = [p for p in own if p.kind is inspect.Parameter.KEYWORD_ONLY]
        clash = names & {p.name for p in own}
        if clash:
            raise TypeError(f"{func.__name__} retypes options of {options_class.__name__}: {sorted(clash)}")
        opts = []
        for f in fields:
            pd = python_defaults.get(f.name)
            default = pd.value if pd is not None else f.default
            annotation = f.type if pd is None else f"{f.type} | {type(pd.value).__name__ if pd.value is not None else 'None'}"
            opts.append(inspect.Parameter(f.name, inspect.Parameter.KEYWORD_ONLY, default=default,
                                          annotation=annotation))
        new_sig = sig.replace(parameters=[*positional, *opts, *keyword])

        @functools.wraps(func)
        def wrapper(*args, **kwargs):
            bound = new_sig.bind(*args, **kwargs)
            bound.apply_defaults()
            return func(*bound.args, **bound.kwargs)

        wrapper.__signature__ = new_sig
        if name is not None:
            wrapper.__name__ = name
            wrapper.__qualname__ = func.__qualname__.rsplit(".", 1)[0] + "." + name if "." in func.__qualname__ \
                else name
        if func.__doc__ and "{options}" in func.__doc__:
            indent = func.__doc__.split("{options}")[0].rsplit("\n", 1)[-1]
            body = textwrap.indent(options_doc(options_class, python_defaults, only), indent)[len(indent):]
            wrapper.__doc__ = func.__doc__.replace("{options}", body)
        wrapper.options_class = options_class
        wrapper.options_only = None if only is None else tuple(only)
        wrapper.python_defaults = python_defaults
        return wrapper

    return decorate


def cpp_options(options_class, values: dict, python_defaults: dict[str, PythonDefault] | None = None):
    """The C++ options object from a function's keyword values: a value equal to its declared Python default is
    replaced by the C++ value it stands for; the struct validates (ValueError/TypeError naming the field)."""
    python_defaults = python_defaults or {}
    kw = {}
    for f in option_fields(options_class):
        if f.name not in values:  # an option the function does not take: the struct's default
            continue
        v = values[f.name]
        pd = python_defaults.get(f.name)
        if pd is not None and (v is pd.value or (isinstance(v, str) and v == pd.value)):
            v = pd.cpp
        kw[f.name] = v
    return options_class(**kw)


def result_fields(table) -> tuple[OptionField, ...]:
    """The fields of a C++ result table (``_core.MARGINS_FIELDS`` ...): name, type, unit, doc (no default)."""
    return tuple(OptionField(name=d["name"], type=d["type"], default=None, unit=d["unit"], doc=d["doc"])
                 for d in table)


def keys_doc(table) -> str:
    """The keys of a dict a result carries (a C++ struct's table: ``_core.STABILITY_FIELDS`` ...), for a docstring:
    ``"name" (unit: doc), ...`` in the table's order (decision OR1)."""
    entries = []
    for f in result_fields(table):
        unit = f"{f.unit}: " if f.unit else ""
        entries.append(f'"{f.name}" ({unit}{_rst(f.doc)})')
    return ", ".join(entries)


def fill_keys(doc: str | None, keys: dict) -> str | None:
    """`doc` with each ``{name}`` placeholder of `keys` (name -> table) replaced by :func:`keys_doc` of its table,
    filled to the placeholder's indent."""
    if not doc:
        return doc
    for name, table in keys.items():
        mark = "{" + name + "}"
        if mark not in doc:
            raise ValueError(f"the docstring has no {mark} placeholder")
        head = doc.split(mark)[0].rsplit("\n", 1)[-1]
        indent = " " * (len(head) - len(head.lstrip()))
        text = textwrap.fill(head + keys_doc(table), 116, subsequent_indent=indent, break_on_hyphens=False)
        doc = doc.replace(head + mark, text, 1)
    return doc


@typing.dataclass_transform(frozen_default=True)
def described_result(table, *, lead: tuple[str, ...] = (), after: dict[str, tuple[str, ...]] | None = None,
                     keys: dict | None = None):
    """Class decorator for a frozen result dataclass whose single-figure fields are described in C++: the table's
    fields (names, types, units and docs read from it) come first -- after the class's own fields named in `lead`,
    which keeps a constructor's positional order (decision OQ6) -- as required fields carrying ``unit`` and ``doc``
    in their ``metadata``, then the class's other annotated fields; `after` places some of the class's own fields
    right after a table field (table field -> own fields), so a result keeps its field order (repr, positional
    constructor) when its figures and its own fields interleave (decision OR1). The ``{fields}`` placeholder of the
    docstring is replaced by their documentation (decision OP6); each ``{name}`` of `keys` (name -> a C++ table) by
    the keys that table describes (:func:`fill_keys`: a dict field's keys, e.g. a notch design's)."""
    fields = result_fields(table)
    after = dict(after or {})
    unknown = set(after) - {f.name for f in fields}
    if unknown:
        raise TypeError(f"described_result(after=...) names fields the table does not describe: {sorted(unknown)}")

    def decorate(cls):
        own = dict(cls.__dict__.get("__annotations__", {}))
        clash = {f.name for f in fields} & set(own)
        if clash:
            raise TypeError(f"{cls.__name__} retypes fields described in C++: {sorted(clash)}")
        first = {name: own.pop(name) for name in lead}
        annotations = dict(first)
        for f in fields:
            annotations[f.name] = f.type
            for name in after.get(f.name, ()):
                annotations[name] = own.pop(name)
        cls.__annotations__ = {**annotations, **own}
        for f in fields:
            setattr(cls, f.name, dataclasses.field(metadata={"unit": f.unit, "doc": f.doc}))
        if cls.__doc__ and "{fields}" in cls.__doc__:
            indent = cls.__doc__.split("{fields}")[0].rsplit("\n", 1)[-1]
            body = textwrap.indent("\n".join(_entry(f) for f in fields), indent)[len(indent):]
            cls.__doc__ = cls.__doc__.replace("{fields}", body)
        cls.__doc__ = fill_keys(cls.__doc__, keys or {})
        return dataclasses.dataclass(frozen=True)(cls)

    return decorate


@typing.dataclass_transform(frozen_default=True)
def described_options(options_class, *, python_defaults: dict[str, PythonDefault] | None = None,
                      python_fields: dict[str, str] | None = None):
    """Class decorator for a frozen Python dataclass of options whose fields are those of a bound C++ options
    struct: names, types, defaults (or the declared :class:`PythonDefault` stand-ins), units and docs read from its
    table, in the struct's order, ``unit``/``doc``/``cpp_default`` in each field's metadata; `python_fields`: C++
    field -> the class's own annotated field that takes its place (a Python spelling of the same quantity, e.g.
    counts_per_rev for output_per_rad). The ``{fields}`` placeholder of the docstring is replaced by their
    documentation (decision OQ3)."""
    python_defaults = dict(python_defaults or {})
    python_fields = dict(python_fields or {})
    fields = option_fields(options_class)

    def decorate(cls):
        own = dict(cls.__dict__.get("__annotations__", {}))
        table = {f.name for f in fields}
        clash = table & set(own)
        if clash:
            raise TypeError(f"{cls.__name__} retypes fields described in C++: {sorted(clash)}")
        annotations = {}
        for f in fields:
            if f.name in python_fields:
                name = python_fields[f.name]
                annotations[name] = own.pop(name)
                continue
            pd = python_defaults.get(f.name)
            annotations[f.name] = f.type if pd is None else f"{f.type} | None"
            setattr(cls, f.name, dataclasses.field(
                default=f.default if pd is None else pd.value,
                metadata={"unit": f.unit, "doc": f.doc, "cpp_default": f.default}))
        cls.__annotations__ = {**annotations, **own}
        if cls.__doc__ and "{fields}" in cls.__doc__:
            indent = cls.__doc__.split("{fields}")[0].rsplit("\n", 1)[-1]
            entries = [_entry(f, python_defaults[f.name].doc if f.name in python_defaults else "")
                       for f in fields if f.name not in python_fields]
            cls.__doc__ = cls.__doc__.replace("{fields}", textwrap.indent("\n".join(entries), indent)[len(indent):])
        cls.options_class = options_class
        cls.python_defaults = python_defaults
        cls.python_fields = python_fields
        return dataclasses.dataclass(frozen=True)(cls)

    return decorate
