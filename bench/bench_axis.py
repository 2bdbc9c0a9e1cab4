"""Benchmark: servo ticks per second of one simulated axis, C++ core vs the same loop in pure Python.

The full chain of this version: GT servo law -> two (pass-through) filter slots -> 16-bit DAC -> torque drive
with a first-order current loop -> rigid plant with Coulomb friction (exact ZOH) -> quantised encoder.
The pure-Python loop implements the same tick (its ZOH from scipy.linalg.expm) and must reproduce the C++
feedback exactly before its speed is reported. Writes bench/results/axis_ticks.md.

Run: python bench/bench_axis.py [--ticks 1000000] [--python-ticks 200000] [--quick] [--results-dir DIR]
"""

from __future__ import annotations

import argparse
import datetime
import math
import os
import platform
import time

import numpy as np

import servobench as sb

import benchlib

GOAL_TICKS_PER_S = 10e6  # product goal for the full chain on one core
GOAL_VS_TIGHT = 1.5  # rigid chain, feedback only: within 1.5x of a tight C++ loop of the same arithmetic (issue 22)
GOAL_VS_NUMBA = 1.0  # rigid chain, feedback only: >= 1.0x the same loop compiled with numba (issue 22 point 1)
GOAL_FULL_CHAIN = 15e6  # full chain (two-mass, Stribeck, two biquads, DAC, current loop), ticks/s (issue 22 point 1)
GOAL_FLAT = 1.25  # cost per tick at the longest run / at 10^4 ticks, feedback only ("flat", issue 22 point 1)


def python_reference(axis: sb.Axis, cmd: sb.Trajectory, n: int) -> np.ndarray:
    """The servo tick of servobench written in plain Python (GT law, DAC, lagged torque drive, rigid plant with
    Coulomb friction solved implicitly with stiction, quantised encoder). Returns the feedback (pulse) per tick."""
    from scipy.linalg import expm

    law, drv, pl, enc = axis.law, axis.drive, axis.plant, axis.encoder
    ts = axis.servo_period_s
    wc = 2 * math.pi * drv.current_bw_hz
    j = pl.inertia_kgm2
    a = np.array([[-wc, 0, 0], [0, 0, 1], [drv.kt / j, 0, -pl.viscous_nms / j]])
    b = np.array([[wc, 0], [0, 0], [0, 1 / j]])  # inputs: current command, external torque

    def zoh(a_, b_):
        m = np.zeros((5, 5))
        m[:3, :3], m[:3, 3:] = a_ * ts, b_ * ts
        e = expm(m)
        return e[:3, :3].tolist(), e[:3, 3:].tolist()

    phi, gam = zoh(a, b)
    al, bl = a.copy(), b.copy()
    al[1:, :] = 0
    bl[1:, :] = 0
    phil, gaml = zoh(al, bl)  # mechanics locked by stiction: only the current loop moves
    cpr = enc.counts_per_rev / (2 * math.pi)
    kp, ki, kd, kvff, kaff = law.kp, law.ki, law.kd, law.kvff, law.kaff
    ilmt, bias, mlim = law.ilmt, law.bias, law.mtr_lmt
    apv, ilim, coul, load = drv.amps_per_volt, drv.current_limit_a, pl.coulomb_nm, pl.load_nm
    fs = max(pl.static_nm, coul)
    g, gth = gam[2][1], gam[1][1]
    i = th = w = 0.0
    stuck = True
    s = e_prev = 0.0
    pending = 0.0
    pos, vel, acc = cmd.pos.tolist(), cmd.vel.tolist(), cmd.acc.tolist()
    out = [0.0] * n
    for k in range(n):
        icmd = max(-ilim, min(ilim, apv * pending))
        y = math.floor(th * cpr + 0.5)
        err = pos[k] - y
        s = max(-ilmt, min(ilmt, s + err))
        u = kp * err + ki * s / 256 + kd * (err - e_prev) + kvff * vel[k] + kaff * acc[k] + bias
        u = max(-mlim, min(mlim, u))
        e_prev = err
        v = max(-10.0, min(10.0, u * (10 / 32767)))
        out[k] = y
        pending = round(v * 3276.7) / 3276.7  # 16-bit DAC
        ext = -load
        xi = phi[0][0] * i + phi[0][1] * th + phi[0][2] * w + gam[0][0] * icmd + gam[0][1] * ext
        xt = phi[1][0] * i + phi[1][1] * th + phi[1][2] * w + gam[1][0] * icmd + gam[1][1] * ext
        xw = phi[2][0] * i + phi[2][1] * th + phi[2][2] * w + gam[2][0] * icmd + gam[2][1] * ext
        if fs == 0.0:
            i, th, w = xi, xt, xw
            continue
        d = xt - th
        st = False
        f_slip = -coul if w > 0 else coul
        if w != 0.0 and (xw + g * f_slip) * (1.0 if w > 0 else -1.0) > 0.0:
            f = f_slip
        else:
            f_stick = -xw / g
            if -fs <= f_stick <= fs:
                f, st = f_stick, True
            else:
                f = -fs if xw > 0 else fs
        if not (st and w == 0.0) and f * (d + gth * f) > 0.0:
            st = False
            f = 0.0 if d == 0.0 else (-1.0 if d > 0 else 1.0) * min(abs(f), abs(d) / gth)
        if st and stuck and w == 0.0:
            i = phil[0][0] * i + gaml[0][0] * icmd + gaml[0][1] * ext
            continue
        i, th, w = xi + gam[0][1] * f, xt + gam[1][1] * f, xw + gam[2][1] * f
        if st:
            w = 0.0
        stuck = st
    return np.array(out)


def long_move(n: int) -> sb.Trajectory:
    """Back-and-forth moves filling n ticks (each 10000 pulse at 20 pulse/tick, 0.1 pulse/tick^2)."""
    one = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=200)
    back = sb.trapezoid_move(start_pulse=10000, distance_pulse=-10000, vel_pulse_per_tick=20,
                             acc_pulse_per_tick2=0.1, dwell_after=200)
    reps = n // (len(one) + len(back)) + 1
    cat = lambda f: np.tile(np.concatenate([getattr(one, f), getattr(back, f)]), reps)[:n]  # noqa: E731
    return sb.Trajectory(pos=cat("pos"), vel=cat("vel"), acc=cat("acc"))


def full_chain_axis(drive_mode: str) -> sb.Axis:
    """Two-mass plant with Stribeck friction on both sides, cogging, quantised encoder, 16-bit DAC, both filter
    slots, GT law at 250 us; torque- or velocity-mode drive (20 kHz speed loop: 5 sub-steps per tick)."""
    plant = sb.TwoMassPlant(jm_kgm2=2e-5, jl_kgm2=8e-5, k_nm_per_rad=800.0, c_nms_per_rad=0.01,
                            motor_coulomb_nm=0.01, motor_static_nm=0.015, load_coulomb_nm=0.02, load_static_nm=0.03,
                            cogging_nm=0.002, cogging_periods=6)
    if drive_mode == "torque":
        drive = sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500)
        law = sb.GtServoLaw(kp=12, ki=10, kd=300, kaff=4000)
    else:
        drive = sb.VelocityDrive(speed_per_volt_rad_s=31.4, kp_nms=0.02, ki_nm_per_rad=2.0, loop_rate_hz=20000)
        law = sb.GtServoLaw(kp=200, kvff=1000)
    # Both biquad slots busy, in the card's integer form: a 1 kHz low-pass and a notch at the plant's resonance.
    filters = (sb.design.lowpass(cutoff_hz=1000, sample_time_s=250e-6).to_adlink(),
               sb.design.notch(center_hz=plant.resonance_hz, sample_time_s=250e-6, q=2, prewarp=True).to_adlink())
    return sb.Axis(law=law, drive=drive, plant=plant, servo_period_s=250e-6, filters=filters)


def card_run(card_ticks: int, sampler: bool) -> float:
    """Wall time of `card_ticks` ticks of a 4-axis virtual card (demo axes, GT law, each axis jogging at +-5
    pulse/tick), recording nothing; with `sampler`, the card's scope takes the four following errors every tick."""
    base = sb.demo_axis()
    card = sb.Card(4, law=base.law, drive=base.drive, plant=base.plant, encoder=base.encoder)
    for i in range(4):
        card.axis_on(i)
        card.set_mode(i, "jog")
        card.stage_acc(i, 0.05)
        card.stage_vel(i, 5.0 if i % 2 == 0 else -5.0)
    card.update(0b1111)
    if sampler:
        card.sample([(i, "error") for i in range(4)], depth=10000, continuous=True)
    t0 = time.perf_counter()
    card._card.run(card_ticks, [])
    return time.perf_counter() - t0


def alternate_cpu(ours, theirs, repeats: int):
    """CPU-time medians (s) of `ours()` and `theirs()` run alternately `repeats` times in this process (so load
    changes hit both alike); returns (ours s, theirs s, the last values `ours()` and `theirs()` returned)."""
    t_ours, t_theirs, v_ours, v_theirs = [], [], None, None
    for _ in range(repeats):
        c0 = time.process_time()
        v_ours = ours()
        t_ours.append(time.process_time() - c0)
        c0 = time.process_time()
        v_theirs = theirs()
        t_theirs.append(time.process_time() - c0)
    return float(np.median(t_ours)), float(np.median(t_theirs)), v_ours, v_theirs


def median_cpu(fn, repeats: int, setup=None) -> float:
    """Median CPU time (s) of `repeats` calls of fn() in this process. With `setup`, each call is fn(setup()) and
    setup() runs before the clock starts: an axis is built (filter design, discretisation), then only its run is
    timed (decision FV23)."""
    times = []
    for _ in range(repeats):
        arg = setup() if setup is not None else None
        c0 = time.process_time()
        fn(arg) if setup is not None else fn()
        times.append(time.process_time() - c0)
    return float(np.median(times))


def best_of(fn, repeats: int, setup=None) -> float:
    """Shortest wall time (s) of `repeats` calls of fn(); `setup` as in median_cpu."""
    best = math.inf
    for _ in range(repeats):
        arg = setup() if setup is not None else None
        t0 = time.perf_counter()
        fn(arg) if setup is not None else fn()
        best = min(best, time.perf_counter() - t0)
    return best


FULL = dict(ticks=1_000_000, python_ticks=200_000, flat=(10_000, 100_000, 1_000_000, 10_000_000, 100_000_000))
QUICK = dict(ticks=20_000, python_ticks=5_000, flat=(10_000, 20_000))


def run(quick: bool = False, ticks: int | None = None, python_ticks: int | None = None) -> benchlib.Result:
    """Measures every row (C++ chains, card, pure-Python tick in the same run) and returns the figures and table."""
    size = dict(QUICK if quick else FULL)
    size.update({k: v for k, v in dict(ticks=ticks, python_ticks=python_ticks).items() if v is not None})
    n_ticks = size["ticks"]
    load_start = os.getloadavg()[0]
    rep5, rep3 = (1, 1) if quick else (5, 3)
    cmd = long_move(n_ticks)
    rows = []

    def cpp_run(signals):
        axis = sb.demo_axis()
        axis.run(cmd, signals=signals)

    t_all = best_of(lambda: cpp_run("all"), rep5)
    t_default = best_of(lambda: cpp_run(None), rep5)
    t_min = best_of(lambda: cpp_run(["fb_pos"]), rep5)
    t_chain = {}
    for mode in ("torque", "velocity"):
        slow = long_move(n_ticks)
        slow = sb.Trajectory(pos=slow.pos * 0.5, vel=slow.vel * 0.5, acc=slow.acc * 0.25)
        # The axis is built outside the timing (decision FV23): its filter design and two-mass discretisation take
        # ~4 ms, about 5 % of a 10^6-tick run, and are not ticks.
        t_chain[mode] = best_of(lambda axis: axis.run(slow, signals="all"), rep3,
                                setup=lambda: full_chain_axis(mode))

    card_ticks = n_ticks // 4
    t_card = min(card_run(card_ticks, False) for _ in range(rep3))
    t_card_scope = min(card_run(card_ticks, True) for _ in range(rep3))

    # Same work check: the pure-Python tick reproduces the C++ feedback exactly. Its ZOH comes from SciPy's expm.
    n_py = min(size["python_ticks"], n_ticks)
    scipy_linalg = benchlib.import_peer("scipy.linalg", "scipy")
    py_rate = None
    if scipy_linalg is not None:
        ref_axis = sb.demo_axis()
        cpp_fb = ref_axis.run(sb.Trajectory(cmd.pos[:n_py], cmd.vel[:n_py], cmd.acc[:n_py]),
                              signals=["fb_pos"]).fb_pos
        t0 = time.perf_counter()
        py_fb = python_reference(sb.demo_axis(), cmd, n_py)
        t_py = time.perf_counter() - t0
        mismatch = int(np.count_nonzero(py_fb != cpp_fb))
        if mismatch:
            raise SystemExit(f"pure-Python reference differs from the C++ core at {mismatch} of {n_py} ticks")
        py_rate = n_py / t_py

    # The strongest peer for the simulated loop: the same rigid chain compiled with numba (issue 22), checked to
    # reproduce the C++ feedback exactly on every tick; CPU-time medians of alternating runs in this process.
    numba = benchlib.import_peer("numba", "numba")
    nb_rate = nb_cpu = sb_cpu = None
    if numba is not None:
        import numba_peer

        chain, _ = numba_peer.kernels()
        consts = numba_peer.chain_constants(sb.demo_axis())
        chain(consts, cmd.pos[:10], cmd.vel[:10], cmd.acc[:10], np.empty(10))  # compile (not timed)

        def numba_run():  # allocates its output like servobench's run does (decision SP4)
            out = np.empty(n_ticks)
            chain(consts, cmd.pos, cmd.vel, cmd.acc, out)
            return out

        sb_cpu, nb_cpu, ref_fb, nb_out = alternate_cpu(
            lambda: sb.demo_axis().run(cmd, signals=["fb_pos"]).fb_pos, numba_run, rep5)
        bad = int(np.count_nonzero(nb_out != ref_fb))
        if bad:
            raise SystemExit(f"numba peer differs from the C++ core at {bad} of {n_ticks} ticks")
        nb_rate = n_ticks / nb_cpu

    # The fused tick's kernels (decision SP1): the one this CPU runs by default against the portable one, forced.
    kernel = sb._core.tick_kernel()

    def sb_kernel_run(name):
        axis = sb.demo_axis()
        axis._axis.set_tick_kernel(name)
        return axis.run(cmd, signals=["fb_pos"]).fb_pos

    auto_cpu, port_cpu, auto_fb, port_fb = alternate_cpu(lambda: sb_kernel_run("auto"),
                                                         lambda: sb_kernel_run("portable"), rep5)
    if not np.array_equal(auto_fb, port_fb):
        raise SystemExit("the portable kernel's feedback differs from the default kernel's")

    # "A tight C++ loop of the same arithmetic" (issue 22): bench/tight_rigid.cpp, the numba loop written once in C++
    # and compiled for this CPU; bench-only, checked bit-identical to servobench, alternating CPU-time medians.
    import numba_peer
    import tight_peer

    tight = tight_peer.kernel()
    tight_cpu = tight_sb_cpu = None
    if tight is not None:
        consts = numba_peer.chain_constants(sb.demo_axis())

        def tight_run():  # allocates its output like servobench's run does (decision SP4)
            out = np.empty(n_ticks)
            tight(consts, cmd.pos, cmd.vel, cmd.acc, out)
            return out

        tight_sb_cpu, tight_cpu, ref_fb, t_out = alternate_cpu(
            lambda: sb.demo_axis().run(cmd, signals=["fb_pos"]).fb_pos, tight_run, rep5)
        bad = int(np.count_nonzero(t_out != ref_fb))
        if bad:
            raise SystemExit(f"tight C++ peer differs from the C++ core at {bad} of {n_ticks} ticks")

    # The linear loop (no friction, quantisation or saturation; no feed-forward) against the strongest peer for a
    # linear loop: scipy.signal.lfilter of the closed loop's transfer function (servobench's own linear_model, made a
    # transfer function with ss2tf: set-up, not timed). Outputs checked equal to 1e-6 pulse; CPU-time medians.
    scipy_signal = benchlib.import_peer("scipy.signal", "scipy")
    lf_cpu = lin_cpu = lf_dev = None
    if scipy_signal is not None:
        from servobench import frequency as fr

        base = sb.demo_axis()

        def lin_axis():
            return sb.Axis(law=base.law.replace(kvff=0, kaff=0), plant=base.plant.replace(coulomb_nm=0, static_nm=0),
                           drive=base.drive.replace(current_limit_a=float("inf")),
                           encoder=base.encoder.replace(quantize=False), dac=sb.Dac(quantize=False),
                           servo_period_s=base.servo_period_s)

        closed = fr.linear_model(lin_axis())["closed_loop"]
        num, den = scipy_signal.ss2tf(*(np.asarray(getattr(closed, k)) for k in "ABCD"))
        r_lin = cmd.pos * 0.01  # +-100 pulse: inside +-10 V on the whole move
        lin_cpu, lf_cpu, y_lin, y_lf = alternate_cpu(lambda: lin_axis().run(r_lin, signals=["fb_pos"]).fb_pos,
                                                     lambda: scipy_signal.lfilter(num[0], den, r_lin), rep5)
        lf_dev = float(np.max(np.abs(y_lin - y_lf)))
        if not lf_dev <= 1e-6:
            raise SystemExit(f"lfilter peer differs from the linear C++ loop by {lf_dev} pulse (> 1e-6)")

    # Full chain with the feedback only recorded (issue 22's 15 M ticks/s goal) and the cost per tick against the run
    # length (feedback only: flat from 10^4 ticks up, no cliff).
    slow_t = long_move(n_ticks)
    slow_t = sb.Trajectory(pos=slow_t.pos * 0.5, vel=slow_t.vel * 0.5, acc=slow_t.acc * 0.25)
    # CPU time, median (decision SP6): the 15 M ticks/s goal is about one core, which a loaded machine shares.
    t_full_fb = median_cpu(lambda axis: axis.run(slow_t, signals=["fb_pos"]), rep5,
                           setup=lambda: full_chain_axis("torque"))
    flat = {}
    for n_flat in size["flat"]:
        hold = np.full(n_flat, 1000.0)
        reps = max(1, min(rep5, 10_000_000 // n_flat))
        costs = []
        for _ in range(reps):
            a_flat = sb.demo_axis()
            c0 = time.process_time()
            a_flat.run(hold, signals=["fb_pos"])
            costs.append((time.process_time() - c0) / n_flat)
        flat[n_flat] = float(np.median(costs))
        del hold
    flat_ratio = flat[max(flat)] / flat[min(flat)]

    rows.append((f"servobench C++ core, rigid chain, all {len(sb.SIGNALS)} signals recorded", n_ticks, t_all,
                 n_ticks / t_all))
    rows.append(("servobench C++ core, rigid chain, feedback only recorded", n_ticks, t_min, n_ticks / t_min))
    rows.append(("full chain, torque drive: two-mass + Stribeck both sides + cogging, all signals", n_ticks,
                 t_chain["torque"], n_ticks / t_chain["torque"]))
    rows.append(("full chain, velocity drive (PI at 20 kHz, 5 sub-steps/tick), all signals", n_ticks,
                 t_chain["velocity"], n_ticks / t_chain["velocity"]))
    rows.append(("virtual card: 4 demo axes jogging, card safety/status every tick, nothing recorded (axis ticks)",
                 4 * card_ticks, t_card, 4 * card_ticks / t_card))
    rows.append(("virtual card as above, the scope sampling 4 following errors every tick (axis ticks)",
                 4 * card_ticks, t_card_scope, 4 * card_ticks / t_card_scope))
    if py_rate is not None:
        rows.append(("rigid chain tick in pure Python (CPython)", n_py, t_py, py_rate))
    extra_rows = [(f"servobench C++ core, rigid chain, the default {len(sb.DEFAULT_SIGNALS)} signals recorded "
                   f"({', '.join(sb.DEFAULT_SIGNALS)})", n_ticks, t_default, n_ticks / t_default),
                  (f"full chain, torque drive, feedback only recorded (CPU-time median of {rep5})", n_ticks, t_full_fb,
                   n_ticks / t_full_fb)]
    extra_rows.append((f"servobench, rigid chain, feedback only, default kernel ({kernel}; CPU-time median of {rep5}, "
                       "alternating with the next row)", n_ticks, auto_cpu, n_ticks / auto_cpu))
    extra_rows.append(("servobench, rigid chain, feedback only, portable kernel forced (baseline x86-64; same run)",
                       n_ticks, port_cpu, n_ticks / port_cpu))
    if nb_rate is not None:
        extra_rows.append((f"servobench, rigid chain, feedback only (CPU-time median of {rep5})", n_ticks, sb_cpu,
                           n_ticks / sb_cpu))
        extra_rows.append((f"the same rigid chain compiled with numba {numba.__version__} (CPU-time median of "
                           f"{rep5}, same run)", n_ticks, nb_cpu, nb_rate))
    if lf_cpu is not None:
        extra_rows.append((f"servobench, linear loop (no friction/quantisation/saturation), feedback only (CPU-time "
                           f"median of {rep5})", n_ticks, lin_cpu, n_ticks / lin_cpu))
        extra_rows.append((f"scipy.signal.lfilter of the same closed loop (order {len(den) - 1}; max deviation "
                           f"{lf_dev:.1e} pulse; CPU-time median of {rep5}, same run)", n_ticks, lf_cpu,
                           n_ticks / lf_cpu))
    if tight_cpu is not None:
        extra_rows.append((f"servobench, rigid chain, feedback only (CPU-time median of {rep5}, alternating with the "
                           "tight loop)", n_ticks, tight_sb_cpu, n_ticks / tight_sb_cpu))
        extra_rows.append((f"tight C++ loop of the same arithmetic, bench-only ({tight_peer.compiler_version()}, "
                           f"{' '.join(tight_peer.FLAGS[:3])}; CPU-time median of {rep5}, same run)", n_ticks,
                           tight_cpu, n_ticks / tight_cpu))

    lines = [
        "# Axis servo ticks per second",
        "",
        f"Generated by `bench/bench_axis.py` on {datetime.date.today()} ({platform.processor() or platform.machine()}, "
        f"Python {platform.python_version()}, one core). Chain: GT law, two filter slots, 16-bit DAC, torque drive with "
        "current loop, rigid plant with Coulomb friction, quantised encoder. "
        + (f"The pure-Python loop reproduces the C++ feedback exactly on its {n_py} ticks (checked in the same run). "
           if py_rate is not None else
           "The pure-Python loop was not run: it takes its ZOH from SciPy, which is not installed. ")
        + f"Best of {rep5} (full chains and card: of {rep3}) for the C++ "
        "runs. The full chains are compared with the pure-Python *rigid* chain, a lower bound of their ratio (a "
        "pure-Python two-mass chain with the implicit friction solve would be slower still). The full chains run two "
        "ADLINK integer biquads (1 kHz low-pass, notch at the resonance); the rigid chain runs the card's default "
        "pass-through biquads. The card rows count axis ticks (4 per card tick)."
        + f" The fused tick ran its {kernel} kernel (decision SP1). Each peer allocates its output array in the timed "
        "call, as servobench's run does (decision SP4). Machine load (1-min average) at the start "
        f"{load_start:.2f}, at the end {os.getloadavg()[0]:.2f}; 2 cores shared."
        + (" QUICK run (tiny sizes, for the tests): the figures say nothing about speed." if quick else ""),
        "",
        "| implementation | ticks | wall [s] | ticks/s | vs pure Python | vs goal 10 M ticks/s |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for name, n, wall, rate in rows + extra_rows:
        vs_py = f"{rate / py_rate:.0f}x" if py_rate is not None else benchlib.NOT_INSTALLED
        lines.append(f"| {name} | {n:,} | {wall:.4f} | {rate / 1e6:.2f} M | {vs_py} | "
                     f"{rate / GOAL_TICKS_PER_S:.2f} |")
    lines += ["", "Against numba (issue 22): "
              + (f"servobench {n_ticks / sb_cpu / 1e6:.2f} M ticks/s, numba {nb_rate / 1e6:.2f} M ticks/s: "
                 f"servobench is **{nb_cpu / sb_cpu:.2f}x** numba"
                 + (" -- a loss: the numba loop is faster." if sb_cpu > nb_cpu else ".")
                 if nb_rate is not None else "numba not installed."),
              "", "Against a tight C++ loop of the same arithmetic (issue 22, goal: servobench within "
              f"{GOAL_VS_TIGHT:g}x of it): "
              + (f"servobench {tight_sb_cpu / n_ticks * 1e9:.1f} ns/tick, tight loop {tight_cpu / n_ticks * 1e9:.1f} "
                 f"ns/tick: servobench takes **{tight_sb_cpu / tight_cpu:.2f}x** its time"
                 + (" -- a loss." if tight_sb_cpu > tight_cpu else ".")
                 if tight_cpu is not None else "no C++ compiler found."),
              "", "Cost per tick against the run length (rigid chain, feedback only, CPU time):", "",
              "| ticks | ns/tick |", "|---:|---:|"]
    lines += [f"| {n:,} | {c * 1e9:.1f} |" for n, c in sorted(flat.items())]
    lines += ["", f"Longest / shortest: {flat_ratio:.2f}x (goal <= {GOAL_FLAT})."]
    text = "\n".join(lines) + "\n"

    # Figures for the summary: every C++ row against the pure-Python rigid tick of the same run.
    py = dict(peer="pure-Python rigid tick", peer_value=None if py_rate is None else py_rate / 1e6,
              peer_status=benchlib.MEASURED if py_rate is not None else benchlib.NOT_INSTALLED)
    goal = dict(goal=GOAL_TICKS_PER_S / 1e6, goal_source="issues 2, 3")
    short = ["rigid chain, all signals recorded", "rigid chain, feedback only recorded",
             "full chain, torque drive (two-mass, Stribeck, cogging, 2 biquads)",
             "full chain, velocity drive (PI at 20 kHz)", "virtual card, 4 axes, nothing recorded",
             "virtual card, 4 axes, scope on 4 channels"]
    figures = []
    for i, (label, (_name, _n, _wall, rate)) in enumerate(zip(short, rows)):
        card = i >= 4
        figures.append(benchlib.Figure(
            "axis", label + (" (axis ticks)" if card else ""), "M ticks/s", rate / 1e6, True, **py,
            **({} if card else goal),
            note="no goal stated for the card, issue 10" if card else
            ("peer is the rigid tick: ratio is a lower bound" if i >= 2 else "")))
    figures.append(benchlib.Figure(
        "axis", "rigid chain, feedback only, CPU time, vs numba", "M ticks/s",
        (n_ticks / sb_cpu if sb_cpu else n_ticks / t_min) / 1e6, True,
        **benchlib.peer_figure("numba (same loop)", numba, lambda: nb_rate / 1e6),
        goal=GOAL_VS_NUMBA, goal_on="ratio", goal_source="issue 22",
        note="a ratio below 1 is a loss to numba"))
    figures.append(benchlib.Figure(
        "axis", "rigid chain, feedback only, CPU time, vs a tight C++ loop of the same arithmetic", "M ticks/s",
        (n_ticks / tight_sb_cpu if tight_sb_cpu else n_ticks / t_min) / 1e6, True,
        **benchlib.peer_figure("tight C++ loop (bench-only)", tight, lambda: n_ticks / tight_cpu / 1e6),
        goal=1 / GOAL_VS_TIGHT, goal_on="ratio", goal_source="issue 22",
        note=f"within {GOAL_VS_TIGHT:g}x of it = ratio >= {1 / GOAL_VS_TIGHT:.2f}; below 1 is a loss"))
    figures.append(benchlib.Figure(
        "axis", "linear loop (no friction, quantisation, saturation), feedback only, CPU time", "M ticks/s",
        (n_ticks / lin_cpu if lin_cpu else n_ticks / t_min) / 1e6, True,
        **benchlib.peer_figure("scipy.signal.lfilter, same closed loop", scipy_signal, lambda: n_ticks / lf_cpu / 1e6),
        note="outputs equal to 1e-6 pulse; a ratio below 1 is a loss to lfilter"))
    figures.append(benchlib.Figure(
        "axis", "full chain, torque drive, feedback only", "M ticks/s", n_ticks / t_full_fb / 1e6, True,
        **py, goal=GOAL_FULL_CHAIN / 1e6, goal_source="issue 22", note="peer is the rigid tick: ratio is a lower bound"))
    figures.append(benchlib.Figure(
        "axis", f"cost per tick, {max(flat):,} vs {min(flat):,} ticks, feedback only", "x", flat_ratio, False,
        goal=GOAL_FLAT, goal_source="issue 22", note="1.0 = flat"))
    return benchlib.Result("axis", "bench/bench_axis.py", "axis_ticks.md", text, figures, quick,
                           peers={"SciPy": benchlib.version(scipy_linalg), "numba": benchlib.version(numba)})


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ticks", type=int, default=None, help="default 1000000 (quick: 20000)")
    ap.add_argument("--python-ticks", type=int, default=None, help="default 200000 (quick: 5000)")
    ap.add_argument("--out", default=None, help="the .md file (default <results-dir>/axis_ticks.md)")
    benchlib.add_common_args(ap)
    args = ap.parse_args(argv)
    res = run(args.quick, args.ticks, args.python_ticks)
    print(res.markdown)
    benchlib.write_result(res, args.results_dir)
    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        with open(args.out, "w") as f:
            f.write(res.markdown)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
