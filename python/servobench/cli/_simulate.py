"""`servobench simulate`: a move on the axis, its record and plots."""

from __future__ import annotations

import math

import numpy as np

from ._common import EXIT_OK, Output, UsageError, WorkFailed, _bad_input, _load, _stem


# ----------------------------------------------------------------------------------------------------------------
# simulate
# ----------------------------------------------------------------------------------------------------------------
def _make_move(args, axis):
    from ..motion import GtSCurve, move_trajectory
    from ..trajectory import Trajectory, trapezoid_move

    with _bad_input("--distance-pulse/--vel/--acc/--jerk/--dwell-before/--dwell-after"):
        for name in ("dwell_before", "dwell_after"):
            v = getattr(args, name)
            if v < 0:
                raise ValueError(f"--{name.replace('_', '-')} = {v} must be >= 0 (ticks)")
        if args.move == "trapezoid":
            move = trapezoid_move(distance_pulse=args.distance_pulse, vel_pulse_per_tick=args.vel,
                                  acc_pulse_per_tick2=args.acc, dwell_before=args.dwell_before,
                                  dwell_after=args.dwell_after)
        else:
            if args.distance_pulse != int(args.distance_pulse):
                raise ValueError(f"--distance-pulse = {args.distance_pulse} must be whole pulses for the S-curve "
                                 "(GT_PrflS)")
            move = move_trajectory(GtSCurve(pos=args.distance_pulse, vel=args.vel, macc=args.acc, jerk=args.jerk),
                                   period_s=axis.servo_period_s, dwell_before=args.dwell_before,
                                   dwell_after=args.dwell_after)
    if args.ticks is not None:
        if args.ticks < 2:
            raise UsageError(f"--ticks = {args.ticks} must be >= 2")
        n = len(move)
        if args.ticks > n:  # hold the end
            pad = args.ticks - n
            move = Trajectory(pos=np.concatenate([move.pos, np.full(pad, move.pos[-1])]),
                              vel=np.concatenate([move.vel, np.zeros(pad)]),
                              acc=np.concatenate([move.acc, np.zeros(pad)]))
        else:
            move = Trajectory(pos=move.pos[:args.ticks], vel=move.vel[:args.ticks], acc=move.acc[:args.ticks])
    return move


def cmd_simulate(args) -> int:
    from ..axis import SIGNAL_UNITS
    from ..metrics import move_metrics
    from ..plot import response

    axis, _ = _load(args.axis)
    move = _make_move(args, axis)
    with _bad_input("--settle-band-pulse"):
        if not (args.settle_band_pulse > 0 and math.isfinite(args.settle_band_pulse)):
            raise ValueError(f"--settle-band-pulse = {args.settle_band_pulse} must be > 0 (pulse)")
    out = Output(args, _stem(args.axis))
    run = axis.run(move, signals="all")  # the trace file holds every signal
    metrics = move_metrics(run, settle_band_pulse=args.settle_band_pulse)
    ts = axis.servo_period_s
    if not args.quiet:
        print(f"{args.axis}: {args.move} move of {args.distance_pulse:g} pulse, {len(run)} ticks of "
              f"{ts * 1e6:g} us ({len(run) * ts:.4g} s)")
        print(f"  {metrics}")
    out.csv("trace", run.to_dict(), SIGNAL_UNITS, "every signal per tick")
    units = {"distance_pulse": "pulse", "rise_time_s": "s", "overshoot_pulse": "pulse", "overshoot_pct": "%",
             "settling_time_s": "s", "peak_following_error_pulse": "pulse", "final_error_pulse": "pulse",
             "settle_band_pulse": "pulse"}
    out.json("metrics", {
        "axis": args.axis, "servo_period_s": ts, "ticks": len(run), "stopped": run.stopped,
        "move": {"profile": args.move, "distance_pulse": args.distance_pulse, "vel_pulse_per_tick": args.vel,
                 "acc_pulse_per_tick2": args.acc,
                 "jerk_pulse_per_tick3": args.jerk if args.move == "s-curve" else None},
        "metrics": metrics.to_dict(), "units": units}, "move metrics: rise, overshoot, settling, peak following error")
    fig = response(run, metrics=metrics, title=f"servobench simulate: {_stem(args.axis)}, {args.move}, "
                                               f"Ts = {ts * 1e6:g} us")
    out.figure("response", fig, "position, following error and DAC output over time")
    if run.stopped:
        raise WorkFailed(f"the run stopped early at tick {len(run)}: {run.stopped}")
    return EXIT_OK
