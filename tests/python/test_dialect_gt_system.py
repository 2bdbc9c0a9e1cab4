"""The GT dialect's system, I/O and auxiliary-encoder commands and the coordinated-motion commands added for issue 25
point 3 (GT manual seed 000, `Lnnn` its lines), each checked against what the manual says; and the dialect
functions that no test had called (docs/coverage.md). The machine side of the I/O is servobench.card_io."""

import math
import threading

import numpy as np
import pytest

import servobench as sb
from servobench import card_io
from servobench.dialects import gt
from servobench.dialects.gt import UNSUPPORTED, GtController
from test_card_gt import LAW, g, sts  # noqa: F401  (g: a tuned 4-axis card, drives off)
from test_card_modes import gt as gt_on, gt_map_mm  # noqa: F401  (gt_on: the same card, every drive on)


# -- several cards in one PC ----------------------------------------------------------------------------------------
def test_switch_to_card_no_and_get_current_card_no_l5130_5150_l3713():
    c = GtController()
    assert c.GT_SwitchtoCardNo(0) == -1 and c.GT_GetCurrentCardNo() == -1       # nothing open
    cards = [sb.Card(4, law=LAW) for _ in range(3)]
    c.use_machine(cards)
    assert c.GT_Open() == 0 and c.card is cards[0] and c.GT_GetCurrentCardNo() == 0   # the first card found is 0
    assert c.GT_Axis(3) == 0 and c.GT_SetKp(77) == 0
    assert c.GT_SwitchtoCardNo(2) == 0 and c.card is cards[2] and c.GT_GetCurrentCardNo() == 2
    assert c.GT_GetKp() == (0, 38)                      # card 2's axis 1: its own current axis and registers
    assert c.GT_SwitchtoCardNo(3) == -1 and c.GT_SwitchtoCardNo(16) == -1 and c.GT_SwitchtoCardNo(-1) == -1
    assert c.GT_GetCurrentCardNo() == 2                 # a failed switch keeps the current card
    assert c.GT_SwitchtoCardNo(0) == 0 and c.GT_GetKp() == (0, 77)   # card 0 kept its current axis (3) and Kp
    assert cards[1].staged(2)["law"].kp == 38
    assert c.GT_Close() == 0 and c.card is None and c.GT_GetCurrentCardNo() == -1


def test_program_mode_cards_keep_one_time():
    # all the PC's cards run at once: switching brings the card switched to up to the time of the one left
    cards = [sb.Card(4, law=LAW) for _ in range(2)]
    for k in cards:
        k.set_clock("program")
    c = GtController()
    c.use_machine(lambda: cards)
    assert c.GT_Open() == 0
    c.delay(10)                                          # card 0: 10 ms = 50 ticks
    assert cards[0].tick == 50 and cards[1].tick == 0
    assert c.GT_SwitchtoCardNo(1) == 0
    assert cards[1].tick == 50
    with pytest.raises(TypeError, match="servobench.Card"):
        c.use_machine([cards[0], "card"])


# -- base address, sample time --------------------------------------------------------------------------------------
def test_set_addr_get_addr_example_3_1_l506_l547_556_l3524_3549():
    c = GtController()
    assert c.GT_GetAddr() == (0, 0x300)                  # the default, no exchange with the card: always 0
    card = sb.Card(4, law=LAW)
    card_io.of(card).base_address = 0x340                # the jumper of this card
    c.use_machine(card)
    assert c.GT_SetAddr(0x300) == -1                     # nothing answers at 0x300 (L552-556)
    assert c.GT_GetAddr() == (0, 0x300)                  # the wrong address reads back (L3530)
    assert c.GT_SetAddr(0x340) == 0 and c.card is card and c.GT_GetAddr() == (0, 0x340)
    assert c.GT_SetAddr(0x10000) == 7 and c.GT_SetAddr(-1) == 7
    assert [c.GT_Reset(), c.GT_SetSmplTm(200)] == [0, 0]   # Example 3-1 (L506-508) goes on
    assert c.GT_SetAddr(0x300) == -1 and c.card is None and c.GT_Reset() == -1   # nothing answers: -1 (L399)


def test_isa_windows_open_example_3_2_l519_523_l549_553():
    card = sb.Card(4, law=LAW)
    c = GtController()
    c.use_machine(card)
    assert c.GT_Open(0x300, 0) == 0 and c.card is card     # GT_Open(PortBase, irq): the default jumper 0x300
    assert [c.GT_Reset(), c.GT_SetSmplTm(200)] == [0, 0]
    assert c.GT_Close() == 0
    assert c.GT_Open(0x340, 0) == -1 and c.card is None     # no card at 0x340
    assert c.GT_Open(0x300, 9) == 7                         # irq: 0 (none) or 10..15 (L551)
    assert c.GT_Open(0x300, 11) == 0 and c.GT_GetAddr() == (0, 0x300)


def test_set_smpl_tm_is_the_machines_period_l5026_5036(g):
    assert g.GT_SetSmplTm(200) == 0 and g.GT_GetSmplTm() == (0, pytest.approx(200.0))
    assert g.GT_SetSmplTm(47.9) == 7 and g.GT_SetSmplTm(1966.09) == 7 and g.GT_SetSmplTm(float("nan")) == 7
    assert g.GT_SetSmplTm(400) == 1 and g.card.last_fault == "not_simulated"   # another period: not simulated
    g400 = GtController()
    assert g400.GT_Open(sb.Card(4, law=LAW, servo_period_s=400e-6)) == 0 and g400.GT_SetSmplTm(400) == 0
    assert GtController().GT_SetSmplTm(200) == -1


# -- encoder direction, pulse form ----------------------------------------------------------------------------------
def test_enc_sns_corrects_the_machines_wiring_table_11_2_l3267_3300():
    card = sb.Card(4, law=LAW)
    io = card_io.of(card)
    io.encoder_reversed = 0x3                            # axes 1 and 2 wired against the motor (L3283: EncSns(3))
    io.aux_encoders[0] = card_io.AuxEncoder(lambda t: 100.0)
    c = GtController()
    assert c.GT_Open(card) == 0
    assert c.GT_EncSns(0) == 1 and c.card.last_fault == "not_simulated"   # positive feedback: not simulated
    assert c.GT_EncSns(3) == 0                           # the manual's sample corrects it
    assert c.GT_EncPos(1) == (0, 100)
    assert c.GT_EncSns(0x13) == 0 and c.GT_EncPos(1) == (0, 100)   # auxiliary 1 reversed: the count stays ...
    card.run(5)
    io.aux_encoders[0] = card_io.AuxEncoder(lambda t: 100.0 + 1e4 * t)   # ... and now counts down as it turns up
    assert c.GT_EncPos(1) == (0, 100 - math.floor(100 + 1e4 * 5 * 200e-6) + 100)
    assert c.GT_EncSns(0x40) == 7 and c.GT_EncSns(-1) == 7


def test_step_dir_step_pulse_on_pulse_axes_only_l5104_5124():
    card = sb.Card([sb.Axis(law=LAW), sb.Axis(law=LAW), sb.Axis(drive=sb.StepperDrive()),
                    sb.Axis(drive=sb.ServoPositionDrive())])
    c = GtController()
    assert c.GT_Open(card) == 0
    assert c.GT_Axis(1) == 0 and c.GT_StepPulse() == 1 and c.card.last_fault == "invalid_in_mode"
    assert c.GT_Axis(3) == 0 and c.GT_CtrlMode(1) == 0
    assert c.pulse_form(3) == "pulse_dir"                 # the default (L5108)
    assert c.GT_StepPulse() == 0 and c.pulse_form(3) == "cw_ccw"
    assert c.GT_StepDir() == 0 and c.pulse_form(3) == "pulse_dir"
    assert c.GT_Axis(4) == 0 and c.GT_StepPulse() == 0 and c.pulse_form(4) == "cw_ccw"
    assert c.GT_Reset() == 0 and c.pulse_form(4) == "pulse_dir"     # reset: pulse + direction again
    with pytest.raises(ValueError, match="1..4"):
        c.pulse_form(5)


# -- general I/O, pulse width, A/D ----------------------------------------------------------------------------------
def test_exinpt_exopt_sample_9_1_and_example_4_5(gt_on):
    # Sample 9-1 (L2544-2556): if EXI5 is high, EXO0 high. Example 4-5 (L1106-1119): EXI15 high -> AbptStp.
    io = card_io.of(gt_on.card)
    io.inputs = lambda t: 0x20 | (0x8000 if t >= 0.1 else 0)
    rtn, ex_inp = gt_on.GT_ExInpt()
    assert rtn == 0 and ex_inp == 0x20
    if ex_inp & 0x20:
        assert gt_on.GT_ExOpt(0x1) == 0
    assert io.outputs == 0x1
    assert gt_on.GT_ExOpt(0x10000) == 7 and io.outputs == 0x1
    gt_on.GT_Axis(1)
    assert [gt_on.GT_SetAcc(0.1), gt_on.GT_SetVel(2), gt_on.GT_SetPos(100000), gt_on.GT_Update()] == [0] * 4
    while True:
        gt_on.run(50)
        rtn, ex_data = gt_on.GT_ExInpt()
        if ex_data & 0x8000:
            assert gt_on.GT_AbptStp() == 0
            break
    assert gt_on.card.tick == 500 and gt_on.card.profile_vel(0) == 0     # 0.1 s = 500 ST; stopped at once
    io.inputs = 0x10000
    assert gt_on.GT_ExInpt()[0] == 7                     # a machine that gives no 16-bit word: 7, no exception


def test_exinpt_exi8_stops_the_coordinated_motion_tv45_l3395_3403(gt_on):
    # L3395-3403: "If EXI8 is at logic 1, stop the motion in coordinate system": GT_StpMtn, a smooth stop
    gt_map_mm(gt_on, pulse_per_mm=100)
    card_io.of(gt_on.card).inputs = lambda t: 0x100 if t >= 0.2 else 0
    assert [gt_on.GT_SetSynVel(0.05), gt_on.GT_SetSynAcc(0.001), gt_on.GT_LnXY(100, 0)] == [0] * 3
    while True:
        gt_on.run(10)
        rtn, ex_inp = gt_on.GT_ExInpt()
        if ex_inp & 0x100:
            assert gt_on.GT_StpMtn() == 0
            break
    assert gt_on.card.tick == 1000                       # 0.2 s
    gt_on.run(2000)
    assert gt_on.GT_GetCrdSts()[1] & 1 and gt_on.card.profile_pos(0) < 10000   # stopped short of 100 mm


def test_set_time_records_the_pulse_width_l5042_5050(g):
    assert g.GT_SetTime(65535) == 0 and card_io.of(g.card).pulse_width_s == pytest.approx(16e-3)
    assert g.GT_SetTime(0) == 0 and card_io.of(g.card).pulse_width_s == 0
    assert g.GT_SetTime(65536) == 7 and g.GT_SetTime(1.5) == 7


def test_get_adc_set_adc_chn_l3498_3520_l4585_4595(g):
    io = card_io.of(g.card)
    io.adc_volts[1] = 5.0
    io.adc_volts[2] = -2.5
    io.adc_volts[7] = lambda t: 10.0 if t > 0 else 0.0
    rtn, adc = g.GT_GetAdc(2)
    assert rtn == 0 and adc == 1024                      # +5 V: half of 0..2047
    rtn, adc = g.GT_GetAdc(3)
    assert adc == 2048 + 512                             # -2.5 V, as the sample decodes (L3511): -10 (d-2048)/2048
    assert -10 * (adc - 2048) / 2048 == -2.5
    io.adc_volts[1] = -5.0
    assert g.GT_GetAdc(2) == (0, 3072)                   # TV32 (L3517-3519): code 3072 -> -5 V
    assert g.GT_GetAdc(8) == (0, 0)
    g.card.run(5)                                        # 1 ms: still before the next 770 Hz conversion (1.3 ms)
    assert g.GT_GetAdc(8) == (0, 0)
    g.card.run(2)
    assert g.GT_GetAdc(8) == (0, 2047)                   # +10 V: the top code
    assert g.GT_SetAdcChn(2) == 0 and g.GT_GetAdc(3) == (7, 0) and g.GT_GetAdc(2)[1] == 3072
    assert g.GT_SetAdcChn(9) == 7 and g.GT_SetAdcChn(0) == 7 and g.GT_GetAdc(0) == (7, 0)
    assert g.GT_Reset() == 0 and g.GT_GetAdc(8)[0] == 0  # reset: all 8 channels again


# -- auxiliary encoders ---------------------------------------------------------------------------------------------
def test_aux_encoder_position_velocity_clear_l3124_3136_l3241_3330(g):
    io = card_io.of(g.card)
    io.aux_encoders[1] = card_io.AuxEncoder(lambda t: 25000.0 * t)      # 5 pulse/ST at 200 us
    assert g.GT_EncPos(2) == (0, 0) and g.GT_EncPos(1) == (0, 0)        # nothing connected to No. 1: 0
    g.card.run(100)
    assert g.GT_EncPos(2) == (0, 500) and g.GT_EncVel(2) == (0, 5.0)
    assert g.GT_ClrEncPos(2) == 0 and g.GT_EncPos(2) == (0, 0)
    g.card.run(10)
    assert g.GT_EncPos(2) == (0, 50)
    assert g.GT_EncPos(3) == (7, 0) and g.GT_EncVel(0) == (7, 0) and g.GT_ClrEncPos(3) == -1   # "-1 failure"
    assert GtController().GT_EncPos(1) == (-1, 0)


def test_aux_encoder_index_capture_l3727_3759_l4733_4747(g):
    io = card_io.of(g.card)
    io.aux_encoders[0] = card_io.AuxEncoder(lambda t: -3000.0 + 20000.0 * t, counts_per_index=4000,
                                            index_offset=1000.0)   # 4 pulse/ST; marks at 1000 + 4000 k
    assert g.GT_GetEncSts() == (0, 0) and g.GT_GetEncCapt() == (0, 0)
    assert g.GT_SetEncCapt() == 0
    g.card.run(500)                                      # from -3000 to -1000: the mark at -3000 is where it starts
    assert g.GT_GetEncSts() == (0, 0)
    g.card.run(1000)                                     # to 3000: the mark at 1000 is crossed
    assert g.GT_GetEncSts() == (0, 0x8) and g.GT_GetEncCapt() == (0, 1000)
    g.card.run(1000)                                     # past 5000: the capture holds until armed again
    assert g.GT_GetEncCapt() == (0, 1000)
    assert g.GT_SetEncCapt() == 0 and g.GT_GetEncSts() == (0, 0)
    assert g.GT_GetEncCapt() == (0, 1000)                # the previous value until the next capture (L3731)
    g.card.run(1000)
    assert g.GT_GetEncSts() == (0, 0x8) and g.GT_GetEncCapt() == (0, 9000)
    with pytest.raises(ValueError, match="counts_per_index"):
        card_io.AuxEncoder(counts_per_index=-1)


# -- coordinated motion ---------------------------------------------------------------------------------------------
def arc_p_run(g, call, plane):
    """Runs an immediate arc by end point and radius on axes 1-3 (100 pulse/mm); returns the path, mm, in the
    plane's two coordinates."""
    gt_map_mm(g, axes=(1, 2, 3), pulse_per_mm=100)
    assert g.GT_SetSynVel(0.02) == 0 and g.GT_SetSynAcc(0.0002) == 0
    assert call() == 0
    run = g.run(12000)
    pos = np.c_[run[0].pos, run[1].pos, run[2].pos] / 100.0
    return pos[:, plane[0]], pos[:, plane[1]]


def check_half_circle_cw(u, v):
    # from (0, 0) to (20, 0) with radius 10, direction -1 (CW seen from the third axis, L1793): through (10, +10)
    # (the axes' command positions are whole pulses: 0.01 mm at 100 pulse/mm)
    assert u[-1] == pytest.approx(20, abs=1e-9) and v[-1] == pytest.approx(0, abs=1e-9)
    assert np.max(v) == pytest.approx(10, abs=0.01) and np.min(v) >= 0
    assert np.allclose(np.hypot(u - 10, v), 10, atol=0.011)


def test_arc_xyp_by_end_point_and_radius_l1753(gt_on):
    check_half_circle_cw(*arc_p_run(gt_on, lambda: gt_on.GT_ArcXYP(20, 0, 10, -1), (0, 1)))


def test_arc_yzp_by_end_point_and_radius_l1755(gt_on):
    check_half_circle_cw(*arc_p_run(gt_on, lambda: gt_on.GT_ArcYZP(20, 0, 10, -1), (1, 2)))


def test_arc_zxp_by_end_point_and_radius_l1757(gt_on):
    check_half_circle_cw(*arc_p_run(gt_on, lambda: gt_on.GT_ArcZXP(20, 0, 10, -1), (2, 0)))


def test_arc_return_codes_5_and_7_l406(gt_on):
    gt_map_mm(gt_on, pulse_per_mm=100)
    assert gt_on.GT_SetSynVel(0.02) == 0 and gt_on.GT_SetSynAcc(0.0002) == 0
    assert gt_on.GT_ArcXYP(30, 0, 10, 1) == 5            # chord 30 > diameter 20: end point or radius wrong (L406)
    assert gt_on.GT_ArcXYP(10, 0, 10, 0) == 7            # direction is +1 or -1
    assert gt_on.GT_ArcXYP(10, 0, 10, 1) == 0


def test_arc_yz_zx_centre_angle_l1754_1756(gt_on):
    gt_map_mm(gt_on, axes=(1, 2, 3), pulse_per_mm=100)
    assert gt_on.GT_SetSynVel(0.02) == 0 and gt_on.GT_SetSynAcc(0.0002) == 0
    assert gt_on.GT_ArcYZ(0, 10, 90) == 0                # about (y, z) = (0, 10): from (0,0) a quarter CCW
    gt_on.run(12000)
    assert [gt_on.card.profile_pos(k) / 100 for k in (1, 2)] == [pytest.approx(10), pytest.approx(10)]
    assert gt_on.GT_ArcZX(0, 0, -90) == 0                # about (z, x) = (0, 0): z 10 -> x ... a quarter CW
    gt_on.run(12000)
    assert gt_on.card.profile_pos(2) / 100 == pytest.approx(0, abs=1e-6)
    assert abs(gt_on.card.profile_pos(0) / 100) == pytest.approx(10)


def test_get_mtn_nm_counts_the_buffer_segments_l1971_1985(gt_on):
    gt_map_mm(gt_on, pulse_per_mm=100)
    assert gt_on.GT_GetMtnNm() == (0, 0)                 # immediate mode
    assert [gt_on.GT_StrtList(), gt_on.GT_MvXY(5, 0, 0.05, 0.001)] == [0, 0]
    for x, y in ((10, 0), (10, 10), (0, 10)):
        assert gt_on.GT_LnXY(x, y) == 0
    assert [gt_on.GT_EndList(), gt_on.GT_StrtMtn()] == [0, 0]
    seen = []
    while True:
        gt_on.run(20)
        seen.append(gt_on.GT_GetMtnNm()[1])
        if gt_on.GT_GetCrdSts()[1] & 1:                  # bit 0: 1 when the coordinated motion has finished
            break
    assert seen[0] == 0                                  # the Mv line has no number (L1979)
    assert sorted(set(seen)) == [0, 1, 2, 3] and seen == sorted(seen) and seen[-1] == 3
    assert gt_on.GT_StrtList() == 0 and gt_on.GT_GetMtnNm() == (0, 0)


def test_set_acc_lmt_lowers_the_corner_velocity_l1956_1966(gt_on):
    def axis_velocities(limit):
        g = GtController()
        assert g.GT_Open(sb.Card(4, law=LAW)) == 0
        for a in (1, 2):
            g.GT_Axis(a)
            g.GT_AxisOn()
            if limit is not None:
                assert g.GT_SetAccLmt(limit) == 0            # before the mapping: kept and applied (GF10)
        gt_map_mm(g, pulse_per_mm=100)
        assert [g.GT_StrtList(), g.GT_MvXY(0, 0, 0.05, 0.0005), g.GT_LnXY(20, 0), g.GT_LnXY(20, 20),
                g.GT_EndList(), g.GT_StrtMtn()] == [0] * 6
        run = g.card.run(20000, signals=["prf_vel"])
        return run[0].prf_vel, run[1].prf_vel             # pulse/ST

    vx, vy = axis_velocities(None)
    vx_l, vy_l = axis_velocities(0.2)
    # a 90-degree joint at 5 pulse/ST: without a limit each axis changes its velocity there by the joint speed in
    # one cycle; with AccLmt 0.2 pulse/ST^2 on each axis the vector velocity is lowered so that neither does
    assert np.max(np.abs(np.diff(vx))) > 1 and np.max(np.abs(np.diff(vy))) > 1
    assert np.max(np.abs(np.diff(vx_l))) <= 0.2 + 1e-9 and np.max(np.abs(np.diff(vy_l))) <= 0.2 + 1e-9
    assert vx_l[-1] == vy_l[-1] == 0
    assert gt_on.GT_SetAccLmt(-1) == 7 and gt_on.GT_SetAccLmt(16385) == 7


def test_stp_mtn_keeps_the_breakpoint_and_restarts(gt_on):
    # L1934-1940: StpMtn stops smoothly and closes the buffer; GetBrkPnt gives where; StrtMtn resumes
    gt_map_mm(gt_on, pulse_per_mm=100)
    assert [gt_on.GT_StrtList(), gt_on.GT_MvXY(0, 0, 0.05, 0.001), gt_on.GT_LnXY(50, 0), gt_on.GT_EndList(),
            gt_on.GT_StrtMtn()] == [0] * 5
    gt_on.run(500)                                       # 50 mm at 0.05 mm/ST takes 1000 ST and more
    assert gt_on.GT_StpMtn() == 0
    gt_on.run(2000)
    rtn, brk = gt_on.GT_GetBrkPnt()
    assert rtn == 0 and 0 < brk[0] < 50 and gt_on.GT_GetCrdSts()[1] & 1
    assert gt_on.GT_StrtMtn() == 0
    while not gt_on.GT_GetCrdSts()[1] & 1:
        gt_on.run(100)
    assert gt_on.card.profile_pos(0) == 5000


# -- interrupts --------------------------------------------------------------------------------------------------
def test_set_int_sync_event_is_set_by_the_isr_l2334_2410(gt_on):
    ev = threading.Event()
    assert gt_on.GT_SetIntSyncEvent(ev) == 0
    gt_on.GT_Axis(1)
    assert [gt_on.GT_EvntIntr(), gt_on.GT_ClrSts(), gt_on.GT_SetIntrMsk(0x1)] == [0] * 3
    assert not ev.is_set()
    assert [gt_on.GT_SetAcc(0.1), gt_on.GT_SetVel(1), gt_on.GT_SetPos(100), gt_on.GT_Update()] == [0] * 4
    gt_on.run(300)                                       # motion complete: the interrupt is requested
    assert ev.is_set() and gt_on.GT_GetIntr()[1] & 0x1
    assert gt_on.GT_SetIntSyncEvent(None) == 0           # released before closing (L2340)
    assert gt_on.GT_SetIntSyncEvent(42) == 7


def test_unhook_isr_restores_the_previous_routine_l5164_5182(gt_on):
    calls = []
    old = gt_on.GT_HookIsr(lambda: calls.append("mine"))
    assert old is None
    assert gt_on.GT_UnhookIsr(old) == 0
    gt_on.GT_Axis(1)
    assert [gt_on.GT_ClrSts(), gt_on.GT_SetIntrMsk(0x1), gt_on.GT_SetAcc(0.1), gt_on.GT_SetVel(1),
            gt_on.GT_SetPos(100), gt_on.GT_Update()] == [0] * 6
    gt_on.run(300)
    assert calls == []                                    # unhooked: the routine is not called
    assert GtController().GT_UnhookIsr(None) == -1


# -- registers that read back ---------------------------------------------------------------------------------
def test_getters_read_back_the_staged_registers_l3694_4104(g):
    g.GT_Axis(2)
    assert g.GT_SetKi(12) == 0 and g.GT_GetKi() == (0, 12)
    assert g.GT_SetKd(345) == 0 and g.GT_GetKd() == (0, 345)
    assert g.GT_SetKvff(6) == 0 and g.GT_GetKvff() == (0, 6)
    assert g.GT_SetKaff(789) == 0 and g.GT_GetKaff() == (0, 789)
    assert g.GT_SetMtrBias(-20) == 0 and g.GT_GetMtrBias() == (0, -20)
    assert g.card.axes[1].law.kd == LAW.kd                  # staged only: the active law changes at GT_Update
    assert g.GT_PrflS() == 0 and g.GT_SetJerk(0.001) == 0 and g.GT_GetJerk() == (0, 0.001)
    assert g.GT_SetMAcc(0.25) == 0 and g.GT_GetMAcc() == (0, 0.25)
    assert g.GT_SetRatio(-2.5) == 0 and g.GT_GetRatio() == (0, -2.5)
    assert g.GT_OpenLp() == 0 and g.GT_SetMtrCmd(-1234) == 0 and g.GT_GetMtrCmd() == (0, -1234)


def test_brk_off_and_au_updt_off_l2935_2956_l2775_2800(gt_on):
    gt_on.GT_Axis(1)
    assert [gt_on.GT_AuUpdtOn(), gt_on.GT_SetBrkCn(200), gt_on.GT_SetAcc(0.1), gt_on.GT_SetVel(1),
            gt_on.GT_SetPos(1000), gt_on.GT_Update(), gt_on.GT_PosBrk()] == [0] * 7
    assert gt_on.GT_GetMode()[1] & 0x400
    assert gt_on.GT_AuUpdtOff() == 0 and not gt_on.GT_GetMode()[1] & 0x400
    assert gt_on.GT_BrkOff() == 0                         # cancelled before it triggers (L2947)
    gt_on.run(1200)
    assert not sts(gt_on) & 0x4 and gt_on.card.profile_pos(0) == 1000   # never triggered


def test_lmts_on_stops_at_the_limit_again_l4262_4272():
    rad = 2 * math.pi / 8000
    card = sb.Card(4, law=LAW, switches=sb.Switches(pos_limit_rad=3000 * rad))
    c = GtController()
    assert c.GT_Open(card) == 0 and c.GT_Axis(1) == 0 and c.GT_AxisOn() == 0
    assert c.GT_LmtsOff() == 0 and c.GT_LmtsOn() == 0 and card.limits(0).enabled
    assert [c.GT_SetAcc(0.1), c.GT_SetVel(2), c.GT_SetPos(10000), c.GT_Update()] == [0] * 4
    card.run(6000)
    assert sts(c) & 0x20 and c.GT_GetAtlPos()[1] < 4000  # stopped at the positive limit (bit 5)


def test_gt_home_with_index_l4152_4213():
    rad = 2 * math.pi / 8000
    card = sb.Card(4, law=sb.GtServoLaw(kp=30, ki=0, kd=600, kaff=8000),
                   encoder=sb.Encoder(counts_per_rev=8000, index_angle_rad=6000 * rad),
                   switches=sb.Switches(home_min_rad=20000 * rad, home_max_rad=30000 * rad))
    c = GtController()
    assert c.GT_Open(card) == 0 and c.GT_Axis(1) == 0 and c.GT_AxisOn() == 0
    assert c.GT_Index(2) == 7 and c.GT_Index(1) == 0
    assert [c.GT_SetAcc(0.5), c.GT_SetVel(4)] == [0, 0]
    assert c.GT_Home(100000) == 0
    c.wait_until(lambda: card.profile_vel(0) == 0 and sts(c) & 0x1 and card.tick > 100, max_ticks=200000, chunk=20)
    card.run(2000)
    # Home + Index: it stops at the first index mark past the switch edge at 20000: 22000 (marks at 6000 + 8000 k)
    assert abs(card.axes[0].feedback_pulse - 22000) <= 2
    assert GtController().GT_Index(1) == -1


# -- not simulated ----------------------------------------------------------------------------------------------
def test_unsupported_functions_return_1_with_the_reason(g):
    assert set(UNSUPPORTED) == {"GT_BrkOn", "GT_HomeSense", "GT_SetLmt", "GT_SetBgCommandSet",
                                "GT_GetBgCommandResult"}
    for name in UNSUPPORTED:
        out = getattr(g, name)(0)
        assert (out[0] if isinstance(out, tuple) else out) == 1, name
        assert g.card.last_fault == "not_simulated"
    assert g.GT_BrkOn() == 1 and GtController().GT_SetLmt(0) == -1
    assert GtController().GT_GetBgCommandResult() == (-1, 0)
    assert g.GT_HomeSense() == 1 and g.GT_SetBgCommandSet([], 0) == 1
