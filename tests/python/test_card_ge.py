"""The GE manual's programs run against the virtual card through servobench.dialects.ge.

Each test transcribes an example of the GE programming manual (seed 001, `Lnnn` = its line numbers; Tn = the
test vectors of the digest ge.md §8) and checks the documented result. The manual's drives run in speed mode
(L1000, L3913): the axes here have a velocity drive (50 pulse/ms per volt), so the examples' Kp = 10 alone
holds the axis. Servo period 200 us unless a test says otherwise (decision V86)."""

import math
import threading

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import ge
from servobench.dialects.ge import GeController

BIT = [1 << k for k in range(32)]


def make_card(axes=4, servo_period_s=200e-6, **parts):
    parts.setdefault("drive", sb.VelocityDrive())
    parts.setdefault("law", sb.GtServoLaw(fractional_gains=True))
    return sb.Card(axes, servo_period_s=servo_period_s, **parts)


@pytest.fixture
def g():
    """A GE-800-PV program's view of a fresh 8-axis card, as after GT_Open + GT_Reset."""
    c = GeController("PX", 8)
    assert c.GT_Open(make_card(8)) == 0
    assert c.GT_Reset() == 0
    return c


def sts(g, axis):
    rtn, s = g.GT_GetSts(axis)
    assert rtn == 0
    return s


def cmd_sts(g):
    rtn, s = g.GT_GetCmdSts()
    assert rtn == 0
    return s


def axis_initial(g, axis_num, limit, kp):
    """Example 3-4 (L662-683): LmtSns, then per axis SetKp, Update, AxisOn, ClrSts, delay(200)."""
    assert g.GT_LmtSns(limit) == 0
    for i in range(1, axis_num + 1):
        assert [g.GT_SetKp(i, kp), g.GT_Update(i), g.GT_AxisOn(i), g.GT_ClrSts(i)] == [0] * 4
        g.delay(200)


def axis_run_t(g, axis, pos, vel, acc):
    """Example 5-1 AxisRunT (L1012-1019)."""
    return [g.GT_PrflT(axis), g.GT_SetPos(axis, pos), g.GT_SetVel(axis, vel), g.GT_SetAcc(axis, acc),
            g.GT_Update(axis)]


def wait_stopped(g, axis, max_ms=10**6):
    """do { GT_GetSts(axis, &status); } while (status & 0x400), polling every ms; returns the ms waited."""
    n = g.wait_until(lambda: not sts(g, axis) & 0x400, max_ticks=int(max_ms * 5), chunk=5)
    return n * g.servo_period_s * 1e3


def motion_ms(run, axis):
    """Ticks (as ms) until the recorded profile of `axis` (0-based) stops moving."""
    moving = np.flatnonzero(run[axis].moving)
    return (moving[-1] + 1) * run.servo_period_s * 1e3


# -- system ------------------------------------------------------------------------------------------------------

def test_module_functions_and_no_card():
    ge.GT_Close()
    assert ge.GT_AxisOn(1) == -1            # no card: communication error (Table 2-1 L266)
    assert ge.GT_GetSts(1) == (-1, 0)
    assert ge.GT_Open() == 0 and isinstance(ge.card(), sb.Card) and len(ge.card()) == 4
    assert ge.GT_GetSts(5) == (7, 0)        # axis 5 on a 4-axis card: parameter error
    assert ge.GT_GetSts(4)[1] >> 28 == 3    # bits 30:28 = axis - 1
    assert ge.GT_Close() == 0
    assert {"GT_Update", "GT_MltiUpdt", "GT_GetCmdSts", "GT_SetKp", "GT_PrflS", "GT_CaptProb",
            "GT_HookCommand", "GT_SwitchtoCardNo"} <= set(ge.GE_FUNCTIONS)


def test_constructor_arguments_are_validated():
    with pytest.raises(ValueError, match="variant"):
        GeController("PV")
    with pytest.raises(ValueError, match="axes = 8 must be 4"):
        GeController("SX", 8)
    with pytest.raises(ValueError, match="servo_period_s = 0.01 is outside"):
        GeController("PX", 4, servo_period_s=0.01)
    c = GeController("PX", 4)
    with pytest.raises(ValueError, match="servo_period_s"):
        c.GT_Open(make_card(4, servo_period_s=250e-6))
    with pytest.raises(ValueError, match="8 axes"):
        c.GT_Open(make_card(8))
    with pytest.raises(ValueError, match="GtServoLaw"):
        c.GT_Open(sb.Card(4, law=sb.ApsServoLaw()))


def test_t35_two_cards_switch_and_close():
    # GT_GetCurrentCardNo example L4308-4339: open two cards, close the first, the second is card 1.
    c = GeController()
    assert c.GT_Open() == 0 and c.GT_Open() == 0
    assert c.GT_GetCurrentCardNo() == 1                  # the second GT_Open opened (and selected) card 1
    first, second = c._slots[0].card, c._slots[1].card
    assert c.GT_SwitchtoCardNo(0) == 0 and c.card is first
    assert c.GT_Close() == 0
    assert c.GT_AxisOn(1) == -1                          # card 0 is closed
    assert c.GT_SwitchtoCardNo(1) == 0 and c.card is second
    assert c.GT_GetCurrentCardNo() == 1
    assert c.GT_Close() == 0
    assert c.GT_SwitchtoCardNo(16) == 7 and c.GT_SwitchtoCardNo(0) == -1   # 0..15; no card 0 open
    for _ in range(16):
        assert c.GT_Open(make_card()) == 0
    assert c.GT_Open(make_card()) == -1                  # at most 16 cards (L4299)


def test_hook_command_gets_name_arguments_and_return_value(g):
    # L394-400, L4855-4866 and the CommandHandle of Example 5-1 (L1021-1036).
    log = []
    assert g.GT_HookCommand(lambda command, error: log.append((command, error))) == 0
    g.GT_SetKp(1, 10)
    g.GT_SetKp(1, -1)
    g.GT_GetSts(2)
    g.GT_MltiUpdt(0)
    assert log == [("GT_SetKp(1,10)", 0), ("GT_SetKp(1,-1)", 7), ("GT_GetSts(2)", 0), ("GT_MltiUpdt(0)", 1)]
    assert g.GT_HookCommand(None) == 0 and g.GT_ClrSts(1) == 0 and len(log) == 4
    assert g.GT_HookCommand(42) == 7


def test_reentered_command_returns_minus_3(g):
    # Table 2-1 L266: -3 = a command called while another runs (another thread).
    results = []
    with g._lock:  # a command of another thread is running now
        t = threading.Thread(target=lambda: results.append((g.GT_SetKp(1, 10), g.GT_GetSts(1))))
        t.start()
        t.join()
    assert results == [(-3, (-3, 0))]
    assert g.GT_SetKp(1, 10) == 0


def test_reset_defaults_l4769_4786(g):
    for rtn in (g.GT_SetKp(1, 100), g.GT_SetILmt(1, 5), g.GT_SetMtrLmt(1, 100), g.GT_SetPosErr(1, 7),
                g.GT_Update(1), g.GT_PrflS(2), g.GT_AuStpOn(3), g.GT_OpenLp(4), g.GT_LmtsOff(5),
                g.GT_SetPos(6, 1234), g.GT_ExOpt(0x55)):
        assert rtn == 0
    g.run(1)
    assert g.GT_Reset() == 0
    for axis in range(1, 9):
        assert [g.GT_GetKp(axis), g.GT_GetKi(axis), g.GT_GetKd(axis), g.GT_GetKvff(axis), g.GT_GetKaff(axis)] \
            == [(0, 0)] * 5                                                     # gains 0 [4]
        assert g.GT_GetILmt(axis) == (0, 32767) and g.GT_GetMtrLmt(axis) == (0, 32767)   # [5], [6]
        assert g.GT_GetPosErr(axis) == (0, 32767)                                # [7]
        assert g.GT_GetMode(axis) == (0, 0)                                      # trapezoid [3], auto-stop off [8]
        assert sts(g, axis) & (BIT[8] | BIT[11]) == BIT[8] | BIT[11]             # closed loop [9], limits on
        assert g.GT_GetPos(axis) == (0, 0)                                       # motion registers 0 [1]
    assert g.outputs() == 0


# -- servo parameters ----------------------------------------------------------------------------------------

def test_t31_pid_config_l5576_5612(g):
    # PidConfig: Kp 10, Ki 20, ILmt 20000, Kd 5, Kaff 10, Kvff 10, Bias -200, MtrLmt 6*3276, PosErr 32767, Update.
    for rtn in (g.GT_SetKp(1, 10), g.GT_SetKi(1, 20), g.GT_SetILmt(1, 20000), g.GT_SetKd(1, 5),
                g.GT_SetKaff(1, 10), g.GT_SetKvff(1, 10), g.GT_SetMtrBias(1, -200), g.GT_SetMtrLmt(1, 6 * 3276),
                g.GT_SetPosErr(1, 32767)):
        assert rtn == 0
    # the GetK* read-backs return the values set (L4463-4496), before they are effective
    assert [g.GT_GetKp(1), g.GT_GetKi(1), g.GT_GetILmt(1), g.GT_GetKd(1), g.GT_GetKaff(1), g.GT_GetKvff(1),
            g.GT_GetMtrBias(1), g.GT_GetMtrLmt(1), g.GT_GetPosErr(1)] == \
        [(0, 10), (0, 20), (0, 20000), (0, 5), (0, 10), (0, 10), (0, -200), (0, 19656), (0, 32767)]
    assert g.card.axes[0].law.kp == 0
    assert g.GT_Update(1) == 0
    g.run(1)
    law = g.card.axes[0].law
    assert (law.kp, law.ki, law.ilmt, law.kd, law.kaff, law.kvff, law.bias, law.mtr_lmt) == \
        (10, 20, 20000, 5, 10, 10, -200, 19656)
    # MtrLmt 19656 counts is +-5.999 V (32767 = 10 V, L5331-5337): a huge error saturates there
    assert g.GT_AxisOn(1) == 0 and g.GT_ClrSts(1) == 0
    assert axis_run_t(g, 1, 1000000, 400, 100) == [0] * 5
    run = g.card.run(300, signals=["volts"])
    assert run[0].volts.max() == pytest.approx(19656 * 10 / 32767, abs=1e-9)
    assert 19656 * 10 / 32767 == pytest.approx(5.999, abs=1e-3)


def test_fractional_gains_and_ranges(g):
    # GE gains are doubles in [0, 32767] (L5530-5620); ILmt/MtrLmt/PosErr are unsigned shorts, bias a short.
    assert g.GT_SetKp(2, 12.75) == 0 and g.GT_GetKp(2) == (0, 12.75)
    assert g.GT_SetKvff(2, 32767) == 0 and g.GT_SetKvff(2, 32767.5) == 7
    assert cmd_sts(g) == BIT[1]                       # illegal parameter (Table 2-3 bit 1)
    assert sts(g, 2) & BIT[7]                         # axis command error (Table 4-3 bit 7)
    assert g.GT_SetILmt(2, 1.5) == 7 and g.GT_SetMtrBias(2, -32769) == 7 and g.GT_SetPosErr(2, 32768) == 7
    assert g.GT_GetKvff(2) == (0, 32767) and g.GT_GetILmt(2) == (0, 32767)   # nothing changed
    assert g.GT_SetMtrBias(2, -32768) == 0
    assert g.GT_Update(2) == 0
    g.run(1)
    assert g.card.axes[1].law.kp == 12.75


def test_t32_open_loop_voltage_l5674_5686(g):
    # OpenLp(1); SetMtrCmd(1, 3*3276) -> 9828 counts = 2.9994 V at 32767 = 10 V.
    assert g.GT_OpenLp(1) == 0
    assert sts(g, 1) & BIT[8] == 0                    # bit 8: open loop
    assert g.GT_AxisOn(1) == 0 and g.GT_SetMtrCmd(1, 3 * 3276) == 0
    assert g.GT_GetMtrCmd(1) == (0, 9828)
    run = g.card.run(5, signals=["volts"])
    assert run[0].volts[-1] == pytest.approx(9828 * 10 / 32767) == pytest.approx(2.9994, abs=1e-4)
    assert g.GT_CloseLp(1) == 1                       # servo must be off first (L3875-3883)
    assert g.GT_AxisOff(1) == 0 and g.GT_CloseLp(1) == 0 and sts(g, 1) & BIT[8]
    assert g.GT_SetMtrCmd(1, 32768) == 7


# -- point-to-point profiles ---------------------------------------------------------------------------------

def test_t1_trapezoid_example_5_1(g):
    # L998-1050: AxisInitial(1,0,10); AxisRunT(1,200000,166.7,4): acc 4 pulse/ms^2, vel 166.7 pulse/ms.
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 200000, 166.7, 4) == [0] * 5
    assert g.GT_GetVel(1) == (0, 166.7) and g.GT_GetAcc(1) == (0, 4) and g.GT_GetPos(1) == (0, 200000)
    run = g.card.run(6600, signals=["moving", "prf_vel", "pos"])
    # [calc] t_acc = 166.7/4 = 41.675 ms; total = 200000/166.7 + 41.675 = 1241.4 ms
    assert motion_ms(run, 0) == pytest.approx(200000 / 166.7 + 166.7 / 4, abs=0.4)
    assert run[0].prf_vel.max() * 5 == pytest.approx(166.7)      # pulse/tick * 5 ticks/ms
    assert g.GT_GetPrfPos(1) == (0, 200000) and g.GT_GetPrfVel(1) == (0, 0)
    g.delay(300)
    assert abs(g.GT_GetAtlPos(1)[1] - 200000) <= 2


def test_t1_timing_does_not_depend_on_the_servo_period():
    # The units are pulse/ms (L991-996): the same program at Ts = 250 us takes the same 1241.4 ms.
    c = GeController("PX", 4, servo_period_s=250e-6)
    assert c.GT_Open() == 0
    assert axis_run_t(c, 1, 200000, 166.7, 4) == [0] * 5
    run = c.card.run(5200, signals=["moving", "prf_vel"])
    assert motion_ms(run, 0) == pytest.approx(1241.4, abs=0.5)
    assert run[0].prf_vel.max() * 4 == pytest.approx(166.7)
    assert c.GT_GetVel(1) == (0, 166.7)


def test_t2_s_curve_example_5_2_jerk_limited(g):
    # L1103-1158: AxisRunS(1,200000,166.7,4,0.001): jerk 0.001 pulse/ms^3; a^2/j = 16000 > v, so MAcc is never
    # reached: peak acc sqrt(v j) = 0.408 pulse/ms^2, jerk phases 408.3 ms, total 2016.3 ms [calc].
    axis_initial(g, 1, 0, 10)
    assert [g.GT_PrflS(1), g.GT_SetPos(1, 200000), g.GT_SetVel(1, 166.7), g.GT_SetMAcc(1, 4),
            g.GT_SetJerk(1, 0.001), g.GT_Update(1)] == [0] * 6
    assert g.GT_GetMode(1) == (0, 0x1000)                          # S-curve 010 in bits 13..11
    assert g.GT_GetJerk(1) == (0, 0.001) and g.GT_GetMAcc(1) == (0, 4)
    run = g.card.run(10300, signals=["moving", "prf_vel", "pos"])
    t_j = math.sqrt(166.7 / 0.001)
    total = 2 * (2 * t_j) + (200000 - 2 * 166.7 * t_j) / 166.7
    assert total == pytest.approx(2016.3, abs=0.1)
    assert motion_ms(run, 0) == pytest.approx(total, abs=1.0)
    acc_ms2 = np.diff(run[0].prf_vel) * 5 * 5                     # pulse/ms^2
    assert acc_ms2.max() == pytest.approx(math.sqrt(166.7 * 0.001), rel=2e-3)
    assert run[0].pos[-1] == 200000


def test_t3_velocity_mode_example_5_3(g):
    # L1208-1257: AxisRunV(1,166.7,4): reaches 166.7 pulse/ms after 41.675 ms and holds it.
    axis_initial(g, 1, 0, 10)
    assert [g.GT_PrflV(1), g.GT_SetVel(1, 166.7), g.GT_SetAcc(1, 4), g.GT_Update(1)] == [0] * 4
    assert g.GT_GetMode(1) == (0, 0x0800)                          # velocity 001
    run = g.card.run(1000, signals=["prf_vel"])
    v = run[0].prf_vel * 5
    reached = int(np.flatnonzero(np.isclose(v, 166.7))[0]) + 1
    assert reached * 0.2 == pytest.approx(41.675, abs=0.2)
    assert np.allclose(v[reached:], 166.7) and sts(g, 1) & BIT[10]
    # the velocity may change at any time (L1263-1264), also its sign (range -40958..40957)
    assert g.GT_SetVel(1, -100) == 0 and g.GT_Update(1) == 0
    g.run(2000)
    assert g.GT_GetPrfVel(1)[1] == pytest.approx(-100)
    assert g.GT_SetVel(1, -40959) == 7 and cmd_sts(g) == BIT[0]     # parameter overflow (bit 0)


def test_t28_multi_update_starts_together_l5207_5228(g):
    # SetKp 10 on axes 1 and 3, MltiUpdt(5), AxisOn; PrflV, Vel 10, Acc 0.1 on both; MltiUpdt(5).
    assert [g.GT_SetKp(1, 10), g.GT_SetKp(3, 10), g.GT_MltiUpdt(5), g.GT_AxisOn(1), g.GT_AxisOn(3)] == [0] * 5
    for axis in (1, 3):
        assert [g.GT_PrflV(axis), g.GT_SetVel(axis, 10), g.GT_SetAcc(axis, 0.1)] == [0] * 3
    assert g.GT_MltiUpdt(5) == 0
    run = g.card.run(600, signals=["pos", "prf_vel"])
    np.testing.assert_array_equal(run[0].pos, run[2].pos)          # both axes in the same tick
    assert np.all(run[1].pos == 0)                                 # axis 2 not in the mask
    k = int(np.flatnonzero(np.isclose(run[0].prf_vel * 5, 10))[0]) + 1
    assert k * 0.2 == pytest.approx(100, abs=0.2)                  # [calc] 10 / 0.1 = 100 ms
    assert run[0].pos[k - 1] == pytest.approx(500, abs=1)         # [calc] 500 pulse travelled
    assert g.GT_MltiUpdt(0) == 1 and cmd_sts(g) == BIT[2]          # mask 0 (Table 2-3 bit 2)


def test_t23_feedback_after_a_move_l4155_4230(g):
    # AxisInitial(1,0,1) (Kp 1); AxisRunT(1,10000,10,1); wait for bit 10 = 0; read AtlErr, positions, velocities.
    axis_initial(g, 1, 0, 1)
    assert axis_run_t(g, 1, 10000, 10, 1) == [0] * 5
    assert sts(g, 1) & BIT[10]                                     # the planner has the move at once (V89)
    g.run(3000)                                                    # 600 ms: cruising
    rtn, vp = g.GT_GetPrfVel(1)
    assert rtn == 0 and vp == pytest.approx(10)                   # cruising at 10 pulse/ms
    assert g.GT_GetAtlVel(1)[1] == pytest.approx(10, rel=0.02)    # the axis follows (time constant ~65 ms)
    # AtlErr is the last tick's profile - actual: within one tick of travel (2 pulse) of the readings now
    assert abs(g.GT_GetAtlErr(1)[1] - (g.GT_GetPrfPos(1)[1] - g.GT_GetAtlPos(1)[1])) <= 2
    ms = 3000 * 0.2 + wait_stopped(g, 1)
    assert ms == pytest.approx(1010, abs=1.0)                     # [calc] 10000/10 + 10/1
    assert g.GT_GetPrfPos(1) == (0, 10000) and g.GT_GetPrfVel(1) == (0, 0)
    g.delay(500)
    err = g.GT_GetAtlErr(1)[1]
    assert err == 10000 - g.GT_GetAtlPos(1)[1] and abs(err) <= 2   # the residual error with Kp = 1


def test_t30_set_atl_pos_and_rst_sts_l5474_5488(g):
    # AxisRunT(1,10000,1,0.1); wait for bit 10 = 0; SetAtlPos(1,0); RstSts(1,0xFE): bit 0 only is cleared.
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 10000, 1, 0.1) == [0] * 5
    g.run(10)
    assert g.GT_ZeroPos(1) == 1                                    # in motion: rtn 1, bit 11, axis bit 7
    assert cmd_sts(g) == BIT[11] and sts(g, 1) & BIT[7]
    ms = 10 * 0.2 + wait_stopped(g, 1, 20000)
    assert ms == pytest.approx(10010, abs=1.0)                    # [calc] 10000/1 + 1/0.1 ms
    g.delay(200)
    assert g.GT_SetAtlPos(1, 0) == 0
    assert g.GT_GetAtlPos(1) == (0, 0) and g.GT_GetPos(1) == (0, 0) and g.GT_GetPrfPos(1) == (0, 0)
    assert g.GT_RstSts(1, 0xFE) == 0
    assert sts(g, 1) & BIT[7]                                      # bits 1-7 kept
    assert g.GT_RstSts(1, 0x7F) == 0 and not sts(g, 1) & BIT[7]   # a 0 clears
    assert g.GT_SetAtlPos(1, 2 ** 30) == 7 and cmd_sts(g) == BIT[0]


def test_t15_abrupt_stop_on_exi15_l3317_3335(g):
    # AxisInitial(1,0); AxisRunT(1,1000000,1,0.1); when EXI15 (0x8000) is high: AbptStp -> profile velocity 0.
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 1000000, 1, 0.1) == [0] * 5
    g.run(500)
    g.set_inputs(0x8000)
    rtn, exi = g.GT_ExInpt()
    assert rtn == 0 and exi & 0x8000
    assert g.GT_AbptStp(1) == 0
    assert g.GT_GetPrfVel(1) == (0, 0) and not sts(g, 1) & BIT[10]
    p = g.GT_GetPrfPos(1)[1]
    g.run(100)
    assert g.GT_GetPrfPos(1) == (0, p)


def test_smooth_stop_is_immediate_and_uses_the_acceleration(g):
    # SmthStp decelerates at the mode's acceleration (L1310-1312, L5792-5797; immediate, decision V91).
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 1000000, 10, 0.5) == [0] * 5
    g.run(200)                                                     # cruising at 10 pulse/ms after 20 ms
    assert g.GT_SmthStp(1) == 0
    ms = wait_stopped(g, 1)
    assert ms == pytest.approx(10 / 0.5, abs=1.0)                  # 20 ms to rest


def test_t24_limits_on_off_bit_11_l4921_4944(g):
    assert [g.GT_LmtsOff(1), g.GT_LmtsOn(2), g.GT_ClrSts(1)] == [0] * 3
    assert sts(g, 1) & BIT[11] == 0 and sts(g, 2) & BIT[11]


# -- illegal sequences leave the state unchanged ------------------------------------------------------------

def test_mode_change_while_moving_l310_l5368(g):
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 100000, 10, 1) == [0] * 5
    g.run(50)
    assert g.GT_PrflS(1) == 1 and g.GT_PrflV(1) == 1
    assert cmd_sts(g) == BIT[6] and g.GT_GetMode(1) == (0, 0) and sts(g, 1) & BIT[7]


def test_update_of_acc_during_a_t_move_l315(g):
    axis_initial(g, 1, 0, 10)
    assert axis_run_t(g, 1, 100000, 10, 1) == [0] * 5
    g.run(50)
    assert g.GT_SetAcc(1, 2) == 0 and g.GT_Update(1) == 1           # trapezoid: Acc may not change in motion
    assert cmd_sts(g) == BIT[11] and g.card.active(0)["acc"] == pytest.approx(1 * 0.04)
    # target and velocity may change (L1067-1071): with the old Acc staged back
    assert g.GT_SetAcc(1, 1) == 0 and g.GT_SetVel(1, 20) == 0 and g.GT_Update(1) == 0
    g.run(200)
    assert g.GT_GetPrfVel(1)[1] == pytest.approx(20)


def test_s_curve_velocity_change_in_motion_refused_l315(g):
    axis_initial(g, 1, 0, 10)
    assert [g.GT_PrflS(1), g.GT_SetPos(1, 100000), g.GT_SetVel(1, 10), g.GT_SetMAcc(1, 1), g.GT_SetJerk(1, 0.1),
            g.GT_Update(1)] == [0] * 6
    g.run(100)
    assert g.GT_SetVel(1, 20) == 0 and g.GT_Update(1) == 1 and cmd_sts(g) == BIT[11]
    assert g.card.active(0)["vel"] == pytest.approx(10 * 0.2)
    assert g.GT_SetVel(1, 10) == 0 and g.GT_SetPos(1, 50000) == 0 and g.GT_Update(1) == 0   # target may change


def test_drive_reset_with_servo_on_and_alarm_recovery_l3954_3980(g):
    axis_initial(g, 1, 0, 10)
    assert g.GT_DrvRst(1) == 1 and cmd_sts(g) == BIT[3]            # DrvRst with the servo on
    g.card.set_alarm_input(0, True)                                # the drive alarms (L2390-2398)
    g.run(1)
    s = sts(g, 1)
    assert s & BIT[1] and not s & BIT[9]                           # bit 1, servo off
    assert g.GT_AxisOn(1) == 1 and cmd_sts(g) == BIT[9]            # AxisOn during the alarm
    g.card.set_alarm_input(0, False)                               # the cause is fixed
    assert [g.GT_AxisOff(1), g.GT_DrvRst(1), g.GT_ClrSts(1), g.GT_AxisOn(1)] == [0] * 4
    assert sts(g, 1) & (BIT[1] | BIT[9]) == BIT[9]


def test_zero_target_velocity_is_a_command_error(g):
    axis_initial(g, 1, 0, 10)
    assert g.GT_SetPos(1, 1000) == 0 and g.GT_Update(1) == 1       # Vel 0, Acc 0 after the reset
    assert cmd_sts(g) == BIT[1]


def test_parameter_errors_return_7(g):
    assert g.GT_SetPos(1, 2 ** 30) == 7 and cmd_sts(g) == BIT[0]
    assert g.GT_SetVel(1, 40958) == 7 and g.GT_SetVel(1, -1) == 7   # T mode: 0..40957
    assert g.GT_SetVel(1, 40957) == 0
    assert g.GT_SetAcc(1, 102401) == 7 and g.GT_SetMAcc(1, -1) == 7 and g.GT_SetJerk(1, 256001) == 7
    assert g.GT_SetJerk(1, 256000) == 0
    assert g.GT_SetKp(9, 1) == 7 and g.GT_SetKp(0, 1) == 7 and cmd_sts(g) == BIT[1]
    assert g.GT_RstSts(1, 0x10000) == 7 and g.GT_MltiUpdt(-1) == 7 and g.GT_LmtSns(1.5) == 7
    assert g.GT_GetPos(1) == (0, 0) and g.GT_GetAcc(1) == (0, 0)


# -- following error, limits ------------------------------------------------------------------------------------

def test_following_error_bit_4_and_auto_stop_l2344_2364(g):
    axis_initial(g, 1, 0, 10)
    assert [g.GT_SetPosErr(1, 100), g.GT_Update(1), g.GT_AuStpOn(1)] == [0] * 3
    assert g.GT_GetMode(1) == (0, 0x80)                            # mode bit 7
    assert axis_run_t(g, 1, 1000000, 100, 10) == [0] * 5           # lag 100/0.15 ~ 650 pulse > 100
    g.run(200)
    s = sts(g, 1)
    assert s & BIT[4] and not s & BIT[9] and not s & BIT[10]       # flagged, e-stopped, servo off


def test_limit_switch_stops_and_inhibits_l2381_2388():
    c = GeController("PX", 4)
    assert c.GT_Open(make_card(switches=sb.Switches(pos_limit_rad=2 * math.pi * 0.3))) == 0   # +3000 pulse
    axis_initial(c, 1, 0, 10)
    assert axis_run_t(c, 1, 100000, 20, 1) == [0] * 5
    c.run(2000)
    s = sts(c, 1)
    assert s & BIT[5] and not s & BIT[10]                          # bit 5, stopped abruptly
    assert c.GT_GetLmtSwt() == (0, 0b01)                           # Limit0+ high (bit 0)
    assert c.GT_SetPos(1, 200000) == 0 and c.GT_Update(1) == 1    # motion toward the limit is refused
    assert c.GT_SetPos(1, 0) == 0 and c.GT_Update(1) == 0          # moving away is allowed
    c.run(3000)
    assert c.GT_ClrSts(1) == 0 and not sts(c, 1) & BIT[5]


def test_t34_lmt_sns_bitmap_l516_520(g):
    # LmtSns bit 3 = axis 2 negative (bit 2k axis k+1 positive, 2k+1 negative); 1 = triggers on a low level.
    assert g.GT_LmtSns(0b1000) == 0
    assert [g.card.limits(k).neg_active_low for k in range(3)] == [False, True, False]
    assert not any(g.card.limits(k).pos_active_low for k in range(8))
    # with the switch not hit the input is low: axis 2's negative limit now triggers
    assert g.GT_GetLmtSwt() == (0, 0)                              # levels, whatever LmtSns says
    assert g.GT_AxisOn(2) == 0
    g.run(1)
    assert sts(g, 2) & BIT[6] and not sts(g, 1) & BIT[6]


# -- capture and homing ---------------------------------------------------------------------------------------

HOME_SW = sb.Switches(home_min_rad=-2 * math.pi * 0.3, home_max_rad=-2 * math.pi * 0.2)  # -3000..-2000 pulse


def home_ex_7_2(g, axis, pos, offset, vel_high, vel_low):
    """Example 7-2 Home() (L2226-2310), transcribed: Home then Index capture; 0 ok, 1 no Home, 2 no Index."""
    poll = lambda cond: g.wait_until(cond, chunk=5)          # the host polls every ms
    g.GT_ClrSts(axis)
    g.GT_CaptHome(axis)
    g.GT_SetPos(axis, pos)
    g.GT_SetVel(axis, vel_high)
    g.GT_SetAcc(axis, 0.01)
    g.GT_Update(axis)
    poll(lambda: sts(g, axis) & 0x8 or not sts(g, axis) & 0x400)
    if not sts(g, axis) & 0x8:
        return 1
    g.GT_SmthStp(axis)
    poll(lambda: not sts(g, axis) & 0x400)
    _, pos = g.GT_GetCapt(axis)
    g.GT_SetPos(axis, pos)
    g.GT_SetVel(axis, vel_low)
    g.GT_Update(axis)
    poll(lambda: not sts(g, axis) & 0x400)
    g.GT_ClrSts(axis)
    g.GT_CaptIndex(axis)
    g.GT_SetPos(axis, pos + 11000)
    g.GT_Update(axis)
    poll(lambda: sts(g, axis) & 0x8 or not sts(g, axis) & 0x400)
    if not sts(g, axis) & 0x8:
        return 2
    g.GT_SmthStp(axis)
    poll(lambda: not sts(g, axis) & 0x400)
    _, pos = g.GT_GetCapt(axis)
    g.GT_SetPos(axis, pos)
    g.GT_SetVel(axis, vel_low)
    g.GT_Update(axis)
    poll(lambda: not sts(g, axis) & 0x400)
    g.GT_SetPos(axis, pos + offset)
    g.GT_Update(axis)
    poll(lambda: not sts(g, axis) & 0x400)
    g.delay(1000)
    g.GT_ZeroPos(axis)
    return 0


def test_t9_home_and_index_example_7_2():
    c = GeController("PX", 8)
    assert c.GT_Open(make_card(8, switches=HOME_SW)) == 0 and c.GT_Reset() == 0
    log = []
    c.GT_HookCommand(lambda cmd, err: log.append((cmd, err)))
    axis_initial(c, 1, 0, 10)
    assert home_ex_7_2(c, 1, -1000000, 1000, 20, 2) == 0
    assert all(err == 0 for _cmd, err in log)                     # CommandHandle never reports an error
    # the index capture is the encoder's index mark (raw count 0 here), ZeroPos 1000 pulse beyond it
    assert c.GT_GetCapt(1)[1] == pytest.approx(-1000, abs=1)      # the capture, in the new coordinates
    assert abs(c.GT_GetAtlPos(1)[1]) <= 1 and c.GT_GetPrfPos(1) == (0, 0)
    assert c.card.axes[0].feedback_pulse == pytest.approx(1000, abs=1)


def test_t9_home_missing_returns_1(g):
    axis_initial(g, 1, 0, 10)                                      # no home switch on these axes
    assert home_ex_7_2(g, 1, -3000, 1000, 20, 2) == 1
    assert sts(g, 1) & BIT[14]                                     # still armed


def test_home_only_procedure_l2053_2069():
    # Home only: toward the switch with capture armed, smooth stop, back to the capture, a set distance past it,
    # settle, ZeroPos.
    c = GeController("PX", 4)
    assert c.GT_Open(make_card(switches=HOME_SW)) == 0
    axis_initial(c, 1, 0, 10)
    assert [c.GT_CaptHome(1), c.GT_SetPos(1, -100000), c.GT_SetVel(1, 5), c.GT_SetAcc(1, 0.05),
            c.GT_Update(1)] == [0] * 5
    assert sts(c, 1) & BIT[14]
    c.wait_until(lambda: sts(c, 1) & 0x8, max_ticks=10**6, chunk=5)
    assert not sts(c, 1) & BIT[14]                                 # one shot
    assert c.GT_CaptHome(1) == 1 and c.GT_GetCmdSts() == (0, BIT[5])   # re-arm before ClrSts (L2334-2336)
    _, capt = c.GT_GetCapt(1)
    assert capt == pytest.approx(-2000, abs=1)                     # the switch edge entered from above
    assert c.GT_SmthStp(1) == 0
    wait_stopped(c, 1)
    assert [c.GT_SetPos(1, capt - 1500), c.GT_Update(1)] == [0] * 2
    wait_stopped(c, 1)
    c.delay(500)
    assert c.GT_ZeroPos(1) == 0
    assert abs(c.card.axes[0].feedback_pulse - (capt - 1500)) <= 2 and abs(c.GT_GetAtlPos(1)[1]) <= 2


def test_probe_capture_all_axes_l3828_3862(g):
    axis_initial(g, 2, 0, 10)
    assert axis_run_t(g, 2, 100000, 10, 1) == [0] * 5
    assert g.GT_CaptProb() == 0
    assert g.GT_CaptProb() == 1 and cmd_sts(g) == BIT[5]          # one shot, not yet triggered
    g.set_probe_time(0.5)                                          # EXI0 edge at t = 0.5 s on the axes' clock
    g.run(int(0.6 / g.servo_period_s) - g.card.tick)
    for axis in range(1, 9):
        assert sts(g, axis) & BIT[3]                               # bit 3 of all axes
    _, capt = g.GT_GetCapt(2)
    assert 0 < capt < g.GT_GetAtlPos(2)[1] and g.GT_GetCapt(3) == (0, 0)


# -- SX variant, I/O, unsupported -----------------------------------------------------------------------------

def test_sx_status_word_and_command_set():
    c = GeController("SX", 4)
    assert c.GT_Open(make_card()) == 0
    assert c.GT_GetSts(3) == (0, (2 << 12) | BIT[11])            # 16 bits: axis 3 = 10 in 13:12, no bit 8
    assert c.GT_PrflT(1) == 1 and c.GT_GetCmdSts() == (0, BIT[14])    # not in the SX command set
    assert c.GT_GetPrfPos(1) == (1, 0)
    assert c.GT_AxisOn(1) == 0
    assert c.GT_AlarmOff(1) == 1 and c.GT_GetCmdSts() == (0, BIT[3])  # motor state: servo on (Table 2-4)
    assert c.GT_EncOff(1) == 1 and c.GT_GetCmdSts() == (0, BIT[3])
    assert c.GT_CtrlMode(1, 1) == 1 and c.GT_GetCmdSts() == (0, BIT[6])  # CtrlMode with the servo on
    assert c.GT_StepDir(2) == 1 and c.GT_GetCmdSts() == (0, BIT[6])  # StepDir on an analog axis
    assert c.GT_SetKp(9, 1) == 7 and c.GT_GetCmdSts() == (0, BIT[1])
    assert c.GT_SetPosErr(1, 0) == 0 and c.GT_Update(1) == 0        # SX: a following error always stops
    assert c.GT_AxisOff(1) == 0 and c.GT_AlarmOff(1) == 0 and c.GT_EncOff(2) == 0
    assert c.GT_GetAtlPos(2) == (0, 0)


def test_sx_pulse_axis_servo_commands():
    c = GeController("SX", 4)
    assert c.GT_Open(sb.Card(4, drive=sb.StepperDrive(), law=sb.GtServoLaw())) == 0
    assert c.GT_CtrlMode(1, 1) == 0 and c.GT_StepPulse(1) == 0 and c.GT_StepDir(1) == 0   # Example 3-3
    assert c.GT_SetKp(1, 10) == 1 and c.GT_GetCmdSts() == (0, BIT[6])   # servo command in pulse mode
    assert c.GT_CtrlMode(2, 0) == 1 and c.GT_GetCmdSts() == (0, 0)      # a stepper takes no voltage: not simulated


def test_t22_exopt_and_home_levels_l4094_4118():
    c = GeController("PX", 4)
    assert c.GT_Open(make_card(switches=HOME_SW)) == 0
    c.set_inputs(0x2)
    _, exi = c.GT_ExInpt()
    if exi & 0x2:                                                  # EXI1 high -> EXO2 high, all others low
        assert c.GT_ExOpt(0x4) == 0
    assert c.outputs() == 0x4
    assert c.GT_GetHomeSwt() == (0, 0)
    axis_initial(c, 1, 0, 10)
    assert axis_run_t(c, 1, -2500, 5, 0.5) == [0] * 5
    wait_stopped(c, 1)
    c.delay(200)
    assert c.GT_GetHomeSwt() == (0, 0b1)                           # Home0 (axis 1) inside its switch


def test_unsupported_commands_say_so(g):
    # the spindle (GE-X00-SV, L5732, L3891) and the auxiliary encoder are SX commands: 1 on a PX card (GF17);
    # the A/D is simulated on both (tests/python/test_dialect_ge_io.py)
    assert g.GT_SetSpindleVel(100) == 1 and g.GT_CloseSpindle() == 1
    assert g.card.last_fault == "not_in_command_set" and g.GT_GetCmdSts() == (0, 0)
    assert g.GT_HandWheel(1, 0.1) == 1 and g.GT_EncPos(1) == (1, 0)   # SX commands on a PX card
    assert g.GT_HomeSns(0) == 0 and g.GT_HomeSns(1) == 1            # rising edge not simulated
    assert g.GT_EncSns(0) == 0 and g.GT_EncSns(0x4) == 1 and g.GT_EncSns(0x100) == 0  # bit 8: no axis 9
    assert g.GT_CtrlMode(1, 1) == 1 and g.GT_CtrlMode(1, 2) == 7


def test_watch_example_10_1_through_the_ge_dialect():
    # GE Example 10-1 (L2464-2884, ge.md §6.6) as written for the card: axis 2, SetWatch(config, 400) with bits 0-1,
    # StartWatch(0), Update, then GetWatch blocks while the axis moves. Kp 10 only, as the example.
    from servobench.dialects.ge import GeController, TWatchBuffer

    card = sb.Card(8, law=sb.GtServoLaw(), servo_period_s=200e-6,
                   plant=sb.RigidPlant(inertia_kgm2=2e-5, viscous_nms=2e-3))
    ge = GeController("PX", axes=8)
    assert ge.GT_Open(card=card) == 0
    config = [0, 3, 0, 0, 0, 0, 0, 0]
    assert ge.GT_SetWatch(config, 400) == 0
    assert ge.GT_SetWatch([0x10] + [0] * 7, 400) == 7          # bit 4 is reserved (Table 10-2)
    assert ge.GT_SetWatch([0x4F] * 8, 1000) == 7               # 40000 values: more than the watch memory (L2793, V75)
    assert ge.GT_SetWatch(config, 400) == 0
    buf = TWatchBuffer(8)
    buf.Axis[1].PrfPos = np.zeros(400, dtype=np.int64)
    buf.Axis[1].AtlPos = np.zeros(400, dtype=np.int64)
    for rtn in (ge.GT_SetKp(2, 10), ge.GT_Update(2), ge.GT_AxisOn(2), ge.GT_SetPos(2, 100000), ge.GT_SetVel(2, 10),
                ge.GT_SetAcc(2, 1), ge.GT_StartWatch(0), ge.GT_Update(2)):
        assert rtn == 0
    blocks = []
    while True:
        rtn, available = ge.GT_GetWatch(buf)
        assert rtn == 0
        if available:
            blocks.append(buf.Axis[1].PrfPos.copy())
        rtn, sts = ge.GT_GetSts(2)
        if not sts & 0x400:
            break
        ge.run(100)
    assert ge.GT_StopWatch() == 0
    prf = np.concatenate(blocks)
    assert np.all(np.diff(prf) >= 0) and 40 <= prf[50] <= 60  # 10 ms ramp at 1 pulse/ms^2: ~50 pulse
    np.testing.assert_array_equal(np.diff(prf[10000:10006]), [2] * 5)  # 10 pulse/ms = 2 pulse per 200 us tick
