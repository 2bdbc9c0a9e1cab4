"""Benchmark: servo ticks per second of one simulated axis, C++ core vs the same loop in pure Python.

The full chain of this version: GT servo law -> two (pass-through) filter slots -> 16-bit DAC -> torque drive
with a first-order current loop -> rigid plant with Coulomb friction (exact ZOH) -> quantised encoder.
The pure-Python loop implements the same tick (its ZOH from scipy.linalg.expm) and must reproduce the C++
feedback exactly before its speed is reported. Writes bench/results/axis_ticks.md.

Run: python bench/bench_axis.py [--ticks 1000000] [--python-ticks 200000]
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

GOAL_TICKS_PER_S = 10e6  # product goal for the full chain on one core


def python_reference(axis: sb.Axis, cmd: sb.Trajectory, n: int) -> np.ndarray:
    """The servo tick of servobench written in plain Python (GT law, DAC, lagged torque drive, rigid plant with
    Coulomb friction and stiction, quantised encoder). Returns the feedback (pulse) per tick."""
    from scipy.linalg import expm

    law, drv, pl, enc = axis.law, axis.drive, axis.plant, axis.encoder
    ts = axis.servo_period_s
    wc = 2 * math.pi * drv.current_bw_hz
    j = pl.inertia_kgm2
    a = np.array([[-wc, 0, 0], [0, 0, 1], [drv.kt / j, 0, -pl.viscous_nms / j]])
    b = np.array([[wc, 0], [0, 0], [0, 1 / j]])
    m = np.zeros((5, 5))
    m[:3, :3], m[:3, 3:] = a * ts, b * ts
    e = expm(m)
    phi, gam = e[:3, :3].tolist(), e[:3, 3:].tolist()
    phil, gaml = math.exp(-wc * ts), 1 - math.exp(-wc * ts)
    cpr = enc.counts_per_rev / (2 * math.pi)
    kp, ki, kd, kvff, kaff = law.kp, law.ki, law.kd, law.kvff, law.kaff
    ilmt, bias, mlim = law.ilmt, law.bias, law.mtr_lmt
    apv, ilim, kt, coul, load = drv.amps_per_volt, drv.current_limit_a, drv.kt, pl.coulomb_nm, pl.load_nm
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
        v = round(v * 3276.7) / 3276.7  # 16-bit DAC
        out[k] = y
        applied = kt * i - load
        if stuck or w == 0.0:
            if -coul <= applied <= coul:
                i = phil * i + gaml * icmd
                w = 0.0
                stuck = True
                pending = v
                continue
            fr = -coul if applied > 0 else coul
            stuck = False
        else:
            fr = -coul if w > 0 else coul
        w0 = w
        ext = fr - load
        x0, x1, x2 = i, th, w
        i = phi[0][0] * x0 + phi[0][1] * x1 + phi[0][2] * x2 + gam[0][0] * icmd + gam[0][1] * ext
        th = phi[1][0] * x0 + phi[1][1] * x1 + phi[1][2] * x2 + gam[1][0] * icmd + gam[1][1] * ext
        w = phi[2][0] * x0 + phi[2][1] * x1 + phi[2][2] * x2 + gam[2][0] * icmd + gam[2][1] * ext
        if w0 != 0.0 and (w == 0.0 or (w > 0) != (w0 > 0)):
            if -coul <= kt * i - load <= coul:
                w = 0.0
                stuck = True
        pending = v
    return np.array(out)


def long_move(n: int) -> sb.Trajectory:
    """Back-and-forth moves filling n ticks (each 10000 pulse at 20 pulse/tick, 0.1 pulse/tick^2)."""
    one = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1, dwell_after=200)
    back = sb.trapezoid_move(start_pulse=10000, distance_pulse=-10000, vel_pulse_per_tick=20,
                             acc_pulse_per_tick2=0.1, dwell_after=200)
    reps = n // (len(one) + len(back)) + 1
    cat = lambda f: np.tile(np.concatenate([getattr(one, f), getattr(back, f)]), reps)[:n]  # noqa: E731
    return sb.Trajectory(pos=cat("pos"), vel=cat("vel"), acc=cat("acc"))


def best_of(fn, repeats: int) -> float:
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ticks", type=int, default=1_000_000)
    ap.add_argument("--python-ticks", type=int, default=200_000)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "results", "axis_ticks.md"))
    args = ap.parse_args()

    cmd = long_move(args.ticks)
    rows = []

    def cpp_run(signals):
        axis = sb.demo_axis()
        axis.run(cmd, signals=signals)

    t_all = best_of(lambda: cpp_run(None), 5)
    t_min = best_of(lambda: cpp_run(["fb_pos"]), 5)

    # Same work check: the pure-Python tick reproduces the C++ feedback exactly.
    n_py = min(args.python_ticks, args.ticks)
    ref_axis = sb.demo_axis()
    cpp_fb = ref_axis.run(sb.Trajectory(cmd.pos[:n_py], cmd.vel[:n_py], cmd.acc[:n_py]), signals=["fb_pos"]).fb_pos
    t0 = time.perf_counter()
    py_fb = python_reference(sb.demo_axis(), cmd, n_py)
    t_py = time.perf_counter() - t0
    mismatch = int(np.count_nonzero(py_fb != cpp_fb))
    if mismatch:
        raise SystemExit(f"pure-Python reference differs from the C++ core at {mismatch} of {n_py} ticks")

    py_rate = n_py / t_py
    rows.append(("servobench C++ core, all 20 signals recorded", args.ticks, t_all, args.ticks / t_all))
    rows.append(("servobench C++ core, feedback only recorded", args.ticks, t_min, args.ticks / t_min))
    rows.append(("same tick in pure Python (CPython)", n_py, t_py, py_rate))

    lines = [
        "# Axis servo ticks per second",
        "",
        f"Generated by `bench/bench_axis.py` on {datetime.date.today()} ({platform.processor() or platform.machine()}, "
        f"Python {platform.python_version()}, one core). Chain: GT law, two filter slots, 16-bit DAC, torque drive with "
        "current loop, rigid plant with Coulomb friction, quantised encoder. The pure-Python loop reproduces the C++ "
        f"feedback exactly on its {n_py} ticks (checked in the same run). Best of 5 for the C++ runs.",
        "",
        "| implementation | ticks | wall [s] | ticks/s | vs pure Python | vs goal 10 M ticks/s |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for name, n, wall, rate in rows:
        lines.append(f"| {name} | {n:,} | {wall:.4f} | {rate / 1e6:.2f} M | {rate / py_rate:.0f}x | "
                     f"{rate / GOAL_TICKS_PER_S:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
