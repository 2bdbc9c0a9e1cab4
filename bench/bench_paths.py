"""Benchmark: look-ahead planning speed (segments per second), servobench vs the same algorithm in NumPy and in
pure Python.

No installed peer does this work: Ruckig (used by bench_motion.py) generates one time-optimal trajectory from a
state to a target, it does not plan end speeds along a path of segments with a corner rule. So the peers here are
the same look-ahead pass written (a) in pure Python, streaming with the same window of n segments, and (b) in
NumPy, vectorised for an unlimited window (the backward and forward passes become a suffix and a prefix minimum
of squared speeds, np.minimum.accumulate). servobench runs `plan_polyline_lookahead` (C++: tangents, corner caps,
sliding-window minimum, forward pass) on the same polyline. Every peer's end speeds must agree with servobench's
(relative 1e-9) before any time is reported. Writes bench/results/paths.md and paths.json.

Run: python bench/bench_paths.py [--segments 1000000] [--python-segments 100000] [--quick] [--results-dir DIR]
"""

from __future__ import annotations

import argparse
import datetime
import math
import platform
import time

import numpy as np

import servobench as sb

import benchlib

GOAL = 1e6  # segments/s (issue 9)


def polyline(n: int, seed: int = 9) -> np.ndarray:
    """A wandering 2-D polyline of n segments, 5..500 pulse long, turning up to +-60 deg at each joint."""
    rng = np.random.default_rng(seed)
    heading = np.cumsum(rng.uniform(-np.pi / 3, np.pi / 3, n))
    step = rng.uniform(5, 500, n)
    pts = np.zeros((n + 1, 2))
    pts[1:, 0] = np.cumsum(step * np.cos(heading))
    pts[1:, 1] = np.cumsum(step * np.sin(heading))
    return pts


def python_lookahead(points, vel, acc, t_ms, acc_max, n):
    """The same algorithm (decisions C10-C16) in pure Python: window of n segments, squared-speed sliding min."""
    from collections import deque
    a = min(acc, acc_max)
    out, q, mins = [], deque(), deque()
    w_total, v_prev, idx0 = 0.0, 0.0, 0
    px, py = points[0]
    ux_prev = uy_prev = None

    def pop():
        nonlocal v_prev, idx0
        length, w_end, cap = q.popleft()
        m = w_total
        if mins and mins[0][0] == idx0:
            m = min(m, mins[0][1])
            mins.popleft()
        elif mins:
            m = min(m, mins[0][1])
        idx0 += 1
        v = min(math.sqrt(max(m - w_end, 0.0)), math.sqrt(v_prev * v_prev + 2 * a * length))
        v_prev = v
        out.append(v)

    for x, y in points[1:]:
        dx, dy = x - px, y - py
        px, py = x, y
        length = math.hypot(dx, dy)
        if length == 0:
            continue
        ux, uy = dx / length, dy / length
        if q:
            d = math.hypot(ux - ux_prev, uy - uy_prev)
            cap = min(vel, acc_max * t_ms / d) if d > 1e-15 else vel
            key = cap * cap + q[-1][1]
            while mins and mins[-1][1] >= key:
                mins.pop()
            mins.append((idx0 + len(q) - 1, key))
        ux_prev, uy_prev = ux, uy
        w_total += 2 * a * length
        q.append((length, w_total, None))
        if len(q) > n:
            pop()
    while q:
        pop()
    return np.array(out)


def numpy_lookahead(points, vel, acc, t_ms, acc_max):
    """The same corner caps, unlimited window, vectorised: suffix / prefix minima of squared speeds."""
    a = min(acc, acc_max)
    d = np.diff(points, axis=0)
    length = np.hypot(d[:, 0], d[:, 1])
    u = d / length[:, None]
    du = np.hypot(*(u[1:] - u[:-1]).T)
    with np.errstate(divide="ignore"):
        cap = np.minimum(vel, np.where(du > 1e-15, acc_max * t_ms / du, np.inf))
    cap = np.append(cap, 0.0)  # the path ends at rest
    w = np.cumsum(2 * a * length)
    back = np.minimum.accumulate((cap**2 + w)[::-1])[::-1] - w  # v_i^2 <= min_j>=i (cap_j^2 + W_j) - W_i
    w0 = w - 2 * a * length  # W at each segment's start
    fwd = w + np.minimum.accumulate(np.minimum(back, np.inf) - w)  # v_i^2 <= min_k<=i (v_k^2 - W_k) + W_i
    fwd = np.minimum(fwd, w - w0[0])  # from rest at the start
    return np.sqrt(np.maximum(np.minimum(back, fwd), 0.0))


def best_time(f, repeats=3):
    best, out = float("inf"), None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


FULL = dict(segments=1_000_000, python_segments=100_000)
QUICK = dict(segments=20_000, python_segments=3_000)


def run(quick: bool = False, segments: int | None = None, python_segments: int | None = None) -> benchlib.Result:
    """Times servobench's look-ahead and its pure-Python and NumPy peers in the same run; figures and table."""
    size = dict(QUICK if quick else FULL)
    size.update({k: v for k, v in dict(segments=segments, python_segments=python_segments).items()
                 if v is not None})
    n_seg = size["segments"]
    reps = 1 if quick else 3
    vel, acc, t_ms, acc_max = 100.0, 1.0, 5.0, 1.0
    pts = polyline(n_seg)
    p200 = sb.LookAheadParams(t_ms=t_ms, acc_max=acc_max, n=200)
    pall = sb.LookAheadParams(t_ms=t_ms, acc_max=acc_max, n=32766)
    t_sb, v_sb = best_time(lambda: sb.plan_polyline_lookahead(pts, vel, acc, p200), reps)
    t_sb_big, _ = best_time(lambda: sb.plan_polyline_lookahead(pts, vel, acc, pall), reps)
    n_py = min(size["python_segments"], n_seg)
    t_py, v_py = best_time(lambda: python_lookahead(pts[: n_py + 1], vel, acc, t_ms, acc_max, 200), repeats=1)
    v_sb_py = sb.plan_polyline_lookahead(pts[: n_py + 1], vel, acc, p200)
    err_py = float(np.max(np.abs(v_py - v_sb_py) / np.maximum(v_sb_py, 1e-9)))
    # NumPy (unlimited window) against servobench with a window longer than the path.
    n_np = min(30000, n_seg)
    sub = pts[: n_np + 1]
    t_np, v_np = best_time(lambda: numpy_lookahead(sub, vel, acc, t_ms, acc_max), reps)
    t_sb_sub, v_sb_sub = best_time(lambda: sb.plan_polyline_lookahead(sub, vel, acc, pall), reps)
    err_np = float(np.max(np.abs(v_np - v_sb_sub) / np.maximum(v_sb_sub, 1e-9)))
    if err_py > 1e-9 or err_np > 1e-9:
        raise SystemExit(f"end speeds disagree: python {err_py:.3g}, numpy {err_np:.3g}")
    rate = lambda n, t: n / t  # noqa: E731
    rows = [
        ("servobench `plan_polyline_lookahead` (C++), window 200", n_seg, rate(n_seg, t_sb), 1.0),
        ("servobench, window 32766", n_seg, rate(n_seg, t_sb_big), rate(n_seg, t_sb) / rate(n_seg, t_sb_big)),
        ("pure Python, same algorithm, window 200", n_py, rate(n_py, t_py), rate(n_seg, t_sb) / rate(n_py, t_py)),
        (f"servobench, window >= path ({n_np:,} segments)", n_np, rate(n_np, t_sb_sub),
         rate(n_seg, t_sb) / rate(n_np, t_sb_sub)),
        (f"NumPy vectorised, unlimited window ({n_np:,} segments)", n_np, rate(n_np, t_np),
         rate(n_seg, t_sb) / rate(n_np, t_np)),
    ]
    lines = [
        "# Look-ahead planning speed",
        "",
        f"Generated by `bench/bench_paths.py` on {datetime.date.today()} ({platform.machine()}, Python "
        f"{platform.python_version()}, NumPy {np.__version__}, one core; machine shared, best of {reps}). A random 2-D "
        "polyline (segments 5..500 pulse, turns up to +-60 deg), feed 100 pulse/ms, acceleration 1 pulse/ms^2, "
        "T = 5 ms, accMax = 1. No installed peer plans path look-ahead (Ruckig plans one trajectory to a target), "
        "so the peers are the same algorithm in pure Python and in NumPy; their end speeds agree with servobench's "
        f"to {max(err_py, err_np):.1e} (relative) before timing."
        + (" QUICK run (tiny sizes, for the tests): the figures say nothing about speed." if quick else ""),
        "",
        "| planner | segments | segments per second | time per segment vs servobench |",
        "|---|---:|---:|---:|",
    ]
    lines += [f"| {name} | {n:,} | {r / 1e6:.2f} M | {ratio:.1f}x |" for name, n, r, ratio in rows]
    r0 = rate(n_seg, t_sb)
    lines += ["", f"Goal: >= 1 M segments/s: **{'met' if r0 >= GOAL else 'NOT met'}** ({r0 / 1e6:.2f} M segments/s).", ""]
    text = "\n".join(lines)
    goal = dict(goal=GOAL / 1e6, goal_source="issue 9")
    py = dict(peer="pure Python, same algorithm, window 200", peer_value=rate(n_py, t_py) / 1e6,
              peer_status=benchlib.MEASURED)
    figures = [
        benchlib.Figure("paths", "look-ahead planning, window 200", "M segments/s", r0 / 1e6, True, **py, **goal),
        benchlib.Figure("paths", "look-ahead planning, window 32766", "M segments/s", rate(n_seg, t_sb_big) / 1e6,
                        True, **py, **goal, note="the peer runs window 200"),
        benchlib.Figure("paths", f"look-ahead planning, window >= path ({n_np:,} segments)", "M segments/s",
                        rate(n_np, t_sb_sub) / 1e6, True, peer="NumPy vectorised, unlimited window",
                        peer_value=rate(n_np, t_np) / 1e6, peer_status=benchlib.MEASURED, **goal),
    ]
    return benchlib.Result("paths", "bench/bench_paths.py", "paths.md", text, figures, quick)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--segments", type=int, default=None, help="default 1000000 (quick: 20000)")
    ap.add_argument("--python-segments", type=int, default=None, help="default 100000 (quick: 3000)")
    benchlib.add_common_args(ap)
    args = ap.parse_args(argv)
    res = run(args.quick, args.segments, args.python_segments)
    benchlib.write_result(res, args.results_dir)
    print(res.markdown)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
