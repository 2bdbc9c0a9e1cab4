"""Frequency responses of a simulated axis: the card's stepped-sine Bode sweep, fast broadband measurements, the
analytic response of the same loop, and the figures of merit read from them.

The loop and its signals (ADLINK Bode tool, L1978-2045)::

    R --(+)--E--> law C --(+)--> biquad 0 -> biquad 1 --U--> DAC -> drive -> plant -> encoder --Y-->
         ^-              ^ feed-forward Cff on R                                               |
         '-------------------------------------------------------------------------------------'

R the command sine (pulse), E = R - Y the following error (pulse), U the DAC input (the second biquad's output,
DAC counts, 32767 counts = 10 V), Y the encoder (pulse). Response types: plant Y/U (pulse/count: DAC, drive,
motor and mechanics, with the one-tick output delay), open loop Y/E (pulse/pulse) and closed loop Y/R
(pulse/pulse), all three from the same closed-loop run.

What is in the loop during a measurement is explicit: ``feedforward`` (default False: Kvff/Kaff zeroed, so that
Y/E is the loop gain the margins need) and ``filters`` (default True: the biquads stay, they shape the loop);
docs/decisions.md B1-B2 give the reasons.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

import numpy as np

from . import _checks, _core
from . import _options as _opts
from ._frequency_response import _SWEEP_SIGNALS, FrequencyResponse, Peak, resonances
from .margins import Margins, _margins_from, analytic_margins, closed_loop_poles, margins  # noqa: F401 (re-exported)

__all__ = [
    "FrequencyResponse",
    "Margins",
    "Peak",
    "analytic_margins",
    "analytic_response",
    "closed_loop_poles",
    "broadband_response",
    "linear_model",
    "chirp",
    "margins",
    "multisine",
    "resonances",
    "sine_sweep",
]

# The result types live in _frequency_response.py (one concept per file, decision OR2); this module stays their
# home: pickles, saved results (servobench._serialise names the type by module) and the docs name them here.
for _obj in (FrequencyResponse, Peak, resonances):
    _obj.__module__ = __name__
del _obj


# ----------------------------------------------------------------------------------------------------------------
# Progress
# ----------------------------------------------------------------------------------------------------------------
def _progress_callback(progress, label: str) -> Callable[[int, int], bool] | None:
    """callback(done, total) for the core from ``progress=``: a tqdm bar (servobench._progress, decision W7)."""
    from ._progress import counter

    return counter(progress, label, owner=label)


def _core_axis(axis):
    return getattr(axis, "_axis", axis)


# ----------------------------------------------------------------------------------------------------------------
# Measurements
# ----------------------------------------------------------------------------------------------------------------
_SWEEP_PYTHON_DEFAULTS = {
    "amplitude_pulse": _opts.PythonDefault(None, 0.0, "None (default): chosen per point as for 0; the amplitudes "
                                           "used are in ``signals[\"amplitude_pulse\"]``"),
    "deviation_limit_pulse": _opts.PythonDefault(
        "auto", None, "Default ``\"auto\"``: the larger of the axis's "
        ":attr:`~servobench.Axis.default_error_limit_pulse` (2 encoder revolutions) and twice the amplitude, so an "
        "unstable loop stops with status ``\"deviation_exceeded\"``; None or 0 = off. A drive alarm also ends it "
        "(``\"drive_alarm\"``)"),
    "max_amplitude_pulse": _opts.PythonDefault(None, 0.0, "None (default): one encoder revolution"),
}


@_opts.takes_options(_core.SineSweepOptions, python_defaults=_SWEEP_PYTHON_DEFAULTS,
                     name="sine_sweep")
def _sine_sweep(axis, *, progress="auto", **options) -> FrequencyResponse:
    """The ADLINK Bode tool's stepped-sine measurement on a simulated axis (L1978-2045). Defaults are the manual's
    example (L2023, L2035): 10-100 Hz, 100 points, 0.1 s per point; the amplitude chosen per point.

    axis
        a :class:`servobench.Axis` (voltage-output: torque or velocity drive). The sweep runs from its present
        state around its last command position and continues it; it is left where the sweep ended.
    {options}
    progress
        ``"auto"`` (default: a tqdm bar when stderr is a terminal), True (a bar: a widget in Jupyter), None/False
        (none) or a callable(done, total) returning False to stop (status ``"stopped"``).

    The options, their defaults, units and ranges are those of :class:`servobench._core.SineSweepOptions`
    (tuning/sine_sweep.hpp), read from it. A point failing the judge (coherence, distortion, the quantisation
    floors, or any tick of DAC saturation, clamped current command or torque at the drive's limit) is flagged
    (``flags``), drawn hollow and left out of margins. Releases the GIL while it runs; deterministic (no randomness
    unless the encoder has noise, seeded).
    """
    feedforward = _checks.flag("sine_sweep", "feedforward", options["feedforward"])
    filters = _checks.flag("sine_sweep", "filters", options["filters"])
    amplitude_pulse, max_amplitude_pulse = options["amplitude_pulse"], options["max_amplitude_pulse"]
    if amplitude_pulse is not None:
        amplitude_pulse = _checks.real("sine_sweep", "amplitude_pulse", amplitude_pulse, 1e-9, 1e12,
                                       unit="pulse (or None: automatic)")
    if max_amplitude_pulse is not None:
        max_amplitude_pulse = _checks.real("sine_sweep", "max_amplitude_pulse", max_amplitude_pulse, 1e-9, 1e12,
                                           unit="pulse (or None: one encoder revolution)")
    # The automatic amplitude is at most max_amplitude_pulse (default one revolution): the "auto" deviation limit
    # (two revolutions, or twice the amplitude) then never trips on a loop that follows.
    span = amplitude_pulse if amplitude_pulse is not None else (max_amplitude_pulse or 0.0)
    values = dict(options, feedforward=bool(feedforward), filters=bool(filters),
                  amplitude_pulse=0.0 if amplitude_pulse is None else float(amplitude_pulse),
                  max_amplitude_pulse=0.0 if max_amplitude_pulse is None else float(max_amplitude_pulse),
                  deviation_limit_pulse=_checks.error_limit("sine_sweep", "deviation_limit_pulse",
                                                            options["deviation_limit_pulse"], axis, span))
    o = _opts.cpp_options(_core.SineSweepOptions, values)
    d = _core.sine_sweep(_core_axis(axis), o, _progress_callback(progress, "Bode sweep"))
    r, e, u, y = d["r"], d["e"], d["u"], d["y"]
    with np.errstate(divide="ignore", invalid="ignore"):
        return FrequencyResponse(
            freq_hz=d["freq_hz"], plant=y / u, open_loop=y / e, closed_loop=y / r, method="stepped sine",
            servo_period_s=axis.servo_period_s, feedforward=bool(feedforward), filters=bool(filters),
            coherence=d["coherence"], distortion=d["distortion"], status=d["status"], message=d["message"],
            signals={name: d[name] for name in _SWEEP_SIGNALS},
            flags=list(d["flag"]), integrators=int(d["integrators"]),
            open_loop_unstable_poles=int(d["open_loop_unstable_poles"]))


# typed signature of sine_sweep (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def sine_sweep(axis, *, start_hz: float = 10.0, end_hz: float = 100.0, amplitude_pulse: float | None = None,
                   points: int = 100, update_s: float = 0.1, deviation_limit_pulse: float | str = 'auto',
                   settle_fraction: float = 0.25, feedforward: bool = False, filters: bool = True,
                   min_coherence: float = 0.99, max_distortion: float = 0.05, min_response_pulse: float = 4.0,
                   min_dac_counts: float = 30.0, dac_fraction: float = 0.5, max_amplitude_pulse: float | None = None,
                   progress='auto') -> FrequencyResponse: ...
else:
    sine_sweep = _sine_sweep
# end of the typed signature of sine_sweep


@_opts.takes_options(_core.LoopOptions, name="analytic_response")
def _analytic_response(axis, freq_hz, **options) -> FrequencyResponse:
    """The analytic frequency response of the axis's loop at `freq_hz` (Hz, > 0, below Nyquist), computed from the
    same parameter objects the simulator runs: the law in z, both biquads, the one-tick output delay, the output
    stage (10 V per 32767 counts, ADLINK V_INVERSE), the drive (current loop; velocity mode: its discrete speed
    loop) and the zero-order-hold mechanics lifted exactly to the servo rate, the encoder's counts per radian.
    Exact for a linear configuration (no friction, saturation, quantisation or noise): a stepped-sine sweep of
    such an axis agrees with it (tests/python/test_bode.py). Also returns ``loop_gain`` and ``sensitivity``.

    {options}
    """
    feedforward, filters = options["feedforward"], options["filters"]
    feedforward = _checks.flag("analytic_response", "feedforward", feedforward)
    filters = _checks.flag("analytic_response", "filters", filters)
    f = np.atleast_1d(np.asarray(freq_hz, dtype=float))
    d = _core.loop_response(_core_axis(axis), f, bool(feedforward), bool(filters))
    mm = None
    if f.size >= 2 and np.all(np.diff(f) > 0):
        mm = analytic_margins(axis, f, filters=filters)
    return FrequencyResponse(freq_hz=d["freq_hz"], plant=d["plant"], open_loop=d["open_loop"],
                             closed_loop=d["closed_loop"], method="analytic", servo_period_s=axis.servo_period_s,
                             feedforward=bool(feedforward), filters=bool(filters), loop_gain=d["loop_gain"],
                             sensitivity=d["sensitivity"], model_margins=mm,
                             signals={"controller": d["controller"], "feedforward": d["feedforward"],
                                      "filters": d["filters"]})


# typed signature of analytic_response (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def analytic_response(axis, freq_hz, *, feedforward: bool = False, filters: bool = True) -> FrequencyResponse: ...
else:
    analytic_response = _analytic_response
# end of the typed signature of analytic_response


# ----------------------------------------------------------------------------------------------------------------
# Broadband excitations and the H1 estimate
# ----------------------------------------------------------------------------------------------------------------
def chirp(*, start_hz: float, end_hz: float, duration_s: float, servo_period_s: float, amplitude: float = 1.0,
          kind: str = "log") -> np.ndarray:
    """A swept sine of `amplitude` (any unit: pulse for a command, V for an injection) sampled every
    `servo_period_s` (s) for `duration_s` (s), sweeping from `start_hz` to `end_hz` (Hz, below Nyquist);
    ``kind = "log"`` (exponential, equal time per decade) or ``"linear"``. Starts at phase 0 (value 0)."""
    ts = float(servo_period_s)
    _check_band(start_hz, end_hz, ts)
    if not duration_s > 0:
        raise ValueError(f"duration_s = {duration_s} must be > 0 s")
    if kind not in ("log", "linear"):
        raise ValueError(f"kind = {kind!r} must be 'log' or 'linear'")
    return _core.chirp(start_hz=float(start_hz), end_hz=float(end_hz), duration_s=float(duration_s),
                       servo_period_s=ts, amplitude=float(amplitude), kind=kind)


def multisine(*, start_hz: float, end_hz: float, period_ticks: int, servo_period_s: float, amplitude: float = 1.0,
              lines: int | None = None, periods: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """A periodic multisine with Schroeder phases (low crest factor), scaled to a peak of `amplitude`.

    One period is `period_ticks` samples at `servo_period_s` (s); its lines are the DFT bins k*fs/period_ticks
    between `start_hz` and `end_hz` (Hz): all of them, or `lines` of them log-spaced (distinct bins). Returns
    ``(signal, line_bins)``: `periods` repetitions of the period, and the excited bin numbers.
    """
    ts = float(servo_period_s)
    _check_band(start_hz, end_hz, ts)
    n = int(period_ticks)
    if n < 8:
        raise ValueError(f"period_ticks = {period_ticks} must be >= 8")
    if lines is not None and lines < 1:
        raise ValueError(f"lines = {lines} must be >= 1")
    x, bins = _core.schroeder_multisine(start_hz=float(start_hz), end_hz=float(end_hz), period_ticks=n,
                                        servo_period_s=ts, amplitude=float(amplitude),
                                        lines=0 if lines is None else int(lines))
    return np.tile(x, int(periods)), bins.astype(int)


def _check_band(start_hz, end_hz, ts):
    nyq = 0.5 / ts
    for name, v in (("start_hz", start_hz), ("end_hz", end_hz)):
        if not (0 < v < nyq):
            raise ValueError(f"{name} = {v} must be > 0 and below the Nyquist frequency {nyq:g} Hz")
    if not end_hz > start_hz:
        raise ValueError(f"end_hz = {end_hz} must be above start_hz = {start_hz}")


def _measure_with(axis, feedforward: bool, filters: bool):
    """Context: the law's feed-forward and the biquads set for a measurement, restored afterwards."""
    import contextlib

    @contextlib.contextmanager
    def ctx():
        law, flt = axis.law, axis.filters
        meas_law = law if feedforward else law.replace(kvff=0, kaff=0)
        axis.set_law(meas_law)
        if not filters:
            axis.set_filters((None, None))
        try:
            yield
        finally:
            axis.set_law(law)
            axis.set_filters(flt)

    return ctx()


def _stopped(run, method, ts, feedforward, filters) -> FrequencyResponse:
    """The empty response of a broadband run the axis's protection ended (issue 21.4)."""
    status = "deviation_exceeded" if run.stopped == "error_limit" else run.stopped
    empty = np.zeros(0)
    return FrequencyResponse(freq_hz=empty, plant=empty.astype(complex), open_loop=empty.astype(complex),
                             closed_loop=empty.astype(complex), method=method, servo_period_s=ts,
                             feedforward=bool(feedforward), filters=bool(filters), coherence=empty, status=status,
                             message=f"{method}: the run stopped at tick {len(run.fb_pos)} ({run.stopped}, "
                                     f"|E| = {abs(run.stop_error_pulse):.6g} pulse); the loop is not stable")


@_opts.takes_options(_core.LoopOptions, name="broadband_response")
def _broadband_response(axis, *, excitation: str = "multisine", start_hz: float = 10.0, end_hz: float | None = None,
                       amplitude_pulse: float = 10.0, lines: int | None = 1000, period_ticks: int | None = None,
                       periods: int = 4, duration_s: float | None = None, rest_s: float = 0.5,
                       min_coherence: float = 0.99, **options) -> FrequencyResponse:
    """A whole frequency response from one closed-loop run with a broadband command R (the fast alternative to
    the stepped sine). The H1 estimates use R as the reference: Y/R = S_RY/S_RR, Y/E = S_RY/S_RE,
    Y/U = S_RY/S_RU (the indirect closed-loop method: unbiased by anything that enters the loop after R).

    excitation
        ``"multisine"``: a periodic Schroeder multisine of `period_ticks` ticks (default: the shortest period
        whose line spacing puts `lines` distinct log-spaced lines between start_hz and end_hz, at least
        fs/start_hz); one period is run to settle, then `periods` periods are averaged; results at the excited
        lines. Exact in steady state (no leakage). Coherence from the spread between periods.
        ``"chirp"``: a logarithmic chirp of `duration_s` s (default: what `lines` distinct lines need), tapered to start and end at rest, followed by `rest_s` s
        for the loop to settle; the record is run `periods` times from rest and the spectra of the whole records
        averaged (the response must die out within the rest for the estimate to be exact). Results at the record's
        DFT lines between start_hz and end_hz, thinned to `lines` log-spaced ones.
    start_hz, end_hz
        band, Hz (end default 0.4/Ts).
    amplitude_pulse
        peak amplitude of R, pulse.
    {options}
    min_coherence
        lines whose coherence is below this (0..1; with periods > 1) are flagged; when any tick of the run saturated
        (DAC, current command or torque limit; counts in ``signals``) every line is flagged. Flagged lines are left
        out of margins (``flags``).

    The axis continues from its present state around its last command position. Returns a
    :class:`FrequencyResponse` with ``coherence`` (magnitude-squared, R to Y).
    """
    feedforward, filters = options["feedforward"], options["filters"]
    feedforward = _checks.flag("broadband_response", "feedforward", feedforward)
    filters = _checks.flag("broadband_response", "filters", filters)
    ts = axis.servo_period_s
    fs = 1.0 / ts
    if end_hz is None:
        end_hz = 0.4 * fs
    _check_band(start_hz, end_hz, ts)
    if not amplitude_pulse > 0:
        raise ValueError(f"amplitude_pulse = {amplitude_pulse} must be > 0 pulse")
    if int(periods) < 1:
        raise ValueError(f"periods = {periods} must be >= 1")
    base = axis.last_command_pulse
    # The record length that gives `lines` distinct log-spaced DFT lines: spacing df <= start*(r - 1),
    # r = (end/start)^(1/(lines-1)); at least one period of start_hz.
    n_min = int(np.ceil(fs / start_hz))
    if lines is not None and lines > 1:
        r = (end_hz / start_hz) ** (1.0 / (lines - 1))
        n_min = max(n_min, int(np.ceil(fs / (start_hz * (r - 1.0)))))
    with _measure_with(axis, feedforward, filters):
        if excitation == "multisine":
            if period_ticks is None:
                period_ticks = n_min
            x, bins = multisine(start_hz=start_hz, end_hz=end_hz, period_ticks=period_ticks, servo_period_s=ts,
                                amplitude=amplitude_pulse, lines=lines, periods=int(periods) + 1)
            run = axis.run(base + x, signals=("fb_pos", "error", "biquad1", "u", "volts", "torque_nm"),
                           continue_=True)
            if run.stopped:  # the loop tripped the axis's default error limit (or the drive alarmed): report it
                return _stopped(run, excitation, ts, feedforward, filters)
            h1 = _core.h1_estimate(r=x, e=run.error, u=run.biquad1, y=run.fb_pos, record_ticks=int(period_ticks),
                                   records=int(periods), skip_ticks=int(period_ticks), lines=bins,
                                   servo_period_s=ts, remove_offset=False)
        elif excitation == "chirp":
            if duration_s is None:
                duration_s = max(n_min * ts - rest_s, 10.0 / start_hz)
            if not duration_s > 0:
                raise ValueError(f"duration_s = {duration_s} must be > 0 s")
            n_rest = int(round(rest_s / ts))
            # Tapered to start and end at rest (ramps of one start-frequency period and 20 end-frequency periods),
            # then a rest for the loop to settle back (tuning/chirp.hpp).
            record = _core.chirp_record(start_hz=float(start_hz), end_hz=float(end_hz), duration_s=float(duration_s),
                                        servo_period_s=ts, amplitude=float(amplitude_pulse), rest_ticks=n_rest)
            n = len(record)
            # settle whatever ran before, at the base position
            axis.run(np.full(n_rest, base), signals=(), continue_=True)
            x = np.tile(record, int(periods))
            run = axis.run(base + x, signals=("fb_pos", "error", "biquad1", "u", "volts", "torque_nm"),
                           continue_=True)
            if run.stopped:  # the loop tripped the axis's default error limit (or the drive alarmed): report it
                return _stopped(run, excitation, ts, feedforward, filters)
            in_band = _core.chirp_lines(record_ticks=n, servo_period_s=ts, start_hz=float(start_hz),
                                        end_hz=float(end_hz), lines=-1 if lines is None else int(lines))
            h1 = _core.h1_estimate(r=x, e=run.error, u=run.biquad1, y=run.fb_pos - base, record_ticks=n,
                                   records=int(periods), skip_ticks=0, lines=in_band, servo_period_s=ts,
                                   remove_offset=True)
        else:
            raise ValueError(f"excitation = {excitation!r} must be 'multisine' or 'chirp'")
    sat = _saturated_ticks(axis, run)
    freq, coh = h1["freq_hz"], h1["coherence"]
    flags = []
    run_flag = "; ".join(f"{k.replace('_', ' ')} {v} ticks" for k, v in sat.items() if v)
    for c in coh:
        why = [run_flag] if run_flag else []
        if periods > 1 and c < min_coherence:
            why.append(f"coherence {c:.4g} < {min_coherence:g}")
        flags.append("; ".join(why))
    n_bad = sum(1 for f_ in flags if f_)
    integ = _core.loop_poles(_core_axis(axis), bool(filters))
    return FrequencyResponse(freq_hz=freq, plant=h1["plant"], open_loop=h1["open_loop"], closed_loop=h1["closed_loop"],
                             method=excitation, servo_period_s=ts, feedforward=bool(feedforward),
                             filters=bool(filters), coherence=coh, status="completed",
                             message=f"{excitation}: {len(freq)} lines, {len(x)} ticks" +
                             (f"; {n_bad} lines flagged" + (f" (the run saturated: {run_flag})" if run_flag else "")
                              if n_bad else "; every line passed the checks"),
                             signals={k: np.array([v]) for k, v in sat.items()}, flags=flags,
                             integrators=int(integ["integrators"]),
                             open_loop_unstable_poles=int(integ["open_loop_unstable"]))


# typed signature of broadband_response (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def broadband_response(axis, *, feedforward: bool = False, filters: bool = True, excitation: str = 'multisine',
                           start_hz: float = 10.0, end_hz: float | None = None, amplitude_pulse: float = 10.0,
                           lines: int | None = 1000, period_ticks: int | None = None, periods: int = 4,
                           duration_s: float | None = None, rest_s: float = 0.5,
                           min_coherence: float = 0.99) -> FrequencyResponse: ...
else:
    broadband_response = _broadband_response
# end of the typed signature of broadband_response


def _saturated_ticks(axis, run) -> dict:
    """Ticks of a run at which the output stage or the drive saturated: DAC at full scale or the law's output at
    +-32767 counts, the torque drive's current command clamped, the torque at the velocity drive's limit."""
    volts, u, u1, torque = (np.abs(np.asarray(getattr(run, k))) for k in ("volts", "u", "biquad1", "torque_nm"))
    dac = int(np.sum((volts >= axis.dac.full_scale_v * (1 - 1e-9)) | (u >= 32767) | (u1 >= 32767)))
    cur = trq = 0
    drv = axis.drive
    if isinstance(drv, _core.TorqueDrive):
        limit = min(drv.current_limit_a, drv.torque_limit_nm / drv.kt)
        cur = int(np.sum(drv.amps_per_volt * volts >= limit * (1 - 1e-9)))
    elif isinstance(drv, _core.VelocityDrive):
        limit = min(drv.torque_limit_nm, drv.current_limit_a * drv.kt)
        trq = int(np.sum(torque >= limit * (1 - 1e-9)))
    return {"dac_saturated_ticks": dac, "current_saturated_ticks": cur, "torque_saturated_ticks": trq}


# ----------------------------------------------------------------------------------------------------------------
# The same loop as python-control systems
# ----------------------------------------------------------------------------------------------------------------
@_opts.takes_options(_core.LoopOptions, name="linear_model")
def _linear_model(axis, **options) -> dict:
    """The axis's loop as discrete-time python-control systems (dt = the servo period, s), built from the same
    parameters as :func:`analytic_response`: ``controller`` C(z) (counts/pulse), ``feedforward`` Cff(z),
    ``filters`` F(z) (both biquads), all three as state-space systems, ``plant`` P(z) (DAC counts to encoder pulses, with the one-tick delay; a
    state-space system from the lifted power train), ``loop_gain`` F C P and ``closed_loop`` Y/R. Needs the
    ``control`` package. For analysis with python-control's tools (step responses, root locus, margins).

    {options}
    """
    feedforward, filters = options["feedforward"], options["filters"]
    _checks.has("linear_model", "axis", axis, "servo_period_s", "law")
    import control

    ts = axis.servo_period_s
    law = axis.law
    gt = isinstance(law, _core.GtServoLaw)
    if gt:
        kp, ki, kd = law.kp, (0.0 if law.ilmt == 0 else law.ki / 256.0), law.kd
        kvff, kaff, vpc = law.kvff, law.kaff, 10.0 / 32767.0
    else:
        def eff(k, shift):
            return k * 2.0 ** (shift + law.pid_shift)
        kp, kd = eff(law.kp, law.kp_shift), eff(law.kd, law.kd_shift)
        ki = 0.0 if law.integral_limit == 0 else eff(law.ki, law.ki_shift)
        kvff, kaff = eff(law.kvff, law.kvff_shift), eff(law.kaff, law.kaff_shift)
        vpc = (-1.0 if law.v_inverse else 1.0) * 10.0 / 32767.0
    if not feedforward:
        kvff = kaff = 0.0
    # C(z) = kp + ki z/(z-1) + kd (z-1)/z = [(kp+ki+kd) z^2 - (kp+2kd) z + kd] / (z^2 - z); without an acting
    # integral term no pole at z = 1 (it would cancel a zero there and leave an unobservable pole on the circle)
    if ki != 0:
        c = control.tf([kp + ki + kd, -(kp + 2 * kd), kd], [1, -1, 0], ts)
    else:
        c = control.tf([kp + kd, -kd], [1, 0], ts)
    # Cff(z) = kvff (1 - z^-1) + kaff (1 - z^-1)^2 = [(kvff+kaff) z^2 - (kvff+2kaff) z + kaff] / z^2
    cff = control.tf([kvff + kaff, -(kvff + 2 * kaff), kaff], [1, 0, 0], ts)
    f = control.tf([1], [1], ts)
    if filters:
        for flt in axis.filters:
            if flt is None:
                continue
            q = flt.to_float() if hasattr(flt, "to_float") else flt
            f = f * control.tf([q.b0, q.b1, q.b2], [1, q.a1, q.a2], ts)
    a, b, c_motor, c_load = _core.tick_model(_core_axis(axis))
    out = c_load if axis.encoder.on_load else c_motor
    scale = axis.encoder.counts_per_rev / (2 * np.pi) * vpc
    delay = control.tf([1], [1, 0], ts)
    p = control.ss(a, b, scale * out, 0, ts) * delay
    # Products in state space (polynomial products of this order lose digits).
    c, cff, f = control.ss(c), control.ss(cff), control.ss(f)
    loop = f * c * p
    # Y/R = F (C + Cff) P / (1 + L)
    closed = control.feedback(loop, 1) if not feedforward else (f * (c + cff) * p) * control.feedback(1, loop)
    return {"controller": c, "feedforward": cff, "filters": f, "plant": p, "loop_gain": loop,
            "closed_loop": closed}


# typed signature of linear_model (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def linear_model(axis, *, feedforward: bool = False, filters: bool = True) -> dict: ...
else:
    linear_model = _linear_model
# end of the typed signature of linear_model
