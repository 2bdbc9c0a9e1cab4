"""`servobench tune`: relay or model-based tuning, checked, and the tuned axis file."""

from __future__ import annotations

import os

import numpy as np

from .. import _core
from ._common import (EXIT_OK, Output, UsageError, WorkFailed, _bad_input, _drive_mode, _linearity_note, _load,
    _margins_dict, _need_voltage_output, _progress, _stem)


# ----------------------------------------------------------------------------------------------------------------
# tune
# ----------------------------------------------------------------------------------------------------------------
def _step_run(axis, step_pulse, ticks):
    cmd = np.full(ticks, float(step_pulse))
    cmd[:50] = 0.0
    return axis.run(cmd, signals=["time_s", "cmd_pos", "fb_pos", "volts"])


def cmd_tune(args) -> int:
    from .. import _core
    from .. import frequency as fr
    from ..autotune import model_based_tune, relay_autotune
    from ..axisfile import save_axis
    from ..frequency import Margins
    from ..plot import _pyplot, bode

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
    from ..tune_check import TuningRefused

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
        from ..agreement import model_agreement

        report["after"]["model_agreement"] = model_agreement(swept, meas)["summary"] if len(meas) else ""
        lin = _linearity_note(swept, mm, report["after"]["analytic_margins"], args.amplitude_pulse)
        report["after"]["linearity_note"] = lin
        if len(meas) >= 2:
            curves["after, measured (stepped sine)"] = meas
        if not args.quiet and mm is not None:
            from ..frequency import Margins

            print("tuned loop, measured with the stepped-sine sweep:\n  " + str(Margins(**mm)).replace("\n", "\n  "))
            if lin:
                print("  note: " + lin)
    # step response before and after
    ticks = args.step_ticks
    r0 = _step_run(before, args.step_pulse, ticks)
    r1 = _step_run(after, args.step_pulse, ticks)
    from ..metrics import move_metrics

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
