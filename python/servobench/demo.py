"""The demo: simulate a point-to-point move on the reference axis, print its figures of merit and write the
response plot; measure the axis's loop with the card's Bode sweep, check it against the analytic response, print the
margins and write the Bode plot; then identify the axis's plant from a 5 s experiment (Ceres), design the loop from
the identified model, apply it, and measure the tuned loop with the Bode sweep (plot written)."""

from __future__ import annotations

__all__ = ["run_demo", "main"]

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
    # The Bode tool's measurement (ADLINK L2035's example band at this axis's rate) and the model it must match.
    import numpy as np

    from . import frequency as fr
    from .plot import bode

    bode_axis = demo_axis(law=law)
    t0 = time.perf_counter()
    meas = fr.sine_sweep(bode_axis, start_hz=10, end_hz=1000, amplitude_pulse=20, points=40, update_s=0.1)
    sweep_wall = time.perf_counter() - t0
    ana = fr.analytic_response(bode_axis, np.geomspace(10, 1000, 800))
    bode_path = os.path.join(out_dir, f"demo_bode_{law}.png")
    bode([meas, ana], which="open_loop", title=f"servobench demo: open loop, {law_name}", path=bode_path)
    at_points = fr.analytic_response(bode_axis, meas.freq_hz)
    err_db = np.abs(20 * np.log10(np.abs(meas.open_loop / at_points.open_loop)))
    # Identify the plant (from rough guesses), design from the model, apply, verify with the Bode sweep.
    from .autotune import model_based_tune
    from .identify import fit_time, run_experiment

    t0 = time.perf_counter()
    log = run_experiment(demo_axis(law=law), amplitude_v=0.1, seed=0)
    fit = fit_time(log, "rigid", guess={"inertia_kgm2": 3e-4, "viscous_nms": 3e-4, "coulomb_nm": 0.02})
    ident_wall = time.perf_counter() - t0
    from .axis import Axis

    ref = demo_axis(law=law)
    model_axis = Axis(law=ref.law, drive=ref.drive, plant=fit.to_plant(), encoder=ref.encoder,
                      servo_period_s=ref.servo_period_s)
    tune = model_based_tune(model_axis)
    tuned = demo_axis(law=law)
    tune.apply(tuned)
    tuned_meas = fr.sine_sweep(tuned, start_hz=10, end_hz=1000, amplitude_pulse=20, points=40, update_s=0.1)
    tuned_path = os.path.join(out_dir, f"demo_bode_tuned_{law}.png")
    bode([meas, tuned_meas], which="open_loop", labels=["before, measured (stepped sine)",
                                                        "after, measured (stepped sine)"],
         title=f"servobench demo: open loop before and after the model-based tuning, {law_name}", path=tuned_path)
    return {"metrics": metrics, "plot": path, "ticks": len(run), "wall_s": wall, "axis": axis,
            "bode": meas, "bode_plot": bode_path, "margins": ana.margins(), "sweep_wall_s": sweep_wall,
            "bode_error_db": err_db, "identified": fit, "identify_wall_s": ident_wall, "tune": tune,
            "tuned_bode": tuned_meas, "tuned_margins": tuned_meas.margins(), "tuned_bode_plot": tuned_path}


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
    meas = res["bode"]
    print(f"Bode sweep: {len(meas)} points, {meas.message}, {res['sweep_wall_s'] * 1e3:.1f} ms wall")
    err, f = res["bode_error_db"], meas.freq_hz
    print(f"measured vs the linear model: |gain error| <= {err[f >= 40].max():.2f} dB from 40 Hz up; "
          f"{err[f < 40].max():.1f} dB below, where the Coulomb friction the model leaves out stiffens the axis")
    print("margins of the loop (analytic linear model):")
    print("  " + str(res["margins"]).replace("\n", "\n  "))
    print(f"Bode plot written to {res['bode_plot']}")
    fit = res["identified"]
    print(f"identified from a 5 s experiment in {res['identify_wall_s']:.2f} s (Ceres), guesses 3x / 3x / 4x off:")
    for name in ("inertia_kgm2", "viscous_nms", "coulomb_nm"):
        print(f"  {fit.parameters[name]}")
    t = res["tune"]
    print(f"model-based tuning: kp {t.kp:.2f}, ki {t.ki:.4f}, kd {t.kd:.1f} per tick, designed crossover "
          f"{t.crossover_hz:.1f} Hz")
    print("margins of the tuned loop (measured with the Bode sweep on the simulated axis):")
    print("  " + str(res["tuned_margins"]).replace("\n", "\n  "))
    print(f"Bode plot before/after written to {res['tuned_bode_plot']}")
    return 0
