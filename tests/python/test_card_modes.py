"""Gear, coordinate systems, PVT and FollowEx on the virtual card, through the GT dialect (servobench.dialects.gt)
and the GUC-ECAT / iDEABOX dialect (servobench.dialects.gts): the manuals' example programs give the documented
numbers on the card, and the axes track them in closed loop. Manuals in ../shared/seeds/: GT = 000 (digest gt.md
§3.4, §9), GUC-ECAT = 002 (guc-ecat.md §2, §6), iDEABOX = 003 (ideabox.md §2, §6)."""

import numpy as np
import pytest

import servobench as sb
from servobench.dialects.gt import GtController
from servobench.dialects.gts import GtsController, TCrdPrm

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)
TS = 200e-6  # the tuned law's servo period; the GUC/iDEABOX manuals state none (guc-ecat.md §1)


def tick_of_ms(ms):
    return int(round(ms * 1e-3 / TS))


@pytest.fixture
def gt():
    c = GtController()
    assert c.GT_Open(sb.Card(4, law=LAW)) == 0
    for a in range(1, 5):
        c.GT_Axis(a)
        c.GT_AxisOn()
    return c


@pytest.fixture
def gts():
    c = GtsController()
    assert c.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS)) == 0
    for a in range(1, 5):
        assert c.GT_AxisOn(a) == 0
    return c


def crd_xy(g, **kw):
    prm = TCrdPrm(dimension=2, profile=[1, 2], synVelMax=500, synAccMax=1, **kw)
    assert g.GT_SetCrdPrm(1, prm) == 0


# -- GT electronic gear ------------------------------------------------------------------------------------------

def test_gt_gear_tv10_through_the_dialect(gt):
    # GT L1055-1059 (TV10): GT_Axis(1); GT_PrflG(2); GT_SetRatio(-1); GT_Update() -> dpos1 = -dpos2, bit 10 stays 1.
    assert gt.GT_Axis(1) == 0 and gt.GT_PrflG(2) == 0 and gt.GT_SetRatio(-1) == 0 and gt.GT_Update() == 0
    assert gt.GT_GetMode() == (0, 3 << 11)
    gt.GT_Axis(2)
    for rtn in (gt.GT_PrflT(), gt.GT_SetAcc(0.01), gt.GT_SetVel(2), gt.GT_SetPos(30000), gt.GT_Update()):
        assert rtn == 0
    run = gt.run(16000)
    # axis 1 is numbered below its master: it sees axis 2's previous tick (V51, iDEABOX L487)
    np.testing.assert_array_equal(run[0].pos[1:], -run[1].pos[:-1])
    assert run[1].pos[-1] == 30000
    assert np.all(run[0].moving == 1)                       # bit 10 always set in gear mode (L1090)
    assert np.abs(run[0].error).max() < 20                  # the slave's loop tracks the geared command
    assert abs(run[0].actual_pos[-1] + 30000) <= 2
    gt.GT_Axis(1)
    assert gt.GT_GetSts()[1] & 0x400
    # gear-mode rules: SmthStp, ZeroPos, SetAtlPos invalid (L1144, L1421-1429); aux encoder masters 5/6 not simulated
    assert gt.GT_SmthStp() == 1 and gt.GT_ZeroPos() == 1 and gt.GT_SetAtlPos(0) == 1
    assert gt.GT_PrflG(5) == 1 and gt.GT_PrflG(7) == 7
    assert gt.GT_PrflG(1) == 1                              # its own master
    assert gt.card.mode(0) == "gear"                        # refused calls changed nothing
    assert gt.GT_PrflT() == 0 and gt.card.mode(0) == "t_curve"


def test_gt_gear_tv11_chain_through_the_dialect(gt):
    # GT L4421-4435 (TV11): axis 4 PrflT; axis 1 PrflG(4) ratio -1.5; axis 3 PrflG(1) ratio 0.5; MltiUpdt(0x5).
    for rtn in (gt.GT_Axis(4), gt.GT_PrflT(), gt.GT_Axis(1), gt.GT_PrflG(4), gt.GT_SetRatio(-1.5), gt.GT_Axis(3),
                gt.GT_PrflG(1), gt.GT_SetRatio(0.5), gt.GT_MltiUpdt(0x5)):
        assert rtn == 0
    gt.GT_Axis(4)
    for rtn in (gt.GT_SetAcc(0.02), gt.GT_SetVel(2), gt.GT_SetPos(20000), gt.GT_Update()):
        assert rtn == 0
    run = gt.run(11000)
    d4 = run[3].pos - run[3].pos[0]
    # axis 1 follows axis 4 (numbered below its master: one tick late, V51), axis 3 follows axis 1 the same tick
    np.testing.assert_allclose(run[0].pos[1:], np.round(-1.5 * d4[:-1] + 1e-9), atol=1)
    np.testing.assert_allclose(run[2].pos, np.round(0.5 * run[0].pos), atol=1)
    assert (run[3].pos[-1], run[0].pos[-1], run[2].pos[-1]) == (20000, -30000, -15000)
    for a in (0, 2):
        assert abs(run[a].actual_pos[-1] - run[a].pos[-1]) <= 2


# -- GUC-ECAT / iDEABOX coordinate systems -----------------------------------------------------------------------

HEX = [(200000, 0), (100000, 173205), (-100000, 173205), (-200000, 0), (-100000, -173205), (100000, -173205),
       (200000, 0)]


def run_until_idle(g, crd=1, fifo=0, max_ms=60000):
    n = g.wait_until(lambda: g.GT_CrdStatus(crd, fifo)[1] == 0, max_ticks=tick_of_ms(max_ms), chunk=50)
    return n * TS * 1e3


def test_guc_hexagon_with_buffered_io_on_the_card(gts):
    # GUC L802-843 (guc-ecat.md §6.2), iDEABOX Ex 4-4 L1219-1370: 7 sides of 3000 ms; BufIO 0x55 after side 2,
    # 0xAA after 3, BufDelay 400 after 4, BufIO 0x55 + BufDelay 100 after 5: ends at 21500 ms at (200000, 0).
    crd_xy(gts)
    for i, (x, y) in enumerate(HEX, start=1):
        assert gts.GT_LnXY(1, x, y, 100, 0.1, 0, 0) == 0
        if i == 2:
            assert gts.GT_BufIO(1, 12, 0xFFFF, 0x55) == 0
        elif i == 3:
            assert gts.GT_BufIO(1, 12, 0xFFFF, 0xAA) == 0
        elif i == 4:
            assert gts.GT_BufDelay(1, 400) == 0
        elif i == 5:
            assert gts.GT_BufIO(1, 12, 0xFFFF, 0x55) == 0 and gts.GT_BufDelay(1, 100) == 0
    assert gts.GT_GetRemainderSegNum(1) == (0, 7)
    assert gts.GT_CrdStart(1, 0) == 0
    run = gts.run(tick_of_ms(21600))
    t_ms = (np.arange(len(run)) + 1) * TS * 1e3
    moving = (run[0].moving > 0) | (run[1].moving > 0)
    assert t_ms[np.flatnonzero(moving)[-1]] == pytest.approx(21500, abs=0.5)
    assert gts.GT_CrdStatus(1) == (0, 0, 7)
    assert gts.GT_GetCrdPos(1) == (0, [200000.0, 0.0])
    assert (run[0].pos[-1], run[1].pos[-1]) == (200000, 0)
    dwell = (t_ms > 12001) & (t_ms < 12399)
    assert np.all(run[0].pos[dwell] == -200000) and np.all(run[1].pos[dwell] == 0)
    # closed loop on the simulated plant: the axes track the path
    assert np.abs(run[0].error).max() < 30 and np.abs(run[1].error).max() < 30
    assert abs(run[0].actual_pos[-1] - 200000) <= 2


def test_guc_circle_program_on_the_card(gts):
    # GUC L857-875 (guc-ecat.md §6.3), iDEABOX Ex 4-5: line, full CW circle (centre form), 90 deg CCW (radius
    # form), line home: 17424.78 ms.
    crd_xy(gts)
    assert gts.GT_LnXY(1, 200000, 0, 100, 0.1) == 0
    assert gts.GT_ArcXYC(1, 200000, 0, -100000, 0, 0, 100, 0.1) == 0
    assert gts.GT_ArcXYR(1, 0, 200000, 200000, 1, 100, 0.1) == 0
    assert gts.GT_LnXY(1, 0, 0, 100, 0.1) == 0
    assert gts.GT_ArcXYR(1, 5, 5, 1, 1, 100, 0.1) == 7      # no such arc: 7 (GUC L906)
    assert gts.GT_GetRemainderSegNum(1) == (0, 4)           # the refused arc left nothing
    assert gts.GT_CrdStart(1, 0) == 0
    assert run_until_idle(gts) == pytest.approx(17424.78, abs=10)  # polled every 50 ticks (10 ms)
    assert gts.GT_CrdStatus(1) == (0, 0, 4)
    card = gts.card
    assert (card.profile_pos(0), card.profile_pos(1)) == (0, 0)


def test_guc_lookahead_example_on_the_card(gts):
    # GUC L933-961 (guc-ecat.md §6.4), iDEABOX Ex 4-7: T 5 ms, accMax 1, n 200; 300 collinear-ish lines at
    # v 100, a 0.8: with look-ahead one trapezoid, ~7563 ms.
    crd_xy(gts)
    assert gts.GT_InitLookAhead(1, 0, 5, 1, 200) == 0
    for k in range(300):
        assert gts.GT_LnXY(1, 8000 + 1600 * k, 9000 + 1852 * k, 100, 0.8) == 0
    assert gts.GT_CrdSpace(1) == (0, 4096 - 100)
    assert gts.GT_CrdData(1, None) == 0
    assert gts.GT_CrdStart(1, 0) == 0
    gts.run(tick_of_ms(3000))
    assert gts.GT_GetCrdVel(1) == (0, pytest.approx(100))
    assert run_until_idle(gts) + 3000 == pytest.approx(7563, abs=12)
    assert gts.GT_GetCrdPos(1) == (0, [486400.0, 562748.0])


def test_guc_bufmove_and_bufgear_on_the_card(gts):
    # GUC L1021-1043 (guc-ecat.md §6.5), iDEABOX Ex 4-8: axis 4 moves to 50000 during line 2 (non-modal, from
    # 3828.43 ms) and to 100000 before the arc (modal); the arc ends at 16078.3 ms.
    crd_xy(gts)
    assert gts.GT_LnXY(1, 200000, 200000, 100, 0.1) == 0
    assert gts.GT_BufMove(1, 4, 50000, 30, 0.1, 0) == 0
    assert gts.GT_LnXY(1, 200000, 0, 100, 0.1) == 0
    assert gts.GT_BufMove(1, 4, 100000, 30, 0.1, 1) == 0
    assert gts.GT_ArcXYC(1, -200000, 0, -200000, 0, 0, 100, 0.1) == 0
    assert gts.GT_BufMove(1, 1, 0, 30, 0.1, 0) == 7          # a crd axis cannot be moved (GUC L647)
    assert gts.GT_CrdStart(1, 0) == 0
    run = gts.run(tick_of_ms(16200))
    t_ms = (np.arange(len(run)) + 1) * TS * 1e3
    a4 = run[3].pos
    # the reported whole pulse leaves 0 once 0.05 t^2 >= 0.5 (acc 0.1 pulse/ms^2): sqrt(10) ms after the start,
    # and reaches 50000 as far before the end
    assert t_ms[np.argmax(a4 > 0)] == pytest.approx(3828.43 + 10 ** 0.5, abs=0.5)
    assert t_ms[np.argmax(a4 >= 50000)] == pytest.approx(3828.43 + 1966.67 - 10 ** 0.5, abs=0.5)
    assert a4[-1] == 100000 and abs(run[3].actual_pos[-1] - 100000) <= 2
    crd_moving = (run[0].moving > 0) | (run[1].moving > 0)
    assert t_ms[np.flatnonzero(crd_moving)[-1]] == pytest.approx(16078.3, abs=1)


def test_guc_bufgear_on_the_card(gts):
    # GUC L1080-1104 (guc-ecat.md §6.5), iDEABOX Ex 4-9: +50000 over line 2 (ratio 0.25) and +50000 over the arc.
    crd_xy(gts)
    assert gts.GT_LnXY(1, 200000, 200000, 100, 0.1) == 0
    assert gts.GT_BufGear(1, 4, 50000) == 0
    assert gts.GT_LnXY(1, 200000, 0, 100, 0.1) == 0
    assert gts.GT_BufGear(1, 4, 50000) == 0
    assert gts.GT_ArcXYC(1, -200000, 0, -200000, 0, 0, 100, 0.1) == 0
    assert gts.GT_CrdStart(1, 0) == 0
    run = gts.run(tick_of_ms(16200))
    v4 = np.diff(run[3].pos) / (TS * 1e3)
    assert run[3].pos[-1] == 100000
    assert v4.max() == pytest.approx(25, abs=5.1)  # 25 pulse/ms on the line, whole pulses per 0.2 ms tick


def test_ideabox_ex4_6_fifo1_tool_change_on_the_card(gts):
    # iDEABOX Ex 4-6 (L1713-1900): FIFO0 to (100000, 100000); GT_Stop crd 1 (bit 12, abrupt) once X > 50000;
    # FIFO1 out and back to the stop point; FIFO0 resumes and ends at (100000, 100000).
    crd_xy(gts)
    assert gts.GT_LnXY(1, 100000, 100000, 10, 1) == 0
    assert gts.GT_CrdStart(1, 0) == 0
    gts.run(10)
    assert gts.GT_LnXY(1, 0, 5000, 10, 1, 0, 1) == 1        # FIFO1 data while FIFO0 moves (GUC L1003)
    gts.wait_until(lambda: gts.GT_GetCrdPos(1)[1][0] > 50000, chunk=5)
    assert gts.GT_Stop(1 << 12, 1 << 12) == 0
    gts.wait_until(lambda: gts.GT_CrdStatus(1, 0)[1] == 0)
    stop = [round(p) for p in gts.GT_GetCrdPos(1)[1]]
    for x, y in ((70000, 30000), (110000, 50000)):
        assert gts.GT_LnXY(1, x, y, 10, 1, 0, 1) == 0
    assert gts.GT_CrdStart(1, 1) == 0
    run_until_idle(gts, fifo=1)
    assert gts.GT_CrdStart(1, 0) == 1                       # FIFO0 resumes only at its breakpoint (L1648-1653)
    assert gts.GT_LnXY(1, stop[0], stop[1], 10, 1, 0, 1) == 0
    assert gts.GT_CrdStart(1, 1) == 0
    run_until_idle(gts, fifo=1)
    assert gts.GT_GetCrdPos(1)[1] == pytest.approx(stop, abs=0.5)
    assert gts.GT_CrdStart(1, 0) == 0
    run_until_idle(gts)
    assert gts.GT_GetCrdPos(1) == (0, [100000.0, 100000.0])
    card = gts.card
    gts.run(200)
    assert abs(card.actual_pos(0) - 100000) <= 2 and abs(card.actual_pos(1) - 100000) <= 2


def test_crd_illegal_sequences_return_the_codes_and_change_nothing(gts):
    assert gts.GT_LnXY(1, 10, 10, 100, 0.1) == 1            # crd not set up
    assert gts.GT_SetCrdPrm(1, TCrdPrm(dimension=2, profile=[1, 1], synVelMax=500, synAccMax=1)) == 7  # L785
    assert gts.GT_SetCrdPrm(3, TCrdPrm(dimension=2, profile=[1, 2], synVelMax=500, synAccMax=1)) == 7
    assert gts.GT_SetCrdPrm(1, TCrdPrm(dimension=2, profile=[1, 2], synVelMax=0, synAccMax=1)) == 7
    assert gts.card.mode(0) == "t_curve"
    crd_xy(gts)
    assert gts.GT_SetCrdPrm(2, TCrdPrm(dimension=1, profile=[1], synVelMax=500, synAccMax=1)) == 1  # axis 1 in crd 1
    assert gts.GT_LnXY(1, 10, 10, 0, 0.1) == 7 and gts.GT_LnXY(1, 10, 10, 100, 40000) == 7
    assert gts.GT_LnXY(1, 2**30, 0, 100, 0.1) == 7
    assert gts.GT_BufDelay(1, 16384) == 7 and gts.GT_SetOverride(1, 1.5) == 7
    assert gts.GT_GetRemainderSegNum(1) == (0, 0)
    assert gts.GT_CrdStart(1, 0) == 0                       # nothing buffered: starts and ends at once
    assert gts.GT_LnXY(1, 100000, 0, 100, 0.1) == 0 and gts.GT_CrdStart(1, 0) == 0
    gts.run(50)
    assert gts.GT_CrdClear(1, 0) == 1                       # refused while moving
    assert gts.GT_PrfTrap(1) == 1                           # no mode change while the crd moves
    gts.card.emergency_stop = True
    gts.run(2)
    assert gts.GT_CrdStatus(1) == (0, 0, 0)                 # the e-stop stopped the path (an axis fault)
    assert gts.card.group_info(0)["fault_cause"] == "emergency_stop"
    assert gts.GT_CrdStart(1, 0) == 1                       # refused while the e-stop is active
    assert GtsController().GT_LnXY(1, 1, 1, 1, 1) == -1     # no card open
    assert gts.GT_Open() == -6                              # already open (GUC L176)


def test_limit_on_a_crd_axis_stops_the_path(gts):
    # A hard limit of a crd axis stops the coordinated motion (GT L2011 auto-stop default; GUC stop inputs
    # L625-645): the path stops at once and keeps its breakpoint.
    card = gts.card
    crd_xy(gts)
    assert gts.GT_LnXY(1, 200000, 0, 100, 0.1) == 0 and gts.GT_CrdStart(1, 0) == 0
    gts.run(tick_of_ms(500))
    card.set_limits(0, card.limits(0).replace(pos_active_low=True))   # the +limit input of X now "triggers"
    gts.run(3)
    info = card.group_info(0)
    assert info["fault_stopped"] and info["fault_cause"] == "pos_limit" and info["fault_axis"] == 0
    assert gts.GT_CrdStatus(1) == (0, 0, 0)
    x = card.profile_pos(0)
    gts.run(100)
    assert card.profile_pos(0) == x


# -- PVT on the card -------------------------------------------------------------------------------------------------

def test_guc_pvt_example_on_the_card(gts):
    # GUC L1506-1604 (guc-ecat.md §6.7): samples p/v at t = 600, 1600, 2500, 4400 ms; end 68966.
    t = [0, 1200, 2000, 3000, 3800, 5000]
    p = [0, 9750, 24483, 44483, 59216, 68966]
    v = [1, 15.25, 20, 20, 15.25, 1]
    assert gts.GT_PrfPvt(1) == 0
    assert gts.GT_PvtTable(1, 6, t, p, v) == 0
    assert gts.GT_PvtTableSelect(1, 1) == 0 and gts.GT_PvtStart(1) == 0
    run = gts.run(tick_of_ms(5200))
    pos = run[0].pos
    for t_ms, p_ms in ((600, 2737.5), (1600, 16641.5), (2500, 34483), (4400, 66228.5)):
        assert pos[tick_of_ms(t_ms) - 1] == pytest.approx(p_ms, abs=0.51)
    assert pos[-1] == 68966 and np.abs(run[0].error).max() < 30
    assert gts.GT_PvtStatus(1)[0] == 0 and gts.GT_GetPvtLoop(1) == (0, 1, 1)
    # illegal: start on an empty table, select an empty table, download into a table in use
    assert gts.GT_PvtTableSelect(1, 2) == 1 and gts.GT_PvtStatus(1)[1] == 1
    assert gts.GT_PrfPvt(2) == 0 and gts.GT_PvtTableSelect(2, 3) == 1
    assert gts.GT_PvtStart(4) == 1                          # axis 3 is not in PVT mode


def test_guc_complete_live_table_swap_on_the_card(gts):
    # GUC L1606-1773 (guc-ecat.md §6.8): 40000 sin^2(pi t / 2000), complete mode, infinite loop; a table selected
    # while moving takes over at the next pass boundary (t = 2000 k) with the 1.5x amplitude.
    t = [0, 500, 1000, 1500, 2000]
    assert gts.GT_PrfPvt(1) == 0
    assert gts.GT_PvtTableComplete(1, 5, t, [0, 20000, 40000, 20000, 0], None, None, None, 0, 0) == 0
    assert gts.GT_PvtTableComplete(2, 5, t, [0, 30000, 60000, 30000, 0], None, None, None, 0, 0) == 0
    assert gts.GT_SetPvtLoop(1, 0) == 0 and gts.GT_PvtStart(1) == 0
    run1 = gts.run(tick_of_ms(1000))
    assert run1[0].pos[-1] == 40000
    assert gts.GT_PvtTableSelect(1, 2) == 0
    assert gts.GT_PvtTable(1, 2, [0, 1], [0, 1], [0, 0]) == 1  # table 1 is in use (GUC L1306, iDEABOX L2787)
    run2 = gts.run(tick_of_ms(2000))
    assert run2[0].pos[tick_of_ms(1000) - 1] == 0               # pass 1 ends on table 1 (t = 2000 ms)
    assert run2[0].pos[-1] == 60000                             # pass 2 on table 2 peaks at 60000 (t = 3000 ms)
    assert gts.GT_PvtStatus(1)[1] == 2


def test_guc_percent_two_axes_on_the_card(gts):
    # GUC L1775-1944 (guc-ecat.md §6.9): X loops 2, Y (start delay 2000 ms) loops 3 and feeds forward 15000 per
    # pass; Y is still while X cruises; X ends at 12000 ms at 0, Y at 45000 at 11000 ms.
    assert gts.GT_PrfPvt(1) == 0 and gts.GT_PrfPvt(2) == 0
    assert gts.GT_PvtTablePercent(1, 7, [0, 1000, 2000, 3000, 4000, 5000, 6000],
                                  [0, 5000, 15000, 20000, 15000, 5000, 0], [60, 0, 60, 60, 0, 60, 0], 0) == 0
    assert gts.GT_PvtTablePercent(2, 5, [2000, 2500, 3500, 4000, 5000], [0, 2500, 12500, 15000, 15000],
                                  [60, 0, 60, 0, 0], 0) == 0
    assert gts.GT_PvtTableSelect(1, 1) == 0 and gts.GT_PvtTableSelect(2, 2) == 0
    assert gts.GT_SetPvtLoop(1, 2) == 0 and gts.GT_SetPvtLoop(2, 3) == 0
    assert gts.GT_PvtStart(0b11) == 0
    run = gts.run(tick_of_ms(12100))
    x, y = run[0].pos, run[1].pos
    assert np.all(y[: tick_of_ms(2000)] == 0)
    assert y[tick_of_ms(11000)] == 45000 and x[tick_of_ms(12000)] == 0
    cruise = slice(tick_of_ms(4000) + 1, tick_of_ms(5000))
    assert np.ptp(y[cruise]) == 0
    assert gts.GT_GetPvtLoop(2) == (0, 3, 3)


def test_guc_continuous_on_the_card(gts):
    # GUC L1946-2098 (guc-ecat.md §6.10): X 0 -> 30000, Y 0 -> 20000; vmax 10, acc = dec = 0.01, 100 %: the times
    # 5000 / 4000 ms (peak reading, M24); Y starts 1000 ms late so that both end together.
    args = dict(pVel=[0, 0], pPercent=[100, 100], pVelMax=[10, 10], pAcc=[0.01, 0.01], pDec=[0.01, 0.01])
    rx, tx = gts.GT_PvtContinuousCalculate(2, [0, 30000], **args)
    ry, ty = gts.GT_PvtContinuousCalculate(2, [0, 20000], **args)
    assert (rx, ry) == (0, 0) and tx[1] == pytest.approx(5000) and ty[1] == pytest.approx(4000)
    assert gts.GT_PrfPvt(1) == 0 and gts.GT_PrfPvt(2) == 0
    assert gts.GT_PvtTableContinuous(1, 2, [0, 30000], timeBegin=0, **args) == 0
    assert gts.GT_PvtTableContinuous(2, 2, [0, 20000], timeBegin=tx[1] - ty[1], **args) == 0
    assert gts.GT_PvtTableSelect(1, 1) == 0 and gts.GT_PvtTableSelect(2, 2) == 0 and gts.GT_PvtStart(3) == 0
    run = gts.run(tick_of_ms(5100))
    x, y = run[0].pos, run[1].pos
    assert np.all(y[: tick_of_ms(1000)] == 0)
    end_x = np.flatnonzero(x != 30000)[-1] + 1
    end_y = np.flatnonzero(y != 20000)[-1] + 1
    # both reach their whole-pulse end together, within the last 0.5 pulse of the jerk-limited ramp of 5000 ms
    assert abs(end_x - end_y) <= tick_of_ms(5)
    assert end_x * TS * 1e3 == pytest.approx(5000, abs=100) and end_x <= tick_of_ms(5000)


# -- FollowEx on the card --------------------------------------------------------------------------------------------

def test_ideabox_followex_percent_example_on_the_card(gts):
    # iDEABOX Ex 4-1 (L554-742; ideabox.md §6.1): master axis 1 jogs at 50 pulse/ms (acc 1); slave axis 2 in
    # FollowEx: NORMAL (20000, 10000) 60 %, 1000 EVEN (20, 20), STOP (20000, 10000) 60 %; PASS at 50000 (+);
    # loop 0 (infinite). The slave starts when the master passes 50000 and gains 40000 per 60000 of master.
    assert gts.GT_PrfFollowEx(2, 0) == 0
    assert gts.GT_SetFollowMasterEx(2, 1, 2, 0) == 0
    assert gts.GT_SetFollowExMaxSegment(2, 5000) == 0 and gts.GT_SetFollowMemoryEx(2, 2) == 0
    m, s = 20000, 10000
    assert gts.GT_FollowDataPercentEx(2, m, s, 0, 60) == 0
    for _ in range(1000):
        m, s = m + 20, s + 20
        assert gts.GT_FollowDataPercentEx(2, m, s, 1, 0) == 0
    assert gts.GT_FollowDataPercentEx(2, m + 20000, s + 10000, 2, 60) == 0
    assert gts.GT_FollowSpaceEx(2) == (0, 5000 - 1002)
    assert gts.GT_SetFollowMemoryEx(2, 1) == 1              # the FIFO size is set before the data (L514)
    assert gts.GT_SetFollowEventEx(2, 2, 1, 50000) == 0 and gts.GT_SetFollowLoopEx(2, 0) == 0
    assert gts.GT_FollowStartEx(0b10, 0) == 0
    assert gts.GT_PrfJog(1) == 0 and gts.GT_SetJogPrm(1, 1) == 0 and gts.GT_SetVel(1, 50) == 0
    assert gts.GT_Update(1) == 0
    run = gts.run(tick_of_ms(1025 + 1200 + 1300))
    master, slave = run[0].pos, run[1].pos
    cross = int(np.argmax(master >= 50000))
    assert cross * TS * 1e3 == pytest.approx(1025, abs=1)
    assert np.all(slave[:cross] == 0) and slave[cross + tick_of_ms(20)] > 0  # starts at the PASS (S ramp from 0)
    # one pass: 60000 master pulses -> +40000 slave; the cam ends with the ratio 0 and starts again
    k_end = int(np.argmax(master >= master[cross] + 60000))
    assert slave[k_end] == pytest.approx(40000, abs=2)
    assert gts.GT_GetFollowLoopEx(2) == (0, 2)          # 2500 ms at 50 pulse/ms after the PASS: 2 passes
    assert np.abs(run[1].error).max() < 60
    # illegal while following: clear the FIFO in use, a second start, a master change
    assert gts.GT_FollowClearEx(2, 0) == 1 and gts.GT_FollowStartEx(0b10) == 1
    assert gts.GT_SetFollowMasterEx(2, 3) == 1 and gts.GT_GetFollowMasterEx(2) == (0, 1, 2, 0)


def test_ideabox_followex_complete_example_on_the_card(gts):
    # iDEABOX Ex 4-2 (L744-929; ideabox.md §6.2): 15 knots, ratios 1.0 at both ends, START event; the slave
    # passes through every knot (40000 + 80000 k) as the master passes its knot.
    master = [80413.3639047272, 157154.804159183, 237950.186413352, 318114.127553862, 398779.880063041,
              478874.108217906, 559116.022497938, 638766.227014426, 717913.614082098, 797072.893063808,
              875882.568327684, 954476.131862087, 1033099.7498508, 1127738.87660855, 1212761]
    slave = [40000 + 80000 * k for k in range(15)]
    assert gts.GT_PrfFollowEx(2, 0) == 0 and gts.GT_SetFollowMasterEx(2, 1) == 0
    assert gts.GT_SetFollowMemoryEx(2, 1) == 0
    rtn = gts.GT_FollowDataCompleteEx(2, 0, 15, master, slave, None, None, None, 1.0, 1.0)
    assert rtn == 0 and gts.GT_FollowSpaceEx(2) == (0, 512 - 14)
    assert gts.GT_SetFollowEventEx(2, 1) == 0 and gts.GT_SetFollowLoopEx(2, 1) == 0
    # the master moves by a trap move; the cam starts at the master's present position (master knots are
    # travel from the follow start)
    assert gts.GT_FollowStartEx(0b10) == 0
    assert gts.GT_PrfTrap(1) == 0 and gts.GT_SetTrapPrm(1, 0.5) == 0 and gts.GT_SetVel(1, 400) == 0
    assert gts.GT_SetPos(1, 1212761 - 80413) == 0 and gts.GT_Update(1) == 0
    run = gts.run(tick_of_ms(4000))
    m, s = run[0].pos, run[1].pos
    for mk, sk in zip(master[1:], slave[1:]):
        k = int(np.argmax(m >= mk - master[0]))
        assert s[k] - s[0] == pytest.approx(sk - slave[0], abs=400 * 1.1 * TS * 1e3 + 1)
    assert s[-1] == 1120000
    assert abs(run[1].actual_pos[-1] - 1120000) <= 2


# -- GT coordinated motion on the card (GT L1513-2011, gt.md §4) ---------------------------------------------------

def gt_map_mm(gt, axes=(1, 2), pulse_per_mm=2000):
    # GT L1584-1617 (TV34): 8000 counts/rev, 4 mm lead -> 2000 pulse/mm per axis
    for k, a in enumerate(axes):
        cnt = [0.0] * 5
        cnt[k] = pulse_per_mm
        assert gt.GT_MapAxis(a, cnt) == 0


def test_gt_map_and_immediate_line_tv34_tv37(gt):
    # TV34 (L1584-1617): LnXY(10, 10) mm -> axes 1 and 2 at 20000 pulses. TV37 (Ex 5-5, L1767-1787): SynAcc 1e-7,
    # SynVel 0.01 mm/ST: a triangle, v_pk = sqrt(A L) = 1.189e-3 mm/ST, T = 2 sqrt(L/A) = 23784 ST; a second path
    # command before it completes returns 1 with command status bit 12 (L1800).
    gt_map_mm(gt)
    assert gt.GT_Axis(1) == 0 and gt.card.mode(0) == "coordinated" and gt.GT_GetMode() == (0, 5 << 11)
    assert gt.GT_GetCrdSts() == (0, 0x00D3)                  # idle, closed, segment done, auto-stop, immediate
    assert gt.GT_SetSynVel(0.01) == 0 and gt.GT_SetSynAcc(1e-7) == 0
    assert gt.GT_LnXY(10, 10) == 0
    run = gt.run(100)
    assert gt.GT_LnXYZ(1, 1, 1) == 1 and gt.GT_GetCmdSts() == (0, 1 << 12)
    assert not gt.GT_GetCrdSts()[1] & 1                      # moving
    run = gt.run(23800)
    moving = np.flatnonzero(run[0].moving > 0)
    assert 100 + moving[-1] + 1 == pytest.approx(23784, abs=2)
    assert (run[0].pos[-1], run[1].pos[-1]) == (20000, 20000)
    assert abs(run[0].actual_pos[-1] - 20000) <= 2 and np.abs(run[0].error).max() < 20
    assert np.diff(run[0].pos).max() <= 1.189e-3 * 2000 / 2 ** 0.5 + 1
    assert gt.GT_GetCrdSts()[1] & 1
    gt.GT_Axis(1)
    assert gt.GT_SetPos(5) == 0 and gt.GT_Update() == 1      # independent commands invalid in crd mode (L1659)
    assert gt.GT_MapAxis(1, [1, 0, 0, 0, 5]) == 0            # re-map at rest
    assert gt.GT_MapAxis(3, [0, 0, 0, 0, 5]) == 6            # maps no coordinate (return 6)


def test_gt_buffer_program_tv38(gt):
    # Ex 5-6 (L1899-1921, TV38): MvXYZA(0,0,0,0, 0.01, 1e-8); LnXY(10,10); ArcXY(0,0,123); LnXYZA(0,0,10,12);
    # EndList; StrtMtn. The arc (radius 14.142 about the origin, 45 -> 168 deg CCW) ends at (-13.833, 2.940).
    gt_map_mm(gt, axes=(1, 2, 3, 4))
    assert gt.GT_LnXY(1, 1) == 7                             # no SynVel / SynAcc yet: parameter error
    assert gt.GT_StrtMtn() == 1                              # needs StrtList + Mv (L1843)
    assert gt.GT_StrtList() == 0 and gt.GT_LnXY(10, 10) == 1  # Mv must come first
    for rtn in (gt.GT_MvXYZA(0, 0, 0, 0, 0.01, 1e-8), gt.GT_LnXY(10, 10), gt.GT_ArcXY(0, 0, 123),
                gt.GT_LnXYZA(0, 0, 10, 12), gt.GT_EndList()):
        assert rtn == 0
    sts = gt.GT_GetCrdSts()[1]
    assert sts & 0x2 and not sts & 0x80                      # buffer closed, buffer mode
    assert gt.GT_AddList() == 0 and gt.GT_AddList() == 1 and gt.GT_EndList() == 0
    assert gt.GT_StrtMtn() == 0
    assert gt.GT_StrtMtn() == 1                              # while the buffer executes: bit 12
    ends = []
    for _ in range(400):
        run = gt.run(2000)
        ends.append((run[0].pos[-1], run[1].pos[-1], run[2].pos[-1], run[3].pos[-1]))
        if gt.GT_GetCrdSts()[1] & 1:
            break
    assert ends[-1] == (0, 0, 20000, 24000)
    assert gt.GT_GetCrdSts()[1] & 0x2003 == 0x2003           # finished, closed, buffer empty after the start
    p = gt.card.gt_path()
    arc = sb.PathSegment.arc_center_angle([10, 10, 0, 0], "xy", (0, 0), 123)
    np.testing.assert_allclose(arc.end[:2], [-13.833, 2.940], atol=1e-3)
    assert p.state.segments_done >= 3


def test_gt_streaming_and_estop_resume_tv39(gt):
    # L3348-3357 (TV39): StrtList; MvXYZ(0,0,0,16,3.7); LnXYZ(1234,5678,9013); StrtMtn; ArcXY(2345,6789,360);
    # EndList; EStpMtn: commands streamed after StrtMtn run; EStpMtn -> vector velocity 0 at once, bits 0 and 1
    # set, resumable with StrtMtn (L3336, L1940). Identity map (1 unit = 1 pulse).
    for a in (1, 2, 3):
        cnt = [0.0] * 5
        cnt[a - 1] = 1
        assert gt.GT_MapAxis(a, cnt) == 0
    for rtn in (gt.GT_StrtList(), gt.GT_MvXYZ(0, 0, 0, 16, 3.7), gt.GT_LnXYZ(1234, 5678, 9013), gt.GT_StrtMtn(),
                gt.GT_ArcXY(2345, 6789, 360), gt.GT_EndList()):
        assert rtn == 0
    gt.run(1000)                                             # on the circle (line: ~700 ST)
    assert gt.GT_EStpMtn() == 0
    gt.run(2)
    stop = [gt.card.profile_pos(a) for a in range(3)]
    gt.run(100)
    assert [gt.card.profile_pos(a) for a in range(3)] == stop
    assert gt.GT_GetCrdSts()[1] & 0x3 == 0x3
    brk = gt.GT_GetBrkPnt()[1]
    assert np.hypot(brk[0] - 2345, brk[1] - 6789) == pytest.approx(np.hypot(1111, 1111), abs=1e-6)  # 1571.19
    assert gt.GT_StrtMtn() == 0
    gt.wait_until(lambda: gt.GT_GetCrdSts()[1] & 1, chunk=50, max_ticks=20000)
    assert [gt.card.profile_pos(a) for a in range(3)] == [1234, 5678, 9013]


def test_faults_stop_pvt_and_followex_axes(gts):
    # A soft limit on a PVT axis stops its table motion at once (the card's safety, ADLINK L3983-4010 style
    # soft limits; V54 for driven axes); a FollowEx slave on the master's encoder (masterType 1, L7345-7363)
    # follows the actual position, and an e-stop stops it.
    card = gts.card
    card.set_limits(0, card.limits(0).replace(soft_pos_enabled=True, soft_pos_pulse=3000))
    assert gts.GT_PrfPvt(1) == 0
    assert gts.GT_PvtTable(1, 2, [0, 1000], [0, 10000], [0, 0]) == 0 and gts.GT_PvtStart(1) == 0
    gts.run(tick_of_ms(1000))
    assert abs(card.profile_pos(0) - 3000) < 50 and card.stop_cause(0) == "soft_pos_limit"  # actual reached 3000
    assert not card.moving(0) and gts.GT_GetPvtLoop(1) == (0, 0, 1)
    # FollowEx on the encoder of axis 3
    assert gts.GT_PrfFollowEx(4, 0) == 0 and gts.GT_SetFollowMasterEx(4, 3, 1) == 0
    assert gts.GT_FollowDataPercentEx(4, 10000, 5000, 1, 0) == 0 and gts.GT_SetFollowLoopEx(4, 0) == 0
    assert gts.GT_FollowStartEx(0b1000) == 0
    assert gts.GT_PrfTrap(3) == 0 and gts.GT_SetTrapPrm(3, 0.1) == 0 and gts.GT_SetVel(3, 20) == 0
    assert gts.GT_SetPos(3, 8000) == 0 and gts.GT_Update(0b100) == 0
    gts.run(tick_of_ms(700))
    assert card.profile_pos(3) == pytest.approx(0.5 * card.actual_pos(2), abs=1)   # EVEN ratio 0.5 on the encoder
    card.emergency_stop = True
    gts.run(2)
    assert not card.follow(3).moving and card.stop_cause(3) == "emergency_stop"


def test_gt_syn_parameters_mv_errors_and_a_full_buffer_return_the_manuals_codes(gt):
    # Table 2-1 (L401): SetSynVel/SetSynAcc zero, negative or too large -> 4. Table 2-2: an Mv* error sets command
    # status bit 13 (L476), a path command refused because the buffer is full bit 15 (L477-478: not accepted,
    # send it again); a command in the wrong state stays bit 12 (L1800).
    gt_map_mm(gt)
    assert [gt.GT_SetSynVel(0), gt.GT_SetSynVel(-1), gt.GT_SetSynAcc(0), gt.GT_SetSynAcc(1e9)] == [4] * 4
    assert gt.GT_StrtList() == 0
    assert gt.GT_MvXY(0, 0, 0, 1) == 7 and gt.GT_GetCmdSts() == (0, 1 << 13)       # bad Mv* parameters
    assert gt.GT_MvXY(0, 0, 1, 0.01) == 0
    assert gt.GT_MvXY(0, 0, 1, 0.01) == 1 and gt.GT_GetCmdSts() == (0, 1 << 13)    # a repeated Mv*
    path = gt.card.gt_path()
    filled = 0
    while path.fifo_space > 0:
        assert gt.GT_LnXY(filled % 2, 1) == 0
        filled += 1
    assert path.fifo_size == 4096 and filled in (4095, 4096)                       # the GT buffer of 4096
    before = gt.card.snapshot()
    assert gt.GT_LnXY(5, 5) == 1 and gt.GT_GetCmdSts() == (0, 1 << 15)             # full: re-send later
    assert gt.card.snapshot() == before
