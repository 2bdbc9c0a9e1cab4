"""The Python implementations of the chirp and multisine excitations and of the broadband H1 estimate as they were
before they moved to C++ (session 11, issue 24 point 4; decision OP5), kept verbatim as the reference the C++ ones
are tested against (tests/python/test_excitation_cpp.py): results equal within 1e-9 relative."""

from __future__ import annotations

import math

import numpy as np

from servobench import _checks, _core
from servobench.frequency import FrequencyResponse, _check_band, _core_axis, _measure_with, _saturated_ticks, _stopped


def chirp_reference(*, start_hz: float, end_hz: float, duration_s: float, servo_period_s: float, amplitude: float = 1.0,
          kind: str = "log") -> np.ndarray:
    """A swept sine of `amplitude` (any unit: pulse for a command, V for an injection) sampled every
    `servo_period_s` (s) for `duration_s` (s), sweeping from `start_hz` to `end_hz` (Hz, below Nyquist);
    ``kind = "log"`` (exponential, equal time per decade) or ``"linear"``. Starts at phase 0 (value 0)."""
    ts = float(servo_period_s)
    _check_band(start_hz, end_hz, ts)
    if not duration_s > 0:
        raise ValueError(f"duration_s = {duration_s} must be > 0 s")
    t = np.arange(int(round(duration_s / ts))) * ts
    if kind == "log":
        k = np.log(end_hz / start_hz) / duration_s
        phase = 2 * np.pi * start_hz * np.expm1(k * t) / k if k != 0 else 2 * np.pi * start_hz * t
    elif kind == "linear":
        phase = 2 * np.pi * (start_hz * t + 0.5 * (end_hz - start_hz) / duration_s * t * t)
    else:
        raise ValueError(f"kind = {kind!r} must be 'log' or 'linear'")
    return amplitude * np.sin(phase)


def multisine_reference(*, start_hz: float, end_hz: float, period_ticks: int, servo_period_s: float, amplitude: float = 1.0,
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
    df = 1.0 / (n * ts)
    k_lo = max(1, int(np.ceil(start_hz / df - 1e-9)))
    k_hi = min(n // 2 - 1, int(np.floor(end_hz / df + 1e-9)))
    if k_hi < k_lo:
        raise ValueError(f"no DFT line of a {n}-tick period (spacing {df:.4g} Hz) lies in {start_hz}..{end_hz} Hz: "
                         "lengthen period_ticks")
    bins = np.arange(k_lo, k_hi + 1)
    if lines is not None:
        if lines < 1:
            raise ValueError(f"lines = {lines} must be >= 1")
        pick = np.unique(np.round(np.geomspace(k_lo, k_hi, int(lines))).astype(int))
        bins = pick
    m = len(bins)
    phases = -np.pi * np.arange(m) * (np.arange(m) + 1) / m  # Schroeder
    spec = np.zeros(n // 2 + 1, dtype=complex)
    spec[bins] = np.exp(1j * phases)
    x = np.fft.irfft(spec, n)
    x *= amplitude / np.max(np.abs(x))
    return np.tile(x, int(periods)), bins


def broadband_response_reference(axis, *, excitation: str = "multisine", start_hz: float = 10.0, end_hz: float | None = None,
                       amplitude_pulse: float = 10.0, lines: int | None = 1000, period_ticks: int | None = None,
                       periods: int = 4, duration_s: float | None = None, rest_s: float = 0.5,
                       feedforward: bool = False, filters: bool = True,
                       min_coherence: float = 0.99) -> FrequencyResponse:
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
    feedforward, filters
        as for :func:`sine_sweep`.
    min_coherence
        lines whose coherence is below this (0..1; with periods > 1) are flagged; when any tick of the run saturated
        (DAC, current command or torque limit; counts in ``signals``) every line is flagged. Flagged lines are left
        out of margins (``flags``).

    The axis continues from its present state around its last command position. Returns a
    :class:`FrequencyResponse` with ``coherence`` (magnitude-squared, R to Y).
    """
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
            x, bins = multisine_reference(start_hz=start_hz, end_hz=end_hz, period_ticks=period_ticks, servo_period_s=ts,
                                amplitude=amplitude_pulse, lines=lines, periods=int(periods) + 1)
            run = axis.run(base + x, signals=("fb_pos", "error", "biquad1", "u", "volts", "torque_nm"),
                           continue_=True)
            if run.stopped:  # the loop tripped the axis's default error limit (or the drive alarmed): report it
                return _stopped(run, excitation, ts, feedforward, filters)
            n = int(period_ticks)
            seg = slice(n, None)  # drop the settling period

            def spectra(sig):
                s = np.asarray(sig, dtype=float)[seg].reshape(int(periods), n)
                return np.fft.rfft(s, axis=1)[:, bins]

            R, E, U, Y = (spectra(s) for s in (x, run.error, run.biquad1, run.fb_pos))
            s_ry = np.sum(np.conj(R) * Y, axis=0)
            s_re = np.sum(np.conj(R) * E, axis=0)
            s_ru = np.sum(np.conj(R) * U, axis=0)
            s_rr = np.sum(np.abs(R) ** 2, axis=0)
            s_yy = np.sum(np.abs(Y) ** 2, axis=0)
            freq = bins * fs / n
            coh = np.abs(s_ry) ** 2 / (s_rr * s_yy) if periods > 1 else np.ones(len(bins))
        elif excitation == "chirp":
            if duration_s is None:
                duration_s = max(n_min * ts - rest_s, 10.0 / start_hz)
            if not duration_s > 0:
                raise ValueError(f"duration_s = {duration_s} must be > 0 s")
            n_chirp = int(round(duration_s / ts))
            n_rest = int(round(rest_s / ts))
            x1 = chirp_reference(start_hz=start_hz, end_hz=end_hz, duration_s=duration_s, servo_period_s=ts,
                       amplitude=amplitude_pulse)
            # Taper: half-cosine ramps of one start-frequency period at the start and 20 end-frequency periods at
            # the end, so R starts and ends at rest; then a rest for the loop to settle back.
            ramp_in = min(n_chirp // 4, int(round(fs / start_hz)))
            ramp_out = min(n_chirp // 4, int(round(20 * fs / end_hz)))
            taper = np.ones(n_chirp)
            taper[:ramp_in] = 0.5 - 0.5 * np.cos(np.pi * np.arange(ramp_in) / ramp_in)
            taper[n_chirp - ramp_out:] = 0.5 + 0.5 * np.cos(np.pi * np.arange(1, ramp_out + 1) / ramp_out)
            record = np.concatenate([x1 * taper, np.zeros(n_rest)])
            n = len(record)
            # settle whatever ran before, at the base position
            axis.run(np.full(n_rest, base), signals=(), continue_=True)
            x = np.tile(record, int(periods))
            run = axis.run(base + x, signals=("fb_pos", "error", "biquad1", "u", "volts", "torque_nm"),
                           continue_=True)
            if run.stopped:  # the loop tripped the axis's default error limit (or the drive alarmed): report it
                return _stopped(run, excitation, ts, feedforward, filters)
            freq_all = np.fft.rfftfreq(n, ts)
            in_band = np.nonzero((freq_all >= start_hz) & (freq_all <= end_hz))[0]
            if lines is not None and lines < len(in_band):
                want = np.geomspace(freq_all[in_band[0]], freq_all[in_band[-1]], int(lines))
                in_band = np.unique(np.searchsorted(freq_all, want).clip(in_band[0], in_band[-1]))
            freq = freq_all[in_band]

            def spectra(sig):
                s = np.asarray(sig, dtype=float).reshape(int(periods), n)
                s = s - s[:, :1]  # each repetition starts at rest: its first sample is the offset
                return np.fft.rfft(s, axis=1)[:, in_band]

            R, E, U, Y = (spectra(s) for s in (x, run.error, run.biquad1, run.fb_pos - base))
            s_ry = np.sum(np.conj(R) * Y, axis=0)
            s_re = np.sum(np.conj(R) * E, axis=0)
            s_ru = np.sum(np.conj(R) * U, axis=0)
            s_rr = np.sum(np.abs(R) ** 2, axis=0)
            s_yy = np.sum(np.abs(Y) ** 2, axis=0)
            coh = np.abs(s_ry) ** 2 / (s_rr * s_yy) if periods > 1 else np.ones(len(freq))
        else:
            raise ValueError(f"excitation = {excitation!r} must be 'multisine' or 'chirp'")
    sat = _saturated_ticks(axis, run)
    coh = np.clip(coh, 0.0, 1.0)
    flags = []
    run_flag = "; ".join(f"{k.replace('_', ' ')} {v} ticks" for k, v in sat.items() if v)
    for c in coh:
        why = [run_flag] if run_flag else []
        if periods > 1 and c < min_coherence:
            why.append(f"coherence {c:.4g} < {min_coherence:g}")
        flags.append("; ".join(why))
    n_bad = sum(1 for f_ in flags if f_)
    integ = _core.loop_poles(_core_axis(axis), bool(filters))
    return FrequencyResponse(freq_hz=freq, plant=s_ry / s_ru, open_loop=s_ry / s_re, closed_loop=s_ry / s_rr,
                             method=excitation, servo_period_s=ts, feedforward=bool(feedforward),
                             filters=bool(filters), coherence=coh, status="completed",
                             message=f"{excitation}: {len(freq)} lines, {len(x)} ticks" +
                             (f"; {n_bad} lines flagged" + (f" (the run saturated: {run_flag})" if run_flag else "")
                              if n_bad else "; every line passed the checks"),
                             signals={k: np.array([v]) for k, v in sat.items()}, flags=flags,
                             integrators=int(integ["integrators"]),
                             open_loop_unstable_poles=int(integ["open_loop_unstable"]))



def excitation_reference(kind: str, n_samples: int, *, amplitude: float = 1.0, servo_period_s: float = 200e-6,
               seed: int = 0, hold_samples: int = 10, start_hz: float = 1.0, end_hz: float | None = None,
               step_samples: int = 500) -> np.ndarray:
    """An identification input of n_samples, in the unit of `amplitude` (V at the DAC, or N*m).

    kind
        ``"prbs"``: a random binary sequence +-amplitude held for `hold_samples` ticks (flat spectrum up to about
        1/(2.3 hold_samples Ts)); ``"multisine"``: random-phase sines on every DFT line from start_hz to end_hz
        (whole periods), crest-scaled to peak `amplitude`; ``"chirp"``: a logarithmic sweep start_hz..end_hz;
        ``"steps"``: random levels in [-amplitude, amplitude] held for `step_samples`.
    seed
        the random generator's seed: the same seed gives the same signal.
    """
    if kind not in ("prbs", "multisine", "chirp", "steps"):
        raise ValueError(f"kind = {kind!r} is not one of 'prbs', 'multisine', 'chirp', 'steps'")
    n = _whole("excitation", "n_samples", n_samples, 1, 10**8)
    amplitude = float(amplitude)
    if not (math.isfinite(amplitude) and amplitude >= 0):
        raise ValueError(f"excitation.amplitude = {amplitude} must be a finite number >= 0")
    ts = float(servo_period_s)
    if not (ts > 0 and math.isfinite(ts)):
        raise ValueError(f"excitation.servo_period_s = {servo_period_s} must be > 0")
    nyq = 0.5 / ts
    end = nyq * 0.5 if end_hz is None else float(end_hz)
    rng = np.random.default_rng(seed)
    if kind == "prbs":
        h = _whole("excitation", "hold_samples", hold_samples, 1, n)
        return np.repeat(rng.choice([-1.0, 1.0], size=n // h + 1), h)[:n] * amplitude
    if kind == "steps":
        h = _whole("excitation", "step_samples", step_samples, 1, n)
        return np.repeat(rng.uniform(-1.0, 1.0, size=n // h + 1), h)[:n] * amplitude
    if not (0 < start_hz < end <= nyq):
        raise ValueError(f"excitation: start_hz = {start_hz}, end_hz = {end} must satisfy 0 < start < end <= "
                         f"{nyq:g} Hz (the Nyquist frequency)")
    t = np.arange(n) * ts
    if kind == "chirp":
        dur = n * ts
        k = math.log(end / start_hz) / dur
        return amplitude * np.sin(2 * np.pi * start_hz * (np.exp(k * t) - 1) / k)
    df = 1.0 / (n * ts)
    lines = np.arange(max(1, math.ceil(start_hz / df)), math.floor(end / df) + 1)
    if len(lines) == 0:
        raise ValueError("excitation: no DFT line between start_hz and end_hz; lengthen the signal")
    phases = rng.uniform(0, 2 * np.pi, size=len(lines))
    x = np.zeros(n)
    for k, ph in zip(lines, phases):
        x += np.cos(2 * np.pi * k * df * t + ph)
    return amplitude * x / np.max(np.abs(x))


def _whole(owner, name, value, lo, hi) -> int:
    v = float(value)
    if not (math.isfinite(v) and v == int(v) and lo <= v <= hi):
        raise ValueError(f"{owner}.{name} = {value} is outside the allowed range {lo}..{hi} (a whole number)")
    return int(v)
