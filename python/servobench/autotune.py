"""Auto-tuning of the position loop (docs/autotune.md).

* :func:`relay_autotune`: the ADLINK card's relay experiment with hysteresis (manual L1764-1847), done right: the
  describing function of a relay *with* hysteresis, a PID designed for a phase margin on the card's own discrete law;
  Ziegler-Nichols and Tyreus-Luyben from the same experiment (:meth:`RelayTuneResult.rule`).
* :func:`model_based_tune`: a design from the axis's analytic plant (given or identified): the highest crossover
  whose whole loop keeps the target phase margin, a gain margin and a peak sensitivity, with a notch at the plant's
  resonance when it raises that crossover.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import _checks
from . import _core

__all__ = ["ModelTuneResult", "RelayTuneResult", "model_based_tune", "predicted_limit_cycle", "relay_autotune"]


@dataclass(frozen=True)
class RelayTuneResult:
    """The outcome of :func:`relay_autotune`.

    status, message
        ``"completed"`` or why it stopped (manual L1826-1831): ``"user_stop"``, ``"limit_or_alarm"`` (PEL/MEL,
        ALM), ``"deviation_exceeded"``, ``"spread_too_large"`` (fluctuation above 10 %), ``"no_oscillation"``.
    kp, ki, kd
        the mean per-tick gains (counts/pulse; ki per pulse*tick), the card law's units.
    kc, ti_s, td_s
        the same as a continuous PID kc (1 + 1/(ti s) + td s), kc in counts/pulse, times in s.
    kp_spread, ki_spread, kd_spread
        relative standard deviation of each gain over the sets (the manual's "fluctuation").
    ultimate_freq_hz, ultimate_gain_v_per_pulse
        mean identified point: 1/Tu and 4 d / (pi a).
    cycles
        per-cycle arrays: period_s, amplitude_pulse (fundamental of e), peak_pulse, center_pulse,
        gain_pulse_per_v and phase_deg (the describing-function point), kp, ki, kd.
    error_pulse, output_v
        the experiment's record per servo tick.
    """

    status: str
    message: str
    kp: float
    ki: float
    kd: float
    kc: float
    ti_s: float
    td_s: float
    kp_spread: float
    ki_spread: float
    kd_spread: float
    ultimate_freq_hz: float
    ultimate_gain_v_per_pulse: float
    sampling_time_s: float
    servo_period_s: float
    cycles: dict = field(repr=False)
    error_pulse: np.ndarray = field(repr=False)
    output_v: np.ndarray = field(repr=False)

    def gt_law(self, base=None):
        """The result as GT servo-filter gains (Kp, Ki with its /256, Kd; feed-forward 0), integers in 0..32767
        (ValueError naming the gain that does not fit)."""
        return _law(self, "gt", base)

    def aps_law(self, base=None):
        """The result as ADLINK gains: integers 0..65535 with per-term shifts chosen to keep the most digits
        (PID_SHIFT -5; feed-forward 0)."""
        return _law(self, "aps", base)

    def rule(self, name: str) -> "RelayTuneResult":
        """The same experiment's gains by a classic rule from the mean ultimate point (Ku = 4d/(pi a), Tu):
        ``"ziegler_nichols"`` (0.6 Ku, Tu/2, Tu/8) or ``"tyreus_luyben"`` (Ku/2.2, 2.2 Tu, Tu/6.3); ``"phase_margin"``
        is this result. Returns a copy with those gains (fluctuations and cycles kept)."""
        import dataclasses

        if name == "phase_margin":
            return self
        ku = self.ultimate_gain_v_per_pulse * 32767.0 / 10.0  # counts per pulse
        g = _core.classic_rule(name, ku, 1.0 / self.ultimate_freq_hz, self.servo_period_s)
        return dataclasses.replace(self, kp=g["kp"], ki=g["ki"], kd=g["kd"], kc=g["kc"], ti_s=g["ti_s"],
                                   td_s=g["td_s"], message=f"{name} rule from the same experiment")

    def apply(self, axis) -> None:
        """The manual's "Set final" (L1820): writes the gains to the axis's law, switches feed-forward and filters
        off, and turns the servo on."""
        law = self.gt_law(axis.law) if isinstance(axis.law, _core.GtServoLaw) else self.aps_law(axis.law)
        axis.set_law(law)
        axis.set_filters((None, None))
        axis.set_servo_on(True)


def _law(res, kind, base):
    if kind == "gt":
        base = base if isinstance(base, _core.GtServoLaw) else _core.GtServoLaw()
    else:
        base = base if isinstance(base, _core.ApsServoLaw) else _core.ApsServoLaw()
    return _core.pid_to_law(res.kp, res.ki, res.kd, base)


def relay_autotune(axis, *, amplitude_v: float = 1.0, hysteresis_pulse: float = 50.0, data_length: int = 200,
                   sampling_time_s: float = 500e-6, deviation_limit_pulse: float = 2000.0, max_spread: float = 0.10,
                   phase_margin_deg: float = 60.0, alpha: float = 4.0, settle_cycles: int = 3,
                   max_cycle_s: float = 10.0, progress=None) -> RelayTuneResult:
    """Relay auto-tuning on a simulated axis, with the ADLINK card's parameters and defaults (L1842-1847).

    amplitude_v
        relay output +-d, V (0 < d <= 10, default 1).
    hysteresis_pulse
        relay hysteresis eps on the position error, pulse (> 0, default 50).
    data_length
        gain sets (limit cycles) to compute, default 200.
    sampling_time_s
        relay sampling time, s (100..1000 us, default 500 us); rounded to whole servo ticks.
    deviation_limit_pulse
        ``|position error|`` above this stops the tuning, servo off, pulse (0 = off, default 2000).
    max_spread
        accepted relative standard deviation of each gain (the manual's 10 %).
    phase_margin_deg, alpha
        design target (deg, 10..89, default 60) and Ti = alpha * Td (default 4).
    settle_cycles
        first limit cycles discarded; max_cycle_s: give up when no cycle completes within this time, s.
    progress
        None, True (text bar on stderr) or callable(done, total) -> bool (False: the user's Stop).

    The servo law is replaced by the relay during the experiment and the servo is left off at the end (apply the
    result with :meth:`RelayTuneResult.apply`). A relay with hysteresis needs a plant whose phase lies above -180
    deg somewhere: a velocity-mode drive (an integrating plant), as the manual's procedure assumes; a lightly
    damped torque-mode axis (a double integrator) has no steady limit cycle and ends with a clear status.
    Releases the GIL; deterministic.
    """
    from .frequency import _progress_callback

    d = _core.relay_autotune(getattr(axis, "_axis", axis), amplitude_v=float(amplitude_v),
                             hysteresis_pulse=float(hysteresis_pulse), data_length=float(data_length),
                             sampling_time_s=float(sampling_time_s), deviation_limit_pulse=float(deviation_limit_pulse),
                             max_spread=float(max_spread), phase_margin_deg=float(phase_margin_deg),
                             alpha=float(alpha), settle_cycles=float(settle_cycles), max_cycle_s=float(max_cycle_s),
                             progress=_progress_callback(progress, "Relay tuning"))
    m = d["mean"]
    cycles = {k: d[k] for k in ("period_s", "amplitude_pulse", "peak_pulse", "center_pulse", "gain_pulse_per_v",
                                "phase_deg", "kp", "ki", "kd")}
    return RelayTuneResult(status=d["status"], message=d["message"], kp=m["kp"], ki=m["ki"], kd=m["kd"],
                           kc=m["kc"], ti_s=m["ti_s"], td_s=m["td_s"], kp_spread=d["kp_spread"],
                           ki_spread=d["ki_spread"], kd_spread=d["kd_spread"],
                           ultimate_freq_hz=d["ultimate_freq_hz"],
                           ultimate_gain_v_per_pulse=d["ultimate_gain_v_per_pulse"],
                           sampling_time_s=d["sampling_time_s"], servo_period_s=axis.servo_period_s, cycles=cycles,
                           error_pulse=d["error_pulse"], output_v=d["output_v"])


def predicted_limit_cycle(axis, *, amplitude_v: float = 1.0, hysteresis_pulse: float = 50.0,
                          sampling_time_s: float = 500e-6) -> dict:
    """The limit cycle the describing function predicts for the relay experiment on this axis, computed from the
    analytic plant (the same lifted model as :func:`servobench.frequency.analytic_response`): the frequency wu where
    angle P(j wu) = -180 deg + asin(eps / a) with a = (4 d / pi) ``|P(j wu)|``. P is the plant from the relay's volts to
    the encoder with the one-tick delay, shifted by the sampled relay's mean switching delay (docs/decisions.md R4).

    Returns {"freq_hz", "amplitude_pulse", "ultimate_gain_v_per_pulse" (= 1/``|P|``)}; ValueError if the plant's phase
    never reaches the needed value (no limit cycle: e.g. an undamped double integrator with hysteresis).
    """
    from .frequency import analytic_response

    ts = axis.servo_period_s
    tr = max(1, round(sampling_time_s / ts)) * ts
    d, eps = float(amplitude_v), float(hysteresis_pulse)
    law = axis.law
    sign = -1.0 if isinstance(law, _core.ApsServoLaw) and law.v_inverse else 1.0

    def point(f):
        f = np.atleast_1d(np.asarray(f, dtype=float))
        p = analytic_response(axis, f).plant * (32767.0 / 10.0) * sign  # pulse per volt
        return p * np.exp(-1j * 2 * np.pi * f * (tr - ts) / 2)

    def mismatch(f):
        p = point(f)
        a = 4 * d / np.pi * np.abs(p)
        with np.errstate(invalid="ignore"):
            want = -np.pi + np.arcsin(np.clip(eps / a, -1.0, 1.0))
        m = np.angle(p * np.exp(-1j * want))  # angle P - want, wrapped to (-pi, pi]
        m[a <= eps] = np.nan
        return m

    f = np.geomspace(0.1, 0.45 / ts, 20000)
    m = mismatch(f)
    ok = np.isfinite(m[:-1]) & np.isfinite(m[1:]) & (m[:-1] > 0) & (m[1:] <= 0) & (np.abs(m[:-1] - m[1:]) < 1)
    idx = np.nonzero(ok)[0]
    if not idx.size:
        raise ValueError("the plant's phase never reaches -180 deg + asin(eps/a): the describing function predicts "
                         "no limit cycle for this relay (a velocity-mode drive gives an integrating plant that has one)")
    lo, hi = f[idx[0]], f[idx[0] + 1]
    for _ in range(60):
        mid = np.sqrt(lo * hi)
        (lo, hi) = (mid, hi) if mismatch(mid)[0] > 0 else (lo, mid)
    fu = np.sqrt(lo * hi)
    p = point(fu)[0]
    return {"freq_hz": float(fu), "amplitude_pulse": float(4 * d / np.pi * abs(p)),
            "ultimate_gain_v_per_pulse": float(1 / abs(p))}


@dataclass(frozen=True)
class ModelTuneResult:
    """The outcome of :func:`model_based_tune`; ``str(result)`` is its summary.

    kp, ki, kd
        per-tick gains (counts/pulse; ki per pulse*tick), as designed (before the card's integers).
    kc, ti_s, td_s
        the same as a continuous PID kc (1 + 1/(ti s) + td s), kc in counts/pulse, times in s (ti = alpha td).
    crossover_hz
        the design crossover chosen, Hz.
    margins
        :class:`servobench.frequency.Margins` of the analytic loop with the card law's integers and the filters
        (phase margin at the crossover, gain margin, Ms, bandwidth): what :meth:`apply` will give.
    max_pole_radius
        the closed loop's largest pole magnitude ``|z|`` (< 1: stable).
    law, filters
        the card law (integers, feed-forward 0) and the two biquads (notch or pass-through; pass-through) that
        :meth:`apply` writes.
    resonances
        peaks found in the plant response: list of {"freq_hz", "prominence_db", "width_decades"}.
    resonance_hz, resonance_prominence_db
        the resonance notched (or the most prominent one found; 0 when none).
    notch
        {"used", "center_hz", "q", "low_hz", "high_hz" (the -3 dB edges), "depth_db" (attenuation at the resonance
        of the biquad run), "phase_at_crossover_deg", "float_biquad", "adlink_biquad" (the card's integers)}.
    crossover_without_notch_hz
        the best crossover with no notch (0: none meets the bounds), Hz.
    limited_by
        what failed just above the chosen crossover.
    scan
        the chosen filter option's crossover candidates: arrays freq_hz, phase_margin_deg, pm_freq_hz,
        gain_margin_db, ms, max_pole_radius, pid_lead_deg, feasible, and the list reason.
    summary
        the self-explaining report.
    """

    kp: float
    ki: float
    kd: float
    kc: float
    ti_s: float
    td_s: float
    crossover_hz: float
    margins: object
    max_pole_radius: float
    law: object
    filters: tuple
    resonances: list
    resonance_hz: float
    resonance_prominence_db: float
    notch: dict
    crossover_without_notch_hz: float
    limited_by: str
    servo_period_s: float
    scan: dict = field(repr=False)
    summary: str = field(repr=False)

    def __str__(self) -> str:
        return self.summary

    def gt_law(self, base=None):
        """The gains as GT servo-filter gains (Kp, Ki with its /256, Kd; feed-forward 0), integers in 0..32767."""
        return _law(self, "gt", base)

    def aps_law(self, base=None):
        """The gains as ADLINK gains: integers 0..65535 with per-term shifts (PID_SHIFT -5; feed-forward 0)."""
        return _law(self, "aps", base)

    def apply(self, axis) -> None:
        """Writes the gains to the axis's law (its own kind: GT or ADLINK, feed-forward 0), the notch to biquad 0
        and pass-through to biquad 1, and turns the servo on."""
        law = self.gt_law(axis.law) if isinstance(axis.law, _core.GtServoLaw) else self.aps_law(axis.law)
        axis.set_law(law)
        axis.set_filters(self.filters)
        axis.set_servo_on(True)


def model_based_tune(axis, *, phase_margin_deg: float = 60.0, alpha: float = 4.0, notch: bool = True,
                     min_gain_margin_db: float = 10.0, max_ms: float = 2.0, max_pid_lead_deg: float = 70.0,
                     pm_tolerance_deg: float = 2.0, resonance_hz: float | None = None,
                     min_resonance_prominence_db: float = 6.0, notch_q=(0.5, 0.7, 1.0, 1.4, 2.0, 3.0, 5.0),
                     min_crossover_hz: float = 1.0, max_crossover_hz: float | None = None, candidates: int = 60,
                     points: int = 4000, law: str | None = None) -> ModelTuneResult:
    """A PID (Ti = alpha Td) and a notch designed from the axis's analytic plant: the highest crossover at which the
    whole loop keeps the phase margin, the gain margin and the peak sensitivity asked for (docs/autotune.md).

    The plant is the axis's own (output stage, one-tick delay, drive and mechanics lifted to the servo rate: the
    model of :func:`servobench.frequency.analytic_response`), so any plant the axis runs is designed for, an
    identified one included. Nothing is run on the axis; :meth:`ModelTuneResult.apply` writes the result.

    phase_margin_deg, pm_tolerance_deg
        target phase margin (deg, 10..89) and the accepted deviation over all gain crossovers of the loop
        (deg, 0.1..20).
    alpha
        Ti = alpha * Td (1..100).
    min_gain_margin_db, max_ms
        bounds on the loop's upper gain margin (dB, 0..60) and peak sensitivity (1.05..10).
    max_pid_lead_deg
        largest phase the PID may add at the crossover (deg, 5..89); bounds Td so the PID's zeros stay within
        a factor tan((lead + 90)/2) below the crossover (5.7 at 70 deg): no slowly creeping closed-loop mode.
    notch, resonance_hz, min_resonance_prominence_db, notch_q
        try a notch (pre-warped, in biquad 0; the card's integers on an ADLINK law) at the plant's resonance: the
        given `resonance_hz` (Hz) or each of the up to 3 most prominent peaks of the plant's gain above a -40
        dB/decade line by at least `min_resonance_prominence_db` (dB); each q of `notch_q` is tried. A notch is
        kept only when it raises the crossover.
    min_crossover_hz, max_crossover_hz, candidates
        the crossover scan: `candidates` log-spaced frequencies (Hz) from min to max (None: 0.45/Ts); the highest
        feasible one is taken and the boundary to the candidate above it bisected.
    points
        log-spaced frequencies of the band the loop is checked over (0.1 Hz or lower .. Nyquist).
    law
        None (the axis's law), ``"gt"`` or ``"aps"``: the card law whose integers the design is checked with.

    Raises ValueError for a pulse-input axis (no position loop on the card), a parameter outside its range (named),
    or when no crossover meets the bounds (the message names the bounds to relax and the nearest miss).
    Releases the GIL; about 0.1-0.5 s.
    """
    from .frequency import Margins

    if resonance_hz is not None and float(resonance_hz) == 0.0:
        raise ValueError("model_based_tune.resonance_hz = 0 is outside the allowed range 0 < f < Nyquist; "
                         "use None to find it in the plant response")
    d = _core.model_tune(getattr(axis, "_axis", axis), phase_margin_deg=float(phase_margin_deg), alpha=float(alpha),
                         pm_tolerance_deg=float(pm_tolerance_deg), min_gain_margin_db=float(min_gain_margin_db),
                         max_ms=float(max_ms), max_pid_lead_deg=float(max_pid_lead_deg), notch=_checks.flag("model_based_tune", "notch", notch),
                         resonance_hz=0.0 if resonance_hz is None else float(resonance_hz),
                         min_resonance_prominence_db=float(min_resonance_prominence_db),
                         notch_q_set=[float(q) for q in np.atleast_1d(notch_q)],
                         min_crossover_hz=float(min_crossover_hz),
                         max_crossover_hz=0.0 if max_crossover_hz is None else float(max_crossover_hz),
                         candidates=float(candidates), points=float(points), law="axis" if law is None else str(law))
    p = d["pid"]
    return ModelTuneResult(kp=p["kp"], ki=p["ki"], kd=p["kd"], kc=p["kc"], ti_s=p["ti_s"], td_s=p["td_s"],
                           crossover_hz=d["crossover_hz"], margins=Margins(**d["margins"]),
                           max_pole_radius=d["max_pole_radius"], law=d["law"], filters=tuple(d["filters"]),
                           resonances=list(d["resonances"]), resonance_hz=d["resonance_hz"],
                           resonance_prominence_db=d["resonance_prominence_db"], notch=dict(d["notch"]),
                           crossover_without_notch_hz=d["crossover_without_notch_hz"], limited_by=d["limited_by"],
                           servo_period_s=axis.servo_period_s,
                           scan={k: (list(v) if k == "reason" else np.asarray(v)) for k, v in d["scan"].items()},
                           summary=d["summary"])
