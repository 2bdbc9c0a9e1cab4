"""More ADLINK functions (issue 25.3; decisions AF13-AF23): the *_multi stops, APS_vel_all, position and counter
reads, the compare timer, the watchdog, VAO tables, board parameters and the drive mode. `Lnnnn` = lines of the
ADLINK PCI-8254/8258 manual (seed 004)."""

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import ApsController

LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)
TS = 250e-6
TICKS_PER_MS = 4


def bit(word, b):
    return (word >> b) & 1


def ctl(program=False):
    c = ApsController()
    card = sb.Card(4, law=LAW, servo_period_s=TS)
    assert c.APS_initial(0, card)[0] == 0
    for i in range(4):
        assert c.APS_set_servo_on(i, 1) == 0
    if program:
        card.set_clock("program")
    return c


def test_multi_stops_act_on_every_listed_axis_in_one_tick_l2578_l2580():
    c = ctl()
    for i in range(4):
        assert c.APS_set_axis_param_f(i, aps.PRA_SD_DEC, 1e5) == 0
        assert c.APS_vel(i, 0, 8000.0, 0) == 0
    c.Sleep(200)
    assert c.APS_emg_stop_multi(2, [0, 1, 3]) == 0                # only the first Dimension axes
    assert c.APS_stop_move_multi(1, [2]) == 0
    r = c.run(400)
    for i in (0, 1):
        assert np.all(np.diff(r[i].pos) == 0)                       # at once (L2576)
    v2 = np.diff(r[2].pos) / TS
    assert v2[0] > 7000 and v2[-1] == 0 and np.count_nonzero(v2) > 100   # decelerates (L2574)
    assert np.diff(r[3].pos)[-1] / TS == pytest.approx(8000)       # not listed: runs on
    assert all(bit(c.APS_motion_status(i), aps.MTS_MDN) for i in (0, 1, 2))
    assert c.APS_stop_move_multi(2, [0, 9]) == aps.ERR_ParametersInvalid
    assert c.APS_emg_stop_multi(0, [0]) == aps.ERR_ParametersInvalid
    assert ApsController().APS_stop_move_multi(1, [0]) == aps.ERR_DeviceNotInitial


def test_vel_all_uses_its_own_speeds_l2572():
    c = ctl()
    assert c.APS_vel_all(0, 1, 0.0, 4000.0, 0.0, 2e4, 2e4, 0.0, 0) == 0   # negative, 4000 pulse/s, T-curve
    r = c.card.run(2000, signals=["prf_vel"])
    v = r[0].prf_vel / TS
    ramp = np.flatnonzero(v <= -4000 + 1e-6)[0] + 1
    assert v[-1] == pytest.approx(-4000) and ramp * TS == pytest.approx(4000 / 2e4, abs=2 * TS)
    assert c.APS_get_axis_param_f(0, aps.PRA_ACC) == (0, 1e6)         # the axis parameters unchanged
    assert c.APS_vel_all(0, 0, 0.0, 0.0, 0.0, 2e4, 2e4, 0.0, 0) == aps.ERR_ParametersInvalid  # Vm 0
    assert c.APS_vel_all(0, 2, 0.0, 100.0, 0.0, 2e4, 2e4, 0.0, 0) == aps.ERR_ParametersInvalid
    assert c.APS_vel_all(0, 0, 0.0, 100.0, 0.0, 2e4, 2e4, 1.5, 0) == aps.ERR_ParametersInvalid


def test_command_encoder_and_counters_l2056_l2099():
    c = ctl()
    assert c.APS_relative_move(0, 12345, 50000) == 0
    c.wait_until(lambda: bit(c.APS_motion_status(0), aps.MTS_MDN), max_ticks=40000)
    c.run(400)
    assert c.APS_get_command_f(0) == (0, 12345.0)
    assert c.APS_get_command_counter(0) == (0, 12345)
    assert c.APS_get_encoder(0) == c.APS_get_position(0) and abs(c.APS_get_encoder(0)[1] - 12345) <= 2
    err = c.card.actual_pos(0) - c.card.profile_pos(0)
    assert c.APS_set_command(0, 1000) == 0                           # a coordinate shift, the error kept (AF14)
    assert c.APS_get_command(0) == (0, 1000)
    assert c.card.actual_pos(0) - c.card.profile_pos(0) == pytest.approx(err)
    c.run(400)
    assert c.APS_get_command(0) == (0, 1000)                         # no move followed
    assert c.APS_vel(0, 0, 1000.0, 0) == 0
    assert c.APS_set_command(0, 0) == aps.ERR_FunctionNotAvailable    # only at rest
    assert c.APS_set_command(0, 0.5) == aps.ERR_ParametersInvalid
    assert c.APS_get_encoder(7)[0] == aps.ERR_ParametersInvalid


def test_timer_counter_counts_servo_ticks_l3363_l3378():
    c = ctl()
    assert c.APS_set_trigger_param(0, aps.TIMR_ITV, 4) == 0          # one count per 4 ticks = 1 ms
    assert c.APS_get_timer_counter(0, 0) == (0, 0)
    assert c.APS_set_trigger_param(0, aps.TIMR_EN, 1) == 0
    c.run(400)
    assert c.APS_get_timer_counter(0, 0) == (0, 100)
    assert c.APS_set_trigger_param(0, aps.TIMR_DIR, 1) == 0          # counts down from here
    c.run(40)
    assert c.APS_get_timer_counter(0, 0) == (0, 90)
    assert c.APS_set_timer_counter(0, 0, -2147483640) == 0
    c.run(80)
    assert c.APS_get_timer_counter(0, 0) == (0, -2**31)             # held at the I32 limit
    assert c.APS_set_trigger_param(0, aps.TIMR_RING_EN, 1) == 0
    c.run(4)
    assert c.APS_get_timer_counter(0, 0) == (0, 2**31 - 1)          # ring: wraps
    assert c.APS_set_trigger_param(0, aps.TIMR_EN, 0) == 0
    c.run(40)
    assert c.APS_get_timer_counter(0, 0) == (0, 2**31 - 1)          # stopped
    assert c.APS_get_trigger_param(0, aps.TIMR_ITV) == (0, 4)
    assert c.APS_set_trigger_param(0, aps.TIMR_ITV, 0) == aps.ERR_ParametersInvalid
    assert c.APS_get_timer_counter(0, 1)[0] == aps.ERR_ParametersInvalid
    assert c.APS_set_timer_counter(0, 0, 2**31) == aps.ERR_ParametersInvalid


def test_watchdog_fires_when_the_program_stops_resetting_l4025_l4084():
    c = ctl(program=True)
    assert c.APS_write_d_output(0, 0, 0xA5) == 0
    assert c.APS_wdt_set_action_event(0, 0, aps.WDT_ACTION_SERVO_OFF | aps.WDT_ACTION_DO_OFF) == 0
    assert c.APS_wdt_get_action_event(0, 0) == (0, 3)
    assert c.APS_wdt_start(0, 0, 10) == 0                           # 10 x 100 ms = 1 s (L4070)
    assert c.APS_wdt_get_timeout_period(0, 0) == (0, 10)
    assert c.APS_vel(0, 0, 5000.0, 0) == 0
    for _ in range(6):                                              # the example's loop: reset every 500 ms
        c.Sleep(500)
        assert c.APS_wdt_reset_counter(0, 0) == 0
    assert all(bit(c.APS_motion_io_status(i), aps.MIO_SVON) for i in range(4))
    assert c.APS_read_d_output(0, 0) == (0, 0xA5)
    t_reset = c.card.tick
    c.Sleep(999)
    assert bit(c.APS_motion_io_status(0), aps.MIO_SVON)              # not yet
    c.Sleep(2)
    # fired 1 s after the last reset, to within one motion cycle (AF16): every servo off, DO off
    assert not any(bit(c.APS_motion_io_status(i), aps.MIO_SVON) for i in range(4))
    assert c.APS_read_d_output(0, 0) == (0, 0)
    assert c.card.tick - t_reset >= 1.0 / TS
    assert c.APS_wdt_reset_counter(0, 0) == aps.ERR_FunctionNotAvailable   # one-shot: restart with wdt_start
    assert c.APS_wdt_start(0, 1, 10) == aps.ERR_ParametersInvalid          # only timer 0 (L4069)
    assert c.APS_wdt_set_action_event(0, 0, 8) == aps.ERR_ParametersInvalid
    assert c.APS_wdt_start(0, 0, 0) == 0 and c.APS_wdt_reset_counter(0, 0) == aps.ERR_FunctionNotAvailable


def test_watchdog_and_a_program_timer_coexist_aw5():
    """The watchdog checks on its own timer watch (AW5): a program's Card.on_event timer runs beside it."""
    c = ctl()
    seen = []
    c.card.on_event(lambda _card, f: seen.append(f.tick), timer_ticks=40)   # every 10 ms
    assert c.APS_write_d_output(0, 0, 0x1) == 0
    assert c.APS_wdt_set_action_event(0, 0, aps.WDT_ACTION_DO_OFF) == 0
    assert c.APS_wdt_start(0, 0, 1) == 0                                    # 100 ms
    c.Sleep(99)
    assert c.APS_read_d_output(0, 0) == (0, 0x1)
    c.Sleep(3)
    assert c.APS_read_d_output(0, 0) == (0, 0) and len(seen) == 10         # fired; the program's timer ran on
    c.Sleep(50)
    assert len(seen) == 15 and c.APS_wdt_reset_counter(0, 0) == aps.ERR_FunctionNotAvailable


def test_vao_table_interpolates_the_power_over_the_speed_l3489():
    c = ctl()
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_OUTPUT_TYPE + 2 * 2, 1) == 0     # table 2: PWM duty mode
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_INPUT_TYPE + 2 * 2, 1) == 0      # command speed
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_PWM_Config + 2, 1000) == 0       # 1000 Hz
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_SRC + 2, 0x3) == 0               # axes 0 and 1 (L3537-3539)
    # the digest's check T24: (V2, P2) = (100, 400), (V3, P3) = (200, 800), Vx = 150 -> 600
    assert c.APS_set_vao_table(0, 2, 0, 100, 3, [0, 400, 800]) == 0
    assert c.APS_switch_vao_table(0, 2) == 0
    assert c.APS_start_vao(0, 0, 1) == 0
    assert c.APS_vel(0, 0, 90.0, 0) == 0 and c.APS_vel(1, 0, 120.0, 0) == 0     # composite 150 pulse/s
    c.run(4000)
    out = c.vao_output(0)
    assert out["on"] and out["table"] == 2 and out["unit"] == "0.05 %"
    assert out["speed"] == pytest.approx(150.0) and out["power"] == pytest.approx(600.0)
    assert c.APS_vel(0, 0, 3000.0, 0) == 0
    c.run(4000)
    assert c.vao_output(0)["power"] == 800.0                         # held at the last point
    # the DO mapping (PRB_PWM0_MAP_DO, L3530): DO3, logic 1 (DO on enables PWM0)
    assert c.APS_set_board_param(0, aps.PRB_PWM0_MAP_DO, 0x100 | 3) == 0
    assert c.APS_get_board_param(0, aps.PRB_PWM0_MAP_DO) == (0, 0x103)
    assert not c.vao_output(0)["on"] and c.vao_output(0)["power"] == 0.0
    assert c.APS_write_d_output(0, 0, 1 << 3) == 0
    assert c.vao_output(0)["on"]
    assert c.APS_start_vao(0, 0, 0) == 0 and not c.vao_output(0)["on"]
    # refusals: the vendor codes
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_INPUT_TYPE, 0) == aps.ERR_FunctionNotAvailable  # feedback (AF19)
    assert c.APS_start_vao(0, 1, 1) == aps.ERR_FunctionNotAvailable            # controller 1: table 0 not set
    assert c.APS_set_vao_table(0, 2, 0, 100, 33, [0] * 33) == aps.ERR_ParametersInvalid
    assert c.APS_set_vao_table(0, 2, 0, 0, 2, [0, 1]) == aps.ERR_ParametersInvalid
    assert c.APS_set_vao_table(0, 2, 0, 100, 2, [0, 2001]) == aps.ERR_ParametersInvalid
    assert c.APS_switch_vao_table(0, 8) == aps.ERR_ParametersInvalid
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_PWM_Config + 2, 2) == aps.ERR_ParametersInvalid  # < 3 Hz


def test_watchdog_pwm_off_action():
    c = ctl(program=True)
    assert c.APS_set_vao_param(0, aps.VAO_TABLE_INPUT_TYPE, 1) == 0
    assert c.APS_set_vao_table(0, 0, 0, 1000, 2, [100, 200]) == 0
    assert c.APS_start_vao(0, 0, 1) == 0 and c.vao_output(0)["power"] == 100.0
    assert c.APS_wdt_set_action_event(0, 0, aps.WDT_ACTION_PWM_OFF) == 0
    assert c.APS_wdt_start(0, 0, 2) == 0
    c.Sleep(250)
    assert not c.vao_output(0)["on"] and bit(c.APS_motion_io_status(0), aps.MIO_SVON)   # servo left on


def test_board_parameters_and_drive_mode_l1498_l1623():
    c = ctl()
    assert c.APS_get_eep_curr_drv_ctrl_mode(0) == (0, 0b1111)          # 4 axes, analog command (AF18)
    assert c.APS_set_board_param(0, aps.PRS_EMG_LOGIC, 0) == 0
    assert c.APS_set_board_param(0, aps.PRS_EMG_LOGIC, 1) == aps.ERR_FunctionNotAvailable   # AF17
    assert c.APS_set_board_param(0, aps.PRB_PWM1_MAP_DO, 8) == aps.ERR_ParametersInvalid   # DO0..7
    assert c.APS_set_board_param(0, 0x55, 0) == aps.ERR_ParametersInvalid
    assert c.APS_set_board_param(1, aps.PRB_PWM1_MAP_DO, -1) == aps.ERR_ParametersInvalid  # board 0 only
    assert ApsController().APS_get_eep_curr_drv_ctrl_mode(0) == (aps.ERR_DeviceNotInitial, 0)


def test_arc_and_spiral_forms_called_by_name_reach_their_end_at_their_speed_l2978_3052():
    # The _v / _all forms test_dialect_gaps_aps.py reaches through getattr, called by their names here (the
    # function coverage counts calls by name): each ends exactly at its end point at its vector speed Vm.
    from test_card_aps_interp import controller
    from test_dialect_gaps_aps import run_path

    r = 4000.0
    al = (0.0, 12000.0, 0.0, 5e4, 5e4, 0.5)                        # Vs, Vm, Ve, Acc, Dec, SFac
    cases = [
        (lambda c: c.APS_arc2_ca_all([0, 1], 0, [-r, 0], 90, 0.0, *al), (0, 1), (-r, r), 12000.0),
        (lambda c: c.APS_arc2_ce_v([0, 1], 0, [-r, 0], [-r, r], 1, 0.0, 15000.0), (0, 1), (-r, r), 15000.0),
        (lambda c: c.APS_arc3_ca_all([0, 1, 2], 0, [0, 0, -r], [0, 1, 0], 90, 0.0, *al), (0, 1, 2), (r, 0, -r),
         12000.0),
        (lambda c: c.APS_arc3_ce_all([0, 1, 2], 0, [0, 0, -r], [r, 0, -r], 0, 0.0, *al), (0, 1, 2), (r, 0, -r),
         12000.0),
        (lambda c: c.APS_sprial_ca_v([0, 1, 2], 0, [-r, 0, 0], [0, 0, 1], 360, 2000, r / 2, 0.0, 15000.0),
         (0, 1, 2), (-r / 2, 0, 2000), 15000.0),
        (lambda c: c.APS_sprial_ce_all([0, 1, 2], 0, [-r, 0, 0], [0, 0, 1], [-r, r / 2, 2000], 0, 0.0, *al),
         (0, 1, 2), (-r, r / 2, 2000), 12000.0),
    ]
    for call, axes, end, vm in cases:
        c = controller(vm=10000.0, acc=1e5)
        assert call(c) == aps.ERR_NoError
        _pos, v, _err = run_path(c, list(axes))
        assert [c.APS_get_command(i)[1] for i in axes] == [round(x) for x in end]
        assert v.max() == pytest.approx(vm, rel=1e-3)
