"""Plant identification: experiments on an axis, and grey-box fits of its mechanics with Ceres.

The time-domain fit (:func:`fit_time`) estimates a rigid or two-mass plant -- inertias, stiffness, damping, viscous,
Coulomb and Stribeck friction, a constant load -- from a log of the drive's torque command and the measured position
(or speed). Its model is the simulator's own plant code (the same matrices, the same exact zero-order hold, the same
dry-friction sub-step, templated in C++ so that Ceres differentiates it); the fit is an output-error fit by multiple
shooting over the stretches of one-way motion, with a segment-length continuation that makes it converge from
guesses 50 % off. The frequency-domain fit (:func:`fit_frequency`) matches the axis's analytic plant response to a
measured Y/U. Both return an :class:`IdentifiedPlant`: estimates with standard errors, fit quality, the parameters
the data could not determine, a residual plot, and :meth:`IdentifiedPlant.to_plant` for simulation and tuning.

Units: torque N*m, angles rad, speeds rad/s, inertias kg*m^2, time s; the log's measured position may be given in
pulses with the encoder's counts per revolution.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Iterable

import numpy as np

from . import _checks, _core
from .idlog import IdentificationLog

__all__ = [
    "frequency_input",
    "IdentificationLog", "IdentifiedPlant", "Estimate", "excitation", "run_experiment", "fit_time", "fit_frequency",
    "model_parameters", "torque_per_volt", "log_spectrum", "LogSpectrum", "resonance_guess", "ResonanceGuess",
    "IdentificationError",
]

MODELS = ("rigid", "two_mass")


def model_parameters(model: str) -> list[dict]:
    """The parameters of a plant model ('rigid' or 'two_mass'): name, unit, lower bound, meaning -- the field names of
    :class:`RigidPlant` / :class:`TwoMassPlant`."""
    return list(_core.identify_parameters(_model(model)))


def _model(model: str) -> str:
    if model not in MODELS:
        raise ValueError(f"model = {model!r} is not one of 'rigid', 'two_mass'")
    return model


# ----------------------------------------------------------------------------------------------------------------
# Excitations
# ----------------------------------------------------------------------------------------------------------------
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
                   **excitation_options) -> IdentificationLog:
    """Runs an identification experiment on `axis` (its servo law closes the loop) and returns the log.

    The command is a reversing motion whose speed amplitude grows geometrically from speed_rad_s[0] to
    speed_rad_s[1] (rad/s, motor side) at reversal_hz reversals pairs per second -- so the friction is seen at
    every speed, on the way through its low-speed (Stribeck) branch many times -- and an `injection`
    (:func:`excitation` kind, amplitude_v volts at the DAC, seeded) is added to the controller's output for the
    inertia and the resonances. The log holds the drive's torque command (from the DAC voltage, its A/V, its current
    limit and kt) and the encoder reading. The axis must have a torque-mode drive.
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
    inj = excitation(injection, n, amplitude=amplitude_v, servo_period_s=ts, seed=seed, **excitation_options)
    run = axis.run(ref, injection_v=inj, signals=["volts", "fb_pos"])
    drive = axis.drive
    i_max = min(drive.current_limit_a, drive.torque_limit_nm / drive.kt)
    volts_applied = np.concatenate([[0.0], run.volts[:-1]])
    torque = np.clip(volts_applied * drive.amps_per_volt, -i_max, i_max) * drive.kt
    return IdentificationLog(ts, torque, run.fb_pos * 2 * np.pi / cpr, False, axis.encoder.on_load, cpr,
                             drive.current_bw_hz, axis.substeps,
                             extra={"volts": run.volts, "fb_pulse": run.fb_pos, "command_pulse": ref,
                                    "injection_v": inj, "torque_per_volt": tpv})


# ----------------------------------------------------------------------------------------------------------------
# Spectral view of a log: the starting point of a two-mass fit
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LogSpectrum:
    """Torque-to-speed response of the mechanics estimated from a log (Welch, H1 = S_uv / S_uu).

    freq_hz: bin centres, Hz; response: speed over torque, (rad/s)/(N*m), complex, the known current loop divided
    out; coherence: 0..1 per bin (1: the speed is linear in the torque there; low: noise, friction, quantisation).
    apparent_inertia_kgm2 = 1 / (``|response|`` * 2 pi f): flat at the total inertia for a rigid body; a two-mass
    motor-side log shows a peak at the anti-resonance and a dip at the resonance.
    """

    freq_hz: np.ndarray
    response: np.ndarray
    coherence: np.ndarray

    @property
    def apparent_inertia_kgm2(self) -> np.ndarray:
        with np.errstate(divide="ignore"):
            return 1.0 / (np.abs(self.response) * 2 * np.pi * self.freq_hz)


def log_spectrum(log: IdentificationLog, *, segment_samples: int = 1024, instrument=None) -> LogSpectrum:
    """The torque-to-speed response of a position or speed log (Hann windows of `segment_samples`, half overlap;
    the speed of a position log is its per-sample difference over Ts, aligned with the torque held over that sample).

    instrument
        a signal injected into the loop during the experiment, one value per sample (default: the log's
        ``extra["injection_v"]`` from :func:`run_experiment`, if any). With it the estimate is S_rv / S_ru, which the
        closed loop does not bias: measurement noise fed back through the controller correlates with the torque but
        not with the injection. Without it (a log from elsewhere) it is H1 = S_uv / S_uu, biased towards the
        inverse of the controller where the noise dominates. The coherence is the instrument's (or the torque's)
        with the speed.
    """
    _checks.has("log_spectrum", "log", log, "torque_nm", "sample_period_s")
    n = len(log)
    segment_samples = _whole("log_spectrum", "segment_samples", segment_samples, 16, max(16, n - 1))
    if instrument is None:
        instrument = log.extra.get("injection_v")
    ts = log.sample_period_s
    m = n - 1 if not log.measured_is_speed else n
    u = log.torque_nm[:m]
    v = np.diff(log.measured) / ts if not log.measured_is_speed else log.measured
    if instrument is not None:
        r = np.asarray(instrument, float)
        if r.shape != (n,):
            raise ValueError(f"log_spectrum.instrument has shape {r.shape}; it must have one value per sample ({n})")
        r = r[:m]
    else:
        r = u
    win = np.hanning(segment_samples)
    sru = srv = srr = svv = 0.0
    for a in range(0, m - segment_samples + 1, segment_samples // 2):
        def ft(x):
            x = x[a:a + segment_samples]
            return np.fft.rfft(win * (x - x.mean()))
        rf, uf, vf = ft(r), ft(u), ft(v)
        sru = sru + np.conj(rf) * uf
        srv = srv + np.conj(rf) * vf
        srr = srr + np.abs(rf) ** 2
        svv = svv + np.abs(vf) ** 2
    f = np.fft.rfftfreq(segment_samples, ts)[1:]
    sru, srv, srr, svv = sru[1:], srv[1:], srr[1:], svv[1:]
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.where(np.abs(sru) > 0, srv / sru, 0)
        coh = np.where(srr * svv > 0, np.abs(srv) ** 2 / (srr * svv), 0.0)
    if math.isfinite(log.current_bw_hz):
        h = h * (1 + 1j * f / log.current_bw_hz)  # the known first-order current loop
    return LogSpectrum(f, h, coh)


@dataclass(frozen=True)
class ResonanceGuess:
    """Two-mass inertias and stiffness read off a motor-side log's spectrum: total inertia J from the low band,
    anti-resonance fa = sqrt(k/jl)/2pi and resonance fr = sqrt(k (jm + jl)/(jm jl))/2pi from the apparent inertia's
    peak and dip; then jm = J (fa/fr)^2, jl = J - jm, k = jl (2 pi fa)^2."""

    jm_kgm2: float
    jl_kgm2: float
    k_nm_per_rad: float
    anti_resonance_hz: float
    resonance_hz: float
    total_inertia_kgm2: float

    def as_guess(self) -> dict:
        return {"jm_kgm2": self.jm_kgm2, "jl_kgm2": self.jl_kgm2, "k_nm_per_rad": self.k_nm_per_rad}


def resonance_guess(log: IdentificationLog, *, min_coherence: float = 0.3,
                    segment_samples: int = 1024) -> ResonanceGuess:
    """Starting values of jm, jl and k for a two-mass fit from a motor-side log's spectrum (:func:`log_spectrum`).
    `min_coherence` is 0..1.

    The apparent inertia of the undamped-to-lightly-damped two-mass model,
    1 / (``|V/T|`` w) with V/T = (jl s^2 + c s + k) / (s (jm jl s^2 + c (jm + jl) s + k (jm + jl))), is matched in
    log magnitude (weighted by the coherence; bins below `min_coherence` and above 0.4 fs left out) over a grid of
    anti-resonance (the excited band), resonance/anti-resonance ratio (1.02..5) and anti-resonance damping
    (0.01..0.3), the total inertia in closed form. Magnitude only: the phase carries the sampling's delays. Raises
    :class:`IdentificationError` when the best two-mass shape explains the spectrum less than 4x better than a rigid
    body (no resonance in the excited band) or for a load-side log."""
    _checks.has("resonance_guess", "log", log, "measured_on_load", "sample_period_s")
    _checks.real("resonance_guess", "min_coherence", min_coherence, 0.0, 1.0)
    if log.measured_on_load:
        raise IdentificationError("resonance_guess: a load-side log has no anti-resonance to read jm/jl from")
    sp = log_spectrum(log, segment_samples=segment_samples)
    keep = (sp.coherence >= min_coherence) & (sp.freq_hz <= 0.4 / log.sample_period_s)
    if np.count_nonzero(keep) < 16:
        raise IdentificationError(f"resonance_guess: only {np.count_nonzero(keep)} spectrum bins reach coherence "
                                  f"{min_coherence}; excite the axis more (injection amplitude, duration)")
    f, w = sp.freq_hz[keep], sp.coherence[keep]
    la = np.log(sp.apparent_inertia_kgm2[keep])
    wn = w / w.sum()
    rigid = float(np.sum(wn * (la - np.sum(wn * la)) ** 2))
    # Shape with J = 1: fa, fr, damping zeta_a = c / (2 sqrt(k jl)) on a grid; s = j 2 pi f.
    fa = np.geomspace(f[0], f[-1], 64)[:, None, None, None]
    ratio = np.geomspace(1.02, 5.0, 48)[None, :, None, None]
    zeta = np.array([0.01, 0.03, 0.1, 0.3])[None, None, :, None]
    wa = 2 * np.pi * fa
    jm = ratio ** -2.0
    jl = 1.0 - jm
    k = jl * wa ** 2
    c = 2 * zeta * np.sqrt(k * jl)
    s_ = 2j * np.pi * f[None, None, None, :]
    vt = (jl * s_ ** 2 + c * s_ + k) / (s_ * (jm * jl * s_ ** 2 + c * s_ + k))
    lshape = -np.log(np.abs(vt) * 2 * np.pi * f)
    log_j = np.sum(wn * (la - lshape), axis=-1, keepdims=True)
    cost = np.sum(wn * (la - lshape - log_j) ** 2, axis=-1)
    i = np.unravel_index(int(np.argmin(cost)), cost.shape)
    best = float(cost[i])
    if not best * 4 < rigid:
        raise IdentificationError(
            f"resonance_guess: no two-mass resonance in the coherent band {f[0]:.0f}..{f[-1]:.0f} Hz (the best "
            f"two-mass shape fits the spectrum only {rigid / max(best, 1e-300):.1f}x better than a rigid body)")
    j_total = float(np.exp(log_j[i][0]))
    f_anti = float(fa[i[0], 0, 0, 0])
    f_res = f_anti * float(ratio[0, i[1], 0, 0])
    jm_v = j_total * (f_anti / f_res) ** 2
    jl_v = j_total - jm_v
    return ResonanceGuess(jm_v, jl_v, jl_v * (2 * np.pi * f_anti) ** 2, f_anti, f_res, j_total)


# ----------------------------------------------------------------------------------------------------------------
# Results
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Estimate:
    """One parameter: value and standard error in `unit`; fixed ones were held at their initial value."""

    name: str
    value: float
    std_error: float
    unit: str
    initial: float
    fixed: bool
    at_bound: bool

    @property
    def relative_std_error(self) -> float:
        return self.std_error / abs(self.value) if self.value else math.inf

    def __str__(self) -> str:
        if self.fixed:
            return f"{self.name:28s} {self.value:12.6g} {self.unit:10s} (fixed)"
        bound = "  at a bound" if self.at_bound else ""
        return (f"{self.name:28s} {self.value:12.6g} {self.unit:10s} +- {self.std_error:.3g} "
                f"({100 * self.relative_std_error:.2g} %){bound}")


class IdentificationError(ValueError):
    """The data cannot determine a parameter (the message says which, and why)."""


@dataclass(frozen=True)
class IdentifiedPlant:
    """The outcome of :func:`fit_time` or :func:`fit_frequency`.

    model: 'rigid' or 'two_mass'; parameters: name -> :class:`Estimate`; nrmse: residual RMS over the measurement's
    standard deviation (time) or relative complex error (frequency); residual_rms in the measurement's unit (rad, or
    rad/s; nepers/radians for a frequency fit); summary: Ceres-style report; not_identifiable: what the data could not
    determine; time-domain fits keep predicted/residual per sample (NaN outside the segments used).
    """

    model: str
    parameters: dict
    nrmse: float
    residual_rms: float
    converged: bool
    iterations: int
    seconds: float
    summary: str
    not_identifiable: list
    stribeck_exponent: float = 2.0
    time_s: np.ndarray | None = field(default=None, repr=False)
    measured: np.ndarray | None = field(default=None, repr=False)
    predicted: np.ndarray | None = field(default=None, repr=False)
    residual: np.ndarray | None = field(default=None, repr=False)
    freq_hz: np.ndarray | None = field(default=None, repr=False)
    response: np.ndarray | None = field(default=None, repr=False)
    predicted_response: np.ndarray | None = field(default=None, repr=False)
    starts: list = field(default_factory=list, repr=False)
    disagreement: list = field(default_factory=list)
    segment_samples: int | None = None
    linear: bool = False
    start_guess: dict = field(default_factory=dict, repr=False)

    def __getitem__(self, name: str) -> float:
        return self.parameters[_LINEAR_ALIASES.get(name, (name,))[0]].value

    def values(self) -> dict:
        """name -> value (SI)."""
        return {k: e.value for k, e in self.parameters.items()}

    def to_dict(self) -> dict:
        return {k: {"value": e.value, "std_error": e.std_error, "unit": e.unit, "fixed": e.fixed}
                for k, e in self.parameters.items()}

    def __str__(self) -> str:
        if self.linear:  # the axis's own units: m, N, kg
            shown = []
            for e in self.parameters.values():
                alias = _LINEAR_NAMES.get(e.name)
                shown.append(str(dataclasses.replace(e, name=alias[0], unit=alias[1])) if alias else str(e))
        else:
            shown = [str(e) for e in self.parameters.values()]
        return "\n".join([self.summary, ""] + shown)

    @property
    def agrees(self) -> bool:
        """True when every converged start landed within 2 combined standard errors of the others."""
        return not self.disagreement

    def to_plant(self):
        """The identified plant as a :class:`RigidPlant` / :class:`TwoMassPlant` for an :class:`Axis` (and so for the
        model-based tuning rule)."""
        v = {k: e.value for k, e in self.parameters.items() if k != "delay_s"}
        if self.model == "rigid":
            if v["static_nm"] <= v["coulomb_nm"]:
                v["static_nm"] = 0.0
            return _core.RigidPlant(stribeck_exponent=self.stribeck_exponent, **v)
        if v["motor_static_nm"] <= v["motor_coulomb_nm"]:
            v["motor_static_nm"] = 0.0
        return _core.TwoMassPlant(motor_stribeck_exponent=self.stribeck_exponent, **v)

    def plot_residuals(self, *, path: str | None = None, ax=None):
        """Measured vs predicted and the residual (time fits: in encoder-count-sized units of the measurement;
        frequency fits: gain and phase). Returns the figure."""
        import matplotlib.pyplot as plt
        if self.freq_hz is not None:
            fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
            a1.semilogx(self.freq_hz, 20 * np.log10(np.abs(self.response)), "o", ms=3, label="measured")
            a1.semilogx(self.freq_hz, 20 * np.log10(np.abs(self.predicted_response)), "-", label="fitted model")
            a1.set_ylabel("gain, dB")
            a1.legend()
            a2.semilogx(self.freq_hz, np.degrees(np.unwrap(np.angle(self.response))), "o", ms=3)
            a2.semilogx(self.freq_hz, np.degrees(np.unwrap(np.angle(self.predicted_response))), "-")
            a2.set_ylabel("phase, deg")
            a2.set_xlabel("frequency, Hz")
        else:
            fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
            a1.plot(self.time_s, self.measured, lw=0.8, label="measured")
            a1.plot(self.time_s, self.predicted, lw=0.8, label="model (per segment)")
            a1.set_ylabel("measured")
            a1.legend()
            a2.plot(self.time_s, self.residual, lw=0.6)
            a2.set_ylabel("residual")
            a2.set_xlabel("time, s")
        fig.suptitle(f"{self.model} fit: NRMSE {self.nrmse:.3g}")
        fig.tight_layout()
        if path:
            fig.savefig(path, dpi=110)
        return fig


# a linear axis's log fitted by the rotary model (kg*m^2 <-> kg, N*m <-> N, rad <-> m): names and units shown
_LINEAR_NAMES = {"inertia_kgm2": ("mass_kg", "kg"), "viscous_nms": ("viscous_ns_per_m", "N*s/m"),
                 "coulomb_nm": ("coulomb_n", "N"), "static_nm": ("static_n", "N"),
                 "stribeck_speed_rad_s": ("stribeck_speed_m_s", "m/s"), "load_nm": ("offset_n", "N")}
_LINEAR_ALIASES = {v[0]: (k,) for k, v in _LINEAR_NAMES.items()}

_SCALE_PARAMETERS = ("inertia_kgm2", "jm_kgm2", "jl_kgm2", "k_nm_per_rad")


def _setup(model: str, guess: dict, fixed: Iterable[str], bounds: dict | None):
    info = model_parameters(model)
    names = [p["name"] for p in info]
    unknown = set(guess) - set(names)
    if unknown:
        raise ValueError(f"guess: unknown parameter(s) {sorted(unknown)}; the {model} model has {names}")
    fixed = set(fixed)
    if fixed - set(names):
        raise ValueError(f"fixed: unknown parameter(s) {sorted(fixed - set(names))}")
    bounds = dict(bounds or {})
    if set(bounds) - set(names):
        raise ValueError(f"bounds: unknown parameter(s) {sorted(set(bounds) - set(names))}")
    initial, hold, lower, upper = [], [], [], []
    stribeck = "static_nm" if model == "rigid" else "motor_static_nm"
    speed = "stribeck_speed_rad_s" if model == "rigid" else "motor_stribeck_speed_rad_s"
    for p in info:
        n = p["name"]
        if n in guess:
            v = float(guess[n])
            if not math.isfinite(v):
                raise ValueError(f"guess[{n!r}] = {v} is not a finite number")
        else:  # absent: held at its "off" value
            v = 1.0 if n == speed else 0.0
        off = n not in guess or n in fixed
        if n == speed and stribeck not in guess:
            off = True
        initial.append(v)
        hold.append(off)
        lo, hi = p["lower"], math.inf
        if n == speed:
            lo, hi = v / 100, v * 100  # the Stribeck speed is kept within two decades of its guess
        elif n in _SCALE_PARAMETERS and n in guess and v > 0:
            lo = max(lo, v / 1000)  # inertias and stiffness above 1/1000 of their guess (1/J stays finite)
        if n in bounds:
            lo, hi = (float(b) for b in bounds[n])
        lower.append(lo)
        upper.append(hi)
        if not off and not (lo <= v <= hi):
            raise ValueError(f"guess[{n!r}] = {v} is outside its bounds {lo:g}..{hi:g}")
    if all(hold):
        raise ValueError(f"guess: no parameter left to fit (every parameter of the {model} model is absent from "
                         f"guess or in fixed); give a guess for at least one of {names}")
    return names, np.array(initial), hold, np.array(lower), np.array(upper)


def _estimates(ps) -> dict:
    return {p["name"]: Estimate(p["name"], p["value"], p["std_error"], p["unit"], p["initial"], p["fixed"],
                                p["at_bound"]) for p in ps}


def fit_time(log: IdentificationLog, model: str = "rigid", *, guess: dict | None = None, fixed: Iterable[str] = (),
             bounds: dict | None = None, segment_samples: int | str = "auto", initial_segment_samples: int = 250,
             n_starts: int = 3, seed: int = 0, dynamics_hz: float | None = None, max_relative_std_error: float = 0.2,
             strict: bool = True, progress=None, **options) -> IdentifiedPlant:
    """Fits a rigid or two-mass plant to a time log (Ceres; the GIL is released).

    guess
        name -> starting value (SI) of every parameter to estimate; parameters not named are held at 0 (no Stribeck
        peak unless static_nm / motor_static_nm is guessed). None (rigid model, position log): the IDIM-LS answer
        (:func:`servobench.idim_ls`: inertia or mass, viscous and Coulomb friction, offset as load_nm). fixed: names held at their guess. bounds: name ->
        (low, high); the default keeps inertias and the stiffness above 1/1000 of their guess, frictions >= 0, and
        the Stribeck speed within two decades of its guess.
    segment_samples, initial_segment_samples
        the multiple-shooting segment length of the final stage and of the first (doubled in between).
        'auto' (default): from the data -- the correlation time of the IDIM residual, 50..1000 samples
        (:func:`servobench.oefit.segment_length`); 1000 when the IDIM does not apply (two-mass model, speed log,
        no reference and no dynamics_hz).
    n_starts, seed
        the fit runs from the start and n_starts - 1 seeded perturbations of it (each free parameter x 1/1.5..1.5);
        the result is the converged start with the lowest residual, ``starts`` lists them all and
        ``disagreement`` says when converged starts differ beyond 2 combined standard errors.
    dynamics_hz
        the closed loop's dynamics frequency for the IDIM (see :func:`servobench.idim_ls`); None: from the log.
    loss
        'none', 'huber', 'soft_l1' or 'cauchy', departing from least squares at loss_scale_counts encoder counts.
    direction_window, rest_threshold_counts, edge_samples
        the segmentation into one-way motion: the direction is the sign of the measured change over
        direction_window samples once it reaches rest_threshold_counts counts; edge_samples are trimmed at both ends
        of every run (rest phases and reversals are not fitted: a segment simulated through a stick-slip event can
        trap the solver).
    start
        where a two-mass fit starts its inertias and stiffness: 'auto' (default) from :func:`resonance_guess` when the
        log's spectrum shows the resonance, else the guess; 'spectrum' (the same, but an error when it does not);
        'guess' (the guess as given). A time-domain fit started with the resonance ~30 % off can settle in another
        local minimum; the spectrum puts it within a few per cent. Rigid fits always start from the guess.
    hold_stribeck_first
        with the Stribeck peak free, solve a first stage with its level and speed held at their guesses (far from
        the truth, the peak otherwise tends to vanish, ws -> 0, and stay vanished).
    max_relative_std_error
        standard errors are Ceres' times sqrt(long-run variance / variance) of the residual (correlated residuals,
        :func:`servobench.oefit.long_run_variance_ratio`); a parameter whose standard error exceeds this fraction
        of its own value is not identifiable.
    strict
        raise :class:`IdentificationError` (a ValueError) naming the parameters the data cannot determine; with
        False they are reported in ``not_identifiable`` and their standard error is inf.
    num_threads
        Ceres threads. 1 (default) is deterministic: the same log gives bit-identical estimates. More threads evaluate
        the segments in parallel (about 1.7x faster on 2 cores) but Ceres then sums the Schur complement in a
        varying order, so estimates differ from run to run at ~1e-8 relative and iteration counts by a few.
    progress
        None, or a callable(iteration, cost) -> bool (False stops the solve).
    """
    from . import oefit
    from .idim import idim_ls

    model = _model(model)
    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (see IdentificationLog.from_arrays / run_experiment)")
    n_starts = _whole("fit_time", "n_starts", n_starts, 1, 20)
    notes = []
    idim = None
    idim_ok = model == "rigid" and not log.measured_is_speed and (log.reference is not None or dynamics_hz)
    if idim_ok and (guess is None or segment_samples == "auto"):
        try:
            idim = idim_ls(log, dynamics_hz=dynamics_hz)
        except ValueError as e:
            if guess is None:
                raise ValueError(f"fit_time: no guess and the IDIM start failed: {e}") from None
            notes.append(f"IDIM not used ({e})")
    if guess is None:
        if idim is None:
            raise ValueError("fit_time: give a guess (name -> starting value); the IDIM start needs a rigid model, a "
                             "position log and the log's reference or dynamics_hz")
        guess = oefit.start_from_idim(idim)
        notes.append("Start: the IDIM-LS answer (" + ", ".join(f"{k} = {v:.6g}" for k, v in guess.items()) + ").")
    if isinstance(segment_samples, str):
        if segment_samples != "auto":
            raise ValueError(f"fit_time.segment_samples = {segment_samples!r} must be 'auto' or a whole number")
        if idim is not None:
            segment_samples, how = oefit.segment_length(idim)
            notes.append("Segments: " + how + ".")
        else:
            segment_samples = 1000
            notes.append("Segments: 1000 samples (the IDIM does not apply to this log).")
    segment_samples = _whole("fit_time", "segment_samples", segment_samples, 20, 10**8)
    initial_segment_samples = min(_whole("fit_time", "initial_segment_samples", initial_segment_samples, 20, 10**8),
                                  segment_samples)
    free = set(guess) - set(fixed)
    fits = []
    for i, g in enumerate(oefit.perturbed_starts(guess, free, n_starts, seed)):
        try:
            fits.append(_fit_once(log, model, guess=g, fixed=fixed, bounds=bounds, segment_samples=segment_samples,
                                  initial_segment_samples=initial_segment_samples,
                                  max_relative_std_error=max_relative_std_error, strict=False, progress=progress,
                                  **options))
        except ValueError:
            if i == 0:
                raise
    converged = [f for f in fits if f.converged]
    best = min(converged or fits, key=lambda f: f.residual_rms)
    ratio = oefit.long_run_variance_ratio(best.residual) if best.residual is not None else 1.0
    k = math.sqrt(ratio)
    params = {n: Estimate(e.name, e.value, e.std_error * k, e.unit, e.initial, e.fixed, e.at_bound)
              for n, e in best.parameters.items()}
    inflated = [dataclasses.replace(f, parameters={n: dataclasses.replace(e, std_error=e.std_error * k)
                                                   for n, e in f.parameters.items()}) for f in fits]
    disagree = oefit.disagreements(inflated)
    not_id = [x for x in best.not_identifiable if "too weakly excited" not in x]
    for n, e in params.items():
        if not e.fixed and math.isfinite(e.std_error) and e.std_error > max_relative_std_error * abs(e.value) \
                and not any(x.startswith(n + ":") for x in not_id):
            not_id.append(f"{n}: relative standard error {100 * e.relative_std_error:.3g} % above "
                          f"{100 * max_relative_std_error:.3g} % of its value: too weakly excited")
    if strict and not_id:
        raise IdentificationError("the log cannot determine: " + "; ".join(not_id) +
                                  " -- excite the axis more (longer log, more speed range or reversals), or fix "
                                  "these parameters (fixed=...)")
    notes.append(f"Standard errors x {k:.3g} for correlated residuals (long-run / plain variance {ratio:.3g}).")
    notes.append(f"Starts: {len(fits)}, converged {len(converged)}" +
                 (("; DISAGREE beyond their error bars: " + "; ".join(disagree[:3])) if disagree else
                  ", agreeing within their error bars") + ".")
    return dataclasses.replace(best, parameters=params, not_identifiable=not_id,
                               summary=best.summary + "\n" + "\n".join(notes), starts=inflated,
                               disagreement=disagree, segment_samples=segment_samples, linear=log.linear,
                               start_guess=dict(guess))


def _fit_once(log: IdentificationLog, model: str = "rigid", *, guess: dict, fixed: Iterable[str] = (),
             bounds: dict | None = None, segment_samples: int = 1000, initial_segment_samples: int = 250,
             loss: str = "none", loss_scale_counts: float = 3.0, stribeck_exponent: float = 2.0,
             max_iterations: int = 200, num_threads: int = 1, max_relative_std_error: float = 0.2,
             direction_window: int = 6, rest_threshold_counts: float = 2.0, edge_samples: int = 3,
             start: str = "auto", hold_stribeck_first: bool = True, strict: bool = True,
             progress=None) -> IdentifiedPlant:
    """One output-error fit from one start (see :func:`fit_time`)."""
    model = _model(model)
    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (see IdentificationLog.from_arrays / run_experiment)")
    if start not in ("auto", "spectrum", "guess"):
        raise ValueError(f"fit_time.start = {start!r} must be 'auto', 'spectrum' or 'guess'")
    start_note = ""
    if model == "two_mass" and start != "guess":
        free = {"jm_kgm2", "jl_kgm2", "k_nm_per_rad"} & set(guess) - set(fixed)
        try:
            rg = resonance_guess(log)
        except IdentificationError as e:
            if start == "spectrum":
                raise
            start_note = f"\nStart: the guess ({e})."
        else:
            guess = dict(guess)
            guess.update({k: v for k, v in rg.as_guess().items() if k in free})
            start_note = (f"\nStart: {', '.join(sorted(free))} from the log's spectrum (anti-resonance "
                          f"{rg.anti_resonance_hz:.1f} Hz, resonance {rg.resonance_hz:.1f} Hz, total inertia "
                          f"{rg.total_inertia_kgm2:.4g} kg*m^2).")
    names, initial, hold, lower, upper = _setup(model, guess, fixed, bounds)
    if all(hold):
        raise ValueError("guess: no parameter to estimate")
    scale = log.count_rad if not log.measured_is_speed else log.count_rad / log.sample_period_s
    r = _core.identify_time(
        log.torque_nm, log.measured, sample_period_s=log.sample_period_s, measured_is_speed=log.measured_is_speed,
        measured_on_load=log.measured_on_load, model=model, initial=initial, fixed=hold, lower=lower, upper=upper,
        segment_samples=segment_samples, initial_segment_samples=initial_segment_samples, min_segment_samples=20,
        edge_samples=edge_samples, direction_window=direction_window, rest_threshold=rest_threshold_counts,
        substeps=log.substeps,
        current_bw_hz=log.current_bw_hz, stribeck_exponent=stribeck_exponent, measurement_scale=scale,
        continuity_weight=0.0, loss=loss, loss_scale=loss_scale_counts, max_iterations=max_iterations,
        num_threads=num_threads, max_relative_std_error=max_relative_std_error,
        hold_stribeck_first=hold_stribeck_first, progress=progress)
    s = r["summary"]
    if strict and s["not_identifiable"]:
        raise IdentificationError("the log cannot determine: " + "; ".join(s["not_identifiable"]) +
                                  " -- excite the axis more (longer log, more speed range or reversals), or fix "
                                  "these parameters (fixed=...)")
    return IdentifiedPlant(model, _estimates(r["parameters"]), s["nrmse"], s["residual_rms"], s["converged"],
                           s["iterations"], s["seconds"], s["report"] + start_note, list(s["not_identifiable"]),
                           stribeck_exponent, log.time_s, log.measured, r["predicted"], r["residual"])


_BODE_UNITS = {"hz": ("freq", 1.0), "rad/s": ("freq", 1 / (2 * math.pi)), "db": ("gain", "db"),
               "abs": ("gain", "abs"), "deg": ("phase", math.pi / 180), "rad": ("phase", 1.0)}


def frequency_input(response):
    """(freq_hz, complex response, coherence or None) of a measured response given as a servobench
    :class:`FrequencyResponse` (its plant Y/U), a python-control ``FRD`` (frequencies in rad/s), the path of a Bode
    CSV (a header row with unit tags: frequency ``[Hz]`` or ``[rad/s]``, gain ``[dB]`` or ``[abs]``, phase ``[deg]``
    or ``[rad]``; pandas), or a (freq_hz, complex) pair. ValueError naming what is wrong."""
    if hasattr(response, "freq_hz"):
        coh = getattr(response, "coherence", None)
        return (np.asarray(response.freq_hz, float), np.asarray(response.response("plant")),
                None if coh is None else np.asarray(coh, float))
    if hasattr(response, "omega") and (hasattr(response, "frdata") or hasattr(response, "fresp")):
        data = np.asarray(response.frdata if hasattr(response, "frdata") else response.fresp)
        if data.ndim == 3:
            if data.shape[:2] != (1, 1):
                raise ValueError(f"fit_frequency: the FRD has {data.shape[0]} outputs x {data.shape[1]} inputs; "
                                 "give a single-input single-output response")
            data = data[0, 0]
        return np.asarray(response.omega, float) / (2 * math.pi), np.asarray(data, complex).ravel(), None
    if isinstance(response, (str, bytes)) or hasattr(response, "__fspath__"):
        from .idlog import finite_column, read_csv

        cols = read_csv(str(response) if not isinstance(response, bytes) else response.decode())
        roles = {}
        for name, (values, unit) in cols.items():
            if unit is None:
                continue
            u = unit.strip().lower()
            if u not in _BODE_UNITS:
                raise ValueError(f"{response}: column {name!r}: unit {unit!r} is not a Bode unit "
                                 f"({', '.join(['Hz', 'rad/s', 'dB', 'abs', 'deg', 'rad'])})")
            role, conv = _BODE_UNITS[u]
            if role in roles:
                raise ValueError(f"{response}: two {role} columns ({roles[role][0]!r} and {name!r})")
            roles[role] = (name, conv, finite_column(name, values))
        missing = [r for r in ("freq", "gain", "phase") if r not in roles]
        if missing:
            raise ValueError(f"{response}: no {' / '.join(missing)} column with a unit tag (e.g. 'f [Hz]', "
                             "'gain [dB]', 'phase [deg]')")
        f = roles["freq"][2] * roles["freq"][1]
        gain = roles["gain"][2]
        mag = 10 ** (gain / 20) if roles["gain"][1] == "db" else gain
        return f, mag * np.exp(1j * roles["phase"][2] * roles["phase"][1]), None
    try:
        f, g = (np.asarray(a) for a in response)
    except (TypeError, ValueError):
        raise TypeError("fit_frequency: response must be a FrequencyResponse, a control.FRD, a Bode CSV path or a "
                        "(freq_hz, complex) pair") from None
    return np.asarray(f, float), np.asarray(g, complex), None


def fit_frequency(response, axis, model: str = "rigid", *, guess: dict, fixed: Iterable[str] = (),
                  bounds: dict | None = None, fit_delay: bool = False, delay_s: float = 0.0, weight=None,
                  max_iterations: int = 200, max_relative_std_error: float = 0.2, strict: bool = True,
                  progress=None) -> IdentifiedPlant:
    """Fits the mechanics of `axis` to a measured plant response Y/U (U in DAC counts, Y in pulse: the ``plant`` of a
    :func:`servobench.frequency.sine_sweep` or :func:`broadband_response`, a python-control ``FRD`` (rad/s), a Bode
    CSV (Hz or rad/s, dB, deg; see :func:`frequency_input`) or (freq_hz, complex) arrays).

    The model is the axis's own analytic plant response with its mechanics replaced (friction is invisible to a
    linear response: only inertias, stiffness, damping and viscous friction are fitted), optionally times an extra
    delay exp(-j w tau) (`fit_delay`, starting at delay_s) for lags a real machine adds. The residual is the complex
    log-ratio (nepers and radians), weighted by `weight` (default: the measurement's coherence if it has one).
    """
    model = _model(model)
    f, g, coh = frequency_input(response)
    if weight is None and coh is not None:
        weight = coh
    names, initial, hold, lower, upper = _setup(model, guess, fixed, bounds)
    w = np.ones(len(f)) if weight is None else np.asarray(weight, float)
    core_axis = getattr(axis, "_axis", axis)
    r = _core.identify_frequency(core_axis, f.astype(float), g.astype(complex), weight=w, model=model,
                                 initial=initial, fixed=hold, lower=lower, upper=upper, fit_delay=fit_delay,
                                 delay_initial_s=delay_s, max_iterations=max_iterations,
                                 max_relative_std_error=max_relative_std_error, progress=progress)
    s = r["summary"]
    if strict and s["not_identifiable"]:
        raise IdentificationError("the response cannot determine: " + "; ".join(s["not_identifiable"]))
    return IdentifiedPlant(model, _estimates(r["parameters"]), s["nrmse"], s["residual_rms"], s["converged"],
                           s["iterations"], s["seconds"], s["report"], list(s["not_identifiable"]), 2.0,
                           freq_hz=f, response=g, predicted_response=r["predicted"])
