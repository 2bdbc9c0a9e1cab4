"""Identification experiments: the excitation signals and the default closed-loop experiment on an axis.

The injection is adapted to a frequency band (``band_hz``): a PRBS held h ticks has a sinc-shaped spectrum,
``|sinc(f h Ts)|``, -3 dB at 0.443 / (h Ts) and a null at 1 / (h Ts); the default experiment chooses h so the band's
upper edge is within 3 dB; the default band reaches 0.2 times the servo rate (held 2 ticks: no null below the
Nyquist frequency). A mode sitting in a spectral null is not
excited: its damping cannot be identified (decision J40). Units: V at the DAC, s, Hz, rad/s (motor side).
"""

from __future__ import annotations

import math

import numpy as np

from . import _checks, _core
from .idlog import IdentificationLog

__all__ = ["excitation", "run_experiment", "torque_per_volt", "prbs_hold_for_band", "default_band_hz"]

def excitation(kind: str, n_samples: int, *, amplitude: float = 1.0, servo_period_s: float = 200e-6,
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
    if kind == "chirp":  # tuning/chirp.hpp: x_n = A sin(2 pi f0 (exp(k t_n) - 1) / k), k = ln(f1/f0) / (n Ts)
        return _core.chirp(start_hz=float(start_hz), end_hz=end, duration_s=n * ts, servo_period_s=ts,
                           amplitude=amplitude)
    df = 1.0 / (n * ts)
    lines = np.arange(max(1, math.ceil(start_hz / df)), math.floor(end / df) + 1)
    if len(lines) == 0:
        raise ValueError("excitation: no DFT line between start_hz and end_hz; lengthen the signal")
    phases = rng.uniform(0, 2 * np.pi, size=len(lines))
    # tuning/multisine.hpp: sum_i cos(2 pi k_i n / N + phase_i) scaled to a peak of `amplitude`
    return _core.multisine_sum(n_samples=n, servo_period_s=ts, lines=lines, phases_rad=phases, amplitude=amplitude)


def _whole(owner, name, value, lo, hi) -> int:
    v = float(value)
    if not (math.isfinite(v) and v == int(v) and lo <= v <= hi):
        raise ValueError(f"{owner}.{name} = {value} is outside the allowed range {lo}..{hi} (a whole number)")
    return int(v)


# the PRBS's power spectrum |sinc(f h Ts)|^2 is 3 dB down at f h Ts = 0.4429
_SINC_3DB = 0.4429


def default_band_hz(servo_period_s: float, duration_s: float) -> tuple[float, float]:
    """The default experiment's injection band, Hz: from 1/duration_s to 0.2/servo_period_s (1 kHz at a 200 us servo
    period: resonances up to ~0.15/Ts with their upper skirt; the PRBS that covers it is held 2 ticks, still -13 dB
    at 0.4/Ts where the two-mass start stops reading, its first null at the Nyquist frequency)."""
    return 1.0 / float(duration_s), 0.2 / float(servo_period_s)


def prbs_hold_for_band(high_hz: float, servo_period_s: float) -> int:
    """The longest PRBS hold (ticks, >= 1) whose spectrum is within 3 dB up to `high_hz` (Hz): floor(0.443 /
    (high_hz Ts)). Its first spectral null, 1 / (h Ts), is then above 2.26 high_hz."""
    ts = _checks.real("prbs_hold_for_band", "servo_period_s", servo_period_s, 1e-9, 1.0, unit="s")
    hi = _checks.real("prbs_hold_for_band", "high_hz", high_hz, 1e-6, 0.5 / ts, unit="Hz (up to the Nyquist frequency)")
    return max(1, int(math.floor(_SINC_3DB / (hi * ts))))


def torque_per_volt(drive) -> float:
    """N*m per DAC volt of a torque-mode drive: kt * amps_per_volt."""
    if not isinstance(drive, _core.TorqueDrive):
        raise ValueError("identification needs a torque-mode drive (TorqueDrive): with a velocity-mode drive the "
                         "torque reaching the mechanics is not the card's output")
    return drive.kt * drive.amps_per_volt


# ----------------------------------------------------------------------------------------------------------------
# Logs
# ----------------------------------------------------------------------------------------------------------------
def run_experiment(axis, *, duration_s: float = 5.0, speed_rad_s: tuple[float, float] = (3.0, 30.0),
                   reversal_hz: float = 2.0, injection: str = "prbs", amplitude_v: float = 0.1, seed: int = 0,
                   band_hz: tuple[float, float] | None = None, **excitation_options) -> IdentificationLog:
    """Runs an identification experiment on `axis` (its servo law closes the loop) and returns the log.

    The command is a reversing motion whose speed amplitude grows geometrically from speed_rad_s[0] to
    speed_rad_s[1] (rad/s, motor side) at reversal_hz reversals pairs per second -- so the friction is seen at
    every speed, on the way through its low-speed (Stribeck) branch many times -- and an `injection`
    (:func:`excitation` kind, amplitude_v volts at the DAC, seeded) is added to the controller's output for the
    inertia and the resonances. The log holds the drive's torque command (from the DAC voltage, its A/V, its current
    limit and kt) and the encoder reading. The axis must have a torque-mode drive.

    band_hz
        (low, high), Hz: the band the injection must excite within 3 dB -- put the resonances you want identified
        inside it. Default :func:`default_band_hz`: 1/duration_s .. 0.2/Ts (1 kHz at a 200 us servo period). A PRBS
        is held :func:`prbs_hold_for_band` ticks (2 for the default band: no spectral null below the Nyquist
        frequency); a multisine or chirp runs from low to high. An explicit ``hold_samples``, ``start_hz`` or
        ``end_hz`` wins. The band used is in ``log.extra["injection_band_hz"]``.
    """
    tpv = torque_per_volt(axis.drive)
    ts = axis.servo_period_s
    _checks.real("run_experiment", "reversal_hz", reversal_hz, 1e-3, 0.1 / ts, unit="Hz (up to a tenth of the servo rate)")
    _checks.real("run_experiment", "amplitude_v", amplitude_v, 0.0, 10.0, unit="V")
    _checks.real("run_experiment", "duration_s", duration_s, ts, 3600.0, unit="s")
    if not (duration_s > 0 and math.isfinite(duration_s)):
        raise ValueError(f"run_experiment.duration_s = {duration_s} must be > 0")
    lo, hi = (float(v) for v in speed_rad_s)
    if not (0 < lo <= hi and math.isfinite(hi)):
        raise ValueError(f"run_experiment.speed_rad_s = {speed_rad_s} must be (low, high) with 0 < low <= high")
    n = int(round(duration_s / ts))
    t = np.arange(n) * ts
    speed = np.geomspace(lo, hi, n) * np.sin(2 * np.pi * reversal_hz * t)
    cpr = axis.encoder.counts_per_rev
    ref = axis.feedback_pulse + np.cumsum(speed) * ts * cpr / (2 * np.pi)
    if band_hz is None:
        band = default_band_hz(ts, duration_s)
    else:
        try:
            band = tuple(float(v) for v in band_hz)
        except (TypeError, ValueError):
            raise TypeError(f"run_experiment.band_hz must be (low, high) in Hz, got {band_hz!r}") from None
        if len(band) != 2 or not (0 < band[0] < band[1] <= 0.5 / ts and math.isfinite(band[1])):
            raise ValueError(f"run_experiment.band_hz = {band_hz!r} must be (low, high) Hz with 0 < low < high <= "
                             f"{0.5 / ts:g} Hz (the Nyquist frequency)")
    if injection == "prbs":
        excitation_options.setdefault("hold_samples", prbs_hold_for_band(band[1], ts))
    elif injection in ("multisine", "chirp"):
        excitation_options.setdefault("start_hz", band[0])
        excitation_options.setdefault("end_hz", band[1])
    inj = excitation(injection, n, amplitude=amplitude_v, servo_period_s=ts, seed=seed, **excitation_options)
    run = axis.run(ref, injection_v=inj, signals=["volts", "fb_pos"], continue_=True)  # from where it stands
    drive = axis.drive
    i_max = min(drive.current_limit_a, drive.torque_limit_nm / drive.kt)
    volts_applied = np.concatenate([[0.0], run.volts[:-1]])
    torque = np.clip(volts_applied * drive.amps_per_volt, -i_max, i_max) * drive.kt
    return IdentificationLog(ts, torque, run.fb_pos * 2 * np.pi / cpr, False, axis.encoder.on_load, cpr,
                             drive.current_bw_hz, axis.substeps,
                             extra={"volts": run.volts, "fb_pulse": run.fb_pos, "command_pulse": ref,
                                    "injection_v": inj, "torque_per_volt": tpv,
                                    "injection_band_hz": band})

