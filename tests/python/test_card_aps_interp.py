"""ADLINK interpolation (APS_line / arc / spiral with the continuous-interpolation buffer) and the electronic gear
through servobench.dialects.aps on the virtual card, closed loop.

`Lnnnn` = lines of the ADLINK PCI-8254/8258 manual (seed 004; digest adlink.md §6.7, §6.9, test vectors §10);
decisions V113-V125 (docs/decisions.md)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import ApsController
from servobench.homing import pulse_to_rad

LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)  # as test_card_aps_motion
TS = 250e-6  # ADLINK servo period (L1733)
CPR = 10000
EL = 50000  # hard limits at +-EL, pulse
FE_BOUND = 60  # pulse: following error bound of every axis (the card tests' closed-loop bound)


def bit(word, b):
    return bool((word >> b) & 1)


def controller(vm=10000.0, acc=1e5):
    sw = sb.Switches(neg_limit_rad=pulse_to_rad(-EL, CPR), pos_limit_rad=pulse_to_rad(EL, CPR))
    c = ApsController()
    assert c.APS_initial(0, sb.Card(4, law=LAW, servo_period_s=TS, switches=sw,
                                    encoder=sb.Encoder(counts_per_rev=CPR)))[0] == 0
    for i in range(4):
        assert c.APS_set_servo_on(i, 1) == 0
        for para, v in ((aps.PRA_VM, vm), (aps.PRA_ACC, acc), (aps.PRA_DEC, acc)):
            assert c.APS_set_axis_param_f(i, para, v) == 0
    c.run(2)
    return c


def run_until_done(c, axes, limit_ticks=40000):
    """Runs in chunks until every axis reports MDN; returns the concatenated profile/actual positions and errors."""
    pos, act, err = [], [], []
    ticks = 0
    while True:
        r = c.run(200)
        pos.append(np.stack([r[a].pos for a in axes], 1))
        act.append(np.stack([r[a].actual_pos for a in axes], 1))
        err.append(np.stack([r[a].error for a in axes], 1))
        ticks += 200
        if all(bit(c.APS_motion_status(a), aps.MTS_MDN) for a in axes) or ticks >= limit_ticks:
            break
    assert ticks < limit_ticks
    return np.concatenate(pos), np.concatenate(act), np.concatenate(err)


def test_line_axis_speeds_are_the_vector_speed_times_the_direction():
    # T19, L2829-2855: dP = sqrt(dX^2 + dY^2); Vi = dXi/dP * V: dX = 3000, dY = 4000, V = 10000 -> 6000, 8000.
    c = controller(vm=10000)
    assert c.APS_line(2, [0, 1], 0, [3000, 4000], 0.0) == aps.ERR_NoError
    c.run(2000)  # 0.5 s: past the 0.1 s acceleration, before the deceleration (0.5 s + 0.1 s in all)
    vx, vy = (c.card.profile_vel(i) / TS for i in (0, 1))
    assert vx == pytest.approx(6000, rel=1e-6) and vy == pytest.approx(8000, rel=1e-6)
    m = c.APS_motion_status(0)
    assert not bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_CSTP)
    pos, act, err = run_until_done(c, [0, 1])
    assert c.APS_get_command(0) == (0, 3000) and c.APS_get_command(1) == (0, 4000)
    assert np.abs(err).max() < FE_BOUND
    assert np.abs(act[-1] - [3000, 4000]).max() <= 2
    # the path is the straight line: 4 x - 3 y = 0 along the whole profile
    assert np.abs(4 * pos[:, 0] - 3 * pos[:, 1]).max() <= 7  # whole-pulse rounding of both axes
    # after the group: the axes move alone again (the idle group is released, V116)
    assert c.APS_relative_move(0, 100, 10000) == aps.ERR_NoError


def unwrapped_angle_deg(pos, center):
    a = np.unwrap(np.arctan2(pos[:, 1] - center[1], pos[:, 0] - center[0]))
    return np.degrees(a[-1] - a[0])


@pytest.mark.parametrize("direction,sweep", [(0, 30), (1, 390), (-1, -330)])
def test_arc2_ce_angle_is_theta_plus_dir_laps(direction, sweep):
    # T20, L2943-2958: theta = 30 deg; Dir 0 -> 30, 1 -> 390, -1 -> -330 deg; the end point is exact.
    c = controller(vm=20000, acc=2e5)
    r = 2000.0
    end = [r * math.cos(math.radians(30)) - r, r * math.sin(math.radians(30))]
    assert c.APS_arc2_ce([0, 1], 0, [-r, 0], end, direction, 0.0) == aps.ERR_NoError
    pos, act, err = run_until_done(c, [0, 1])
    assert unwrapped_angle_deg(np.vstack([[0, 0], pos]), [-r, 0]) == pytest.approx(sweep, abs=0.2)
    assert c.APS_get_command(0)[1] == round(end[0]) and c.APS_get_command(1)[1] == round(end[1])
    assert np.abs(err).max() < FE_BOUND
    radius = np.hypot(pos[:, 0] + r, pos[:, 1])
    assert np.abs(radius - r).max() < 1.5  # on the circle (whole-pulse profile positions)


def test_arc_ca_spiral_and_relative_option_end_where_they_should():
    # L2886-2926 (arc by centre + angle, 2-D and 3-D), L3001-3035 (spiral_ca), Option bit 0 relative (L3686).
    c = controller(vm=20000, acc=2e5)
    assert c.APS_arc2_ca([0, 1], 1, [1000, 0], 90, 0.0) == 0  # relative centre (1000, 0), CCW quarter
    run_until_done(c, [0, 1])
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [1000, -1000]
    assert c.APS_arc3_ca([0, 1, 2], 0, [1000, 0, 0], [0, 0, 1], 180, 0.0) == 0
    run_until_done(c, [0, 1, 2])
    assert [c.APS_get_command(i)[1] for i in (0, 1, 2)] == [1000, 1000, 0]
    assert c.APS_sprial_ca([0, 1, 2], 0, [1000, 0, 0], [0, 0, 1], 720, 500, 500, 0.0) == 0
    pos, act, err = run_until_done(c, [0, 1, 2])
    assert [c.APS_get_command(i)[1] for i in (0, 1, 2)] == [1000, 500, 500]
    assert np.abs(err).max() < FE_BOUND
    assert np.abs(np.diff(pos[:, 2])).max() > 0  # it rises


def test_blend_percent_starts_the_next_move_at_90_percent():
    # T21, L3138-3143: residual 10 % of a 1000-long move -> the next move starts at 900; MTS BLD while both run.
    c = controller(vm=10000)
    assert c.APS_line(2, [0, 1], aps.ITP_OPT_BUFFERED, [1000, 0], 0.0) == 0
    assert c.APS_line(2, [0, 1], aps.ITP_OPT_BLEND_PCNT, [1000, 1000], 10.0) == 0
    pos, bld = [], []
    for _ in range(4000):
        r = c.run(1)
        pos.append([r[0].pos[0], r[1].pos[0]])
        bld.append(bit(c.APS_motion_status(1), aps.MTS_BLD))
        if bit(c.APS_motion_status(0), aps.MTS_MDN):
            break
    pos, bld = np.array(pos), np.array(bld)
    k = int(np.argmax(bld))  # the first tick of the blend
    assert bld.any() and not bld[-1]
    assert pos[k - 1, 1] == 0 and 900 - 3 <= pos[k, 0] <= 900 + 3  # it begins at 900 (2.5 pulse/tick)
    assert pos[k + 40, 1] > 0
    _, act, err = run_until_done(c, [0, 1])
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [1000, 1000]
    assert np.abs(err).max() < FE_BOUND


def test_buffered_moves_run_in_sequence_and_abort_modes_replace_them():
    # L3117-3122 (Buffered: exact paths in sequence), L3100-3105 (Aborting forced: at once), L3087 (flush).
    c = controller(vm=10000)
    assert c.APS_line(2, [0, 1], aps.ITP_OPT_BUFFERED, [2000, 0], 0.0) == 0
    assert c.APS_line(2, [0, 1], aps.ITP_OPT_BUFFERED, [2000, 2000], 0.0) == 0
    assert c.card.aps_interp_info()["pending"] >= 1
    c.run(400)
    assert c.card.profile_pos(1) == 0  # the second waits for the first
    assert c.APS_line(2, [0, 1], aps.ITP_OPT_ABORT_FORCE | 1, [0, -1000], 0.0) == 0  # relative, at once
    x0 = c.card.profile_pos(0)
    assert c.card.aps_interp_info()["pending"] == 0  # the buffered move was flushed
    run_until_done(c, [0, 1])
    assert c.APS_get_command(1) == (0, -1000)
    assert abs(c.APS_get_command(0)[1] - x0) <= 1


def test_mf_wait_holds_the_group_until_the_move_trigger():
    # L3686-3691: Option bit 8 -> WAIT (MTS bit 10) until APS_move_trigger (L3787-3790; V115).
    c = controller()
    assert c.APS_line(2, [0, 1], aps.MF_WAIT, [1000, 1000], 0.0) == 0
    c.run(200)
    for i in (0, 1):
        m = c.APS_motion_status(i)
        assert bit(m, aps.MTS_WAIT) and not bit(m, aps.MTS_MDN)
        assert c.card.profile_pos(i) == 0
    assert c.APS_move_trigger(2, [0, 1]) == 0
    run_until_done(c, [0, 1])
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [1000, 1000]
    assert not bit(c.APS_motion_status(0), aps.MTS_WAIT)


def test_a_limit_on_any_axis_stops_the_group_with_its_stop_code():
    # L3955-3981 (PEL/MEL stop, codes 4/5, ASTP) on an axis of the group: the whole group stops (V117).
    c = controller(vm=100000, acc=1e6)
    assert c.APS_line(2, [0, 1], 0, [20000, 60000], 0.0) == 0
    pos, act, err = run_until_done(c, [0, 1])
    for i in (0, 1):
        assert c.APS_get_stop_code(i) == (0, aps.STOP_PEL)
        m = c.APS_motion_status(i)
        assert bit(m, aps.MTS_ASTP) and bit(m, aps.MTS_MDN)
    x, y = (c.APS_get_command(i)[1] for i in (0, 1))
    assert EL - 200 < y < 60000 and x < 20000  # stopped at the limit, short of the end
    assert abs(3 * x - y) < 200  # on the line
    # a new interpolation away from the limit starts and clears ASTP (L3652)
    assert c.APS_line(2, [0, 1], 0, [0, 0], 0.0) == 0
    c.run(1)
    assert not bit(c.APS_motion_status(0), aps.MTS_ASTP)


def test_emg_input_stops_the_group_and_stop_move_on_any_axis_decelerates_it():
    c = controller(vm=20000, acc=2e5)
    assert c.APS_line(2, [0, 1], 0, [20000, 20000], 0.0) == 0
    c.run(1000)
    c.card.emergency_stop = True  # L3924-3938: stop at once, code 1
    c.run(2)
    x = c.card.profile_pos(0)
    c.run(100)
    assert c.card.profile_pos(0) == x
    assert [c.APS_get_stop_code(i)[1] for i in (0, 1)] == [aps.STOP_EMG] * 2
    c.card.emergency_stop = False
    assert c.APS_line(2, [0, 1], 0, [20000, 20000], 0.0) == 0
    c.run(1000)
    assert c.APS_stop_move(1) == 0  # the non-reference axis: the group decelerates at the reference SD_DEC
    pos, _, err = run_until_done(c, [0, 1])
    assert np.abs(np.diff(pos[:, 0])).max() <= 20000 * TS + 1  # no jump: a deceleration
    assert [c.APS_get_stop_code(i)[1] for i in (0, 1)] == [aps.STOP_NORMAL] * 2  # a normal stop (V45)
    assert c.card.profile_pos(0) < 20000
    assert np.abs(err).max() < FE_BOUND



def test_interpolation_refused_under_emg_reads_stop_code_emg_like_a_single_axis_move():
    # L3931-3936: with EMG active a motion command is ignored (ERR_NoError) and the stop code reads EMG, ASTP set;
    # the same as APS_relative_move under EMG (test_card_aps.py::test_hard_limit_emergency_stop_and_alarm_codes).
    c = controller(vm=20000, acc=2e5)
    c.card.emergency_stop = True
    c.run(1)
    before = [c.APS_get_command(i)[1] for i in (0, 1)]
    assert c.APS_line(2, [0, 1], 0, [20000, 20000], 0.0) == aps.ERR_NoError
    c.run(50)
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == before
    assert [c.APS_get_stop_code(i)[1] for i in (0, 1)] == [aps.STOP_EMG] * 2
    assert all(bit(c.APS_motion_status(i), aps.MTS_ASTP) for i in (0, 1))

def _moving_ptp(c):
    assert c.APS_relative_move(1, 50000, 20000) == 0
    c.run(100)


def _running_line(c):
    assert c.APS_line(2, [0, 1], 0, [20000, 20000], 0.0) == 0
    c.run(100)


ILLEGAL = {
    "interpolation while an axis of the array moves": (
        _moving_ptp, lambda c: c.APS_line(2, [0, 1], 0, [1000, 1000], 0.0), aps.ERR_FunctionNotAvailable),
    "a ptp on an axis of a running interpolation": (
        _running_line, lambda c: c.APS_relative_move(1, 100, 1000), aps.ERR_FunctionNotAvailable),
    "another axis array while one interpolates (L3077-3079)": (
        _running_line, lambda c: c.APS_line(2, [2, 1], 0, [100, 100], 0.0), aps.ERR_FunctionNotAvailable),
    "arc2_ce over exactly 180 deg (L2930-2933)": (
        _moving_ptp, lambda c: c.APS_arc2_ce([2, 3], 0, [1000, 0], [2000, 0], 0, 0.0), aps.ERR_ParametersInvalid),
    "transition mode field 7": (
        _moving_ptp, lambda c: c.APS_line(2, [2, 3], 0x7000, [100, 100], 0.0), aps.ERR_ParametersInvalid),
    "an axis twice in the array": (
        _moving_ptp, lambda c: c.APS_line(2, [2, 2], 0, [100, 100], 0.0), aps.ERR_ParametersInvalid),
    "blend percent 100": (
        _running_line, lambda c: c.APS_line(2, [0, 1], aps.ITP_OPT_BLEND_PCNT, [0, 0], 100.0),
        aps.ERR_ParametersInvalid),
    "gear on a moving slave": (
        _moving_ptp, lambda c: c.APS_start_gear(1, 1), aps.ERR_FunctionNotAvailable),
}


@pytest.mark.parametrize("case", list(ILLEGAL))
def test_illegal_interpolation_sequences_leave_the_card_unchanged(case):
    setup, call, code = ILLEGAL[case]
    c = controller()
    setup(c)
    before = c.card.snapshot()
    info = c.card.aps_interp_info()
    assert call(c) == code
    assert c.card.snapshot() == before
    assert c.card.aps_interp_info() == info


def test_gear_engages_on_the_ramp_and_releases():
    # L3303-3325: PRA_GEAR_MASTER/ENGAGE_RATE/RATIO on the slave, APS_start_gear; T22 (L3313): engage rate =
    # ratio / engage time: ratio 2 in 0.5 s -> 4 /s. GER = MTS bit 28.
    c = controller()
    for para, v in ((aps.PRA_GEAR_MASTER, 0), (aps.PRA_GEAR_RATIO, 2.0), (aps.PRA_GEAR_ENGAGE_RATE, 4.0)):
        assert c.APS_set_axis_param_f(1, para, v) == 0
    assert c.APS_vel(0, 0, 8000) == 0
    c.run(800)  # master at speed (0.1 s ramp)
    assert c.APS_start_gear(1, 1) == 0
    assert bit(c.APS_motion_status(1), aps.MTS_GER)
    c.run(1000)  # 0.25 s: half the ratio
    assert c.card.gear_ratio(1) == pytest.approx(1.0, abs=0.01)
    c.run(1000)
    assert c.card.gear_ratio(1) == pytest.approx(2.0)
    r = c.run(400)
    assert np.mean(np.diff(r[1].pos)) / TS == pytest.approx(16000, rel=0.01)  # slave = 2 x master speed
    assert np.abs(r[1].error).max() < FE_BOUND
    # on the fly: ratio -1, ramped at 4 /s -> 0.75 s
    assert c.APS_set_axis_param_f(1, aps.PRA_GEAR_RATIO, -1.0) == 0
    c.run(1500)
    assert c.card.gear_ratio(1) == pytest.approx(0.5, abs=0.01)
    c.run(1500)
    assert c.card.gear_ratio(1) == pytest.approx(-1.0)
    r = c.run(2000)
    assert np.abs(r[1].error).max() < FE_BOUND
    # release: the slave holds, the master keeps moving
    assert c.APS_start_gear(1, 0) == 0
    assert not bit(c.APS_motion_status(1), aps.MTS_GER)
    y = c.card.profile_pos(1)
    c.run(200)
    assert c.card.profile_pos(1) == y and c.card.profile_vel(0) / TS == pytest.approx(8000)


def test_a_slave_limit_releases_the_gear_and_the_master_keeps_moving():
    # L3321-3324: EMG/ALM/PEL/MEL of the slave release the gear; the master is not affected.
    c = controller()
    for para, v in ((aps.PRA_GEAR_MASTER, 0), (aps.PRA_GEAR_RATIO, 3.0)):
        assert c.APS_set_axis_param_f(1, para, v) == 0
    assert c.APS_start_gear(1, 1) == 0  # engage rate 0: at once (V120)
    assert c.APS_vel(0, 0, 10000) == 0
    for _ in range(40):
        c.run(200)
        if c.APS_get_stop_code(1)[1]:
            break
    assert c.APS_get_stop_code(1) == (0, aps.STOP_PEL)
    m = c.APS_motion_status(1)
    assert bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_GER)
    assert c.card.profile_vel(0) / TS == pytest.approx(10000)  # the master keeps its speed
    assert c.APS_relative_move(1, -1000, 10000) == 0  # the released slave moves alone, away from the limit


def test_v_all_and_linear_move_forms():
    # L2855-2870: _v overrides VM, _all gives every speed (the PRA values unchanged); the I32 linear moves.
    c = controller(vm=10000)
    assert c.APS_line_v(2, [0, 1], 0, [6000, 8000], 0.0, 5000) == 0
    c.run(4000)  # 1 s: cruise at 5000 pulse/s along (0.6, 0.8)
    assert c.card.profile_vel(1) / TS == pytest.approx(4000, rel=1e-6)
    run_until_done(c, [0, 1])
    assert c.APS_line_all(3, [2, 0, 1], 1, [0, -6000, -8000], 0.0, 0, 20000, 0, 4e5, 4e5, 0.5) == 0
    c.run(2000)  # 0.5 s: cruise at 20000 pulse/s, the S-curve ramps 0.075 s
    assert c.card.profile_vel(0) / TS == pytest.approx(-12000, rel=1e-6)
    assert c.APS_get_axis_param_f(2, aps.PRA_VM) == (0, 10000)
    run_until_done(c, [0, 1, 2])
    assert c.APS_absolute_linear_move(2, [0, 1], [300, 400], 1000) == 0
    run_until_done(c, [0, 1])
    assert c.APS_relative_linear_move(2, [0, 1], [-300, -400], 1000) == 0
    run_until_done(c, [0, 1])
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [0, 0]
    assert c.APS_absolute_linear_move(2, [0, 1], [300.5, 400], 1000) == aps.ERR_ParametersInvalid  # I32
    # spiral by centre + end (L3037-3063): the end is exact
    assert c.APS_sprial_ce([0, 1, 2], 0, [1000, 0, 0], [0, 0, 1], [2000, 0, 300], 0, 0.0) == 0
    _, _, err = run_until_done(c, [0, 1, 2])
    assert [c.APS_get_command(i)[1] for i in (0, 1, 2)] == [2000, 0, 300]
    assert np.abs(err).max() < FE_BOUND
