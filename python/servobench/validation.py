"""Validation of an identified rigid axis: simulate it on a record and compare.

:func:`validate` simulates the model **open loop** from the record's measured effort (force N / torque N*m) and
its initial state (position and speed from the first samples), and -- where the record's controller is known
(:class:`CascadePD`, the EMPS benchmark's position-velocity law) -- **closed loop** from its reference. It reports
RMS, NRMSE and R^2 of the position and draws measured vs simulated with the residual.

The model (:class:`RigidModel`) is M a = F - offset - friction(v) with asymmetric viscous and Coulomb friction
(Fv+, Fc+ for v > 0; Fv-, Fc- for v < 0) and an optional Stribeck peak; a stopped axis sticks while
-Fc- <= F - offset <= Fc+. Integration: semi-implicit Euler with `substeps` sub-steps per sample, the effort held
over each sample (zero-order hold); a speed that changes sign within a sub-step stops at zero. Units: linear m,
m/s, N, kg; rotary rad, rad/s, N*m, kg*m^2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._serialise import JsonResult, dataframe

__all__ = ["RigidModel", "CascadePD", "simulate_rigid", "validate", "ValidationResult"]


def _finite(owner, name, v, lo=-math.inf, lo_open=False):
    v = float(v)
    ok = math.isfinite(v) and (v > lo if lo_open else v >= lo)
    if not ok:
        raise ValueError(f"{owner}.{name} = {v} must be a finite number {'>' if lo_open else '>='} {lo:g}")
    return v


@dataclass(frozen=True)
class RigidModel(JsonResult):
    """A rigid axis: mass_kg (kg; kg*m^2 on a rotary axis), viscous friction per direction fv_pos / fv_neg
    (N*s/m or N*m*s/rad), Coulomb friction per direction fc_pos / fc_neg (N or N*m, >= 0; fv_neg, fc_neg default to
    the positive side's), a constant offset (N or N*m: M a = F - offset - friction) and an optional Stribeck peak
    `static` (N or N*m, above the Coulomb level; 0 = none) decaying with stribeck_speed (m/s or rad/s)."""

    mass_kg: float
    fv_pos: float = 0.0
    fc_pos: float = 0.0
    fv_neg: float | None = None
    fc_neg: float | None = None
    offset: float = 0.0
    static: float = 0.0
    stribeck_speed: float = 1.0
    linear: bool = True

    def __post_init__(self):
        _finite("RigidModel", "mass_kg", self.mass_kg, 0.0, lo_open=True)
        for n in ("fv_pos", "fc_pos", "static"):
            _finite("RigidModel", n, getattr(self, n), 0.0)
        for n, twin in (("fv_neg", "fv_pos"), ("fc_neg", "fc_pos")):
            if getattr(self, n) is None:
                object.__setattr__(self, n, getattr(self, twin))
            _finite("RigidModel", n, getattr(self, n), 0.0)
        _finite("RigidModel", "offset", self.offset)
        _finite("RigidModel", "stribeck_speed", self.stribeck_speed, 0.0, lo_open=True)

    @classmethod
    def from_result(cls, result) -> "RigidModel":
        """From an :class:`~servobench.idim.IdimResult` (symmetric or asymmetric friction)."""
        v = result.values()
        if "Fv" in v:
            return cls(v["M"], max(v["Fv"], 0.0), max(v["Fc"], 0.0), None, None, v.get("offset", 0.0),
                       linear=result.linear)
        return cls(v["M"], max(v["Fv+"], 0.0), max(v["Fc+"], 0.0), max(v["Fv-"], 0.0), max(v["Fc-"], 0.0),
                   v.get("offset", 0.0), linear=result.linear)

    def to_plant(self, lead_m_per_rev: float | None = None):
        """The model as a :class:`RigidPlant` for an :class:`Axis` (simulation, tuning): mean and half-difference of
        each friction pair (viscous_nms / viscous_asym_nms, coulomb_nm / coulomb_asym_nm), the offset as load_nm.
        A linear model maps to the motor side through the screw lead (m per motor revolution): J = M (lead/2 pi)^2,
        torque = force lead / (2 pi); without a lead it maps 1:1 (1 m -> 1 rad, 1 N -> 1 N*m, 1 kg -> 1 kg*m^2)."""
        from . import _core

        k = 1.0
        if lead_m_per_rev is not None:
            lead = _finite("to_plant", "lead_m_per_rev", lead_m_per_rev, 0.0, lo_open=True)
            if not self.linear:
                raise ValueError("to_plant: lead_m_per_rev applies to a linear model only")
            k = 2 * math.pi / lead
        fv, dv = (self.fv_pos + self.fv_neg) / 2, (self.fv_pos - self.fv_neg) / 2
        fc, dc = (self.fc_pos + self.fc_neg) / 2, (self.fc_pos - self.fc_neg) / 2
        static = self.static / k if self.static > max(self.fc_pos, self.fc_neg) else 0.0
        return _core.RigidPlant(inertia_kgm2=self.mass_kg / k ** 2, viscous_nms=fv / k ** 2,
                                viscous_asym_nms=dv / k ** 2, coulomb_nm=fc / k, coulomb_asym_nm=dc / k,
                                static_nm=static, stribeck_speed_rad_s=self.stribeck_speed * k, load_nm=self.offset / k)

    @property
    def units(self) -> dict:
        if self.linear:
            return {"mass": "kg", "viscous": "N*s/m", "effort": "N", "position": "m", "speed": "m/s"}
        return {"mass": "kg*m^2", "viscous": "N*m*s/rad", "effort": "N*m", "position": "rad", "speed": "rad/s"}

    def __str__(self) -> str:
        u = self.units
        return (f"RigidModel: M = {self.mass_kg:.6g} {u['mass']}, Fv+ = {self.fv_pos:.6g}, Fv- = {self.fv_neg:.6g} "
                f"{u['viscous']}, Fc+ = {self.fc_pos:.6g}, Fc- = {self.fc_neg:.6g}, offset = {self.offset:.6g} "
                f"{u['effort']}")


@dataclass(frozen=True)
class CascadePD:
    """The EMPS benchmark's controller (its eq. 6-7): effort = gain * sat(kp*kv*(q_ref - q) - kv*v_m,
    +-saturation_v), v_m = (q_k - q_{k-2}) / (2 Ts) (the two-tap FIR on the position, then a difference).
    kp_per_s: 1/s; kv: V per m/s (or per rad/s); gain: N/V (or N*m/V); saturation_v: V."""

    kp_per_s: float
    kv: float
    gain: float
    saturation_v: float = 10.0

    def __post_init__(self):
        for n in ("kp_per_s", "kv", "gain", "saturation_v"):
            _finite("CascadePD", n, getattr(self, n), 0.0, lo_open=True)

    @classmethod
    def from_log(cls, log) -> "CascadePD | None":
        """From a log read with the EMPS variable names (its extra holds kp, kv and gtau), else None."""
        e = log.extra
        if all(k in e for k in ("kp", "kv", "gtau")):
            return cls(e["kp"], e["kv"], e["gtau"])
        return None


def simulate_rigid(model: RigidModel, sample_period_s: float, *, effort=None, reference=None,
                   controller: CascadePD | None = None, q0=0.0, v0=0.0, substeps: int = 10, disturbance=None,
                   position_quantum: float | None = None):
    """Simulates `model` over the samples of `effort` (open loop, N or N*m held over each sample) or of `reference`
    (m or rad) with `controller` (closed loop). q0, v0: the initial position and speed (any state). disturbance:
    an effort per sample (N or N*m) added to the drive's on the mass but not to the returned effort (an unmeasured
    load); position_quantum: the encoder count (m or rad) the controller sees the position through. Returns
    (position, speed, effort) per sample. Arrays of shape (n, R) simulate R records at once (q0, v0 scalars or
    length R)."""
    ts = _finite("simulate_rigid", "sample_period_s", sample_period_s, 0.0, lo_open=True)
    if not (float(substeps) == int(substeps) and 1 <= int(substeps) <= 1000):
        raise ValueError(f"simulate_rigid.substeps = {substeps} must be a whole number in 1..1000")
    substeps = int(substeps)
    closed = controller is not None
    src = reference if closed else effort
    if src is None:
        raise ValueError("simulate_rigid: give effort (open loop) or reference and controller (closed loop)")
    src = np.asarray(src, float)
    if not np.all(np.isfinite(src)):
        raise ValueError("simulate_rigid: the input holds non-finite samples")
    m = model
    h = ts / substeps
    q = np.zeros_like(src[0]) + q0
    v = np.zeros_like(src[0]) + v0
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(v))):
        raise ValueError("simulate_rigid: q0 and v0 must be finite")
    dist = np.zeros_like(src) if disturbance is None else np.broadcast_to(np.asarray(disturbance, float), src.shape)
    if not np.all(np.isfinite(dist)):
        raise ValueError("simulate_rigid: the disturbance holds non-finite samples")
    quant = None if position_quantum is None else _finite("simulate_rigid", "position_quantum", position_quantum,
                                                          0.0, lo_open=True)
    if src.ndim == 1 and disturbance is None and quant is None:
        return _simulate_scalar(m, ts, src, closed, controller, float(q), float(v), substeps)
    Q, V, F = np.empty_like(src), np.empty_like(src), np.empty_like(src)
    q1 = q2 = q
    inv_m = 1.0 / m.mass_kg
    strib = m.static > max(m.fc_pos, m.fc_neg)
    for k in range(len(src)):
        Q[k] = q
        V[k] = v
        if closed:
            qm = q if quant is None else np.round(q / quant) * quant
            vm = (qm - q2) / (2 * ts)
            u = np.clip(controller.kp_per_s * controller.kv * (src[k] - qm) - controller.kv * vm,
                        -controller.saturation_v, controller.saturation_v)
            f = controller.gain * u
            q2, q1 = q1, qm
        else:
            f = src[k]
        F[k] = f
        drive = f - m.offset + dist[k]
        for _ in range(substeps):
            if strib:
                w = np.exp(-(v / m.stribeck_speed) ** 2)
                fcp = m.fc_pos + (m.static - m.fc_pos) * w
                fcn = m.fc_neg + (m.static - m.fc_neg) * w
            else:
                fcp, fcn = m.fc_pos, m.fc_neg
            fr = np.where(v > 0, m.fv_pos * v + fcp, np.where(v < 0, m.fv_neg * v - fcn, 0.0))
            v_new = v + h * (drive - fr) * inv_m
            crossed = (v != 0) & (np.sign(v_new) != np.sign(v))
            stuck = (v == 0) & (drive <= fcp) & (drive >= -fcn)
            v_new = np.where(crossed | stuck, 0.0, v_new)
            q = q + h * v_new
            v = v_new
    return Q, V, F


def _simulate_scalar(m, ts, src, closed, ctrl, q, v, substeps):
    """simulate_rigid for one record, in Python floats (the same steps as the array version, ~20x faster)."""
    h = ts / substeps
    n = len(src)
    Q, V, F = np.empty(n), np.empty(n), np.empty(n)
    q1 = q2 = q
    inv_m = 1.0 / m.mass_kg
    strib = m.static > max(m.fc_pos, m.fc_neg)
    fvp, fvn, off = m.fv_pos, m.fv_neg, m.offset
    if closed:
        kpkv, kv, gain, sat = ctrl.kp_per_s * ctrl.kv, ctrl.kv, ctrl.gain, ctrl.saturation_v
    srcl = src.tolist()
    for k in range(n):
        Q[k] = q
        V[k] = v
        if closed:
            u = kpkv * (srcl[k] - q) - kv * (q - q2) / (2 * ts)
            f = gain * (sat if u > sat else -sat if u < -sat else u)
            q2, q1 = q1, q
        else:
            f = srcl[k]
        F[k] = f
        drive = f - off
        for _ in range(substeps):
            fcp, fcn = m.fc_pos, m.fc_neg
            if strib:
                w = math.exp(-(v / m.stribeck_speed) ** 2)
                fcp += (m.static - fcp) * w
                fcn += (m.static - fcn) * w
            if v > 0:
                v_new = v + h * (drive - fvp * v - fcp) * inv_m
                if v_new < 0:
                    v_new = 0.0
            elif v < 0:
                v_new = v + h * (drive - fvn * v + fcn) * inv_m
                if v_new > 0:
                    v_new = 0.0
            elif -fcn <= drive <= fcp:
                v_new = 0.0
            else:
                v_new = h * drive * inv_m
            q += h * v_new
            v = v_new
    return Q, V, F


@dataclass(frozen=True)
class ValidationResult(JsonResult):
    """Measured vs simulated position of one record: rms (m or rad), nrmse (rms over the measured position's
    standard deviation), r2 (1 - SSE/SST) of the open-loop simulation; closed_loop: the same three for the
    closed-loop simulation (None without a known controller); series: the arrays drawn; lead_m_per_rev: the log's
    screw lead (a linear axis prints its RMS at the motor too)."""

    rms: float
    nrmse: float
    r2: float
    closed_loop: dict | None
    linear: bool
    series: dict = field(repr=False)
    lead_m_per_rev: float | None = None

    def _rms(self, rms: float) -> str:
        u = "m" if self.linear else "rad"
        out = f"RMS {rms:.4g} {u}"
        if self.linear and self.lead_m_per_rev is not None:
            from .idlog import motor_side

            v, mu = motor_side(rms, "m", self.lead_m_per_rev)
            out += f" ({v:.4g} {mu} at the motor, lead {1e3 * self.lead_m_per_rev:.6g} mm/rev)"
        return out

    def __str__(self) -> str:
        s = f"open loop: {self._rms(self.rms)}, NRMSE {self.nrmse:.4g}, R^2 {self.r2:.6f}"
        if self.closed_loop:
            c = self.closed_loop
            s += f"\nclosed loop: {self._rms(c['rms'])}, NRMSE {c['nrmse']:.4g}, R^2 {c['r2']:.6f}"
        return s

    def to_dataframe(self):
        """The series drawn by :meth:`plot` as a pandas DataFrame, one row per sample: ``time_s`` (s), the
        measured position and the open-loop (and, when simulated, closed-loop) simulation, named with their unit:
        ``measured_rad``, ``open_loop_rad``, ``closed_loop_rad`` (``_m`` on a linear axis); ``df.attrs["units"]``
        gives the units."""
        u = "m" if self.linear else "rad"
        cols, units = {}, {}
        for k, v in self.series.items():
            name = k if k == "time_s" else f"{k}_{u}"
            cols[name], units[name] = v, ("s" if k == "time_s" else u)
        return dataframe(cols, units)

    def plot(self, *, ax=None, path: str | None = None):
        """Measured vs simulated position (top) and the residual (bottom), units on every axis. `ax`: two axes.
        Returns the data drawn (dict of arrays)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
        u = "m" if self.linear else "rad"
        s = self.series
        ax[0].plot(s["time_s"], s["measured"], lw=0.9, label="measured")
        ax[0].plot(s["time_s"], s["open_loop"], "--", lw=0.9, label="simulated, open loop")
        ax[1].plot(s["time_s"], s["measured"] - s["open_loop"], lw=0.7, label="open loop")
        if "closed_loop" in s:
            ax[0].plot(s["time_s"], s["closed_loop"], ":", lw=0.9, label="simulated, closed loop")
            ax[1].plot(s["time_s"], s["measured"] - s["closed_loop"], lw=0.7, label="closed loop")
        ax[0].set_ylabel(f"position, {u}")
        ax[1].set_ylabel(f"measured - simulated, {u}")
        ax[1].set_xlabel("time, s")
        ax[0].legend(fontsize=8)
        ax[1].legend(fontsize=8)
        if path:
            ax[0].figure.savefig(path, dpi=110)
        return s


def _scores(meas, sim) -> dict:
    e = meas - sim
    rms = float(np.sqrt(np.mean(e ** 2)))
    sd = float(np.std(meas))
    return {"rms": rms, "nrmse": rms / sd if sd > 0 else math.inf,
            "r2": float(1 - np.sum(e ** 2) / np.sum((meas - meas.mean()) ** 2))}


def validate(model, log, *, controller="auto", substeps: int = 10) -> ValidationResult:
    """Simulates `model` (a :class:`RigidModel` or an IDIM result) on `log`: open loop from the measured effort
    and the initial state (position = first sample, speed = central difference of the first samples), and closed
    loop from the log's reference when the controller is known (`controller`: a :class:`CascadePD`, None, or
    'auto' = :meth:`CascadePD.from_log`). Returns a :class:`ValidationResult` (RMS in m or rad, NRMSE, R^2)."""
    from .idlog import IdentificationLog

    if not isinstance(model, RigidModel):
        model = RigidModel.from_result(model)
    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog")
    if log.measured_is_speed:
        raise ValueError("validate: the log's measured signal is a speed; a position record is needed")
    if len(log) < 10:
        raise ValueError(f"validate: the record is too short ({len(log)} samples)")
    ts = log.sample_period_s
    q = log.measured
    v0 = float((q[2] - q[0]) / (2 * ts))
    Q, _, _ = simulate_rigid(model, ts, effort=log.torque_nm, q0=float(q[0]), v0=v0, substeps=substeps)
    series = {"time_s": log.time_s, "measured": q, "open_loop": Q}
    ctrl = CascadePD.from_log(log) if isinstance(controller, str) and controller == "auto" else controller
    closed = None
    if ctrl is not None and log.reference is not None:
        Qc, _, _ = simulate_rigid(model, ts, reference=log.reference, controller=ctrl, q0=float(q[0]), v0=v0,
                                  substeps=substeps)
        series["closed_loop"] = Qc
        closed = _scores(q, Qc)
    s = _scores(q, Q)
    return ValidationResult(s["rms"], s["nrmse"], s["r2"], closed, log.linear, series,
                            log.lead_m_per_rev if log.linear else None)
