"""Mechanics and drives through the Python face: two-mass plant, friction curve, velocity drive, drive alarm,
encoder noise/index/mounting, switches, analytic plant response."""

import math

import numpy as np
import pytest

import servobench as sb


def test_two_mass_reports_its_resonances():
    p = sb.TwoMassPlant(jm_kgm2=2e-5, jl_kgm2=6e-5, k_nm_per_rad=400.0)
    assert p.antiresonance_hz == pytest.approx(math.sqrt(400 / 6e-5) / (2 * math.pi))
    assert p.resonance_hz == pytest.approx(math.sqrt(400 * 8e-5 / (2e-5 * 6e-5)) / (2 * math.pi))
    f = np.logspace(1, 3.5, 2000)
    mag = np.abs(p.frequency_response(f, output="motor"))
    # The motor-side response has its notch at the anti-resonance and its peak at the resonance.
    k_min = np.argmin(mag * (2 * np.pi * f) ** 2)
    k_max = np.argmax(mag * (2 * np.pi * f) ** 2)
    assert f[k_min] == pytest.approx(p.antiresonance_hz, rel=0.01)
    assert f[k_max] == pytest.approx(p.resonance_hz, rel=0.01)


def test_zoh_response_tends_to_continuous_at_low_frequency():
    p = sb.TwoMassPlant()
    f = np.array([1.0, 5.0, 20.0])
    hc = p.frequency_response(f)
    hd = p.frequency_response(f, period_s=100e-6)
    # ZOH adds the half-sample delay: H_d ~ H_c * exp(-j w T/2) for f << fs.
    assert np.allclose(hd, hc * np.exp(-1j * 2 * np.pi * f * 50e-6), rtol=1e-3)
    with pytest.raises(ValueError, match="Nyquist"):
        p.frequency_response([6000.0], period_s=100e-6)
    with pytest.raises(ValueError, match="output = 'middle'"):
        p.frequency_response([10.0], output="middle")


def test_friction_curve_is_the_stribeck_curve():
    p = sb.RigidPlant(coulomb_nm=0.02, static_nm=0.03, stribeck_speed_rad_s=0.1, stribeck_exponent=2.0,
                      viscous_nms=1e-3)
    w = np.array([-10.0, -0.1, 0.0, 1e-6, 0.1, 10.0])
    t = p.friction_torque(w)
    expected = np.sign(w) * (0.02 + 0.01 * np.exp(-(np.abs(w) / 0.1) ** 2)) + 1e-3 * w
    assert np.allclose(t, expected, rtol=0, atol=1e-15)
    assert t[3] == pytest.approx(0.03, abs=1e-9)  # breakaway level just above zero speed


def open_loop_axis(plant, drive=None, **kw):
    """An axis whose controller outputs a constant voltage: GT law with only the bias term."""
    return sb.Axis(law=kw.pop("law", sb.GtServoLaw()), plant=plant, drive=drive or sb.TorqueDrive(), **kw)


def test_velocity_drive_tracks_its_speed_command():
    drive = sb.VelocityDrive(speed_per_volt_rad_s=10.0, kp_nms=0.05, ki_nm_per_rad=5.0, loop_rate_hz=20000)
    axis = sb.Axis(law=sb.GtServoLaw(bias=3277), drive=drive, plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-3))
    assert axis.substeps_per_tick == 4  # 200 us at 20 kHz
    run = axis.run(np.zeros(5000), signals=["volts", "speed_rad_s"])
    assert run.volts[-1] == pytest.approx(3277 * 10 / 32767, abs=1e-3)
    # PI loop: zero steady speed error against the viscous load.
    assert run.speed_rad_s[-1] == pytest.approx(10.0 * run.volts[-1], rel=1e-6)


def test_velocity_drive_torque_limit_caps_acceleration():
    drive = sb.VelocityDrive(speed_per_volt_rad_s=100.0, kp_nms=1.0, torque_limit_nm=0.2)
    axis = sb.Axis(law=sb.GtServoLaw(bias=32767), drive=drive, plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=0))
    run = axis.run(np.zeros(50), signals=["torque_nm", "speed_rad_s"])
    assert np.max(np.abs(run.torque_nm)) <= 0.2 + 1e-12
    acc = np.diff(run.speed_rad_s) / axis.servo_period_s
    assert np.max(acc) <= 0.2 / 1e-4 * (1 + 1e-9)


def test_drive_alarm_trips_at_the_chosen_time():
    drive = sb.TorqueDrive(current_bw_hz=math.inf, alarm_at_s=0.01)
    axis = open_loop_axis(sb.RigidPlant(), drive, law=sb.GtServoLaw(bias=1000))
    run = axis.run(np.zeros(100), signals=["time_s", "alarm", "current_a"])
    tripped = np.flatnonzero(run.alarm)
    assert run.time_s[tripped[0]] == pytest.approx(0.0102, abs=1e-9)  # first tick after 10 ms: t = 10.2 ms records it
    assert np.all(run.alarm[tripped[0]:] == 1) and axis.alarm
    assert np.all(run.current_a[tripped[0]:] == 0.0)
    assert np.all(run.current_a[1:tripped[0]] > 0.0)
    axis.reset()
    assert not axis.alarm


def test_encoder_noise_is_seeded():
    def fb(seed):
        enc = sb.Encoder(noise_counts=2.0, seed=seed)
        return sb.Axis(encoder=enc).run(np.zeros(2000), signals=["fb_pos"]).fb_pos

    a, b, c = fb(7), fb(7), fb(8)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, c)
    assert 1.5 < np.std(a) < 2.5  # the axis is at rest (zero gains): what varies is the noise


def test_index_marks_once_per_revolution_and_encoder_mounting():
    plant = sb.TwoMassPlant(jm_kgm2=2e-5, jl_kgm2=6e-5, k_nm_per_rad=400.0)
    for on_load in (False, True):
        enc = sb.Encoder(counts_per_rev=10000, on_load=on_load, index_angle_rad=0.5)
        axis = open_loop_axis(plant, sb.TorqueDrive(), encoder=enc, law=sb.GtServoLaw(bias=300))
        run = axis.run(np.zeros(20000))
        shaft = run.load_angle_rad if on_load else run.angle_rad
        assert np.array_equal(run.fb_pos, np.floor(shaft * 10000 / (2 * np.pi) + 0.5))
        revs = np.floor((shaft - 0.5) / (2 * np.pi))
        assert np.sum(run.index) == revs[-1] - revs[0] > 3


def test_switch_windows():
    sw = sb.Switches(home_min_rad=1.0, home_max_rad=1.5, pos_limit_rad=3.0, neg_limit_rad=-0.5)
    axis = open_loop_axis(sb.RigidPlant(), switches=sw, law=sb.GtServoLaw(bias=200))
    run = axis.run(np.zeros(20000))
    a = run.load_angle_rad
    assert np.array_equal(run.home_sw == 1, (a >= 1.0) & (a <= 1.5))
    assert np.array_equal(run.pos_limit_sw == 1, a >= 3.0)
    assert np.all(run.neg_limit_sw == 0) and a[-1] > 3.0


def test_stiction_holds_a_closed_loop_at_rest_without_chatter():
    """An integrating loop on a Stribeck axis: no creep while the torque stays below breakaway."""
    plant = sb.RigidPlant(coulomb_nm=0.05, static_nm=0.08)
    axis = open_loop_axis(plant, sb.TorqueDrive(), law=sb.GtServoLaw(bias=600))  # 600 counts -> 0.073 N*m
    run = axis.run(np.zeros(100000), signals=["angle_rad", "speed_rad_s"])
    assert np.all(run.angle_rad == 0.0) and np.all(run.speed_rad_s == 0.0)


def test_identical_configuration_gives_identical_runs():
    def go():
        axis = sb.Axis(plant=sb.TwoMassPlant(motor_coulomb_nm=0.01, load_coulomb_nm=0.01, load_static_nm=0.02),
                       law=sb.GtServoLaw(kp=20, kd=400, ki=10), encoder=sb.Encoder(noise_counts=0.7, seed=3))
        return axis.run(sb.trapezoid_move(distance_pulse=3000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.05,
                                          dwell_after=500)).fb_pos

    assert np.array_equal(go(), go())


def stepper_axis(**plant_kw):
    drive = sb.StepperDrive(full_steps_per_rev=200, microsteps=16, holding_torque_nm=0.5)
    plant = sb.RigidPlant(inertia_kgm2=1e-5, viscous_nms=1e-3, **plant_kw)
    return sb.Axis(drive=drive, plant=plant, substeps=4)


def test_stepper_follows_the_step_train_below_pull_out():
    axis = stepper_axis()
    move = sb.trapezoid_move(distance_pulse=3200, vel_pulse_per_tick=1.0, acc_pulse_per_tick2=0.01, dwell_after=2000)
    run = axis.run(move)
    assert np.all(run.volts == 0) and np.all(run.u == 0)  # pulse output: no servo law, no DAC
    lag = move.pos * 2 * np.pi / 3200 - run.angle_rad
    assert np.max(np.abs(lag)) < 0.25 * (2 * np.pi / 200)  # never a quarter full step behind
    assert run.angle_rad[-1] == pytest.approx(2 * np.pi, abs=1e-4)  # one revolution, no step lost


def test_stepper_loses_whole_teeth_beyond_pull_out():
    axis = stepper_axis(coulomb_nm=0.02)
    # 3 pulse/tick^2 needs J*alpha = 1e-5 * 3 * (2 pi/3200) / (200 us)^2 = 1.5 N*m, three times the holding torque.
    move = sb.trapezoid_move(distance_pulse=32000, vel_pulse_per_tick=60, acc_pulse_per_tick2=3.0, dwell_after=5000)
    run = axis.run(move)
    pitch = 2 * np.pi / 50  # one rotor tooth = 4 full steps
    lost = (move.pos[-1] * 2 * np.pi / 3200 - run.angle_rad[-1]) / pitch
    assert abs(lost) >= 1  # steps were lost ...
    assert abs(lost - round(lost)) < 0.05  # ... by whole tooth pitches (the rotor re-locks on a tooth)


def test_servo_position_drive_tracks_pulses():
    drive = sb.ServoPositionDrive(pulses_per_rev=10000, kpp_per_s=300, kp_nms=0.03, ki_nm_per_rad=3.0)
    axis = sb.Axis(drive=drive, plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, coulomb_nm=0.005))
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=2000)
    run = axis.run(move)
    assert abs(run.fb_pos[-1] - 10000) <= 1
    assert np.max(np.abs(run.error)) < 60  # pulses of lag while moving, with the speed feed-forward
    no_ff = sb.Axis(drive=drive.replace(speed_feedforward=0.0), plant=axis.plant).run(move)
    assert np.max(np.abs(no_ff.error)) > 5 * np.max(np.abs(run.error))
