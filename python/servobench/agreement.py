"""How far a measured frequency response agrees with the axis's linear model, and where that model applies
(issue 20: the README's ``servobench bode`` must agree with the model within 1 dB / 5 deg wherever the model
applies, and say where it does not).

The linear model (:func:`servobench.frequency.analytic_response`) leaves out friction, saturation and
quantisation. Saturation and quantisation are judged per point by the sweep itself (``FrequencyResponse.flags``).
Friction is judged here: Coulomb (or static) friction of level Fc acting on a sinusoidal motion adds a square wave
of torque whose fundamental is 4 Fc / pi (its describing function), so at a point where the drive's torque
fundamental is T the linear model is off by about (4 Fc / pi) / T. Where that share exceeds `friction_share`
(default 0.05: an error of about 0.4 dB / 3 deg, well inside 1 dB / 5 deg) the point is marked "model does not
apply (friction)".
"""

from __future__ import annotations

import numpy as np

__all__ = ["friction_level_nm", "model_agreement"]

_FRICTION_FIELDS = ("coulomb_nm", "static_nm", "motor_coulomb_nm", "motor_static_nm", "load_coulomb_nm",
                    "load_static_nm")


def _kind(reason: str) -> str:
    """The family of a point's flag: "encoder quantisation", "coherence", "DAC saturated", "friction", ..."""
    if "(" in reason and reason.startswith("|"):
        return reason[reason.index("(") + 1:reason.rindex(")")]
    for key in ("friction", "coherence", "distortion", "DAC saturated", "current command", "torque", "no response"):
        if reason.startswith(key):
            return key
    return reason.split(" ")[0]


def friction_level_nm(plant) -> float:
    """The largest dry-friction level of the plant, N*m: max(coulomb, static) on the motor side plus that of the load
    side (0 for a friction-free plant)."""
    def g(name):
        return float(getattr(plant, name, 0.0) or 0.0)

    motor = max(g("coulomb_nm"), g("static_nm"), g("motor_coulomb_nm"), g("motor_static_nm"))
    load = max(g("load_coulomb_nm"), g("load_static_nm"))
    return motor + load


def model_agreement(axis, measured, which: str = "open_loop", *, tolerance_db: float = 1.0,
                    tolerance_deg: float = 5.0, friction_share: float = 0.05) -> dict:
    """Compares a measured :class:`~servobench.frequency.FrequencyResponse` (stepped sine) of `axis` with the
    axis's analytic response at the same frequencies.

    which
        the response compared: "plant", "open_loop" or "closed_loop".
    tolerance_db, tolerance_deg
        the agreement asked for where the model applies (dB, deg; > 0).
    friction_share
        the share (4 Fc / pi) / T above which friction makes the linear model inapplicable at a point (0..1).

    Returns a dict: ``freq_hz``, ``gain_error_db``, ``phase_error_deg`` (measured minus model, per point),
    ``model_applies`` (bool per point), ``why_not`` (per point: "" or the reasons: the sweep's own flag, friction
    share), ``max_gain_error_db`` and ``max_phase_error_deg`` over the points where the model applies (None if
    none), ``agrees`` (both within tolerance), ``not_applicable_hz`` (ranges [lo, hi] of consecutive points where
    the model does not apply) and ``summary`` (one sentence).
    """
    from .frequency import analytic_response

    for name, v in (("tolerance_db", tolerance_db), ("tolerance_deg", tolerance_deg)):
        if not (np.isfinite(v) and v > 0):
            raise ValueError(f"model_agreement.{name} = {v} must be finite and > 0")
    if not (0 < friction_share <= 1):
        raise ValueError(f"model_agreement.friction_share = {friction_share} must be in (0, 1]")
    f = np.asarray(measured.freq_hz, dtype=float)
    if f.size == 0:
        raise ValueError("model_agreement: the measurement has no points")
    model = analytic_response(axis, f, feedforward=measured.feedforward, filters=measured.filters)
    h_m, h_a = np.asarray(measured.response(which)), np.asarray(model.response(which))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = h_m / h_a
        gain_err = 20 * np.log10(np.abs(ratio))
        phase_err = np.degrees(np.angle(ratio))
    flags = list(measured.flags) if measured.flags is not None else [""] * f.size
    fc = friction_level_nm(axis.plant)
    torque = np.asarray(measured.signals.get("torque_amplitude_nm", np.full(f.size, np.nan)), dtype=float)
    why = []
    for i in range(f.size):
        reasons = [flags[i]] if flags[i] else []
        if not np.isfinite(gain_err[i]) or not np.isfinite(phase_err[i]):
            reasons.append("no response")
        if fc > 0:
            share = (4 * fc / np.pi) / torque[i] if torque[i] > 0 else np.inf
            if share > friction_share:
                reasons.append(f"friction: (4 Fc/pi) / torque = {share:.3g} > {friction_share:g}")
        why.append("; ".join(reasons))
    applies = np.array([not w for w in why], dtype=bool)
    max_g = float(np.max(np.abs(gain_err[applies]))) if applies.any() else None
    max_p = float(np.max(np.abs(phase_err[applies]))) if applies.any() else None
    agrees = applies.any() and max_g <= tolerance_db and max_p <= tolerance_deg
    ranges, start = [], None
    for i in range(f.size + 1):
        bad = i < f.size and not applies[i]
        if bad and start is None:
            start = i
        elif not bad and start is not None:
            ranges.append([float(f[start]), float(f[i - 1])])
            start = None
    if applies.any():
        summary = (f"{which.replace('_', ' ')}: measured vs model within {max_g:.2f} dB / {max_p:.2f} deg over the "
                   f"{int(applies.sum())} of {f.size} points where the model applies "
                   f"({'within' if agrees else 'OUTSIDE'} {tolerance_db:g} dB / {tolerance_deg:g} deg)")
    else:
        summary = f"{which.replace('_', ' ')}: the linear model applies at none of the {f.size} points"
    if ranges:
        kinds = sorted({_kind(r) for w in why for r in w.split("; ") if r})
        summary += ("; it does not apply at " + ", ".join(f"{lo:.4g}-{hi:.4g} Hz" if hi > lo else f"{lo:.4g} Hz"
                                                         for lo, hi in ranges) + f" ({', '.join(kinds)})")
    return {"freq_hz": f, "gain_error_db": gain_err, "phase_error_deg": phase_err, "model_applies": applies,
            "why_not": why, "max_gain_error_db": max_g, "max_phase_error_deg": max_p, "agrees": bool(agrees),
            "not_applicable_hz": ranges, "summary": summary}
