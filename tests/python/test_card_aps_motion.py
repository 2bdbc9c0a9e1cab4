"""ADLINK homing, jog, synchronous start, PTP variants, limit stop mode and distance events through
servobench.dialects.aps on the virtual card.

`Lnnnn` = lines of the ADLINK PCI-8254/8258 manual (seed 004; digest adlink.md §6.3-6.8)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import ApsController
from servobench.homing import pulse_to_rad

LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)  # as test_card_aps (GT tuning in the ADLINK units)
TS = 250e-6  # ADLINK servo period (L1733)
CPR = 10000
ORG = (10000, 14000)  # home switch window, pulse
EL = 50000  # limits at +-EL, pulse
INDEX = 2500


def bit(word, b):
    return bool((word >> b) & 1)


def controller(**parts):
    parts.setdefault("switches", sb.Switches(
        home_min_rad=pulse_to_rad(ORG[0], CPR), home_max_rad=pulse_to_rad(ORG[1], CPR),
        neg_limit_rad=pulse_to_rad(-EL, CPR), pos_limit_rad=pulse_to_rad(EL, CPR)))
    parts.setdefault("encoder", sb.Encoder(counts_per_rev=CPR, index_angle_rad=pulse_to_rad(INDEX, CPR)))
    c = ApsController()
    assert c.APS_initial(0, sb.Card(4, law=LAW, servo_period_s=TS, **parts)) == (aps.ERR_NoError, 1)
    for i in range(4):
        assert c.APS_set_servo_on(i, 1) == 0
    return c


def done(c, axis):
    return bit(c.APS_motion_status(axis), aps.MTS_MDN)


def test_home_move_manual_example():
    # The manual's home example, L2295-2326: mode 0 (ORG), DIR 1 (negative), T-curve, ACC 1e6, VM 1e5, VO 5e4,
    # EZA 0, SHIFT 0, POS 0; wait with Sleep(100) while the motion is not done, then check ASTP.
    c = controller()
    for para, value in ((aps.PRA_HOME_MODE, 0), (aps.PRA_HOME_DIR, 1), (aps.PRA_HOME_CURVE, 0),
                        (aps.PRA_HOME_ACC, 1000000), (aps.PRA_HOME_VM, 100000), (aps.PRA_HOME_VO, 50000),
                        (aps.PRA_HOME_EZA, 0), (aps.PRA_HOME_SHIFT, 0), (aps.PRA_HOME_POS, 0)):
        assert c.APS_set_axis_param(0, para, value) == aps.ERR_NoError
    assert c.APS_get_axis_param(0, aps.PRA_HOME_VO) == (0, 50000)
    assert c.APS_home_move(0) == aps.ERR_NoError
    c.run(1)
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_HMV) and not bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_JOG)
    assert c.APS_relative_move(0, 100, 1000) == aps.ERR_FunctionNotAvailable  # homing runs
    polls = 0
    while not done(c, 0):
        c.Sleep(100)
        polls += 1
        assert polls < 100
    m = c.APS_motion_status(0)
    assert not bit(m, aps.MTS_ASTP) and not bit(m, aps.MTS_HMV)  # homing success (L2319-2326)
    assert c.APS_get_stop_code(0) == (0, aps.STOP_NORMAL)
    # start case C (below ORG with DIR negative: the search reverses at MEL), stops at the PEL-side edge of
    # ORG (L2372); command and feedback positions are then HOME_POS = 0 (L2252)
    assert c.APS_get_command(0) == (0, 0)
    assert abs(c.APS_get_position(0)[1]) <= 2
    assert abs(c.card.axes[0].feedback_pulse - ORG[1]) <= 2
    # the MEL the search met is a level input: once left, moves in both directions work again (V31)
    assert c.APS_relative_move(0, -1000, 40000) == 0
    c.wait_until(lambda: done(c, 0), max_ticks=20000)
    assert c.APS_get_command(0) == (0, -1000)


@pytest.mark.parametrize("direction,edge", [(0, EL), (1, -EL)])
def test_home_mode1_el_is_not_aborted_by_the_limit_it_searches(direction, edge):
    # Mode 1 (L2459-2508): search PEL (DIR 0, positive) or MEL and stop at the limit edge; HOME_POS 100.
    c = controller()
    assert c.APS_set_axis_param(1, aps.PRA_HOME_MODE, 1) == 0
    assert c.APS_set_axis_param(1, aps.PRA_HOME_DIR, direction) == 0
    assert c.APS_set_axis_param(1, aps.PRA_HOME_VM, 200000) == 0
    assert c.APS_set_axis_param(1, aps.PRA_HOME_POS, 100) == 0
    assert c.APS_home_move(1) == 0
    c.wait_until(lambda: done(c, 1), max_ticks=200000)
    assert c.APS_get_stop_code(1) == (0, aps.STOP_NORMAL)
    assert not bit(c.APS_motion_status(1), aps.MTS_ASTP)
    assert c.APS_get_command(1) == (0, 100)
    # the card's coordinates put HOME_POS at the limit edge: raw encoder count - card position = edge - 100
    offset = c.card.axes[1].feedback_pulse - c.APS_get_position(1)[1]
    assert abs(offset - (edge - 100)) <= 1
    # moving away from the limit is allowed; the direction toward it still is while it is active
    away = -5000 if direction == 0 else 5000
    assert c.APS_relative_move(1, away, 40000) == 0
    c.wait_until(lambda: done(c, 1), max_ticks=20000)
    assert c.APS_get_command(1) == (0, 100 + away)


def test_home_parameters_are_validated():
    c = controller()
    assert c.APS_set_axis_param(0, aps.PRA_HOME_MODE, 3) == aps.ERR_ParametersInvalid
    assert c.APS_set_axis_param(0, aps.PRA_HOME_DIR, 2) == aps.ERR_ParametersInvalid
    assert c.APS_set_axis_param_f(0, aps.PRA_HOME_CURVE, 1.5) == aps.ERR_ParametersInvalid
    assert c.APS_get_axis_param(0, aps.PRA_HOME_MODE) == (0, 0)  # unchanged
    # VO above VM is refused when the homing starts (AdlinkHome: 0 < vo <= vm)
    assert c.APS_set_axis_param(0, aps.PRA_HOME_VO, 200000) == 0
    assert c.APS_home_move(0) == aps.ERR_ParametersInvalid
    assert done(c, 0) and c.APS_get_command(0) == (0, 0)


def test_stop_move_during_homing_decelerates():
    # APS_stop_move decelerates at PRA_SD_DEC (L2570-2574), also when it ends a homing sequence.
    c = controller()
    assert c.APS_set_axis_param(0, aps.PRA_HOME_DIR, 0) == 0  # toward ORG at 10000: a long search at VM
    assert c.APS_set_axis_param(0, aps.PRA_SD_DEC, 1e6) == 0
    assert c.APS_home_move(0) == 0
    c.run(400)  # 0.1 s: at VM 1e5 pulse/s after the 0.1 s ramp
    vel = c.card.profile_vel(0) / TS
    assert vel == pytest.approx(1e5, rel=1e-6)
    start = c.APS_get_command(0)[1]
    assert c.APS_stop_move(0) == 0
    c.wait_until(lambda: done(c, 0), max_ticks=10000)
    # v^2 / (2 dec) = 1e10 / 2e6 = 5000 pulse
    assert c.APS_get_command(0)[1] - start == pytest.approx(5000, abs=30)
    assert not bit(c.APS_motion_status(0), aps.MTS_HMV)


def test_jog_continuous_and_step():
    # L2639-2710: continuous mode moves while JOG-ON is on and decelerates when it goes off; step mode moves
    # one offset, waits the delay, then moves on, ending on a whole multiple of the offset.
    c = controller()
    for para, value in ((aps.PRA_JG_MODE, 0), (aps.PRA_JG_DIR, 1), (aps.PRA_JG_ACC, 1e6), (aps.PRA_JG_DEC, 1e6),
                        (aps.PRA_JG_VM, 20000)):
        assert c.APS_set_axis_param_f(2, para, value) == 0
    assert c.APS_jog_on(2, 1) == 0
    c.run(400)
    m = c.APS_motion_status(2)
    assert bit(m, aps.MTS_JOG) and bit(m, aps.MTS_DIR) and not bit(m, aps.MTS_MDN)
    assert c.card.profile_vel(2) / TS == pytest.approx(20000, rel=1e-9)
    assert c.APS_relative_move(2, 100, 1000) == aps.ERR_FunctionNotAvailable  # other motion refused (L2706)
    assert c.APS_jog_on(2, 0) == 0
    c.wait_until(lambda: done(c, 2), max_ticks=10000)
    assert not bit(c.APS_motion_status(2), aps.MTS_JOG)
    # step mode, negative: offset 1000, delay 50 ms; held 0.3 s -> the stop lands on a multiple of 1000
    start = c.APS_get_command(2)[1]
    for para, value in ((aps.PRA_JG_MODE, 1), (aps.PRA_JG_DIR, 0), (aps.PRA_JG_OFFSET, 1000),
                        (aps.PRA_JG_DELAY, 50000)):
        assert c.APS_set_axis_param_f(2, para, value) == 0
    assert c.APS_jog_on(2, 1) == 0
    c.Sleep(300)
    assert c.APS_jog_on(2, 0) == 0
    c.wait_until(lambda: done(c, 2), max_ticks=40000)
    travel = start - c.APS_get_command(2)[1]
    assert travel > 1000 and travel % 1000 == 0
    # a short tap: exactly one offset
    start = c.APS_get_command(2)[1]
    assert c.APS_jog_on(2, 1) == 0
    c.Sleep(1)
    assert c.APS_jog_on(2, 0) == 0
    c.wait_until(lambda: done(c, 2), max_ticks=40000)
    assert start - c.APS_get_command(2)[1] == 1000
    # DI-linked jog is not simulated
    assert c.APS_set_axis_param(2, aps.PRA_JG_MAP_DI_EN, 1) == aps.ERR_FunctionNotAvailable
    assert c.APS_set_axis_param(2, aps.PRA_JG_DELAY, 10_000_001) == aps.ERR_ParametersInvalid


def test_jog_is_ignored_while_another_motion_runs():
    c = controller()
    assert c.APS_relative_move(3, 20000, 40000) == 0
    c.run(10)
    assert c.APS_jog_on(3, 1) == aps.ERR_FunctionNotAvailable  # L2708
    assert not bit(c.APS_motion_status(3), aps.MTS_JOG)


def test_simultaneous_move_example():
    # L3781-3790: APS_ptp(0, 0x100, 10000), APS_ptp(1, 0x100, 20000), APS_move_trigger(2, {0, 1}).
    c = controller()
    option = 0x100
    assert option == aps.MF_WAIT
    assert c.APS_ptp(0, option, 10000, 0) == 0
    assert c.APS_ptp(1, option, 20000, 0) == 0
    c.run(100)
    for axis in (0, 1):
        m = c.APS_motion_status(axis)
        assert bit(m, aps.MTS_WAIT) and c.APS_get_command(axis) == (0, 0)  # waiting, not moving (L3700)
    assert c.APS_move_trigger(2, [0, 1]) == 0
    assert not bit(c.APS_motion_status(0), aps.MTS_WAIT)
    run = c.card.run(6000, signals=["pos"])
    first = [int(np.argmax(run[axis].pos != 0)) for axis in (0, 1)]
    assert first[0] == first[1] <= 3  # both start together (same ACC: the first whole pulse in the same tick)
    assert c.APS_get_command(0) == (0, 10000) and c.APS_get_command(1) == (0, 20000)
    # "each axis then follows its own profile, the end time varies" (L3675): axis 0 finishes first
    assert int(np.argmax(run[0].pos == 10000)) < int(np.argmax(run[1].pos == 20000))
    assert c.APS_move_trigger(0, [0]) == aps.ERR_ParametersInvalid
    assert c.APS_move_trigger(1, [7]) == aps.ERR_ParametersInvalid


def test_waiting_move_meets_a_limit_and_is_ignored():
    c = controller()
    assert c.APS_set_axis_param(0, aps.PRA_SPEL_POS, 500) == 0
    assert c.APS_set_axis_param(0, aps.PRA_SPEL_EN, 1) == 0
    assert c.APS_ptp(0, aps.MF_WAIT, 10000) == 0
    c.card.set_actual_pos(0, 600)  # the axis now stands in the soft limit
    c.run(1)
    assert c.APS_move_trigger(1, [0]) == 0
    assert c.APS_get_command(0) == (0, 600) and c.APS_get_stop_code(0) == (0, aps.STOP_SPEL)


def test_ptp_v_and_ptp_all():
    # L2716-2740: APS_ptp_v takes VM; APS_ptp_all every speed; the axis parameters stay.
    c = controller()
    assert c.APS_set_axis_param_f(0, aps.PRA_ACC, 4e5) == 0
    assert c.APS_set_axis_param_f(0, aps.PRA_DEC, 4e5) == 0
    assert c.APS_ptp_v(0, 0, 10000, 40000) == 0
    ticks = c.wait_until(lambda: done(c, 0), max_ticks=10000)
    assert ticks == pytest.approx(1400, abs=1)  # 0.1 s ramps + 0.15 s cruise
    assert c.APS_ptp_all(0, 1, -10000, 0, 40000, 0, 8e5, 8e5, 0, 0) == 0
    ticks = c.wait_until(lambda: done(c, 0), max_ticks=10000)
    assert ticks == pytest.approx(1200, abs=1)  # 0.05 s ramps + 0.2 s cruise
    assert c.APS_get_command(0) == (0, 0)
    assert c.APS_get_axis_param_f(0, aps.PRA_ACC) == (0, 4e5)  # unchanged by ptp_all
    assert c.APS_ptp_all(0, 0, 100, 0, 40000, 0, -1, 8e5, 0, 0) == aps.ERR_ParametersInvalid
    assert c.APS_ptp_all(0, 0, 100, 0, 40000, 0, 8e5, 8e5, 1.5, 0) == aps.ERR_ParametersInvalid
    assert c.APS_ptp_v(0, 0, 100, 0) == aps.ERR_ParametersInvalid


@pytest.mark.parametrize("el_mode", [0, 1])
def test_el_mode_immediate_or_decelerating_limit_stop(el_mode):
    # L3985-3998: PRA_EL_MODE selects the limit stop: immediate (0) or decelerating at PRA_SD_DEC (1).
    c = controller()
    assert c.APS_set_axis_param_f(0, aps.PRA_SD_DEC, 2e6) == 0
    assert c.APS_set_axis_param(0, aps.PRA_EL_MODE, el_mode) == 0
    assert c.APS_get_axis_param(0, aps.PRA_EL_MODE) == (0, el_mode)
    assert c.APS_set_axis_param(0, aps.PRA_SPEL_POS, 20000) == 0
    assert c.APS_set_axis_param(0, aps.PRA_SPEL_EN, 1) == 0
    assert c.APS_velocity_move(0, 100000) == 0
    c.wait_until(lambda: done(c, 0), max_ticks=20000)
    assert c.APS_get_stop_code(0) == (0, aps.STOP_SPEL)
    overshoot = c.APS_get_command(0)[1] - 20000
    if el_mode == 0:
        assert 0 <= overshoot <= 100000 * TS * 3  # stopped within a few ticks of travel
    else:
        assert overshoot == pytest.approx(1e10 / (2 * 2e6), abs=60)  # v^2 / (2 SD_DEC) = 2500 pulse
    assert c.APS_set_axis_param(0, aps.PRA_EL_MODE, 2) == aps.ERR_ParametersInvalid


def test_pre_and_post_distance_events():
    # L3284-3292, L3661-3662: PRED when the travelled distance > PRE_EVENT_DIST, POSTD when the remaining
    # distance < POST_EVENT_DIST; both cleared when the next motion starts.
    c = controller()
    assert c.APS_set_axis_param(0, aps.PRA_PRE_EVENT_DIST, 2000) == 0
    assert c.APS_set_axis_param(0, aps.PRA_POST_EVENT_DIST, 1000) == 0
    assert c.APS_get_axis_param(0, aps.PRA_POST_EVENT_DIST) == (0, 1000)
    assert c.APS_relative_move(0, 10000, 40000) == 0
    pred = postd = None
    for k in range(3000):
        c.run(1)
        m = c.APS_motion_status(0)
        pos = c.APS_get_command(0)[1]
        if pred is None and bit(m, aps.MTS_PRED):
            pred = pos
        if postd is None and bit(m, aps.MTS_POSTD):
            postd = pos
        assert not bit(m, aps.MTS_POSTD) or pos > 9000
    assert 2000 < pred <= 2000 + 40000 * TS + 1
    assert 9000 < postd <= 9000 + 40000 * TS + 1
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_PRED) and bit(m, aps.MTS_POSTD) and bit(m, aps.MTS_MDN)  # kept after the stop
    assert c.APS_relative_move(0, -10000, 40000) == 0
    m = c.APS_motion_status(0)
    assert not bit(m, aps.MTS_PRED) and not bit(m, aps.MTS_POSTD)  # cleared at the start
