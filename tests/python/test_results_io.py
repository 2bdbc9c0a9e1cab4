"""Results to pandas and to standard JSON (issue 23.5): every result with arrays has ``to_dataframe()``; ``to_json()``
writes RFC 8259 JSON (NaN and infinities as null, their places listed under "nonfinite") and ``from_json`` reads it
back exactly; logs come in from a DataFrame; progress bars are tqdm's, off when stderr is not a terminal."""

from __future__ import annotations

import dataclasses
import io
import json

import numpy as np
import pandas as pd
import pytest

import servobench as sb
from servobench import _progress, _serialise, examples


def _strict_loads(text: str):
    def bad(name):
        raise AssertionError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=bad)


def _same(a, b, path="") -> None:
    """Deep equality with NaN == NaN, arrays by value, dataclasses field by field."""
    if dataclasses.is_dataclass(a):
        assert type(a) is type(b), path
        for f in dataclasses.fields(a):
            if f.compare:  # compare=False: a cache the class itself leaves out of ==, e.g. AxisRun's lazy replay
                _same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}")
    elif isinstance(a, pd.DataFrame):
        pd.testing.assert_frame_equal(a, b)
    elif isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray) and a.shape == b.shape and a.dtype.kind == b.dtype.kind, path
        if a.dtype.kind in "fc":
            np.testing.assert_array_equal(a, b, err_msg=path)
        else:
            assert a.tolist() == b.tolist(), path
    elif isinstance(a, dict) or hasattr(a, "keys"):
        assert list(a.keys()) == list(b.keys()), path
        for k in a.keys():
            _same(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, (list, tuple)):
        assert type(a) is type(b) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and np.isnan(a):
        assert isinstance(b, float) and np.isnan(b), path
    else:
        assert a == b, (path, a, b)


def _round_trip(result):
    text = result.to_json()
    assert "Infinity" not in text and "NaN" not in text
    doc = _strict_loads(text)
    back = type(result).from_json(text)
    _same(result, back)
    assert back.to_json() == text, "writing the read-back result gives the same document"
    return doc, back


@pytest.fixture(scope="module")
def move_run():
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=500)
    return sb.demo_axis().run(move)


def test_axis_run_dataframe_and_json(move_run):
    df = move_run.to_dataframe()
    assert list(df.columns) == list(move_run.signals) and len(df) == len(move_run)
    assert df.attrs["units"]["fb_pos"] == "pulse" and df.index.name == "tick"
    np.testing.assert_array_equal(df["fb_pos"].to_numpy(), move_run.fb_pos)
    doc, back = _round_trip(move_run)
    assert doc["type"] == "servobench.axis:AxisRun"
    assert back.law == move_run.law and back.stopped is None


def test_margins_nonfinite_become_null_with_a_flag():
    m = sb.frequency.analytic_margins(sb.demo_axis())
    # what a loop without crossings reports: no gain margin (inf), no lower one (-inf), no bandwidth (NaN)
    m = dataclasses.replace(m, gain_margin_db=np.inf, lower_gain_margin_db=-np.inf, bandwidth_hz=np.nan,
                            gain_crossovers={"freq_hz": np.array([1.0, np.inf, np.nan, -np.inf])})
    doc, back = _round_trip(m)
    assert doc["data"]["lower_gain_margin_db"] is None and doc["data"]["gain_margin_db"] is None
    assert doc["nonfinite"]["/lower_gain_margin_db"] == "-inf" and doc["nonfinite"]["/gain_margin_db"] == "inf"
    assert doc["nonfinite"]["/bandwidth_hz"] == "nan"
    assert doc["data"]["gain_crossovers"]["freq_hz"] == [1.0, None, None, None]
    assert doc["nonfinite"]["/gain_crossovers/freq_hz"] == {"inf": [1], "nan": [2], "-inf": [3]}
    assert back.lower_gain_margin_db == -np.inf and back.gain_margin_db == np.inf


def test_frequency_responses_analytic_and_measured():
    axis = sb.demo_axis()
    an = sb.analytic_response(axis, np.logspace(1, 3, 50))
    df = an.to_dataframe()
    assert df.index.name == "freq_hz" and {"open_loop_db", "open_loop_deg", "closed_loop_db"} <= set(df.columns)
    np.testing.assert_allclose(df["open_loop_db"].to_numpy(), an.gain_db("open_loop"))
    assert df.attrs["units"]["open_loop_deg"] == "deg"
    doc, back = _round_trip(an)
    assert "/open_loop" in doc["complex"]
    me = sb.sine_sweep(sb.demo_axis(), start_hz=10, end_hz=300, points=8)
    dm = me.to_dataframe()
    assert list(dm["usable"]) == list(me.usable) and "coherence" in dm.columns and "flag" in dm.columns
    _round_trip(me)


def test_tuner_results():
    res = sb.model_based_tune(examples.resonant_axis())
    scan = res.to_dataframe()
    assert len(scan) > 5 and "phase_margin_deg" in scan.columns
    _round_trip(res)
    relay = sb.relay_autotune(examples.velocity_axis(), data_length=20)
    cycles = relay.to_dataframe()
    assert len(cycles) == len(relay.cycles["kp"]) and cycles.attrs["units"]["period_s"] == "s"
    rec = relay.to_dataframe("record")
    assert len(rec) == len(relay.error_pulse)
    _round_trip(relay)
    with pytest.raises(ValueError, match="which"):
        relay.to_dataframe("spectrum")


def test_fit_and_log_from_a_dataframe():
    axis = sb.demo_axis()
    log = sb.run_experiment(axis, duration_s=2.0)
    df = pd.DataFrame({"time_s": log.time_s, "torque_nm": log.torque_nm, "position_rad": log.measured})
    again = sb.IdentificationLog.from_dataframe(df)
    np.testing.assert_array_equal(again.measured, log.measured)
    fit = sb.fit_time(again, "rigid", guess={"inertia_kgm2": 2e-4, "viscous_nms": 1e-4, "coulomb_nm": 0.01})
    table = fit.to_dataframe()
    assert table.loc["inertia_kgm2", "value"] == pytest.approx(1e-4, rel=0.05)
    assert table.loc["inertia_kgm2", "unit"] == "kg*m^2"
    samples = fit.to_dataframe("samples")
    assert len(samples) == len(log.time_s)
    _round_trip(fit)


def test_batch_result():
    axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=1000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.1, dwell_after=200)
    res = sb.monte_carlo(axis, move, spread={"plant.inertia_kgm2": (0.8e-4, 1.2e-4)}, n=3, seed=1)
    assert len(res.to_dataframe()) == 3
    long = res.to_dataframe("signals")
    assert len(long) == 3 * len(move.pos) and set(long["plant"]) == {0, 1, 2}
    _round_trip(res)


def test_move_metrics_nan_settling():
    run = sb.demo_axis().run(np.concatenate([[0.0], np.full(30, 5000.0)]))  # too short to settle: NaN
    m = run.metrics()
    assert np.isnan(m.settling_time_s)
    doc, back = _round_trip(m)
    assert doc["nonfinite"]["/settling_time_s"] == "nan"


def test_from_json_refuses_foreign_documents():
    with pytest.raises(ValueError, match="servobench"):
        _serialise.from_json(json.dumps({"type": "os:system", "format": 1, "data": {}}))
    with pytest.raises(ValueError, match="format"):
        _serialise.from_json(json.dumps({"type": "servobench.metrics:MoveMetrics", "format": 99, "data": {}}))
    with pytest.raises(ValueError, match="RelayTuneResult"):
        sb.RelayTuneResult.from_json(sb.frequency.analytic_margins(sb.demo_axis()).to_json())


def test_progress_is_tqdm_and_off_without_a_terminal(monkeypatch):
    assert _progress.counter("auto", "x") is None  # pytest's stderr is not a terminal
    assert _progress.counter(None, "x") is None
    buf = io.StringIO()
    monkeypatch.setattr(_progress, "_tqdm", lambda **kw: __import__("tqdm").tqdm(file=buf, **kw))
    cb = _progress.counter(True, "Bode sweep")
    for k in range(1, 5):
        assert cb(k, 4)
    assert "Bode sweep" in buf.getvalue() and "4/4" in buf.getvalue()
    mine = []
    sb.sine_sweep(sb.demo_axis(), start_hz=10, end_hz=100, points=3, progress=lambda d, t: mine.append(d) or True)
    assert mine[-1] == 3
    with pytest.raises(TypeError, match="progress"):
        sb.sine_sweep(sb.demo_axis(), points=3, progress="yes")


def test_path_run():
    g = sb.PathGenerator(sb.CoordSystem.identity(2))
    g.line([1000, 500], vel=10, acc=1)
    g.start()
    run = sb.run_path(g)
    df = run.to_dataframe()
    assert len(df) == len(run) and {"t_ms", "pos_0", "pos_1", "speed"} <= set(df.columns)
    np.testing.assert_array_equal(df["pos_1"].to_numpy(), run.pos[:, 1])
    _round_trip(run)
