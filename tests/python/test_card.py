"""servobench.Card: the Python face of machine::Card (construction, staged/active registers, runs, refusals).
Manual lines: GT seed 000 (digest gt.md)."""

import math

import numpy as np
import pytest

import servobench as sb

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)


def test_construction_from_parts_or_axes_and_validation():
    card = sb.Card(4, law=LAW)
    assert len(card) == 4 and card.servo_period_s == 200e-6 and card.tick == 0
    assert [a.law.kp for a in card.axes] == [38] * 4
    assert sb.Card(8).axis_count == 8
    with pytest.raises(ValueError, match="4 or 8"):
        sb.Card(5)
    with pytest.raises(ValueError, match="one servo clock"):
        sb.Card([sb.Axis(), sb.Axis(), sb.Axis(), sb.Axis(servo_period_s=400e-6)])
    with pytest.raises(ValueError, match="host_cycle_ticks"):
        sb.Card(4, motion_cycle_ticks=4, host_cycle_ticks=6)
    with pytest.raises(TypeError):
        sb.Card([sb.Axis()] * 3 + [object()])


def test_staged_registers_commit_at_the_next_tick_and_run_records_numpy():
    card = sb.Card(4, law=LAW)
    card.axis_on(0)
    card.stage_acc(0, 0.1)
    card.stage_vel(0, 5)
    card.stage_pos(0, 10000)
    assert card.staged(0)["pos"] == 10000 and card.active(0)["pos"] == 0
    card.update(0b0001)
    assert card.commit_pending(0) and card.active(0)["pos"] == 0
    run = card.run(3000)
    assert isinstance(run[0].actual_pos, np.ndarray) and run[0].actual_pos.shape == (3000,)
    assert run.to_array("pos").shape == (4, 3000)
    assert card.active(0)["pos"] == 10000
    assert run[0].prf_vel[0] == pytest.approx(0.1) and run[1].prf_vel[0] == 0  # the first tick of the move is the commit tick
    assert abs(run[0].actual_pos[-1] - 10000) <= 1
    assert "motion_complete" in sb.events_named(card.events(0))
    assert run[0].servo_on.all() and not run[1].servo_on.any()
    np.testing.assert_allclose(run[0].time_s, np.arange(3000) * 200e-6)
    with pytest.raises(ValueError, match="unknown signal 'nope'"):
        card.run(1, signals=["nope"])


def test_refused_commands_raise_and_leave_the_state():
    card = sb.Card(4, law=LAW)
    card.axis_on(0)
    card.set_mode(0, "s_curve")
    card.stage_vel(0, 2)
    card.stage_macc(0, 0.01)
    card.stage_jerk(0, 0.001)
    card.stage_pos(0, 5000)
    card.update(1)
    card.run(50)
    card.stage_vel(0, 3)
    with pytest.raises(sb.CardCommandRefused, match="only the target may change"):
        card.update(1)
    assert isinstance(sb.CardCommandRefused("x"), RuntimeError)
    assert card.last_fault == "change_in_motion"
    assert card.active(0)["vel"] == 2
    with pytest.raises(ValueError, match="Card.pos = 0.5"):
        card.stage_pos(0, 0.5)
    assert card.last_fault == "motion_param_overflow"
    with pytest.raises(ValueError, match="mode"):
        card.set_mode(0, "fast")


def test_open_loop_and_limit_sense():
    # GT L776-778 open loop = host MtrCmd; L4219 a wrong LmtSns flags the limits.
    card = sb.Card(4, law=LAW)
    card.set_closed_loop(1, False)
    card.set_mtr_cmd(1, -3276.7)
    card.axis_on(1)
    run = card.run(3, signals=["volts", "u"])
    assert run[1].volts[-1] == pytest.approx(-1.0, abs=1e-3)
    card.set_limits(2, sb.CardLimits(pos_active_low=True))
    card.run(1)
    assert "pos_limit" in sb.events_named(card.events(2))
    assert card.pos_limit_input(2)


def test_soft_limits_estop_and_error_level():
    card = sb.Card(4, law=LAW)
    for i in range(4):
        card.axis_on(i)
    card.set_limits(0, sb.CardLimits(soft_pos_enabled=True, soft_pos_pulse=1500))
    for i in (0, 1):
        card.stage_acc(i, 0.1)
        card.stage_vel(i, 4)
        card.stage_pos(i, 5000)
    card.update(0b11)
    card.run(600)
    assert card.stop_cause(0) == "soft_pos_limit" and not card.moving(0)
    card.emergency_stop = True
    card.run(1)
    assert card.stop_cause(1) == "emergency_stop" and not card.moving(1)
    assert card.emergency_stop
    card.emergency_stop = False
    card.set_error_level(2, 3)
    card.stage_acc(2, 1)
    card.stage_vel(2, 30)
    card.stage_pos(2, 50000)
    card.update(0b100)
    card.run(100)
    assert not card.servo_on(2) and card.stop_cause(2) == "error_level"


def test_run_until_and_units():
    card = sb.Card(4, law=LAW)
    card.axis_on(3)
    card.stage_acc(3, 0.5)
    card.stage_vel(3, 10)
    card.stage_pos(3, 2000)
    card.update(8)
    n = card.run_until(lambda c: not c.moving(3) and c.tick > 0, max_ticks=10000)
    assert 0 < n < 10000 and card.profile_pos(3) == 2000
    assert sb.Card.units("events") == "bits" and sb.Card.units("error") == "pulse"
    assert math.isclose(card.following_error(3), card.run(1)[3].error[0], abs_tol=2)
