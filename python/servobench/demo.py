"""The demo: simulate a point-to-point move on the reference axis, print its figures of merit and write the
response plot."""

from __future__ import annotations

import argparse
import os
import time

from .examples import demo_axis
from .metrics import move_metrics
from .trajectory import trapezoid_move


def run_demo(*, law: str = "gt", out_dir: str = "out", show: bool = False) -> dict:
    """Runs the demo and returns {"metrics": MoveMetrics, "plot": path, "ticks": n, "wall_s": s}."""
    axis = demo_axis(law=law)
    # One revolution (10000 pulse) at 20 pulse/tick (600 rpm at 200 us), 0.1 pulse/tick^2, then 0.2 s at rest.
    move = trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1,
                          dwell_before=50, dwell_after=1000)
    t0 = time.perf_counter()
    run = axis.run(move)
    wall = time.perf_counter() - t0
    metrics = move_metrics(run, settle_band_pulse=5)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, f"demo_response_{law}.png")
    from .plot import response

    law_name = "GT servo filter" if law == "gt" else "ADLINK servo law"
    response(run, metrics=metrics, title=f"servobench demo: {law_name}, Ts = {axis.servo_period_s * 1e6:g} us",
             path=path)
    return {"metrics": metrics, "plot": path, "ticks": len(run), "wall_s": wall, "axis": axis}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="servobench demo", description=__doc__)
    parser.add_argument("--law", choices=["gt", "aps"], default="gt", help="servo law (default gt)")
    parser.add_argument("--out", default="out", help="folder for the plot (default ./out)")
    args = parser.parse_args(argv)
    res = run_demo(law=args.law, out_dir=args.out)
    m = res["metrics"]
    print(f"servobench demo: {res['axis']!r}")
    print(f"simulated {res['ticks']} ticks in {res['wall_s'] * 1e3:.2f} ms wall")
    print(f"rise time               {m.rise_time_s * 1e3:8.3f} ms")
    print(f"overshoot               {m.overshoot_pulse:8.3f} pulse ({m.overshoot_pct:.4f} %)")
    print(f"settling time (+-{m.settle_band_pulse:g} p)  {m.settling_time_s * 1e3:8.3f} ms after the command ends")
    print(f"peak following error    {m.peak_following_error_pulse:8.3f} pulse")
    print(f"final error             {m.final_error_pulse:8.3f} pulse")
    print(f"response plot written to {res['plot']}")
    return 0
