"""The `servobench` command line (docs/cli.md).

Sub-commands: ``simulate``, ``bode``, ``tune``, ``identify`` (each reads an axis file, TOML or JSON, see
:mod:`servobench.axisfile`) and ``demo``. Each writes its data (CSV with units in the header, JSON) and its plots
(PNG or SVG) into ``--out`` (default ./out) and prints what it wrote.

Exit codes: 0 done; 1 the work failed (a tuning or a fit that did not succeed, a sweep that tripped, an output that
could not be written); 2 a usage error or bad input (options, axis file, log file). User errors never print a
traceback: ``servobench: error: <file>: <key>: <message>``.
"""

from __future__ import annotations

__all__ = ["main", "build_parser", "LOG_COLUMNS", "UsageError", "WorkFailed", "Output", "cmd_simulate", "cmd_bode",
           "cmd_tune", "cmd_identify", "cmd_demo"]

import argparse
import contextlib
import math
import os
import sys

import numpy as np

from . import _core, _serialise

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2


class UsageError(Exception):
    """Bad options or input files: exit 2."""


class WorkFailed(Exception):
    """The work ran but did not succeed: exit 1."""


# ----------------------------------------------------------------------------------------------------------------
# Output helpers
# ----------------------------------------------------------------------------------------------------------------
class Output:
    """The --out folder, the plot format and the record of what was written."""

    def __init__(self, args, stem: str):
        self.dir = args.out
        self.fmt = args.format
        self.stem = stem
        self.quiet = args.quiet
        self.written: list[str] = []

    def path(self, what: str, ext: str) -> str:
        os.makedirs(self.dir, exist_ok=True)
        return os.path.join(self.dir, f"{self.stem}_{what}.{ext}")

    def done(self, path: str, what: str) -> None:
        self.written.append(path)
        print(f"wrote {path}  ({what})")

    def csv(self, what: str, columns: dict, units: dict, doc: str) -> str:
        """Writes columns (name -> 1-D array) with a header 'name [unit]'."""
        p = self.path(what, "csv")
        names = list(columns)
        data = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
        header = ",".join(f"{n} [{units[n]}]" if units.get(n) else n for n in names)
        np.savetxt(p, data, delimiter=",", header=header, comments="", fmt="%.10g")
        self.done(p, doc)
        return p

    def json(self, what: str, obj: dict, doc: str) -> str:
        p = self.path(what, "json")
        with open(p, "w", encoding="utf-8") as f:
            f.write(_serialise.dumps(obj, indent=2) + "\n")
        self.done(p, doc)
        return p

    def figure(self, what: str, fig, doc: str) -> str:
        from .plot import Plot

        fig = fig.figure if isinstance(fig, Plot) else fig
        p = self.path(what, self.fmt)
        fig.savefig(p, dpi=110)
        import matplotlib.pyplot as plt

        plt.close(fig)
        self.done(p, doc)
        return p


def _margins_dict(m) -> dict:
    import dataclasses

    return dataclasses.asdict(m)


def _linearity_note(axis, measured: dict | None, analytic: dict | None, amplitude_pulse,
                    tolerance_deg: float = 3.0) -> str:
    """Why a measured phase margin differs from the analytic one by more than ``tolerance_deg``: the analytic loop
    linearises the plant (friction, cogging, unbalance and load torques are left out), so a small sweep amplitude
    on a plant with friction measures a different loop. Empty when they agree or a margin is missing."""
    try:
        pm_m, pm_a = float(measured["phase_margin_deg"]), float(analytic["phase_margin_deg"])
    except (TypeError, KeyError, ValueError):
        return ""
    if not (np.isfinite(pm_m) and np.isfinite(pm_a)) or abs(pm_m - pm_a) <= tolerance_deg:
        return ""
    fields = ("coulomb_nm", "static_nm", "motor_coulomb_nm", "motor_static_nm", "load_coulomb_nm",
              "load_static_nm", "cogging_nm", "unbalance_nm", "load_nm")
    nonlinear = [f"{f} {getattr(axis.plant, f):g} N*m" for f in fields if getattr(axis.plant, f, 0.0)]
    amp = "the automatic amplitude" if amplitude_pulse is None else f"{amplitude_pulse:g} pulse"
    why = (f"the plant has {', '.join(nonlinear)}, which the analytic loop leaves out; at {amp} "
           f"of sine amplitude they are a large share of the torque (a larger --amplitude-pulse measures closer to "
           f"the linear loop)") if nonlinear else \
        "the plant is linear: look at the sweep's coherence and the DAC/encoder quantisation at this amplitude"
    return (f"measured phase margin {pm_m:.1f} deg differs from the analytic {pm_a:.1f} deg by "
            f"{pm_m - pm_a:+.1f} deg: {why}")


def _progress(args):
    """progress= argument for the library: a text bar on stderr when wanted (L5)."""
    if args.quiet:
        return None
    return True if (args.progress or sys.stderr.isatty()) else None


def _fit_progress(args):
    """callback(iteration, cost) for the fit: a tqdm counter on stderr when wanted (L5, W7)."""
    from ._progress import iterations

    return iterations(_progress(args), "Identification")


@contextlib.contextmanager
def _bad_input(what: str):
    """ValueError/TypeError raised while building from options -> a usage error naming them."""
    try:
        yield
    except (ValueError, TypeError) as e:
        raise UsageError(f"{what}: {e}") from None


def _load(path: str):
    """(Axis, the file's dict) of an axis file."""
    from .axisfile import axis_from_dict, read_axis

    data = read_axis(path)
    return axis_from_dict(data, path), data


def _stem(path: str) -> str:
    return os.path.splitext(os.path.basename(path))[0]


def _drive_mode(axis) -> str:
    from . import _core

    return {_core.TorqueDrive: "torque", _core.VelocityDrive: "velocity", _core.ServoPositionDrive: "position",
            _core.StepperDrive: "stepper"}.get(type(axis.drive), type(axis.drive).__name__)


def _need_voltage_output(axis, path, command):
    mode = _drive_mode(axis)
    if mode not in ("torque", "velocity"):
        raise UsageError(f"{path}: drive.mode: {command} needs the card's position loop, i.e. a voltage-output axis "
                         f"(drive.mode = \"torque\" or \"velocity\"); this axis's drive is \"{mode}\" (pulse input, "
                         "the servo law is bypassed)")


# ----------------------------------------------------------------------------------------------------------------
# simulate
# ----------------------------------------------------------------------------------------------------------------
def _make_move(args, axis):
    from .motion import GtSCurve, move_trajectory
    from .trajectory import Trajectory, trapezoid_move

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
    from .axis import SIGNAL_UNITS
    from .metrics import move_metrics
    from .plot import response

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


# ----------------------------------------------------------------------------------------------------------------
# bode
# ----------------------------------------------------------------------------------------------------------------
_KIND = {"plant": "plant", "open": "open_loop", "closed": "closed_loop"}
_RESP_UNITS = {"plant": "pulse/count", "open_loop": "pulse/pulse", "closed_loop": "pulse/pulse"}


def _response_columns(fr) -> tuple[dict, dict]:
    cols, units = {"freq_hz": fr.freq_hz}, {"freq_hz": "Hz"}
    for w in ("plant", "open_loop", "closed_loop"):
        cols[f"{w}_gain_db"] = fr.gain_db(w)
        units[f"{w}_gain_db"] = f"dB re 1 {_RESP_UNITS[w]}"
        cols[f"{w}_phase_deg"] = fr.phase_deg(w)
        units[f"{w}_phase_deg"] = "deg"
    if fr.coherence is not None:
        cols["coherence"], units["coherence"] = fr.coherence, "1"
    if fr.distortion is not None:
        cols["distortion"], units["distortion"] = fr.distortion, "1"
    return cols, units


def _stability_lines(report: dict) -> list[str]:
    """The verdicts to print first: "UNSTABLE ..." lines for the model and the measurement (empty when stable)."""
    out = []
    for key, name in (("analytic_margins", "model"), ("margins", "measured")):
        m = report.get(key)
        if isinstance(m, dict) and not m.get("stable", True) and m.get("stability", {}).get("decided", True):
            out.append(f"UNSTABLE ({name}): {m['stability'].get('reason', '')}")
    return out


def cmd_bode(args) -> int:
    from . import frequency as fr
    from .agreement import model_agreement
    from .plot import bode

    axis, _ = _load(args.axis)
    _need_voltage_output(axis, args.axis, "bode")
    kind = _KIND[args.kind]
    nyquist = 0.5 / axis.servo_period_s
    with _bad_input("--start-hz/--end-hz/--points/--amplitude-pulse"):
        if not (0 < args.start_hz < args.end_hz < nyquist):
            raise ValueError(f"the band must satisfy 0 < start ({args.start_hz:g} Hz) < end ({args.end_hz:g} Hz) < "
                             f"Nyquist ({nyquist:g} Hz at Ts = {axis.servo_period_s * 1e6:g} us)")
        if not 2 <= args.points <= 100000:
            raise ValueError(f"--points = {args.points} is outside the allowed range 2..100000")
        if args.amplitude_pulse is not None and not args.amplitude_pulse > 0:
            raise ValueError(f"--amplitude-pulse = {args.amplitude_pulse:g} must be > 0 pulse (omit it: automatic)")
    out = Output(args, _stem(args.axis))
    dense = np.geomspace(args.start_hz, args.end_hz, 400)
    with _bad_input("analytic model"):
        ana = fr.analytic_response(axis, dense, feedforward=args.feedforward)
    report = {"axis": args.axis, "servo_period_s": axis.servo_period_s, "kind": args.kind,
              "band_hz": [args.start_hz, args.end_hz], "feedforward": args.feedforward,
              "analytic_margins": _margins_dict(ana.margins())}
    failed = None
    amps = np.zeros(0)
    if args.analytic:
        data = fr.analytic_response(axis, np.geomspace(args.start_hz, args.end_hz, args.points),
                                    feedforward=args.feedforward)
        report.update(method="analytic", points=args.points, margins=_margins_dict(data.margins()))
        plotted = {"analytic model": ana}
    else:
        with _bad_input("--amplitude-pulse/--update-s/--deviation-limit-pulse"):
            data = fr.sine_sweep(axis, start_hz=args.start_hz, end_hz=args.end_hz, amplitude_pulse=args.amplitude_pulse,
                                 points=args.points, update_s=args.update_s,
                                 deviation_limit_pulse=args.deviation_limit_pulse, feedforward=args.feedforward,
                                 progress=_progress(args))
        amps = np.asarray(data.signals.get("amplitude_pulse", []), dtype=float)
        report.update(method=data.method, status=data.status, message=data.message, points=len(data),
                      amplitude_pulse="auto" if args.amplitude_pulse is None else args.amplitude_pulse,
                      amplitude_pulse_used=amps, update_s=args.update_s,
                      points_flagged=[{"freq_hz": float(f), "reason": r}
                                      for f, r in zip(data.freq_hz, data.flags or []) if r],
                      saturated_ticks={k: np.asarray(data.signals[k]) for k in
                                       ("dac_saturated_ticks", "current_saturated_ticks", "torque_saturated_ticks")})
        if len(data) >= 2 and not args.feedforward:
            try:
                mm = data.margins()
                report["margins"], report["margins_note"] = _margins_dict(mm), mm.note
            except ValueError as e:
                report["margins_note"] = f"no measured margin: {e}"
                failed = report["margins_note"]
        if len(data):
            agr = model_agreement(axis, data, kind)
            report["model_agreement"] = {k: agr[k] for k in ("max_gain_error_db", "max_phase_error_deg", "agrees",
                                                             "not_applicable_hz", "summary")}
            report["model_agreement"]["why_not"] = [{"freq_hz": float(f), "reason": w}
                                                    for f, w in zip(agr["freq_hz"], agr["why_not"]) if w]
            with np.errstate(divide="ignore", invalid="ignore"):
                err = np.abs(agr["gain_error_db"])
            report["max_gain_error_vs_analytic_db"] = float(np.nanmax(err)) if np.any(np.isfinite(err)) else None
        if data.status != "completed":
            failed = f"the sweep ended early: {data.status} ({data.message})"
        plotted = {"measured (stepped sine)": data, "analytic model": ana}
    report["units"] = {"freq_hz": "Hz", "plant": "pulse per DAC count", "open_loop": "pulse/pulse (Y/E)",
                       "closed_loop": "pulse/pulse (Y/R)", "margins": "dB, deg, Hz, s",
                       "amplitude_pulse_used": "pulse"}
    unstable = _stability_lines(report)
    report["unstable"] = bool(unstable)
    for line in unstable:
        print(line)
    if not args.quiet:
        from .frequency import Margins

        if "margins" in report:
            print(f"{args.axis}: margins ({report['method']}):\n  " +
                  str(Margins(**report["margins"])).replace("\n", "\n  "))
        elif report.get("margins_note"):
            print(f"{args.axis}: {report['margins_note']}")
        print(f"{args.axis}: margins (analytic model):\n  " + str(ana.margins()).replace("\n", "\n  "))
        if len(amps):
            print(f"  excitation amplitude {'chosen per point' if args.amplitude_pulse is None else 'given'}: "
                  f"{amps.min():.4g}..{amps.max():.4g} pulse")
        if report.get("model_agreement"):
            print("  " + report["model_agreement"]["summary"])
    cols, units = _response_columns(data)
    if len(amps):
        cols["amplitude_pulse"], units["amplitude_pulse"] = amps, "pulse"
        cols["usable"], units["usable"] = data.usable.astype(float), "1 = passed the checks"
    if len(data):
        out.csv("bode", cols, units, f"{report['method']} response: gain and phase of plant, open and closed loop")
    out.json("bode", report, "margins, band, status")
    with np.errstate(divide="ignore", invalid="ignore"):  # a measured point the encoder did not see: gain 0
        res = bode(dense, plotted, which=kind, title=f"servobench bode: {_stem(args.axis)}, "
                   f"{kind.replace('_', ' ')}", margins=True if kind == "open_loop" else False)
    out.figure("bode", res, f"Bode plot of the {kind.replace('_', ' ')}")
    if unstable:
        raise WorkFailed(unstable[0])
    if failed:
        raise WorkFailed(failed)
    return EXIT_OK


# ----------------------------------------------------------------------------------------------------------------
# tune
# ----------------------------------------------------------------------------------------------------------------
def _step_run(axis, step_pulse, ticks):
    cmd = np.full(ticks, float(step_pulse))
    cmd[:50] = 0.0
    return axis.run(cmd, signals=["time_s", "cmd_pos", "fb_pos", "volts"])


def cmd_tune(args) -> int:
    from . import _core
    from . import frequency as fr
    from .autotune import model_based_tune, relay_autotune
    from .axisfile import save_axis
    from .frequency import Margins
    from .plot import _pyplot, bode

    axis, data = _load(args.axis)
    _need_voltage_output(axis, args.axis, "tune")
    if args.method == "relay" and not isinstance(axis.drive, _core.VelocityDrive):
        raise UsageError(f"{args.axis}: drive.mode: relay tuning needs a velocity-mode drive (drive.mode = "
                         f"\"velocity\", as the ADLINK manual's procedure assumes); this axis's drive is "
                         f"\"{_drive_mode(axis)}\": a torque-mode axis is a double integrator with no steady relay "
                         "limit cycle. Use --method model")
    stem = _stem(args.axis)
    out = Output(args, stem)
    report = {"axis": args.axis, "method": args.method, "phase_margin_deg_target": args.phase_margin_deg}
    if args.method == "model":
        with _bad_input("--phase-margin-deg/--alpha/--min-gain-margin-db/--max-ms"):
            if not 10 <= args.phase_margin_deg <= 89:
                raise ValueError(f"--phase-margin-deg = {args.phase_margin_deg:g} is outside the allowed range 10..89")
        try:
            res = model_based_tune(axis, phase_margin_deg=args.phase_margin_deg, alpha=args.alpha,
                                   notch=not args.no_notch, min_gain_margin_db=args.min_gain_margin_db,
                                   max_ms=args.max_ms)
        except ValueError as e:
            raise WorkFailed(f"model-based tuning: {e}") from None
        report["result"] = {"kp": res.kp, "ki": res.ki, "kd": res.kd, "kc": res.kc, "ti_s": res.ti_s,
                            "td_s": res.td_s, "crossover_hz": res.crossover_hz, "limited_by": res.limited_by,
                            "designed_margins": _margins_dict(res.margins),
                            "notch": {k: v for k, v in res.notch.items() if k not in ("float_biquad", "adlink_biquad")}}
        if not args.quiet:
            print(res.summary)
        specs = None
        if res.notch.get("used"):
            specs = [{"type": "notch", "center_hz": res.notch["center_hz"], "q": res.notch["q"], "prewarp": True,
                      "adlink": isinstance(res.filters[0], _core.AdlinkBiquad)}]
    else:
        with _bad_input("--phase-margin-deg/--amplitude-v/--hysteresis-pulse/--data-length"):
            res = relay_autotune(axis, amplitude_v=args.amplitude_v, hysteresis_pulse=args.hysteresis_pulse,
                                 data_length=args.data_length, phase_margin_deg=args.phase_margin_deg,
                                 progress=_progress(args))
        report["result"] = {"status": res.status, "message": res.message, "kp": res.kp, "ki": res.ki, "kd": res.kd,
                            "kc": res.kc, "ti_s": res.ti_s, "td_s": res.td_s, "kp_spread": res.kp_spread,
                            "ki_spread": res.ki_spread, "kd_spread": res.kd_spread,
                            "ultimate_freq_hz": res.ultimate_freq_hz,
                            "ultimate_gain_v_per_pulse": res.ultimate_gain_v_per_pulse, "rule": args.rule}
        if not args.quiet:
            print(f"relay tuning: {res.message}")
        if res.status != "completed":
            out.json("tune", report, "tuning report (failed)")
            raise WorkFailed(f"relay tuning did not complete: {res.status} ({res.message})")
        res = res.rule(args.rule)
        report["result"].update(kp=res.kp, ki=res.ki, kd=res.kd, kc=res.kc, ti_s=res.ti_s, td_s=res.td_s)
        specs = None
    before, _ = _load(args.axis)
    after, _ = _load(args.axis)
    from .tune_check import TuningRefused

    try:
        check = res.apply(after, force=args.force)
    except TuningRefused as e:
        report["check"] = {"accepted": False, "failures": e.check.failures,
                           "model_margins": _margins_dict(e.check.model),
                           "measured_margins": None if e.check.measured is None else _margins_dict(e.check.measured),
                           "measured_note": e.check.measured_note}
        print(str(e.check))
        out.json("tune", report, "tuning report (refused)")
        raise WorkFailed("REFUSED: the tuned loop fails its check (" + "; ".join(e.check.failures) +
                         "); --force applies it anyway") from None
    except ValueError as e:
        raise WorkFailed(f"the gains do not fit the card's law: {e}") from None
    report["check"] = {"accepted": check.accepted, "forced": bool(args.force and not check.accepted),
                       "failures": check.failures, "model_margins": _margins_dict(check.model),
                       "measured_margins": None if check.measured is None else _margins_dict(check.measured),
                       "measured_note": check.measured_note}
    if not args.quiet:
        print(str(check))
    report["before"] = {"law": before.law.to_dict()}
    report["after"] = {"law": after.law.to_dict(),
                       "filters": [None if f is None else {"type": type(f).__name__, **f.to_dict()}
                                   for f in after.filters]}
    if not args.quiet:
        print(f"tuned law: {after.law!r}")
    # the tuned axis file, in the input's format
    ext = os.path.splitext(args.axis)[1].lower()
    p = out.path("tuned", ext.lstrip("."))
    desc = f"{data.get('description', stem)}; tuned by servobench tune --method {args.method}"
    save_axis(after, p, filter_specs=specs, description=desc,
              header=f"written by servobench tune --method {args.method} from {args.axis}")
    out.done(p, "the tuned axis file")
    # margins: analytic before/after, measured after
    nyq = 0.5 / after.servo_period_s
    f_hi = min(args.end_hz, 0.9 * nyq)
    dense = np.geomspace(args.start_hz, f_hi, 400)
    ana_before = fr.analytic_response(before, dense)
    ana_after = fr.analytic_response(after, dense)
    report["before"]["analytic_margins"] = _margins_dict(ana_before.margins())
    report["after"]["analytic_margins"] = _margins_dict(ana_after.margins())
    curves = {"before, model (analytic)": ana_before, "after, model (analytic)": ana_after}
    mm = None
    if not args.no_sweep:
        swept, _ = _load(args.axis)
        res.apply(swept, force=True, verify=False)
        meas = fr.sine_sweep(swept, start_hz=args.start_hz, end_hz=f_hi, amplitude_pulse=args.amplitude_pulse,
                             points=args.points, progress=_progress(args))  # update_s: the struct's
        report["after"]["sweep"] = {"status": meas.status, "message": meas.message, "points": len(meas),
                                    "band_hz": [args.start_hz, f_hi],
                                    "amplitude_pulse": "auto" if args.amplitude_pulse is None else args.amplitude_pulse,
                                    "amplitude_pulse_used": np.asarray(meas.signals["amplitude_pulse"])}
        try:
            mmo = meas.margins()
            mm, note = _margins_dict(mmo), mmo.note
        except ValueError as e:
            mm, note = None, str(e)
        report["after"]["measured_margins"], report["after"]["measured_margins_note"] = mm, note
        from .agreement import model_agreement

        report["after"]["model_agreement"] = model_agreement(swept, meas)["summary"] if len(meas) else ""
        lin = _linearity_note(swept, mm, report["after"]["analytic_margins"], args.amplitude_pulse)
        report["after"]["linearity_note"] = lin
        if len(meas) >= 2:
            curves["after, measured (stepped sine)"] = meas
        if not args.quiet and mm is not None:
            from .frequency import Margins

            print("tuned loop, measured with the stepped-sine sweep:\n  " + str(Margins(**mm)).replace("\n", "\n  "))
            if lin:
                print("  note: " + lin)
    # step response before and after
    ticks = args.step_ticks
    r0 = _step_run(before, args.step_pulse, ticks)
    r1 = _step_run(after, args.step_pulse, ticks)
    from .metrics import move_metrics

    for name, r in (("before", r0), ("after", r1)):
        try:
            report[name]["step_metrics"] = move_metrics(r, settle_band_pulse=max(1.0, 0.02 * abs(args.step_pulse))).to_dict()
        except ValueError:
            report[name]["step_metrics"] = None
    report["units"] = {"kp": "counts/pulse per tick", "ki": "counts/(pulse*tick)", "kd": "counts*tick/pulse",
                       "kc": "counts/pulse", "ti_s": "s", "td_s": "s", "margins": "dB, deg, Hz, s"}
    out.json("tune", report, "gains, designed and measured margins, step metrics before/after")
    plt = _pyplot()
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), constrained_layout=True)
    t_ms = r0.time_s * 1e3
    a1.plot(t_ms, r0.cmd_pos, "k:", lw=1, label="command")
    a1.plot(t_ms, r0.fb_pos, lw=1, label="before")
    a1.plot(t_ms, r1.fb_pos, lw=1, label="after")
    a1.set_ylabel("position [pulse]")
    a1.legend(loc="lower right")
    a2.plot(t_ms, r0.volts, lw=1, label="before")
    a2.plot(t_ms, r1.volts, lw=1, label="after")
    a2.set_ylabel("DAC output [V]")
    a2.set_xlabel("time [ms]")
    for a in (a1, a2):
        a.grid(True, alpha=0.3)
    fig.suptitle(f"servobench tune ({args.method}): {stem}, {args.step_pulse:g} pulse step before and after", fontsize=10)
    out.figure("tune_step", fig, "step response before and after")
    with np.errstate(divide="ignore", invalid="ignore"):  # a measured point the encoder did not see: gain 0
        fig = bode(dense, curves, which="open_loop",
                   margins={"after, model (analytic)": ana_after.margins(),
                            **({"after, measured (stepped sine)": Margins(**mm)} if mm else {})},
                   title=f"servobench tune ({args.method}): {stem}, open loop before and after")
    out.figure("tune_bode", fig, "Bode plot of the open loop before and after (margins of the tuned loop)")
    return EXIT_OK


# ----------------------------------------------------------------------------------------------------------------
# identify
# ----------------------------------------------------------------------------------------------------------------
#: Columns of an identification log CSV (a header row; a " [unit]" tag on a name gives its unit, see
#: servobench.idlog: the same reader as IdentificationLog.from_csv).
LOG_COLUMNS = {
    "time_s": "sample time, s, uniformly spaced (the servo period)",
    "torque_nm": "torque command held over the sample, N*m (or volts)",
    "volts": "DAC voltage held over the sample, V (converted with --torque-per-volt or the axis's drive)",
    "position_pulse": "measured position, pulse (encoder counts; or position_rad, speed_rad_s, speed_pulse_s)",
    "position_rad": "measured position, rad",
    "speed_rad_s": "measured speed, rad/s",
    "speed_pulse_s": "measured speed, pulse/s",
}
_MEASURED = {"position_pulse": "pulse", "position_rad": "rad", "speed_rad_s": "rad/s", "speed_pulse_s": "pulse/s"}


def _parse_guesses(items) -> dict:
    out = {}
    for item in items or []:
        if "=" not in item:
            raise UsageError(f"--guess {item!r}: expected name=value (SI units), e.g. inertia_kgm2=2e-4")
        k, v = item.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            raise UsageError(f"--guess {item!r}: '{v}' is not a number") from None
    return out


def _nominal_guess(plant, model: str) -> dict:
    """The axis file's plant values of the parameters a fit estimates: the non-zero ones (the Stribeck pair only
    when the file has a breakaway peak)."""
    from .identify import model_parameters

    d = plant.to_dict()
    names = [p["name"] for p in model_parameters(model)]
    g = {n: d[n] for n in names if n in d and d[n] != 0}
    static, coul, speed = (("static_nm", "coulomb_nm", "stribeck_speed_rad_s") if model == "rigid" else
                           ("motor_static_nm", "motor_coulomb_nm", "motor_stribeck_speed_rad_s"))
    if d.get(static, 0) <= d.get(coul, 0):
        g.pop(static, None)
        g.pop(speed, None)
    return g


def cmd_identify(args) -> int:
    from . import _core
    from .axis import Axis
    from .axisfile import save_axis
    from .identify import IdentificationError, IdentificationLog, fit_time, model_parameters, run_experiment

    if args.axis is None and args.log is None:
        raise UsageError("identify: give an axis file (to run the standard experiment on it as a digital twin) "
                         "and/or --log LOG.csv")
    model = {"two-mass": "two_mass"}.get(args.model, args.model) if args.model else None
    axis = data = None
    if args.axis is not None:
        axis, data = _load(args.axis)
        if model is None:
            model = "two_mass" if isinstance(axis.plant, _core.TwoMassPlant) else "rigid"
    model = model or "rigid"
    names = [p["name"] for p in model_parameters(model)]
    guess = {}
    if axis is not None and type(axis.plant) is (_core.RigidPlant if model == "rigid" else _core.TwoMassPlant):
        guess = _nominal_guess(axis.plant, model)
    given = _parse_guesses(args.guess)
    for k in list(given) + list(args.fixed or []):
        if k not in names:
            from .axisfile import _suggest

            raise UsageError(f"--guess/--fixed: '{k}' is not a parameter of the {model} model{_suggest(k, names)} "
                             f"(parameters: {', '.join(names)})")
    guess.update(given)
    if not guess and model != "rigid":
        raise UsageError(f"identify: no starting values: give --guess name=value for each {model} parameter to "
                         f"estimate ({', '.join(names)}), or an axis file whose plant holds them")
    stem = _stem(args.log if args.log else args.axis)
    out = Output(args, stem)
    if args.log is None:
        if not isinstance(axis.drive, _core.TorqueDrive):
            raise UsageError(f"{args.axis}: drive.mode: identification needs a torque-mode drive (the torque reaching "
                             f"the mechanics must be known); this axis's drive is \"{_drive_mode(axis)}\"")
        with _bad_input("--duration-s/--amplitude-v/--seed"):
            log = run_experiment(axis, duration_s=args.duration_s, amplitude_v=args.amplitude_v, seed=args.seed)
        source = f"the standard experiment on {args.axis} ({args.duration_s:g} s, PRBS {args.amplitude_v:g} V, " \
                 f"seed {args.seed})"
        cpr = axis.encoder.counts_per_rev
        out.csv("identify_log", {"time_s": log.time_s, "torque_nm": log.torque_nm,
                                 "position_pulse": log.measured * cpr / (2 * np.pi), "volts": log.extra["volts"]},
                {"time_s": "s", "torque_nm": "N*m", "position_pulse": "pulse", "volts": "V"},
                "the experiment's log (identify --log reads it back)")
    else:
        cpr = args.counts_per_rev or (axis.encoder.counts_per_rev if axis is not None else 10000.0)
        bw = args.current_bw_hz if args.current_bw_hz is not None else (
            axis.drive.current_bw_hz if axis is not None and hasattr(axis.drive, "current_bw_hz") else math.inf)
        gain = args.torque_per_volt
        if gain is None and axis is not None and isinstance(axis.drive, _core.TorqueDrive):
            gain = axis.drive.kt * axis.drive.amps_per_volt
        units = {}
        for item in args.unit or []:
            if "=" not in item:
                raise UsageError(f"--unit {item!r}: expected COLUMN=UNIT, e.g. qm=mm")
            k, v = item.split("=", 1)
            units[k.strip()] = v.strip()
        kw = dict(units=units, command_gain=gain, counts_per_rev=cpr, current_bw_hz=bw, count_m=args.count_m,
                  measured_on_load=bool(axis is not None and axis.encoder.on_load))
        for opt in ("time", "command", "measured", "reference"):
            if getattr(args, opt + "_column"):
                kw[opt] = getattr(args, opt + "_column")
        if not os.path.exists(args.log):
            raise UsageError(f"{args.log}: no such file")
        try:
            if args.log.lower().endswith(".mat"):
                log = IdentificationLog.from_mat(args.log, **kw)
            else:
                log = IdentificationLog.from_csv(args.log, **kw)
        except (ValueError, TypeError) as e:  # the reader's messages name the file, the line and the column
            msg = str(e)
            raise UsageError(msg if msg.startswith(str(args.log)) else f"{args.log}: {msg}") from None
        cols = log.extra.get("columns", {})
        source = (f"{args.log} ({len(log)} samples, " + ", ".join(f"{c} [{u}]" for c, u in cols.items()) +
                  (f", time jitter {log.time_jitter_ppm:.3g} ppm" if log.time_jitter_ppm else "") + ")")
    if not args.quiet:
        print(f"identify: {model} model from {source}; starting values: "
              + (", ".join(f"{k}={v:g}" for k, v in guess.items()) if guess else "the IDIM-LS answer"))
    fit_progress = _fit_progress(args)
    try:
        fit = fit_time(log, model, guess=guess or None, fixed=args.fixed or (), progress=fit_progress,
                       dynamics_hz=args.dynamics_hz)
    except IdentificationError as e:
        raise WorkFailed(f"identification: {e}") from None
    except ValueError as e:
        raise UsageError(f"identify: {e}") from None
    finally:
        if fit_progress is not None:
            fit_progress.close()
    if not args.quiet:
        print(str(fit))
    report = {"source": source, "model": model, "converged": fit.converged, "iterations": fit.iterations,
              "seconds": fit.seconds, "nrmse": fit.nrmse, "residual_rms": fit.residual_rms,
              "residual_unit": "rad/s" if log.measured_is_speed else "rad",
              "parameters": {k: {"value": e.value, "std_error": e.std_error, "unit": e.unit, "fixed": e.fixed,
                                 "initial": e.initial, "at_bound": e.at_bound} for k, e in fit.parameters.items()},
              "not_identifiable": fit.not_identifiable, "summary": fit.summary}
    if args.log is None:
        truth = axis.plant.to_dict()
        report["twin_error_pct"] = {k: 100 * (e.value / truth[k] - 1) for k, e in fit.parameters.items()
                                    if not e.fixed and truth.get(k)}
    out.json("identified", report, "identified parameters with standard errors")
    out.figure("identify_fit", fit.plot_residuals(), "measured vs model and the residual")
    plant = fit.to_plant()
    if axis is not None:
        base = axis
        ident = Axis(law=base.law, drive=base.drive, plant=plant, encoder=base.encoder, dac=base.dac,
                     switches=base.switches, servo_period_s=base.servo_period_s, substeps=base.substeps,
                     filters=base.filters)
        ext = os.path.splitext(args.axis)[1].lstrip(".").lower()
        specs = data.get("filters")
    else:
        try:
            ident = Axis(plant=plant, servo_period_s=float(f"{log.sample_period_s:.12g}"),
                         encoder=_core.Encoder(counts_per_rev=log.counts_per_rev))
        except ValueError:
            ident = Axis(plant=plant, encoder=_core.Encoder(counts_per_rev=log.counts_per_rev))
        ext, specs = "toml", None
    p = out.path("identified", ext)
    save_axis(ident, p, filter_specs=specs, description=f"plant identified ({model}) from {source}",
              header="written by servobench identify")
    out.done(p, "axis file with the identified plant")
    if not fit.converged:
        raise WorkFailed("the fit did not converge (see the summary above)")
    return EXIT_OK


# ----------------------------------------------------------------------------------------------------------------
# demo
# ----------------------------------------------------------------------------------------------------------------
def cmd_demo(args) -> int:
    from .demo import main as demo_main

    return demo_main(["--law", args.law, "--out", args.out])


# ----------------------------------------------------------------------------------------------------------------
# The parser
# ----------------------------------------------------------------------------------------------------------------
class _Formatter(argparse.ArgumentDefaultsHelpFormatter, argparse.RawDescriptionHelpFormatter):
    pass


def _described(group, flag: str, options_class, name: str, help_prefix: str = ""):
    """An option whose default, type, unit and meaning are those of a C++ options struct (its describe() table,
    read through the binding; decision OQ4): nothing retyped here."""
    from . import _options

    f = next(f for f in _options.option_fields(options_class) if f.name == name)
    unit = f" [{f.unit}]" if f.unit else ""
    text = (help_prefix + f.doc + unit).replace("%", "%%")  # argparse formats help with %
    group.add_argument(flag, type=int if f.type == "int" else float, default=f.default, help=text)


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    common = argparse.ArgumentParser(add_help=False)
    g = common.add_argument_group("output")
    g.add_argument("--out", default="out", metavar="DIR", help="folder for the files written")
    g.add_argument("--format", choices=["png", "svg"], default="png", help="plot file format")
    g.add_argument("--quiet", "-q", action="store_true", help="print only the files written; no progress bars")
    g.add_argument("--progress", action="store_true",
                   help="progress bars on stderr even when it is not a terminal (default: only on a terminal)")

    p = argparse.ArgumentParser(
        prog="servobench", formatter_class=_Formatter,
        description="servobench: simulate, measure, tune and identify a servo axis described in a TOML/JSON file.",
        epilog="Each command's --help lists its options with units. Exit codes: 0 done, 1 the work failed, "
               "2 usage error or bad input file. Axis files: docs/cli.md; examples in examples/axes/.")
    p.add_argument("--version", action="version", version=f"servobench {__version__}")
    sub = p.add_subparsers(dest="command", metavar="<command>")

    s = sub.add_parser("simulate", parents=[common], formatter_class=_Formatter,
                       help="run a point-to-point move: trace (CSV), metrics (JSON), response plot",
                       description="Runs a point-to-point move on the axis and writes <stem>_trace.csv (every signal "
                                   "per tick, units in the header), <stem>_metrics.json (rise time, overshoot, "
                                   "settling time, peak following error) and <stem>_response.<format>.")
    s.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    s.add_argument("--move", choices=["trapezoid", "s-curve"], default="trapezoid",
                   help="profile: trapezoid (servobench.trapezoid_move) or s-curve (the GT card's GT_PrflS)")
    s.add_argument("--distance-pulse", type=float, default=10000.0, help="move length, pulse (signed)")
    s.add_argument("--vel", type=float, default=20.0, help="cruise velocity, pulse/tick")
    s.add_argument("--acc", type=float, default=0.1, help="acceleration, pulse/tick^2 (s-curve: the maximum, < 0.5)")
    s.add_argument("--jerk", type=float, default=0.001, help="s-curve jerk, pulse/tick^3 (0 < jerk < 0.5)")
    s.add_argument("--dwell-before", type=int, default=50, help="ticks at rest before the move")
    s.add_argument("--dwell-after", type=int, default=1000, help="ticks at rest after the move")
    s.add_argument("--ticks", type=int, default=None,
                   help="run exactly this many ticks (the end held, or the move cut); default: the move + dwells")
    s.add_argument("--settle-band-pulse", type=float, default=5.0, help="in-position band for the settling time, pulse")
    s.set_defaults(func=cmd_simulate)

    b = sub.add_parser("bode", parents=[common], formatter_class=_Formatter,
                       help="stepped-sine Bode sweep (the ADLINK Bode tool): response CSV/JSON, margins, plot",
                       description="Measures the loop with the ADLINK Bode tool's stepped sine (defaults = the "
                                   "manual's example, L2023/L2035) and writes <stem>_bode.csv (gain dB and phase deg "
                                   "of plant Y/U, open loop Y/E, closed loop Y/R per frequency), <stem>_bode.json "
                                   "(margins measured and analytic, status) and <stem>_bode.<format> (measured dots "
                                   "on the analytic model).")
    b.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    b.add_argument("--kind", choices=list(_KIND), default="open",
                   help="response plotted: plant Y/U (pulse/count), open loop Y/E, closed loop Y/R")
    _described(b, "--start-hz", _core.SineSweepOptions, "start_hz")
    _described(b, "--end-hz", _core.SineSweepOptions, "end_hz")
    _described(b, "--points", _core.SineSweepOptions, "points")
    b.add_argument("--amplitude-pulse", type=float, default=None,
                   help="sine amplitude added to the command, pulse (the manual's example: 300); default: chosen per "
                        "point to keep the DAC and the drive out of saturation and above quantisation")
    _described(b, "--update-s", _core.SineSweepOptions, "update_s")
    _described(b, "--deviation-limit-pulse", _core.SineSweepOptions, "deviation_limit_pulse")
    b.add_argument("--feedforward", action="store_true", help="keep the feed-forward in the loop (no margins then)")
    b.add_argument("--analytic", action="store_true",
                   help="compute the analytic response of the linear model instead of measuring (instant)")
    b.set_defaults(func=cmd_bode)

    t = sub.add_parser("tune", parents=[common], formatter_class=_Formatter,
                       help="relay or model-based auto-tuning: tuned axis file, report, step and Bode before/after",
                       description="Tunes the position loop and writes <stem>_tuned.<toml|json> (the axis file with "
                                   "the new gains, in the input's format), <stem>_tune.json (gains, designed and "
                                   "measured margins, step metrics), <stem>_tune_step.<format> (step response before "
                                   "and after) and <stem>_tune_bode.<format> (open loop before and after).")
    t.add_argument("axis", metavar="AXIS", help="axis file (.toml or .json)")
    t.add_argument("--method", choices=["model", "relay"], default="model",
                   help="model: design from the axis's analytic plant (servobench.model_based_tune); relay: the "
                        "ADLINK relay experiment (needs a velocity-mode drive)")
    _described(t, "--phase-margin-deg", _core.ModelTuneOptions, "phase_margin_deg")
    m = t.add_argument_group("model-based tuning")
    _described(m, "--alpha", _core.ModelTuneOptions, "alpha")
    _described(m, "--min-gain-margin-db", _core.ModelTuneOptions, "min_gain_margin_db")
    _described(m, "--max-ms", _core.ModelTuneOptions, "max_ms")
    m.add_argument("--no-notch", action="store_true", help="do not try a notch at the plant's resonance")
    r = t.add_argument_group("relay tuning (ADLINK manual L1842-1847 defaults)")
    _described(r, "--amplitude-v", _core.RelayTuneOptions, "amplitude_v")
    _described(r, "--hysteresis-pulse", _core.RelayTuneOptions, "hysteresis_pulse")
    _described(r, "--data-length", _core.RelayTuneOptions, "data_length")
    r.add_argument("--rule", choices=["phase_margin", "ziegler_nichols", "tyreus_luyben"], default="phase_margin",
                   help="gains from the experiment by this rule")
    v = t.add_argument_group("verification")
    v.add_argument("--step-pulse", type=float, default=100.0, help="step for the before/after response, pulse")
    v.add_argument("--step-ticks", type=int, default=1000, help="length of the step runs, ticks")
    v.add_argument("--start-hz", type=float, default=10.0, help="verification sweep and Bode plot from, Hz")
    v.add_argument("--end-hz", type=float, default=1000.0, help="... to, Hz (capped at 0.9 Nyquist)")
    v.add_argument("--points", type=int, default=40, help="verification sweep points")
    v.add_argument("--amplitude-pulse", type=float, default=None,
                   help="verification sweep amplitude, pulse (default: chosen per point, out of saturation)")
    v.add_argument("--force", action="store_true",
                   help="write the tuned axis even when the tuned loop fails its check (stability, PM within 5 deg of "
                        "the target, gain-margin floor; model and verification sweep)")
    v.add_argument("--no-sweep", action="store_true", help="skip the measured sweep of the tuned loop")
    t.set_defaults(func=cmd_tune)

    i = sub.add_parser("identify", parents=[common], formatter_class=_Formatter,
                       help="fit a rigid or two-mass plant (Ceres) to the standard experiment or a CSV log",
                       description="Identifies the mechanics: `identify AXIS` runs the standard experiment on the "
                                   "described axis as a digital twin (servobench.run_experiment) and fits it; "
                                   "`identify --log LOG.csv` fits a recorded log. Writes <stem>_identified.json "
                                   "(estimates with standard errors), <stem>_identify_fit.<format> (fit and residual), "
                                   "<stem>_identified.<toml|json> (the axis file with the identified plant) and, for "
                                   "the twin, <stem>_identify_log.csv.\n\nLog CSV columns (header row; a ' [unit]' "
                                   "tag gives a column's unit -- mm, deg, mN*m, ... are converted, an unknown unit is "
                                   "an error; a .mat file needs --unit for each column):\n" + "\n".join(f"  {k:15s} {v}" for k, v in LOG_COLUMNS.items()))
    i.add_argument("axis", metavar="AXIS", nargs="?", default=None,
                   help="axis file: the twin to run the experiment on; with --log: drive, encoder and starting values")
    i.add_argument("--log", metavar="LOG.csv", default=None, help="fit this log instead of running the experiment")
    i.add_argument("--model", choices=["rigid", "two-mass", "two_mass"], default=None,
                   help="plant model (default: the axis file's plant type, else rigid)")
    i.add_argument("--guess", nargs="+", metavar="NAME=VALUE", action="extend",
                   help="starting value (SI) of a parameter to estimate; default: the axis file's non-zero plant "
                        "values")
    i.add_argument("--fixed", nargs="+", metavar="NAME", action="extend", help="parameters held at their guess")
    i.add_argument("--duration-s", type=float, default=5.0, help="experiment length, s")
    i.add_argument("--amplitude-v", type=float, default=0.1, help="PRBS injection amplitude at the DAC, V")
    i.add_argument("--seed", type=int, default=0, help="PRBS seed")
    i.add_argument("--torque-per-volt", "--command-gain", dest="torque_per_volt", type=float, default=None,
                   help="drive gain, N*m/V (N/V on a linear axis), for a command column in volts")
    i.add_argument("--time", dest="time_column", default=None, help="the log's time column (default time_s; a .mat file: t)")
    i.add_argument("--command", dest="command_column", default=None, help="the log's command column (default: torque_nm, force_n or volts)")
    i.add_argument("--measured", dest="measured_column", default=None, help="the log's measured column (default: position_pulse, "
                                                    "position_rad, position_m, speed_rad_s, ...)")
    i.add_argument("--reference", dest="reference_column", default=None, help="the log's position reference column (closed-loop records)")
    i.add_argument("--unit", nargs="+", metavar="COLUMN=UNIT", action="extend",
                   help="a column's unit when its header has no [unit] tag, e.g. qm=m vir=V")
    i.add_argument("--dynamics-hz", type=float, default=None,
                   help="the closed loop's dynamics frequency, Hz, for the IDIM start (default: from the log's "
                        "reference)")
    i.add_argument("--count-m", type=float, default=None, help="one encoder count, m (linear axes; default: "
                                                               "detected from the position's steps)")
    i.add_argument("--counts-per-rev", type=float, default=None, help="encoder counts/rev for pulse columns "
                                                                        "(default: the axis file's, else 10000)")
    i.add_argument("--current-bw-hz", type=float, default=None,
                   help="drive current-loop bandwidth, Hz (default: the axis file's, else ideal)")
    i.set_defaults(func=cmd_identify)

    d = sub.add_parser("demo", formatter_class=_Formatter,
                       help="the README's quick start: move, Bode sweep, identification and tuning on the reference axis",
                       description="Simulates a move on the reference axis (servobench.demo_axis), measures its loop, "
                                   "identifies its plant, tunes from the model and writes demo_response_<law>.png, "
                                   "demo_bode_<law>.png and demo_bode_tuned_<law>.png.")
    d.add_argument("--law", choices=["gt", "aps"], default="gt", help="servo law")
    d.add_argument("--out", default="out", metavar="DIR", help="folder for the plots")
    d.set_defaults(func=cmd_demo)
    return p


def main(argv=None) -> int:
    """Runs the command line; returns the exit code (0 done, 1 the work failed, 2 usage error or bad input)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    if not argv:
        parser.print_help()
        return EXIT_OK
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:  # --help, --version, usage errors (argparse printed them)
        return e.code if isinstance(e.code, int) else EXIT_USAGE
    if args.command is None:
        parser.print_help()
        return EXIT_USAGE
    from .axisfile import AxisFileError

    try:
        return args.func(args)
    except (AxisFileError, UsageError) as e:
        print(f"servobench: error: {e}", file=sys.stderr)
        return EXIT_USAGE
    except WorkFailed as e:
        print(f"servobench {args.command}: failed: {e}", file=sys.stderr)
        return EXIT_FAILED
    except (OSError, ValueError, RuntimeError) as e:  # an output that cannot be written, the library refusing
        print(f"servobench {args.command}: failed: {e}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print(f"servobench {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
