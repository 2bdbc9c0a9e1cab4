"""Runs every benchmark and writes bench/results/summary.md: each figure against its peer in the same run and against
the goal of its issue.

Each bench runs in its own subprocess (a crash loses only its own rows, shown as FAILED) with installs off
(SERVOBENCH_BENCH_NO_INSTALL=1): scripts/bench.sh installs the peers first, and a peer still missing is shown as
"not installed". Every bench writes its detailed table (<name>.md) and its figures (<topic>.json) into the results
directory; this script reads the JSON files and writes summary.md beside them.

Run: python bench/run_all.py [--quick] [--results-dir DIR] [--only axis,motion] [--timeout 3600]
(`bash scripts/bench.sh` installs the package and the peers, then runs this.)
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import pathlib
import platform
import resource
import subprocess
import sys
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import benchlib  # noqa: E402

# (topic, script, detailed table) in the order of the summary.
BENCHES = [
    ("axis", "bench_axis.py", "axis_ticks.md"),
    ("motion", "bench_motion.py", "motion_planning.md"),
    ("bode", "bench_bode.py", "bode.md"),
    ("autotune", "bench_autotune.py", "autotune.md"),
    ("paths", "bench_paths.py", "paths.md"),
    ("identify", "bench_identify.py", "identify.md"),
    ("batch", "bench_batch.py", "batch.md"),
]
SUMMARY_START = "<!-- summary-start -->"  # docs/benchmarks.md includes what lies between these two
SUMMARY_END = "<!-- summary-end -->"
TABLE_START = "<!-- summary-table-start -->"
TABLE_END = "<!-- summary-table-end -->"
HEADER = "| benchmark | figure | servobench | peer (same run) | speed-up | goal | met |"
PEER_NAMES = {"SciPy": "scipy", "python-control": "control", "Ruckig": "ruckig", "numba": "numba"}


def loadavg() -> str:
    try:
        return " / ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        return "unknown"


def git_describe() -> str:
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=benchlib.ROOT, capture_output=True,
                              text=True, check=True).stdout.strip()
        # The results folder is what this run writes: an earlier run's tables there do not make the code dirty.
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--", ".",
                                ":(exclude)bench/results"], cwd=benchlib.ROOT,
                               capture_output=True, text=True, check=True).stdout.strip()
        return head + (" with uncommitted changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def run_bench(topic: str, script: str, results_dir: pathlib.Path, quick: bool, timeout: float) -> dict:
    """Runs one bench in a subprocess; returns {topic, ok, seconds, load_before, load_after, result | error}."""
    env = dict(os.environ, SERVOBENCH_BENCH_NO_INSTALL="1")
    # One thread for NumPy/SciPy's BLAS in every bench (E12): idle OpenBLAS threads spin and take a core from the
    # timed loop on a small machine, and both sides of every comparison are single-threaded code.
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env.setdefault(var, "1")
    cmd = [sys.executable, str(HERE / script), "--results-dir", str(results_dir)] + (["--quick"] if quick else [])
    json_path = results_dir / f"{topic}.json"
    started = datetime.datetime.now(datetime.timezone.utc).replace(microsecond=0)
    load_before = loadavg()
    cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    out = dict(topic=topic, script=f"bench/{script}", load_before=load_before)
    try:
        proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout, cwd=benchlib.ROOT)
        code, err = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired as e:
        tail = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
        code, err = None, tail + f"\ntimed out after {timeout:g} s"
    cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out.update(seconds=time.perf_counter() - t0, load_after=loadavg(),
               cpu_seconds=(cpu1.ru_utime - cpu0.ru_utime) + (cpu1.ru_stime - cpu0.ru_stime))
    result = None
    if code == 0 and json_path.exists():
        result = json.loads(json_path.read_text())
        if datetime.datetime.fromisoformat(result["generated"]) < started:
            result = None
            err = f"{json_path.name} was not rewritten by this run"
    if result is None:
        lines = [ln for ln in (err or "").strip().splitlines() if ln.strip()]
        why = lines[-1].strip() if lines else "no output"
        out.update(ok=False, error=f"exit code {code}: {why}" if code is not None else why)
        sys.stderr.write(err or "")
    else:
        out.update(ok=True, result=result)
    return out


def cell_value(v, unit: str) -> str:
    return f"{benchlib.fmt(v)} {unit}"


def goal_cell(f: benchlib.Figure) -> str:
    if f.goal is None:
        return "none stated"
    src = f" ({f.goal_source})" if f.goal_source else ""
    if f.goal_on == "ratio":
        return f"≥ {f.goal:g}× peer{src}"
    return f"{'≥' if f.higher_is_better else '≤'} {f.goal:g} {f.unit}{src}"


def met_cell(f: benchlib.Figure) -> str:
    if f.goal is None:
        return "-"
    m = f.goal_met
    if m is None:
        return "n/a (peer not installed)"
    return "yes" if m else "**no**"


def peer_cell(f: benchlib.Figure) -> str:
    if f.peer_status == benchlib.NO_PEER:
        return "none"
    if f.peer_status == benchlib.NOT_INSTALLED:
        return f"{f.peer}: {benchlib.NOT_INSTALLED}"
    return f"{f.peer}: {cell_value(f.peer_value, f.unit)}"


def table_rows(runs: list) -> list:
    rows = []
    for r in runs:
        if not r["ok"]:
            rows.append(f"| {r['topic']} | FAILED ({r['error'].replace('|', '/')}) | - | - | - | - | - |")
            continue
        for d in r["result"]["figures"]:
            f = benchlib.Figure.from_dict(d)
            label = f.figure + (f" ({f.note})" if f.note else "")
            ratio = f.ratio
            rows.append(f"| {f.benchmark} | {label} | {cell_value(f.value, f.unit)} | {peer_cell(f)} | "
                        f"{'-' if ratio is None else benchlib.fmt(ratio) + '×'} | {goal_cell(f)} | {met_cell(f)} |")
    return rows


def peer_versions(runs: list) -> str:
    seen = {}
    for r in runs:
        if r["ok"]:
            for name, v in r["result"].get("peers", {}).items():
                if seen.get(name) in (None, benchlib.NOT_INSTALLED):
                    seen[name] = v
    for name in PEER_NAMES:
        seen.setdefault(name, "not used by the benches run")
    return ", ".join(f"{name} {seen[name]}" for name in sorted(seen, key=lambda n: list(PEER_NAMES).index(n)
                                                                 if n in PEER_NAMES else 99))


def summary_markdown(runs: list, *, quick: bool, started: datetime.datetime, seconds: float, load_start: str,
                     load_end: str, commit: str, command: str) -> str:
    n_fig = sum(len(r["result"]["figures"]) for r in runs if r["ok"])
    failed = [r["topic"] for r in runs if not r["ok"]]
    not_met = sum(1 for r in runs if r["ok"] for d in r["result"]["figures"] if d.get("goal_met") is False)
    try:
        import servobench
        sb_version = servobench.__version__
    except ImportError:
        sb_version = "?"
    minutes, secs = divmod(int(round(seconds)), 60)
    lines = [
        "# Benchmark summary",
        "",
        SUMMARY_START,
        "",
        f"Generated by `{command}` on {started:%Y-%m-%d %H:%M} UTC; the whole run took {minutes} min {secs:02d} s."
        + (" **QUICK run** (tiny sizes, one repeat, for the tests): the figures say nothing about speed." if quick
           else ""),
        "",
        f"- **Machine:** {benchlib.machine()}, {os.cpu_count()} logical cores, {platform.system()} "
        f"{platform.release()}. The machine is shared with other jobs: load average (1 / 5 / 15 min) "
        f"{load_start} at the start and {load_end} at the end (per bench below). Under load the absolute figures "
        "are pessimistic; the speed-ups compare two programs timed in the same run and move less.",
        f"- **Software:** Python {platform.python_version()}, NumPy {np.__version__}, servobench {sb_version} "
        f"(git {commit}); peers: {peer_versions(runs)}.",
        f"- **Result:** {n_fig} figures from {len(runs) - len(failed)} of {len(runs)} benchmarks"
        + (f"; FAILED: {', '.join(failed)}" if failed else "") + f"; goals not met: {not_met}.",
        "",
        "servobench and peer are measured in the same run of the same bench, on the same inputs, and the bench "
        "checks that both give the same answer before it reports a time (see each detailed table). **speed-up** = "
        "how many times faster servobench is than the peer (peer time / servobench time, or servobench rate / peer "
        "rate; above 1 servobench is faster). A goal bounds the servobench figure, or the speed-up where it says "
        "\"× peer\"; goals come from the issues named. A peer that is not installed is shown as such, never left out.",
        "",
        TABLE_START,
        "",
        HEADER,
        "|---|---|---:|---|---:|---|---|",
    ] + table_rows(runs) + [
        "",
        TABLE_END,
        "",
        SUMMARY_END,
        "",
        "## Per benchmark",
        "",
    ]
    for topic, script, md in BENCHES:
        r = next((x for x in runs if x["topic"] == topic), None)
        if r is None:
            continue
        state = "ok" if r["ok"] else f"FAILED ({r['error']})"
        cpu = f" (CPU {r['cpu_seconds']:.1f} s)" if "cpu_seconds" in r else ""
        lines.append(f"- **{topic}**: `bench/{script}`, {r['seconds']:.1f} s wall{cpu}, {state}, load {r['load_before']} → "
                     f"{r['load_after']}; detailed table: [{md}]({md})")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="tiny sizes (for the tests; the figures mean nothing)")
    ap.add_argument("--results-dir", default=str(benchlib.RESULTS))
    ap.add_argument("--only", default="", help="comma-separated topics (default: all)")
    ap.add_argument("--timeout", type=float, default=3600.0, help="seconds per bench")
    ap.add_argument("--command", default="python bench/run_all.py", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    results_dir = pathlib.Path(args.results_dir).resolve()
    results_dir.mkdir(parents=True, exist_ok=True)
    only = {s.strip() for s in args.only.split(",") if s.strip()}
    unknown = only - {t for t, _, _ in BENCHES}
    if unknown:
        ap.error(f"--only: unknown benchmark(s) {sorted(unknown)}; known: {[t for t, _, _ in BENCHES]}")

    started = datetime.datetime.now(datetime.timezone.utc)
    load_start, commit = loadavg(), git_describe()
    t0 = time.perf_counter()
    runs = []
    for topic, script, _md in BENCHES:
        if only and topic not in only:
            continue
        print(f"== {topic}: bench/{script}{' --quick' if args.quick else ''} (load {loadavg()})", flush=True)
        r = run_bench(topic, script, results_dir, args.quick, args.timeout)
        print(f"   {'ok' if r['ok'] else 'FAILED: ' + r['error']} in {r['seconds']:.1f} s", flush=True)
        runs.append(r)
    text = summary_markdown(runs, quick=args.quick, started=started, seconds=time.perf_counter() - t0,
                            load_start=load_start, load_end=loadavg(), commit=commit, command=args.command)
    out = results_dir / "summary.md"
    out.write_text(text)
    print(text)
    print(f"wrote {out}")
    return 0 if all(r["ok"] for r in runs) else 1


if __name__ == "__main__":
    sys.exit(main())
