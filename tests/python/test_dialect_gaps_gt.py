"""GT dialect functions that no other test called (docs/coverage.md "Untested"), each checked against what the GT
programming manual says (seed 000 = ../shared/seeds/000_*.txt, `Lnnn` its lines; digest spec/gt.md)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects.gt import GtController
from test_card_gt import LAW, first, g, sts  # noqa: F401  (g is the fixture: a tuned 4-axis card, drives off)
from test_card_modes import gt, gt_map_mm  # noqa: F401  (gt: the same card with every drive on)


def test_get_intgr_is_the_error_sum_the_law_integrates(g):
    # L3775-3785: GT_GetIntgr returns the integral error of the current axis's filter; the law's integral term is
    # Ki * SumE / 256 (L801-803), SumE clamped to ILmt (L4749-4761). So GetIntgr = the recorded errors' sum and
    # = 256 * (integral term) / Ki, and never exceeds ILmt.
    assert GtController().GT_GetIntgr() == (-1, 0)                       # no card open (L399)
    g.GT_Axis(2)
    g.GT_AxisOn()
    assert g.GT_GetIntgr() == (0, 0)
    assert [g.GT_SetAcc(0.1), g.GT_SetVel(4), g.GT_SetPos(3000), g.GT_Update()] == [0] * 4
    run = g.card.run(300, signals=["error", "i"])
    rtn, intgr = g.GT_GetIntgr()
    assert rtn == 0 and intgr == run[1].error.sum() != 0
    assert intgr == pytest.approx(256 * run[1].i[-1] / LAW.ki)
    # the other axes did not move: their sums are 0
    g.GT_Axis(1)
    assert g.GT_GetIntgr() == (0, 0)
    # ILmt 5: the sum the law uses is clamped to +-5, and GetIntgr shows the clamped sum
    g.GT_Axis(2)
    assert [g.GT_SetILmt(5), g.GT_SetPos(0), g.GT_Update()] == [0] * 3
    run = g.card.run(300, signals=["error", "i"])
    assert np.abs(run[1].i).max() == pytest.approx(5 * LAW.ki / 256)
    assert abs(g.GT_GetIntgr()[1]) <= 5
    assert g.GT_GetIntgr()[1] == pytest.approx(256 * run[1].i[-1] / LAW.ki)


def test_au_stp_off_only_flags_the_following_error(g):
    # L2729-2750: with the auto-stop bit cleared, an error beyond GT_SetPosErr only sets the axis's motion-error
    # flag (status bit 4); the output is not stopped. Mode register bit 7 is the auto-stop bit (L3954-3978).
    g.GT_Axis(4)
    for rtn in (g.GT_SetKp(3), g.GT_SetKd(0), g.GT_SetKi(0), g.GT_SetKaff(0), g.GT_SetPosErr(100), g.GT_Update(),
                g.GT_AxisOn(), g.GT_AuStpOn()):
        assert rtn == 0
    assert g.GT_GetMode()[1] & 0x80
    assert g.GT_AuStpOff() == 0 and not g.GT_GetMode()[1] & 0x80        # the manual's sample: axis 4, AuStpOff
    assert [g.GT_ClrSts(), g.GT_SetAcc(1), g.GT_SetVel(20), g.GT_SetPos(20000), g.GT_Update()] == [0] * 5
    run = g.card.run(3000, signals=["error", "events", "servo_on", "pos"])
    k = first(run[3].events, 0x10)
    assert k is not None and abs(run[3].error[k]) > 100                 # flagged when the band is left
    assert np.all(run[3].servo_on == 1)                                  # but the drive stays on
    assert run[3].pos[-1] == 20000 and g.card.axes[3].feedback_pulse > 15000  # the move goes on
    assert sts(g) & 0x0210 == 0x0210                                     # bit 4 set, still enabled (bit 9)
    assert GtController().GT_AuStpOff() == -1


def test_get_smpl_tm_is_the_cards_servo_period():
    # L4066-4078: *Timer returns the servo period in us, 48 .. 1966.08 us; the card's default ST is 200 us (L578).
    g = GtController()
    assert g.GT_GetSmplTm() == (-1, 0)
    assert g.GT_Open(sb.Card(4, law=LAW)) == 0
    assert g.GT_GetSmplTm() == (0, pytest.approx(200.0))
    for period_us in (48.0, 1000.0, 1966.08):
        assert g.GT_Open(sb.Card(4, law=LAW, servo_period_s=period_us * 1e-6)) == 0
        rtn, tm = g.GT_GetSmplTm()
        assert rtn == 0 and tm == pytest.approx(period_us)
        # the profile runs in pulse per ST: Vel 2 for 1000 ST is 2000 pulses whatever ST is (L854)
        g.GT_Axis(1)
        g.GT_AxisOn()
        g.GT_PrflV()
        assert [g.GT_SetAcc(16384), g.GT_SetVel(2), g.GT_Update()] == [0] * 3
        g.delay(tm * 1000 / 1000)                                        # 1000 ST, in ms
        assert g.card.profile_pos(0) == pytest.approx(2000, abs=2)


def test_hard_rst_restores_every_initial_state_l4118_4142(gt):
    # GT_HardRst (void, L4120-4122) resets: registers 0 [1], capture 0 [2], events cleared [3], interrupts masked
    # [4], T-curve [5], filter 0 [6], ILmt 32767 [7], PosErr 32767 [8], BrkCn 0 [9], no auto-update [10], closed
    # loop [11], no auto-stop [12], MtrLmt 32767 [13], coordinated auto-stop allowed [15], immediate mode [16],
    # no mapping [17] (L4126-4142).
    gt_map_mm(gt)
    assert gt.GT_SetSynVel(0.01) == 0 and gt.GT_SetSynAcc(1e-7) == 0
    assert gt.GT_CrdAuStpOff() == 0 and gt.GT_StrtList() == 0
    assert gt.GT_GetCrdSts()[1] & 0xC0 == 0                              # bit 6 off, buffer mode (bit 7 = 0)
    gt.GT_Axis(3)
    for rtn in (gt.GT_SetKp(100), gt.GT_SetILmt(7), gt.GT_SetPosErr(9), gt.GT_SetMtrLmt(1000), gt.GT_SetBrkCn(1234),
                gt.GT_SetVel(3), gt.GT_SetAcc(0.5), gt.GT_SetPos(4000), gt.GT_Update(), gt.GT_AuUpdtOn(),
                gt.GT_AuStpOn(), gt.GT_OpenLp(), gt.GT_SetIntrMsk(0x10), gt.GT_CaptHome()):
        assert rtn == 0
    gt.card.run(2)
    assert gt.GT_GetMode()[1] & 0x0480 and gt.GT_GetBrkCn() == (0, 1234) and gt.GT_GetIntrMsk() == (0, 0x10)
    assert gt.GT_HardRst() is None                                       # void (L4122)
    assert gt.GT_GetBrkCn() == (0, 0) and gt.GT_GetIntrMsk() == (0, 0)   # [9], [4]
    assert gt.GT_GetPos() == (0, 0) and gt.GT_GetVel() == (0, 0) and gt.GT_GetAcc() == (0, 0)  # [1]
    assert gt.GT_GetCapt() == (0, 0)                                     # [2]
    assert gt.GT_GetKp() == (0, 0) and gt.GT_GetILmt() == (0, 32767)     # [6], [7]
    assert gt.GT_GetPosErr() == (0, 32767) and gt.GT_GetMtrLmt() == (0, 32767)  # [8], [13]
    assert gt.GT_GetMode() == (0, 0)                                     # [5] T-curve, [10], [12] bits off
    assert sts(gt) == 0x0100 | 0x0800 | 0x2000                           # [3] no events, [11] closed loop, axis 3
    assert gt.card.mode(0) != "coordinated" and not gt.card.group_info(2)["set_up"]  # [17]
    assert gt.GT_GetCrdSts() == (0, 0x00D3)                              # [15] bit 6 on, [16] immediate (bit 7)
    assert gt.GT_LnXY(1, 1) == 1                                         # no mapping: nothing to move


def test_neg_brk_example_4_7_l1296_1330(g):
    # Example 4-7 (negative form, L1296-1330): 0 -> -50000 at Vel 1, Acc 0.1; BrkCn -20000; NegBrk; Vel 4 staged.
    # The breakpoint fires when the actual position is <= -20000 (L1299) and the staged Vel 4 takes effect then.
    g.GT_Axis(1)
    g.GT_AxisOn()
    assert [g.GT_ClrSts(), g.GT_SetVel(1), g.GT_SetAcc(0.1), g.GT_SetPos(-50000), g.GT_AuUpdtOn(),
            g.GT_SetBrkCn(-20000), g.GT_Update(), g.GT_NegBrk(), g.GT_SetVel(4)] == [0] * 9
    assert g.GT_GetMode()[1] & 0x0400
    run = g.card.run(30000, signals=["events", "prf_vel", "actual_pos", "pos"])
    fired = first(run[0].events, 0x4)
    assert fired == int(np.flatnonzero(run[0].actual_pos <= -20000)[0])  # on the actual position
    assert run[0].prf_vel[fired] == pytest.approx(-1.0)
    assert run[0].prf_vel[fired + 30] == pytest.approx(-4.0)             # 1 -> 4 at 0.1: 30 ST after the commit
    assert run[0].pos[-1] == -50000 and sts(g) & 0x5 == 0x5
    assert g.GT_GetVel() == (0, 4.0)
    # one-shot: once fired, the breakpoint mode is cleared (L1299); going back past -20000 does not fire again
    assert [g.GT_ClrSts(), g.GT_SetPos(0), g.GT_Update()] == [0] * 3
    run = g.card.run(20000, signals=["events"])
    assert first(run[0].events, 0x4) is None


def test_ext_brk_fires_on_the_home_switch_tv23_l3443_3470():
    # GT_ExtBrk (L3443-3470, TV23): axis 2, AuUpdtOn, CaptHome, ExtBrk, PrflT, Pos 87654, Vel 32, Acc 1.1, Update,
    # SmthStp staged: when the home switch is seen, the breakpoint fires (status bit 2, with the capture, bit 3),
    # the staged smooth stop takes effect, and the axis stops short of 87654. Without ExtBrk the move runs through.
    rad = 2 * math.pi / 10000
    home = 30000
    card = sb.Card(4, law=LAW, switches=sb.Switches(home_min_rad=home * rad, home_max_rad=(home + 5000) * rad))
    g = GtController()
    g.GT_Open(card)
    g.GT_Axis(2)
    g.GT_AxisOn()
    assert [g.GT_ClrSts(), g.GT_AuUpdtOn(), g.GT_CaptHome(), g.GT_ExtBrk(), g.GT_PrflT(), g.GT_SetPos(87654),
            g.GT_SetVel(32), g.GT_SetAcc(1.1), g.GT_Update(), g.GT_SmthStp()] == [0] * 10
    run = card.run(5000, signals=["events", "prf_vel", "pos", "actual_pos"])
    fired = first(run[1].events, 0x4)
    assert fired is not None and fired == first(run[1].events, 0x8)      # with the home capture
    assert fired == int(np.flatnonzero(run[1].actual_pos >= home)[0])    # when the axis reaches the switch
    assert abs(g.GT_GetCapt()[1] - home) <= 1                            # the switch's edge, +-1 pulse (L2015)
    assert run[1].prf_vel[fired] == pytest.approx(32)
    assert np.all(np.diff(run[1].prf_vel[fired:]) <= 1e-9)               # decelerating from there
    stop = run[1].pos[-1]
    assert home < stop <= home + 32 * 32 / (2 * 1.1) + 64 and stop < 87654  # smooth stop at Acc 1.1
    assert sts(g) & 0xD == 0xD                                           # done, breakpoint, captured
    # the same program without ExtBrk: the capture happens but the move runs to 87654
    card2 = sb.Card(4, law=LAW, switches=sb.Switches(home_min_rad=home * rad, home_max_rad=(home + 5000) * rad))
    g2 = GtController()
    g2.GT_Open(card2)
    g2.GT_Axis(2)
    g2.GT_AxisOn()
    assert [g2.GT_AuUpdtOn(), g2.GT_CaptHome(), g2.GT_PrflT(), g2.GT_SetPos(87654), g2.GT_SetVel(32),
            g2.GT_SetAcc(1.1), g2.GT_Update(), g2.GT_SmthStp()] == [0] * 8
    run = card2.run(5000, signals=["events", "pos"])
    assert first(run[1].events, 0x4) is None and run[1].pos[-1] == 87654


def test_get_brk_cn_reads_the_staged_compare_value(g):
    # GT_GetBrkCn (L3624-3638) returns the value GT_SetBrkCn set (L4717-4731: +-2^30 pulses, double-buffered);
    # out of range: 7, the value is unchanged.
    g.GT_Axis(3)
    assert g.GT_GetBrkCn() == (0, 0)
    assert g.GT_SetBrkCn(-123456) == 0 and g.GT_GetBrkCn() == (0, -123456)
    assert g.GT_SetBrkCn(2 ** 30) == 7 and g.GT_GetCmdSts() == (0, 1 << 0)
    assert g.GT_SetBrkCn(1.5) == 7 and g.GT_GetBrkCn() == (0, -123456)
    assert g.GT_SetBrkCn(1073741823) == 0 and g.GT_GetBrkCn() == (0, 1073741823)
    g.GT_Axis(4)
    assert g.GT_GetBrkCn() == (0, 0)                                     # per axis
    assert GtController().GT_GetBrkCn() == (-1, 0)


def test_crd_au_stp_on_off_is_coordinate_status_bit_6(gt):
    # L2000-2011: coordinate status bit 6, default 1, set by GT_CrdAuStpOn and cleared by GT_CrdAuStpOff. With the
    # bit clear the card still stops the whole path on an axis fault (V64: the manual calls going on "very
    # dangerous"); the fault shows as bit 9.
    assert GtController().GT_CrdAuStpOff() == -1 and GtController().GT_CrdAuStpOn() == -1
    gt_map_mm(gt)
    assert gt.GT_GetCrdSts()[1] & 0x40
    assert gt.GT_CrdAuStpOff() == 0 and not gt.GT_GetCrdSts()[1] & 0x40
    assert gt.GT_CrdAuStpOn() == 0 and gt.GT_GetCrdSts()[1] & 0x40
    assert gt.GT_CrdAuStpOff() == 0
    assert gt.GT_SetSynVel(0.01) == 0 and gt.GT_SetSynAcc(1e-6) == 0 and gt.GT_LnXY(10, 10) == 0
    gt.run(2000)
    gt.card.set_alarm_input(1, True)                                     # axis 2's drive alarm during the line
    gt.run(2)
    stopped = [gt.card.profile_pos(a) for a in (0, 1)]
    gt.run(200)
    assert [gt.card.profile_pos(a) for a in (0, 1)] == stopped and 0 < stopped[0] < 20000
    sts_crd = gt.GT_GetCrdSts()[1]
    assert sts_crd & 0x200 and not sts_crd & 0x40                       # bit 9 (a fault stopped it), bit 6 off
