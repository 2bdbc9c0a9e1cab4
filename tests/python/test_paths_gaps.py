"""FIFO1, buffered limits / stop inputs, GE start velocity and look-ahead in mm/s, ADLINK interpolation, from
Python. Manuals in ../shared/seeds/: GE 001 (L1395-1399, L1666-1727), GUC-ECAT 002 (L609-645, L997-1005),
iDEABOX 003 (Ex 4-6 L1713-1900), ADLINK 004 (L2813-3150); digests ge.md §4, guc-ecat.md §2.2/2.5,
ideabox.md §2.2, adlink.md §6.7."""

import numpy as np
import pytest

import servobench as sb


def test_fifo1_tool_change_example_ideabox_ex4_6():
    # iDEABOX Ex 4-6 (L1713-1900): FIFO0 to (100000, 100000) at 10 pulse/ms, stopped once X > 50000; FIFO1 out
    # and back to the DINT-rounded stop point; FIFO0 resumes and ends at (100000, 100000).
    pair = sb.CrdFifoPair(sb.CoordSystem.identity(2))
    pair.fifo(0).line([100000, 100000], vel=10, acc=1)
    pair.start(0)
    pair.step()
    with pytest.raises(RuntimeError, match="return code 1"):  # FIFO1 data while FIFO0 moves (GUC L1003)
        pair.fifo(1).line([0, 5000], vel=10, acc=1)
    while pair.state.pos[0] <= 50000:
        pair.step()
    pair.stop(abrupt=True)
    pair.step()
    stop = pair.state.pos[:2].copy()
    f1 = pair.fifo(1)
    f1.line([70000, 30000], vel=10, acc=1)
    f1.line([110000, 50000], vel=10, acc=1)
    f1.line([round(stop[0]), round(stop[1])], vel=10, acc=1)
    pair.start(1)
    run = sb.run_path(pair)
    assert pair.active == 1
    np.testing.assert_allclose(run.pos[-1], np.round(stop))
    pair.start(0)
    run = sb.run_path(pair)
    np.testing.assert_allclose(run.pos[-1], [100000, 100000])


def test_buffered_limits_and_stop_io_from_python():
    # GUC L609-645: BufLmtsOff / BufLmtsOn and BufSetStopIo execute at their FIFO position.
    g = sb.PathGenerator(sb.CoordSystem.identity(2))
    g.buf_set_stop_io(axis=1, stop_type=0, input_type=4, input_index=3)
    g.line([1000, 0], vel=10, acc=1)
    g.buf_lmts(axis=2, limit_type=-1, on=False)
    g.line([1000, 1000], vel=10, acc=1)
    g.start()
    run = sb.run_path(g, ticks=5)
    assert g.stop_io(1) == {"stop_type": 0, "input_type": 4, "input_index": 3}
    assert g.state.limits_pos == 0xFFFF
    g.set_input(4, 3, True)
    g.step()
    assert g.stopped and g.state.io_stop_axis == 1 and g.state.speed == 0
    g.set_input(4, 3, False)
    g.start()
    sb.run_path(g)
    assert g.state.limits_pos == 0xFFFD and g.state.limits_neg == 0xFFFD
    with pytest.raises(ValueError, match="BufSetStopIo.input_index = 17"):
        g.buf_set_stop_io(1, 0, 4, 17)
    with pytest.raises(ValueError, match="BufLmtsOn.limit_type = 2"):
        g.buf_lmts(1, 2, True)


def test_ge_start_velocity_and_mm_lookahead():
    # GE L1395-1399, L5754: the path leaves rest at the start velocity (default 0.5 pulse/ms on GE).
    g = sb.PathGenerator(sb.CoordSystem.identity(2), sb.PathSetup(start_vel=0.5))
    g.line([1000, 0], vel=10, acc=0.1)
    g.start()
    run = sb.run_path(g)
    assert run.speed[0] == pytest.approx(0.6)
    assert run.speed[:-1].min() >= 0.5 - 1e-12
    # Module A in mm, mm/s (GE L1681-1727): a straight run of collinear points holds its feed.
    la = sb.GeLookAhead(sb.GeLookAheadParams(t_s=0.005, acc_max=1000, acc=500, vel=50, n=200, con=1000))
    for k in range(1, 101):
        assert la.add_look_data(1, 17, 0, k * 1.0, 0, 0, 50, 0, 0, k, False) == 0
    assert la.add_look_data(1, 17, 0, 100.0, 0, 0, 50, 0, 0, 101, False) == 1
    out = [la.cal_vel() for _ in range(100)]
    assert [o[2] for o in out] == list(range(1, 101))
    assert out[-1][0] == 1 and out[-1][1] == 0.0
    assert all(o[0] == 0 for o in out[:-1])
    assert max(o[1] for o in out) == pytest.approx(50)


def test_adlink_interpolation_modes_from_python():
    # ADLINK T19 (L2829-2855) and T21 (L3138-3143): reference-axis profile; residual 10 % of 1000 -> 900.
    it = sb.AdlinkInterpolator([0, 1])
    it.set_axis_params(0, sb.AdlinkPtp(vm=10000, acc=1e5, dec=1e5))
    it.push("line", target=[1000, 0])
    it.push("line", target=[1000, 1000], mode=sb.BlendMode.BLEND_PERCENT, blend=10)
    run = sb.run_adlink(it)
    k = np.argmax(run.pos[:, 1] > 0)
    assert run.pos[k - 1, 0] <= 900 < run.pos[k, 0] + 1e-9
    np.testing.assert_allclose(run.pos[-1], [1000, 1000])
    assert run.moves_done[-1] == 2
    it3 = sb.AdlinkInterpolator([0, 1, 2])
    it3.set_axis_params(0, sb.AdlinkPtp(vm=20000, acc=2e5, dec=2e5))
    it3.push("spiral_ca", center=[0, 1000, 0], normal=[0, 0, 1], angle_deg=720, height=200, final_radius=500)
    run3 = sb.run_adlink(it3)
    np.testing.assert_allclose(run3.pos[-1], [0, 500, 200], atol=1e-6)
    with pytest.raises(ValueError, match="half or full circle"):
        it3.push("arc3_ce", center=[0, 1000, 200], target=[0, 1500, 200])
    with pytest.raises(ValueError, match="kind = 'circle'"):
        it3.push("circle")
    with pytest.raises(ValueError, match="AdlinkInterpolator.blend = 100"):
        it3.push("line", target=[1, 1, 1], mode=sb.BlendMode.BLEND_PERCENT, blend=100)
