"""Illegal sequences return the manual's code and leave the card's state unchanged (issue 10, point 4).

Each case brings a card into a state, snapshots it (Card.snapshot: registers, pending updates, mode, events
without the command-error bit a refusal sets by design, drive, positions, limits, breakpoint, capture), issues
the illegal call in the same tick and compares. GT codes: Table 2-1 (L393-408) and the command-status bits of
Table 2-2 (L455-478), seed 000; ADLINK codes: ErrorCodeDef.h (decision V49), seed 004."""

import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import ApsController
from servobench.dialects.gt import GtController

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)
CMD_ERROR_BIT = 1 << 7  # GT axis status bit 7


def gt_card():
    g = GtController()
    assert g.GT_Open(sb.Card(4, law=LAW)) == 0
    for axis in (1, 2, 3, 4):
        g.GT_Axis(axis)
        assert g.GT_SetKp(38) == 0 and g.GT_SetKd(830) == 0 and g.GT_Update() == 0 and g.GT_AxisOn() == 0
    g.run(2)
    return g


def t_move(g, axis=1):
    g.GT_Axis(axis)
    g.GT_PrflT(); g.GT_SetAcc(0.05); g.GT_SetVel(5); g.GT_SetPos(50000)
    assert g.GT_Update() == 0
    g.run(200)


def s_move(g, axis=2):
    g.GT_Axis(axis)
    g.GT_PrflS(); g.GT_SetMAcc(0.02); g.GT_SetJerk(0.0005); g.GT_SetVel(5); g.GT_SetPos(50000)
    assert g.GT_Update() == 0
    g.run(200)


def t_move_new_acc(g):
    t_move(g)
    assert g.GT_SetAcc(0.2) == 0  # staged: legal; the Update is what the manual refuses


def s_move_new_vel(g):
    s_move(g)
    assert g.GT_SetVel(7) == 0


def drive_alarm(g):
    g.card.set_alarm_input(0, True)
    g.run(1)
    g.card.set_alarm_input(0, False)
    g.run(1)
    g.GT_Axis(1)


def armed_home_capture(g):
    g.GT_Axis(1)
    assert g.GT_CaptHome() == 0


# (set-up, illegal call, expected return code, expected GT_GetCmdSts bit or None)
GT_CASES = {
    "mode change while moving (L837, cmd bit 6)": (t_move, lambda g: g.GT_PrflS(), 1, 6),
    "ZeroPos while moving (L2302, cmd bit 11)": (t_move, lambda g: g.GT_ZeroPos(), 1, 11),
    "SetAtlPos while moving (L4613-4639, cmd bit 11)": (t_move, lambda g: g.GT_SetAtlPos(5), 1, 11),
    "T-curve: new Acc in motion (L974-978, cmd bit 11)": (t_move_new_acc, lambda g: g.GT_Update(), 1, 11),
    "S-curve: new Vel in motion (L1142-1148, cmd bit 11)": (s_move_new_vel, lambda g: g.GT_Update(), 1, 11),
    "MltiUpdt(0) (L4274-4310, cmd bit 2)": (t_move, lambda g: g.GT_MltiUpdt(0), 1, 2),
    "DrvRst with the drive on (L3212-3239, cmd bit 3)": (t_move, lambda g: g.GT_DrvRst(), 1, 3),
    "AxisOn with the alarm latched (L2910-2933, cmd bit 9)": (drive_alarm, lambda g: g.GT_AxisOn(), 1, 9),
    "CaptHome while armed (cmd bit 8)": (armed_home_capture, lambda g: g.GT_CaptHome(), 1, 8),
    "Kp out of range (L4902-4914)": (t_move, lambda g: g.GT_SetKp(40000), 7, None),
    "negative Vel in T mode (L5076-5090)": (t_move, lambda g: g.GT_SetVel(-1), 7, None),
    "MAcc >= 0.5 (L4930-4942)": (s_move, lambda g: g.GT_SetMAcc(0.5), 7, None),
    "axis 5 (L2825-2846)": (t_move, lambda g: g.GT_Axis(5), 7, None),
    "SetMtrCmd out of range (L4958-4970)": (t_move, lambda g: g.GT_SetMtrCmd(40000), 7, None),
}


@pytest.mark.parametrize("case", list(GT_CASES))
def test_gt_illegal_sequences_leave_the_card_unchanged(case):
    setup, call, code, bit = GT_CASES[case]
    g = gt_card()
    setup(g)
    before = g.card.snapshot()
    assert call(g) == code
    assert g.card.snapshot() == before
    if bit is not None:
        assert g.GT_GetCmdSts() == (0, 1 << bit)
        if "MltiUpdt" not in case:  # a card-wide command has no axis to flag
            assert g.GT_GetSts()[1] & CMD_ERROR_BIT  # axis status bit 7: the axis's command was refused
    g.run(5)  # and the card runs on: nothing was half-applied
    assert g.card.snapshot()["axes"][0]["servo_on"] == before["axes"][0]["servo_on"]


def aps_card():
    a = ApsController()
    assert a.APS_initial(0, sb.Card(4, law=sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32), servo_period_s=250e-6))[0] == 0
    for axis in range(4):
        assert a.APS_set_servo_on(axis, 1) == 0
    a.run(2)
    return a


def aps_moving(a):
    assert a.APS_relative_move(0, 50000, 40000) == 0
    a.run(100)


def aps_homing(a):
    assert a.APS_set_axis_param(0, aps.PRA_HOME_DIR, 0) == 0
    assert a.APS_home_move(0) == 0
    a.run(100)


def aps_jogging(a):
    assert a.APS_jog_on(0, 1) == 0
    a.run(100)


def aps_alarm(a):
    a.card.set_alarm_input(0, True)
    a.run(1)


APS_CASES = {
    "set_position while moving": (aps_moving, lambda a: a.APS_set_position(0, 0), aps.ERR_FunctionNotAvailable),
    "a move during homing (L2706-2708)": (aps_homing, lambda a: a.APS_relative_move(0, 100, 1000),
                                          aps.ERR_FunctionNotAvailable),
    "a move while jogging (L2706)": (aps_jogging, lambda a: a.APS_absolute_move(0, 100, 1000),
                                     aps.ERR_FunctionNotAvailable),
    "homing while moving": (aps_moving, lambda a: a.APS_home_move(0), aps.ERR_FunctionNotAvailable),
    "jog while moving (L2708)": (aps_moving, lambda a: a.APS_jog_on(0, 1), aps.ERR_FunctionNotAvailable),
    "servo on with the alarm latched": (aps_alarm, lambda a: a.APS_set_servo_on(0, 1), aps.ERR_FunctionNotAvailable),
    "ptp buffer mode (bits 12-15)": (aps_moving, lambda a: a.APS_ptp(0, 0x1000, 100), aps.ERR_FunctionNotAvailable),
    "fractional distance": (aps_moving, lambda a: a.APS_relative_move(0, 1.5, 1000), aps.ERR_ParametersInvalid),
    "KP above 65535": (aps_moving, lambda a: a.APS_set_axis_param(0, aps.PRA_KP_GAIN, 70000), aps.ERR_ParametersInvalid),
    "S-factor above 1": (aps_moving, lambda a: a.APS_set_axis_param_f(0, aps.PRA_SF, 1.5), aps.ERR_ParametersInvalid),
    "unknown PRA number": (aps_moving, lambda a: a.APS_set_axis_param(0, 0x94, 1), aps.ERR_ParametersInvalid),
    "axis 4 on a PCI-8254": (aps_moving, lambda a: a.APS_relative_move(4, 100, 1000), aps.ERR_ParametersInvalid),
    "move trigger with no axis": (aps_moving, lambda a: a.APS_move_trigger(0, []), aps.ERR_ParametersInvalid),
}


@pytest.mark.parametrize("case", list(APS_CASES))
def test_aps_illegal_sequences_leave_the_card_unchanged(case):
    setup, call, code = APS_CASES[case]
    a = aps_card()
    setup(a)
    before = a.card.snapshot()
    params = [a.APS_get_axis_param_f(0, p) for p in (aps.PRA_KP_GAIN, aps.PRA_SF, aps.PRA_VM, aps.PRA_HOME_VM)]
    assert call(a) == code
    assert a.card.snapshot() == before
    assert [a.APS_get_axis_param_f(0, p) for p in (aps.PRA_KP_GAIN, aps.PRA_SF, aps.PRA_VM, aps.PRA_HOME_VM)] == params
