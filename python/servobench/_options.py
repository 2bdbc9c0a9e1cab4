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

__all__ = ["OptionField", "PythonDefault", "cpp_options", "described_result", "option_fields", "options_doc",
           "result_fields", "takes_options"]


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


def option_fields(options_class) -> tuple[OptionField, ...]:
    """The option table of a bound C++ options class (its ``FIELD_INFO``). A whole-number field has type "int"
    (the class itself shows it as a float, like every number of a parameter class, decision Y2)."""
    return tuple(OptionField(**d) for d in options_class.FIELD_INFO)


_ABS = re.compile(r"(?<![\w`])(\|[^|\n]+?\|)(?![\w`])")


def _rst(text: str) -> str:
    """C++ doc text for a reStructuredText docstring: ``|x|`` (an absolute value, not a substitution)."""
    return _ABS.sub(r"``\1``", text)


def _entry(f: OptionField, note: str = "") -> str:
    unit = f", {f.unit}" if f.unit else ""
    text = _rst(f.doc) + (f". {note}" if note else "")
    return f"{f.name} ({f.type}{unit})\n" + textwrap.indent(textwrap.fill(text, 112), "    ")


def options_doc(options_class, python_defaults: dict | None = None) -> str:
    """The "Parameters" entries of an options class, numpydoc style, from its table."""
    python_defaults = python_defaults or {}
    out = []
    for f in option_fields(options_class):
        pd = python_defaults.get(f.name)
        out.append(_entry(f, pd.doc if pd is not None else ""))
    return "\n".join(out)


def takes_options(options_class, *, python_defaults: dict[str, PythonDefault] | None = None):
    """Decorator: the function ``f(..., *, <its own keyword arguments>, **options)`` gets every field of
    `options_class` as a keyword-only argument whose default is the struct's (or the declared
    :class:`PythonDefault`), a ``__signature__`` saying so, and the ``{options}`` placeholder of its docstring
    replaced by the fields' documentation (unit, range, meaning). Unknown keywords raise TypeError. The function
    receives every option by keyword, filled with its default."""
    python_defaults = dict(python_defaults or {})
    fields = option_fields(options_class)
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
            default = pd.value if pd is not None else (int(f.default) if f.type == "int" else f.default)
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
        if func.__doc__ and "{options}" in func.__doc__:
            indent = func.__doc__.split("{options}")[0].rsplit("\n", 1)[-1]
            body = textwrap.indent(options_doc(options_class, python_defaults), indent)[len(indent):]
            wrapper.__doc__ = func.__doc__.replace("{options}", body)
        wrapper.options_class = options_class
        wrapper.python_defaults = python_defaults
        return wrapper

    return decorate


def cpp_options(options_class, values: dict, python_defaults: dict[str, PythonDefault] | None = None):
    """The C++ options object from a function's keyword values: a value equal to its declared Python default is
    replaced by the C++ value it stands for; the struct validates (ValueError/TypeError naming the field)."""
    python_defaults = python_defaults or {}
    kw = {}
    for f in option_fields(options_class):
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


@typing.dataclass_transform(frozen_default=True)
def described_result(table):
    """Class decorator for a frozen result dataclass whose single-figure fields are described in C++: the table's
    fields (names, types, units and docs read from it) come first, as required fields carrying ``unit`` and ``doc``
    in their ``metadata``, then the class's own annotated fields; the ``{fields}`` placeholder of the docstring is
    replaced by their documentation (decision OP6)."""
    fields = result_fields(table)

    def decorate(cls):
        own = dict(cls.__dict__.get("__annotations__", {}))
        clash = {f.name for f in fields} & set(own)
        if clash:
            raise TypeError(f"{cls.__name__} retypes fields described in C++: {sorted(clash)}")
        cls.__annotations__ = {**{f.name: f.type for f in fields}, **own}
        for f in fields:
            setattr(cls, f.name, dataclasses.field(metadata={"unit": f.unit, "doc": f.doc}))
        if cls.__doc__ and "{fields}" in cls.__doc__:
            indent = cls.__doc__.split("{fields}")[0].rsplit("\n", 1)[-1]
            body = textwrap.indent("\n".join(_entry(f) for f in fields), indent)[len(indent):]
            cls.__doc__ = cls.__doc__.replace("{fields}", body)
        return dataclasses.dataclass(frozen=True)(cls)

    return decorate
