"""Every public result has its table and its JSON (issue 23.5): the public classes are enumerated from
``servobench.__all__`` and every public module's ``__all__``, and each must be classified here -- a result with
arrays (``to_dataframe()`` and a ``to_json()``/``from_json`` round trip, checked on a real instance), a result
without a table (allow-list, with the reason) or not a result (with the reason). A new public class that is none of
these fails :func:`test_every_public_class_is_classified`. Decisions W22-W27."""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import pkgutil

import numpy as np
import pandas as pd
import pytest

import servobench as sb
from servobench import examples
from test_homing import make_axis
from test_results_io import _round_trip


def _public_classes() -> dict[str, type]:
    """name -> class of every class listed in the ``__all__`` of servobench and of its public modules."""
    mods = [sb]
    for m in pkgutil.walk_packages(sb.__path__, "servobench."):
        if not any(part.startswith("_") for part in m.name.split(".")) and m.name != "servobench.cli":
            mods.append(importlib.import_module(m.name))
    found: dict[str, type] = {}
    for mod in mods:
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name, None)
            if inspect.isclass(obj):
                found.setdefault(obj.__name__, obj)
    return found


def _automatic_not_result(cls) -> str | None:
    """Why a class is not a result, when its kind says so."""
    if issubclass(cls, BaseException):
        return "an exception"
    if hasattr(cls, "__members__"):
        return "an enumeration of codes"
    if hasattr(cls, "FIELDS") and hasattr(cls, "to_dict"):
        return "a parameter object (law, drive, plant, profile, ...): an input, saved in axis files"
    return None


# ---- results with arrays: a factory of a typical instance each ----------------------------------------------------
@pytest.fixture(scope="module")
def card_run():
    card = sb.Card(4, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870))
    card.axis_on(0)
    card.stage_acc(0, 0.1)
    card.stage_vel(0, 5)
    card.stage_pos(0, 1000)
    card.update(0b0001)
    card.sample([(0, "actual_pos"), (0, "volts")], depth=100)
    run = card.run(300)
    return run, card.scope_data()


@pytest.fixture(scope="module")
def rigid_log():
    """A linear closed-loop record of a rigid machine (the calibration test's machine, 4 s)."""
    from test_identify_calibration import _records

    return _records(sb.RigidModel(95.0, 200.0, 20.0), 1, seed=3)[0]


@pytest.fixture(scope="module")
def rigid_identification(rigid_log):
    return sb.identify_rigid(rigid_log, dynamics_hz=20.0, output_error=False)


def _card_run(request):
    return request.getfixturevalue("card_run")[0]


TABLES = {
    "CardRun": _card_run,
    "AxisSignals": lambda r: _card_run(r)[0],
    "ScopeData": lambda r: r.getfixturevalue("card_run")[1],
    "Trajectory": lambda r: sb.trapezoid_move(distance_pulse=1000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.5),
    "IdentificationLog": lambda r: r.getfixturevalue("rigid_log"),
    "IdimResult": lambda r: r.getfixturevalue("rigid_identification").idim,
    "RigidIdentification": lambda r: r.getfixturevalue("rigid_identification"),
    "ValidationResult": lambda r: sb.validate(r.getfixturevalue("rigid_identification").model,
                                              r.getfixturevalue("rigid_log")),
    "RobustTuneResult": lambda r: sb.tune_robust(sb.demo_axis(), spread={"plant.inertia_kgm2": (0.8e-4, 1.5e-4)},
                                                 n=8, seed=2, phase_margin_deg=50),
    "Margins": lambda r: sb.frequency.analytic_margins(sb.demo_axis()),
    "SegmentSandwich": lambda r: sb.oefit.SegmentSandwich(names=["inertia_kgm2", "viscous_nms"],
                                                          covariance=np.array([[4e-12, 1e-10], [1e-10, 9e-8]]),
                                                          covariance_iid=np.array([[1e-12, 0.0], [0.0, 2e-8]]),
                                                          lags=3, segments=12, residual_rms=0.4),
    # the results of sessions 8 and earlier (tests/python/test_results_io.py checks their tables in detail)
    "AxisRun": lambda r: sb.demo_axis().run(np.r_[0.0, np.full(200, 100.0)]),
    "LoopRun": lambda r: sb.home(make_axis(), sb.GtHome(pos=20000, vel=4, acc=1), max_ticks=300000).run,
    "FrequencyResponse": lambda r: sb.analytic_response(sb.demo_axis(), np.logspace(1, 3, 20)),
    "LogSpectrum": lambda r: sb.identify.log_spectrum(sb.run_experiment(sb.demo_axis(), duration_s=1.0)),
    "ModelTuneResult": lambda r: sb.model_based_tune(sb.demo_axis()),
    "RelayTuneResult": lambda r: sb.relay_autotune(examples.velocity_axis(), data_length=10),
    "IdentifiedPlant": lambda r: sb.fit_time(sb.run_experiment(sb.demo_axis(), duration_s=1.0), "rigid",
                                             guess={"inertia_kgm2": 2e-4, "viscous_nms": 1e-4, "coulomb_nm": 0.01}),
    "BatchResult": lambda r: sb.monte_carlo(sb.demo_axis(), np.r_[0.0, np.full(100, 50.0)],
                                            spread={"plant.inertia_kgm2": (0.8e-4, 1.2e-4)}, n=2, seed=1),
    "PathRun": lambda r: _path_run(),
    "AdlinkRun": lambda r: _adlink_run(),
    "HomingResult": lambda r: sb.home(make_axis(), sb.GtHome(pos=20000, vel=4, acc=1), max_ticks=300000),
}

#: Results with a table but no JSON of their own, and why.
def _clock_stats():
    card = sb.Card(4)
    clock = card.set_clock("program", call_cost_us=100)
    with clock.vendor_call("gt", "GT_GetSts"):
        pass
    return clock.stats()


TABLE_ONLY = {
    "PvtCurve": "a compiled table built by the PVT description functions; its description (the function and its "
                "arguments) is what to store, its points are to_dataframe() (W25)",
}
TABLE_ONLY_FACTORIES = {
    "PvtCurve": lambda r: sb.pvt_table(time_ms=[0, 10, 20], pos=[0, 500, 1000], vel=[0, 50, 0]),
}

#: Results without per-sample arrays: JSON round trip, no table (the reason).
JSON_ONLY = {
    "MoveMetrics": (lambda r: sb.demo_axis().run(np.r_[0.0, np.full(400, 100.0)]).metrics(),
                    "a handful of scalar figures of one move"),
    "TuneCheck": (lambda r: sb.tune_check.check_design(examples.velocity_axis("rigid"),
                                                       sb.ApsServoLaw(kp=60000, kp_shift=0, kd=0), (None, None),
                                                       target_phase_margin_deg=60),
                  "a verdict with its reasons; its arrays are the sweep's (FrequencyResponse.to_dataframe)"),
    "ResonanceGuess": (lambda r: sb.identify.ResonanceGuess(1e-4, 2e-4, 300.0, 180.0, 320.0, 3e-4),
                       "six scalars read off a spectrum"),
    "Estimate": (lambda r: sb.identify.Estimate("inertia_kgm2", 2.3e-4, 1e-6, "kg*m^2", 2e-4, False, False),
                 "one parameter; a result's parameter table is its to_dataframe()"),
    "Peak": (lambda r: sb.frequency.Peak("resonance", 400.0, 12.0, 9.0), "one peak: four scalars"),
    "FiredEvent": (lambda r: sb.FiredEvent(tick=5, axis=0, word="events", bits=3), "one event: four integers"),
    "RigidModel": (lambda r: sb.RigidModel(95.0, 160.0, 20.0, 240.0, 21.0), "a model's few parameters"),
    "AdlinkQuantisation": (lambda r: sb.design.adlink_quantisation(sb.design.notch(100.0, 1e-4, q=30.0)),
                           "one filter's departure: a few scalars"),
    "ClockStats": (lambda r: _clock_stats(), "what a clock did: counts and times"),
}

#: Public classes that are not results, and why.
NOT_RESULTS = {
    "Axis": "a live simulator", "Card": "a live simulator", "MotionLoop": "a live simulator",
    "PvtAxis": "a live simulator", "FollowEx": "a live simulator", "ProfileGenerator": "a live generator",
    "ElectronicGear": "a live generator", "PathGenerator": "a live generator", "AdlinkInterpolator": "a live generator",
    "GeLookAhead": "a live generator", "CrdFifoPair": "a live generator", "PvtTables": "the card's PVT memory (input)",
    "CoordSystem": "an input (the coordinate system's axes)", "PathSegment": "an input (path geometry)",
    "FollowSegment": "an input (a follow segment)", "PathState": "one instant of a path generator (its pos is one "
    "point per axis, not samples)", "Tuner": "the Jupyter panel (its data: panel.data, results above)",
    "CascadePD": "an input (the known controller of a record)", "MechanicsIO": "an input (what surrounds the "
    "mechanics in a measured response)", "Key": "the axis-file schema", "Table": "the axis-file schema",
    "Variant": "the axis-file schema", "Plot": "a drawn figure; its data are the result's own table",
    "GtController": "a vendor-dialect controller (live)", "CardClock": "a card's live clock",
    "ClockOptions": "an input (how a card's time flows)",
    "CardIO": "a card's live I/O wiring (servobench.card_io)", "AuxEncoder": "an input (an auxiliary encoder's source)",
    "GeController": "a vendor-dialect controller (live)", "GtsController": "a vendor-dialect controller (live)",
    "ApsController": "a vendor-dialect controller (live)", "TAxis": "a vendor struct (input)",
    "TWatchBuffer": "a vendor struct", "TLookAheadMsg": "a vendor struct", "TCrdPrm": "a vendor struct (input)",
    **{n: "an ADLINK point-table struct (input)" for n in ("PTLINE", "PTA2CA", "PTA2CE", "PTHCA", "PTHCE", "PTDWL")},
    "PTSTS": "an ADLINK point-table status struct (one reading, APS_get_pt_status)",
    "TTrapPrm": "a vendor struct (input / read-back)", "TJogPrmExt": "a vendor struct (input / read-back)",
    "TVarInfo": "a vendor struct (motion-program variable id)", "TThreadSts": "a vendor struct (thread status)",
    "TCompileInfo": "a vendor struct (compile result)",
}


def _path_run():
    g = sb.PathGenerator(sb.CoordSystem.identity(2))
    g.line([1000, 500], vel=10, acc=1)
    g.start()
    return sb.run_path(g)


def _adlink_run():
    it = sb.AdlinkInterpolator([0, 1])
    it.set_axis_params(0, sb.AdlinkPtp(vm=10000, acc=1e5, dec=1e5))
    it.push("line", target=[1000, 0])
    return sb.run_adlink(it)


def test_every_public_class_is_classified():
    classes = _public_classes()
    known = set(TABLES) | set(TABLE_ONLY) | set(JSON_ONLY) | set(NOT_RESULTS)
    unclassified = sorted(n for n, c in classes.items() if n not in known and _automatic_not_result(c) is None)
    assert not unclassified, (f"public classes without a place in tests/python/test_results_io_all.py: "
                              f"{unclassified}; a result with arrays needs to_dataframe() and to_json()/from_json")
    stale = sorted(known - set(classes))
    assert not stale, f"classified but not public any more: {stale}"
    assert set(TABLE_ONLY) == set(TABLE_ONLY_FACTORIES)


def test_no_array_field_hides_in_the_allow_lists():
    """A dataclass allowed without a table has no field that holds an array (annotation or default)."""
    classes = _public_classes()
    for name in [*JSON_ONLY, *NOT_RESULTS]:
        cls = classes.get(name)
        if cls is None or not dataclasses.is_dataclass(cls):
            continue
        for f in dataclasses.fields(cls):
            assert "ndarray" not in str(f.type), f"{name}.{f.name} is an array: {name} needs to_dataframe()"


@pytest.mark.parametrize("name", sorted(TABLES))
def test_result_table_and_json_round_trip(name, request):
    cls = _public_classes()[name]
    for method in ("to_dataframe", "to_json", "from_json"):
        assert callable(getattr(cls, method, None)), f"{name}.{method}"
    result = TABLES[name](request)
    assert type(result) is cls
    df = result.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) > 0 and len(df.columns) > 0
    doc, back = _round_trip(result)
    assert doc["type"].endswith(f":{cls.__qualname__}")
    pd.testing.assert_frame_equal(back.to_dataframe(), df)


@pytest.mark.parametrize("name", sorted(TABLE_ONLY))
def test_table_only_results(name, request):
    result = TABLE_ONLY_FACTORIES[name](request)
    df = result.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) > 0
    assert df.attrs["units"]


@pytest.mark.parametrize("name", sorted(JSON_ONLY))
def test_scalar_results_json_round_trip(name, request):
    result = JSON_ONLY[name][0](request)
    assert type(result).__name__ == name
    _round_trip(result)


# ---- the new tables in detail: columns named with their units ------------------------------------------------------
def test_card_run_long_form(card_run):
    run, scope = card_run
    df = run.to_dataframe()
    assert len(df) == 4 * len(run) and list(df.columns[:3]) == ["axis", "tick", "time_s"]
    one = df[df.axis == 0]
    np.testing.assert_array_equal(one["actual_pos"].to_numpy(), run[0].actual_pos)
    np.testing.assert_allclose(one["time_s"].to_numpy(), np.arange(len(run)) * run.servo_period_s)
    assert df.attrs["units"]["actual_pos"] == "pulse" and df.attrs["units"]["volts"] == "V"
    wide = df.pivot(index="tick", columns="axis", values="actual_pos")
    assert wide.shape == (len(run), 4)
    sd = scope.to_dataframe()
    assert list(sd.columns) == ["tick", "time_s", "actual_pos[0]", "volts[0]"]
    assert sd.attrs["units"]["volts[0]"] == "V"
    np.testing.assert_array_equal(sd["volts[0]"].to_numpy(), scope["volts"])


def test_identification_tables(rigid_log, rigid_identification):
    log = rigid_log
    df = log.to_dataframe()
    assert list(df.columns) == ["time_s", "force_n", "position_m", "reference_m"]
    again = sb.IdentificationLog.from_dataframe(df, command="force_n", measured="position_m", reference="reference_m",
                                                count_m=log.count_m)
    np.testing.assert_array_equal(again.measured, log.measured)
    np.testing.assert_array_equal(again.torque_nm, log.torque_nm)
    idim = rigid_identification.idim
    par = idim.to_dataframe()
    assert par.loc["M", "value"] == idim["M"] and par.loc["M", "unit"] == "kg"
    assert par.loc["M", "std_error_iid"] == idim.std_error_iid["M"]
    samples = idim.to_dataframe("samples")
    assert list(samples.columns) == ["time_s", "measured_n", "predicted_n", "residual_n"]
    assert len(samples) == idim.n_samples
    with pytest.raises(ValueError, match="which"):
        idim.to_dataframe("frequency")
    table = rigid_identification.to_dataframe()
    assert {"idim", "idim_asymmetric"} <= set(table.estimator)
    side = table.pivot(index="name", columns="estimator", values="value")
    assert side.loc["M", "idim"] == idim["M"]
    val = sb.validate(rigid_identification.model, log).to_dataframe()
    assert list(val.columns)[:3] == ["time_s", "measured_m", "open_loop_m"]
    assert val.attrs["units"]["open_loop_m"] == "m"


def test_trajectory_margins_robust_tables():
    tr = sb.trapezoid_move(distance_pulse=1000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.5)
    df = tr.to_dataframe()
    assert list(df.columns) == ["pos_pulse", "vel_pulse_per_tick", "acc_pulse_per_tick2"] and df.index.name == "tick"
    m = sb.frequency.analytic_margins(sb.demo_axis())
    cross = m.to_dataframe()
    assert set(cross.crossing) <= {"gain", "phase"} and np.all(np.diff(cross.freq_hz) >= 0)
    g = cross[cross.crossing == "gain"]
    assert m.phase_margin_deg in set(g.phase_margin_deg) and m.pm_freq_hz in set(g.freq_hz)
    assert cross.attrs["units"]["freq_hz"] == "Hz"
    robust = TABLES["RobustTuneResult"](None)
    assert len(robust.to_dataframe()) == 8 and "phase_margin_deg" in robust.to_dataframe("before").columns
    assert "worst_pm_deg" in robust.to_dataframe("candidates").columns
    with pytest.raises(ValueError, match="which"):
        robust.to_dataframe("nominal")


def test_homing_json_leaves_the_live_loop_out():
    res = TABLES["HomingResult"](None)
    assert res.done and res.loop is not None
    doc, back = _round_trip(res)
    assert "loop" not in doc["data"] and back.loop is None
    assert back.reference_pulse == res.reference_pulse and back.offset_pulse == res.offset_pulse
    np.testing.assert_array_equal(back.run.actual_pos, res.run.actual_pos)
    assert back.run.units == res.run.units
