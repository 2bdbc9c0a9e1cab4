"""Plant identification: experiments on an axis, and grey-box fits of its mechanics with Ceres.

The time-domain fit (:func:`fit_time`) estimates a rigid or two-mass plant -- inertias, stiffness, damping, viscous,
Coulomb and Stribeck friction, a constant load -- from a log of the drive's torque command and the measured position
(or speed). Its model is the simulator's own plant code (the same matrices, the same exact zero-order hold, the same
dry-friction sub-step, templated in C++ so that Ceres differentiates it); the fit is an output-error fit by multiple
shooting over the stretches of one-way motion, with a segment-length continuation that makes it converge from
guesses 50 % off. The frequency-domain fit (:func:`fit_frequency`, module :mod:`servobench.frequency_fit`) matches
the axis's analytic plant response -- or, without an Axis, the mechanics described by a :class:`MechanicsIO` -- to a
measured response. The experiments (:func:`run_experiment`, :func:`excitation`) are in :mod:`servobench.experiment`.
Both fits return an :class:`IdentifiedPlant`: estimates with standard errors, fit quality, the parameters the data
could not determine, a residual plot, and :meth:`IdentifiedPlant.to_plant` for simulation and tuning.

Units: torque N*m, angles rad, speeds rad/s, inertias kg*m^2, time s; the log's measured position may be given in
pulses with the encoder's counts per revolution.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Iterable

import numpy as np

from . import _checks, _core
from . import _options as _opts
from .experiment import _whole, excitation, run_experiment, torque_per_volt  # noqa: F401 (re-exported)
from ._serialise import JsonResult, dataframe
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
# Spectral view of a log: the starting point of a two-mass fit
# ----------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LogSpectrum(JsonResult):
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

    def to_dataframe(self):
        """One row per bin (index freq_hz, Hz): gain_db (dB re 1 (rad/s)/(N*m)), phase_deg, coherence,
        apparent_inertia_kgm2."""
        with np.errstate(divide="ignore"):
            db = 20 * np.log10(np.abs(self.response))
        return dataframe({"freq_hz": self.freq_hz, "gain_db": db, "phase_deg": np.degrees(np.angle(self.response)),
                          "coherence": self.coherence, "apparent_inertia_kgm2": self.apparent_inertia_kgm2},
                         {"freq_hz": "Hz", "gain_db": "dB", "phase_deg": "deg", "coherence": "1",
                          "apparent_inertia_kgm2": "kg*m^2"}, index="freq_hz")


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
class ResonanceGuess(JsonResult):
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
class Estimate(JsonResult):
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


@_opts.described_result(_core.FIT_SUMMARY_FIELDS, lead=("model", "parameters"))
class IdentifiedPlant(JsonResult):
    """The outcome of :func:`fit_time` or :func:`fit_frequency`.

    model: 'rigid' or 'two_mass'; parameters: name -> :class:`Estimate`; then the solver's figures, read from the
    C++ summary (identify/fit_report.hpp, decision OQ6):

    {fields}

    summary: Ceres-style report; not_identifiable: what the data could not
    determine; time-domain fits keep predicted/residual per sample (NaN outside the segments used); warnings: what the
    data say against the model (:attr:`misfit`); segment_states: a time fit's fitted start state of every shooting
    segment (segments x state size: angle rad and speed rad/s of each mass, the fit's internal layout), where its
    error bars are evaluated.
    """

    model: str
    parameters: dict
    # nrmse ... seconds follow, read at import from identify::FitSummary::describe() with their units and docs;
    # static type checkers read these names (test_options_once checks they match).
    if TYPE_CHECKING:
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
    warnings: list = field(default_factory=list)
    asymmetry_p_value: float = math.nan
    lead_m_per_rev: float | None = None
    segment_states: np.ndarray | None = field(default=None, repr=False, compare=False)

    @property
    def misfit(self) -> bool:
        """True when the data reject the fitted friction model (a rigid time fit: the segment score test of
        Fv+ = Fv- at the 1 % level; see ``warnings``)."""
        return bool(self.asymmetry_p_value < 0.01)

    def __getitem__(self, name: str) -> float:
        return self.parameters[_LINEAR_ALIASES.get(name, (name,))[0]].value

    def values(self) -> dict:
        """name -> value (SI)."""
        return {k: e.value for k, e in self.parameters.items()}

    def to_dict(self) -> dict:
        return {k: {"value": e.value, "std_error": e.std_error, "unit": e.unit, "fixed": e.fixed}
                for k, e in self.parameters.items()}

    def to_dataframe(self, which: str = "parameters"):
        """A pandas DataFrame: ``"parameters"`` (default) one row per parameter (index ``name``: value, std_error,
        relative_std_error, unit, initial, fixed, at_bound); ``"samples"`` the time-domain fit per sample (time_s,
        measured, predicted, residual; NaN outside the segments used); ``"frequency"`` the frequency fit per point
        (freq_hz; measured and predicted response as gain in dB and phase in deg)."""
        if which == "parameters":
            rows = list(self.parameters.values())
            return dataframe({"name": [e.name for e in rows], "value": [e.value for e in rows],
                              "std_error": [e.std_error for e in rows],
                              "relative_std_error": [e.relative_std_error for e in rows],
                              "unit": [e.unit for e in rows], "initial": [e.initial for e in rows],
                              "fixed": [e.fixed for e in rows], "at_bound": [e.at_bound for e in rows]},
                             index="name")
        if which == "samples":
            if self.time_s is None:
                raise ValueError("to_dataframe: this is a frequency-domain fit: use which='frequency'")
            return dataframe({"time_s": self.time_s, "measured": self.measured, "predicted": self.predicted,
                              "residual": self.residual}, {"time_s": "s"})
        if which == "frequency":
            if self.freq_hz is None:
                raise ValueError("to_dataframe: this is a time-domain fit: use which='samples'")
            cols = {"freq_hz": self.freq_hz}
            for name, h in (("measured", self.response), ("predicted", self.predicted_response)):
                with np.errstate(divide="ignore"):
                    cols[f"{name}_db"] = 20 * np.log10(np.abs(h))
                cols[f"{name}_deg"] = np.degrees(np.angle(h))
            return dataframe(cols, {"freq_hz": "Hz", "measured_db": "dB", "measured_deg": "deg",
                                    "predicted_db": "dB", "predicted_deg": "deg"}, index="freq_hz")
        raise ValueError(f"to_dataframe: which = {which!r} must be 'parameters', 'samples' or 'frequency'")

    def __str__(self) -> str:
        if self.linear:  # the axis's own units: m, N, kg
            shown = []
            for e in self.parameters.values():
                alias = _LINEAR_NAMES.get(e.name)
                shown.append(str(dataclasses.replace(e, name=alias[0], unit=alias[1])) if alias else str(e))
            from .idlog import motor_side_line

            side = motor_side_line([(_LINEAR_NAMES[e.name][0], e.value, _LINEAR_NAMES[e.name][1])
                                    for e in self.parameters.values() if e.name in _LINEAR_NAMES],
                                   self.lead_m_per_rev)
            if side:
                shown.append(side)
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


# The options of the time fit a caller gives (identify/time_fit.hpp's TimeFitOptions, described once there; decision
# OQ2); the others come from the log (substeps, current loop, measurement scale) or keep the struct's default. Two keep
# the Python names they have long had: fit_time sets the measurement scale to one encoder count.
_TIME_OPTIONS = ("segment_samples", "initial_segment_samples", "edge_samples", "direction_window", "rest_threshold",
                 "stribeck_exponent", "loss_scale", "hold_stribeck_first", "max_iterations", "num_threads",
                 "max_relative_std_error")
_TIME_RENAME = {"rest_threshold": "rest_threshold_counts", "loss_scale": "loss_scale_counts"}
_TIME_UNITS = {"rest_threshold_counts": "counts", "loss_scale_counts": "counts"}
_TIME = {f.name: f.default for f in _opts.option_fields(_core.TimeFitOptions, _TIME_OPTIONS, _TIME_RENAME)}


@_opts.documents_options(
    _core.TimeFitOptions, only=_TIME_OPTIONS, rename=_TIME_RENAME, units=_TIME_UNITS,
    python_defaults={"segment_samples": _opts.PythonDefault(
        "auto", None, "'auto' (default): from the data -- the correlation time of the IDIM residual, 50..1000 "
        "samples (:func:`servobench.oefit.segment_length`); the struct's default when the IDIM does not apply "
        "(two-mass model, speed log, no reference and no dynamics_hz).")},
    notes={"max_relative_std_error": "Standard errors are the segment-clustered sandwich for correlated residuals "
           "(:func:`servobench.oefit.segment_sandwich`; with a robust loss Ceres' times sqrt(long-run / plain "
           "variance) of the residual)."},
    name="fit_time")
def _fit_time(log: IdentificationLog, model: str = "rigid", *, guess: dict | None = None, fixed: Iterable[str] = (),
             bounds: dict | None = None, segment_samples: int | str = "auto",
             initial_segment_samples: int = _TIME["initial_segment_samples"],
             n_starts: int = 3, seed: int = 0, dynamics_hz: float | None = None,
             max_relative_std_error: float = _TIME["max_relative_std_error"],
             strict: bool = True, progress=None, start_threads: int = 1, **options) -> IdentifiedPlant:
    """Fits a rigid or two-mass plant to a time log (Ceres; the GIL is released).

    guess
        name -> starting value (SI) of every parameter to estimate; parameters not named are held at 0 (no Stribeck
        peak unless static_nm / motor_static_nm is guessed). None (rigid model, position log): the IDIM-LS answer
        (:func:`servobench.idim_ls`: inertia or mass, viscous and Coulomb friction, offset as load_nm). fixed: names
        held at their guess. bounds: name -> (low, high); the default keeps inertias and the stiffness above 1/1000
        of their guess, frictions >= 0, and the Stribeck speed within two decades of its guess.
    {options}
    n_starts, seed
        the fit runs from the start and n_starts - 1 seeded perturbations of it (each free parameter x 1/1.5..1.5);
        the result is the converged start with the lowest residual, ``starts`` lists them all and
        ``disagreement`` says when converged starts differ beyond 2 combined standard errors. ``converged`` needs a
        second converged start at the best one's point (decision J43), unless the best start is at the encoder's
        resolution floor (:data:`RESOLUTION_FLOOR_COUNTS`) and every other start ended at least 2x worse (J47).
    dynamics_hz
        the closed loop's dynamics frequency for the IDIM (see :func:`servobench.idim_ls`); None: from the log.
    loss
        'none' (default), 'huber', 'soft_l1' or 'cauchy', departing from least squares at loss_scale_counts encoder
        counts.
    start
        where a two-mass fit starts its inertias and stiffness: 'auto' (default) from :func:`resonance_guess` when the
        log's spectrum shows the resonance, else the guess; 'spectrum' (the same, but an error when it does not);
        'guess' (the guess as given). A time-domain fit started with the resonance ~30 % off can settle in another
        local minimum; the spectrum puts it within a few per cent. Rigid fits always start from the guess.
    strict
        raise :class:`IdentificationError` (a ValueError) naming the parameters the data cannot determine; with
        False they are reported in ``not_identifiable`` and their standard error is inf.
    start_threads
        how many starts run at once (default 1: one after the other). Threads help wall time only: the starts
        are independent one-thread solves that release the GIL, so they overlap (measured 1.47x less wall time for
        3 starts on 2 shared cores) but the CPU time is the sum of the starts (0.4-0.7 s each on the 5 s bench
        experiment). Results do not depend on it. With `progress` the starts run one after the other. Ctrl-C
        stops a parallel run at every start's next iteration, which on a loaded machine took 0.6 s (one iteration
        of a 100,000-sample fit), hence the sequential default.
    progress
        None, or a callable(iteration, cost) -> bool (False stops the solve).
    """
    from . import oefit
    from .idim import idim_ls

    model = _model(model)
    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (see IdentificationLog.from_arrays / run_experiment)")
    n_starts = _whole("fit_time", "n_starts", n_starts, 1, 20)
    start_threads = _whole("fit_time", "start_threads", start_threads, 1, 64)
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
            segment_samples = _TIME["segment_samples"]
            notes.append(f"Segments: {segment_samples} samples (the IDIM does not apply to this log).")
    segment_samples = _whole("fit_time", "segment_samples", segment_samples, 20, 10**8)
    initial_segment_samples = min(_whole("fit_time", "initial_segment_samples", initial_segment_samples, 20, 10**8),
                                  segment_samples)
    free = set(guess) - set(fixed)
    spectrum = None  # the log's spectrum does not depend on the start: read once for all starts (decision FT3)
    if model == "two_mass" and options.get("start", "auto") in ("auto", "spectrum") and not log.measured_on_load and \
            log.extra.get("injection_v") is not None:
        try:
            spectrum = resonance_guess(log)
        except IdentificationError as e:
            spectrum = e

    def fit_one(g, prog):
        return _fit_once(log, model, spectrum, guess=g, fixed=fixed, bounds=bounds,
                         segment_samples=segment_samples, initial_segment_samples=initial_segment_samples,
                         max_relative_std_error=max_relative_std_error, strict=False, progress=prog, **options)

    fits = oefit.run_starts(fit_one, oefit.perturbed_starts(guess, free, n_starts, seed), threads=start_threads,
                            progress=progress)
    converged = [f for f in fits if f.converged]
    best = min(converged or fits, key=lambda f: f.residual_rms)
    factor, se_note, sw = _correlated_errors(best, log, model, segment_samples, options)
    warnings = []
    if sw is not None and sw.asymmetry_p_value < 0.01:
        u = "N*s/m" if log.linear else "N*m*s/rad"
        warnings.append(f"friction is asymmetric (robust score test of Fv+ = Fv- over the segments: p = "
                        f"{sw.asymmetry_p_value:.2g}, Fv+ - Fv- about {sw.asymmetry_viscous:.4g} {u}): the symmetric "
                        "friction model is mis-specified; use idim_ls(log, friction='asymmetric') or identify_rigid")
    params = {n: Estimate(e.name, e.value, _scaled(e, factor), e.unit, e.initial, e.fixed, e.at_bound)
              for n, e in best.parameters.items()}
    inflated = [dataclasses.replace(f, parameters={n: dataclasses.replace(e, std_error=_scaled(e, factor))
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
    notes.append(se_note)
    notes += ["WARNING: " + w for w in warnings]
    notes.append(f"Starts: {len(fits)}, converged {len(converged)}" +
                 (("; DISAGREE beyond their error bars: " + "; ".join(disagree[:3])) if disagree else
                  ", agreeing within their error bars") + ".")
    conv_ids = {id(f) for f in converged}
    best_scaled = dataclasses.replace(best, parameters=params)  # error bars with the correlated-residual factor
    confirmed = any(_same_point(best_scaled, g, 1.0) for f, g in zip(fits, inflated)
                    if id(f) in conv_ids and f is not best)
    # A best start at the encoder's resolution floor needs no second start to confirm it when every other start
    # ended in a distinct, clearly worse minimum (decision J47): no other point can explain the log better.
    at_floor = best.residual_rms / log.measurement_count <= RESOLUTION_FLOOR_COUNTS
    others_worse = all(f.residual_rms >= 2.0 * best.residual_rms for f in fits if f is not best)
    alone = best.converged and len(fits) > 1 and not confirmed and not (at_floor and others_worse)
    if best.converged and len(fits) > 1 and not confirmed and not alone:
        notes.append(f"The best start is at the resolution floor ({best.residual_rms / log.measurement_count:.3g} "
                     f"count RMS) and every other start ended at least 2x worse: the point is the log's best.")
    if alone:  # the solver stopped, but no other start confirms the point (decision J43)
        notes.append("NOT CONVERGED: no other start ends at the best start's point (within 2 standard errors or "
                     "5 %): the answer depends on where the fit starts (a local minimum). Give a better guess or a "
                     "log that excites the resonance.")
    return dataclasses.replace(best, parameters=params, not_identifiable=not_id, converged=best.converged and not alone,
                               summary=best.summary + "\n" + "\n".join(notes), starts=inflated,
                               disagreement=disagree, segment_samples=segment_samples, linear=log.linear,
                               start_guess=dict(guess), warnings=warnings,
                               lead_m_per_rev=log.lead_m_per_rev if log.linear else None,
                               asymmetry_p_value=sw.asymmetry_p_value if sw is not None else math.nan)


# typed signature of fit_time (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def fit_time(log: IdentificationLog, model: str = 'rigid', *, guess: dict | None = None, fixed: Iterable[str] = (),
                 bounds: dict | None = None, segment_samples: int | str = 'auto', initial_segment_samples: int = 250,
                 n_starts: int = 3, seed: int = 0, dynamics_hz: float | None = None,
                 max_relative_std_error: float = 0.2, strict: bool = True, progress=None, start_threads: int = 1,
                 loss: str = 'none', loss_scale_counts: float = 3.0, stribeck_exponent: float = 2.0,
                 max_iterations: int = 200, num_threads: int = 1, direction_window: int = 6,
                 rest_threshold_counts: float = 2.0, edge_samples: int = 3, start: str = 'auto',
                 hold_stribeck_first: bool = True) -> IdentifiedPlant: ...
else:
    fit_time = _fit_time
# end of the typed signature of fit_time


#: A residual RMS at or below this, in counts, is the encoder's quantisation floor (1/sqrt(12) = 0.289 count) plus
#: 20 %: nothing left for another minimum to explain (decision J47).
RESOLUTION_FLOOR_COUNTS = 1.2 / math.sqrt(12.0)


def _scaled(e: Estimate, factor: dict) -> float:
    return e.std_error * factor.get(e.name, 1.0) if math.isfinite(e.std_error) else e.std_error


def _correlated_errors(best: IdentifiedPlant, log: IdentificationLog, model: str, segment_samples: int,
                       options: dict) -> tuple[dict, str, object]:
    """(name -> factor from Ceres' white-noise standard error to the one reported, note): the segment-clustered
    sandwich (:func:`servobench.oefit.segment_sandwich`) for least squares; the long-run / plain variance ratio of
    the residual for a robust loss (whose weights the sandwich does not model) or when the sandwich fails; and the
    :class:`~servobench.oefit.SegmentSandwich` (None in those cases)."""
    from . import oefit

    free = {n for n, e in best.parameters.items() if not e.fixed and math.isfinite(e.std_error)}
    if options.get("loss", "none") == "none" and free:
        try:
            sw = oefit.segment_sandwich(log, model, best.values(), free, segment_samples, options,
                                        states=best.segment_states)
        except (ValueError, IndexError, np.linalg.LinAlgError) as err:
            sw, why = None, str(err)
        else:
            fit_rms = best.residual_rms / log.measurement_count
            if not sw.residual_rms <= 1.05 * fit_rms + 1e-12:  # the sandwich must stand where the fit ended (J46)
                sw, why = None, (f"its segment states give a residual RMS of {sw.residual_rms:.4g} counts, the fit's "
                                 f"{fit_rms:.4g}")
        if sw is not None:
            cov = sw.covariance
            names = sw.names
            se = {n: math.sqrt(max(cov[i, i], 0.0)) for i, n in enumerate(names)}
            stat = "static_nm" if model == "rigid" else "motor_static_nm"
            coul = "coulomb_nm" if model == "rigid" else "motor_coulomb_nm"
            if stat in se and coul in se:  # back to the breakaway level: var(Fs) = var(Fc) + var(e) + 2 cov(Fc, e)
                a, b = names.index(coul), names.index(stat)
                se[stat] = math.sqrt(max(cov[a, a] + cov[b, b] + 2 * cov[a, b], 0.0))
            # never below the white-noise value: with few segments the sandwich is itself uncertain (J19)
            factor = {n: max(se[n] / best.parameters[n].std_error, 1.0) for n in se
                      if best.parameters[n].std_error > 0}
            if all(math.isfinite(f) and f > 0 for f in factor.values()):
                lo, hi = min(factor.values()), max(factor.values())
                return factor, (f"Standard errors: sandwich clustered by segment ({sw.segments} segments, Newey-West "
                                f"over {sw.lags} neighbouring segments, never below the white-noise values), "
                                f"{lo:.3g}..{hi:.3g} x the white-noise values."), sw
            why = "non-finite sandwich"
        note_why = f" (the segment sandwich failed: {why})"
    else:
        note_why = " (robust loss)" if free else ""
    ratio = oefit.long_run_variance_ratio(best.residual) if best.residual is not None else 1.0
    k = math.sqrt(ratio)
    return ({n: k for n in best.parameters},
            f"Standard errors x {k:.3g} for correlated residuals (long-run / plain variance {ratio:.3g}){note_why}.",
            None)


def _same_point(a, b, inflate: float) -> bool:
    """Two fits end at the same point: every free parameter within 2 combined standard errors (x inflate) or 5 %."""
    for n, e in a.parameters.items():
        if e.fixed:
            continue
        v = b.parameters[n].value
        tol = max(2 * inflate * math.hypot(e.std_error, b.parameters[n].std_error), 0.05 * abs(e.value))
        if not abs(e.value - v) <= tol:
            return False
    return True


def _fit_once(log: IdentificationLog, model: str = "rigid", spectrum=None, /, *, guess: dict, fixed: Iterable[str] = (),
             bounds: dict | None = None, segment_samples: int = _TIME["segment_samples"],
             initial_segment_samples: int = _TIME["initial_segment_samples"], loss: str = "none",
             loss_scale_counts: float = _TIME["loss_scale_counts"],
             stribeck_exponent: float = _TIME["stribeck_exponent"], max_iterations: int = _TIME["max_iterations"],
             num_threads: int = _TIME["num_threads"], max_relative_std_error: float = _TIME["max_relative_std_error"],
             direction_window: int = _TIME["direction_window"],
             rest_threshold_counts: float = _TIME["rest_threshold_counts"], edge_samples: int = _TIME["edge_samples"],
             start: str = "auto", hold_stribeck_first: bool = _TIME["hold_stribeck_first"], strict: bool = True,
             progress=None) -> IdentifiedPlant:
    """One output-error fit from one start (see :func:`fit_time`). spectrum (positional only, so that it is not one
    of fit_time's options): the log's :func:`resonance_guess` (or the IdentificationError it raised) when the caller
    already has it (fit_time reads it once for all starts)."""
    model = _model(model)
    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (see IdentificationLog.from_arrays / run_experiment)")
    if start not in ("auto", "spectrum", "guess"):
        raise ValueError(f"fit_time.start = {start!r} must be 'auto', 'spectrum' or 'guess'")
    start_note = ""
    if model == "two_mass" and start == "auto" and log.extra.get("injection_v") is None:
        # Without the injection the closed loop biases the spectrum (H1 = S_uv/S_uu fills the anti-resonance with
        # the controller's inverse): the guess, not a misread resonance (decision J42).
        start_note = ("\nStart: the guess (the log has no injection signal; its closed-loop spectrum would misplace "
                      "the resonance).")
    elif model == "two_mass" and start != "guess":
        free = {"jm_kgm2", "jl_kgm2", "k_nm_per_rad"} & set(guess) - set(fixed)
        try:
            rg = resonance_guess(log) if spectrum is None else spectrum
            if isinstance(rg, IdentificationError):
                raise rg
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
    scale = log.measurement_count
    r = _core.identify_time(
        log.torque_nm, log.measured, sample_period_s=log.sample_period_s, measured_is_speed=log.measured_is_speed,
        measured_on_load=log.measured_on_load, model=model, initial=initial, fixed=hold, lower=lower, upper=upper,
        segment_samples=segment_samples, initial_segment_samples=initial_segment_samples,
        min_segment_samples=min(_opts.default(_core.TimeFitOptions, "min_segment_samples"), segment_samples),
        edge_samples=edge_samples, direction_window=direction_window, rest_threshold=rest_threshold_counts,
        substeps=log.substeps,
        current_bw_hz=log.current_bw_hz, stribeck_exponent=stribeck_exponent, measurement_scale=scale, loss=loss,
        loss_scale=loss_scale_counts, max_iterations=max_iterations,
        num_threads=num_threads, max_relative_std_error=max_relative_std_error,
        hold_stribeck_first=hold_stribeck_first, progress=progress)
    s = r["summary"]
    if strict and s["not_identifiable"]:
        raise IdentificationError("the log cannot determine: " + "; ".join(s["not_identifiable"]) +
                                  " -- excite the axis more (longer log, more speed range or reversals), or fix "
                                  "these parameters (fixed=...)")
    return IdentifiedPlant(model, _estimates(r["parameters"]), s["nrmse"], s["residual_rms"], s["converged"],
                           s["iterations"], s["seconds"], s["report"] + start_note, list(s["not_identifiable"]),
                           stribeck_exponent, log.time_s, log.measured, r["predicted"], r["residual"],
                           segment_states=np.asarray(r["segment_states"], float).reshape(len(r["segment_start"]), -1))


from .frequency_fit import MechanicsIO, fit_frequency, frequency_input  # noqa: E402,F401 (re-exported)
