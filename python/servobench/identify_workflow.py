"""One call for a real rigid axis: :func:`identify_rigid` runs the field's estimators on a closed-loop record and says
which answer to use and why.

1. IDIM-LS with symmetric friction and an offset (the benchmark's standard method: the answer), and its test of
   friction asymmetry;
2. IDIM-LS with asymmetric friction (Fv+, Fc+, Fv-, Fc-): the model used when the test rejects symmetry;
3. IDIM-IV (instruments from the reference) when the record has a reference: a large LS-IV difference flags a
   closed-loop noise bias;
4. the output-error fit (:func:`servobench.fit_time`, several starts, segments from the data) started from the
   IDIM answer, as a cross-check: where it differs from the IDIM beyond both error bars, the friction model does
   not describe the machine equally well in force and in position (the note says which parameters).

In closed loop the simulated position is barely sensitive to the parameters (the controller corrects it: Gautier,
Janot & Vandanjon 2013), so the inverse model's estimate is the answer and the output-error fit is the check
(docs/decisions.md, section I19). Units: kg, N*s/m, N on a linear axis; kg*m^2, N*m*s/rad, N*m on a rotary one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._serialise import JsonResult, dataframe

__all__ = ["identify_rigid", "RigidIdentification"]


@dataclass(frozen=True)
class RigidIdentification(JsonResult):
    """The outcome of :func:`identify_rigid`.

    model: the :class:`~servobench.validation.RigidModel` to use (asymmetric friction when the data reject symmetry);
    idim: symmetric IDIM-LS (M, Fv, Fc, offset); idim_asymmetric: IDIM-LS with Fv+, Fc+, Fv-, Fc-; idim_iv: IDIM-IV
    or None; output_error: the :func:`servobench.fit_time` cross-check or None; notes: what was chosen and why,
    disagreements between the estimators."""

    model: object
    idim: object
    idim_asymmetric: object
    idim_iv: object | None
    output_error: object | None
    notes: list = field(default_factory=list)

    def to_dataframe(self):
        """Every estimator's parameters side by side, in long form: one row per (``estimator``, ``name``) with
        ``value``, ``std_error`` and ``unit`` (the axis's units: kg, N*s/m, N on a linear axis; kg*m^2, N*m*s/rad,
        N*m on a rotary one); estimators ``idim``, ``idim_asymmetric``, ``idim_iv`` and ``output_error`` when
        present. ``df.pivot(index="name", columns="estimator", values="value")`` compares them."""
        rows = {"estimator": [], "name": [], "value": [], "std_error": [], "unit": []}
        for est in ("idim", "idim_asymmetric", "idim_iv", "output_error"):
            res = getattr(self, est)
            for e in ([] if res is None else res.parameters.values()):
                for k, v in (("estimator", est), ("name", e.name), ("value", e.value), ("std_error", e.std_error),
                             ("unit", e.unit)):
                    rows[k].append(v)
        return dataframe({k: np.asarray(v, dtype=object if k in ("estimator", "name", "unit") else float)
                          for k, v in rows.items()})

    def values(self) -> dict:
        """The symmetric IDIM-LS estimates: M, Fv, Fc, offset."""
        return self.idim.values()

    def __getitem__(self, name: str) -> float:
        if name in self.idim.parameters:
            return self.idim[name]
        return self.idim_asymmetric[name]

    def __str__(self) -> str:
        parts = [str(self.idim), str(self.idim_asymmetric)]
        if self.idim_iv is not None:
            parts.append(str(self.idim_iv))
        if self.output_error is not None:
            parts.append("Output-error cross-check (fit_time):\n" + str(self.output_error))
        parts.append("Model to use: " + str(self.model))
        parts += ["note: " + n for n in self.notes]
        return "\n\n".join(parts)


_OE_NAMES = {"M": "inertia_kgm2", "Fv": "viscous_nms", "Fc": "coulomb_nm", "offset": "load_nm"}


def identify_rigid(log, *, dynamics_hz: float | None = None, output_error: bool = True, n_starts: int = 3,
                   max_relative_std_error: float = 0.1) -> RigidIdentification:
    """Identifies a rigid axis from a closed-loop position record (see the module's text for the steps).

    log: an :class:`IdentificationLog` with measured position and effort (and ideally the reference);
    dynamics_hz: the closed loop's dynamics frequency, Hz (None: from the reference -> position response);
    output_error: run the :func:`fit_time` cross-check (a few seconds per 10^4 samples and start)."""
    from .idim import idim_iv, idim_ls
    from .identify import fit_time
    from .validation import RigidModel

    ls = idim_ls(log, dynamics_hz=dynamics_hz, max_relative_std_error=max_relative_std_error)
    asym = idim_ls(log, friction="asymmetric", dynamics_hz=ls.dynamics_hz,
                   max_relative_std_error=max_relative_std_error)
    notes = list(ls.warnings)
    model = RigidModel.from_result(asym if ls.misfit else ls)
    notes.append("model: " + ("asymmetric friction (the data reject symmetric friction)" if ls.misfit else
                              "symmetric friction (the data do not reject it)"))
    iv = None
    if log.reference is not None:
        iv = idim_iv(log, dynamics_hz=ls.dynamics_hz, max_relative_std_error=max_relative_std_error)
        for k, e in ls.parameters.items():
            d = iv[k] - e.value
            s = math.hypot(e.std_error, iv.parameters[k].std_error)
            if abs(d) > 2 * s:
                notes.append(f"IDIM-IV differs from IDIM-LS on {k} by {d:.4g} (> 2 x {s:.3g}): a closed-loop noise "
                             "bias in LS is likely; prefer idim_iv")
    oe = None
    if output_error:
        oe = fit_time(log, dynamics_hz=ls.dynamics_hz, n_starts=n_starts, strict=False)
        for k, name in _OE_NAMES.items():
            a, b = ls.parameters[k], oe.parameters[name]
            s = math.hypot(a.std_error, b.std_error)
            if abs(b.value - a.value) > 2 * s:
                notes.append(f"output-error fit and IDIM differ on {k}: {b.value:.6g} vs {a.value:.6g} (> 2 x "
                             f"{s:.3g}, {100 * (b.value / a.value - 1):+.2f} %): the model describes force and "
                             "position differently (mis-specification)")
        if oe.disagreement:
            notes.append("the output-error fit's starts disagree: " + "; ".join(oe.disagreement[:2]))
    return RigidIdentification(model, ls, asym, iv, oe, notes)
