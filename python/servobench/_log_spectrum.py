"""The spectral view of an identification log, the starting point of a two-mass fit: :func:`log_spectrum`
(Welch H1 of torque to speed) and :func:`resonance_guess` (inertias and stiffness from its resonance and
anti-resonance). Defined here, published by :mod:`servobench.identify` (their home for pickles, saved results and the
docs; decision OR2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import _checks
from ._identified import IdentificationError
from ._serialise import JsonResult, dataframe
from .experiment import _whole
from .idlog import IdentificationLog


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
    # log of the apparent inertia 1 / (|V/T| w) in real arithmetic: at s = j w,
    # |V/T| w = |k - jl w^2 + j c w| / |k - jm jl w^2 + j c w|.
    w2 = (2 * np.pi * f[None, None, None, :]) ** 2
    cw2 = c ** 2 * w2
    lshape = 0.5 * np.log(((k - jm * jl * w2) ** 2 + cw2) / ((k - jl * w2) ** 2 + cw2))
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
