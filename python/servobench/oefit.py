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
* **Standard errors**: Ceres' covariance assumes white residuals; each is multiplied by sqrt(long-run variance /
  variance) of the fit's residual (Bartlett kernel, Andrews' bandwidth, pooled over the segments) -- the sandwich's
  correction for a slowly varying Jacobian.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["segment_length", "start_from_idim", "perturbed_starts", "long_run_variance_ratio", "disagreements"]

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
