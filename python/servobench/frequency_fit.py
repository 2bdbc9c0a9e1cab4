"""Frequency-domain identification: fit the linear mechanics (inertias, stiffness, damping, viscous friction) to a
measured frequency response, with Ceres (C++ ``identify/frequency_fit``).

Two ways to say what surrounds the mechanics in the measurement:

- the servobench :class:`~servobench.Axis` it was measured on (a :func:`servobench.frequency.sine_sweep` or
  :func:`~servobench.frequency.broadband_response`: U in DAC counts, Y in encoder pulse; the output stage, the
  one-tick output delay, the drive and the encoder come from the axis);
- or, with no Axis (a drive's analyser, a Bode CSV, an FRD from elsewhere), a :class:`MechanicsIO`: the sample
  period (or none: continuous time), the input's torque per unit, the output's unit, the encoder side, the known
  current loop. What a user of a real machine has is exactly that: the sample time of the analyser and the scale of
  its two channels, not the controller.

Units: frequencies Hz (a python-control FRD's rad/s are converted), torque N*m, angles rad, speeds rad/s, inertias
kg*m^2, stiffness N*m/rad, damping and viscous friction N*m*s/rad, delays s.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Iterable

import numpy as np

from . import _checks, _core
from . import _options as _opts
from .identify import IdentificationError, IdentifiedPlant, _estimates, _model, _setup

__all__ = ["MechanicsIO", "fit_frequency", "frequency_input"]


@_opts.described_options(
    _core.MechanicsIO,
    python_defaults={"sample_period_s": _opts.PythonDefault(None, 0.0, "None (default): continuous time.")},
    python_fields={"output_per_rad": "counts_per_rev"})
class MechanicsIO:
    """What surrounds the mechanics in a measured response, when there is no servobench Axis.

    The model fitted is ``output_per_rad * C (sI - A)^-1 B * torque_per_input`` in continuous time, or with the
    exact zero-order hold over `sample_period_s` and `delay_samples` whole samples of delay when sampled:
    (A, B) the current loop (first order at current_bw_hz; inf: none) in series with the mechanics, C the motor's
    (or, `on_load`, the load's) angle -- or speed with `speed_output`. The fields, their defaults, units and docs
    are those of the C++ struct (identify/frequency_fit.hpp, ``servobench._core.MechanicsIO``), read from it
    (decision OQ3):

    {fields}
    counts_per_rev (float | None, counts/rev)
        the output is in encoder counts (pulse) with this many counts per revolution (output_per_rad =
        counts_per_rev / (2 pi)); None (default): rad (or rad/s), output_per_rad = 1.
    """

    # The fields are read at import from identify::MechanicsIO::describe() (counts_per_rev in output_per_rad's
    # place); static type checkers read the block below (test_options_once checks it against the table).
    if TYPE_CHECKING:
        sample_period_s: float | None = None
        delay_samples: int = 0
        torque_per_input: float = 1.0
        counts_per_rev: float | None = None
        speed_output: bool = False
        on_load: bool = False
        current_bw_hz: float = math.inf
    else:
        counts_per_rev: float | None = None

    def __post_init__(self):
        o = "MechanicsIO"
        if self.sample_period_s is not None:
            _checks.real(o, "sample_period_s", self.sample_period_s, 1e-9, 10.0, unit="s (None: continuous time)")
        d = _checks.real(o, "delay_samples", self.delay_samples, 0, 1000, unit="samples")
        if d != int(d):
            raise ValueError(f"MechanicsIO.delay_samples = {self.delay_samples} must be a whole number of samples")
        if d and self.sample_period_s is None:
            raise ValueError(f"MechanicsIO.delay_samples = {self.delay_samples} needs a sample_period_s (a "
                             "continuous-time response has no samples; use fit_delay for a delay in seconds)")
        t = _checks.real(o, "torque_per_input", self.torque_per_input, -1e12, 1e12, unit="N*m per input unit")
        if t == 0:
            raise ValueError("MechanicsIO.torque_per_input = 0 must be non-zero (N*m per unit of the input)")
        if self.counts_per_rev is not None:
            _checks.real(o, "counts_per_rev", self.counts_per_rev, 1e-6, 1e15, unit="counts/rev (None: rad)")
        _checks.flag(o, "speed_output", self.speed_output)
        _checks.flag(o, "on_load", self.on_load)
        if isinstance(self.current_bw_hz, (bool, np.bool_)) or not (float(self.current_bw_hz) > 0):
            raise ValueError(f"MechanicsIO.current_bw_hz = {self.current_bw_hz} must be > 0 Hz (inf: no current loop)")
        self._cpp()  # and the struct's own validate()

    @classmethod
    def of_axis(cls, axis) -> "MechanicsIO":
        """The plant response (U DAC counts -> Y pulse) of a servobench axis with a torque-mode drive, described
        without the axis: its servo period, one sample of output delay, 10/32767 V per count (negated by ADLINK's
        V_INVERSE) x A/V x kt, its encoder's counts per revolution and side, its current loop."""
        from .experiment import torque_per_volt
        _checks.has("MechanicsIO.of_axis", "axis", axis, "drive", "encoder", "law", "servo_period_s")
        sign = -1.0 if getattr(axis.law, "v_inverse", False) else 1.0
        return cls(sample_period_s=axis.servo_period_s, delay_samples=1,
                   torque_per_input=sign * 10.0 / 32767.0 * torque_per_volt(axis.drive),
                   counts_per_rev=axis.encoder.counts_per_rev, on_load=axis.encoder.on_load,
                   current_bw_hz=axis.drive.current_bw_hz)

    def _core_dict(self) -> dict:
        values = {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.name != "counts_per_rev"}
        values["output_per_rad"] = 1.0 if self.counts_per_rev is None else float(self.counts_per_rev) / (2 * math.pi)
        return {k: float(v) if isinstance(v, np.floating) else v for k, v in values.items()}

    def _cpp(self):
        """The validated C++ struct (``servobench._core.MechanicsIO``) this describes."""
        return _opts.cpp_options(_core.MechanicsIO, self._core_dict(), type(self).python_defaults)


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


@_opts.takes_options(_core.FrequencyFitOptions, name="fit_frequency")
def _fit_frequency(response, axis=None, model: str = "rigid", *, io: MechanicsIO | None = None, guess: dict,
                  fixed: Iterable[str] = (), bounds: dict | None = None, weight=None, strict: bool = True,
                  progress=None, **options) -> IdentifiedPlant:
    """Fits the linear mechanics to a measured frequency response: a servobench :class:`FrequencyResponse` (its
    plant Y/U), a python-control ``FRD`` (rad/s), a Bode CSV (Hz or rad/s, dB or abs, deg or rad; see
    :func:`frequency_input`) or (freq_hz, complex) arrays.

    axis
        the servobench Axis the response was measured on (U in DAC counts, Y in pulse: its output stage, one-tick
        output delay, drive and encoder); or None with `io`.
    io
        a :class:`MechanicsIO` describing the measurement without an Axis (sample period or continuous time, torque
        per input unit, output unit and side, current loop). Exactly one of `axis` and `io`.
    guess, fixed, bounds
        name -> starting value (SI) of every parameter to estimate, names held, name -> (low, high); friction is
        invisible to a linear response: only inertias, stiffness, damping and viscous friction are fitted.
    {options}
    weight
        per frequency, >= 0 (default: the measurement's coherence if it has one). The residual is the complex
        log-ratio (nepers and radians) times the weight: a resonance peak and a -60 dB roll-off count alike.
    strict
        a parameter not identifiable (standard error above `max_relative_std_error` of its value) raises
        :class:`IdentificationError` naming it.

    The options, their defaults, units and ranges are those of :class:`servobench._core.FrequencyFitOptions`
    (identify/frequency_fit.hpp), read from it.
    """
    model = _model(model)
    if (axis is None) == (io is None):
        raise ValueError("fit_frequency: give exactly one of axis (the servobench Axis the response was measured on) "
                         "and io (a MechanicsIO: sample period, torque per input unit, output unit)")
    if io is not None and not isinstance(io, MechanicsIO):
        raise TypeError(f"fit_frequency.io must be a MechanicsIO, got {type(io).__name__}")
    f, g, coh = frequency_input(response)
    if weight is None and coh is not None:
        weight = coh
    names, initial, hold, lower, upper = _setup(model, guess, fixed, bounds)
    w = np.ones(len(f)) if weight is None else np.asarray(weight, float)
    core_axis = None if axis is None else getattr(axis, "_axis", axis)
    r = _core.identify_frequency(core_axis, f.astype(float), g.astype(complex), weight=w, model=model,
                                 initial=initial, fixed=hold, lower=lower, upper=upper,
                                 options=_opts.cpp_options(_core.FrequencyFitOptions, options), progress=progress,
                                 io=None if io is None else io._cpp())
    s = r["summary"]
    if strict and s["not_identifiable"]:
        raise IdentificationError("the response cannot determine: " + "; ".join(s["not_identifiable"]))
    return IdentifiedPlant(model, _estimates(r["parameters"]), s["nrmse"], s["residual_rms"], s["converged"],
                           s["iterations"], s["seconds"], s["report"], list(s["not_identifiable"]), 2.0,
                           freq_hz=f, response=g, predicted_response=r["predicted"])


# typed signature of fit_frequency (generated by scripts/option_signatures.py from the runtime one; decision OQ5)
if TYPE_CHECKING:
    def fit_frequency(response, axis=None, model: str = 'rigid', *, fit_delay: bool = False, delay_s: float = 0.0,
                      max_iterations: int = 200, max_relative_std_error: float = 0.2, io: MechanicsIO | None = None,
                      guess: dict, fixed: Iterable[str] = (), bounds: dict | None = None, weight=None,
                      strict: bool = True, progress=None) -> IdentifiedPlant: ...
else:
    fit_frequency = _fit_frequency
# end of the typed signature of fit_frequency
