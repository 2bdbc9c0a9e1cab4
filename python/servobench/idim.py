"""Inverse-dynamic-model identification of a rigid axis: IDIM-LS and IDIM-IV, with honest standard errors.

The inverse dynamic model (Janot, Gautier & Brunot, "Data Set and Reference Models of EMPS", eq. 1 and 12)::

    tau = M q'' + Fv q' + Fc sign(q') + offset                                   (symmetric friction)
    tau = M q'' + Fv+ [q']+ + Fc+ [q'>0] + Fv- [q']- - Fc- [q'<0] + offset        (asymmetric friction)

is linear in its parameters: tau = phi(q', q'') theta. :func:`idim_ls` follows the benchmark's procedure (its
section 3): the measured position is low-passed by a zero-phase Butterworth filter (order 4, cut-off 5 x the
closed loop's dynamics frequency, ``scipy.signal.butter`` + ``filtfilt``), differentiated twice by central
differences (``numpy.gradient``), the first samples are dropped (filter edge), then every column of phi and the
measured effort are decimated (``scipy.signal.cheby1`` order-8 anti-alias filter applied forward and backward, one
sample in nd kept, nd = round(0.8 f_nyquist / (2 f_dyn)), aligned to the record's last sample as MATLAB's
``decimate``), and theta is the least-squares solution (``scipy.linalg.lstsq``).

Units: linear axis M kg, Fv N*s/m, Fc N, offset N (position m, effort N); rotary axis kg*m^2, N*m*s/rad, N*m.

Standard errors: the residual of an IDIM is coloured (filtered, decimated, and the controller feeds the
disturbance back), so the textbook sigma^2 (X'X)^-1 is too small. Both estimators report the heteroskedasticity-
and-autocorrelation-consistent (HAC, Newey-West) sandwich covariance, Bartlett kernel, its bandwidth chosen from the
data by Andrews' AR(1) plug-in rule (docs/decisions.md, section I19); the textbook value is kept as
``std_error_iid``. A parameter is *not identified* when its HAC standard error exceeds ``max_relative_std_error``
of its own value.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._serialise import JsonResult, dataframe

__all__ = ["idim_ls", "idim_iv", "IdimResult", "hac_covariance", "observation_matrix", "FRICTION_MODELS",
           "filtered_derivatives", "dynamics_frequency", "long_run_covariance"]

FRICTION_MODELS = ("symmetric", "asymmetric")


def _names(friction: str, offset: bool, linear: bool) -> list[tuple[str, str]]:
    m, v, c = ("kg", "N*s/m", "N") if linear else ("kg*m^2", "N*m*s/rad", "N*m")
    if friction == "symmetric":
        out = [("M", m), ("Fv", v), ("Fc", c)]
    else:
        out = [("M", m), ("Fv+", v), ("Fc+", c), ("Fv-", v), ("Fc-", c)]
    if offset:
        out.append(("offset", c))
    return out


def observation_matrix(dq, ddq, friction: str = "symmetric", offset: bool = True) -> np.ndarray:
    """phi (N x p) of the inverse dynamic model from speed dq and acceleration ddq (columns in the order of the
    result's parameters: M, Fv, Fc[, offset] or M, Fv+, Fc+, Fv-, Fc-[, offset])."""
    dq = np.asarray(dq, float)
    ddq = np.asarray(ddq, float)
    if friction == "symmetric":
        cols = [ddq, dq, np.sign(dq)]
    elif friction == "asymmetric":
        pos = dq > 0
        neg = dq < 0
        cols = [ddq, np.where(pos, dq, 0.0), pos.astype(float), np.where(neg, dq, 0.0), -neg.astype(float)]
    else:
        raise ValueError(f"friction = {friction!r} is not one of {FRICTION_MODELS}")
    if offset:
        cols.append(np.ones_like(dq))
    return np.column_stack(cols)


def _bartlett_lags(u: np.ndarray) -> float:
    """Andrews' (1991) AR(1) plug-in bandwidth for the Bartlett kernel, alpha from AR(1) fits of each column of u
    (before rounding): 1.1447 (alpha T)^(1/3)."""
    num = den = 0.0
    for col in u.T:
        c = col - col.mean()
        d = float(c[:-1] @ c[:-1])
        rho = float(c[1:] @ c[:-1]) / d if d > 0 else 0.0
        rho = min(max(rho, -0.97), 0.97)
        s2 = float(np.mean((c[1:] - rho * c[:-1]) ** 2))
        num += 4 * rho ** 2 * s2 ** 2 / ((1 - rho) ** 6 * (1 + rho) ** 2)
        den += s2 ** 2 / (1 - rho) ** 4
    alpha = num / den if den > 0 else 0.0
    return 1.1447 * (alpha * len(u)) ** (1 / 3)


def _bartlett(u: np.ndarray, lags: int) -> np.ndarray:
    S = u.T @ u
    for j in range(1, lags + 1):
        G = u[j:].T @ u[:-j]
        S += (1 - j / (lags + 1)) * (G + G.T)
    return S


def hac_covariance(X: np.ndarray, e: np.ndarray, *, lags: int | None = None, Z: np.ndarray | None = None):
    """(covariance p x p, Bartlett lags used) of a linear estimate theta = (Z'X)^-1 Z'y with residual e (Z = X for
    least squares): the sandwich A S A' with A = (Z'X)^-1 and S the long-run covariance of the scores g_t = z_t e_t,
    estimated by Newey-West (Bartlett kernel) with Andrews & Monahan's (1992) VAR(1) prewhitening -- g_t = B g_{t-1}
    + u_t, S = (I - B)^-1 S_u (I - B)^-T -- and the small-sample factor n / (n - p). lags (for u) defaults to
    Andrews' (1991) AR(1) plug-in bandwidth."""
    Z = X if Z is None else Z
    S, lags = long_run_covariance(Z * e[:, None], lags=lags)
    A = np.linalg.inv(Z.T @ X)
    return A @ S @ A.T, lags


def long_run_covariance(g: np.ndarray, *, lags: int | None = None):
    """(S, lags): the long-run covariance sum_j E[g_t g_{t-j}'] of a score series g (n x p), estimated by Newey-West
    (Bartlett kernel) with Andrews & Monahan's (1992) VAR(1) prewhitening -- g_t = B g_{t-1} + u_t,
    S = (I - B)^-1 S_u (I - B)^-T, eigenvalues of B capped at 0.97 -- and the small-sample factor n / (n - p).
    lags (for u) defaults to Andrews' (1991) AR(1) plug-in bandwidth."""
    n, p = g.shape
    B = np.linalg.lstsq(g[:-1], g[1:], rcond=None)[0].T
    ev = np.abs(np.linalg.eigvals(B))
    if ev.max() > 0.97:  # keep the recolouring stable (Andrews & Monahan's eigenvalue cap)
        U, sv, Vt = np.linalg.svd(B)
        B = U @ np.diag(np.minimum(sv, 0.97)) @ Vt
    u = g[1:] - g[:-1] @ B.T
    if lags is None:
        lags = int(min(max(math.ceil(_bartlett_lags(u)), 1), n // 4))
    lags = int(lags)
    if not (0 <= lags < n - 1):
        raise ValueError(f"hac_lags = {lags} must be a whole number in 0..{n - 2}")
    Su = _bartlett(u, lags)
    D = np.linalg.inv(np.eye(p) - B)
    S = D @ Su @ D.T * (n / (n - 1)) * (n / (n - p))
    return S, lags


def _chi2_1_sf(x: float) -> float:
    """P(X > x) for X chi-squared with 1 degree of freedom, the p-value of a 1-restriction Wald test: X = Z^2 with Z
    standard normal, so P = erfc(sqrt(x / 2)) (the standard library's erfc: scipy.stats.chi2.sf(x, 1) within 2e-13
    relative for x in 0..3000 where SciPy's is above 1e-300, without the 0.3-0.5 s of CPU time that importing
    scipy.stats or scipy.special costs a process's first fit; decision FV17)."""
    return math.erfc(math.sqrt(max(float(x), 0.0) / 2.0))


def dynamics_frequency(log) -> float:
    """The closed loop's natural frequency, Hz, from the record: the -90 degree phase crossing of the response
    reference -> measured position (Welch estimate, scipy.signal.csd/welch, where the coherence exceeds 0.5); for a
    second-order loop that is its natural frequency. Needs the log's reference; ValueError otherwise."""
    from scipy import signal

    if log.reference is None:
        raise ValueError("dynamics_hz: the log has no reference signal to estimate the closed loop's natural "
                         "frequency from; give dynamics_hz (Hz, the closed loop's bandwidth)")
    fs = 1.0 / log.sample_period_s
    n = len(log)
    nper = int(2 ** math.floor(math.log2(max(64, n // 8))))
    f, pxy = signal.csd(log.reference, log.measured, fs=fs, nperseg=nper, detrend="linear")
    _, pxx = signal.welch(log.reference, fs=fs, nperseg=nper, detrend="linear")
    _, coh = signal.coherence(log.reference, log.measured, fs=fs, nperseg=nper, detrend="linear")
    ok = (f > 0) & (pxx > 0) & (coh > 0.5)
    ph = np.unwrap(np.angle(pxy[ok] / pxx[ok]))
    fo = f[ok]
    below = np.flatnonzero(ph < -np.pi / 2)
    if not len(below) or below[0] == 0:
        raise ValueError("dynamics_hz: the reference -> position response of this log does not cross -90 degrees "
                         "where it is coherent; give dynamics_hz (Hz, the closed loop's bandwidth)")
    i = below[0]
    return float(np.interp(-np.pi / 2, [ph[i], ph[i - 1]], [fo[i], fo[i - 1]]))


def _decimate(x: np.ndarray, nd: int) -> np.ndarray:
    """MATLAB-style decimate: Chebyshev-I order 8, 0.05 dB ripple, cut-off 0.8/nd of Nyquist, zero phase
    (filtfilt with a 3 x order reflection), keeping the samples aligned to the last one."""
    from scipy import signal

    if nd == 1:
        return x
    b, a = signal.cheby1(8, 0.05, 0.8 / nd)
    y = signal.filtfilt(b, a, x, axis=0, padlen=3 * 8)
    n = len(x)
    nout = -(-n // nd)
    return y[nd - (nd * nout - n) - 1::nd]


def filtered_derivatives(q, ts: float, cutoff_hz: float, order: int = 4):
    """(q^, q^', q^'') of a sampled position: zero-phase Butterworth low-pass (scipy.signal.butter + filtfilt with a
    3 x order reflection, as MATLAB's filtfilt) then central differences (numpy.gradient). Units: those of q, per s
    and per s^2."""
    from scipy import signal

    wn = cutoff_hz * 2 * ts
    if not (0 < wn < 1):
        raise ValueError(f"cutoff_hz = {cutoff_hz} must be in (0, {0.5 / ts:g}) Hz (below Nyquist)")
    b, a = signal.butter(order, wn)
    qf = signal.filtfilt(b, a, q, padlen=3 * order)
    dq = np.gradient(qf, ts)
    return qf, dq, np.gradient(dq, ts)


@dataclass(frozen=True)
class IdimResult(JsonResult):
    """An IDIM estimate that explains itself.

    parameters: name -> :class:`servobench.identify.Estimate` (HAC standard errors); std_error_iid: the textbook
    standard errors (sigma^2 (X'X)^-1, as the benchmark prints them) for comparison; relative_error_pct:
    100 ||y - X theta|| / ||y||; condition_number of the (decimated) observation matrix; residual_std in the
    effort's unit; not_identified: names whose HAC standard error exceeds max_relative_std_error of their own value;
    warnings: not-identified parameters and model misfit (friction asymmetry); diagnostics: residual
    autocorrelation, the asymmetry test's statistic and p-value.
    """

    method: str
    friction: str
    parameters: dict
    std_error_iid: dict
    covariance: np.ndarray = field(repr=False)
    relative_error_pct: float = 0.0
    condition_number: float = 0.0
    residual_std: float = 0.0
    n_samples: int = 0
    decimation: int = 1
    cutoff_hz: float = 0.0
    dynamics_hz: float = 0.0
    hac_lags: int = 0
    not_identified: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    diagnostics: dict = field(default_factory=dict, repr=False)
    linear: bool = True
    time_s: np.ndarray | None = field(default=None, repr=False)
    measured: np.ndarray | None = field(default=None, repr=False)
    predicted: np.ndarray | None = field(default=None, repr=False)
    lead_m_per_rev: float | None = None

    def __getitem__(self, name: str) -> float:
        return self.parameters[name].value

    def values(self) -> dict:
        """name -> value, in the axis's units."""
        return {k: e.value for k, e in self.parameters.items()}

    @property
    def residual(self) -> np.ndarray:
        """measured - predicted effort per decimated sample, N or N*m."""
        return self.measured - self.predicted

    def to_dataframe(self, which: str = "parameters"):
        """A pandas DataFrame: ``"parameters"`` (default) one row per parameter (index ``name``: ``value``,
        ``std_error`` (HAC), ``std_error_iid``, ``relative_std_error``, ``unit``, ``not_identified``);
        ``"samples"`` the decimated samples the estimate used: ``time_s`` (s) and the effort measured, predicted by
        the model and their difference, ``measured_n``/``predicted_n``/``residual_n`` on a linear axis (N),
        ``..._nm`` on a rotary one (N*m). ``df.attrs["units"]`` gives the units."""
        if which == "parameters":
            rows = list(self.parameters.values())
            return dataframe({"name": [e.name for e in rows], "value": [e.value for e in rows],
                              "std_error": [e.std_error for e in rows],
                              "std_error_iid": [self.std_error_iid.get(e.name, math.nan) for e in rows],
                              "relative_std_error": [e.relative_std_error for e in rows],
                              "unit": [e.unit for e in rows],
                              "not_identified": [e.name in self.not_identified for e in rows]},
                             {"relative_std_error": "1"}, index="name")
        if which == "samples":
            if self.time_s is None or self.measured is None or self.predicted is None:
                raise ValueError("to_dataframe: this IdimResult kept no samples (time_s/measured/predicted are None)")
            u, unit = ("n", "N") if self.linear else ("nm", "N*m")
            return dataframe({"time_s": self.time_s, f"measured_{u}": self.measured, f"predicted_{u}": self.predicted,
                              f"residual_{u}": self.residual},
                             {"time_s": "s", f"measured_{u}": unit, f"predicted_{u}": unit, f"residual_{u}": unit})
        raise ValueError(f"to_dataframe: which = {which!r} must be 'parameters' or 'samples'")

    @property
    def misfit(self) -> bool:
        """True when the model's structure is rejected by the data (see warnings)."""
        return bool(self.diagnostics.get("asymmetry_p_value", 1.0) < 0.01)

    def relative_errors(self, reference: dict) -> dict:
        """name -> value / reference - 1, for the names both have."""
        return {k: self[k] / v - 1 for k, v in reference.items() if k in self.parameters}

    def cross_test(self, log, *, edge_samples: int = 49) -> float:
        """The benchmark's cross-test validation (EMPS description eq. 11, its Script_IDIM_LS_CTV): the effort of
        another record `log` (an :class:`IdentificationLog` the fit did not use) reconstructed with these
        parameters through the same filtering (position low-pass ``cutoff_hz``, central differences, decimation by
        ``decimation``, `edge_samples` dropped), and its relative error 100 ||y - X theta|| / ||y||, %."""
        from .idlog import IdentificationLog

        if not isinstance(log, IdentificationLog):
            raise TypeError("cross_test: log must be an IdentificationLog")
        if log.linear != self.linear:
            raise ValueError(f"cross_test: the log is a {'linear' if log.linear else 'rotary'} axis and the result a "
                             f"{'linear' if self.linear else 'rotary'} one (m, N against rad, N*m)")
        offset = "offset" in self.parameters
        X, y, *_ = _prepare(log, self.dynamics_hz, self.cutoff_hz, self.decimation, edge_samples, self.friction,
                            offset)
        theta = np.array([self[n] for n, _u in _names(self.friction, offset, self.linear)])
        return float(100 * np.linalg.norm(y - X @ theta) / np.linalg.norm(y))

    def __str__(self) -> str:
        unit = "N" if self.linear else "N*m"
        lines = [f"{self.method} ({self.friction} friction): {self.n_samples} samples after decimation by "
                 f"{self.decimation} (position low-pass {self.cutoff_hz:.4g} Hz, dynamics {self.dynamics_hz:.4g} Hz)",
                 f"  {'name':8s} {'value':>12s} {'std err HAC':>12s} {'(%)':>7s} {'std err iid':>12s}"]
        for k, e in self.parameters.items():
            lines.append(f"  {k:8s} {e.value:12.6g} {e.std_error:12.4g} {100 * e.relative_std_error:6.3g}% "
                         f"{self.std_error_iid[k]:12.4g}  {e.unit}")
        lines.append(f"  relative error {self.relative_error_pct:.4g} %, residual std {self.residual_std:.4g} {unit}, "
                     f"condition number {self.condition_number:.4g}, HAC lags {self.hac_lags}")
        if self.linear:
            from .idlog import motor_side_line

            side = motor_side_line([(k, e.value, e.unit) for k, e in self.parameters.items()], self.lead_m_per_rev)
            if side:
                lines.append("  " + side)
        if self.not_identified:
            lines.append("  NOT IDENTIFIED: " + ", ".join(self.not_identified))
        for w in self.warnings:
            lines.append("  warning: " + w)
        return "\n".join(lines)

    def plot(self, *, ax=None, path: str | None = None):
        """Measured and reconstructed effort and their difference over time (the benchmark's "direct comparison").
        Returns the data drawn: {time_s, measured, predicted, residual}."""
        import matplotlib.pyplot as plt

        if ax is None:
            _fig, ax = plt.subplots(figsize=(8, 3.5))
        unit = "N" if self.linear else "N*m"
        ax.plot(self.time_s, self.measured, lw=0.8, label="measured")
        ax.plot(self.time_s, self.predicted, "--", lw=0.8, label=f"{self.method} model")
        ax.plot(self.time_s, self.residual, lw=0.6, label="error")
        ax.set_xlabel("time, s")
        ax.set_ylabel(f"effort, {unit}")
        ax.legend(loc="upper right", fontsize=8)
        if path:
            ax.figure.savefig(path, dpi=110)
        return {"time_s": self.time_s, "measured": self.measured, "predicted": self.predicted,
                "residual": self.residual}


def _check_rel(owner, v):
    v = float(v)
    if not (math.isfinite(v) and 0 < v <= 10):
        raise ValueError(f"{owner}.max_relative_std_error = {v} must be in (0, 10]")


def _prepare(log, dynamics_hz, cutoff_hz, decimation, edge_samples, friction, offset, alignment="sample",
             min_samples=50):
    from .idlog import IdentificationLog

    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (IdentificationLog.from_mat / from_csv / from_arrays)")
    if log.measured_is_speed:
        raise ValueError("idim: the log's measured signal is a speed; the IDIM needs a measured position")
    if friction not in FRICTION_MODELS:
        raise ValueError(f"friction = {friction!r} is not one of {FRICTION_MODELS}")
    if offset and friction == "asymmetric":
        raise ValueError("offset = True with friction = 'asymmetric': a constant effort is indistinguishable from "
                         "shifted Coulomb levels (Fc+ + offset, Fc- - offset) while the axis moves; leave offset=None")
    ts = log.sample_period_s
    nyq = 0.5 / ts
    if dynamics_hz is None:
        dynamics_hz = dynamics_frequency(log)
    dynamics_hz = float(dynamics_hz)
    if not (math.isfinite(dynamics_hz) and 0 < dynamics_hz < nyq / 5):
        raise ValueError(f"dynamics_hz = {dynamics_hz} must be in (0, {nyq / 5:g}) Hz (5 x dynamics_hz is the "
                         "position filter's cut-off, below Nyquist)")
    fc = 5 * dynamics_hz if cutoff_hz is None else float(cutoff_hz)
    if not (math.isfinite(fc) and 0 < fc < nyq):
        raise ValueError(f"cutoff_hz = {cutoff_hz} must be in (0, {nyq:g}) Hz")
    nd = max(1, round(0.8 * nyq / (2 * dynamics_hz))) if decimation is None else decimation
    if decimation is not None and not (float(nd) == int(nd) and 1 <= int(nd) <= 1000):
        raise ValueError(f"decimation = {decimation} must be a whole number in 1..1000")
    nd = int(nd)
    if not (float(edge_samples) == int(edge_samples) and 0 <= int(edge_samples) <= 10**6):
        raise ValueError(f"edge_samples = {edge_samples} must be a whole number in 0..1000000")
    edge = int(edge_samples)
    need = max(min_samples * nd, 4 * edge + 10, 200)
    if len(log) < need:
        raise ValueError(f"idim: the record is too short ({len(log)} samples); it needs at least {need} for "
                         f"decimation by {nd} and {edge} edge samples")
    _, dq, ddq = filtered_derivatives(log.measured, ts, fc)
    v = dq[edge:]
    thr = 1e-3 * float(np.max(np.abs(v)))
    if not (thr > 0 and np.any(v > thr) and np.any(v < -thr)):
        raise ValueError("idim: the record has no motion reversal (the speed keeps one sign): Coulomb friction "
                         "and the offset cannot be told apart; record motion in both directions")
    phi = observation_matrix(v, ddq[edge:], friction, offset)
    if alignment == "zoh":  # the effort held over [t_k-1, t_k+1) on average: what the central difference at t_k sees
        tau = np.concatenate([[log.torque_nm[0]], 0.5 * (log.torque_nm[1:] + log.torque_nm[:-1])])
    elif alignment == "sample":
        tau = log.torque_nm
    else:
        raise ValueError(f"effort_alignment = {alignment!r} must be 'sample' or 'zoh'")
    y = tau[edge:]
    Xd = _decimate(phi, nd)
    yd = _decimate(y, nd)
    names = [n for n, _u in _names(friction, offset, log.linear)]
    cn = Xd / np.linalg.norm(Xd, axis=0)
    sv = np.linalg.svd(cn, compute_uv=False)
    if not (sv[-1] > 1e-8 * sv[0]):
        _u, _s, vt = np.linalg.svd(cn)
        worst = [names[i] for i in np.argsort(-np.abs(vt[-1]))[:2]]
        raise ValueError(f"idim: the observation matrix is rank-deficient: {worst[0]} and {worst[1]} cannot be told "
                         "apart on this record (excite the axis more, or drop one of them)")
    td = _decimate(log.time_s[edge:], nd)
    return Xd, yd, td, nd, fc, dynamics_hz


def _result(method, friction, offset, log, X, y, theta, td, nd, fc, fdyn, Z, max_rel, hac_lags, extra_diag=None):
    from .identify import Estimate

    e = y - X @ theta
    cov, lags = hac_covariance(X, e, lags=hac_lags, Z=Z)
    names = _names(friction, offset, log.linear)
    s2 = float(np.var(e, ddof=1))
    if Z is None:
        cov_iid = s2 * np.linalg.inv(X.T @ X)
    else:
        A = np.linalg.inv(Z.T @ X)
        cov_iid = s2 * A @ (Z.T @ Z) @ A.T
    se = np.sqrt(np.maximum(np.diag(cov), 0))
    params = {n: Estimate(n, float(v), float(s), u, math.nan, False, False) for (n, u), v, s in zip(names, theta, se)}
    not_id = [n for (n, _u), v, s in zip(names, theta, se) if not (s <= max_rel * abs(v))]
    r = e - e.mean()
    acf = [float(r[k:] @ r[:-k] / (r @ r)) for k in (1, 2, 5, 10) if k < len(r)]
    diag = {"residual_acf_lags_1_2_5_10": acf, "hac_lags": lags}
    diag.update(extra_diag or {})
    warnings = []
    if not_id:
        warnings.append(f"not identified (HAC std error > {100 * max_rel:g} % of the value): {', '.join(not_id)}")
    return IdimResult(method, friction, params, {n: float(s) for (n, _), s in zip(names, np.sqrt(np.diag(cov_iid)))},
                      cov, float(100 * np.linalg.norm(e) / np.linalg.norm(y)), float(np.linalg.cond(X)),
                      float(np.std(e, ddof=1)), len(y), nd, fc, fdyn, lags, not_id, warnings, diag, log.linear,
                      td, y, X @ theta, log.lead_m_per_rev if log.linear else None)


def _asymmetry_check(X_asym, y, theta_asym, Z=None):
    """HAC Wald test of Fv+ = Fv- on an asymmetric fit (without offset, it nests the symmetric model with offset:
    Fc = (Fc+ + Fc-)/2, offset = (Fc+ - Fc-)/2): (statistic, p-value, Fv+ - Fv-)."""
    e = y - X_asym @ theta_asym
    cov, _ = hac_covariance(X_asym, e, Z=Z)
    r = np.zeros(X_asym.shape[1])
    r[1], r[3] = 1, -1
    d = float(r @ theta_asym)
    W = d * d / float(r @ cov @ r)
    return W, _chi2_1_sf(W), d


def idim_ls(log, *, friction: str = "symmetric", offset: bool | None = None, dynamics_hz: float | None = None,
            cutoff_hz: float | None = None, decimation: int | None = None, edge_samples: int = 49,
            max_relative_std_error: float = 0.1, hac_lags: int | None = None,
            effort_alignment: str = "sample") -> IdimResult:
    """IDIM-LS: the inverse dynamic model fitted by least squares with the benchmark's data filtering.

    log
        an :class:`IdentificationLog` with a measured position (m or rad) and the effort (N or N*m), with motion
        in both directions.
    friction
        'symmetric' (M, Fv, Fc) or 'asymmetric' (M, Fv+, Fc+, Fv-, Fc-).
    offset
        a constant effort term (N or N*m); None (default): with symmetric friction only -- with asymmetric friction
        a constant is Fc+ and Fc- shifted (Fc+ + offset, Fc- - offset) and cannot be told apart from them.
    dynamics_hz
        the closed loop's dynamics frequency f_dyn, Hz (the position loop's bandwidth, e.g. the 20 Hz the EMPS
        description states); None: estimated from the log's reference -> position response
        (:func:`dynamics_frequency`). The position filter's cut-off is ``cutoff_hz`` = 5 f_dyn and the decimation
        nd = round(0.8 f_nyquist / (2 f_dyn)) unless given.
    edge_samples
        samples dropped at the start (the filter's and differences' edge; the benchmark drops 49).
    max_relative_std_error
        a parameter whose HAC standard error exceeds this fraction of its own value is reported not identified.
    hac_lags
        the Newey-West bandwidth in decimated samples; None: Andrews' plug-in rule.
    effort_alignment
        'sample' (default, the benchmark's procedure): the effort sample k is paired with the derivatives at t_k;
        'zoh': with the mean of samples k-1 and k -- for an effort held over [t_k, t_k+1) (a zero-order hold, as
        servobench's logs), the central second difference at t_k sees exactly that mean, and pairing it with sample
        k alone biases M by about Fv Ts / 2.

    With symmetric friction the result also tests friction asymmetry (HAC Wald test on the asymmetric fit) and
    warns when the data reject symmetry at the 1 % level (``result.misfit``: a mis-specified friction model).
    """
    from scipy import linalg

    _check_rel("idim_ls", max_relative_std_error)
    offset = (friction == "symmetric") if offset is None else bool(offset)
    X, y, td, nd, fc, fdyn = _prepare(log, dynamics_hz, cutoff_hz, decimation, edge_samples, friction, offset,
                                      effort_alignment)
    theta = linalg.lstsq(X, y)[0]
    extra, res_warn = {}, []
    if friction == "symmetric" and offset:
        Xa, ya, *_ = _prepare(log, fdyn, fc, nd, edge_samples, "asymmetric", False, effort_alignment)
        ta = linalg.lstsq(Xa, ya)[0]
        W, p, d = _asymmetry_check(Xa, ya, ta)
        extra.update(asymmetry_wald=W, asymmetry_p_value=p, asymmetry_fv_difference=d)
        if p < 0.01:
            res_warn.append(f"friction is asymmetric (HAC Wald test of Fv+ = Fv-: p = {p:.2g}, Fv+ - Fv- = {d:.4g}): "
                            "the symmetric model is mis-specified, use friction='asymmetric'")
    r = _result("IDIM-LS", friction, offset, log, X, y, theta, td, nd, fc, fdyn, None, max_relative_std_error,
                hac_lags, extra)
    r.warnings.extend(res_warn)
    return r


def idim_iv(log, *, friction: str = "symmetric", offset: bool | None = None, dynamics_hz: float | None = None,
            cutoff_hz: float | None = None, decimation: int | None = None, edge_samples: int = 49,
            max_relative_std_error: float = 0.1, hac_lags: int | None = None,
            effort_alignment: str = "sample") -> IdimResult:
    """IDIM-IV: the model and filtering of :func:`idim_ls`, estimated with instrumental variables
    theta = (Z'X)^-1 Z'y, the instruments Z being the observation matrix built from the closed loop's position
    reference (filtered and differentiated the same way). The reference is free of the measurement noise and of the
    disturbance the controller feeds back, so the estimate is not biased by them in closed loop, where LS can be
    (Janot, Vandanjon & Gautier 2014 build instruments from a simulated closed loop; the reference is the
    noise-free signal every closed-loop record has). Needs the log's reference; the arguments are those of
    :func:`idim_ls`."""
    from .idlog import IdentificationLog

    if not isinstance(log, IdentificationLog):
        raise TypeError("log must be an IdentificationLog (IdentificationLog.from_mat / from_csv / from_arrays)")
    if log.reference is None:
        raise ValueError("idim_iv: the log has no reference signal (the instruments are built from it); read the "
                         "record with its reference column")
    _check_rel("idim_iv", max_relative_std_error)
    offset = (friction == "symmetric") if offset is None else bool(offset)
    X, y, td, nd, fc, fdyn = _prepare(log, dynamics_hz, cutoff_hz, decimation, edge_samples, friction, offset,
                                      effort_alignment)
    ref_log = log._replace(measured=log.reference, reference=None)
    Z, *_ = _prepare(ref_log, fdyn, fc, nd, edge_samples, friction, offset, effort_alignment)
    ZX = Z.T @ X
    if not np.isfinite(np.linalg.cond(ZX)) or np.linalg.cond(ZX) > 1e12:
        raise ValueError("idim_iv: the reference-based instruments are (nearly) uncorrelated with the regressors")
    theta = np.linalg.solve(ZX, Z.T @ y)
    return _result("IDIM-IV", friction, offset, log, X, y, theta, td, nd, fc, fdyn, Z, max_relative_std_error,
                   hac_lags)
