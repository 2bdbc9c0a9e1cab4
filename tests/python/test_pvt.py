"""PVT tables from Python: the description modes, tables and their limits, the PVT axis at the tick, and bad
input (ValueError naming the parameter and its range; table overflow / empty table as MotionCommandRefused
with return code 1). Manuals in ../shared/seeds/: GUC = 002_b2237d67fd2eb602.txt (digest guc-ecat.md §6.6-6.10),
iDEABOX = 003_2c62cffc310de7fb.txt (digest ideabox.md §6). The full vector list is in
tests/cpp/test_motion_pvt.cpp."""

import math

import numpy as np
import pytest

import servobench as sb

NAN, INF = math.nan, math.inf
T4 = [0, 1000, 2000, 3000]
P4 = [0, 5000, 15000, 20000]


def test_guc_tab4_19_complete_and_tab4_21_percent_from_python():
    # GUC Tab 4-19 (002 L1397-1409): Complete gives 0, 9, 9, 0; p(500) = 1375, v(1500) = 10.5.
    c = sb.pvt_table_complete(time_ms=T4, pos=P4)
    np.testing.assert_allclose(c.vel, [0, 9, 9, 0], atol=1e-12)
    s = c.evaluate([500, 1500])
    assert s["pos"][0] == pytest.approx(1375) and s["vel"][1] == pytest.approx(10.5)
    # GUC Tab 4-21 (002 L1459-1471): percent 60/0/100/0 -> v = 0, 10, 10, 0; the percent moves no point.
    np.testing.assert_array_equal(sb.pvt_percent_calculate(time_ms=T4, pos=P4, percent=[60, 0, 100, 0]),
                                  [0, 10, 10, 0])
    pc = sb.pvt_table_percent(time_ms=T4, pos=P4, percent=[60, 0, 100, 0])
    assert pc.blocks_per_point == [3, 1, 2, 1] and pc.blocks == 7
    s = pc.evaluate([300, 500, 700])
    np.testing.assert_allclose(s["pos"], [214.285714, 928.571429, 2214.285714], atol=1e-5)
    np.testing.assert_allclose(pc.evaluate(T4)["pos"], P4, atol=1e-9)


def test_guc_tab4_22_continuous_both_readings():
    # GUC Tab 4-22 (002 L1490-1500): 3428.57 ms (peak reading, the default) or 3000 ms (average).
    kw = dict(pos=[0, 20000], vel=[0, 0], percent=[60, 0], vel_max=[10, 10], acc=[0.01, 0.01], dec=[0.01, 0.01])
    assert sb.pvt_continuous_calculate(**kw)[1] == pytest.approx(3428.571428571)
    assert sb.pvt_continuous_calculate(**kw, acc_meaning="average")[1] == pytest.approx(3000)
    c = sb.pvt_table_continuous(**kw, time_begin_ms=500)
    assert c.time_ms[0] == 500 and c.time_ms[1] == pytest.approx(3928.571428571)
    ex = sb.pvt_table_continuous_ex(pos=[0, 20000], vel=[0, 0], acc_percent=[60, 0], dec_percent=[0, 0],
                                    vel_max=[10, 10], acc=[0.01, 0.01], dec=[0.01, 0.01])
    assert ex.mode == "continuous_ex" and ex.duration_ms < c.duration_ms  # a T-shaped decel is shorter
    with pytest.raises(ValueError, match="acc_meaning = 'mean' is not one of 'peak', 'average'"):
        sb.pvt_continuous_calculate(**kw, acc_meaning="mean")


def test_guc_tab4_23_pvt_example_drives_a_simulated_axis():
    # GUC Tab 4-23 (002 L1506-1604), iDEABOX Table 4-12 (003 L3088-3197) on a 1 ms tick, then on the demo axis.
    c = sb.pvt_table(time_ms=[0, 1200, 2000, 3000, 3800, 5000], pos=[0, 9750, 24483, 44483, 59216, 68966],
                     vel=[1, 15.25, 20, 20, 15.25, 1])
    tr = sb.pvt_trajectory(c, period_s=1e-3, whole_pulses=False)
    assert len(tr) == 5001
    assert tr.pos[600] == pytest.approx(2737.5) and tr.vel[600] == pytest.approx(8.125)
    assert tr.pos[4400] == pytest.approx(66228.5) and tr.pos[-1] == 68966
    assert tr.acc[100] == pytest.approx(0.011875)
    axis = sb.demo_axis()
    small = sb.pvt_trajectory(sb.pvt_table(time_ms=[0, 10, 20], pos=[0, 500, 1000], vel=[0, 50, 0]),
                              period_s=axis.servo_period_s, dwell_after=200)
    run = axis.run(small)
    assert abs(run.fb_pos[-1] - 1000) < 5


def test_guc_tab4_16_loop_start_delay_and_status():
    # GUC Tab 4-16 (002 L1314-1333): 1000 ms delay once, passes of 3000 ms re-initialised to t = 1000.
    tables = sb.PvtTables()
    tables.download(1, sb.pvt_table(time_ms=[1000, 2000, 3000, 4000], pos=P4, vel=[0, 10, 10, 0]))
    ax = sb.PvtAxis(tables, period_s=1e-3)
    ax.set_loop(2)
    ax.start()
    r = ax.run(999)
    assert np.all(r["pos"] == 0) and ax.time_ms == pytest.approx(999)
    ax.run(3001)
    assert ax.time_ms == pytest.approx(1000) and ax.loop_count == 1 and ax.state[0] == pytest.approx(20000)
    rest = ax.run_until_done()
    assert len(rest) and ax.state[0] == pytest.approx(40000) and not ax.moving and ax.loop_count == 2
    assert ax.loop == 2 and ax.table_id == 1
    endless = sb.pvt_trajectory(tables, loop=0, max_ticks=7000)
    assert len(endless) == 7001 and endless.pos[-1] == 40000  # 1000 ms delay + 2 passes, still going


def test_two_axes_share_one_table_and_start_together():
    tables = sb.PvtTables()
    tables.download(3, sb.pvt_table_complete(time_ms=[0, 500, 1000], pos=[0, 800, 1000]))
    a, b = sb.PvtAxis(tables, period_s=1e-3), sb.PvtAxis(tables, period_s=1e-3, start_pos=-100)
    a.select(3)
    b.select(3)
    sb.pvt_start([a, b])
    assert tables.users(3) == 2
    ra, rb = a.run(1000), b.run(1000)
    np.testing.assert_allclose(rb["pos_exact"], ra["pos_exact"] - 100)  # positions relative to the start
    assert tables.users(3) == 0


def test_table_limits_and_refusals():
    tables = sb.PvtTables()
    assert (sb.PvtTables.TABLES, sb.PvtTables.BLOCKS_PER_TABLE) == (32, 1024)
    t = np.arange(1025.0)
    with pytest.raises(sb.MotionCommandRefused, match="1025 memory blocks, a table holds 1024 .return code 1"):
        tables.download(1, sb.pvt_table(time_ms=t, pos=t, vel=np.zeros_like(t)))
    with pytest.raises(ValueError, match=r"PvtTable.table_id = 33 is outside the allowed range 1..32"):
        tables.download(33, sb.pvt_table(time_ms=[0, 1], pos=[0, 1], vel=[0, 0]))
    assert tables.table(1) is None
    ax = sb.PvtAxis(tables)
    with pytest.raises(sb.MotionCommandRefused, match="table 1 is empty, the start fails"):
        ax.start()
    with pytest.raises(sb.MotionCommandRefused, match="table 2 is empty .return code 1; iDEABOX L7048"):
        ax.select(2)
    tables.download(1, sb.pvt_table(time_ms=[0, 100], pos=[0, 100], vel=[0, 0]))
    ax.start()
    with pytest.raises(sb.MotionCommandRefused, match="an axis is moving on this table"):
        tables.download(1, sb.pvt_table(time_ms=[0, 100], pos=[0, 50], vel=[0, 0]))
    assert int(sb.ReturnCode.COMMAND_ERROR) == 1 and int(sb.ReturnCode.PARAMETER_ERROR) == 7


@pytest.mark.parametrize("call,match", [
    (lambda: sb.pvt_table(time_ms=[0, 10, 10], pos=[0, 1, 2], vel=[0, 0, 0]),
     r"PvtTable.time_ms\[2\] = 10 must be greater than time_ms\[1\]"),
    (lambda: sb.pvt_table(time_ms=[0, 10], pos=[0, NAN], vel=[0, 0]), r"PvtTable.pos\[1\] = nan is not a finite"),
    (lambda: sb.pvt_table(time_ms=[0, 10], pos=[0, 1], vel=[0]), r"PvtTable.vel has 1 values; expected 2"),
    (lambda: sb.pvt_table(time_ms=[5], pos=[0], vel=[0]), r"PvtTable.count = 1 is outside the allowed range 2..1024"),
    (lambda: sb.pvt_table(time_ms=np.zeros((2, 2)), pos=[0, 1], vel=[0, 0]), r"PvtTable.time_ms must be a 1-D"),
    (lambda: sb.pvt_table_ex(time_ms=[0, 10], pos=[0, 1], vel_begin=[0, 0], vel_end=[0, INF]),
     r"PvtTableEx.vel_end\[1\] = inf is not a finite"),
    (lambda: sb.pvt_table_complete(time_ms=[0, 10], pos=[0, 1], vel_end=NAN), r"PvtTableComplete.vel_end = nan"),
    (lambda: sb.pvt_table_percent(time_ms=[0, 10], pos=[0, 1], percent=[-1, 0]),
     r"PvtTablePercent.percent\[0\] = -1 is outside the allowed range 0..100"),
    (lambda: sb.pvt_table_percent(time_ms=[0, 10], pos=[0, 1], percent=[0, 0], vel_begin=INF),
     r"PvtTablePercent.vel_begin = inf"),
    (lambda: sb.pvt_table_continuous(pos=[0, 100], vel=[0, 0], percent=[0, 0], vel_max=[1, 1], acc=[-1, 1],
                                     dec=[1, 1]), r"PvtTableContinuous.acc\[0\] = -1 must be > 0"),
    (lambda: sb.pvt_table_continuous(pos=[0, 100], vel=[0, 0], percent=[0, 0], vel_max=[1, 1], acc=[1, 1],
                                     dec=[0, 1]), r"PvtTableContinuous.dec\[0\] = 0 must be > 0"),
    (lambda: sb.pvt_table_continuous(pos=[0, 100], vel=[0, 2], percent=[0, 0], vel_max=[1, 1], acc=[1, 1],
                                     dec=[1, 1]), r"PvtTableContinuous.vel\[1\] = 2 must point along .* <= vel_max"),
    (lambda: sb.pvt_table_continuous(pos=[0, 0], vel=[0, 0], percent=[0, 0], vel_max=[1, 1], acc=[1, 1],
                                     dec=[1, 1]), r"PvtTableContinuous.pos\[1\] = 0 equals pos\[0\]"),
    (lambda: sb.pvt_table_continuous(pos=[0, 100], vel=[0, 0], percent=[0, 0], vel_max=[1, 1], acc=[1, 1],
                                     dec=[1, 1], time_begin_ms=-1), r"time_begin_ms = -1 is outside"),
    (lambda: sb.pvt_table_continuous_ex(pos=[0, 100], vel=[0, 0], acc_percent=[0, 0], dec_percent=[120, 0],
                                        vel_max=[1, 1], acc=[1, 1], dec=[1, 1]), r"dec_percent\[0\] = 120"),
    (lambda: sb.PvtAxis(sb.PvtTables(), period_s=0), r"PvtAxis.period_s = 0"),
    (lambda: sb.PvtAxis(sb.PvtTables()).set_loop(-1), r"PvtAxis.loop = -1 is outside the allowed range 0..2147483647"),
    (lambda: sb.PvtAxis(sb.PvtTables()).select(0.5), r"PvtTable.table_id = 0.5"),
    (lambda: sb.PvtAxis(sb.PvtTables()).run(-1), r"run.ticks = -1"),
    (lambda: sb.pvt_trajectory(sb.pvt_table(time_ms=[0, 1], pos=[0, 1], vel=[0, 0]), loop=0),
     r"loop = 0 repeats the table forever; give max_ticks"),
])
def test_bad_input_names_the_parameter(call, match):
    with pytest.raises(ValueError, match=match):
        call()
