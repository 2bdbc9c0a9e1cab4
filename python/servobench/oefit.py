"""The output-error fit's plan: where it starts, how long its segments are, how its starts are compared, and how its
standard errors are made to hold for correlated residuals. Used by :func:`servobench.identify.fit_time`.

* **Start**: without a guess, a rigid fit starts from :func:`servobench.idim.idim_ls` (inertia/mass, viscous and
  Coulomb friction, offset as the constant load).
* **Segment length** (``segment_samples="auto"``): the correlation time of the IDIM residual -- the first lag at
  which its autocorrelation falls below 1/e, in samples of the log -- clipped to 50..1000 samples. The multiple-
  shooting fit treats what the model does not explain as white noise; over a segment longer than the disturbance's
  correlation time the integrated disturbance (a random walk in speed) dominates the residual and biases the
  estimates, over a shorter one it stays bounded (docs/decisions.md, section I19).
* **Starts**: the plan's start and ``n_starts - 1`` others, each free parameter scaled by a factor drawn
  log-uniformly in [1/1.5, 1.5] (seeded). Two converged starts *disagree* when a parameter differs by more than
  2 sqrt(se1^2 + se2^2); the result says so.
* **Threads**: the starts are independent fits (Ceres with one thread each, the GIL released), so
  :func:`run_starts` can run them on a thread pool (``fit_time(start_threads=2)``): the same results in less wall
  time on several cores; the CPU time is the same (threads do not make a fit cheaper, they overlap the starts).
* **Standard errors** (:func:`segment_sandwich`): Ceres' covariance s^2 (J'J)^-1 assumes white residuals; the
  output-error residual is coloured (an unmeasured disturbance integrates into a random walk in speed within each
  segment), and the white-noise bars were 7-25x too tight on the EMPS record. fit_time reports the sandwich
  H^-1 S H^-1 instead: H = J~'J~ with each segment's own start state projected out of the parameter columns (the
  Schur complement Ceres eliminates), S the long-run covariance of the per-segment scores g_s = J~_s' r~_s --
  Newey-West over the sequence of segments with the IDIM's VAR(1) prewhitening and Andrews' plug-in bandwidth
  (:func:`servobench.idim.long_run_covariance`), small-sample factor m/(m - p) for m segments. Segments are the clusters: within one the residual is strongly correlated, between
  neighbours weakly (the segment is about one correlation time long), so a sum of per-segment scores with a few lags
  holds where a per-sample correction does not (docs/decisions.md, J19).
"""

from __future__ import annotations

import math
import os
import threading
from concurrent import futures
from dataclasses import dataclass

import numpy as np

from ._serialise import JsonResult

__all__ = ["segment_length", "start_from_idim", "perturbed_starts", "long_run_variance_ratio", "disagreements",
           "segment_sandwich", "SegmentSandwich", "run_starts", "shooting_options"]

MIN_SEGMENT, MAX_SEGMENT = 50, 1000


def _acf_time(e: np.ndarray) -> float:
    """First lag (fractional, by linear interpolation) where the autocorrelation of e falls below 1/e."""
    r = e - e.mean()
    n = len(r)
    f = np.fft.rfft(r, 2 * n)
    acf = np.fft.irfft(f * np.conj(f))[:n]
    acf = acf / acf[0] if acf[0] > 0 else acf
    below = np.flatnonzero(acf < 1 / math.e)
    if not len(below):
        return float(n)
    k = int(below[0])
    return float(k - 1 + (acf[k - 1] - 1 / math.e) / (acf[k - 1] - acf[k])) if k > 0 else 0.0


def segment_length(idim_result) -> tuple[int, str]:
    """(segment samples, how) from an IDIM result's residual: its correlation time (1/e) times the decimation
    factor, clipped to 50..1000 samples."""
    tau = _acf_time(idim_result.residual) * idim_result.decimation
    n = int(min(max(round(tau), MIN_SEGMENT), MAX_SEGMENT))
    return n, (f"segments of {n} samples: the correlation time of the IDIM residual ({tau:.0f} samples, clipped to "
               f"{MIN_SEGMENT}..{MAX_SEGMENT})")


def start_from_idim(idim_result) -> dict:
    """A rigid fit's guess from an IDIM-LS result (symmetric friction with offset)."""
    v = idim_result.values()
    return {"inertia_kgm2": v["M"], "viscous_nms": max(v["Fv"], 1e-12 * abs(v["M"])),
            "coulomb_nm": max(v["Fc"], 0.0), "load_nm": v.get("offset", 0.0)}


def perturbed_starts(guess: dict, free: set, n_starts: int, seed: int = 0, spread: float = 1.5) -> list[dict]:
    """[guess] + n_starts - 1 copies with each free parameter scaled by a seeded log-uniform factor in
    [1/spread, spread] (the Stribeck speed excepted: its bounds follow its guess)."""
    rng = np.random.default_rng(seed)
    out = [dict(guess)]
    for _ in range(n_starts - 1):
        g = dict(guess)
        for k in sorted(free):
            if "stribeck_speed" in k:
                continue
            g[k] = guess[k] * float(np.exp(rng.uniform(-math.log(spread), math.log(spread))))
        out.append(g)
    return out


def run_starts(fit_one, guesses: list, *, threads: int | None = None, progress=None) -> list:
    """[fit_one(guess, progress) for each guess], the first start's ValueError raised, later starts' dropped.

    threads: how many starts run at once (None: min(len(guesses), CPU count)); each fit releases the GIL, so
    threads overlap them (wall time), not cheapen them (CPU time). Results do not depend on it. With a `progress`
    callback the starts run one after the other (the callback sees one solve at a time). Ctrl-C in the calling
    thread stops every running start at its next iteration and is re-raised."""
    n = len(guesses)
    threads = min(n, os.cpu_count() or 1) if threads is None else int(threads)
    out = []
    if threads <= 1 or n == 1 or progress is not None:
        for i, g in enumerate(guesses):
            try:
                out.append(fit_one(g, progress))
            except ValueError:
                if i == 0:
                    raise
        return out
    stop = threading.Event()

    def keep_going(_iteration, _cost):
        if stop.is_set():  # raised through the solver like the C++ side's own Ctrl-C: no later stage, no covariance
            raise KeyboardInterrupt
        return True

    with futures.ThreadPoolExecutor(max_workers=threads) as pool:
        jobs = [pool.submit(fit_one, g, keep_going) for g in guesses]
        try:
            while futures.wait(jobs, timeout=0.05).not_done:
                pass
        except BaseException:  # Ctrl-C: every start ends at its next iteration, then the pool joins them
            stop.set()
            raise
    for i, job in enumerate(jobs):
        try:
            out.append(job.result())
        except ValueError:
            if i == 0:
                raise
    return out


def long_run_variance_ratio(residual: np.ndarray) -> float:
    """Long-run variance / variance of a residual with NaN between segments (each finite run is one segment):
    1 + 2 sum_j w_j rho_j, Bartlett weights, Andrews' AR(1) bandwidth; >= 1."""
    r = np.asarray(residual, float)
    ok = np.isfinite(r)
    if ok.sum() < 10:
        return 1.0
    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(int), [0]])))
    runs = [r[a:b] for a, b in zip(edges[::2], edges[1::2]) if b - a > 2]
    c0 = sum(float(x @ x) for x in runs)
    c1 = sum(float(x[1:] @ x[:-1]) for x in runs)
    if c0 <= 0:
        return 1.0
    rho = min(max(c1 / c0, -0.97), 0.97)
    n = sum(len(x) for x in runs)
    alpha = 4 * rho ** 2 / ((1 - rho) ** 2 * (1 + rho) ** 2)
    lags = int(min(max(math.ceil(1.1447 * (alpha * n) ** (1 / 3)), 1), max(len(x) for x in runs) - 1))
    total = 1.0
    for j in range(1, lags + 1):
        cj = sum(float(x[j:] @ x[:-j]) for x in runs if len(x) > j)
        total += 2 * (1 - j / (lags + 1)) * cj / c0
    return max(total, 1.0)


def disagreements(fits: list) -> list[str]:
    """Pairs of converged fits whose free parameters differ by more than 2 combined standard errors."""
    out = []
    ok = [(i, f) for i, f in enumerate(fits) if f.converged]
    for a in range(len(ok)):
        for b in range(a + 1, len(ok)):
            (i, fa), (j, fb) = ok[a], ok[b]
            for k, ea in fa.parameters.items():
                eb = fb.parameters[k]
                if ea.fixed:
                    continue
                s = math.hypot(ea.std_error, eb.std_error)
                if math.isfinite(s) and abs(ea.value - eb.value) > 2 * s:
                    out.append(f"starts {i} and {j} disagree on {k}: {ea.value:.6g} vs {eb.value:.6g} "
                               f"(> 2 x {s:.3g})")
    return out


@dataclass(frozen=True)
class SegmentSandwich(JsonResult):
    """The segment-clustered sandwich covariance of an output-error fit (:func:`segment_sandwich`).

    names: the free parameters (SI, the fit's internal order; the Stribeck entry is the excess Fs - Fc);
    covariance: p x p; covariance_iid: s^2 H^-1 (white residuals) for comparison; lags: Newey-West lags over
    segments; segments: their number; residual_rms: of the re-solved segment states, in encoder counts."""

    names: list
    covariance: np.ndarray
    covariance_iid: np.ndarray
    lags: int
    segments: int
    residual_rms: float
    asymmetry_p_value: float = 1.0
    asymmetry_viscous: float = 0.0

    def to_dataframe(self, which: str = "covariance"):
        """A covariance matrix as a pandas DataFrame labelled by the parameter names on both axes (SI units, the
        fit's internal order): ``"covariance"`` (default, the sandwich) or ``"covariance_iid"`` (s^2 H^-1)."""
        import pandas as pd

        if which not in ("covariance", "covariance_iid"):
            raise ValueError(f"to_dataframe: which = {which!r} must be 'covariance' or 'covariance_iid'")
        return pd.DataFrame(np.asarray(getattr(self, which)), index=list(self.names), columns=list(self.names))

    def std_error(self, name: str) -> float:
        i = self.names.index(name)
        return float(math.sqrt(max(self.covariance[i, i], 0.0)))


def shooting_options(log, segment_samples: int, options: dict) -> dict:
    """The keyword arguments of ``_core.identify_shooting_problem`` / ``identify_shooting_residual`` that describe
    the final stage of a :func:`servobench.fit_time` call with these options."""
    from . import _core
    from . import _options as _opts

    d = {f.name: f.default for f in _opts.option_fields(_core.TimeFitOptions)}  # the struct's defaults (OQ2)
    scale = log.measurement_count
    return dict(sample_period_s=log.sample_period_s, measured_is_speed=log.measured_is_speed,
                measured_on_load=log.measured_on_load, segment_samples=int(segment_samples),
                min_segment_samples=min(d["min_segment_samples"], int(segment_samples)),
                edge_samples=options.get("edge_samples", d["edge_samples"]),
                direction_window=options.get("direction_window", d["direction_window"]),
                rest_threshold=options.get("rest_threshold_counts", d["rest_threshold"]), substeps=log.substeps,
                current_bw_hz=log.current_bw_hz,
                stribeck_exponent=options.get("stribeck_exponent", d["stribeck_exponent"]), measurement_scale=scale)


def segment_sandwich(log, model: str, values: dict, free, segment_samples: int, options: dict | None = None,
                     *, states=None, max_state_iterations: int = 8) -> SegmentSandwich:
    """The sandwich covariance of the fit's free parameters at `values` (SI, external names), clustered by
    shooting segment (see the module's text).

    states: the fit's own segment start states (``fit.segment_states``, one row per segment, the final stage's
    layout), used as they are: the fit solved them jointly with the parameters (one more Gauss-Newton step on them
    moved the standard errors of the three 5 s bench logs by < 5e-7, relative; decision FV19). Without them (or
    when their number does not match the layout) the states start from the data (a line through each segment's
    first samples) and are re-solved with the parameters held (Gauss-Newton per segment, at most
    `max_state_iterations`, stopping when the residual stops falling by 0.1 %). Re-solving from the data can fail
    where a segment starts in stick-slip: compare ``residual_rms`` with the fit's (decision J46). Costs one
    residual-and-Jacobian evaluation with the fit's states (0.013 s CPU for 25,000 samples), a few without."""
    from . import _core

    kw = shooting_options(log, segment_samples, options or {})
    names = [p["name"] for p in _core.identify_parameters(model)]
    sp = _core.identify_shooting_problem(log.torque_nm, log.measured, model=model, **kw)
    starts, counts = sp["starts"].astype(int), sp["counts"].astype(int)
    ns = int(sp["state_size"])
    x = np.array(sp["states"], float)
    if states is not None:
        given = np.asarray(states, float).ravel()
        if given.shape == x.shape and np.all(np.isfinite(given)):
            x = given.copy()
            max_state_iterations = 0  # the fit's own states: no refinement
    p = np.array([values[n] for n in names], float)
    si = names.index("static_nm" if model == "rigid" else "motor_static_nm")
    ci = names.index("coulomb_nm" if model == "rigid" else "motor_coulomb_nm")
    p[si] = p[si] - p[ci] if p[si] > p[ci] else 0.0  # the internal Stribeck excess
    nseg, npar = len(starts), len(p)
    seg = np.repeat(np.arange(nseg), counts)
    fi = [i for i, n in enumerate(names) if n in free]

    offsets = np.concatenate(([0], np.cumsum(counts)[:-1]))
    # The Jacobian's column layout when every entry is stored: per row the parameters, then its segment's states.
    layout = np.concatenate((np.broadcast_to(np.arange(npar), (len(seg), npar)),
                             npar + ns * seg[:, None] + np.arange(ns)), axis=1)

    def evaluate():
        r, (d, idx, ptr), shape = _core.identify_shooting_residual(
            log.torque_nm, log.measured, model=model, starts=starts, counts=counts, parameters=p, states=x,
            jacobian=True, **kw)
        idx = idx.astype(np.int64)
        m, w = shape[0], npar + ns
        if len(d) == m * w and np.array_equal(idx.reshape(m, w), layout):
            # every row holds the parameters' columns, then its segment's states': the dense blocks are views
            blocks = np.asarray(d, float).reshape(m, w)
            return np.asarray(r, float), blocks[:, fi], blocks[:, npar:]
        rows = np.repeat(np.arange(m), np.diff(ptr.astype(np.int64)))
        jp, jx = np.zeros((m, npar)), np.zeros((m, ns))
        on_p = idx < npar
        jp[rows[on_p], idx[on_p]] = d[on_p]
        jx[rows[~on_p], idx[~on_p] - npar - ns * seg[rows[~on_p]]] = d[~on_p]
        return np.asarray(r, float), jp[:, fi], jx

    # The rows are the segments one after the other: per-segment sums by reduceat. Products over all rows go through
    # einsum, not BLAS: a threaded BLAS spins its threads on these tall, thin products and doubled the CPU time of
    # this function (0.095 -> 0.044 s on the 5 s bench log; decision FT2).
    def by_segment(m):
        return np.add.reduceat(m, offsets, axis=0)

    def dot(a, b):
        return float(np.einsum("n,n->", a, b))

    prev = math.inf
    for it in range(max_state_iterations + 1):
        r, jp, jx = evaluate()
        a = by_segment(jx[:, :, None] * jx[:, None, :])
        ai = np.linalg.pinv(a)
        ss = dot(r, r)
        if it == max_state_iterations or ss > 0.999 * prev:
            break
        prev = ss
        x_old = x.copy()
        x -= (ai @ by_segment(jx * r[:, None])[:, :, None])[:, :, 0].ravel()
    if ss > prev:  # the last step did not help: back to the previous states
        x = x_old
        r, jp, jx = evaluate()
        ss = dot(r, r)
        ai = np.linalg.pinv(by_segment(jx[:, :, None] * jx[:, None, :]))
    # each segment's state directions projected out of its parameter columns and residual (Schur complement)
    coef = ai @ by_segment(jx[:, :, None] * jp[:, None, :])
    jt = jp - np.einsum("ns,nsk->nk", jx, coef[seg])
    rt = r - np.einsum("ns,ns->n", jx, (ai @ by_segment(jx * r[:, None])[:, :, None])[:, :, 0][seg])
    g = by_segment(jt * rt[:, None])
    k = len(fi)
    from .idim import _chi2_1_sf, long_run_covariance

    s, lags = long_run_covariance(g)
    hi = np.linalg.pinv(np.einsum("ni,nj->ij", jt, jt))
    dof = max(len(r) - k - ns * nseg, 1)
    p_asym, d_asym = 1.0, 0.0
    if model == "rigid" and "viscous_nms" in free and nseg > 4:
        y = np.asarray(log.measured, float)
        direction = np.sign(y[starts + counts - 1] - y[starts])
        if np.any(direction > 0) and np.any(direction < 0):
            a = jt[:, [names[i] for i in fi].index("viscous_nms")] * direction[seg]
            a = a - np.einsum("nk,k->n", jt, hi @ np.einsum("nk,n->k", jt, a))
            h = by_segment(a * rt)
            lrv, _ = long_run_covariance(h[:, None])
            if lrv[0, 0] > 0:
                stat = float(h.sum()) ** 2 / lrv[0, 0]  # long_run_covariance is the variance of the sum
                p_asym = _chi2_1_sf(stat)
                d_asym = -2.0 * float(h.sum() / dot(a, a))  # r = model - measured: one Gauss-Newton step
    return SegmentSandwich([names[i] for i in fi], hi @ s @ hi, dot(rt, rt) / dof * hi, lags, nseg,
                           float(math.sqrt(ss / max(len(r), 1))), p_asym, d_asym)
