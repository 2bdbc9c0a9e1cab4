"""Coordinated paths from Python: the manuals' programs (hexagon, circle, look-ahead example, BufMove/BufGear),
coordinate systems, look-ahead properties, bad input. Manuals in ../shared/seeds/: GT = 000_0c49d4aa9b235bd5.txt
(digest gt.md §4, §9), GE = 001_b26ef06a365efe59.txt (ge.md §4, §8), GUC = 002_b2237d67fd2eb602.txt (guc-ecat.md
§2, §6.1-6.5), iDEABOX = 003_2c62cffc310de7fb.txt (ideabox.md §2.2-2.3, §6). The C++ tests
(tests/cpp/test_path_*.cpp) hold the full vector list."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.examples import program_guc_hexagon


def guc(**setup):
    return sb.PathGenerator(sb.CoordSystem.identity(2), sb.PathSetup(**setup))


def test_guc_hexagon_with_buffered_io_ends_at_21500_ms():
    # GUC L802-843 (Fig 4-5; guc-ecat.md §6.2), iDEABOX Ex 4-4 L1219-1370: 7 lines of 3000 ms at v 100, a 0.1;
    # BufIO 0x55 after line 2 (6000 ms), 0xAA after line 3 (9000), BufDelay 400 after line 4 (12000-12400),
    # BufIO 0x55 + BufDelay 100 after line 5 (15400-15500): the program ends at 21500 ms.
    g = program_guc_hexagon(guc())
    g.start()
    r = sb.run_path(g)
    assert r.t_ms[-1] == pytest.approx(21500, abs=1)
    np.testing.assert_array_equal(r.pos[-1], [200000, 0])
    assert r.segments[-1] == 7 and g.remaining_segments == 0
    t_of = lambda mask: r.t_ms[np.argmax(mask)]  # noqa: E731
    assert t_of(r.gpo == 0x55) == pytest.approx(6000, abs=1)
    assert t_of(r.gpo == 0xAA) == pytest.approx(9000, abs=1)
    assert t_of((r.t_ms > 9000) & (r.gpo == 0x55)) == pytest.approx(15400, abs=1)
    dwell = (r.t_ms > 12001) & (r.t_ms < 12399)
    assert np.all(r.speed[dwell] == 0) and np.all(r.pos[dwell] == [-200000, 0])
    assert r.speed.max() == pytest.approx(100)


def test_guc_circle_program_17424_ms_and_the_arc_forms():
    # GUC L857-875 (Fig 4-6; guc-ecat.md §6.3), iDEABOX Ex 4-5 L1448-1592.
    g = guc()
    g.line([200000, 0], vel=100, acc=0.1)
    g.arc_center("xy", [200000, 0], center_offset=(-100000, 0), ccw=False, vel=100, acc=0.1)  # full CW circle
    g.arc_radius("xy", [0, 200000], radius=200000, ccw=True, vel=100, acc=0.1)  # 90 deg about the origin
    g.line([0, 0], vel=100, acc=0.1)
    g.start()
    r = sb.run_path(g)
    assert r.t_ms[-1] == pytest.approx(17424.78, abs=1)
    on_circle = r.segments == 1
    np.testing.assert_allclose(np.hypot(r.pos[on_circle, 0] - 100000, r.pos[on_circle, 1]), 100000, atol=1e-6)
    assert r.pos[on_circle, 1].min() == pytest.approx(-100000, abs=1)  # CW: below the centre first
    np.testing.assert_array_equal(r.pos[-1], [0, 0])


def lookahead_program(g):
    for k in range(300):
        g.line([8000 + 1600 * k, 9000 + 1852 * k], vel=100, acc=0.8)


def test_guc_lookahead_example_holds_speed_100():
    # GUC L933-961 (Figs 4-12..4-14; guc-ecat.md §6.4), iDEABOX Ex 4-7 L2016-2075: T 5 ms, accMax 1, n 200.
    g = guc()
    g.init_lookahead(sb.LookAheadParams(t_ms=5, acc_max=1, n=200))
    lookahead_program(g)
    assert g.window_size == 200 and g.fifo_size == 100
    assert g.flush()
    g.start()
    r = sb.run_path(g)
    assert r.t_ms[-1] == pytest.approx(7563, abs=1)
    cruise = (r.t_ms > 126) & (r.t_ms < 7437)
    assert r.speed[cruise].min() == pytest.approx(100, abs=1e-9)
    off = guc()
    lookahead_program(off)
    off.start()
    r0 = sb.run_path(off)
    assert r0.t_ms[-1] == pytest.approx(33321, abs=3)  # about 33.3 s: 299 triangles peaking at 44.25
    assert r0.speed[r0.t_ms > 300].max() == pytest.approx(44.25, abs=0.01)


def test_guc_bufmove_and_bufgear():
    # GUC L1021-1043, L1080-1104 (guc-ecat.md §6.5), iDEABOX Ex 4-8/4-9 L2163-2510.
    def path(g, between):
        g.line([200000, 200000], vel=100, acc=0.1)
        between(g, 1)
        g.line([200000, 0], vel=100, acc=0.1)
        between(g, 2)
        g.arc_center("xy", [-200000, 0], center_offset=(-200000, 0), ccw=False, vel=100, acc=0.1)
        g.start()
        return sb.run_path(g)

    r = path(guc(), lambda g, i: g.buf_move(4, 50000 * i, 30, 0.1, i == 2))
    a4 = r.aux_position(4)
    assert r.t_ms[np.argmax(a4 > 0)] == pytest.approx(3828.43, abs=2)
    assert r.t_ms[np.argmax(a4 >= 50000)] == pytest.approx(3828.43 + 1966.67, abs=2)
    assert r.t_ms[-1] == pytest.approx(16078.3, abs=2) and a4[-1] == 100000
    rg = path(guc(), lambda g, i: g.buf_gear(4, 50000))
    v4 = np.diff(rg.aux_position(4))
    assert rg.aux_position(4)[-1] == 100000
    assert v4.max() == pytest.approx(25, abs=1e-6)  # ratio 0.25 of the path speed on the line


def test_coordinate_systems():
    # GT L1584-1617 (TV34): 2000 pulse/mm, LnXY(10, 10) -> 20000 pulses on both axes; GT L1665 priority.
    cs = sb.CoordSystem.gt_map([(1, 2000, 0, 0, 0, 0), (2, 0, 2000, 0, 0, 0)])
    g = sb.PathGenerator(cs)
    g.line([10, 10, 0, 0], vel=0.01, acc=1e-5)
    g.start()
    r = sb.run_path(g)
    np.testing.assert_array_equal(r.axis_pos[-1], [20000, 20000])
    assert r.axes == [1, 2]
    # GUC L747-765 (§6.1), iDEABOX Ex 4-3: origin (100, 100).
    crd = sb.CoordSystem.crd_prm(dimension=2, profile=[1, 2], syn_vel_max=500, syn_acc_max=1, even_time_ms=50,
                                 set_origin=True, origin_pos=[100, 100])
    np.testing.assert_array_equal(crd.to_axes([200000, 0]), [200100, 100])
    with pytest.raises(ValueError, match="second profile to the same coordinate"):
        sb.CoordSystem.crd_prm(dimension=2, profile=[1, 1], syn_vel_max=500, syn_acc_max=1)
    with pytest.raises(ValueError, match="return code 6"):
        sb.CoordSystem.gt_map([(1, 0, 0, 0, 0, 5)])


def test_geometry_errors_carry_the_return_codes():
    # GT L393-408: 2 bad radius, 3 line length zero, 5 bad end point or radius; GUC L906 / iDEABOX L1444: 7.
    with pytest.raises(sb.PathGeometryError, match="GT/GE return code 3"):
        sb.PathSegment.line([1, 1], [1, 1])
    with pytest.raises(sb.PathGeometryError, match="GT/GE return code 5; GUC-ECAT/iDEABOX return code 7"):
        sb.PathSegment.arc_radius([0, 0], [40001, 0], "xy", 20000, True)
    with pytest.raises(sb.PathGeometryError, match="return code 2.*full circle|full circle.*return code 2"):
        sb.PathSegment.arc_radius([5, 5], [5, 5], "xy", 10, True)
    assert issubclass(sb.PathGeometryError, ValueError)
    s = sb.PathSegment.arc_center_angle([10, 10], "xy", (0, 0), 123)  # GT TV38 / GE T6
    np.testing.assert_allclose(s.end, [-13.833, 2.940], atol=1e-3)
    assert s.length == pytest.approx(30.36, abs=0.01)


def test_bad_input_names_the_parameter():
    g = guc()
    for call, text in [
        (lambda: g.line([1, 0], vel=0, acc=1), "PathSegment.vel = 0"),
        (lambda: g.line([1, 0], vel=1, acc=math.nan), "PathSegment.acc = nan"),
        (lambda: g.buf_delay(16384), "BufDelay.delay_ms = 16384 is outside the allowed range 0..16383"),
        (lambda: g.buf_io(3, 1, 1), "BufIO.do_type = 3"),
        (lambda: g.buf_da(0, 1), "BufDA.channel = 0"),
        (lambda: g.buf_move(2, 0, 1, 1, True), "is an axis of the coordinate system"),
        (lambda: g.set_override(0), "override = 0"),
        (lambda: g.arc_center("xw", [1, 0], (1, 0), True, 1, 1), "plane = 'xw'"),
    ]:
        with pytest.raises(ValueError, match=text.replace(".", r"\.")):
            call()
    small = guc(fifo_capacity=3)
    for k in range(3):
        small.line([k + 1, 0], vel=1, acc=1)
    with pytest.raises(sb.MotionCommandRefused, match="return code 1"):
        small.line([9, 0], vel=1, acc=1)
    four = sb.PathGenerator(sb.CoordSystem.identity(4))
    with pytest.raises(ValueError, match="at most 3 axes"):
        four.init_lookahead(sb.LookAheadParams())


def corner_run(t_ms, acc_max):
    g = guc()
    g.init_lookahead(sb.LookAheadParams(t_ms=t_ms, acc_max=acc_max, n=200))
    g.line([20000, 0], vel=100, acc=acc_max)
    g.line([20000, 20000], vel=100, acc=acc_max)
    g.flush()
    g.start()
    return sb.run_path(g)


def corner_error(run, corner=(20000, 0), filter_ms=8):
    """Corner error of a machine whose axes follow the command through a moving average of filter_ms (a fixed
    smoothing, like the cards' velocity filters): its closest approach to the sharp corner, unit."""
    w = np.ones(filter_ms) / filter_ms
    fx = np.convolve(run.pos[:, 0], w, mode="valid")
    fy = np.convolve(run.pos[:, 1], w, mode="valid")
    return float(np.min(np.hypot(fx - corner[0], fy - corner[1])))


def test_lookahead_larger_t_or_acc_gives_faster_corners_and_larger_corner_error():
    # GE L1779-1783 (Fig 6-3), GUC L967, iDEABOX L2079-2083: larger T or accMax -> higher corner speed and
    # larger corner error; the acceleration along the path never exceeds accMax (GUC L969-971).
    speeds, errors = [], []
    for t_ms, acc_max in [(1, 0.5), (2, 0.5), (5, 0.5), (5, 1.0), (10, 1.0)]:
        r = corner_run(t_ms, acc_max)
        k = np.argmax(r.segments == 1)
        speeds.append(min(r.speed[k - 1], r.speed[k]))
        errors.append(corner_error(r))
        assert np.max(np.abs(np.diff(r.speed))) <= acc_max * (1 + 1e-9)
        assert r.speed[-1] == 0 and np.all(r.pos[-1] == [20000, 20000])
        # the corner cap acc_max * T / |du| = acc_max * T / sqrt(2), within one cycle of acceleration
        assert speeds[-1] == pytest.approx(acc_max * t_ms / math.sqrt(2), abs=acc_max * 1.0 + 1e-9)
    assert all(b > a for a, b in zip(speeds, speeds[1:]))
    assert all(b > a for a, b in zip(errors, errors[1:]))


def test_stop_and_resume_from_python():
    g = guc()
    g.line([200000, 0], vel=100, acc=0.1)
    g.start()
    sb.run_path(g, ticks=1200)
    g.stop()
    r = sb.run_path(g)
    assert g.stopped and np.allclose(g.breakpoint, [120000, 0]) and r.t_ms[-1] == pytest.approx(2200, abs=1)
    g.move_immediate([120000, 1000], vel=10, acc=0.1)
    sb.run_path(g)
    g.start()  # GT/GE: back to the breakpoint first, then on (GT L1940, GE L1660)
    r = sb.run_path(g)
    assert np.all(r.pos[-1] == [200000, 0]) and r.segments[-1] == 1


def test_plan_polyline_lookahead_and_plot():
    pts = np.column_stack([np.arange(0, 10001, 10.0), np.zeros(1001)])
    v = sb.plan_polyline_lookahead(pts, 100, 1, sb.LookAheadParams(t_ms=5, acc_max=1, n=200))
    assert len(v) == 1000 and v[-1] == 0 and v.max() == pytest.approx(math.sqrt(2 * 1 * 10 * 200))
    assert sb.paths.corner_speed_limit([1, 0], [0, 1], 5, 1) == pytest.approx(5 / math.sqrt(2))
    ax = corner_run(5, 1).plot_xy(title="corner")
    assert ax.get_title() == "corner"
