"""The result of a plant fit: :class:`IdentifiedPlant` (estimates, fit quality, residuals, plots, the plant for
simulation), its :class:`Estimate` per parameter, and :class:`IdentificationError`. Defined here, published by
:mod:`servobench.identify` (their home for pickles, saved results and the docs; decision OR2); the fits are there and
in :mod:`servobench.frequency_fit`.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import field
from typing import TYPE_CHECKING

import numpy as np

from . import _core
from . import _options as _opts
from ._serialise import JsonResult, dataframe


# a linear axis's log fitted by the rotary model (kg*m^2 <-> kg, N*m <-> N, rad <-> m): names and units shown
_LINEAR_NAMES = {"inertia_kgm2": ("mass_kg", "kg"), "viscous_nms": ("viscous_ns_per_m", "N*s/m"),
                 "coulomb_nm": ("coulomb_n", "N"), "static_nm": ("static_n", "N"),
                 "stribeck_speed_rad_s": ("stribeck_speed_m_s", "m/s"), "load_nm": ("offset_n", "N")}
_LINEAR_ALIASES = {v[0]: (k,) for k, v in _LINEAR_NAMES.items()}


# ----------------------------------------------------------------------------------------------------------------
# Results
# ----------------------------------------------------------------------------------------------------------------
@_opts.described_result(_core.PARAMETER_ESTIMATE_FIELDS)
class Estimate(JsonResult):
    """One parameter: value and standard error in `unit`; fixed ones were held at their initial value.

    {fields}
    """

    # The fields are read at import from identify::ParameterEstimate::describe() with their docs, in this order
    # (decision OR1); static type checkers read these names (test_options_once checks they match).
    if TYPE_CHECKING:
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
