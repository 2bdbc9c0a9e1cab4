"""The check a tuning result must pass before it is applied (issue 20 point 4: tuning refuses what it cannot stand
behind).

The designed loop (the axis with the new law and filters) is checked twice:

1. on the linear model: closed-loop poles inside the unit circle, the phase margin (the gain crossover nearest to
   -1) within ``target +- pm_tolerance_deg`` and no other crossover nearer to -1 than ``target - pm_tolerance_deg``
   (when the design had a target), the gain margin >= ``min_gain_margin_db``;
2. by a verification sweep on a copy of the axis (the stepped sine with its automatic amplitude, over the band
   from a tenth of the model's crossover to 1.5 times its phase crossover): the Nyquist verdict on the measured
   points must be "stable", the measured phase margin within the same band of the target and, where the sweep
   could read one, the measured gain margin above the floor. A sweep that cannot give a margin refuses.

:meth:`RelayTuneResult.apply` and :meth:`ModelTuneResult.apply` run it and raise :class:`TuningRefused` (with the
report) when it fails, unless ``force=True``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._serialise import JsonResult

__all__ = ["designed_axis", "TuneCheck", "TuningRefused", "check_design"]


@dataclass(frozen=True)
class TuneCheck(JsonResult):
    """The outcome of :func:`check_design`: ``accepted``, the ``failures`` (empty when accepted), the model's and
    the verification sweep's margins (``model``, ``measured``: :class:`servobench.frequency.Margins`; measured None
    when not swept or no margin could be read, with ``measured_note``), and the bounds checked."""

    accepted: bool
    failures: list
    model: object
    measured: object
    measured_note: str
    target_phase_margin_deg: float | None
    pm_tolerance_deg: float
    min_gain_margin_db: float
    sweep: object = field(default=None, repr=False)

    def __str__(self) -> str:
        head = "tuning check: ACCEPTED" if self.accepted else "tuning check: REFUSED"
        lines = [head]
        lines += [f"  - {f}" for f in self.failures]
        target = ("no phase-margin target (a classic rule)" if self.target_phase_margin_deg is None else
                  f"PM {self.target_phase_margin_deg:g} +- {self.pm_tolerance_deg:g} deg")
        lines.append(f"  bounds: stable, {target}, GM >= {self.min_gain_margin_db:g} dB")
        lines.append("  model: " + str(self.model).replace("\n", "\n    "))
        if self.measured is not None:
            lines.append("  verification sweep: " + str(self.measured).replace("\n", "\n    "))
        elif self.measured_note:
            lines.append(f"  verification sweep: {self.measured_note}")
        return "\n".join(lines)


class TuningRefused(ValueError):
    """A tuning result failed its check; ``.check`` is the :class:`TuneCheck` (``str`` it for the report). Apply it
    anyway with ``force=True``."""

    def __init__(self, check: TuneCheck):
        super().__init__("the tuned loop fails its check, not applied (force=True applies it anyway):\n" + str(check))
        self.check = check


def designed_axis(axis, law, filters):
    """A fresh copy of `axis` (same drive, plant, encoder, DAC, switches, period) with `law` and `filters`."""
    from .axis import Axis

    return Axis(law=law, drive=axis.drive, plant=axis.plant, encoder=axis.encoder, dac=axis.dac,
                switches=axis.switches, servo_period_s=axis.servo_period_s, substeps=axis.substeps,
                filters=filters)


def _pm_failures(m, target, tol, where):
    out = []
    if target is None:
        return out
    pms = np.asarray(m.gain_crossovers.get("phase_margin_deg", []), dtype=float)
    if pms.size == 0:
        return [f"{where}: the loop gain does not cross 0 dB, no phase margin"]
    if abs(m.phase_margin_deg - target) > tol:
        out.append(f"{where}: phase margin {m.phase_margin_deg:.1f} deg at {m.pm_freq_hz:.4g} Hz is outside "
                   f"{target:g} +- {tol:g} deg")
    for f, pm in zip(m.gain_crossovers["freq_hz"], pms):  # no other crossover nearer to -1
        if abs(pm) < target - tol and f != m.pm_freq_hz:
            out.append(f"{where}: the gain crossover at {f:.4g} Hz has only {pm:.1f} deg of phase margin")
    return out


def check_design(axis, law, filters, *, target_phase_margin_deg: float | None, pm_tolerance_deg: float = 5.0,
                 min_gain_margin_db: float = 6.0, verify: bool = True, sweep_points: int = 40) -> TuneCheck:
    """Checks the loop `axis` would have with `law` and `filters` (see the module doc). target_phase_margin_deg:
    deg or None (no target: a classic rule); pm_tolerance_deg: deg (> 0); min_gain_margin_db: dB; verify: run the
    verification sweep (on a copy; `axis` is not touched); sweep_points: its number of frequencies (>= 5)."""
    from . import frequency as fr

    if not pm_tolerance_deg > 0:
        raise ValueError(f"pm_tolerance_deg = {pm_tolerance_deg} must be > 0 deg")
    if int(sweep_points) < 5:
        raise ValueError(f"sweep_points = {sweep_points} must be >= 5")
    trial = designed_axis(axis, law, filters)
    model = fr.analytic_margins(trial)
    failures = []
    if not model.stable:
        failures.append(f"model: {model.stability['reason']}")
    failures += _pm_failures(model, target_phase_margin_deg, pm_tolerance_deg, "model")
    if model.stable and model.gain_margin_db < min_gain_margin_db:
        failures.append(f"model: gain margin {model.gain_margin_db:.1f} dB at {model.gm_freq_hz:.4g} Hz is below "
                        f"{min_gain_margin_db:g} dB")
    measured, note, sweep = None, "", None
    if verify and model.stable and np.isfinite(model.pm_freq_hz):
        ts = trial.servo_period_s
        lo = max(model.pm_freq_hz / 10, 1.0)
        hi_want = model.gm_freq_hz * 1.5 if np.isfinite(model.gm_freq_hz) else model.pm_freq_hz * 10
        hi = min(max(hi_want, model.pm_freq_hz * 3), 0.45 / ts)
        update = max(0.05, 2.0 / lo)
        sweep = fr.sine_sweep(trial, start_hz=lo, end_hz=hi, points=int(sweep_points), update_s=update)
        try:
            measured = sweep.margins()
        except ValueError as e:
            note = str(e)
            failures.append(f"verification sweep: {e}")
        if measured is not None:
            if not measured.stable:
                failures.append(f"verification sweep: {measured.verdict}: {measured.stability.get('reason', '')}")
            failures += _pm_failures(measured, target_phase_margin_deg, pm_tolerance_deg, "verification sweep")
            if np.isfinite(measured.gain_margin_db):
                if measured.gain_margin_db < min_gain_margin_db:
                    failures.append(f"verification sweep: gain margin {measured.gain_margin_db:.1f} dB at "
                                    f"{measured.gm_freq_hz:.4g} Hz is below {min_gain_margin_db:g} dB")
            else:
                note = (f"the sweep ({lo:.4g}-{hi:.4g} Hz) read no phase crossover among its usable points; the gain "
                        "margin rests on the model")
        if sweep.status != "completed":
            failures.append(f"verification sweep ended early: {sweep.status} ({sweep.message})")
    elif verify:
        note = "not swept: the model's loop is unstable or does not cross 0 dB"
    return TuneCheck(accepted=not failures, failures=failures, model=model, measured=measured, measured_note=note,
                     target_phase_margin_deg=target_phase_margin_deg, pm_tolerance_deg=float(pm_tolerance_deg),
                     min_gain_margin_db=float(min_gain_margin_db), sweep=sweep)
