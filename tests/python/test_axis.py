"""The servo tick end to end: closed-form response, bias, term reporting, one-tick delay, state, GIL."""

import math
import sys
import threading

import numpy as np
import pytest

import servobench as sb


def ideal_axis(law, *, inertia=1e-4, viscous=0.02, load=0.0, period=200e-6):
    """Linear configuration: ideal drive (no lag, no limit), ideal DAC and encoder, no Coulomb friction."""
    return sb.Axis(
        law=law,
        drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=math.inf, current_bw_hz=math.inf),
        plant=sb.RigidPlant(inertia_kgm2=inertia, viscous_nms=viscous, load_nm=load),
        encoder=sb.Encoder(counts_per_rev=10000, quantize=False),
        dac=sb.Dac(quantize=False),
        servo_period_s=period,
    )


def closed_form_p_loop(kp_eff, r, n, *, inertia, viscous, period):
    """Closed-form discrete response of y (pulse) for U = kp_eff*(r - y) on J*theta'' = kt*A/V*V - b*theta'.

    Plant gain per DAC count: g = kt * A/V * (10/32767) / J * counts_per_rev/(2 pi)   [pulse/s^2 per count].
    With a = b/J and e = exp(-a T), the zero-order hold over one tick T gives exactly
        y+    = y + ydot (1-e)/a + g u (T - (1-e)/a)/a
        ydot+ = ydot e + g u (1-e)/a
    and the output computed at tick k is applied during tick k+1 (u = U[k-1]). With x = [y, ydot, U[k-1]]:
        x[k+1] = A x[k] + B r,   A = [[1, (1-e)/a, g(T-(1-e)/a)/a], [0, e, g(1-e)/a], [-kp, 0, 0]],  B = [0, 0, kp]
    so from rest x[k] = (I - A)^-1 (I - A^k) B r   (A^k by exact repeated squaring).
    """
    g = 0.5 * 0.8 * (10.0 / 32767.0) / inertia * 10000 / (2 * math.pi)
    a, t = viscous / inertia, period
    e = math.exp(-a * t)
    q = (1 - e) / a
    A = np.array([[1.0, q, g * (t - q) / a], [0.0, e, g * q], [-kp_eff, 0.0, 0.0]])
    B = np.array([0.0, 0.0, kp_eff])
    assert np.max(np.abs(np.linalg.eigvals(A))) < 1.0  # the test loop is stable
    inv = np.linalg.inv(np.eye(3) - A)
    return np.array([(inv @ (np.eye(3) - np.linalg.matrix_power(A, k)) @ B * r)[0] for k in range(n)])


@pytest.mark.parametrize("law,kp_eff", [
    (sb.GtServoLaw(kp=10), 10.0),
    (sb.ApsServoLaw(kp=10 * 1024), 10.0),  # default shifts: KP * 2^(-5-5)
])
def test_p_loop_matches_closed_form(law, kp_eff):
    n, r = 3000, 1000.0
    axis = ideal_axis(law)
    run = axis.run(np.full(n, r))
    expected = closed_form_p_loop(kp_eff, r, n, inertia=1e-4, viscous=0.02, period=200e-6)
    rel = np.max(np.abs(run.fb_pos - expected)) / np.max(np.abs(expected))
    assert rel < 1e-9, rel
    assert abs(run.fb_pos[-1] - r) < 1.0  # it did settle toward the target (not a vacuous comparison)


def test_gt_bias_holds_a_constant_load_at_zero_steady_error():
    """GT manual L821: the bias compensates a one-sided load such as gravity on a vertical axis."""
    bias = 1000  # counts -> 1000 * 10/32767 V, exactly one DAC code per count
    tau = 0.5 * 0.8 * bias * 10.0 / 32767.0  # N*m the bias produces through the drive
    common = dict(drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500),
                  plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, load_nm=tau),
                  encoder=sb.Encoder(counts_per_rev=10000))
    n = 20000
    without = sb.Axis(law=sb.GtServoLaw(kp=38, kd=830), **common).run(np.zeros(n))
    with_bias = sb.Axis(law=sb.GtServoLaw(kp=38, kd=830, bias=bias), **common).run(np.zeros(n))
    # Without bias a P-D loop needs a steady error of bias/Kp = 26.3 pulse to hold the load.
    assert abs(np.mean(without.error[-1000:]) - bias / 38) < 1.0
    # With it the steady error is zero: what remains is the +-1 count dither of a quantised encoder on a
    # frictionless axis (no static friction to hold it inside the count).
    tail = with_bias.error[-5000:]
    assert np.max(np.abs(tail)) <= 1.0
    assert abs(np.mean(tail)) < 0.05
    assert np.mean(tail == 0.0) > 0.9
    assert np.all(with_bias.bias == bias)


def test_gt_terms_are_reported_every_tick():
    law = sb.GtServoLaw(kp=38, ki=60, kd=830, kvff=5, kaff=12870, ilmt=32767, bias=-7)
    axis = sb.demo_axis()
    axis.set_law(law)
    move = sb.trapezoid_move(distance_pulse=5000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=200)
    run = axis.run(move)
    e = run.error
    assert np.array_equal(run.p, 38 * e)
    assert np.array_equal(run.d, 830 * np.diff(e, prepend=0.0))
    sums = np.clip(np.cumsum(e), -32767, 32767)
    assert np.max(np.abs(np.abs(np.cumsum(e))) ) < 32767  # no clamp in this run, so the cumsum is exact
    assert np.allclose(run.i, 60 * sums / 256, rtol=0, atol=1e-9)
    assert np.array_equal(run.vff, 5 * move.vel)  # GT takes the profile's own velocity ...
    assert np.array_equal(run.aff, 12870 * move.acc)  # ... and acceleration
    total = run.p + run.i + run.d + run.vff + run.aff + run.bias
    assert np.allclose(run.u, np.clip(total, -32767, 32767), rtol=0, atol=1e-9)
    assert np.array_equal(run.biquad0, run.u) and np.array_equal(run.biquad1, run.u)  # pass-through slots


def test_aps_terms_use_command_differences():
    """ADLINK manual L1723-1731: CmdVel(k) = CmdPos(k) - CmdPos(k-1), CmdAcc(k) = CmdVel(k) - CmdVel(k-1)."""
    law = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32, kvff=100, kaff=12870, kaff_shift=5)
    axis = sb.demo_axis()
    axis.set_law(law)
    move = sb.trapezoid_move(distance_pulse=5000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_before=3)
    run = axis.run(move)
    vel = np.diff(move.pos, prepend=move.pos[0])
    acc = np.diff(vel, prepend=0.0)
    g = law.effective_gains()
    assert np.array_equal(run.cmd_vel, vel)
    assert np.allclose(run.vff, g["kvff"] * vel, rtol=0, atol=1e-12)
    assert np.allclose(run.aff, g["kaff"] * acc, rtol=0, atol=1e-9)
    assert np.allclose(run.p, g["kp"] * run.error, rtol=0, atol=1e-12)
    assert np.allclose(run.u, run.p + run.i + run.d + run.vff + run.aff, rtol=0, atol=1e-9)


def test_output_takes_effect_at_the_next_tick():
    axis = ideal_axis(sb.GtServoLaw(kp=10))
    run = axis.run(np.full(50, 100.0))
    assert run.volts[0] == pytest.approx(10 * 100 * 10 / 32767)
    assert run.current_a[0] == 0.0  # nothing applied during tick 0
    assert np.allclose(run.current_a[1:], 0.8 * run.volts[:-1], rtol=0, atol=1e-15)
    assert run.angle_rad[0] == 0.0 and run.angle_rad[1] == 0.0 and run.angle_rad[2] > 0  # moves from tick 1 on


def test_dac_saturation_and_gt_output_limit():
    axis = sb.Axis(law=sb.GtServoLaw(kp=32767, mtr_lmt=16384), plant=sb.RigidPlant(inertia_kgm2=1.0))
    run = axis.run(np.full(10, 1e6))
    assert np.all(run.u[:5] == 16384)  # +-MtrLmt (GT manual L829)
    assert run.volts[0] == pytest.approx(16384 * 10 / 32767, abs=1e-3)
    axis = sb.Axis(law=sb.GtServoLaw(kp=32767), plant=sb.RigidPlant(inertia_kgm2=1.0))
    run = axis.run(np.full(10, -1e6))
    assert np.all(run.volts[:5] == -10.0)


def test_state_carries_over_between_runs_and_reset_restores_power_on():
    cmd = sb.trapezoid_move(distance_pulse=2000, vel_pulse_per_tick=10, acc_pulse_per_tick2=0.2, dwell_after=300)
    whole = sb.demo_axis().run(cmd)
    axis = sb.demo_axis()
    first = axis.run(cmd.pos[:400], velocities=cmd.vel[:400], accelerations=cmd.acc[:400])
    second = axis.run(cmd.pos[400:], velocities=cmd.vel[400:], accelerations=cmd.acc[400:], continue_=True)
    assert axis.tick == len(cmd)
    assert np.array_equal(np.concatenate([first.fb_pos, second.fb_pos]), whole.fb_pos)
    assert np.array_equal(second.time_s, whole.time_s[400:])
    axis.reset()
    assert axis.tick == 0 and axis.angle_rad == 0.0
    assert np.array_equal(axis.run(cmd).fb_pos, whole.fb_pos)  # deterministic from power-on


def test_signal_selection_and_result_object():
    run = sb.demo_axis().run(np.zeros(10), signals=["time_s", "error"])
    assert list(run.signals) == ["time_s", "error"]
    assert run.units == {"time_s": "s", "error": "pulse"}
    with pytest.raises(AttributeError, match="not recorded"):
        run.volts
    assert "10 ticks" in repr(run)
    assert len(sb.SIGNALS) == 27 and sb.SIGNAL_UNITS["torque_nm"] == "N*m"


def test_demo_axis_tracks_a_move():
    axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1,
                             dwell_before=50, dwell_after=1000)
    m = sb.move_metrics(axis.run(move))
    assert m.peak_following_error_pulse < 10
    assert abs(m.final_error_pulse) <= 1
    assert m.settling_time_s < 0.005
    assert m.overshoot_pulse <= 5


def test_run_releases_the_gil():
    axis = sb.demo_axis()
    cmd = np.zeros(3_000_000)
    done = threading.Event()
    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)
    try:
        started = threading.Event()

        def work():
            started.set()
            axis.run(cmd, signals=["error"])
            done.set()

        th = threading.Thread(target=work)
        th.start()
        started.wait()
        count = 0
        while not done.is_set():
            count += 1
        th.join()
    finally:
        sys.setswitchinterval(old)
    # While the C++ loop ran, this thread kept executing Python code.
    assert count > 10000, count
