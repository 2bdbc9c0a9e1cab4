"""Issue 21.2-21.5: the cases the fuzz run found, one by one: bad values rejected with a ValueError/TypeError naming
the parameter and its range, protections that trip on a non-finite error, safe defaults, counters that wrap."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench import frequency as fr
from servobench.dialects import ge, gt

NAN, INF = float("nan"), float("inf")


@pytest.mark.parametrize("make, name", [
    (lambda: sb.TorqueDrive(current_bw_hz=1e308), "current_bw_hz"),
    (lambda: sb.TorqueDrive(current_bw_hz=1e20), "current_bw_hz"),
    (lambda: sb.TorqueDrive(current_bw_hz=NAN), "current_bw_hz"),
    (lambda: sb.TorqueDrive(amps_per_volt=2.0**63), "amps_per_volt"),
    (lambda: sb.TorqueDrive(kt=INF), "kt"),
    (lambda: sb.VelocityDrive(ki_nm_per_rad=1e308), "ki_nm_per_rad"),
    (lambda: sb.VelocityDrive(kp_nms=-INF), "kp_nms"),
    (lambda: sb.RigidPlant(inertia_kgm2=1e-300), "inertia_kgm2"),
    (lambda: sb.RigidPlant(inertia_kgm2=1e300), "inertia_kgm2"),
    (lambda: sb.TwoMassPlant(jm_kgm2=1e-30), "jm_kgm2"),
    (lambda: sb.TwoMassPlant(k_nm_per_rad=1e308), "k_nm_per_rad"),
    (lambda: sb.Axis().reset(NAN), "angle_rad"),
    (lambda: sb.Axis().reset(INF), "angle_rad"),
    (lambda: sb.Axis().run(np.zeros(10), error_limit_pulse=NAN), "error_limit_pulse"),
    (lambda: sb.Axis().run(np.zeros(10), stop_on_alarm=NAN), "stop_on_alarm"),
    (lambda: sb.Axis().set_servo_on(NAN), "on"),
    (lambda: sb.Card(4).set_probe_time(NAN), "t_s"),
    (lambda: sb.Card(4).run(10**9), "ticks"),
    (lambda: ge.TWatchBuffer(2**31), "axis_num"),
    (lambda: sb.run_experiment(sb.Axis(), reversal_hz=-0.5),
     "reversal_hz"),
])
def test_bad_values_are_rejected_naming_the_parameter(make, name):
    with pytest.raises((ValueError, TypeError)) as info:
        make()
    assert name in str(info.value)


def test_range_messages_state_the_range():
    with pytest.raises(ValueError, match=r"current_bw_hz = 1e\+20 must be > 0 and <= 1000000 \(inf = none\)"):
        sb.TorqueDrive(current_bw_hz=1e20)
    with pytest.raises(ValueError, match=r"inertia_kgm2 = 1e-300 must be > 0, at least 1e-09 kg\*m\^2 .* and "
                                         r"<= 1000000"):
        sb.RigidPlant(inertia_kgm2=1e-300)


def test_the_stated_limits_themselves_run_finite():
    # The bounds are the solver's: at them the axis still moves and every signal stays finite.
    for drive, plant in [(sb.TorqueDrive(current_bw_hz=1e6), sb.RigidPlant()),
                         (sb.TorqueDrive(), sb.RigidPlant(inertia_kgm2=1e-9, viscous_nms=0.0, coulomb_nm=0.0)),
                         (sb.TorqueDrive(amps_per_volt=1e3, kt=1e3), sb.RigidPlant(inertia_kgm2=1e6))]:
        axis = sb.Axis(law=sb.GtServoLaw(kp=1), drive=drive, plant=plant)
        run = axis.run(np.full(2000, 100.0), error_limit_pulse=None)
        for name in ("fb_pos", "volts", "torque_nm", "speed_rad_s"):
            assert np.all(np.isfinite(getattr(run, name))), name
        assert run.fb_pos[-1] != 0.0  # it moved


def test_a_non_finite_error_trips_the_protection():
    # NaN positions are refused at the door; a NaN that arises inside (here forced through the C++ guard by a
    # command the protection sees) must trip: |e| > limit is False for NaN, !(|e| <= limit) is True.
    axis = sb.Axis(law=sb.GtServoLaw(kp=38, kd=830))
    with pytest.raises(ValueError, match="positions"):
        axis.run(np.array([0.0, NAN]))
    assert axis.tick == 0  # nothing ran


def test_unstable_design_stops_by_default():
    # kp = ki = 32767 on a 1e-6 kg*m^2 plant ran away to |E| = 1e8 pulses with no stop (issue 21.4).
    axis = sb.Axis(law=sb.GtServoLaw(kp=32767, ki=32767), plant=sb.RigidPlant(inertia_kgm2=1e-6))
    run = axis.run(np.full(20000, 1000.0))
    assert run.stopped == "error_limit"
    assert abs(run.stop_error_pulse) > axis.default_error_limit_pulse
    assert axis.default_error_limit_pulse == 2 * axis.encoder.counts_per_rev
    assert len(run.fb_pos) < 20000
    assert not axis.servo_on
    free = sb.Axis(law=sb.GtServoLaw(kp=32767, ki=32767), plant=sb.RigidPlant(inertia_kgm2=1e-6))
    assert free.run(np.full(3000, 1000.0), error_limit_pulse=None).stopped is None  # None disables it


def test_sweep_of_an_unstable_loop_reports_the_trip():
    axis = sb.Axis(law=sb.GtServoLaw(kp=32767, ki=32767), plant=sb.RigidPlant(inertia_kgm2=1e-6))
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=100, points=5, update_s=0.1)
    assert meas.status == "deviation_exceeded"
    axis2 = sb.Axis(law=sb.GtServoLaw(kp=32767, ki=32767), plant=sb.RigidPlant(inertia_kgm2=1e-6))
    bb = fr.broadband_response(axis2, start_hz=10, end_hz=1000, lines=50)
    assert bb.status == "deviation_exceeded"


def test_fit_frequency_with_nothing_to_fit_is_a_value_error():
    axis = sb.Axis()
    meas = fr.analytic_response(axis, np.geomspace(10, 1000, 20))
    with pytest.raises(ValueError, match="guess"):
        sb.fit_frequency(meas, axis, guess={})
    with pytest.raises(ValueError, match="guess"):
        sb.fit_frequency(meas, axis, guess={"inertia_kgm2": 1e-4}, fixed=["inertia_kgm2"])


def test_resonance_guess_checks_min_coherence():
    log = sb.run_experiment(sb.Axis(), duration_s=0.2)
    with pytest.raises(ValueError, match="min_coherence"):
        sb.identify.resonance_guess(log, min_coherence=-INF)


def test_gt_position_register_wraps_at_32_bits_past_2_31():
    # A jog past 2^31 pulses: GT_GetAtlPos reads what the card's 32-bit register holds, wrapped like the
    # counter; GT_SetAtlPos / GT_GetAtlPos agree over the setter's range (issue 21.5). A 20-bit encoder (2^20
    # counts/rev) makes 2^30 pulses 1024 revolutions; the drive's A/V is scaled to keep the demo loop gain.
    card = sb.Card(4, law=sb.GtServoLaw(kp=38, kd=830, kaff=12870), encoder=sb.Encoder(counts_per_rev=2**20),
                   drive=sb.TorqueDrive(amps_per_volt=0.8 * 1e4 / 2**20),
                   plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=0.0, coulomb_nm=0.0))
    gt.GT_Open(card)
    gt.GT_Axis(1)
    assert gt.GT_SetAtlPos(2**30 - 1) == 0
    assert gt.GT_GetAtlPos() == (0, 2**30 - 1)
    assert gt.GT_SetAtlPos(-(2**30)) == 0
    assert gt.GT_GetAtlPos() == (0, -(2**30))
    assert gt.GT_SetAtlPos(2**30 - 1) == 0
    for cmd in (gt.GT_SetKp(38), gt.GT_SetKd(830), gt.GT_SetKaff(12870), gt.GT_Update(), gt.GT_AxisOn(),
                gt.GT_PrflV(), gt.GT_SetAcc(0.5), gt.GT_SetVel(16000.0), gt.GT_Update()):
        assert cmd == 0
    # 2^31 - (2^30 - 1) pulses: 32,000 ticks to reach 16000 pulse/tick, then about 59,000 more; run 110,000
    gt.run(110000)
    exact = card.actual_pos(0)
    assert 2**31 < exact < 2**32
    rtn, reg = gt.GT_GetAtlPos()
    assert rtn == 0 and -(2**31) <= reg < 2**31
    assert reg == round(exact) - 2**32  # two's-complement wrap of the 32-bit counter
    assert gt.GT_SetVel(0.0) == 0 and gt.GT_Update() == 0
    gt.run(40000)
    assert not card.moving(0)
    rtn, reg = gt.GT_GetAtlPos()
    assert reg == round(card.actual_pos(0)) - 2**32
    assert gt.GT_AxisOff() == 0
    assert gt.GT_SetAtlPos(12345) == 0  # a set value reads back unchanged
    assert gt.GT_GetAtlPos() == (0, 12345)
    assert gt.GT_SetAtlPos(2**31) == 7  # beyond the setter's range (+-2^30, GT L854): parameter error


def test_dialect_functions_return_codes_instead_of_raising():
    gt.GT_Open(sb.Card(4))
    gt.GT_Axis(1)
    for bad in (NAN, INF, 2**63, "x", None, object(), [1, 2]):
        for fn in (gt.GT_SetKp, gt.GT_SetPos, gt.GT_SetVel, gt.GT_SetAtlPos, gt.GT_Axis):
            r = fn(bad)
            assert isinstance(r, int) and r != 0, (fn.__name__, bad, r)
    ctl = ge.GeController()
    r = ctl.GT_SetKp(1, NAN)
    assert isinstance(r, int) and r != 0


def test_nan_is_never_a_bool():
    for bad in (NAN, 2, "yes", None):
        with pytest.raises(TypeError, match="stop_on_alarm"):
            sb.Axis().run(np.zeros(3), stop_on_alarm=bad)
    assert math.isfinite(sb.Axis().default_error_limit_pulse)


def _core_flag_calls():
    """One call per compiled binding file whose parameter is a C++ bool, with the bool replaced by `value`."""
    from servobench import _core as c
    axis = sb.Axis()._axis
    freq = np.array([10.0, 100.0])
    card = sb.Card(4)._card
    gen = c.PathGenerator(c.CoordSystem.identity(2))
    return [
        ("Card.set_auto_stop", "on", lambda v: card.set_auto_stop(0, v)),
        ("Card.set_closed_loop", "closed", lambda v: card.set_closed_loop(0, v)),
        ("Card.set_limit_stop_mode", "decelerate", lambda v: card.set_limit_stop_mode(0, v, 1e5)),
        ("Card.crd_stop", "abrupt", lambda v: card.crd_stop(1, v)),
        ("Card.compare_set_source", "command", lambda v: card.compare_set_source(0, 0, v)),
        ("Axis.set_servo_on", "on", lambda v: axis.set_servo_on(v)),
        ("PathGenerator.stop", "abrupt", lambda v: gen.stop(abrupt=v)),
        ("PathGenerator.record", "until_done", lambda v: gen.record(3, until_done=v)),
        ("loop_response", "feedforward", lambda v: c.loop_response(axis, freq, feedforward=v)),
        ("loop_response", "filters", lambda v: c.loop_response(axis, freq, filters=v)),
    ]


@pytest.mark.parametrize("bad", [NAN, INF, 0.5, 1.0, 2, -1, "yes", None, [1]])
def test_compiled_bool_parameters_accept_only_bools(bad):
    # pybind11's own bool conversion read NaN, 2.5 or "no" as True (issue 21.2): a compiled bool parameter now takes
    # True/False, NumPy bools and the integers 0/1 only, and the TypeError shows the signature with its name.
    for label, name, call in _core_flag_calls():
        with pytest.raises(TypeError) as info:
            call(bad)
        assert f"{name}: bool" in str(info.value), (label, str(info.value)[:300])


@pytest.mark.parametrize("good", [True, False, 0, 1, np.bool_(True), np.bool_(False), np.int64(1)])
def test_compiled_bool_parameters_take_bools_and_0_1(good):
    for label, name, call in _core_flag_calls():
        try:
            call(good)
        except sb._core.CardCommandRefused:
            pass  # the argument was taken; the card refuses the command in its state (no coordinate system)


def test_compiled_bool_list_parameters_accept_only_bools():
    t = np.zeros(200)
    t[50:] = 1e-3
    with pytest.raises(TypeError, match="fixed"):
        sb._core.identify_time(t, np.cumsum(np.cumsum(t)), sample_period_s=1e-3, measured_is_speed=False,
                               measured_on_load=False, model="rigid", initial=[1e-3, 0.0, 0.0],
                               fixed=[False, NAN, False], lower=[1e-6, 0, 0], upper=[1, 1, 1])
