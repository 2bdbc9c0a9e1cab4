"""GE dialect functions that no other test called (docs/coverage.md "Untested"), each checked against what the GE
programming manual says (seed 001 = ../shared/seeds/001_*.txt, `Lnnn` its lines; digest spec/ge.md)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects.ge import GeController, TLookAheadMsg
from test_card_ge import BIT, axis_initial, axis_run_t, cmd_sts, g, make_card, sts, wait_stopped  # noqa: F401 (g)
from test_card_ge_path import crd, prf, run_path, sx


# -- 7.1 system -------------------------------------------------------------------------------------------------

def test_hard_rst_example_resets_like_gt_reset_l4769_4804(g):
    # GT_HardRst (L4769-4786): motion registers 0 [1], capture 0 [2], trapezoid [3], PID 0 [4], ILmt [5], MtrLmt
    # [6] and PosErr [7] 32767, no auto-stop [8], closed loop [9]. Its example (L4790-4804) resets when EXI0 is
    # high; it returns a short (0). GT_Reset leaves the registers "the same as GT_HardRst" (L5404).
    assert GeController("PX", 8).GT_HardRst() == -1                       # no card open (Table 2-1 L267)
    axis_initial(g, 2, 0, 10)
    for rtn in (g.GT_SetKi(1, 2), g.GT_SetILmt(1, 9), g.GT_SetMtrLmt(2, 100), g.GT_SetPosErr(2, 7),
                g.GT_Update(1), g.GT_Update(2), g.GT_PrflS(2), g.GT_AuStpOn(1)):
        assert rtn == 0
    assert axis_run_t(g, 1, 5000, 5, 0.5) == [0] * 5
    assert g.GT_CaptHome(1) == 0
    g.delay(100)

    def hard_reset():                                                     # the manual's HardReset() (L4790-4804)
        rtn, ex_inpt = g.GT_ExInpt()
        if rtn != 0:
            return rtn
        if ex_inpt & 1:
            return g.GT_HardRst()
        return 0

    g.set_inputs(0)
    assert hard_reset() == 0 and g.GT_GetKp(1) == (0, 10)                 # EXI0 low: nothing happens
    g.set_inputs(1)
    assert hard_reset() == 0
    for axis in (1, 2):
        assert g.GT_GetPos(axis) == (0, 0) and g.GT_GetVel(axis) == (0, 0)          # [1]
        assert g.GT_GetCapt(axis) == (0, 0)                                          # [2]
        assert g.GT_GetMode(axis) == (0, 0)                                          # [3] trapezoid, [8] off
        assert [g.GT_GetKp(axis), g.GT_GetKi(axis), g.GT_GetKd(axis)] == [(0, 0)] * 3  # [4]
        assert g.GT_GetILmt(axis) == (0, 32767) and g.GT_GetMtrLmt(axis) == (0, 32767)  # [5], [6]
        assert g.GT_GetPosErr(axis) == (0, 32767)                                    # [7]
        assert sts(g, axis) & (BIT[8] | BIT[9] | BIT[10]) == BIT[8]                  # [9] closed loop, drive off
    g.run(200)
    assert not g.card.moving(0)                                           # the move was cancelled
    # SX: a following error always stops the path axes (L2364), HardRst keeps that
    c = sx()
    assert c.GT_HardRst() == 0 and all(c.card.auto_stop(a) for a in range(4))


# -- 7.2 axis configuration -------------------------------------------------------------------------------------

def test_alarm_on_off_decides_whether_the_drive_alarm_stops_the_axis_l3396_3430(g):
    # GT_AlarmOn (L3408-3430): the drive-alarm input is effective (the default); GT_AlarmOff (L3396-3406): ignored.
    # An effective alarm sets status bit 1 and turns the servo off (L2390-2398). Its example AlarmConfig.
    def alarm_config(axis, enable):                                       # the manual's example (L3418-3430)
        return g.GT_AlarmOn(axis) if enable else g.GT_AlarmOff(axis)

    axis_initial(g, 2, 0, 10)
    assert alarm_config(1, False) == 0
    g.card.set_alarm_input(0, True)
    g.run(5)
    assert not sts(g, 1) & BIT[1] and sts(g, 1) & BIT[9]                 # ignored: servo still on
    assert alarm_config(1, True) == 0
    g.run(1)
    s = sts(g, 1)
    assert s & BIT[1] and not s & BIT[9]                                  # effective: bit 1, servo off
    g.card.set_alarm_input(0, False)
    assert [g.GT_DrvRst(1), g.GT_ClrSts(1), g.GT_AxisOn(1)] == [0] * 3
    # default on: axis 2 alarms without any AlarmOn
    g.card.set_alarm_input(1, True)
    g.run(1)
    assert sts(g, 2) & BIT[1] and not sts(g, 2) & BIT[9]
    assert g.GT_AlarmOn(9) == 7 and g.GT_AlarmOn(0) == 7 and cmd_sts(g) == BIT[1]   # axis 1..8
    # SX: with the servo on, AlarmOn is a motor-state error (Table 2-4 bit 3, L330)
    c = GeController("SX", 4)
    assert c.GT_Open(make_card()) == 0 and c.GT_AxisOn(1) == 0
    assert c.GT_AlarmOn(1) == 1 and c.GT_GetCmdSts() == (0, BIT[3])
    assert c.GT_AxisOff(1) == 0 and c.GT_AlarmOn(1) == 0


def test_enc_on_off_and_the_actual_position_l1995_2003_l3982_4000():
    # GT_EncOff / GT_EncOn (L3982-4000): the encoder input off / on; illegal with the servo on (SX: Table 2-4 bit
    # 3, L330). With the encoder off GT_GetAtlPos reads the profile position; with it on, the encoder (L1999-2003).
    c = GeController("SX", 4)
    assert c.GT_Open(make_card(law=sb.GtServoLaw(fractional_gains=True))) == 0
    assert c.GT_EncOff(1) == 0
    assert [c.GT_SetKp(1, 10), c.GT_Update(1), c.GT_AxisOn(1)] == [0] * 3
    assert c.GT_EncOn(1) == 1 and c.GT_GetCmdSts() == (0, BIT[3])         # servo on: refused
    assert [c.GT_SetSynVel(5), c.GT_SetSynAcc(0.5), c.GT_LnXY(3000, 0)] == [0] * 3
    c.run(300)                                                           # mid-move: the axis lags its profile
    prf_pos = c.card.profile_pos(0)
    assert c.GT_GetAtlPos(1) == (0, prf_pos) and abs(c.card.actual_pos(0) - prf_pos) > 1   # off: the profile
    run_path(c)
    assert [c.GT_AxisOff(1), c.GT_EncOn(1)] == [0, 0]
    enc = c.card.actual_pos(0)
    assert c.GT_GetAtlPos(1) == (0, round(enc)) and abs(enc - 3000) <= 2  # on: the encoder, near 3000
    assert c.GT_EncOn(5) == 7 and c.GT_GetCmdSts() == (0, BIT[1])         # axis 1..4


def test_index_sns_accepts_the_simulated_edge_only_l4869_4877(g):
    # GT_IndexSns (L4869-4877, PX only): the trigger edge of each axis's index (encoder C phase). The simulated
    # index is one edge: 0 bits are accepted, a set bit for a card axis is not simulated (1, V93); the sense is a
    # 16-bit word (else 7); on an SX card the command is not in the set (Table 2-4 bit 14, L346).
    assert g.GT_IndexSns(0) == 0
    assert g.GT_IndexSns(0x1) == 1 and g.card.last_fault == "not_simulated" and cmd_sts(g) == 0
    assert g.GT_IndexSns(0x100) == 0                                      # bit 8: no axis 9 on this card
    assert g.GT_IndexSns(0x10000) == 7 and g.GT_IndexSns(-1) == 7
    c = sx()
    assert c.GT_IndexSns(0) == 1 and c.GT_GetCmdSts() == (0, BIT[14])
    assert GeController("PX", 4).GT_IndexSns(0) == -1


def test_au_stp_off_leaves_the_axis_moving_l3666_3700_l2344_2364(g):
    # GT_AuStpOff (L3666-3672): beyond the following-error limit the card does not stop the axis; PX sets status
    # bit 4 (L2359). Its example AutoStopConfig (L3688-3700). GT_AuStpOn stops it (compare).
    def auto_stop_config(axis, enable):
        return g.GT_AuStpOn(axis) if enable else g.GT_AuStpOff(axis)

    axis_initial(g, 2, 0, 10)
    for axis, enable in ((1, False), (2, True)):
        assert [g.GT_SetPosErr(axis, 100), g.GT_Update(axis), auto_stop_config(axis, enable)] == [0] * 3
        assert axis_run_t(g, axis, 100000, 100, 10) == [0] * 5            # lag ~650 pulse > 100
    assert g.GT_GetMode(1) == (0, 0) and g.GT_GetMode(2) == (0, 0x80)
    g.run(200)
    s1, s2 = sts(g, 1), sts(g, 2)
    assert s1 & BIT[4] and s1 & BIT[9] and s1 & BIT[10]                   # flagged, servo on, still moving
    assert s2 & BIT[4] and not s2 & BIT[9] and not s2 & BIT[10]           # AuStpOn: stopped, servo off
    g.delay(2000)
    assert g.GT_GetPos(1) == (0, 100000) and abs(g.card.actual_pos(0) - 100000) <= 2   # axis 1 got there
    c = sx()
    assert c.GT_AuStpOff(1) == 1 and c.GT_GetCmdSts() == (0, BIT[14])     # PX only (Table 2-4 bit 14)


# -- 7.5 servo parameters ---------------------------------------------------------------------------------------

def test_get_intgr_is_the_error_sum_of_the_law_l4395_4405(g):
    # GT_GetIntgr (L4395-4405): the axis's error integral, the sum the law multiplies by Ki (L801-803 of the GT
    # lineage, V87); clamped by GT_SetILmt. Compare with the recorded errors and the law's integral term.
    axis_initial(g, 1, 0, 10)
    assert [g.GT_SetKi(1, 0.5), g.GT_Update(1)] == [0, 0]
    assert g.GT_GetIntgr(1) == (0, 0)
    assert axis_run_t(g, 1, 3000, 5, 0.5) == [0] * 5
    run = g.card.run(400, signals=["error", "i"])
    rtn, intgr = g.GT_GetIntgr(1)
    assert rtn == 0 and intgr == round(run[0].error.sum()) != 0
    ki = g.card.axes[0].law.ki
    assert run[0].i[-1] == pytest.approx(ki * g.card.integral(0) / 256)
    assert g.GT_GetIntgr(2) == (0, 0)                                     # axis 2 never moved
    wait_stopped(g, 1)
    assert [g.GT_SetILmt(1, 5), g.GT_Update(1)] == [0, 0]
    assert axis_run_t(g, 1, 0, 5, 0.5) == [0] * 5
    g.card.run(400)
    assert abs(g.GT_GetIntgr(1)[1]) <= 5
    assert g.GT_GetIntgr(9)[0] == 7 and g.GT_GetIntgr(0)[0] == 7         # axis 1..8


# -- 7.9 path motion --------------------------------------------------------------------------------------------

def test_lnxyzag0_4d_rapid_l5113_5130():
    # GT_LnXYZAG0 (L5113-5130; printed GT_LnXYZG0(x,y,z,a), V110): a 4-D line to the absolute point, pulse, from
    # the previous end (buffer) or the current position (immediate); G0 = the full profile from StrtVel up to
    # SynVel and back to rest (L1473-1477), scaled by OverrideG0. A zero length returns 3 (Table 2-2 L280).
    # Its example (buffer): StrtList, MvXYZA(0,0,0,6,0.3,0.5) (start point a = 6, vel 0.3, acc 0.5 pulse/ms,
    # pulse/ms^2: six arguments, T27), LnXYZAG0(12945,58372,65473,65473), StrtMtn.
    c = sx()
    assert [c.GT_StrtList(), c.GT_MvXYZA(0, 0, 0, 6, 0.3, 0.5), c.GT_LnXYZAG0(12945, 58372, 65473, 65473),
            c.GT_EndList(), c.GT_StrtMtn()] == [0] * 5
    start, end = np.array([0, 0, 0, 6.0]), np.array([12945, 58372, 65473, 65473.0])
    pos = c.run(20000).to_array("pos")                                    # the first 20 s of a 6-minute line
    k0 = int(np.flatnonzero(pos[3] >= 6)[0])
    assert pos[3, k0] == 6 and not pos[:3, :k0 + 1].any()                 # the Mv positioning first (a to 6)
    pos = pos[:, k0:]                                                     # then the line
    d = end - start
    t = d @ (pos - start[:, None]) / (d @ d)
    assert np.abs(pos - start[:, None] - np.outer(d, t)).max() <= 1.0     # on the 4-D line (pulse rounding)
    speed = np.linalg.norm(pos[:, -1] - pos[:, -2001]) / 2000            # pulse/ms over the last 2 s
    assert speed == pytest.approx(0.3, rel=0.01)                          # at the example's 0.3 pulse/ms
    assert c.GT_EStpMtn() == 0
    # immediate, as T25 for LnXYG0 (L5048-5062): SynVel 30, SynAcc 1 -> 2 (30 - 0.5) + (L - (30^2 - 0.5^2)) / 30 ms
    c = sx()
    assert [c.GT_SetSynVel(30), c.GT_SetSynAcc(1), c.GT_LnXYZAG0(12945, 58372, 65473, 65473)] == [0] * 3
    ms, pos = run_path(c)
    assert prf(c) == [12945, 58372, 65473, 65473]
    t = end @ pos / (end @ end)
    assert np.abs(pos - np.outer(end, t)).max() <= 1.0 and np.all(np.diff(t) >= 0)
    length = np.linalg.norm(end)
    assert ms == pytest.approx(2 * (30 - 0.5) + (length - (30 ** 2 - 0.5 ** 2)) / 30, abs=3)
    assert c.GT_LnXYZAG0(12945, 58372, 65473, 65473) == 3                 # zero length
    assert c.GT_LnXYZAG0(2 ** 31, 0, 0, 0) == 3                           # overflow
    assert GeController("PX", 4).GT_LnXYZAG0(1, 1, 1, 1) == -1


# -- 7.11 look-ahead module B -----------------------------------------------------------------------------------

def _nearest_in_order(pos, points):
    out, i = [], 0
    for p in points:
        d = np.linalg.norm(pos[:, i:].T - np.asarray(p, float), axis=1)
        i += int(np.argmin(d))
        out.append((i, float(d.min())))
    return out


def test_module_b_yz_zx_arcs_g0_lines_bufiobit_and_delay_l1750_1761():
    # Table 6-10 (L1750-1761): ArcYZEx / ArcZXEx (centre + angle, > 0 CCW; L3545, L3619), ArcYZPEx / ArcZXPEx (end +
    # radius, direction 1 CCW, -1 CW; L3583, L3658), LnXYG0Ex / LnXYZG0Ex (rapid lines "with the complete
    # acceleration profile", L1750, L5103, L5139), BufIOBitEx (one output, effective with the next motion, L3778)
    # and DelayEx (a dwell between motions, ms, V107). mm and mm/s; con 2000 pulse/mm; F 50 mm/s.
    c = sx()
    msg = TLookAheadMsg()
    con = 2000
    assert [c.GT_InitLookAheadEx(0.002, 500, 200, 200, con), c.GT_StrtList(), c.GT_MvXYZEx(0, 0, 0, 50)] == [0] * 3
    program = [(c.GT_LnXYZG0Ex, (0, 10, 0)),       # 1 rapid to (0, 10, 0)
               (c.GT_ArcYZEx, (0, 0, 90)),         # 2 YZ CCW about (y, z) = (0, 0) -> (0, 0, 10)
               (c.GT_ArcYZPEx, (-10, 0, 10, 1)),   # 3 YZ CCW r 10 -> (0, -10, 0) (minor arc: centre (0, 0))
               (c.GT_LnXYZG0Ex, (0, -10, 10)),     # 4 rapid
               (c.GT_ArcZXEx, (0, 0, 90)),         # 5 ZX CCW about (z, x) = (0, 0) -> (10, -10, 0)
               (c.GT_ArcZXPEx, (-10, 0, 10, -1)),  # 6 ZX CW r 10 -> (0, -10, -10) (centre (z, x) = (-10, 10))
               (c.GT_LnXYG0Ex, (5, 5))]            # 7 XY rapid, z stays -10
    for n, (cmd, args) in enumerate(program, 1):
        assert cmd(*args, 50, 0, n, msg) == 0 and msg.error == 0
    assert [c.GT_BufIOBitEx(2, 1), c.GT_DelayEx(100), c.GT_LnXYZEx(0, 0, 0, 50, 0, 8, msg)] == [0] * 3
    assert [c.GT_M30(msg), c.GT_EndList(), c.GT_StrtMtn()] == [0] * 3
    runs, outs = [], []
    while not crd(c) & BIT[0]:
        run = c.run(20)
        runs.append(np.vstack([run[a].pos for a in range(3)]))
        outs.append(c.outputs())
    pos = np.hstack(runs) / con                                           # mm
    ends = [(0, 10, 0), (0, 0, 10), (0, -10, 0), (0, -10, 10), (10, -10, 0), (0, -10, -10), (5, 5, -10), (0, 0, 0)]
    hits = _nearest_in_order(pos, ends)
    step = 50 / 1000                                                      # mm per 1 ms tick at F
    assert all(d <= step for _, d in hits)                                # every end point is reached, in order
    assert prf(c)[:3] == [0, 0, 0]
    idx = [0] + [i for i, _ in hits]
    seg = lambda n: pos[:, idx[n - 1]:idx[n] + 1]                         # noqa: E731
    tol = 2 / con                                                         # 2 pulses
    x, y, z = seg(2)
    assert np.abs(x).max() <= tol and np.abs(np.hypot(y, z) - 10).max() <= tol      # YZ plane, radius 10
    assert np.all(np.diff(np.unwrap(np.arctan2(z, y))) >= -1e-9)                     # CCW in YZ
    x, y, z = seg(3)
    assert np.abs(x).max() <= tol and np.abs(np.hypot(y, z) - 10).max() <= tol
    assert np.all(np.diff(np.unwrap(np.arctan2(z, y))) >= -1e-9)
    x, y, z = seg(5)
    assert np.abs(y + 10).max() <= tol and np.abs(np.hypot(z, x) - 10).max() <= tol  # ZX plane, about (0, 0)
    assert np.all(np.diff(np.unwrap(np.arctan2(x, z))) >= -1e-9)                     # CCW from Z to X
    x, y, z = seg(6)
    assert np.abs(y + 10).max() <= tol and np.abs(np.hypot(z + 10, x - 10) - 10).max() <= tol
    assert np.all(np.diff(np.unwrap(np.arctan2(x - 10, z + 10))) <= 1e-9)            # CW
    x, y, z = seg(7)
    assert np.abs(z + 10).max() <= tol                                    # an XY line keeps Z
    speed = np.linalg.norm(np.diff(pos, axis=1), axis=0)
    assert speed.max() <= step * 1.02
    for n in (1, 4, 7):                                                   # G0: at rest at both ends
        assert speed[idx[n] - 1] <= 2 / con and speed[max(idx[n - 1], 1) - 1] <= 2 / con
    assert speed[idx[2] - 1] == pytest.approx(step, rel=0.02)             # tangent arcs 2 -> 3 at the feed
    # the dwell: 100 ms at (5, 5, -10) before the last line; output 2 set from then on
    still = np.flatnonzero(speed[idx[7]:] > 0)[0]
    assert 99 <= still <= 103
    assert outs[-1] == BIT[2]
    # bad input: Table 2-2 (L276-283) and the Ex argument ranges
    c2 = sx()
    assert [c2.GT_InitLookAheadEx(0.002, 500, 200, 200, con), c2.GT_StrtList(), c2.GT_MvXYZEx(0, 0, 0, 50)] == [0] * 3
    assert c2.GT_ArcYZEx(0, 0, 361, 50, 0, 1, msg) == 7                   # angle beyond a full turn
    assert c2.GT_ArcYZEx(0, 0, 90, 50, 0, 1, msg) == 2                    # radius 0: centre at the start
    assert c2.GT_ArcZXEx(1, 1, 90, 0, 0, 1, msg) == 4                     # F <= 0
    assert c2.GT_ArcYZPEx(0, 30, 10, 1, 50, 0, 1, msg) == 5               # chord 30 > diameter 20
    assert c2.GT_ArcZXPEx(10, 0, 10, 0, 50, 0, 1, msg) == 7               # direction 0
    assert c2.GT_LnXYG0Ex(1, 1, 50, 2, 1, msg) == 7                       # dccFlag 0 or 1
    assert c2.GT_LnXYZG0Ex(0, 0, 0, 50, 0, 1, msg) == 1 and msg.error == 1   # the same point (L3374)
    assert c2.GT_BufIOBitEx(16, 1) == 7 and c2.GT_BufIOBitEx(1, 2) == 7   # io_bit 0..15, status 0/1 (L3778)
    assert c2.GT_DelayEx(0) == 7 and c2.GT_DelayEx(8192) == 7             # 0 < t < 8192
    c3 = sx()
    assert c3.GT_DelayEx(10) == -1 and c3.GT_BufIOBitEx(1, 1) == -1       # buffer mode only (L3758-3762)
