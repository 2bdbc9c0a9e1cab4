"""Benchmark: axis ticks per second of the virtual card (4 demo axes jogging, safety and status every tick).

The same two cases as bench_axis.py's card rows (nothing recorded; the scope sampling the 4 following errors every
tick), timed in CPU time of this process (best of `--repeats`), so a loaded machine disturbs it less than wall time.
Prints one line per case: `<case> <axis ticks/s>`. To compare two builds, run it with each interpreter in turn
(same machine load), e.g. `python bench/bench_card.py --repeats 7`.

Run: python bench/bench_card.py [--ticks 250000] [--repeats 5]
"""

from __future__ import annotations

import argparse
import time

import servobench as sb


def card_cpu_s(card_ticks: int, sampler: bool) -> float:
    """CPU time in s of `card_ticks` ticks of a 4-axis card (demo axes, GT law, each axis jogging at +-5
    pulse/tick), recording nothing; with `sampler`, the scope takes the four following errors every tick."""
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
    c0 = time.process_time()
    card.step(card_ticks)
    return time.process_time() - c0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ticks", type=int, default=250_000, help="card ticks per run (axis ticks = 4x)")
    ap.add_argument("--repeats", type=int, default=5, help="runs per case; the best is reported")
    a = ap.parse_args(argv)
    for name, sampler in (("card_nothing_recorded", False), ("card_scope_4_errors", True)):
        best = min(card_cpu_s(a.ticks, sampler) for _ in range(a.repeats))
        print(f"{name} {4 * a.ticks / best:.4g}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
