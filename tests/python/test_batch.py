"""Many plants at once (issue 22.3, 22.4): simulate_many / monte_carlo equal one Axis.run per plant, are
deterministic for a seed whatever the thread count, and a Dask LocalCluster with 2 workers returns the local
result. Speed is measured by bench/bench_batch.py, not here."""

import math

import numpy as np
import pandas as pd
import pytest

import servobench as sb

STEP = np.concatenate([np.zeros(20), np.full(380, 1000.0)])
SPREAD = {"plant.inertia_kgm2": (0.8e-4, 1.6e-4), "plant.coulomb_nm": (0.0, 0.01), "law.kd": lambda rng, n: rng.integers(700, 901, n)}


def _one(axis, row, command=STEP):
    """The reference: one sb.Axis per plant, built with replace() and run with Axis.run over `command`."""
    parts = {}
    for name, value in row.items():
        part, field = name.split(".")
        parts.setdefault(part, {})[field] = value
    spec = sb.batch.axis_spec(axis)
    for part, changes in parts.items():
        spec[part] = spec[part].replace(**changes)
    return sb.Axis(**spec).run(command)


def _assert_metrics_equal(res, i, ref):
    """Plant i's batch metrics are sb.move_metrics of its reference run, bit for bit (NaN where both are NaN)."""
    m = sb.move_metrics(ref)
    for name in sb.batch.METRICS:
        a, b = res.metrics.loc[i, name], getattr(m, name)
        assert (math.isnan(a) and math.isnan(b)) or a == b, (i, name, a, b)


def test_batch_equals_one_run_per_plant_bit_for_bit():
    axis = sb.demo_axis()
    res = sb.monte_carlo(axis, STEP, spread=SPREAD, n=12, seed=3, signals=("fb_pos", "volts"))
    assert res.signals["fb_pos"].shape == (12, len(STEP))
    for i, row in res.parameters.iterrows():
        ref = _one(axis, row.to_dict())
        np.testing.assert_array_equal(res.signals["fb_pos"][i], ref.fb_pos)
        np.testing.assert_array_equal(res.signals["volts"][i], ref.volts)
        _assert_metrics_equal(res, i, ref)


def test_feedback_only_batch_of_a_position_command_equals_one_run_per_plant():
    """A command given as positions only: the batch derives its velocity and acceleration once for every plant (the
    differences each axis would take from power-on, decision FV27), so plants recording their feedback only run the
    plain kernel; the feedback and metrics stay those of one Axis.run per plant, bit for bit, from a command that
    starts away from 0 and moves both ways."""
    axis = sb.demo_axis()
    cmd = np.concatenate([np.full(15, 7.0), np.linspace(7.0, 907.5, 200), np.full(100, 907.5),
                          np.linspace(907.5, -300.25, 150), np.full(135, -300.25)])
    for signals in (("fb_pos",), ()):
        res = sb.monte_carlo(axis, cmd, spread=SPREAD, n=10, seed=5, signals=signals)
        for i, row in res.parameters.iterrows():
            ref = _one(axis, row.to_dict(), cmd)
            if signals:
                np.testing.assert_array_equal(res.signals["fb_pos"][i], ref.fb_pos)
            _assert_metrics_equal(res, i, ref)


def test_progress_sees_every_plant_and_false_stops_the_batch():
    """progress=(done, total) is called from the calling thread while the workers run and once at the end with every
    plant done; returning False stops the batch (RuntimeError), the plants not started are not run (FV28)."""
    axis = sb.demo_axis()
    calls = []
    res = sb.monte_carlo(axis, STEP, spread=SPREAD, n=400, seed=2, threads=2,
                         progress=lambda done, total: calls.append((done, total)) or True)
    assert calls and calls[-1] == (400, 400) and all(t == 400 for _d, t in calls)
    assert [d for d, _t in calls] == sorted(d for d, _t in calls)
    assert len(res.metrics) == 400
    slow = np.concatenate([np.zeros(20), np.full(20_000, 1000.0)])  # ~0.3 ms a plant: the first poll comes mid-run
    seen = []
    with pytest.raises(RuntimeError, match="progress callback returned False"):
        sb.monte_carlo(axis, slow, spread=SPREAD, n=2000, seed=2, threads=1,
                       progress=lambda done, total: seen.append(done) or False)
    assert seen and seen[0] < 2000
    with pytest.raises(TypeError, match="progress"):
        sb.monte_carlo(axis, STEP, spread=SPREAD, n=4, progress="yes")


def test_same_seed_same_result_whatever_the_threads():
    axis = sb.demo_axis()
    one = sb.monte_carlo(axis, STEP, spread=SPREAD, n=50, seed=7, threads=1)
    two = sb.monte_carlo(axis, STEP, spread=SPREAD, n=50, seed=7, threads=2)
    three = sb.monte_carlo(axis, STEP, spread=SPREAD, n=50, seed=7, threads=3)
    pd.testing.assert_frame_equal(one.metrics, two.metrics)
    pd.testing.assert_frame_equal(one.metrics, three.metrics)
    np.testing.assert_array_equal(one.signals["fb_pos"], two.signals["fb_pos"])
    other = sb.monte_carlo(axis, STEP, spread=SPREAD, n=50, seed=8)
    assert not one.parameters.equals(other.parameters)
    assert one.threads == 1 and two.threads == 2


def test_list_of_axes_and_signals_selection():
    axes = [sb.Axis(**{**sb.batch.axis_spec(sb.demo_axis()),
                       "plant": sb.RigidPlant(inertia_kgm2=j, viscous_nms=1e-4, coulomb_nm=0.005)})
            for j in (1e-4, 2e-4, 3e-4)]
    res = sb.simulate_many(axes, STEP, signals=(), metrics=True)
    assert list(res.parameters.columns) == ["plant.inertia_kgm2"]
    assert res.signals == {}
    assert len(res.metrics) == 3 and res.metrics["overshoot_pct"].notna().all()
    for i, ax in enumerate(axes):
        assert res.metrics.loc[i, "peak_following_error_pulse"] == sb.move_metrics(ax.run(STEP)).peak_following_error_pulse


def test_trajectory_command_uses_its_velocities():
    axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=2000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.2, dwell_after=200)
    res = sb.simulate_many({"law.kp": [38.0, 50.0]}, move, axis=axis, signals=("fb_pos",))
    ref = sb.Axis(**{**sb.batch.axis_spec(axis), "law": axis.law.replace(kp=50.0)}).run(move)
    np.testing.assert_array_equal(res.signals["fb_pos"][1], ref.fb_pos)


def test_bad_input_names_the_parameter():
    axis = sb.demo_axis()
    with pytest.raises(ValueError, match="plant.k_nm_per_rad"):
        sb.simulate_many({"plant.k_nm_per_rad": [1.0]}, STEP, axis=axis)
    with pytest.raises(ValueError, match="row 1.*inertia_kgm2"):
        sb.simulate_many({"plant.inertia_kgm2": [1e-4, -1.0]}, STEP, axis=axis)
    with pytest.raises(ValueError, match="parameters"):
        sb.simulate_many({"plant.inertia_kgm2": [1e-4, float("nan")]}, STEP, axis=axis)
    with pytest.raises(ValueError, match="signals"):
        sb.simulate_many({"law.kp": [1.0]}, STEP, axis=axis, signals=("nope",))
    with pytest.raises(ValueError, match="threads"):
        sb.simulate_many({"law.kp": [1.0]}, STEP, axis=axis, threads=-1)
    with pytest.raises(ValueError, match="moves"):
        sb.simulate_many({"law.kp": [1.0]}, np.zeros(10), axis=axis)
    with pytest.raises(ValueError, match="n = 0"):
        sb.monte_carlo(axis, STEP, spread=SPREAD, n=0)
    with pytest.raises(ValueError, match="low <= high"):
        sb.monte_carlo(axis, STEP, spread={"law.kp": (5.0, 1.0)}, n=3)
    with pytest.raises(TypeError, match="axes_or_table"):
        sb.simulate_many(42, STEP)


def test_spread_accepts_scipy_distributions_and_callables():
    stats = pytest.importorskip("scipy.stats")
    axis = sb.demo_axis()
    spread = {"plant.inertia_kgm2": stats.lognorm(s=0.2, scale=1e-4),
              "law.kp": lambda rng, n: rng.normal(38.0, 2.0, n)}
    a = sb.sample_spread(axis, spread, 20, seed=1)
    b = sb.sample_spread(axis, spread, 20, seed=1)
    pd.testing.assert_frame_equal(a, b)
    assert (a["plant.inertia_kgm2"] > 0).all()


@pytest.fixture(scope="module")
def dask_client():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_dask_local_cluster_equals_the_local_run(dask_client):
    axis = sb.demo_axis()
    local = sb.monte_carlo(axis, STEP, spread=SPREAD, n=40, seed=11, signals=("fb_pos",))
    remote = sb.monte_carlo(axis, STEP, spread=SPREAD, n=40, seed=11, signals=("fb_pos",), client=dask_client,
                            chunk_size=7)
    assert remote.chunks == 6
    pd.testing.assert_frame_equal(local.metrics, remote.metrics)
    np.testing.assert_array_equal(local.signals["fb_pos"], remote.signals["fb_pos"])
    # the scheduler= form: the cluster's address
    by_address = sb.monte_carlo(axis, STEP, spread=SPREAD, n=40, seed=11, signals=(),
                                scheduler=dask_client.scheduler.address)
    pd.testing.assert_frame_equal(local.metrics, by_address.metrics)


def test_dask_local_schedulers_equal_the_local_run():
    pytest.importorskip("dask")
    axis = sb.demo_axis()
    local = sb.monte_carlo(axis, STEP, spread=SPREAD, n=9, seed=2, signals=())
    threaded = sb.monte_carlo(axis, STEP, spread=SPREAD, n=9, seed=2, signals=(), scheduler="threads", chunk_size=2)
    pd.testing.assert_frame_equal(local.metrics, threaded.metrics)
    with pytest.raises(ValueError, match="chunk_size"):
        sb.monte_carlo(axis, STEP, spread=SPREAD, n=9, seed=2, scheduler="sync", chunk_size=0)
    with pytest.raises(ValueError, match="not both"):
        sb.monte_carlo(axis, STEP, spread=SPREAD, n=9, seed=2, scheduler="sync", client=object())
