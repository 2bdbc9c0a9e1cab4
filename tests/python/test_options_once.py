"""Each option described once (issue 24 point 4): the defaults, units and docs the Python API shows are read from
the C++ option structs (their describe() tables, bound as FIELD_INFO), so a retyped copy cannot drift. For each
options pair, every default in the Python signature equals the struct's (through the binding), or is a declared
Python-side stand-in whose C++ value is the struct's meaning; every unit and doc in the generated docstring is the
struct's (decisions OP3-OP4)."""

from __future__ import annotations

import inspect

import pytest

import servobench as sb
from servobench import _core, _options, autotune, frequency, frequency_fit, margins

# (public function, its C++ options class)
PAIRS = [
    (frequency.sine_sweep, _core.SineSweepOptions),
    (autotune.relay_autotune, _core.RelayTuneOptions),
    (autotune.model_based_tune, _core.ModelTuneOptions),
    (margins.margins, _core.MarginsOptions),
    (frequency_fit.fit_frequency, _core.FrequencyFitOptions),
]


@pytest.mark.parametrize("func, cls", PAIRS, ids=lambda x: getattr(x, "__name__", str(x)))
def test_defaults_read_from_the_struct(func, cls):
    sig = inspect.signature(func)
    fields = _options.option_fields(cls)
    assert fields, "the struct lists its options"
    default = cls()  # the default-constructed C++ struct, through the binding
    for f in fields:
        assert f.name in sig.parameters, f"{func.__name__} lacks option {f.name}"
        p = sig.parameters[f.name]
        assert p.kind is inspect.Parameter.KEYWORD_ONLY
        cpp = getattr(default, f.name)
        assert f.default == cpp
        pd = func.python_defaults.get(f.name)
        if pd is None:
            assert p.default == cpp, f"{func.__name__}.{f.name}"
            assert type(p.default).__name__ == f.type, f"{func.__name__}.{f.name}: {type(p.default)} not {f.type}"
        else:
            assert p.default is pd.value or p.default == pd.value
            if pd.cpp is not None:  # the stand-in means a value the struct accepts
                cls(**{f.name: pd.cpp})


@pytest.mark.parametrize("func, cls", PAIRS, ids=lambda x: getattr(x, "__name__", str(x)))
def test_units_and_docs_read_from_the_struct(func, cls):
    doc = func.__doc__
    assert "{options}" not in doc
    for f in _options.option_fields(cls):
        head = f"{f.name} ({f.type}" + (f", {f.unit})" if f.unit else ")")
        assert head in doc, f"{func.__name__}: {head!r} not in its docstring"
        assert " ".join(_options._rst(f.doc).split()[:6]) in " ".join(doc.split()), \
            f"{func.__name__}.{f.name}: doc not the struct's"
        # the bound class documents the same unit on its property and constructor
        prop_doc = getattr(cls, f.name).__doc__
        assert (f"[{f.unit}] " if f.unit else "") + f.doc == prop_doc
        assert f.name + (f" [{f.unit}]" if f.unit else "") + ": " in cls.__init__.__doc__


def test_unknown_option_is_a_type_error_naming_it():
    axis = sb.Axis()
    with pytest.raises(TypeError, match="start_hzz"):
        frequency.sine_sweep(axis, start_hzz=5.0)


def test_a_bad_option_names_the_field_and_range():
    with pytest.raises(ValueError, match="points"):
        _core.SineSweepOptions(points=1)
    with pytest.raises(ValueError, match="data_length"):
        _core.RelayTuneOptions(data_length=0)
    with pytest.raises(ValueError, match="phase_margin_deg"):
        _core.ModelTuneOptions(phase_margin_deg=95.0)
    with pytest.raises(ValueError, match="whole number"):
        _core.SineSweepOptions(points=2.5)


def test_options_are_value_types():
    o = _core.SineSweepOptions(start_hz=5.0, points=50)
    assert o.points == 50.0
    assert o.replace(end_hz=200.0).end_hz == 200.0 and o.end_hz == 100.0
    assert tuple(_core.MODEL_TUNE_NOTCH_Q) == inspect.signature(autotune.model_based_tune).parameters["notch_q"].default
    import pickle

    assert pickle.loads(pickle.dumps(o)) == o


def test_predicted_limit_cycle_reads_the_relay_defaults():
    sig = inspect.signature(autotune.predicted_limit_cycle)
    d = _core.RelayTuneOptions()
    for name in ("amplitude_v", "hysteresis_pulse", "sampling_time_s"):
        assert sig.parameters[name].default == getattr(d, name)


def test_margins_result_fields_read_from_the_struct():
    import dataclasses

    table = _options.result_fields(_core.MARGINS_FIELDS)
    fields = dataclasses.fields(margins.Margins)
    assert [f.name for f in fields[: len(table)]] == [t.name for t in table]
    doc = margins.Margins.__doc__
    assert "{fields}" not in doc
    for f, t in zip(fields, table):
        assert f.metadata["unit"] == t.unit and f.metadata["doc"] == t.doc
        assert f"{t.name} ({t.type}" + (f", {t.unit})" if t.unit else ")") in doc
        assert " ".join(_options._rst(t.doc).split()[:6]) in " ".join(doc.split())
    # what static type checkers see (the TYPE_CHECKING block of margins.py) names the same fields
    import ast
    import pathlib

    tree = ast.parse(pathlib.Path(margins.__file__).read_text())
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Margins")
    block = next(n for n in cls.body if isinstance(n, ast.If))
    assert [a.target.id for a in block.body] == [t.name for t in table]
    # the core's result dict carries exactly these names (the binding writes them from the same table)
    m = margins.margins([1.0, 10.0, 100.0], [10.0 + 0j, -0.5 - 0.5j, -0.01 + 0j])
    assert isinstance(m.phase_margin_deg, float)
    axis = sb.Axis(law=sb.GtServoLaw(kp=38, ki=30, kd=1660), servo_period_s=100e-6)
    assert margins.analytic_margins(axis).pm_freq_hz > 0
