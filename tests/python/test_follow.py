"""FollowEx electronic cam from Python. Manual: ../shared/seeds/003_2c62cffc310de7fb.txt (iDEABOX; digest
ideabox.md §2.1, §6 items 1-2). The rule tests are in tests/cpp/test_motion_follow.cpp."""

import math

import numpy as np
import pytest

import servobench as sb

NAN = math.nan


def jog_master(ticks):
    """The examples' master (003 L716-740): axis 1 jogging at 50 pulse/ms, acc 1 pulse/ms^2, 1 ms tick."""
    g = sb.ProfileGenerator(period_s=1e-3)
    g.command(sb.GeJog(vel=50, acc=1))
    return np.concatenate([[g.state[0]], g.run(ticks)["pos_exact"]])


def test_ideabox_ex4_1_percent_cam_from_python():
    # iDEABOX Ex 4-1 (003 L554-742): cumulative data, PASS at 50000 going positive, infinite loop.
    f = sb.FollowEx(sb.FollowExSetup(max_segment=5000, memory=2, event=2, master_dir=1, event_pos=50000, loop=0))
    m, s = 20000, 10000
    f.data_percent(m, s, sb.FollowSegment.NORMAL, 60)
    for _ in range(1000):
        m, s = m + 20, s + 20
        f.data_percent(m, s, sb.FollowSegment.EVEN)
    f.data_percent(m + 20000, s + 10000, sb.FollowSegment.STOP, 60)
    assert f.space(0) == 5000 - 1002
    tr = sb.follow_trajectory(f, jog_master(2300), whole_pulses=False)
    assert tr.pos[1025] == 0 and tr.pos[1026] > 0          # starts when the master passes 50000
    assert tr.pos[1425] == pytest.approx(10000)            # ratio 0 -> 1 over 20000 master pulses
    assert tr.vel[1625] == pytest.approx(50)               # ratio 1: the master's 50 pulse/tick
    assert tr.pos[2225] == pytest.approx(40000)            # 40000 per 60000 master pulses
    assert f.loop_count == 1 and f.moving


def test_ideabox_ex4_2_complete_cam_from_python():
    # iDEABOX Ex 4-2 (003 L744-929): 15 knots, ratios 1.0 at the ends, memory 1 (512 segments).
    mpos = [80413.3639047272, 157154.737891984, 234538.731662469, 312552.345216181, 391204.578553119,
            470496.431673285, 550428.904576678, 630986.997263298, 712186.709733145, 794025.041986219,
            876494.994022521, 959612.56584205, 1043352.7574448, 1127738.56883079, 1212761]
    spos = [40000 + 80000 * k for k in range(15)]
    f = sb.FollowEx(sb.FollowExSetup(memory=1, loop=0))
    f.data_complete(mpos, spos, ratio_begin=1.0, ratio_end=1.0)
    assert f.size(0) == 14 and f.space(0) == 498
    master = np.arange(0, 1212761 - 80413.3639047272 + 1, 1000.0)
    tr = sb.follow_trajectory(f, np.append(master, 1212761 - 80413.3639047272), whole_pulses=False)
    assert tr.pos[-1] == pytest.approx(1120000)
    assert np.all(np.diff(tr.pos) > 0)
    r = f.ratio
    assert r == pytest.approx(1.0)  # pass end, ratio_end (the next pass starts there too)


def test_follow_cam_ratios_and_segment_types():
    cam = sb.follow_cam(master=[1000, 1000, 1000], slave=[500, 1000, 500], types=[0, 1, 2], percent=[0, 0, 50])
    np.testing.assert_allclose(cam["ratio_begin"], [0, 1, 1])
    np.testing.assert_allclose(cam["ratio_end"], [1, 1, 0])
    assert cam["length"] == 3000 and cam["slave_length"] == 2000
    cont = sb.follow_cam(master=[1000], slave=[500], types=[3], percent=[0], entry_ratio=0.4)
    assert cont["ratio_begin"][0] == pytest.approx(0.4) and cont["ratio_end"][0] == pytest.approx(0.6)


def test_fifo_sizes_switch_and_refusals():
    f = sb.FollowEx()  # memory 0: 16 segments per FIFO (L489-493)
    for i in range(1, 17):
        f.data_percent(100 * i, 50 * i, sb.FollowSegment.EVEN)
    with pytest.raises(sb.MotionCommandRefused, match="the data is lost .return code 1"):
        f.data_percent(1700, 850, sb.FollowSegment.EVEN)
    with pytest.raises(sb.MotionCommandRefused, match="only while moving"):
        f.switch_fifo()
    with pytest.raises(sb.MotionCommandRefused, match="FIFO 1 is empty"):
        f.start(0.0, 1)
    f.data_percent(100, 100, sb.FollowSegment.CONTINUE, fifo=1)
    f.start(0.0)
    with pytest.raises(sb.MotionCommandRefused, match="in use"):
        f.clear(0)
    f.switch_fifo()
    assert f.switch_pending
    out = f.follow(np.arange(1.0, 1701.0))
    assert f.active_fifo == 1 and not f.moving  # loop 1 of FIFO 1 done after the switch
    assert out["pos"][-1] == 900
    f.clear(0)
    assert f.space(0) == 16


@pytest.mark.parametrize("call,exc,match", [
    (lambda f: f.data_percent(100, 10, 7), ValueError, r"FollowDataPercent.type = 7 is outside the allowed range 0..3"),
    (lambda f: f.data_percent(100, 10, 0, 101), ValueError, r"FollowDataPercent.percent = 101 is outside .*0..100"),
    (lambda f: f.data_percent(100.5, 10), ValueError, r"FollowDataPercent.master = 100.5 is not a whole number"),
    (lambda f: f.data_percent(0, 10), ValueError, r"FollowDataPercent.master = 0 repeats the previous value"),
    (lambda f: f.data_percent(100, NAN), ValueError, r"FollowDataPercent.slave = nan"),
    (lambda f: f.data_percent(100, 10, fifo=2), ValueError, r"FollowEx.fifo = 2 is outside the allowed range 0..1"),
    (lambda f: f.data_complete([0], [0]), ValueError, r"FollowDataComplete.n = 1"),
    (lambda f: f.data_complete([0, 10, 5], [0, 1, 2]), ValueError, r"FollowDataComplete.master\[2\] = 5 must continue"),
    (lambda f: f.data_complete([0, 10], [0, 1, 2]), ValueError, r"FollowDataComplete.slave has 3 values; expected 2"),
    (lambda f: f.data_complete([0, 10], [0, 1], ratio_begin=NAN), ValueError, r"FollowDataComplete.ratio_begin"),
    (lambda f: f.step(NAN), ValueError, r"FollowEx.master_pos = nan"),
    (lambda f: f.start(0.0), sb.MotionCommandRefused, r"FIFO 0 is empty"),
    (lambda f: sb.follow_cam(master=[10, -10], slave=[1, 1], types=[0, 0], percent=[0, 0]), ValueError,
     r"FollowCam.master\[1\] reverses"),
    (lambda f: sb.FollowExSetup(memory=2), ValueError, r"FollowExSetup.max_segment = 0 must be set"),
])
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call(sb.FollowEx())
