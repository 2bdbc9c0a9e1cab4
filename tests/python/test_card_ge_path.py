"""The GE manual's SX path programs (seed 001 §6, ch12; digest ge.md §4, §7.9-7.11, test vectors §8) on the card
through servobench.dialects.ge: immediate and buffered path motion, the path status word (Table 4-5
L951-968), the command-error bits of the illegal sequences (Table 2-4 L324-347) and look-ahead modules A and B.

`Lnnn` are the manual's line numbers, Tn the digest's test vectors. The axes have a velocity drive (50 pulse/ms
per volt) and Kp = 10, as the examples' AxisInitial (Example 3-4); the long programs run at a 1 ms servo period
(decision V86: the period is the controller's argument) so that they stay fast; positions are checked on the
profile (the planner, L869-871) and the axes' tracking on the actual positions."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects.ge import GeController, TLookAheadMsg

BIT = [1 << k for k in range(16)]
IDLE = BIT[0] | BIT[1] | BIT[4] | BIT[7] | BIT[13]      # Table 4-5 defaults (L951-968)


def make_card(servo_period_s=1e-3, **parts):
    parts.setdefault("drive", sb.VelocityDrive())
    parts.setdefault("law", sb.GtServoLaw(fractional_gains=True))
    return sb.Card(4, servo_period_s=servo_period_s, **parts)


def sx(servo_period_s=1e-3, **parts):
    """An SX card after GT_Open, GT_Reset and AxisInitial(4, 0) with Kp = 10 (Example 3-4, L662-683)."""
    c = GeController("SX", 4, servo_period_s=servo_period_s)
    assert c.GT_Open(make_card(servo_period_s, **parts)) == 0 and c.GT_Reset() == 0
    for a in range(1, 5):
        assert [c.GT_SetKp(a, 10), c.GT_Update(a), c.GT_AxisOn(a), c.GT_ClrSts(a)] == [0] * 4
    c.delay(20)
    return c


def crd(c):
    rtn, s = c.GT_GetCrdSts()
    assert rtn == 0
    return s


def cmd(c):
    rtn, s = c.GT_GetCmdSts()
    assert rtn == 0
    return s


def prf(c):
    return [c.card.profile_pos(a) for a in range(4)]


def run_path(c, max_ms=10**6):
    """Runs until crd bit 0 (no path motion) is 1 again, recording; returns (ms, run)."""
    runs = []
    ticks = 0
    chunk = 1000
    while ticks < max_ms / (c.servo_period_s * 1e3):
        run = c.run(chunk)
        runs.append(run.to_array("pos"))
        ticks += chunk
        if crd(c) & BIT[0]:
            break
    pos = np.hstack(runs)
    moving = np.flatnonzero(np.any(np.diff(pos, axis=1) != 0, axis=0))
    ms = (moving[-1] + 2) * c.servo_period_s * 1e3 if moving.size else 0.0
    return ms, pos


# -- feed parameters and defaults ---------------------------------------------------------------------------------

def test_t4_example_6_1_units():
    # L1339-1357: lead 5 mm, 10000 pulse/rev -> 2000 pulse/mm; 3 m/min, 0.9 m/s^2, 300 pulse/s, 15 m/min, 3 m/s^2
    con = 10000 / 5
    work_vel, work_acc = 3000 / 60 * con / 1000, 0.9e3 * con / 1e6
    start_vel, max_vel, stop_acc = 300 / 1000, 15000 / 60 * con / 1000, 3e3 * con / 1e6
    assert (work_vel, work_acc, start_vel, max_vel, stop_acc) == pytest.approx((100, 1.8, 0.3, 500, 6))
    c = sx()
    assert [c.GT_SetStrtVel(start_vel), c.GT_SetMaxVel(max_vel), c.GT_SetStpAcc(stop_acc),
            c.GT_SetSynVel(work_vel), c.GT_SetSynAcc(work_acc)] == [0] * 5
    # T5 Example 6-2 (L1445-1467, L1490): an immediate line from the current point to (10, 10)
    assert c.GT_LnXY(10, 10) == 0
    assert not crd(c) & BIT[0]
    run_path(c)
    assert prf(c)[:2] == [10, 10] and crd(c) == IDLE


def test_returns_4_and_7_for_bad_feed_and_overrides():
    c = sx()
    assert [c.GT_SetSynVel(0), c.GT_SetSynVel(-1), c.GT_SetSynAcc(0), c.GT_SetMaxVel(0)] == [4] * 4   # L280
    assert [c.GT_Override(0), c.GT_Override(2.5), c.GT_OverrideG0(-1)] == [7] * 3
    assert c.GT_LnXY(100, 0) == 1 and cmd(c) == BIT[8]        # no feed set: a bad path parameter (L335)


def test_t37_start_velocity_default_and_t25_immediate_line():
    # L4958-4970: SetSynVel(3), SetSynAcc(1), LnXY(12345, 67890); StrtVel default 0.5 pulse/ms (L1399)
    c = sx()
    assert [c.GT_SetSynVel(3), c.GT_SetSynAcc(1), c.GT_LnXY(12345, 67890)] == [0] * 3
    c.run(1)
    assert c.GT_GetPrfVel()[1] >= 0.5                         # leaves rest at the start velocity
    ms, pos = run_path(c)
    assert prf(c)[:2] == [12345, 67890]
    length = math.hypot(12345, 67890)
    ramp = (3**2 - 0.5**2) / 1                                # two ramps 0.5 <-> 3 at 1 pulse/ms^2
    expected = 2 * (3 - 0.5) / 1 + (length - ramp) / 3
    assert ms == pytest.approx(expected, abs=3)
    # the line is straight: y/x constant along the way
    assert np.all(np.abs(pos[1] * 12345 - pos[0] * 67890) / length < 1)   # within a pulse of the line
    # every axis tracks in closed loop
    assert max(abs(c.GT_GetAtlPos(a)[1] - prf(c)[a - 1]) for a in (1, 2)) <= 2


def test_t25_g0_line_full_profile():
    # L5048-5062: G0 version with SetSynVel(30): from StrtVel up and back, then stop (L1473-1477)
    c = sx()
    assert [c.GT_SetSynVel(30), c.GT_SetSynAcc(1), c.GT_LnXYG0(12345, 67890)] == [0] * 3
    ms, _ = run_path(c)
    length = math.hypot(12345, 67890)
    expected = 2 * (30 - 0.5) + (length - (30**2 - 0.5**2)) / 30
    assert prf(c)[:2] == [12345, 67890] and ms == pytest.approx(expected, abs=3)


def test_g0_3d_line_full_profile():
    # GT_LnXYZG0 (L1429, L1473-1477): the 3-D form of T25, the same profile along the 3-D length
    c = sx()
    assert [c.GT_SetSynVel(30), c.GT_SetSynAcc(1), c.GT_LnXYZG0(12345, 67890, -5000)] == [0] * 3
    ms, _ = run_path(c)
    length = math.sqrt(12345**2 + 67890**2 + 5000**2)
    expected = 2 * (30 - 0.5) + (length - (30**2 - 0.5**2)) / 30
    assert prf(c)[:3] == [12345, 67890, -5000] and ms == pytest.approx(expected, abs=3)


def test_t36_override_clamped_to_max_vel():
    # L1952-1958: the overridden feed is clamped to MaxVel (T36: MaxVel 500, feed 300 x 2.0 -> 500), here at a
    # fifth of the speeds so that the velocity drive (50 pulse/ms per volt) keeps up: 100, 60 x 2.0 -> 100
    c = sx()
    assert [c.GT_SetMaxVel(100), c.GT_SetSynVel(60), c.GT_SetSynAcc(2), c.GT_Override(2.0)] == [0] * 4
    assert c.GT_LnXY(100000, 0) == 0
    speeds = []
    while not crd(c) & BIT[0]:
        c.run(50)
        speeds.append(c.GT_GetPrfVel()[1])
    assert max(speeds) == pytest.approx(100, rel=1e-6)
    assert c.GT_Override(0.5) == 0 and c.GT_LnXY(0, 0) == 0
    c.run(400)
    assert c.GT_GetPrfVel()[1] == pytest.approx(30, rel=1e-6)    # sticky: 60 x 0.5


# -- arcs ------------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("cmd_name,plane", [(lambda c, *a: c.GT_ArcXY(*a), (0, 1)), (lambda c, *a: c.GT_ArcYZ(*a), (1, 2)),
                                            (lambda c, *a: c.GT_ArcZX(*a), (2, 0))], ids=["xy", "yz", "zx"])
def test_t17_t20_immediate_half_circle(cmd_name, plane):
    # L3448-3465, L3529-3543, L3603-3617: SynVel 5, SynAcc 0.1, Arc(40000, 30000, 180) from (0, 0)
    c = sx()
    assert [c.GT_SetSynVel(5), c.GT_SetSynAcc(0.1)] == [0, 0]
    assert cmd_name(c, 40000, 30000, 180) == 0
    ms, pos = run_path(c)
    i, j = plane
    p = prf(c)
    assert (p[i], p[j]) == (80000, 60000)
    r = np.hypot(pos[i] - 40000, pos[j] - 30000)
    assert np.all(np.abs(r - 50000) < 2)                      # on the circle, r = 50000
    # CCW seen from the positive third axis (L1481-1486): the arc passes (90000, 30000) and (40000, -20000)
    assert pos[i].max() == pytest.approx(90000, abs=1) and pos[j].min() == pytest.approx(-20000, abs=1)
    # length 157080 (T17) at 5 pulse/ms, ramps 0.5 <-> 5 at 0.1 pulse/ms^2
    assert ms == pytest.approx(2 * 4.5 / 0.1 + (math.pi * 50000 - (25 - 0.25) / 0.1) / 5, abs=3)


def test_arc_return_codes_2_and_5():
    # L280-282: 2 radius or chord 0; 5 chord > diameter
    c = sx()
    assert [c.GT_SetSynVel(5), c.GT_SetSynAcc(0.1)] == [0, 0]
    assert c.GT_ArcXY(0, 0, 90) == 2                          # centre = start point: radius 0
    assert c.GT_ArcXYP(40000, 0, 19999, -1) == 5
    assert c.GT_ArcXYP(40000, 0, 0, -1) == 2
    assert c.GT_ArcXYP(0, 0, 100, 1) == 2                     # chord 0
    assert c.GT_ArcXYP(40000, 0, 20000, 0) == 7               # direction must be +1 / -1
    assert c.GT_ArcXY(1000, 0, 361) == 7                      # angle in [-360, 360]
    assert c.GT_LnXY(0, 0) == 3                               # zero length (L280)
    assert c.GT_LnXY(2**31, 0) == 3                           # overflow
    assert crd(c) == IDLE and prf(c) == [0, 0, 0, 0]


@pytest.mark.parametrize("cmd_name,plane,mv", [(lambda c, *a: c.GT_ArcXYP(*a), (0, 1), "GT_MvXY"),
                                               (lambda c, *a: c.GT_ArcYZP(*a), (1, 2), "GT_MvXYZ"),
                                               (lambda c, *a: c.GT_ArcZXP(*a), (2, 0), "GT_MvXYZ")],
                         ids=["xy", "yz", "zx"])
def test_t18_t19_buffered_arc_by_radius(cmd_name, plane, mv):
    # L3490-3505, L3567-3581, L3642-3656: StrtList; Mv(0, 0, [0,] 5, 0.1); ArcP(40000, 0, 20000, -1); EndList
    c = sx()
    assert c.GT_StrtList() == 0
    args = (0, 0, 5, 0.1) if mv == "GT_MvXY" else (0, 0, 0, 5, 0.1)
    assert getattr(c, mv)(*args) == 0
    assert cmd_name(c, 40000, 0, 20000, -1) == 0
    assert [c.GT_EndList(), c.GT_StrtMtn()] == [0, 0]
    _, pos = run_path(c)
    i, j = plane
    assert (prf(c)[i], prf(c)[j]) == (40000, 0)
    # chord = diameter: a CW semicircle about (20000, 0) through (20000, +20000)
    assert pos[j].max() == pytest.approx(20000, abs=1) and pos[j].min() >= -1
    top = pos[j] == pos[j].max()
    assert pos[i][top].min() <= 20000 <= pos[i][top].max()


# -- buffered motion -------------------------------------------------------------------------------------------------

def test_t6_example_6_3_buffer_and_segment_numbers():
    # L1595-1637: StrtList; MvXYZ(0,0,0,100,1.8); LnXY(10,10); ArcXY(0,0,123); LnXYZ(0,0,10); EndList; StrtMtn
    c = sx(servo_period_s=200e-6)
    assert crd(c) == IDLE
    assert c.GT_StrtList() == 0
    assert crd(c) == BIT[0] | BIT[4] | BIT[13]                # buffer open (bit 1 = 0), buffer mode (bit 7 = 0)
    assert [c.GT_MvXYZ(0, 0, 0, 100, 1.8), c.GT_LnXY(10, 10), c.GT_ArcXY(0, 0, 123), c.GT_LnXYZ(0, 0, 10)] == [0] * 4
    assert not crd(c) & BIT[13]                               # buffer not empty
    assert c.GT_EndList() == 0 and crd(c) & BIT[1]
    assert c.GT_StrtMtn() == 0
    seen, arc_end = set(), None
    while True:
        c.run(1)
        s = crd(c)
        seen.add(c.GT_GetMtnNm()[1])
        if c.GT_GetMtnNm()[1] == 2 and not s & BIT[4]:
            arc_end = c.GT_GetSegPnt()[1]
        if s & BIT[0]:
            break
        assert not s & BIT[4] or s & BIT[13] == 0             # a segment executes, or the next is waiting
    assert seen == {1, 2, 3} and c.GT_GetMtnNm() == (0, 3)    # the Mv is segment 0 (L2005-2017)
    # T6 [calc]: r = 14.1421 from 45 deg to 168 deg -> (-13.833, 2.940)
    assert arc_end == pytest.approx([-13.833, 2.940, 0], abs=2e-3)
    assert prf(c)[:3] == [0, 0, 10]
    assert crd(c) == BIT[0] | BIT[1] | BIT[4] | BIT[13]       # done; still buffer mode (bit 7 = 0)


def test_t16_addlist_and_t21_full_circle():
    # L3339-3366 (AddList) and L4037-4062 (EndList): MvXYZ(0,0,0,16,3.7); LnXYZ(1234,5678,9013);
    # ArcXY(2345,6789,360) (a full circle, r = 1571.19); EndList; AddList reopens; StrtMtn
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXYZ(0, 0, 0, 16, 3.7), c.GT_LnXYZ(1234, 5678, 9013),
            c.GT_ArcXY(2345, 6789, 360), c.GT_EndList()] == [0] * 5
    assert c.GT_AddList() == 0 and not crd(c) & BIT[1]        # reopened (L1559-1571)
    assert [c.GT_EndList(), c.GT_StrtMtn()] == [0, 0]
    ms, pos = run_path(c)
    assert prf(c)[:3] == [1234, 5678, 9013]
    r = math.hypot(2345 - 1234, 6789 - 5678)
    assert r == pytest.approx(1571.19, abs=0.01)
    on_arc = pos[2] == 9013
    assert np.all(np.abs(np.hypot(pos[0][on_arc] - 2345, pos[1][on_arc] - 6789) - r) < 2)
    assert pos[0][on_arc].max() == pytest.approx(2345 + r, abs=1)   # went all the way round
    length = math.sqrt(1234**2 + 5678**2 + 9013**2) + 2 * math.pi * r   # 9872.1 for the circle (T21)
    assert 2 * math.pi * r == pytest.approx(9872.1, abs=0.1)
    assert ms > length / 16                                   # at most the feed


@pytest.mark.parametrize("g0", [False, True])
def test_t26_buffered_3d_line(g0):
    # L4988-5003 / L5084-5099: MvXYZ(0,0,0,6,0.3); LnXYZ(12945,58372,65473) or its G0 form; StrtMtn
    c = sx()
    line = c.GT_LnXYZG0 if g0 else c.GT_LnXYZ
    assert [c.GT_StrtList(), c.GT_MvXYZ(0, 0, 0, 6, 0.3), line(12945, 58372, 65473), c.GT_EndList(),
            c.GT_StrtMtn()] == [0] * 5
    ms, _ = run_path(c)
    length = math.sqrt(12945**2 + 58372**2 + 65473**2)
    assert length == pytest.approx(88666, abs=1)
    assert prf(c)[:3] == [12945, 58372, 65473]
    assert ms == pytest.approx(2 * (6 - 0.5) / 0.3 + (length - (6**2 - 0.25) / 0.3) / 6, abs=3)


def test_t27_mvxyza_six_arguments_and_t29_mv_positioning():
    # L5020-5033: MvXYZA(0,0,0,6,0.3,0.5) read as the prototype (x, y, z, a, vel, acc): a = 6 (V110)
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXYZA(0, 0, 0, 6, 0.3, 0.5), c.GT_LnXYZA(100, 200, 300, 400), c.GT_EndList(),
            c.GT_StrtMtn()] == [0] * 5
    c.run(5)
    assert c.GT_GetMtnNm() == (0, 0) and prf(c)[:3] == [0, 0, 0] and prf(c)[3] > 0   # positioning first
    run_path(c)
    assert prf(c) == [100, 200, 300, 400]
    # T29 L5246-5262: MvXY(1000, 2000, 100, 1.8) positions to (1000, 2000) as segment 0
    assert [c.GT_StrtList(), c.GT_MvXY(1000, 2000, 100, 1.8), c.GT_EndList(), c.GT_StrtMtn()] == [0] * 4
    c.run(5)
    assert c.GT_GetMtnNm() == (0, 0) and c.GT_GetSegPnt()[1][:2] == [1000, 2000]
    run_path(c)
    assert prf(c)[:2] == [1000, 2000]


def test_stop_breakpoint_and_restore():
    # L1648-1664: StpMtn closes the buffer and keeps the breakpoint; an immediate line may move away; RestoreMtn
    # returns to the breakpoint by a line and continues; StrtMtn may not resume (bit 9)
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXY(0, 0, 100, 1), c.GT_LnXY(100000, 0), c.GT_LnXY(100000, 50000)] == [0] * 4
    assert c.GT_StrtMtn() == 0
    c.run(500)
    assert c.GT_StpMtn() == 0 and crd(c) & BIT[1]             # closed at once
    run_path(c)
    rtn, brk = c.GT_GetBrkPnt()
    assert rtn == 0 and 0 < brk[0] < 100000 and brk[1] == 0
    assert crd(c) & BIT[0] and not crd(c) & BIT[13]           # stopped with segments left
    assert [c.GT_SetSynVel(20), c.GT_SetSynAcc(1), c.GT_LnXY(brk[0], 3000)] == [0] * 3   # immediate (L1652)
    run_path(c)
    assert prf(c)[1] == 3000
    before = c.card.snapshot()
    assert c.GT_StrtMtn() == 1 and cmd(c) == BIT[9] and c.card.snapshot() == before
    assert c.GT_RestoreMtn() == 0
    run_path(c)
    assert prf(c)[:2] == [100000, 50000]
    assert c.GT_RestoreMtn() == 1 and cmd(c) == BIT[9]         # nothing left (L336-341)


def test_estpmtn_uses_stop_acceleration():
    c = sx()
    assert [c.GT_SetStpAcc(5), c.GT_StrtList(), c.GT_MvXY(0, 0, 100, 1), c.GT_LnXY(400000, 0), c.GT_EndList(),
            c.GT_StrtMtn()] == [0] * 6
    c.run(300)
    v0 = c.GT_GetPrfVel()[1]
    assert v0 > 50
    assert c.GT_EStpMtn() == 0
    ms, _ = run_path(c)
    assert ms == pytest.approx(v0 / 5, abs=2)                 # L1415-1419, L1648: at StpAcc


def test_buffered_io_delay_and_dcc_vel():
    # BufIO between segments (L3750-3756), at most two; Delay one (L3944-3950, ms: V107); BufIO in immediate -1
    c = sx()
    assert c.GT_BufIO(0x5) == -1 and c.GT_Delay(10) == -1     # L3754
    assert [c.GT_StrtList(), c.GT_MvXY(0, 0, 50, 1), c.GT_LnXY(1000, 0), c.GT_BufIO(0x5), c.GT_BufIO(0x7)] == [0] * 5
    assert c.GT_BufIO(0x9) == 1 and cmd(c) == BIT[8]
    assert c.GT_Delay(100) == 0 and c.GT_Delay(100) == 1
    assert c.GT_Delay(8192) == 7
    assert [c.GT_BufIOBit(3, 1), c.GT_SetDccVel(10), c.GT_LnXY(2000, 0), c.GT_LnXY(2000, 1000),
            c.GT_EndList(), c.GT_StrtMtn()] == [0] * 6
    c.run(5)
    assert c.GT_GetMtnNm() == (0, 1) and c.outputs() == 0             # not before segment 1 ends
    c.wait_until(lambda: c.GT_GetMtnNm()[1] == 2)
    assert c.outputs() == 0x7 | 0x8                                    # BufIO 0x7 then BufIOBit 3 with segment 2
    t0 = c.card.tick
    c.wait_until(lambda: c.card.ge_path().state.segments_done == 2)   # end of segment 2: at 10 pulse/ms
    assert c.GT_GetPrfVel()[1] == pytest.approx(10, abs=1.5)
    run_path(c)
    assert prf(c)[:2] == [2000, 1000] and c.card.tick > t0


# -- status bits and illegal sequences ---------------------------------------------------------------------------------

def test_axis_fault_stops_path_bit_9():
    # L2040: a path-axis fault (limit) stops the path automatically; crd bit 9 (Table 4-5)
    c = sx(switches=sb.Switches(pos_limit_rad=2 * math.pi * 0.5))     # +5000 pulse on every axis
    assert [c.GT_SetSynVel(20), c.GT_SetSynAcc(1), c.GT_LnXY(20000, 1000)] == [0] * 3
    run_path(c)
    s = crd(c)
    assert s & BIT[9] and s & BIT[0]
    assert 4000 < prf(c)[0] < 6000 and c.GT_GetSts(1)[1] & BIT[5]
    assert c.GT_StrtMtn() == 1 and cmd(c) == BIT[9]


def _refused(c, call, bit):
    before = c.card.snapshot()
    st = crd(c)
    assert call() == 1
    assert cmd(c) == BIT[bit]
    assert c.card.snapshot() == before and crd(c) == st


def test_illegal_sequences_leave_the_card_unchanged():
    c = sx()
    assert [c.GT_SetSynVel(20), c.GT_SetSynAcc(1), c.GT_LnXY(20000, 0)] == [0] * 3
    c.run(10)
    _refused(c, lambda: c.GT_LnXY(0, 0), 8)                  # path command while moving (L1492)
    _refused(c, lambda: c.GT_SetMaxVel(100), 8)              # max/start vel, stop acc while moving (L335)
    _refused(c, lambda: c.GT_SetStrtVel(1), 8)
    _refused(c, lambda: c.GT_MapCnt(1, 100), 6)              # MapCnt while an axis moves (L333)
    run_path(c)
    assert c.GT_StrtList() == 0
    _refused(c, lambda: c.GT_LnXY(0, 0), 8)                  # no Mv* after StrtList (L335)
    _refused(c, lambda: c.GT_SetSynAcc(1), 8)                # SetSynAcc in buffer mode
    _refused(c, lambda: c.GT_AddList(), 9)                   # AddList while open
    _refused(c, lambda: c.GT_StrtList(), 9)                  # StrtList while open
    _refused(c, lambda: c.GT_MapCnt(1, 100), 6)              # MapCnt while the buffer is open
    assert c.GT_MvXY(20000, 0, 100, 1) == 0
    _refused(c, lambda: c.GT_MvXY(0, 0, 100, 1), 8)          # a repeated Mv*
    _refused(c, lambda: c.GT_LnXYZ(0, 0, 5), 8)              # 3-D after MvXY (L5244)
    assert [c.GT_LnXY(0, 0), c.GT_EndList()] == [0, 0]
    _refused(c, lambda: c.GT_MvXY(0, 0, 100, 1), 8)          # Mv* after the buffer is closed
    _refused(c, lambda: c.GT_EndList(), 9)
    assert c.GT_StrtMtn() == 0
    c.run(10)
    _refused(c, lambda: c.GT_StrtMtn(), 9)                   # StrtMtn while path motion runs (L336)
    _refused(c, lambda: c.GT_StrtList(), 9)                  # StrtList while buffered motion runs
    _refused(c, lambda: c.GT_RestoreMtn(), 9)                # RestoreMtn while moving
    _refused(c, lambda: c.GT_LnXY(5, 5), 8)                  # an immediate command while the path moves
    run_path(c)
    assert c.GT_StrtList() == 0                              # after the buffer finished: allowed


def test_buffer_full_bit_15():
    # L1575-1579, L347: a full buffer refuses the command; re-send when space frees up
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXY(0, 0, 100, 1)] == [0, 0]
    n = 0
    while c.GT_LnXY(10 * (n + 1), 0) == 0:
        n += 1
    assert n == 4096 - 0 and cmd(c) == BIT[15]                # V102: 4096 buffered commands
    assert [c.GT_EndList(), c.GT_StrtMtn()] == [0, 0]


def test_px_card_has_no_path_commands():
    c = GeController("PX", 4, servo_period_s=1e-3)
    assert c.GT_Open(make_card()) == 0
    assert [c.GT_LnXY(10, 10), c.GT_StrtList(), c.GT_GetCrdSts()[0]] == [1, 1, 1]


def test_mapcnt_work_coordinates():
    # L1960-1971, L5179-5187: axis = work coordinate + offset
    c = sx()
    assert [c.GT_MapCnt(1, 1000), c.GT_MapCnt(2, -500)] == [0, 0]
    assert c.GT_GetPrfPnt() == (0, [-1000, 500, 0])
    assert [c.GT_SetSynVel(10), c.GT_SetSynAcc(1), c.GT_LnXY(0, 0)] == [0] * 3
    run_path(c)
    assert prf(c)[:2] == [1000, -500] and c.GT_GetPrfPnt() == (0, [0, 0, 0])


# -- homing Example 7-1 (SX) ---------------------------------------------------------------------------------------------

HOME_SW = sb.Switches(home_min_rad=-2 * math.pi * 0.3, home_max_rad=-2 * math.pi * 0.2)  # -3000..-2000 pulse


def home_ex_7_1(c, axis, pos, offset, vel_high, vel_low):
    """Example 7-1 Home() (L2126-2191), transcribed; the host polls every ms."""
    poll = lambda cond: c.wait_until(cond, chunk=max(1, int(1e-3 / c.servo_period_s)))
    c.GT_ClrSts(axis)
    c.GT_CaptHome(axis)
    c.GT_SetSynVel(vel_high)
    c.GT_SetSynAcc(0.01)
    prf_pos = c.GT_GetPrfPnt()[1]
    prf_pos[axis - 1] = pos
    c.GT_LnXYZ(*prf_pos)
    poll(lambda: crd(c) & 1 or c.GT_GetSts(axis)[1] & 0x8)
    if not c.GT_GetSts(axis)[1] & 0x8:
        return 1
    c.GT_StpMtn()
    poll(lambda: crd(c) & 1)
    _, cap = c.GT_GetCapt(axis)
    c.GT_SetSynVel(vel_low)
    prf_pos[axis - 1] = cap
    c.GT_LnXYZ(*prf_pos)
    poll(lambda: crd(c) & 1)
    prf_pos[axis - 1] += offset
    c.GT_LnXYZ(*prf_pos)
    poll(lambda: crd(c) & 1)
    c.delay(1000)
    c.GT_ZeroPos(axis)
    return 0


def test_t8_sx_home_example_7_1():
    c = GeController("SX", 4, servo_period_s=200e-6)
    assert c.GT_Open(make_card(200e-6, switches=HOME_SW)) == 0 and c.GT_Reset() == 0
    log = []
    c.GT_HookCommand(lambda command, error: log.append((command, error)))
    for a in range(1, 5):
        assert [c.GT_SetKp(a, 10), c.GT_Update(a), c.GT_AxisOn(a), c.GT_ClrSts(a)] == [0] * 4
    assert home_ex_7_1(c, 1, -1000000, 1000, 20, 2) == 0
    assert all(err == 0 for _cmd, err in log), [e for e in log if e[1]]
    assert c.GT_GetPrfPos is not None and c.card.profile_pos(0) == 0
    assert abs(c.GT_GetAtlPos(1)[1]) <= 1
    # the capture is where the load entered the switch window (-2000 pulse), then 1000 pulse back out of it
    assert c.card.axes[0].feedback_pulse == pytest.approx(-2000 + 1000, abs=3)
    # the path works again from the new zero
    assert [c.GT_SetSynVel(5), c.GT_LnXY(100, 0)] == [0, 0]
    run_path(c)
    assert prf(c)[0] == 100


# -- look-ahead ---------------------------------------------------------------------------------------------------------

def polygon_mm(n, radius=50.0, turns=2.0):
    a = np.linspace(0, 2 * math.pi * turns, n + 1)[1:]
    return np.c_[radius * np.cos(a) - radius, radius * np.sin(a)]


def test_module_a_calvel_setdccvel():
    # L1666-1727, L3370-3394, L3790-3800: InitLookAhead, AddLookData, CalVel, then SetDccVel with each segment
    c = sx()
    con = 2000.0
    assert c.GT_InitLookAhead(0.002, 500, 200, 50, 50, con) == 0
    pts = polygon_mm(200)
    assert all(c.GT_AddLookData(1, 17, 0, x, y, 0, 50, 0, 0, k, k + 1, False) == 0 for k, (x, y) in enumerate(pts))
    assert c.GT_AddLookData(1, 17, 0, *pts[-1], 0, 50, 0, 0, 200, 201, False) == 1   # duplicate point (L3374)
    ends = []
    rtn = 0
    assert [c.GT_StrtList(), c.GT_MvXY(0, 0, 100, 0.4)] == [0, 0]
    k = 0
    while rtn == 0:
        rtn, vel, number = c.GT_CalVel()
        ends.append(vel)
        assert number == k + 1
        assert c.GT_SetDccVel(vel * con / 1000) == 0 and c.GT_LnXY(*(pts[k] * con)) == 0
        k += 1
    assert rtn == 1 and k == 200 and ends[-1] == 0                 # the path ends at rest
    # the 3.6 deg corners: |dv| = 2 v sin(theta/2) <= amax T (the planner's corner rule, ge.md §9.10)
    v_corner = 500 * 0.002 / (2 * math.sin(math.radians(360 * 2 / 200) / 2))
    assert v_corner == pytest.approx(15.918, abs=1e-3)
    assert np.allclose(ends[:150], v_corner, rtol=1e-9)
    assert c.GT_CalVel()[0] == 1
    assert [c.GT_EndList(), c.GT_StrtMtn()] == [0, 0]
    ms, _ = run_path(c)
    assert np.allclose(prf(c)[:2], pts[-1] * con, atol=1)
    seg = math.hypot(*(pts[1] - pts[0])) * con                      # 6283 pulse
    v_c = v_corner * con / 1000                                     # pulse/ms
    # each segment from v_c to v_c at 0.4 pulse/ms^2 (never reaching the feed): 2 (v_p - v_c) / a with
    # v_p^2 = v_c^2 + a L; a stop at every corner would take 2 sqrt(L / a) each
    v_p = math.sqrt(v_c**2 + 0.4 * seg)
    assert ms == pytest.approx(200 * 2 * (v_p - v_c) / 0.4, rel=0.02)
    assert ms < 0.75 * 200 * 2 * math.sqrt(seg / 0.4)


def test_t7_example_6_4_module_b():
    # L1819-1940: T = 0.002 s, amax 500, am 200 mm/s^2, con 2000 pulse/mm, 500 look-ahead segments, 8000 lines,
    # MvXYZEx(0,0,0,50); start when msg.error == 3 or CodeNum == AhdLgth; re-send while error == 3; M30 until 0
    c = sx()
    T, amax, am, con, ahd = 0.002, 500, 200, 2000, 500
    total = 8000
    pts = polygon_mm(total, radius=50.0, turns=2.0)
    msg = TLookAheadMsg()
    assert c.GT_InitLookAheadEx(T, amax, am, 199, con) == 7       # n >= 200 (L1776)
    assert c.GT_InitLookAheadExx(T, amax, am, ahd, con) == 0
    assert [c.GT_StrtList(), c.GT_MvXYZEx(0, 0, 0, 50)] == [0, 0]
    motion = False
    fulls = 0
    for j in range(total):
        code = j + 1
        rtn = c.GT_LnXYZEx(pts[j, 0], pts[j, 1], 0, 50, 0, code, msg)
        if msg.error == 3 or code == ahd:
            if not motion:
                assert c.GT_StrtMtn() == 0
                motion = True
            while msg.error == 3:
                fulls += 1
                c.delay(1)                                         # the card runs while the host re-sends
                rtn = c.GT_LnXYZEx(pts[j, 0], pts[j, 1], 0, 50, 0, code, msg)
        assert rtn == 0
    m30 = []
    while True:
        rtn = c.GT_M30(msg)
        m30.append(rtn)
        if rtn == 0:
            break
        c.delay(1)
    assert c.GT_EndList() == 0 and motion and fulls > 0 and set(m30) == {0, 9} and m30[-1] == 0
    c.run(10)
    speeds = []
    while not crd(c) & BIT[0]:
        c.run(20)
        speeds.append(c.GT_GetPrfVel()[1])
    assert np.allclose(prf(c)[:2], pts[-1] * con, atol=1)
    assert c.GT_GetMtnNm() == (0, total)
    # the look-ahead keeps the feed through the 0.09 deg corners: 50 mm/s = 100 pulse/ms for most of the path
    assert max(speeds) == pytest.approx(100, rel=1e-3)
    assert np.mean(np.asarray(speeds) > 95) > 0.8


def test_module_b_messages_and_dcc_flag():
    c = sx()
    msg = TLookAheadMsg()
    assert c.GT_LnXYEx(1, 1, 50, 0, 1, msg) == 1 and msg.error == 8   # no InitLookAheadEx / MvXYEx
    assert [c.GT_InitLookAheadEx(0.002, 500, 200, 200, 2000), c.GT_StrtList(), c.GT_MvXYEx(0, 0, 50)] == [0] * 3
    assert c.GT_LnXYEx(10, 0, 50, 1, 1, msg) == 0 and msg.error == 0    # dccFlag: stops at (10, 0) mm
    assert c.GT_LnXYEx(10, 0, 50, 0, 2, msg) == 1 and msg.error == 1 and msg.mtnNum == 2   # same point
    assert c.GT_BufIOEx(0x3) == 0
    assert c.GT_ArcXYEx(10, 5, 180, 50, 0, 3, msg) == 0                 # CCW half circle to (10, 10) mm
    assert c.GT_ArcXYPEx(0, 10, 5, 1, 50, 0, 4, msg) == 0 and msg.error == 0
    assert c.GT_LnXYEx(0, 0, 50, 0, 5, msg) == 0
    assert c.GT_M30(msg) == 0 and [c.GT_EndList(), c.GT_StrtMtn()] == [0, 0]
    at_corner = []
    while not crd(c) & BIT[0]:
        c.run(1)
        if abs(prf(c)[0] - 20000) <= 1 and prf(c)[1] == 0:
            at_corner.append(c.GT_GetPrfVel()[1])
    # the dccFlag segment ends at rest: the speed dips to the start velocity (0.5) and leaves again at
    # 0.4 pulse/ms^2; the tangent joint would otherwise pass at the feed (100 pulse/ms)
    assert at_corner and min(at_corner) <= 0.5 + 0.4
    assert c.card.ge_path().state.gpo & 0x3 == 0x3
    assert prf(c)[:2] == [0, 0]


def test_t33_segment_number_wraps_after_32767():
    # L2010 vs L4582 (V109): the segment number runs 1..32767, then restarts at 1; the host streams into the
    # buffer, re-sending when it is full (bit 15, L1575-1579)
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXY(0, 0, 100, 10)] == [0, 0]
    total, started, seen = 32769, False, []
    for k in range(1, total + 1):
        while c.GT_LnXY(10 * k, 0) == 1:
            assert cmd(c) == BIT[15]
            if not started:
                assert c.GT_StrtMtn() == 0
                started = True
            c.run(200)
            seen.append(c.GT_GetMtnNm()[1])
    assert c.GT_EndList() == 0
    while not crd(c) & BIT[0]:
        c.run(200)
        seen.append(c.GT_GetMtnNm()[1])
    assert prf(c)[0] == 10 * total
    assert c.GT_GetMtnNm() == (0, 2)                        # 32768 -> 1, 32769 -> 2
    assert max(seen) <= 32767 and any(n > 32000 for n in seen) and seen[-1] == 2


def test_card_ge_crd_setup_validates():
    card = make_card()
    with pytest.raises(ValueError, match="max_vel"):
        card.ge_crd_setup(max_vel=0)
    with pytest.raises(ValueError, match="dim"):
        card.ge_crd_setup(dim=5)
    with pytest.raises(ValueError, match="offsets"):
        card.ge_crd_setup(offsets=[2.0**31])
    assert not card.ge_crd_exists()
    card.ge_crd_setup(offsets=[100], dim=2)
    path = card.ge_path()
    assert path.coords.dim == 2 and list(path.state.pos[:2]) == [-100, 0] and card.group_of(0) == 4
