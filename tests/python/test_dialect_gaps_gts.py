"""GUC-ECAT / iDEABOX dialect functions that no other test called (docs/coverage.md "Untested"), each checked
against what the manuals say (GUC-ECAT seed 002, iDEABOX seed 003 = ../shared/seeds/00[23]_*.txt, `Lnnn` their
lines; digests spec/guc-ecat.md, spec/ideabox.md). Units pulse, ms, pulse/ms, pulse/ms^2; servo period 200 us."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import gts as G
from servobench.dialects.gts import GtsController, TCrdPrm
from test_card_modes import LAW, TS, crd_xy, gts, run_until_idle, tick_of_ms  # noqa: F401 (gts: the fixture)


def crd_xyz(g, dim=3):
    prm = TCrdPrm(dimension=dim, profile=list(range(1, dim + 1)), synVelMax=500, synAccMax=1)
    assert g.GT_SetCrdPrm(1, prm) == 0


def record(g, ms, axes=(0, 1, 2)):
    run = g.run(tick_of_ms(ms))
    return np.vstack([run[a].pos for a in axes])


# -- coordinate system parameters, stop decelerations, user segment numbers ------------------------------------

def test_get_crd_prm_reads_back_set_crd_prm_guc_l389(gts):
    # GT_GetCrdPrm (GUC L317, L389): the parameters GT_SetCrdPrm set (L369-388); crd 1..2 (else 7); a crd never set
    # up has none (1).
    assert gts.GT_GetCrdPrm(1)[0] == 1
    prm = TCrdPrm(dimension=2, profile=[0, 2, 1, 0], synVelMax=123.5, synAccMax=2.5, evenTime=10, setOriginFlag=1,
                  originPos=[100, -200])
    assert gts.GT_SetCrdPrm(1, prm) == 0
    rtn, got = gts.GT_GetCrdPrm(1)
    assert rtn == 0
    assert (got.dimension, got.synVelMax, got.synAccMax, got.evenTime, got.setOriginFlag) == (2, 123.5, 2.5, 10, 1)
    assert list(got.profile[:4]) == [0, 2, 1, 0] and list(got.originPos[:2]) == [100, -200]
    assert gts.GT_GetCrdPrm(2)[0] == 1 and gts.GT_GetCrdPrm(3) == (7, None)
    assert GtsController().GT_GetCrdPrm(1) == (-1, None)


def test_set_crd_stop_dec_sets_the_stop_decelerations_guc_l704_709(gts):
    # GT_SetCrdStopDec (GUC L704-709; iDEABOX L7182-7201): the smooth-stop and emergency-stop path decelerations,
    # (0, 32767) pulse/ms^2. GT_Stop of the crd (bit 12, option bit 12 = abrupt, iDEABOX Ex 4-6 L1793) uses them.
    crd_xy(gts)
    assert gts.GT_SetCrdStopDec(1, 0.05, 2) == 0
    for option in (0, 1 << 12):
        assert gts.GT_CrdClear(1) == 0 and gts.GT_LnXY(1, 200000, 0, 20, 1) == 0 and gts.GT_CrdStart(1, 0) == 0
        gts.run(tick_of_ms(100))
        assert gts.GT_GetCrdVel(1)[1] == pytest.approx(20)
        assert gts.GT_Stop(1 << 12, option) == 0
        vel = []
        for _ in range(tick_of_ms(500)):
            gts.run(1)
            vel.append(gts.GT_GetCrdVel(1)[1])
        vel = np.asarray(vel)
        stop_ms = (np.flatnonzero(vel > 0)[-1] + 1) * TS * 1e3
        dec = 0.05 if option == 0 else 2
        assert stop_ms == pytest.approx(20 / dec, abs=0.5)                 # 400 ms smooth, 10 ms abrupt
        assert np.diff(vel[vel > 0]).min() >= -dec * TS * 1e3 - 1e-9       # never faster than dec
        gts.run(tick_of_ms(50))
    assert [gts.GT_SetCrdStopDec(1, 0, 1), gts.GT_SetCrdStopDec(1, 1, 32767), gts.GT_SetCrdStopDec(3, 1, 1)] == [7] * 3
    assert GtsController().GT_SetCrdStopDec(1, 1, 1) == -1


def test_user_segment_numbers_follow_the_executing_segment_guc_l662_670(gts):
    # GT_SetUserSegNum (GUC L662-665): a buffered user number; GT_GetUserSegNum (L666-670) reads the number of the
    # segment being executed. Each FIFO has its own (fifo 0..1, else 7).
    crd_xy(gts)
    assert gts.GT_GetUserSegNum(1) == (0, 0)
    for num, (x, y) in ((101, (10000, 0)), (202, (10000, 10000)), (-7, (0, 10000))):
        assert gts.GT_SetUserSegNum(1, num) == 0 and gts.GT_LnXY(1, x, y, 100, 1) == 0
    assert gts.GT_GetUserSegNum(1) == (0, 0)                                 # buffered: nothing runs yet
    assert gts.GT_CrdStart(1, 0) == 0
    seen = []
    while gts.GT_CrdStatus(1)[1]:
        gts.run(tick_of_ms(10))
        seen.append((gts.GT_GetCrdPos(1)[1], gts.GT_GetUserSegNum(1)[1]))
    for (x, y), num in seen[:-1]:
        expected = 101 if y == 0 else (202 if x == 10000 else -7)
        if 0 < x < 10000 or 0 < y < 10000:
            assert num == expected
    assert {num for _, num in seen} == {101, 202, -7}
    assert seen[-1][1] == -7 and gts.GT_GetUserSegNum(1, 1) == (0, 0)
    assert gts.GT_SetUserSegNum(1, 2 ** 31) == 7 and gts.GT_GetUserSegNum(1, 2)[0] == 7


# -- buffered DA, limits and stop inputs ------------------------------------------------------------------------

def test_buf_da_sets_the_dac_when_its_place_in_the_fifo_executes_guc_l603_608(gts):
    # GT_BufDA (GUC L603-608): DA channel 1..8, -32768..32767 (-10..10 V), executed in order with the segments.
    crd_xy(gts)
    f = gts.card.crd(1).fifo(0)
    assert [gts.GT_LnXY(1, 10000, 0, 100, 1), gts.GT_BufDA(1, 3, -16384), gts.GT_LnXY(1, 20000, 0, 100, 1),
            gts.GT_BufDA(1, 3, 32767), gts.GT_BufDA(1, 8, 1000), gts.GT_CrdStart(1, 0)] == [0] * 6
    da3 = []
    x = []
    for _ in range(tick_of_ms(600) // 10):
        gts.run(10)
        da3.append(f.state.da[2])
        x.append(gts.card.profile_pos(0))
    da3, x = np.asarray(da3), np.asarray(x)
    assert np.all(da3[x < 10000] == 0)                                      # not before segment 1 ends
    assert np.all(da3[(x > 10000) & (x < 20000)] == -16384)                 # from the end of segment 1
    assert da3[-1] == 32767 and f.state.da[7] == 1000 and f.state.da[0] == 0
    assert [gts.GT_BufDA(1, 0, 1), gts.GT_BufDA(1, 9, 1), gts.GT_BufDA(1, 1, 32768), gts.GT_BufDA(1, 1, 0.5)] == [7] * 4
    assert gts.GT_BufDA(3, 1, 1) == 7


def test_buf_lmts_and_buf_set_stop_io_change_the_fifo_at_their_place_guc_l609_645(gts):
    # GT_BufLmtsOff / GT_BufLmtsOn (GUC L609-624): buffered disable / enable of an axis's positive (0), negative
    # (1) or both (-1) limits; GT_BufSetStopIo (L625-645): buffered mapping of an input (0 +limit, 1 -limit,
    # 2 alarm, 3 home, 4 GPI) to a stop of the axis, 0 emergency / 1 smooth. They take effect at their FIFO place
    # (C28, C29), and an active mapped input then stops the path with its stop type.
    crd_xy(gts)
    assert gts.GT_SetCrdStopDec(1, 0.1, 5) == 0
    f = gts.card.crd(1).fifo(0)
    assert [gts.GT_LnXY(1, 10000, 0, 20, 1), gts.GT_BufLmtsOff(1, 2, G.MC_LIMIT_NEGATIVE),
            gts.GT_BufSetStopIo(1, 1, 1, G.MC_GPI, 16), gts.GT_LnXY(1, 100000, 0, 20, 1),
            gts.GT_BufLmtsOff(1, 3), gts.GT_BufLmtsOn(1, 2, -1)] == [0] * 6
    gts.GT_CrdStart(1, 0)
    gts.run(tick_of_ms(100))
    assert (f.state.limits_pos, f.state.limits_neg) == (0xFFFF, 0xFFFF)   # not yet executed
    assert f.stop_io(1) is None
    gts.run(tick_of_ms(500))                                               # in segment 2 (10000 at 20/ms)
    assert (f.state.limits_pos, f.state.limits_neg) == (0xFFFF, 0xFFFD)   # axis 2 negative off
    assert f.stop_io(1) == {"stop_type": 1, "input_type": G.MC_GPI, "input_index": 16}
    f.set_input(G.MC_GPI, 16, True)                                        # GPI 16 active: smooth stop
    vel = []
    for _ in range(tick_of_ms(300)):
        gts.run(1)
        vel.append(gts.GT_GetCrdVel(1)[1])
    assert f.state.io_stop_axis == 1 and vel[-1] == 0
    assert (np.flatnonzero(np.asarray(vel) > 0)[-1] + 1) * TS * 1e3 == pytest.approx(20 / 0.1, abs=1)
    f.set_input(G.MC_GPI, 16, False)
    assert gts.GT_CrdStart(1, 0) == 0                                      # resumes from the breakpoint
    run_until_idle(gts)
    assert gts.GT_GetCrdPos(1)[1] == [100000.0, 0.0]
    assert (f.state.limits_pos, f.state.limits_neg) == (0xFFFB, 0xFFFB)   # axis 3 both off, axis 2 back on
    # ranges (C30): axis 1..8, limitType -1/0/1; stopType 0/1, inputType 0..4, index 1..8 (GPI 1..16)
    assert [gts.GT_BufLmtsOn(1, 9), gts.GT_BufLmtsOff(1, 1, 2), gts.GT_BufSetStopIo(1, 1, 2, 4, 1),
            gts.GT_BufSetStopIo(1, 1, 0, 5, 1), gts.GT_BufSetStopIo(1, 1, 0, G.MC_HOME, 9),
            gts.GT_BufSetStopIo(1, 1, 0, G.MC_GPI, 17)] == [7] * 6
    assert gts.GT_BufSetStopIo(1, 1, 0, G.MC_GPI, 16) == 0


def test_buf_set_stop_io_on_the_home_switch_stops_the_path_on_the_card():
    # GUC L625-645: a home input mapped by BufSetStopIo stops the crd when the axis's home switch becomes active.
    rad = 2 * math.pi / 10000
    g = GtsController()
    g.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS, switches=sb.Switches(home_min_rad=5000 * rad,
                                                                          home_max_rad=8000 * rad)))
    for a in (1, 2):
        g.GT_AxisOn(a)
    crd_xy(g)
    assert [g.GT_BufSetStopIo(1, 1, 0, G.MC_HOME, 1), g.GT_LnXY(1, 20000, 0, 20, 1), g.GT_CrdStart(1, 0)] == [0] * 3
    g.run(tick_of_ms(1000))
    assert g.card.profile_pos(0) < 9000


def test_buf_lmts_off_lets_the_path_pass_the_limit_on_the_card():
    # GUC L609-624: after a BufLmtsOff of axis 1 has executed, its limit switch no longer stops the path.
    rad = 2 * math.pi / 10000
    g = GtsController()
    g.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS, switches=sb.Switches(pos_limit_rad=5000 * rad)))
    for a in (1, 2):
        g.GT_AxisOn(a)
    crd_xy(g)
    assert [g.GT_BufLmtsOff(1, 1, -1), g.GT_LnXY(1, 1000, 0, 20, 1), g.GT_LnXY(1, 20000, 0, 20, 1),
            g.GT_CrdStart(1, 0)] == [0] * 4
    g.run(tick_of_ms(1500))
    assert g.card.crd(1).fifo(0).state.limits_pos == 0xFFFE                # the flag is off
    assert g.card.profile_pos(0) == 20000                                  # the card lets the path pass (V129)


# -- YZ / ZX arcs and the 4-D G0 line ---------------------------------------------------------------------------

def test_yz_and_zx_arcs_by_centre_and_radius_guc_l541(gts):
    # GT_ArcYZC / GT_ArcZXC (GUC L334, L541; iDEABOX L3941, L4070): arc in the YZ / ZX plane to the end point, the
    # centre given as an offset from the start point; GT_ArcYZR / GT_ArcZXR (iDEABOX L4002, L4131): radius > 0 the
    # arc <= 180 deg. circleDir 0 clockwise, 1 counter-clockwise (GUC L509-587).
    crd_xyz(gts)
    v, a = 50, 1
    assert [gts.GT_LnXYZ(1, 0, 10000, 0, v, a),
            gts.GT_ArcYZC(1, 0, 10000, -10000, 0, 1, v, a),      # YZ CCW about (y, z) = (0, 0): to (0, 0, 10000)
            gts.GT_ArcYZR(1, -10000, 0, 10000, 1, v, a),          # YZ CCW r 10000 (minor): to (0, -10000, 0)
            gts.GT_LnXYZ(1, 0, -10000, 10000, v, a),
            gts.GT_ArcZXC(1, 0, 10000, -10000, 0, 1, v, a),       # ZX CCW about (z, x) = (0, 0): to (10000, -10000, 0)
            gts.GT_ArcZXR(1, -10000, 0, 10000, 0, v, a),          # ZX CW r 10000: to (0, -10000, -10000)
            gts.GT_CrdStart(1, 0)] == [0] * 7
    pos = []
    while gts.GT_CrdStatus(1)[1] or not pos:
        run = gts.run(200)
        pos.append(np.vstack([run[k].pos for k in range(3)]))
    pos = np.hstack(pos)
    ends = [(0, 10000, 0), (0, 0, 10000), (0, -10000, 0), (0, -10000, 10000), (10000, -10000, 0), (0, -10000, -10000)]
    idx, i = [], 0
    for e in ends:
        d = np.linalg.norm(pos[:, i:].T - np.asarray(e, float), axis=1)
        i += int(np.argmin(d))
        assert d.min() <= v * TS * 1e3                                     # every end point, in order
        idx.append(i)
    seg = lambda n: pos[:, idx[n - 1]:idx[n] + 1]                         # noqa: E731
    for n, sign in ((1, 1), (2, 1)):                                       # the two YZ arcs: x = 0, r = 10000, CCW
        x, y, z = seg(n)
        assert np.abs(x).max() == 0 and np.abs(np.hypot(y, z) - 10000).max() <= 1.5
        assert np.all(sign * np.diff(np.unwrap(np.arctan2(z, y))) >= -1e-9)
    x, y, z = seg(4)                                                       # ZX CCW about (0, 0)
    assert np.all(y == -10000) and np.abs(np.hypot(z, x) - 10000).max() <= 1.5
    assert np.all(np.diff(np.unwrap(np.arctan2(x, z))) >= -1e-9)
    x, y, z = seg(5)                                                       # ZX CW about (z, x) = (-10000, 10000)
    assert np.all(y == -10000) and np.abs(np.hypot(z + 10000, x - 10000) - 10000).max() <= 1.5
    assert np.all(np.diff(np.unwrap(np.arctan2(x - 10000, z + 10000))) <= 1e-9)
    # bad input: circleDir 0/1, a radius arc that cannot reach (7, GUC L892), a coordinate out of range
    assert gts.GT_ArcYZC(1, 0, 0, 1, 1, 2, v, a) == 7
    assert gts.GT_ArcZXR(1, 90000, 0, 100, 1, v, a) == 7
    assert gts.GT_ArcYZR(1, 2 ** 31, 0, 100, 1, v, a) == 7


def test_lnxyzag0_4d_line_ends_at_rest_under_look_ahead_guc_l322_327(gts):
    # GT_LnXYZAG0 (GUC §5.2; the G0 lines end at rest even under look-ahead, GUC L322-327, iDEABOX L1594-1606): a
    # 4-D rapid line to the absolute point. Two G01 lines then a G0 then a G01, look-ahead on: the G0 ends at rest.
    crd_xyz(gts, 4)
    end = (30000, -20000, 10000, 5000)
    assert [gts.GT_LnXYZA(1, 10000, 0, 0, 0, 50, 1), gts.GT_LnXYZAG0(1, *end, 50, 1),
            gts.GT_LnXYZA(1, 40000, -20000, 10000, 5000, 50, 1), gts.GT_CrdStart(1, 0)] == [0] * 4
    pos = []
    while gts.GT_CrdStatus(1)[1] or not pos:
        run = gts.run(200)
        pos.append(np.vstack([run[k].pos for k in range(4)]))
    pos = np.hstack(pos)
    k = int(np.flatnonzero(np.all(pos.T == end, axis=1))[0])
    assert np.linalg.norm(pos[:, k] - pos[:, k - 1]) <= 1.5                # at rest at the G0's end
    d = np.asarray(end) - np.array([10000, 0, 0, 0])
    j = int(np.flatnonzero(pos[0] > 10000)[0])
    t = d @ (pos[:, j:k + 1] - np.array([[10000], [0], [0], [0]])) / (d @ d)
    seg = pos[:, j:k + 1] - np.array([[10000], [0], [0], [0]]) - np.outer(d, t)
    assert np.abs(seg).max() <= 1.0                                        # straight in 4-D
    assert gts.GT_GetCrdPos(1)[1] == [40000.0, -20000.0, 10000.0, 5000.0]
    assert gts.GT_LnXYZAG0(1, 2 ** 31, 0, 0, 0, 50, 1) == 7 and gts.GT_LnXYZAG0(1, 0, 0, 0, 0, 0, 1) == 7


# -- PVT --------------------------------------------------------------------------------------------------------

def test_pvt_percent_calculate_tab_4_21_guc_l1436_1457(gts):
    # GT_PvtPercentCalculate (GUC L1214-1223, L1436; iDEABOX L6255-6275): the node velocities of Percent data,
    # v0 = velBegin, v(i+1) = 2 dp / dt - v(i), percent has no effect; nothing downloaded. Tab 4-21 (guc-ecat.md
    # §3.3): (0, 0, 60 %), (1000, 5000, 0 %), (2000, 15000, 100 %), (3000, 20000, 0 %) -> 0, 10, 10, 0; the same
    # data through GT_PvtTablePercent gives p(300) = 214.286, p(500) = 928.571, p(700) = 2214.286.
    t, p = [0, 1000, 2000, 3000], [0, 5000, 15000, 20000]
    rtn, vel = gts.GT_PvtPercentCalculate(4, t, p, [60, 0, 100, 0], 0)
    assert rtn == 0 and np.allclose(vel, [0, 10, 10, 0])
    assert np.allclose(gts.GT_PvtPercentCalculate(4, t, p, [0, 0, 0, 0], 0)[1], vel)   # percent-free
    assert np.allclose(gts.GT_PvtPercentCalculate(2, t, p, [0, 0], 2)[1], [2, 8])       # velBegin 2
    assert gts.GT_PrfPvt(1) == 0
    assert gts.GT_PvtTablePercent(1, 4, t, p, [60, 0, 100, 0], 0) == 0
    assert gts.GT_PvtTableSelect(1, 1) == 0 and gts.GT_PvtStart(1) == 0
    pos = gts.run(tick_of_ms(3100))[0].pos
    for t_ms, p_ms in ((300, 214.286), (500, 928.571), (700, 2214.286)):
        assert pos[tick_of_ms(t_ms) - 1] == pytest.approx(p_ms, abs=0.51)
    assert pos[-1] == 20000
    assert gts.GT_PvtPercentCalculate(5, t, p, [0] * 4, 0) == (7, None)   # fewer values than count
    assert gts.GT_PvtPercentCalculate(2, [0, 0], [0, 1], [0, 0], 0) == (7, None)   # times must increase


def test_pvt_table_ex_begin_and_end_velocities_ideabox_l6446_6472(gts):
    # GT_PvtTableEx (iDEABOX L6446-6472; ideabox.md §4.4): per point a begin and an end velocity, so the velocity
    # may jump at a point: segment i -> i+1 leaves p(i) at velBegin(i) and reaches p(i+1) at velEnd(i+1) (Hermite
    # cubic). Here 0 -> 5000 from 0 to 5 pulse/ms in 1000 ms, then 5000 -> 15000 at 10 pulse/ms.
    t, p = [0, 1000, 2000], [0, 5000, 15000]
    assert gts.GT_PrfPvt(1) == 0
    assert gts.GT_PvtTableEx(1, 3, t, p, [0, 10, 0], [0, 5, 10]) == 0
    assert gts.GT_PvtTableSelect(1, 1) == 0 and gts.GT_PvtStart(1) == 0
    pos = gts.run(tick_of_ms(2100))[0].pos
    s = 0.5                                                                # Hermite at mid-segment 1
    assert pos[tick_of_ms(500) - 1] == pytest.approx(5000 * (-2 * s ** 3 + 3 * s ** 2) + 1000 * 5 * (s ** 3 - s ** 2),
                                                     abs=0.51)            # 1875
    v_before = (pos[tick_of_ms(1000) - 1] - pos[tick_of_ms(990) - 1]) / 10
    v_after = (pos[tick_of_ms(1010) - 1] - pos[tick_of_ms(1000) - 1]) / 10
    assert v_before == pytest.approx(5, abs=0.2) and v_after == pytest.approx(10, abs=0.2)   # the jump
    assert pos[tick_of_ms(1500) - 1] == pytest.approx(10000, abs=0.51) and pos[-1] == 15000
    assert gts.GT_PvtTableEx(33, 3, t, p, [0] * 3, [0] * 3) == 7           # tableId 1..32
    assert gts.GT_PvtTableEx(2, 4, t, p, [0] * 3, [0] * 3) == 7            # fewer values than count


# -- FollowEx (iDEABOX) -----------------------------------------------------------------------------------------

def test_follow_switch_event_and_memory_ideabox_l5196_5293(gts):
    # GT_FollowSwitchEx (iDEABOX L5196-5293): switches the masked slaves to their other FIFO, only while moving and
    # with data in the other FIFO (else 1; ideabox.md §2.1 L5291-5293); the switch happens at the end of the pass.
    # GT_GetFollowEventEx (L5603) / GT_GetFollowMemoryEx (L5731) read what GT_SetFollowEventEx (L7212-7240) and
    # GT_SetFollowMemoryEx (L489-514) set. Master axis 1 jogs at 10 pulse/ms; slave axis 2 follows 1:1 on FIFO 0
    # (passes of 10000 master pulses, EVEN), 1:2 on FIFO 1.
    assert gts.GT_PrfFollowEx(2, 0) == 0 and gts.GT_SetFollowMasterEx(2, 1) == 0
    assert gts.GT_GetFollowMemoryEx(2) == (0, 0)                            # default: 16 segments
    assert gts.GT_SetFollowMemoryEx(2, 1) == 0 and gts.GT_GetFollowMemoryEx(2) == (0, 1)
    assert gts.GT_FollowSpaceEx(2) == (0, 512)
    assert gts.GT_GetFollowEventEx(2) == (0, G.FOLLOW_EVENT_START, 1, 0)
    assert gts.GT_SetFollowEventEx(2, G.FOLLOW_EVENT_PASS, -1, 1234) == 0
    assert gts.GT_GetFollowEventEx(2) == (0, G.FOLLOW_EVENT_PASS, -1, 1234)
    assert gts.GT_SetFollowEventEx(2, G.FOLLOW_EVENT_START) == 0
    assert gts.GT_FollowDataPercentEx(2, 10000, 10000, G.FOLLOW_SEGMENT_EVEN, 0, 0) == 0
    assert gts.GT_SetFollowLoopEx(2, 0) == 0
    assert gts.GT_FollowSwitchEx(0b10) == 1                                 # not moving
    assert gts.GT_FollowStartEx(0b10, 0) == 0
    assert gts.GT_PrfJog(1) == 0 and gts.GT_SetJogPrm(1, 1) == 0 and gts.GT_SetVel(1, 10) == 0
    assert gts.GT_Update(1) == 0
    gts.run(tick_of_ms(300))
    assert gts.GT_FollowSwitchEx(0b10) == 1                                 # FIFO 1 is empty
    assert gts.GT_FollowDataPercentEx(2, 10000, 20000, G.FOLLOW_SEGMENT_EVEN, 0, 1) == 0
    assert gts.GT_FollowSwitchEx(0b10) == 0
    run = gts.run(tick_of_ms(2500))
    m, s = run[0].pos, run[1].pos
    ratio = np.diff(s) / np.where(np.diff(m) == 0, np.nan, np.diff(m))
    k = int(np.argmax(m >= 10000))                                         # the end of the first pass
    assert np.nanmean(ratio[k - tick_of_ms(100):k - 1]) == pytest.approx(1, abs=0.02)   # FIFO 0 up to there
    assert np.nanmean(ratio[k + tick_of_ms(50):k + tick_of_ms(500)]) == pytest.approx(2, abs=0.02)  # then FIFO 1
    assert s[k] == pytest.approx(10000, abs=15)
    assert [gts.GT_FollowSwitchEx(0), gts.GT_FollowSwitchEx(1 << 4)] == [7, 7]   # mask: the card's axes
    assert [gts.GT_GetFollowMemoryEx(5)[0], gts.GT_GetFollowEventEx(0)[0]] == [7, 7]
    assert GtsController().GT_FollowSwitchEx(1) == -1
