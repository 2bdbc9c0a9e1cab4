"""The ADLINK manual's programs and status rules run against the virtual card through servobench.dialects.aps.

`Lnnnn` = lines of the ADLINK PCI-8254/8258 manual (seed 004); TVnn = the test vectors of the digest adlink.md §10."""

import math

import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import ApsController

# The GT tuning of test_card_gt (Kp 38, Kd 830 counts/pulse) in the ADLINK law's units with the default shifts
# (KP x 2^-10, KD x 2^-5, L1753-1758); ADLINK servo period 250 us (L1733).
LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)
TS = 250e-6


@pytest.fixture
def a():
    c = ApsController()
    rtn, bits = c.APS_initial(0, sb.Card(4, law=LAW, servo_period_s=TS))
    assert (rtn, bits) == (aps.ERR_NoError, 1)
    return c


def bit(word, b):
    return bool((word >> b) & 1)


def test_not_initialised_twice_and_bad_ids():
    c = ApsController()
    assert c.APS_set_servo_on(0, 1) == aps.ERR_DeviceNotInitial
    assert c.APS_motion_status(0) == aps.ERR_DeviceNotInitial
    assert c.APS_initial()[0] == aps.ERR_NoError  # a default 4-axis card with the ADLINK law at 250 us
    assert c.card.servo_period_s == TS
    assert c.APS_initial()[0] == aps.ERR_DeviceAlreadyInitialed
    assert c.APS_set_servo_on(4, 1) == aps.ERR_ParametersInvalid  # axes 0..3 on a PCI-8254
    assert c.APS_set_axis_param(0, 0x94, 1) == aps.ERR_ParametersInvalid  # 94h-99h are not documented
    assert c.APS_close() == aps.ERR_NoError and c.APS_close() == aps.ERR_DeviceNotInitial
    assert aps.APS_close() in (aps.ERR_NoError, aps.ERR_DeviceNotInitial)  # module-level functions exist


def test_parameter_defaults_and_gain_shift_example(a):
    # TV3 (L1748-1762): gains 0 -- here the fixture's law --, shifts -5/-15/0/0/0, PID -5, V_LIMIT 10, limit 2^31-1
    assert a.APS_get_axis_param(0, aps.PRA_KP_SHIFT) == (0, -5)
    assert a.APS_get_axis_param(0, aps.PRA_KI_SHIFT) == (0, -15)
    assert a.APS_get_axis_param(0, aps.PRA_PID_SHIFT) == (0, -5)
    assert a.APS_get_axis_param(0, aps.PRA_SERVO_V_LIMIT) == (0, 10)
    assert a.APS_get_axis_param(0, aps.PRA_INTEGRAL_LIMIT) == (0, 2147483647)
    assert a.APS_get_axis_param(0, aps.PRA_ERR_POS_LEVEL) == (0, 0)
    # TV1 (L1733): KP 100, KP shift 2, PID shift 3 -> equivalent KP 3200 (= 100 * 2^(2+3); the manual's "x 3" is a typo)
    assert a.APS_set_axis_param(1, aps.PRA_KP_GAIN, 100) == 0
    assert a.APS_set_axis_param(1, aps.PRA_KP_SHIFT, 2) == 0
    assert a.APS_set_axis_param(1, aps.PRA_PID_SHIFT, 3) == 0
    a.run(1)
    assert a.card.active(1)["law"].effective_gains()["kp"] == 3200
    # out of range: refused, nothing changes (0~65535, 31~-31, L1748-1758)
    for para, value in ((aps.PRA_KP_GAIN, 65536), (aps.PRA_KD_SHIFT, -32), (aps.PRA_KI_GAIN, 1.5),
                        (aps.PRA_SERVO_V_LIMIT, 11), (aps.PRA_ACC, -1)):
        before = a.APS_get_axis_param_f(1, para)
        assert a.APS_set_axis_param_f(1, para, value) == aps.ERR_ParametersInvalid
        assert a.APS_get_axis_param_f(1, para) == before


def test_velocity_move_example(a):
    # L2606-2630: STP_DEC 10000, CURVE 0.5, ACC = DEC = 10000; APS_vel 500 -> 1000 -> 600 -> stop, 2 s apart.
    # TV38: with S = 0.5 the ramp 0 -> 500 takes (1 + S) * 500 / 10000 = 0.075 s (adlink.md §6.2).
    assert a.APS_set_servo_on(0, 1) == 0
    assert a.APS_set_axis_param_f(0, aps.PRA_STP_DEC, 10000.0) == 0
    assert a.APS_set_axis_param_f(0, aps.PRA_CURVE, 0.5) == 0
    assert a.APS_set_axis_param_f(0, aps.PRA_ACC, 10000.0) == 0
    assert a.APS_set_axis_param_f(0, aps.PRA_DEC, 10000.0) == 0
    vel = lambda: a.card.profile_vel(0) / TS  # pulse/s
    assert a.APS_vel(0, 0, 500.0, 0) == 0
    a.Sleep(74)
    m = a.APS_motion_status(0)
    assert bit(m, aps.MTS_ACC) and not bit(m, aps.MTS_MDN) and bit(m, aps.MTS_DIR)
    assert vel() < 500
    a.Sleep(2)
    assert vel() == pytest.approx(500, abs=1e-6) and bit(a.APS_motion_status(0), aps.MTS_VM)
    a.Sleep(2000 - 76)
    assert a.APS_vel(0, 0, 1000.0, 0) == 0  # on the fly (L2564)
    a.Sleep(2000)
    assert vel() == pytest.approx(1000, abs=1e-6)
    assert a.APS_vel(0, 0, 600.0, 0) == 0
    a.Sleep(59)  # (1 + S) * 400 / 10000 = 0.06 s down to 600
    assert bit(a.APS_motion_status(0), aps.MTS_DEC)
    a.Sleep(2)
    assert vel() == pytest.approx(600, abs=1e-6)
    a.Sleep(2000 - 61)
    assert a.APS_stop_move(0) == 0  # decelerates at PRA_STP_DEC: (1 + S) * 600 / 10000 = 0.09 s
    a.Sleep(89)
    assert not bit(a.APS_motion_status(0), aps.MTS_MDN)
    a.Sleep(2)
    m = a.APS_motion_status(0)
    assert bit(m, aps.MTS_MDN) and bit(m, aps.MTS_CSTP) and not bit(m, aps.MTS_ASTP)
    assert a.APS_get_stop_code(0) == (0, aps.STOP_NORMAL)
    # distance of the profile: 500*2 + 1000*2 + 600*2 s minus the ramps' shortfalls (S-ramps symmetric: dV*t/2)
    expect = (500 * 2 - 500 * 0.075 / 2) + (1000 * 2 - 500 * 0.075 / 2) + (600 * 2 + 400 * 0.06 / 2) + 600 * 0.09 / 2
    assert a.APS_get_command(0)[1] == pytest.approx(expect, abs=2)


def test_ptp_in_position_and_motion_done(a):
    # L2724: completion via APS_motion_status (MDN); INP once at rest within the band; positions readable.
    assert a.APS_set_servo_on(2, 1) == 0
    assert a.APS_set_axis_param_f(2, aps.PRA_ACC, 4e5) == 0
    assert a.APS_set_axis_param_f(2, aps.PRA_DEC, 4e5) == 0
    assert a.APS_relative_move(2, 10000, 40000) == 0
    a.run(10)
    assert not bit(a.APS_motion_io_status(2), aps.MIO_INP)
    ticks = a.wait_until(lambda: bit(a.APS_motion_status(2), aps.MTS_MDN), max_ticks=10000)
    # 0.1 s ramps, 0.15 s cruise: 0.35 s = 1400 ticks from the call (an APS move starts at once, no Update)
    assert 10 + ticks == pytest.approx(1400, abs=1)
    assert a.APS_get_command(2) == (0, 10000)
    a.wait_until(lambda: bit(a.APS_motion_io_status(2), aps.MIO_INP), max_ticks=4000)
    rtn, pos = a.APS_get_position(2)
    assert rtn == 0 and abs(pos - 10000) <= 10
    assert abs(a.APS_get_error_position(2)[1]) <= 10
    io = a.APS_motion_io_status(2)
    assert bit(io, aps.MIO_SVON) and not bit(io, aps.MIO_ALM)
    # absolute move back, and APS_ptp with option bit 0 = relative (L3686-3691)
    assert a.APS_absolute_move(2, 0, 40000) == 0
    a.wait_until(lambda: bit(a.APS_motion_status(2), aps.MTS_MDN), max_ticks=10000)
    assert a.APS_get_command(2) == (0, 0) and not bit(a.APS_motion_status(2), aps.MTS_DIR)
    assert a.APS_ptp(2, 1, -3000.0) == 0
    a.wait_until(lambda: bit(a.APS_motion_status(2), aps.MTS_MDN), max_ticks=10000)
    assert a.APS_get_command(2) == (0, -3000)
    assert a.APS_ptp(2, 0x1000, 0.0) == aps.ERR_FunctionNotAvailable  # buffer modes (bits 12-15) not simulated


def test_error_pos_level_trips_servo_off(a):
    # L4012-4023: |E| > PRA_ERR_POS_LEVEL -> servo off, stop code STOP_ERROR_LEVEL, ASTP (V41: code 13).
    assert a.APS_set_servo_on(1, 1) == 0
    assert a.APS_set_axis_param(1, aps.PRA_ERR_POS_LEVEL, 5) == 0
    assert a.APS_set_axis_param_f(1, aps.PRA_ACC, 4e8) == 0
    assert a.APS_set_axis_param_f(1, aps.PRA_DEC, 4e8) == 0
    assert a.APS_relative_move(1, 50000, 400000) == 0
    a.run(100)
    io, m = a.APS_motion_io_status(1), a.APS_motion_status(1)
    assert not bit(io, aps.MIO_SVON) and bit(m, aps.MTS_ASTP) and bit(m, aps.MTS_MDN)
    assert a.APS_get_stop_code(1) == (0, aps.STOP_ERROR_LEVEL)
    # recovery: servo on again; a new move clears ASTP (L3652)
    assert a.APS_set_axis_param(1, aps.PRA_ERR_POS_LEVEL, 0) == 0
    assert a.APS_set_servo_on(1, 1) == 0
    assert a.APS_relative_move(1, 1000, 40000) == 0
    assert not bit(a.APS_motion_status(1), aps.MTS_ASTP)
    assert a.APS_get_stop_code(1) == (0, aps.STOP_NORMAL)


@pytest.mark.parametrize("positive", [True, False])
def test_soft_limit_stop_codes_and_ignored_commands(a, positive):
    # L3983-4010: SPEL/SMEL stop at once with codes 6/7 and ASTP; further motion toward the limit is ignored
    # (ERR_NoError, nothing moves, the stop code stays), motion away is allowed.
    sign = 1 if positive else -1
    assert a.APS_set_servo_on(3, 1) == 0
    assert a.APS_set_axis_param(3, aps.PRA_SPEL_POS, 2000) == 0
    assert a.APS_set_axis_param(3, aps.PRA_SMEL_POS, -2000) == 0
    assert a.APS_set_axis_param(3, aps.PRA_SPEL_EN, 1) == 0
    assert a.APS_set_axis_param(3, aps.PRA_SMEL_EN, 1) == 0
    assert a.APS_relative_move(3, sign * 20000, 40000) == 0
    a.run(4000)
    code = aps.STOP_SPEL if positive else aps.STOP_SMEL
    assert a.APS_get_stop_code(3) == (0, code)
    m, io = a.APS_motion_status(3), a.APS_motion_io_status(3)
    assert bit(m, aps.MTS_ASTP) and bit(m, aps.MTS_MDN)
    assert bit(io, aps.MIO_SPEL if positive else aps.MIO_SMEL)
    cmd = a.APS_get_command(3)
    assert a.APS_relative_move(3, sign * 100, 40000) == aps.ERR_NoError  # ignored
    a.run(10)
    assert a.APS_get_command(3) == cmd and a.APS_get_stop_code(3) == (0, code)
    assert a.APS_relative_move(3, -sign * 1000, 40000) == 0
    assert not bit(a.APS_motion_status(3), aps.MTS_ASTP)


def test_hard_limit_emergency_stop_and_alarm_codes():
    # L3931-3981: EMG 1, ALM 2, PEL 4, MEL 5 with ASTP; motion ignored while active.
    rad = 2 * math.pi / 10000
    c = ApsController()
    card = sb.Card(4, law=LAW, servo_period_s=TS,
                   switches=sb.Switches(pos_limit_rad=3000 * rad, neg_limit_rad=-3000 * rad))
    c.APS_initial(0, card)
    for i in range(4):
        assert c.APS_set_servo_on(i, 1) == 0
    assert c.APS_relative_move(0, 10000, 40000) == 0
    assert c.APS_relative_move(1, -10000, 40000) == 0
    c.run(3000)
    assert c.APS_get_stop_code(0) == (0, aps.STOP_PEL) and bit(c.APS_motion_io_status(0), aps.MIO_PEL)
    assert c.APS_get_stop_code(1) == (0, aps.STOP_MEL) and bit(c.APS_motion_io_status(1), aps.MIO_MEL)
    assert c.APS_velocity_move(2, 20000) == 0
    c.run(100)
    card.emergency_stop = True
    c.run(1)
    assert c.APS_get_stop_code(2) == (0, aps.STOP_EMG) and bit(c.APS_motion_io_status(2), aps.MIO_EMG)
    assert bit(c.APS_motion_status(2), aps.MTS_MDN)
    assert c.APS_relative_move(3, 100, 40000) == aps.ERR_NoError  # ignored, code 1 (L3936)
    assert c.APS_get_stop_code(3) == (0, aps.STOP_EMG) and c.APS_get_command(3) == (0, 0)
    card.emergency_stop = False
    card.set_alarm_input(3, True)
    c.run(1)
    assert c.APS_get_stop_code(3) == (0, aps.STOP_ALM)
    io = c.APS_motion_io_status(3)
    assert bit(io, aps.MIO_ALM) and not bit(io, aps.MIO_SVON)
    assert c.APS_set_servo_on(3, 1) == aps.ERR_FunctionNotAvailable  # alarm latched: state unchanged
    assert not bit(c.APS_motion_io_status(3), aps.MIO_SVON)


def test_illegal_sequences_leave_state_unchanged(a):
    assert a.APS_set_servo_on(0, 1) == 0
    assert a.APS_relative_move(0, 20000, 40000) == 0
    a.run(50)
    assert a.APS_set_position(0, 0) == aps.ERR_FunctionNotAvailable  # at rest only
    assert a.APS_relative_move(0, 1.5, 40000) == aps.ERR_ParametersInvalid
    assert a.APS_relative_move(0, 100, 0) == aps.ERR_ParametersInvalid
    # a PTP move shorter than its VS -> VE steps needs (decision M9): the distance is not enough
    assert a.APS_set_axis_param_f(1, aps.PRA_VS, 20000) == 0  # 20000^2 / (2 * DEC 1e6) = 200 pulse to stop
    assert a.APS_relative_move(1, 1, 40000) == aps.ERR_DistantNotEnough
    assert a.APS_get_command(1) == (0, 0) and bit(a.APS_motion_status(1), aps.MTS_MDN)
    a.wait_until(lambda: bit(a.APS_motion_status(0), aps.MTS_MDN), max_ticks=20000)
    assert a.APS_set_position(0, 5) == 0
    assert a.APS_get_command(0) == (0, 5)
