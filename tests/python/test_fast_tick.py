"""Issue 22 point 1 and issue 23 point 7: the fused tick gives the general loop's doubles, a default run records a
small set and still gives every signal (replayed exactly), and runs repeat from the initial state unless
continue_=True (decisions P16-P18)."""

import numpy as np
import pytest

import servobench as sb


def _move():
    return sb.trapezoid_move(distance_pulse=3000, vel_pulse_per_tick=12, acc_pulse_per_tick2=0.2, dwell_after=400)


def _axes():
    plant2 = sb.TwoMassPlant(jm_kgm2=2e-5, jl_kgm2=8e-5, k_nm_per_rad=800.0, c_nms_per_rad=0.01,
                             motor_coulomb_nm=0.01, motor_static_nm=0.015, load_coulomb_nm=0.02, load_static_nm=0.03,
                             cogging_nm=0.002, cogging_periods=6)
    filters = (sb.design.lowpass(cutoff_hz=1000, sample_time_s=250e-6).to_adlink(),
               sb.design.notch(center_hz=plant2.resonance_hz, sample_time_s=250e-6, q=2, prewarp=True).to_adlink())
    yield sb.demo_axis()
    yield sb.Axis(law=sb.GtServoLaw(kp=12, ki=10, kd=300, kaff=4000), plant=plant2, servo_period_s=250e-6,
                  filters=filters, encoder=sb.Encoder(noise_counts=0.5, seed=7, on_load=True), substeps=3)
    yield sb.Axis(law=sb.ApsServoLaw(kp=2000, ki=200, kd=20000), servo_period_s=250e-6,
                  drive=sb.TorqueDrive(current_bw_hz=float("inf")),
                  plant=sb.RigidPlant(coulomb_nm=0.004, static_nm=0.006, load_nm=0.001))


KERNELS = ["portable", "sse4.1", "avx2", "avx512"]  # each needs the instructions of the one before it


def _kernels():
    """The fused tick's kernels this CPU runs (decisions SP1, FV20): portable always, then SSE4.1, AVX2 and AVX-512 up
    to the one 'auto' picks."""
    return KERNELS[:KERNELS.index(sb._core.tick_kernel()) + 1]


def _fused_and_general(index, kernel):
    """Axis `index` of _axes() twice: on the fused tick with `kernel`, and on the general loop (the reference)."""
    if kernel not in _kernels():
        pytest.skip(f"this CPU lacks the {kernel} kernel's instructions")
    axis = list(_axes())[index]
    axis._axis.set_tick_kernel(kernel)
    ref = list(_axes())[index]
    ref._axis.set_fused_tick(False)
    return axis, ref


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("index", range(3))
def test_the_fused_tick_gives_the_general_loops_doubles(index, kernel):
    axis, ref = _fused_and_general(index, kernel)
    cmd = _move()
    a = axis.run(cmd, signals="all")
    b = ref.run(cmd, signals="all")
    for name in sb.SIGNALS:
        assert np.array_equal(a[name], b[name], equal_nan=True), name
    a2 = axis.run(cmd.pos[:700] * 0.5, continue_=True, signals="all")  # continued from the written-back state
    b2 = ref.run(cmd.pos[:700] * 0.5, continue_=True, signals="all")
    for name in sb.SIGNALS:
        assert np.array_equal(a2[name], b2[name], equal_nan=True), name
    assert axis.tick == ref.tick and axis.angle_rad == ref.angle_rad and axis.speed_rad_s == ref.speed_rad_s



@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("index", range(3))
def test_a_feedback_only_run_gives_the_general_loops_doubles(index, kernel):
    """Decision SR1: a run recording fb_pos only (the benchmarks' runs; the fused loop skips its recording block):
    its feedback, the state it leaves and a continued run match the general loop bit for bit."""
    axis, ref = _fused_and_general(index, kernel)
    cmd = _move()
    a = axis.run(cmd, signals=["fb_pos"])
    b = ref.run(cmd, signals="all")
    assert list(a.signals) == ["fb_pos"]
    assert np.array_equal(a.fb_pos, b.fb_pos)
    assert axis.tick == ref.tick and axis.angle_rad == ref.angle_rad and axis.speed_rad_s == ref.speed_rad_s
    a2 = axis.run(cmd.pos[:700] * 0.5, continue_=True, signals=["fb_pos"])
    b2 = ref.run(cmd.pos[:700] * 0.5, continue_=True, signals=["fb_pos"])
    assert np.array_equal(a2.fb_pos, b2.fb_pos)
    assert axis.angle_rad == ref.angle_rad and axis.speed_rad_s == ref.speed_rad_s
    assert axis.load_angle_rad == ref.load_angle_rad and axis.load_speed_rad_s == ref.load_speed_rad_s
    assert axis.feedback_pulse == ref.feedback_pulse and axis.tick == ref.tick

def test_a_default_run_records_the_small_set_and_replays_the_rest_exactly():
    assert sb.DEFAULT_SIGNALS == ("time_s", "cmd_pos", "fb_pos", "error", "u", "volts")
    cmd = _move()
    for axis, full_axis in zip(_axes(), _axes()):
        run = axis.run(cmd)
        assert list(run.signals) == list(sb.DEFAULT_SIGNALS)
        full = full_axis.run(cmd, signals="all")
        axis.run(cmd.pos[:50] + 7.0)  # the axis runs on; the replay does not care
        for name in sb.SIGNALS:  # read one: all come, the same doubles as recording them
            assert np.array_equal(run[name], full[name], equal_nan=True), name
            assert np.array_equal(getattr(run, name), full[name], equal_nan=True), name
    with pytest.raises(ValueError, match="'all'"):
        sb.demo_axis().run(np.zeros(5), signals="some")
    with pytest.raises(AttributeError, match="not recorded"):  # an explicit selection still means what it says
        sb.demo_axis().run(np.zeros(5), signals=["fb_pos"]).volts


def test_the_replay_keeps_a_tripped_run_and_injection():
    axis = sb.demo_axis()
    inj = 0.5 * np.sin(np.arange(3000) / 9.0)
    run = axis.run(np.full(3000, 5000.0), injection_v=inj, error_limit_pulse=3000)
    assert run.stopped == "error_limit"
    inj[:] = 0.0  # changing the caller's array later changes nothing
    ref = sb.demo_axis().run(np.full(3000, 5000.0), injection_v=0.5 * np.sin(np.arange(3000) / 9.0),
                             error_limit_pulse=3000, signals="all")
    assert len(run) == len(ref) and np.array_equal(run.current_a, ref.current_a)


def test_runs_repeat_from_the_initial_state_unless_continued():
    cmd = _move()
    axis = sb.demo_axis()
    first = axis.run(cmd)
    again = axis.run(cmd)  # a notebook cell run twice: the same answer
    assert np.array_equal(first.fb_pos, again.fb_pos) and np.array_equal(first.time_s, again.time_s)
    whole = sb.demo_axis().run(cmd.pos[:1000], velocities=cmd.vel[:1000], accelerations=cmd.acc[:1000])
    part = axis.run(cmd.pos[:400], velocities=cmd.vel[:400], accelerations=cmd.acc[:400])
    rest = axis.run(cmd.pos[400:1000], velocities=cmd.vel[400:1000], accelerations=cmd.acc[400:1000],
                    continue_=True)
    assert np.array_equal(np.concatenate([part.fb_pos, rest.fb_pos]), whole.fb_pos)
    assert rest.time_s[0] == pytest.approx(400 * axis.servo_period_s)
    # the initial state is the last reset's, and the servo-off setting is kept
    axis.reset(0.3, speed_rad_s=2.0)
    s1 = axis.run(np.zeros(200), error_limit_pulse=None)
    s2 = axis.run(np.zeros(200), error_limit_pulse=None)
    assert np.array_equal(s1.fb_pos, s2.fb_pos) and s1.fb_pos[0] == pytest.approx(0.3 * 10000 / (2 * np.pi), abs=1)
    axis.set_servo_on(False)
    off1 = axis.run(np.zeros(100), injection_v=np.full(100, 0.2), signals=["fb_pos", "u"], error_limit_pulse=None)
    off2 = axis.run(np.zeros(100), injection_v=np.full(100, 0.2), signals=["fb_pos", "u"], error_limit_pulse=None)
    assert not axis.servo_on and np.all(off1.u == 0) and np.array_equal(off1.fb_pos, off2.fb_pos)
    with pytest.raises(TypeError, match="continue_"):
        axis.run(np.zeros(3), continue_="yes")


def test_step_continues_and_a_run_after_steps_starts_over():
    axis = sb.demo_axis()
    for _ in range(50):
        axis.step(300.0)
    assert axis.tick == 50
    run = axis.run(np.full(50, 300.0))
    ref = sb.demo_axis().run(np.full(50, 300.0))
    assert np.array_equal(run.fb_pos, ref.fb_pos) and axis.tick == 50


def test_the_tick_kernel_is_chosen_for_the_cpu_and_can_be_forced():
    assert sb._core.tick_kernel() in KERNELS
    axis = sb.demo_axis()
    for kernel in ["auto"] + _kernels():
        axis._axis.set_tick_kernel(kernel)
    with pytest.raises(ValueError, match="'auto', 'portable', 'sse4.1', 'avx2' or 'avx512'"):
        axis._axis.set_tick_kernel("avx10")
    for kernel in set(KERNELS) - set(_kernels()):
        with pytest.raises(ValueError, match=f"'{kernel}' cannot run here .*lacks its instructions"):
            axis._axis.set_tick_kernel(kernel)


def test_a_long_recording_is_an_ordinary_array_with_the_same_doubles():
    # From 1 MiB up the recording is allocated outside NumPy's allocator (decision SP3): still an ordinary array.
    n = 300_000
    cmd = np.tile(np.concatenate([np.linspace(0, 4000, 1500), np.full(500, 4000.0), np.linspace(4000, 0, 1500),
                                  np.zeros(500)]), n // 4000 + 1)[:n]
    run = sb.demo_axis().run(cmd, signals=["fb_pos", "u"])
    ref_axis = sb.demo_axis()
    ref_axis._axis.set_fused_tick(False)
    ref = ref_axis.run(cmd, signals=["fb_pos", "u"])
    for name in ("fb_pos", "u"):
        a = run[name]
        assert a.dtype == np.float64 and a.shape == (n,) and a.flags.c_contiguous and a.flags.writeable
        assert a.flags.aligned and np.array_equal(a, ref[name])
        a[0] = 1.5  # writeable, and the memory stays alive with the array
        assert a[0] == 1.5 and np.array_equal(a[1:], ref[name][1:])
    kept = run.fb_pos[::1000].copy()
    fb = run.fb_pos
    del run
    assert np.array_equal(fb[::1000], kept)


@pytest.mark.parametrize("continued", [False, True])
@pytest.mark.parametrize("which", ["positions", "velocities", "injection_v"])
def test_a_bad_sample_deep_in_a_long_run_leaves_the_axis_as_it_was(which, continued):
    # The binding checks the inputs chunk by chunk as the run goes (decision SP5): a NaN found after ticks ran puts
    # the axis back as it was before the call, then raises.
    n = 400_000
    axis = sb.demo_axis()
    axis.run(np.full(3000, 700.0))  # somewhere other than the initial state
    before = (axis.tick, axis.angle_rad, axis.speed_rad_s, axis.feedback_pulse, axis.last_command_pulse)
    pos, vel, inj = np.full(n, 900.0), np.zeros(n), np.zeros(n)
    {"positions": pos, "velocities": vel, "injection_v": inj}[which][n - 5] = np.nan
    with pytest.raises(ValueError, match=rf"{which}\[{n - 5}\] = nan is not a finite number"):
        axis.run(pos, velocities=vel, injection_v=inj, continue_=continued)
    assert (axis.tick, axis.angle_rad, axis.speed_rad_s, axis.feedback_pulse, axis.last_command_pulse) == before
    # the core call without an undo copy restores the state the run began from
    core = axis._axis
    with pytest.raises(ValueError, match="is not a finite number"):
        core.run(pos, vel, None, ["fb_pos"], inj, 0.0, False, None, 0, None)
    assert (axis.tick, axis.angle_rad, axis.speed_rad_s) == before[:3]
    run = axis.run(np.full(3000, 700.0), continue_=True)  # and it runs on from there as if nothing happened
    ref = sb.demo_axis()
    ref.run(np.full(3000, 700.0))
    assert np.array_equal(run.fb_pos, ref.run(np.full(3000, 700.0), continue_=True).fb_pos)


@pytest.mark.parametrize("bad_at", [0, 8191, 8192, 8193, 50_001, 99_999])
def test_the_block_checks_find_a_bad_sample_anywhere_and_restore_the_axis(bad_at):
    # The binding checks each block of 8192 ticks right before it runs (decision SQ1): a bad sample at a block's
    # first or last tick, or deep in a later chunk, names its index and leaves the axis as it was.
    n = 100_000
    for which in ("positions", "accelerations"):
        axis = sb.demo_axis()
        axis.run(np.full(2000, 300.0))
        before = (axis.tick, axis.angle_rad, axis.speed_rad_s, axis.feedback_pulse, axis.last_command_pulse)
        pos, acc = np.full(n, 500.0), np.zeros(n)
        {"positions": pos, "accelerations": acc}[which][bad_at] = np.inf
        with pytest.raises(ValueError, match=rf"{which}\[{bad_at}\] = inf is not a finite number"):
            axis.run(pos, velocities=np.zeros(n), accelerations=acc, continue_=True)
        assert (axis.tick, axis.angle_rad, axis.speed_rad_s, axis.feedback_pulse, axis.last_command_pulse) == before


def test_a_compiled_controller_sees_the_runs_tick_index_across_blocks():
    # The run goes block by block (decision SQ1); a compiled controller's tick argument is still the index in the run.
    import ctypes

    seen = []
    proto = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.c_int64, ctypes.c_double, ctypes.c_double,
                             ctypes.POINTER(ctypes.c_double))
    hook = proto(lambda k, cmd, fb, st: seen.append(k) or 0.0)
    n = 3 * 8192 + 77
    run = sb.demo_axis().run(np.zeros(n), controller=hook, signals=("volts",))
    assert seen == list(range(n)) and run.volts.shape == (n,)
