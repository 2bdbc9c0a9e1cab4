"""`servobench bode`: the stepped-sine sweep, the analytic loop beside it, margins."""

from __future__ import annotations

import numpy as np

from ._common import (EXIT_OK, Output, WorkFailed, _bad_input, _load, _margins_dict, _need_voltage_output,
    _progress, _stem)


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
    from .. import frequency as fr
    from ..agreement import model_agreement
    from ..plot import bode

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
        from ..frequency import Margins

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
