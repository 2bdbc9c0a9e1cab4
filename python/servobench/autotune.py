"""Auto-tuning of the position loop (docs/autotune.md).

* :func:`relay_autotune`: the ADLINK card's relay experiment with hysteresis (manual L1764-1847), done right: the
  describing function of a relay *with* hysteresis, a PID designed for a phase margin on the card's own discrete law;
  Ziegler-Nichols and Tyreus-Luyben from the same experiment (:meth:`RelayTuneResult.rule`).
* :func:`model_based_tune`: a design from the axis's analytic plant (given or identified): the highest crossover
  whose whole loop keeps the target phase margin, a gain margin and a peak sensitivity, with a notch at the plant's
  resonance when it raises that crossover.
"""

from __future__ import annotations

from dataclasses import field
from typing import TYPE_CHECKING

import numpy as np

from . import _checks
from ._serialise import JsonResult, dataframe
from . import _core
from . import _options as _opts

__all__ = ["ModelTuneResult", "RelayTuneResult", "model_based_tune", "predicted_limit_cycle", "relay_autotune"]


@_opts.described_result(_core.RELAY_TUNE_FIELDS, lead=("status", "message"))
class RelayTuneResult(JsonResult):
    """The outcome of :func:`relay_autotune`.

    status, message
        ``"completed"`` or why it stopped (manual L1826-1831): ``"user_stop"``, ``"limit_or_alarm"`` (PEL/MEL,
        ALM), ``"deviation_exceeded"``, ``"spread_too_large"`` (fluctuation above 10 %), ``"no_oscillation"``.
    {fields}
    servo_period_s
        the axis's servo period, s.
    cycles
        per-cycle arrays: period_s, amplitude_pulse (fundamental of e), peak_pulse, center_pulse,
        gain_pulse_per_v and phase_deg (the describing-function point), kp, ki, kd.
    error_pulse, output_v
        the experiment's record per servo tick.
    phase_margin_deg, min_gain_margin_db
        the design target (deg; None for a classic rule's gains) and the gain-margin floor (dB) that :meth:`apply`
        checks the tuned loop against.
    """

    status: str
    message: str
    # The single figures (kp ... sampling_time_s) follow, read at import from tuning::RelayTuneResult::describe()
    # with their units and docs; static type checkers read these names (test_options_once checks they match).
    if TYPE_CHECKING:
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
    phase_margin_deg: float | None = None
    min_gain_margin_db: float = 6.0

    def to_dataframe(self, which: str = "cycles"):
        """A pandas DataFrame: ``"cycles"`` (default) one row per identified limit cycle (period_s, amplitude_pulse,
        peak_pulse, center_pulse, gain_pulse_per_v, phase_deg and the gains kp, ki, kd of that cycle), or
        ``"record"`` the experiment's record per servo tick (time_s, error_pulse, output_v).
        ``df.attrs["units"]`` names each unit."""
        if which == "cycles":
            units = {"period_s": "s", "amplitude_pulse": "pulse", "peak_pulse": "pulse", "center_pulse": "pulse",
                     "gain_pulse_per_v": "pulse/V", "phase_deg": "deg", "kp": "counts/pulse",
                     "ki": "counts/(pulse*tick)", "kd": "counts*tick/pulse"}
            df = dataframe(dict(self.cycles), units)
            df.index.name = "cycle"
            return df
        if which == "record":
            n = len(self.error_pulse)
            return dataframe({"time_s": np.arange(n) * self.servo_period_s, "error_pulse": self.error_pulse,
                              "output_v": self.output_v}, {"time_s": "s", "error_pulse": "pulse", "output_v": "V"})
        raise ValueError(f"to_dataframe: which = {which!r} must be 'cycles' or 'record'")

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
        pid = {f["name"]: g[f["name"]] for f in _core.PID_DESIGN_FIELDS}  # kc ... kd (tuning::PidDesign, OR1)
        return dataclasses.replace(self, **pid, message=f"{name} rule from the same experiment",
                                   phase_margin_deg=None)

    def apply(self, axis, *, force: bool = False, verify: bool = True, pm_tolerance_deg: float = 5.0,
              min_gain_margin_db: float | None = None):
        """The manual's "Set final" (L1820), checked first: writes the gains to the axis's law, switches
        feed-forward and filters off, and turns the servo on, but only when the tuned loop passes
        :func:`servobench.tune_check.check_design` (closed-loop poles, phase margin within ``pm_tolerance_deg`` deg
        of the design target, gain margin >= ``min_gain_margin_db`` dB (default: this result's floor, 6 dB), on the
        model and by a verification sweep when `verify`). Raises :class:`servobench.tune_check.TuningRefused` with
        the report otherwise; ``force=True`` applies anyway. Returns the :class:`~servobench.tune_check.TuneCheck`."""
        from .tune_check import TuningRefused, check_design

        if self.status != "completed":
            raise ValueError(f"relay tuning did not complete ({self.status}: {self.message}): nothing to apply")
        law = self.gt_law(axis.law) if isinstance(axis.law, _core.GtServoLaw) else self.aps_law(axis.law)
        floor = self.min_gain_margin_db if min_gain_margin_db is None else float(min_gain_margin_db)
        check = check_design(axis, law, (None, None), target_phase_margin_deg=self.phase_margin_deg,
                             pm_tolerance_deg=pm_tolerance_deg, min_gain_margin_db=floor, verify=verify)
        if not check.accepted and not force:
            raise TuningRefused(check)
        axis.set_law(law)
        axis.set_filters((None, None))
        axis.set_servo_on(True)
        return check


def _law(res, kind, base):
    if kind == "gt":
        base = base if isinstance(base, _core.GtServoLaw) else _core.GtServoLaw()
    else:
        base = base if isinstance(base, _core.ApsServoLaw) else _core.ApsServoLaw()
    return _core.pid_to_law(res.kp, res.ki, res.kd, base)


@_opts.takes_options(_core.RelayTuneOptions, name="relay_autotune")
def _relay_autotune(axis, *, progress="auto", min_gain_margin_db: float = 6.0, **options) -> RelayTuneResult:
    """Relay auto-tuning on a simulated axis, with the ADLINK card's parameters and defaults (L1842-1847).

    {options}
    progress
        ``"auto"`` (default: a tqdm bar when stderr is a terminal), True (a bar: a widget in Jupyter), None/False
        (none) or callable(done, total) -> bool (False: the user's Stop).
    min_gain_margin_db
        the gain-margin floor (dB, 0..60, default 6) :meth:`RelayTuneResult.apply` checks the tuned loop against.

    The options, their defaults, units and ranges are those of :class:`servobench._core.RelayTuneOptions`
    (tuning/relay_autotune.hpp), read from it. The servo law is replaced by the relay during the experiment and the
    servo is left off at the end (apply the result with :meth:`RelayTuneResult.apply`). A relay with hysteresis
    needs a plant whose phase lies above -180 deg somewhere: a velocity-mode drive (an integrating plant), as the
    manual's procedure assumes; a lightly damped torque-mode axis (a double integrator) has no steady limit cycle
    and ends with a clear status. Releases the GIL; deterministic.
    """
    from .frequency import _progress_callback

    if not (0 <= float(min_gain_margin_db) <= 60):
        raise ValueError(f"relay_autotune.min_gain_margin_db = {min_gain_margin_db} is outside the allowed range 0..60 dB")
    o = _opts.cpp_options(_core.RelayTuneOptions, options)
    d = _core.relay_autotune(getattr(axis, "_axis", axis), o, _progress_callback(progress, "Relay tuning"))
    cycles = {k: d[k] for k in ("period_s", "amplitude_pulse", "peak_pulse", "center_pulse", "gain_pulse_per_v",
                                "phase_deg", "kp", "ki", "kd")}
    return RelayTuneResult(status=d["status"], message=d["message"], **d["figures"],
                           servo_period_s=axis.servo_period_s, cycles=cycles,
                           error_pulse=d["error_pulse"], output_v=d["output_v"],
                           phase_margin_deg=float(o.phase_margin_deg), min_gain_margin_db=float(min_gain_margin_db))


# typed signature of relay_autotune (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def relay_autotune(axis, *, amplitude_v: float = 1.0, hysteresis_pulse: float = 50.0, data_length: int = 200,
                       sampling_time_s: float = 0.0005, deviation_limit_pulse: float = 2000.0, max_spread: float = 0.1,
                       phase_margin_deg: float = 60.0, alpha: float = 4.0, settle_cycles: int = 3,
                       max_cycle_s: float = 10.0, progress='auto',
                       min_gain_margin_db: float = 6.0) -> RelayTuneResult: ...
else:
    relay_autotune = _relay_autotune
# end of the typed signature of relay_autotune


def _relay_decides(n_ticks: int, servo_period_s: float, sampling_time_s: float) -> np.ndarray:
    """Per tick: True where the relay decides (the first tick at or after each multiple of its sampling time, as
    the experiment does; no rounding to whole ticks)."""
    k = np.arange(n_ticks)
    s = np.floor(k * (servo_period_s / sampling_time_s) + 1e-9)
    out = np.ones(n_ticks, dtype=bool)
    out[1:] = s[1:] != s[:-1]
    return out


_RELAY_DEFAULTS = _core.RelayTuneOptions()  # the relay's defaults, read from the C++ struct (decision OP4)


def predicted_limit_cycle(axis, *, amplitude_v: float = _RELAY_DEFAULTS.amplitude_v,
                          hysteresis_pulse: float = _RELAY_DEFAULTS.hysteresis_pulse,
                          sampling_time_s: float = _RELAY_DEFAULTS.sampling_time_s, cycles: int = 60) -> dict:
    """The limit cycle the relay experiment of :func:`relay_autotune` settles into on this axis's linear model:
    the sampled relay with hysteresis (deciding at the first tick at or after each multiple of `sampling_time_s`,
    exactly as the experiment; no rounding), its one-tick output delay and the plant lifted exactly to the servo rate
    (the model of :func:`servobench.frequency.analytic_response`) are run together from rest for `cycles` limit
    cycles; the last half are measured the way the experiment measures them (rising switch to rising switch,
    single-bin DFT of the error).

    Returns {"freq_hz" (1 / mean period), "period_ticks" and "half_period_ticks" (exact means, not whole ticks),
    "amplitude_pulse" (fundamental of the error), "ultimate_gain_v_per_pulse" (4 d / (pi a), what the experiment
    reports), "describing_function": the classic describing-function prediction from the same plant, a relay delayed
    by half its sampling time beyond the servo tick (decisions R4): {"freq_hz", "amplitude_pulse",
    "ultimate_gain_v_per_pulse" = 1/``|P|``}}. ValueError if no steady cycle appears (e.g. an undamped double
    integrator with hysteresis: the oscillation grows) or the describing function predicts none.
    """
    from . import _core
    from .frequency import analytic_response

    ts = axis.servo_period_s
    d, eps = float(amplitude_v), float(hysteresis_pulse)
    if not (0 < d <= 10):
        raise ValueError(f"amplitude_v = {amplitude_v} must be in (0, 10] V")
    if not eps > 0:
        raise ValueError(f"hysteresis_pulse = {hysteresis_pulse} must be > 0 pulse")
    if not (100e-6 <= sampling_time_s <= 1000e-6):
        raise ValueError(f"sampling_time_s = {sampling_time_s} must be in 100e-6..1000e-6 s (ADLINK L1847)")
    tr = max(float(sampling_time_s), ts)
    law = axis.law
    sign = -1.0 if isinstance(law, _core.ApsServoLaw) and law.v_inverse else 1.0

    # The describing function (kept for reference).
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
    p_u = point(fu)[0]
    df = {"freq_hz": float(fu), "amplitude_pulse": float(4 * d / np.pi * abs(p_u)),
          "ultimate_gain_v_per_pulse": float(1 / abs(p_u))}

    # The sampled relay on the lifted linear model, tick by tick.
    a_m, b_m, c_motor, c_load = (np.asarray(x, dtype=float) for x in _core.tick_model(getattr(axis, "_axis", axis)))
    b_v = b_m[:, 0] if b_m.ndim == 2 else b_m
    c = (c_load if axis.encoder.on_load else c_motor).reshape(-1) * axis.encoder.counts_per_rev / (2 * np.pi)
    period_guess = max(4, int(round(1.0 / (df["freq_hz"] * ts))))
    n_max = int(min(2_000_000, (cycles + 10) * period_guess * 3))
    decide = _relay_decides(n_max, ts, tr)
    x = np.zeros(a_m.shape[0])
    u, v_applied = d, 0.0
    e_hist = np.empty(n_max)
    rising = []
    for k in range(n_max):
        e = -(c @ x)
        e_hist[k] = e
        if decide[k]:
            if e > eps:
                if u < 0:
                    rising.append(k)
                u = d
            elif e < -eps:
                u = -d
        x = a_m @ x + b_v * v_applied
        v_applied = sign * u  # reaches the drive one tick later
        if len(rising) > cycles:
            break
    if len(rising) <= cycles or not np.all(np.isfinite(e_hist[:k + 1])):
        raise ValueError(f"no steady limit cycle on the linear model within {n_max} ticks "
                         f"({len(rising)} of {cycles} cycles): the relay's oscillation does not settle")
    r = np.asarray(rising[len(rising) // 2:])
    amps = []
    for t0, t1 in zip(r[:-1], r[1:]):
        n = t1 - t0
        seg = e_hist[t0:t1]
        amps.append(2 * abs(np.sum(seg * np.exp(-2j * np.pi * np.arange(n) / n))) / n)
    a_mean = float(np.mean(amps))
    growth = abs(amps[-1] / amps[0] - 1) if amps[0] > 0 else np.inf
    if growth > 0.02:
        raise ValueError(f"no steady limit cycle on the linear model: the cycle's amplitude still changes by "
                         f"{100 * growth:.1f} % over the measured cycles (it grows: no limit cycle for this relay)")
    period = float(np.mean(np.diff(r)))
    return {"freq_hz": 1.0 / (period * ts), "period_ticks": period, "half_period_ticks": period / 2,
            "amplitude_pulse": a_mean, "ultimate_gain_v_per_pulse": 4 * d / (np.pi * a_mean),
            "describing_function": df}


@_opts.described_result(_core.MODEL_TUNE_FIELDS,
                        after={"crossover_hz": ("margins",), "max_pole_radius": ("law", "filters", "resonances"),
                               "resonance_prominence_db": ("notch",)},
                        keys={"resonance_keys": _core.RESONANCE_PEAK_FIELDS, "notch_keys": _core.NOTCH_DESIGN_FIELDS,
                              "scan_keys": _core.CROSSOVER_CANDIDATE_FIELDS})
class ModelTuneResult(JsonResult):
    """The outcome of :func:`model_based_tune`; ``str(result)`` is its summary.

    {fields}
    margins
        :class:`servobench.frequency.Margins` of the analytic loop with the card law's integers and the filters
        (phase margin at the crossover, gain margin, Ms, bandwidth): what :meth:`apply` will give.
    law, filters
        the card law (integers, feed-forward 0) and the two biquads (notch or pass-through; pass-through) that
        :meth:`apply` writes.
    resonances
        peaks found in the plant response, a list of dicts:
        {resonance_keys}.
    notch
        a dict: {notch_keys}; "float_biquad" (the pre-warped design) and "adlink_biquad" (the card's integers; None
        when quantisation leaves none).
    servo_period_s
        the axis's servo period, s.
    scan
        the chosen filter option's crossover candidates, a dict of columns (arrays; reason a list):
        {scan_keys}.
    summary
        the self-explaining report.
    phase_margin_deg, min_gain_margin_db
        the design's target (deg) and gain-margin floor (dB), which :meth:`apply` checks the loop against.
    """

    # The single figures (kp ... limited_by) are read at import from tuning::ModelTuneResult::describe() with their
    # units and docs, margins, law, filters, resonances and notch placed among them as before (decision OR1);
    # static type checkers read these names (test_options_once checks they match).
    if TYPE_CHECKING:
        kp: float
        ki: float
        kd: float
        kc: float
        ti_s: float
        td_s: float
        crossover_hz: float
        max_pole_radius: float
        resonance_hz: float
        resonance_prominence_db: float
        crossover_without_notch_hz: float
        limited_by: str
    margins: object
    law: object
    filters: tuple
    resonances: list
    notch: dict
    servo_period_s: float
    scan: dict = field(repr=False)
    summary: str = field(repr=False)
    phase_margin_deg: float = 60.0
    min_gain_margin_db: float = 10.0

    def __str__(self) -> str:
        return self.summary

    def to_dataframe(self):
        """The crossover scan as a pandas DataFrame, one row per candidate crossover (freq_hz, Hz; phase_margin_deg,
        pm_freq_hz, gain_margin_db, ms, max_pole_radius, pid_lead_deg, feasible and the reason it was rejected);
        ``df.attrs["units"]`` names each unit."""
        units = {"freq_hz": "Hz", "phase_margin_deg": "deg", "pm_freq_hz": "Hz", "gain_margin_db": "dB", "ms": "1",
                 "max_pole_radius": "1", "pid_lead_deg": "deg"}
        n = max((len(v) for v in self.scan.values()), default=0)
        cols = {k: (np.asarray(v, dtype=object) if k == "reason" else v) for k, v in self.scan.items()
                if len(v) == n}
        return dataframe(cols, units)

    def gt_law(self, base=None):
        """The gains as GT servo-filter gains (Kp, Ki with its /256, Kd; feed-forward 0), integers in 0..32767."""
        return _law(self, "gt", base)

    def aps_law(self, base=None):
        """The gains as ADLINK gains: integers 0..65535 with per-term shifts (PID_SHIFT -5; feed-forward 0)."""
        return _law(self, "aps", base)

    def apply(self, axis, *, force: bool = False, verify: bool = True, pm_tolerance_deg: float = 5.0):
        """Writes the gains to the axis's law (its own kind: GT or ADLINK, feed-forward 0), the notch to biquad 0
        and pass-through to biquad 1, and turns the servo on, but only when the loop passes
        :func:`servobench.tune_check.check_design` (closed-loop poles, the phase margin within ``pm_tolerance_deg``
        deg of the target and no crossover nearer to -1, gain margin >= the design's ``min_gain_margin_db``, on the model and
        by a verification sweep when `verify`). Raises :class:`servobench.tune_check.TuningRefused` with the report
        otherwise; ``force=True`` applies anyway. Returns the :class:`~servobench.tune_check.TuneCheck`."""
        from .tune_check import TuningRefused, check_design

        law = self.gt_law(axis.law) if isinstance(axis.law, _core.GtServoLaw) else self.aps_law(axis.law)
        check = check_design(axis, law, self.filters, target_phase_margin_deg=self.phase_margin_deg,
                             pm_tolerance_deg=pm_tolerance_deg, min_gain_margin_db=self.min_gain_margin_db,
                             verify=verify)
        if not check.accepted and not force:
            raise TuningRefused(check)
        axis.set_law(law)
        axis.set_filters(self.filters)
        axis.set_servo_on(True)
        return check


_MODEL_TUNE_PYTHON_DEFAULTS = {
    "resonance_hz": _opts.PythonDefault(None, 0.0, "None (default): found in the plant response as for 0"),
    "max_crossover_hz": _opts.PythonDefault(None, 0.0, "None (default): 0.45 / Ts"),
}


@_opts.takes_options(_core.ModelTuneOptions, python_defaults=_MODEL_TUNE_PYTHON_DEFAULTS,
                     name="model_based_tune")
def _model_based_tune(axis, *, notch_q=tuple(_core.MODEL_TUNE_NOTCH_Q), law: str | None = None,
                     **options) -> ModelTuneResult:
    """A PID (Ti = alpha Td) and a notch designed from the axis's analytic plant: the highest crossover at which the
    whole loop keeps the phase margin, the gain margin and the peak sensitivity asked for (docs/autotune.md).

    The plant is the axis's own (output stage, one-tick delay, drive and mechanics lifted to the servo rate: the
    model of :func:`servobench.frequency.analytic_response`), so any plant the axis runs is designed for, an
    identified one included. Nothing is run on the axis; :meth:`ModelTuneResult.apply` writes the result.

    {options}
    notch_q
        the notch quality factors tried, each 0.1..100 (default ``ModelTuneOptions::notch_q_set``, read from C++).
    law
        None (the axis's law), ``"gt"`` or ``"aps"``: the card law whose integers the design is checked with.

    Raises ValueError for a pulse-input axis (no position loop on the card), a parameter outside its range (named),
    or when no crossover meets the bounds (the message names the bounds to relax and the nearest miss). The options,
    their defaults, units and ranges are those of :class:`servobench._core.ModelTuneOptions` (tuning/model_tune.hpp),
    read from it.
    Releases the GIL; about 0.1-0.5 s.
    """
    from .frequency import _margins_from

    resonance_hz = options["resonance_hz"]
    if resonance_hz is not None and float(resonance_hz) == 0.0:
        raise ValueError("model_based_tune.resonance_hz = 0 is outside the allowed range 0 < f < Nyquist; "
                         "use None to find it in the plant response")
    values = dict(options, notch=_checks.flag("model_based_tune", "notch", options["notch"]))
    o = _opts.cpp_options(_core.ModelTuneOptions, values, _MODEL_TUNE_PYTHON_DEFAULTS)
    d = _core.model_tune(getattr(axis, "_axis", axis), o, [float(q) for q in np.atleast_1d(notch_q)],
                         "axis" if law is None else str(law))
    figures = {f["name"]: d[f["name"]] for f in _core.MODEL_TUNE_FIELDS}  # kp ... limited_by (OR1)
    return ModelTuneResult(**figures, margins=_margins_from(d["margins"], "analytic model"), law=d["law"],
                           filters=tuple(d["filters"]), resonances=list(d["resonances"]), notch=dict(d["notch"]),
                           servo_period_s=axis.servo_period_s,
                           scan={k: (list(v) if k == "reason" else np.asarray(v)) for k, v in d["scan"].items()},
                           summary=d["summary"], phase_margin_deg=float(o.phase_margin_deg),
                           min_gain_margin_db=float(o.min_gain_margin_db))


# typed signature of model_based_tune (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def model_based_tune(axis, *, phase_margin_deg: float = 60.0, alpha: float = 4.0, notch: bool = True,
                         min_gain_margin_db: float = 10.0, max_ms: float = 2.0, max_pid_lead_deg: float = 70.0,
                         pm_tolerance_deg: float = 2.0, resonance_hz: float | None = None,
                         min_resonance_prominence_db: float = 6.0, min_crossover_hz: float = 1.0,
                         max_crossover_hz: float | None = None, candidates: int = 60, points: int = 4000,
                         notch_q=(0.5, 0.7, 1.0, 1.4, 2.0, 3.0, 5.0), law: str | None = None) -> ModelTuneResult: ...
else:
    model_based_tune = _model_based_tune
# end of the typed signature of model_based_tune
