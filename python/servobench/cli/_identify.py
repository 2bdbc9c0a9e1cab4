"""`servobench identify`: a fit of the plant to a log file."""

from __future__ import annotations

import math
import os

import numpy as np

from .. import _core
from ._common import EXIT_OK, Output, UsageError, WorkFailed, _bad_input, _drive_mode, _fit_progress, _load, _stem


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
    from ..identify import model_parameters

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
    from .. import _core
    from ..axis import Axis
    from ..axisfile import save_axis
    from ..identify import IdentificationError, IdentificationLog, fit_time, model_parameters, run_experiment

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
            from ..axisfile import _suggest

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
