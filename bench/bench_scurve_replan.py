"""Benchmark: S-curve replanned from a moving state (target changed in motion), servobench vs Ruckig, same process.

The same random reachable states (|a| <= A, |v + a|a|/(2J)| <= V: what an S-curve under its own limits passes
through, decision MO3) and targets go to servobench's C++ batch entry point
(`servobench.motion.plan_s_curve_replan_batch`, no Python per plan) and to Ruckig's `calculate` through its Python
binding; the binding's own loop cost (the same loop without `calculate`) is measured and subtracted ("net").
Times are process CPU time (`time.process_time`, best of the repeats) and wall time; the load average is recorded
at the start and the end, since the machine is shared. The durations must agree within 1e-6 relative (both
time-optimal) before any time is reported. Goal (issue 25 point 5): servobench no slower than Ruckig net.

Run: python bench/bench_scurve_replan.py [--moves 200000] [--ruckig-moves 20000] [--quick] [--results-dir DIR]
Writes bench/results/scurve_replan.md and scurve_replan.json.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import sys
import time

import numpy as np

import servobench as sb

import benchlib

GOAL_RATIO = 1.0  # servobench at least as fast as Ruckig net (issue 25 point 5)
FULL = dict(moves=200_000, ruckig_moves=20_000)
QUICK = dict(moves=2_000, ruckig_moves=500)


def random_replans(n: int, seed: int = 25):
    """Reachable moving states and targets per tick: vel 0.1..100 pulse/tick, acc 1e-3..1 pulse/tick^2, jerk
    1e-5..0.1 pulse/tick^3 (log-uniform), target distance 1..1e6 pulse either side. Returns pos, vel, acc,
    target, vmax, amax, jmax (arrays)."""
    rng = np.random.default_rng(seed)
    lu = lambda lo, hi: np.exp(rng.uniform(np.log(lo), np.log(hi), n))  # noqa: E731
    V, A, J = lu(0.1, 100), lu(1e-3, 1), lu(1e-5, 0.1)
    a0 = rng.uniform(-1, 1, n) * A
    shift = a0 * np.abs(a0) / (2 * J)
    lo, hi = np.maximum(-V, -V - shift), np.minimum(V, V - shift)
    ok = lo < hi
    v0 = np.where(ok, lo + rng.uniform(0, 1, n) * (hi - lo), 0.0)
    a0 = np.where(ok, a0, 0.0)
    pos = np.round(rng.uniform(-1e6, 1e6, n))
    target = pos + np.round(np.exp(rng.uniform(0, np.log(1e6), n))) * rng.choice([-1.0, 1.0], n)
    return pos, v0, a0, target, V, A, J


def time_servobench(cases, repeats: int):
    """Best CPU and wall seconds of the batch planner over `repeats` runs, and its durations (ticks)."""
    cpu = wall = float("inf")
    out = None
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        out = sb.motion.plan_s_curve_replan_batch(*cases)
        cpu, wall = min(cpu, time.process_time() - c0), min(wall, time.perf_counter() - w0)
    return cpu, wall, out


def time_ruckig(ruckig, cases, n: int, repeats: int):
    """Best CPU seconds of Ruckig's loop with and without `calculate` (the binding overhead), and its durations."""
    pos, vel, acc, target, V, A, J = (c[:n] for c in cases)
    otg, inp, traj = ruckig.Ruckig(1), ruckig.InputParameter(1), ruckig.Trajectory(1)
    durations = np.empty(n)

    def loop(call: bool) -> float:
        c0 = time.process_time()
        for i in range(n):
            inp.current_position, inp.current_velocity, inp.current_acceleration = [pos[i]], [vel[i]], [acc[i]]
            inp.target_position, inp.target_velocity, inp.target_acceleration = [target[i]], [0.0], [0.0]
            inp.max_velocity, inp.max_acceleration, inp.max_jerk = [V[i]], [A[i]], [J[i]]
            if call:
                otg.calculate(inp, traj)
                durations[i] = traj.duration
        return time.process_time() - c0

    total = min(loop(True) for _ in range(repeats))
    overhead = min(loop(False) for _ in range(repeats))
    return total, overhead, durations


def run(quick: bool = False, moves: int | None = None, ruckig_moves: int | None = None) -> benchlib.Result:
    """Times the replan batch planner and (when installed) Ruckig on the same states; returns figures and table."""
    size = dict(QUICK if quick else FULL)
    size.update({k: v for k, v in dict(moves=moves, ruckig_moves=ruckig_moves).items() if v is not None})
    n = size["moves"]
    load_start = os.getloadavg()
    ruckig = benchlib.import_peer("ruckig", "ruckig")
    cases = random_replans(n)
    cpu_sb, wall_sb, dur_sb = time_servobench(cases, repeats=1 if quick else 5)
    us_sb = cpu_sb / n * 1e6
    rows = [("servobench `plan_s_curve_replan_batch` (C++, whole profile built)", n, us_sb, wall_sb / n * 1e6, 1.0)]
    us_net = None
    if ruckig is not None:
        n_r = min(size["ruckig_moves"], n)
        t_r, t_over, dur_r = time_ruckig(ruckig, cases, n_r, repeats=1 if quick else 3)
        worst = float(np.max(np.abs(dur_sb[:n_r] / dur_r - 1)))
        if worst > 1e-6:
            raise SystemExit(f"durations disagree with Ruckig: worst relative difference {worst:.3g}")
        us_r, us_net = t_r / n_r * 1e6, (t_r - t_over) / n_r * 1e6
        rows += [("Ruckig `calculate` via its Python binding", n_r, us_r, None, us_r / us_sb),
                 ("Ruckig, binding loop overhead subtracted (net)", n_r, us_net, None, us_net / us_sb)]
        same = f"Same durations: worst relative difference {worst:.2e} over {n_r} states."
    else:
        same = "Ruckig is not installed: no peer in this run."
    load_end = os.getloadavg()
    load = lambda v: " / ".join(f"{x:.2f}" for x in v)  # noqa: E731
    lines = [
        "# S-curve replanned from a moving state",
        "",
        f"Generated by `bench/bench_scurve_replan.py` on {datetime.date.today()} ({benchlib.machine()}, Python "
        f"{platform.python_version()}, ruckig {benchlib.version(ruckig)}, one core, CPU time, best of several runs). "
        f"Load average (1 / 5 / 15 min) {load(load_start)} at the start, {load(load_end)} at the end (shared machine). "
        "Random reachable states (vel 0.1..100 pulse/tick, acc 1e-3..1 pulse/tick^2, jerk 1e-5..0.1 "
        "pulse/tick^3, log-uniform; target 1..1e6 pulse either side). " + same
        + (" QUICK run (tiny sizes, for the tests): the figures say nothing about speed." if quick else ""),
        "",
        "| planner | states | CPU per plan [us] | wall per plan [us] | time vs servobench |",
        "|---|---:|---:|---:|---:|",
    ]
    lines += [f"| {name} | {k:,} | {us:.4f} | {'' if w is None else f'{w:.4f}'} | {r:.2f}x |"
              for name, k, us, w, r in rows]
    if ruckig is None:
        lines.append(f"| Ruckig | {benchlib.NOT_INSTALLED} | | | |")
    else:
        met = us_sb <= us_net
        lines += ["", f"Goal: no slower than Ruckig net: **{'met' if met else 'NOT met'}** ({us_sb:.4f} us vs "
                  f"{us_net:.4f} us, {us_net / us_sb:.2f}x)."]
    lines.append("")
    fig = benchlib.Figure("scurve_replan", "S-curve replan from a moving state, mean CPU time (Ruckig net of its "
                          "binding loop)", "µs", us_sb, False,
                          **benchlib.peer_figure("Ruckig net", ruckig, lambda: us_net),
                          goal=GOAL_RATIO, goal_on="ratio", goal_source="issue 25")
    return benchlib.Result("scurve_replan", "bench/bench_scurve_replan.py", "scurve_replan.md", "\n".join(lines),
                           [fig], quick, peers={"Ruckig": benchlib.version(ruckig)})


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--moves", type=int, default=None, help="default 200000 (quick: 2000)")
    ap.add_argument("--ruckig-moves", type=int, default=None, help="default 20000 (quick: 500)")
    benchlib.add_common_args(ap)
    args = ap.parse_args(argv)
    res = run(args.quick, args.moves, args.ruckig_moves)
    benchlib.write_result(res, args.results_dir)
    print(res.markdown)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    sys.exit(main())
