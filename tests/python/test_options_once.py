"""Each option described once (issue 24 point 4): the defaults, units and docs the Python API shows are read from
the C++ option structs (their describe() tables, bound as FIELD_INFO), so a retyped copy cannot drift. For each
options pair, every default in the Python signature equals the struct's (through the binding), or is a declared
Python-side stand-in whose C++ value is the struct's meaning; every unit and doc in the generated docstring is the
struct's (decisions OP3-OP4)."""

from __future__ import annotations

import inspect

import pytest

import servobench as sb
from servobench import _core, _options, autotune, frequency, frequency_fit, identify, margins

# (public function, its C++ options class)
PAIRS = [
    (frequency.sine_sweep, _core.SineSweepOptions),
    (autotune.relay_autotune, _core.RelayTuneOptions),
    (autotune.model_based_tune, _core.ModelTuneOptions),
    (margins.margins, _core.MarginsOptions),
    (frequency_fit.fit_frequency, _core.FrequencyFitOptions),
    # session 12 (decisions OQ1-OQ5): the loop options of the analytic responses and margins
    (frequency.analytic_response, _core.LoopOptions),
    (frequency.broadband_response, _core.LoopOptions),
    (frequency.linear_model, _core.LoopOptions),
    (margins.analytic_margins, _core.LoopOptions),
    (margins.closed_loop_poles, _core.LoopOptions),
]


@pytest.mark.parametrize("func, cls", PAIRS, ids=lambda x: getattr(x, "__name__", str(x)))
def test_defaults_read_from_the_struct(func, cls):
    sig = inspect.signature(func)
    fields = _options.option_fields(cls, func.options_only)
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
    for f in _options.option_fields(cls, func.options_only):
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


# ----------------------------------------------------------------------------------------------------------------
# Session 12 (issue 24.4 continued; decisions OQ1-OQ5)
# ----------------------------------------------------------------------------------------------------------------
def test_fit_time_options_read_from_the_struct():
    """fit_time keeps ``**options`` (its public signature, OP2); the options it documents and the defaults of its
    explicit keywords, and of the single-start fit it hands them to, are the struct's (TimeFitOptions)."""
    cls = _core.TimeFitOptions
    fit = identify.fit_time
    fields = _options.option_fields(cls, fit.options_only, fit.options_rename)
    assert len(fields) == 11
    d = cls()
    once = inspect.signature(identify._fit_once).parameters
    sig = inspect.signature(fit).parameters
    cpp_name = {v: k for k, v in fit.options_rename.items()}
    for f in fields:
        cpp = getattr(d, cpp_name.get(f.name, f.name))
        assert f.default == cpp
        assert once[f.name].default == cpp and type(once[f.name].default).__name__ == f.type, f.name
        if f.name in sig and f.name not in fit.python_defaults:
            assert sig[f.name].default == cpp, f.name
        unit = fit.options_units.get(f.name, f.unit)
        head = f"{f.name} ({f.type}" + (f", {unit})" if unit else ")")
        assert head in fit.__doc__, head
        assert " ".join(_options._rst(f.doc).split()[:6]) in " ".join(fit.__doc__.split()), f.name
    assert sig["segment_samples"].default == fit.python_defaults["segment_samples"].value == "auto"
    # the binding builds the struct from the same table: an unknown option names the fields
    with pytest.raises(TypeError, match="rest_thresholdd.*its fields are"):
        _core.identify_shooting_problem([0.0] * 50, [0.0] * 50, sample_period_s=1e-3, measured_is_speed=False,
                                        measured_on_load=False, model="rigid", rest_thresholdd=1.0)
    with pytest.raises(ValueError, match="direction_window"):
        cls(direction_window=1)
    # shooting_options (the sandwich's problem) reads the struct's defaults too
    from servobench import oefit

    class _Log:
        sample_period_s, measured_is_speed, measured_on_load = 1e-3, False, False
        substeps, current_bw_hz, measurement_count = 1, float("inf"), 1e-4

    kw = oefit.shooting_options(_Log(), 500, {})
    assert kw["edge_samples"] == d.edge_samples and kw["direction_window"] == d.direction_window
    assert kw["rest_threshold"] == d.rest_threshold and kw["min_segment_samples"] == d.min_segment_samples


def test_mechanics_io_fields_read_from_the_struct():
    import dataclasses
    import math

    cls = frequency_fit.MechanicsIO
    table = _options.option_fields(_core.MechanicsIO)
    fields = {f.name: f for f in dataclasses.fields(cls)}
    # the struct's order, output_per_rad spelt counts_per_rev in its place
    assert [f.name for f in dataclasses.fields(cls)] == [cls.python_fields.get(t.name, t.name) for t in table]
    d = _core.MechanicsIO()
    for t in table:
        if t.name in cls.python_fields:
            continue
        f = fields[t.name]
        assert f.metadata["unit"] == t.unit and f.metadata["doc"] == t.doc
        assert f.metadata["cpp_default"] == getattr(d, t.name)
        pd = cls.python_defaults.get(t.name)
        assert f.default == (getattr(d, t.name) if pd is None else pd.value), t.name
        assert f"{t.name} ({t.type}" + (f", {t.unit})" if t.unit else ")") in cls.__doc__
    # what static type checkers read (the TYPE_CHECKING block of the class) is the same fields, types, defaults
    import ast
    import pathlib

    tree = ast.parse(pathlib.Path(frequency_fit.__file__).read_text())
    node = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "MechanicsIO")
    block = next(n for n in node.body if isinstance(n, ast.If))
    typed = [(a.target.id, ast.unparse(a.annotation), eval(ast.unparse(a.value), {"math": math}))
             for a in block.body]
    assert typed == [(f.name, f.type, f.default) for f in dataclasses.fields(cls)]
    io = cls(sample_period_s=1e-4, delay_samples=1, counts_per_rev=10000)
    cpp = io._cpp()
    assert cpp.output_per_rad == pytest.approx(10000 / (2 * math.pi)) and cpp.delay_samples == 1
    assert cls()._cpp().sample_period_s == 0.0  # None stands for the struct's 0: continuous time
    with pytest.raises(ValueError, match="MechanicsIO.torque_per_input"):
        _core.MechanicsIO(torque_per_input=0.0)


def test_cli_defaults_read_from_the_structs():
    """The CLI's bode and tune options take their defaults, types and help (with the unit) from the structs."""
    from servobench import cli

    parser = cli.build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices
    cases = {"bode": (_core.SineSweepOptions, ["start_hz", "end_hz", "points", "update_s", "deviation_limit_pulse"]),
             "tune": (None, ["phase_margin_deg", "alpha", "min_gain_margin_db", "max_ms", "amplitude_v",
                             "hysteresis_pulse", "data_length"])}
    seen = 0
    for command, (cls, names) in cases.items():
        actions = {a.dest: a for a in sub[command]._actions}
        for name in names:
            owner = cls or (_core.RelayTuneOptions if name in ("amplitude_v", "hysteresis_pulse", "data_length")
                            else _core.ModelTuneOptions)
            f = next(f for f in _options.option_fields(owner) if f.name == name)
            a = actions[name]
            assert a.default == f.default and type(a.default) is type(f.default), (command, name)
            assert a.type is (int if f.type == "int" else float)
            assert f.doc.replace("%", "%%") in a.help and (not f.unit or f"[{f.unit}]" in a.help)
            seen += 1
    assert seen == 12
    # --phase-margin-deg serves both tuning methods: their structs agree on it
    assert _core.RelayTuneOptions().phase_margin_deg == _core.ModelTuneOptions().phase_margin_deg


def _class_node(cls):
    """The class statement of `cls`, in whichever module of the package defines it (a result may be defined in a
    private module and published, with its __module__, by a public one; decision OR2)."""
    import ast
    import pathlib
    import sys

    for name, mod in list(sys.modules.items()):
        if not name.startswith("servobench.") or getattr(mod, cls.__name__, None) is not cls:
            continue
        path = getattr(mod, "__file__", None)
        if not path or not path.endswith(".py"):
            continue
        tree = ast.parse(pathlib.Path(path).read_text())
        for n in tree.body:
            if isinstance(n, ast.ClassDef) and n.name == cls.__name__:
                return n
    raise AssertionError(f"no module of the package defines {cls.__qualname__}")


RESULTS = [  # (Python result, its C++ field table, the Python fields that come before the table's)
    ("autotune.RelayTuneResult", "RELAY_TUNE_FIELDS", ("status", "message")),
    ("identify.IdentifiedPlant", "FIT_SUMMARY_FIELDS", ("model", "parameters")),
    ("margins.Margins", "MARGINS_FIELDS", ()),
    ("autotune.ModelTuneResult", "MODEL_TUNE_FIELDS", ()),
    ("identify.Estimate", "PARAMETER_ESTIMATE_FIELDS", ()),
]

# Results whose own fields sit among the described ones (described_result's `after`, decision OR1): their whole
# field order, as it was before the figures were read from C++ (repr and positional constructor unchanged).
FIELD_ORDER = {
    "autotune.ModelTuneResult": ["kp", "ki", "kd", "kc", "ti_s", "td_s", "crossover_hz", "margins", "max_pole_radius",
                                 "law", "filters", "resonances", "resonance_hz", "resonance_prominence_db", "notch",
                                 "crossover_without_notch_hz", "limited_by", "servo_period_s", "scan", "summary",
                                 "phase_margin_deg", "min_gain_margin_db"],
    "identify.Estimate": ["name", "value", "std_error", "unit", "initial", "fixed", "at_bound"],
}


@pytest.mark.parametrize("qualname, table_name, lead", RESULTS, ids=[r[0] for r in RESULTS])
def test_result_fields_read_from_the_struct(qualname, table_name, lead):
    """A result's single figures are the C++ struct's describe() list: their names in its order (after the lead
    fields, so the constructor keeps its positional order), types, units and docs; the docstring documents them and
    the TYPE_CHECKING block static checkers read names the same fields (decision OQ6)."""
    import ast
    import dataclasses
    import importlib

    module_name, cls_name = qualname.split(".")
    module = importlib.import_module(f"servobench.{module_name}")
    cls = getattr(module, cls_name)
    table = _options.result_fields(getattr(_core, table_name))
    fields = dataclasses.fields(cls)
    assert [f.name for f in fields[: len(lead)]] == list(lead)
    if qualname in FIELD_ORDER:
        assert [f.name for f in fields] == FIELD_ORDER[qualname]
        described = [f for f in fields if f.name in {t.name for t in table}]
    else:
        described = fields[len(lead): len(lead) + len(table)]
    assert [f.name for f in described] == [t.name for t in table]
    doc = cls.__doc__
    assert "{fields}" not in doc
    for f, t in zip(described, table):
        assert f.metadata["unit"] == t.unit and f.metadata["doc"] == t.doc
        assert f.type == t.type
        assert f"{t.name} ({t.type}" + (f", {t.unit})" if t.unit else ")") in doc
        assert " ".join(_options._rst(t.doc).split()[:6]) in " ".join(doc.split())
    node = _class_node(cls)
    block = next(n for n in node.body if isinstance(n, ast.If))
    assert [(a.target.id, ast.unparse(a.annotation)) for a in block.body] == [(t.name, t.type) for t in table]


def _names(table_name):
    return [t.name for t in _options.result_fields(getattr(_core, table_name))]


def test_result_parts_keys_read_from_the_structs():
    """The dicts a result carries -- a model-based design's pid, notch, resonances and scan, a Margins' stability, a
    classic rule's PID, the stepped sine's signals, a fit's estimates -- have the keys their C++ struct's describe()
    names, in its order, and the docstrings list them (decision OR1)."""
    import servobench as sb
    from servobench import autotune, frequency, margins
    from servobench.examples import resonant_axis

    axis = resonant_axis()
    res = sb.model_based_tune(axis)
    d = _core.model_tune(getattr(axis, "_axis", axis), _core.ModelTuneOptions(), list(_core.MODEL_TUNE_NOTCH_Q), "axis")
    assert list(d["pid"]) == _names("PID_DESIGN_FIELDS")
    assert list(res.notch)[:-2] == _names("NOTCH_DESIGN_FIELDS")
    assert list(res.notch)[-2:] == ["float_biquad", "adlink_biquad"]
    assert res.resonances and all(list(p) == _names("RESONANCE_PEAK_FIELDS") for p in res.resonances)
    assert list(res.scan) == _names("CROSSOVER_CANDIDATE_FIELDS")
    assert list(res.margins.stability) == _names("STABILITY_FIELDS")
    for name in _names("MODEL_TUNE_FIELDS"):
        assert getattr(res, name) == d[name]
    assert list(_core.classic_rule("ziegler_nichols", 10.0, 0.01, 1e-4)) == _names("PID_DESIGN_FIELDS")
    docs = " ".join(autotune.ModelTuneResult.__doc__.split())
    for table in ("RESONANCE_PEAK_FIELDS", "NOTCH_DESIGN_FIELDS", "CROSSOVER_CANDIDATE_FIELDS"):
        for t in _options.result_fields(getattr(_core, table)):
            assert f'"{t.name}" (' in docs
    assert "{" + "notch_keys}" not in docs and "{" + "scan_keys}" not in docs
    mdoc = " ".join(margins.Margins.__doc__.split())
    assert all(f'"{n}" (' in mdoc for n in _names("STABILITY_FIELDS"))

    sweep = frequency.sine_sweep(axis, start_hz=20, end_hz=200, points=3, update_s=0.05, progress=None)
    signals = [n for n in _names("SINE_SWEEP_FIELDS") if n not in ("freq_hz", "coherence", "distortion", "flag")]
    assert list(sweep.signals) == signals
    fdoc = " ".join(frequency.FrequencyResponse.__doc__.split())
    assert all(f'"{n}" (' in fdoc for n in signals)
    raw = _core.sine_sweep(getattr(axis, "_axis", axis), _core.SineSweepOptions(start_hz=20, end_hz=200, points=3, update_s=0.05))
    assert set(_names("SINE_SWEEP_FIELDS")) | {"status", "message", "integrators", "open_loop_unstable_poles"} \
        == set(raw)
