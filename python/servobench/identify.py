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
from typing import TYPE_CHECKING, Iterable

import numpy as np

from . import _core
from . import _options as _opts
from ._identified import Estimate, IdentificationError, IdentifiedPlant
from ._log_spectrum import LogSpectrum, ResonanceGuess, log_spectrum, resonance_guess
from .experiment import _whole, excitation, run_experiment, torque_per_volt  # noqa: F401 (re-exported)
from .idlog import IdentificationLog

__all__ = [
    "frequency_input",
    "IdentificationLog", "IdentifiedPlant", "Estimate", "excitation", "run_experiment", "fit_time", "fit_frequency",
    "model_parameters", "torque_per_volt", "log_spectrum", "LogSpectrum", "resonance_guess", "ResonanceGuess",
    "IdentificationError",
]

# The results and the spectral view live in _identified.py and _log_spectrum.py (one concept per file, decision
# OR2); this module stays their home: pickles, saved results (servobench._serialise names the type by module) and the
# docs name them here.
for _obj in (Estimate, IdentificationError, IdentifiedPlant, LogSpectrum, ResonanceGuess, log_spectrum,
             resonance_guess):
    _obj.__module__ = __name__
del _obj

MODELS = ("rigid", "two_mass")


def model_parameters(model: str) -> list[dict]:
    """The parameters of a plant model ('rigid' or 'two_mass'): name, unit, lower bound, meaning -- the field names of
    :class:`RigidPlant` / :class:`TwoMassPlant`."""
    return list(_core.identify_parameters(_model(model)))


def _model(model: str) -> str:
    if model not in MODELS:
        raise ValueError(f"model = {model!r} is not one of 'rigid', 'two_mass'")
    return model


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
    return {p["name"]: Estimate(**{f["name"]: p[f["name"]] for f in _core.PARAMETER_ESTIMATE_FIELDS}) for p in ps}


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
        The first start runs alone; a later start whose free parameters agree with the first start's within 1e-4
        (relative) at the end of a stage of the continuation stops there and takes the first start's outcome (from
        the same point the remaining stages repeat the first start's; its summary says "Joined start 1"). On the 5 s
        bench experiments this saved 9-47 % of the CPU time (bench table, decision FV15).
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
        how many of the later starts run at once, after the first (default 1: one after the other). Threads help
        wall time only: the later starts are independent one-thread solves that release the GIL, so they overlap,
        but the first start runs alone (FV15) and the CPU time is the sum of the starts (a rigid start 0.07-0.13 s
        on the 5 s bench experiments, decision FV16). Measured with 2 threads on 2 cores, 3 starts, best of 5: wall
        time 1.22x (rigid A), 1.30x (rigid B) and 1.05x (two-mass, whose later starts join after one stage) less,
        CPU time 0-10 % more. Results do not depend on it. With `progress`
        the starts run one after the other. Ctrl-C stops a parallel run at every start's next iteration, which on a
        loaded machine took 0.6 s (one iteration of a 100,000-sample fit), hence the sequential default.
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

    def fit_one(g, prog, join=None, record=None):
        return _fit_once(log, model, spectrum, join, record, guess=g, fixed=fixed, bounds=bounds,
                         segment_samples=segment_samples, initial_segment_samples=initial_segment_samples,
                         max_relative_std_error=max_relative_std_error, strict=False, progress=prog, **options)

    def fit_later(g, prog):  # a later start that fails is dropped (oefit.run_starts)
        try:
            return fit_one(g, prog, record["stage_parameters"])
        except ValueError:
            return None

    # The first start runs alone and leaves its parameters at the end of every stage; a later start whose parameters
    # agree with them at the end of a stage stops there and takes the first start's outcome: from the same point the
    # remaining stages would repeat the first start's (decision FV15). The later starts run after the first whatever
    # start_threads is, so which start joins does not depend on the thread count.
    guesses = oefit.perturbed_starts(guess, free, n_starts, seed)
    record = {}
    first = fit_one(guesses[0], progress, None, record)
    rest = [f for f in oefit.run_starts(fit_later, guesses[1:], threads=start_threads, progress=progress)
            if f is not None] if len(guesses) > 1 else []
    joined = sum(isinstance(f, _Joined) for f in rest)
    fits = [first] + [f.take(first) if isinstance(f, _Joined) else f for f in rest]
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
                 (f" ({joined} joined start 1 at an intermediate stage of the continuation, every free parameter "
                  f"within {_JOIN_RTOL:g} of start 1's there, and took its outcome)" if joined else "") +
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


# Two starts whose free parameters agree within this (relative) at the end of a stage continue as one (decision
# FV15): at the end of the 250-sample stage the bench's starts agree within 5e-6 (rigid) and 2.5e-5 (two-mass).
_JOIN_RTOL = 1e-4


@dataclasses.dataclass(frozen=True)
class _Joined:
    """A later start of fit_time that stopped after `stage` (0-based) because it reached the first start's point."""
    stage: int
    iterations: int
    seconds: float
    report: str

    def take(self, first: IdentifiedPlant) -> IdentifiedPlant:
        """The first start's outcome with this start's own iterations, seconds and report."""
        return dataclasses.replace(first, iterations=self.iterations, seconds=self.seconds,
                                   summary=self.report + f"\nJoined start 1 after stage {self.stage + 1}: its "
                                   "parameters, residuals and standard errors are start 1's from there on.")


def _fit_once(log: IdentificationLog, model: str = "rigid", spectrum=None, join=None, record=None, /, *,
             guess: dict, fixed: Iterable[str] = (),
             bounds: dict | None = None, segment_samples: int = _TIME["segment_samples"],
             initial_segment_samples: int = _TIME["initial_segment_samples"], loss: str = "none",
             loss_scale_counts: float = _TIME["loss_scale_counts"],
             stribeck_exponent: float = _TIME["stribeck_exponent"], max_iterations: int = _TIME["max_iterations"],
             num_threads: int = _TIME["num_threads"], max_relative_std_error: float = _TIME["max_relative_std_error"],
             direction_window: int = _TIME["direction_window"],
             rest_threshold_counts: float = _TIME["rest_threshold_counts"], edge_samples: int = _TIME["edge_samples"],
             start: str = "auto", hold_stribeck_first: bool = _TIME["hold_stribeck_first"], strict: bool = True,
             progress=None):
    """One output-error fit from one start (see :func:`fit_time`). Positional only, so that they are not fit_time's
    options: spectrum, the log's :func:`resonance_guess` (or the IdentificationError it raised) when the caller
    already has it (fit_time reads it once for all starts); join, another start's parameters at the end of each
    stage (this start then returns a :class:`_Joined` if it reaches them, decision FV15); record, a dict that
    receives this start's ``stage_parameters``."""
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
        hold_stribeck_first=hold_stribeck_first, progress=progress, join_points=join, join_rtol=_JOIN_RTOL)
    s = r["summary"]
    if record is not None:
        record["stage_parameters"] = r["stage_parameters"]
    if r["joined_stage"] >= 0:
        return _Joined(r["joined_stage"], s["iterations"], s["seconds"], s["report"] + start_note)
    if strict and s["not_identifiable"]:
        raise IdentificationError("the log cannot determine: " + "; ".join(s["not_identifiable"]) +
                                  " -- excite the axis more (longer log, more speed range or reversals), or fix "
                                  "these parameters (fixed=...)")
    return IdentifiedPlant(model, _estimates(r["parameters"]), s["nrmse"], s["residual_rms"], s["converged"],
                           s["iterations"], s["seconds"], s["report"] + start_note, list(s["not_identifiable"]),
                           stribeck_exponent, log.time_s, log.measured, r["predicted"], r["residual"],
                           segment_states=np.asarray(r["segment_states"], float).reshape(len(r["segment_start"]), -1))


from .frequency_fit import MechanicsIO, fit_frequency, frequency_input  # noqa: E402,F401 (re-exported)
