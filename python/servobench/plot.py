"""matplotlib plots of servobench results. Functions return the Figure and draw nothing on screen by
themselves; pass `path` to write a PNG/SVG."""

from __future__ import annotations

import numpy as np


def _pyplot():
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "module://matplotlib_inline.backend_inline") and \
            not _has_display():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _has_display() -> bool:
    import os

    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def response(run, *, metrics=None, title: str | None = None, path: str | None = None):
    """Three stacked panels of a run: command and feedback position (pulse), following error (pulse) and the
    DAC output (V), over time (ms). `metrics` (a :class:`MoveMetrics`) is written into the title.
    Returns the matplotlib Figure; writes it to `path` (PNG, SVG, ...) if given."""
    plt = _pyplot()
    t_ms = np.asarray(run.time_s) * 1e3
    fig, (ax_pos, ax_err, ax_v) = plt.subplots(3, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    ax_pos.plot(t_ms, run.cmd_pos, label="command", lw=1.2)
    ax_pos.plot(t_ms, run.fb_pos, label="feedback", lw=1.0, ls="--")
    ax_pos.set_ylabel("position [pulse]")
    ax_pos.legend(loc="lower right")
    ax_err.plot(t_ms, run.error, color="C3", lw=1.0)
    ax_err.set_ylabel("following error [pulse]")
    ax_v.plot(t_ms, run.volts, color="C2", lw=1.0)
    ax_v.set_ylabel("DAC output [V]")
    ax_v.set_xlabel("time [ms]")
    for ax in (ax_pos, ax_err, ax_v):
        ax.grid(True, alpha=0.3)
    head = title or "servobench: point-to-point move"
    if metrics is not None:
        head += (f"\nrise {metrics.rise_time_s * 1e3:.2f} ms, overshoot {metrics.overshoot_pulse:.3g} pulse, "
                 f"settling {metrics.settling_time_s * 1e3:.2f} ms, peak FE {metrics.peak_following_error_pulse:.3g} pulse")
    fig.suptitle(head, fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig


def bode(freq_hz, responses, *, title: str | None = None, markers: dict | None = None, path: str | None = None,
         unwrap: bool = True):
    """Bode plot: gain (dB) and phase (deg) over log frequency (Hz).

    freq_hz: array of frequencies, Hz. responses: a complex array, or a dict {label: complex array} to overlay
    several responses on the same frequencies. markers: optional {label: frequency_hz} drawn as vertical lines
    (e.g. resonances). Returns the matplotlib Figure; writes it to `path` if given.
    """
    plt = _pyplot()
    f = np.asarray(freq_hz, dtype=float)
    if not isinstance(responses, dict):
        responses = {"response": responses}
    fig, (ax_mag, ax_ph) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), constrained_layout=True)
    for label, h in responses.items():
        h = np.asarray(h, dtype=complex)
        if h.shape != f.shape:
            raise ValueError(f"response '{label}' has shape {h.shape}; freq_hz has {f.shape}")
        phase = np.angle(h)
        phase = np.degrees(np.unwrap(phase) if unwrap else phase)
        ax_mag.semilogx(f, 20 * np.log10(np.abs(h)), label=label)
        ax_ph.semilogx(f, phase, label=label)
    for label, fm in (markers or {}).items():
        for ax in (ax_mag, ax_ph):
            ax.axvline(fm, color="0.4", ls=":", lw=1)
        ax_mag.annotate(f"{label}\n{fm:.4g} Hz", (fm, 1.0), xycoords=("data", "axes fraction"), fontsize=8,
                        ha="left", va="top")
    ax_mag.set_ylabel("gain [dB]")
    ax_ph.set_ylabel("phase [deg]")
    ax_ph.set_xlabel("frequency [Hz]")
    for ax in (ax_mag, ax_ph):
        ax.grid(True, which="both", alpha=0.3)
    if len(responses) > 1:
        ax_mag.legend()
    if title:
        fig.suptitle(title, fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig


def plant_bode(plant, freq_hz=None, *, period_s: float | None = None, path: str | None = None):
    """Bode plot of a plant from motor torque (N*m) to angle (rad): for a two-mass plant, motor and load side,
    with the anti-resonance and resonance marked. period_s: also overlay the zero-order-hold response sampled at
    that period (s). freq_hz defaults to 1 Hz .. 0.45/period_s (or 10 kHz). Returns the Figure."""
    f_hi = 0.45 / period_s if period_s else 1e4
    f = np.logspace(0, np.log10(f_hi), 600) if freq_hz is None else np.asarray(freq_hz, dtype=float)
    responses, markers = {}, {}
    two_mass = hasattr(plant, "resonance_hz")
    outputs = ("motor", "load") if two_mass else ("motor",)
    for out in outputs:
        kw = {"output": out} if two_mass else {}
        responses[f"{out} angle / torque"] = plant.frequency_response(f, **kw)
        if period_s:
            responses[f"{out}, ZOH at {period_s * 1e6:g} us"] = plant.frequency_response(f, period_s=period_s, **kw)
    if two_mass:
        markers = {"anti-resonance": plant.antiresonance_hz, "resonance": plant.resonance_hz}
    name = type(plant).__name__
    return bode(f, responses, markers=markers, title=f"{name}: angle [rad] per torque [N*m]", path=path)


def friction_curve(plant, speed_rad_s=None, *, side: str = "motor", path: str | None = None):
    """Steady friction torque (N*m) against speed (rad/s): the Stribeck curve plus viscous friction, with the
    breakaway level marked. `side` selects the motor or load side of a two-mass plant. Returns the Figure."""
    plt = _pyplot()
    w = np.linspace(-1.0, 1.0, 801) if speed_rad_s is None else np.asarray(speed_rad_s, dtype=float)
    two_mass = hasattr(plant, "resonance_hz")
    t = plant.friction_torque(w, side=side) if two_mass else plant.friction_torque(w)
    fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
    ax.plot(w, t, lw=1.5)
    ax.axhline(0, color="0.5", lw=0.8)
    ax.axvline(0, color="0.5", lw=0.8)
    ax.set_xlabel("speed [rad/s]")
    ax.set_ylabel("friction torque [N*m]")
    ax.grid(True, alpha=0.3)
    ax.set_title(f"{type(plant).__name__} friction ({side} side)" if two_mass else "RigidPlant friction", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig


def filter_response(*filters, freq_hz=None, sample_time_s: float | None = None, labels=None,
                    title: str | None = None, path: str | None = None):
    """Bode plot of one or more biquads (:class:`FloatBiquad` or :class:`AdlinkBiquad`): magnitude in dB and
    phase in degrees over frequency in Hz (log axis).

    freq_hz
        frequencies in Hz; default 2000 points log-spaced from Nyquist/10^4 to just below Nyquist.
    sample_time_s
        sample time in s for filters not bound to one (``sample_time_s == 0``); default: each filter's own.
    labels
        legend entries, one per filter (default: the class name and index).

    Returns the matplotlib Figure; writes it to `path` if given.
    """
    if not filters:
        raise ValueError("filter_response: give at least one filter")
    plt = _pyplot()
    ts_all = [sample_time_s or f.sample_time_s for f in filters]
    if any(not ts for ts in ts_all):
        raise ValueError("filter_response: a filter is not bound to a sample time; pass sample_time_s (s)")
    if freq_hz is None:
        nyq = 0.5 / min(ts_all)
        freq_hz = np.logspace(np.log10(nyq * 1e-4), np.log10(nyq * 0.999), 2000)
    freq_hz = np.asarray(freq_hz, dtype=float)
    if labels is None:
        labels = [f"{type(f).__name__} {i}" for i, f in enumerate(filters)]
    fig, (ax_m, ax_p) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), constrained_layout=True)
    for f, ts, label in zip(filters, ts_all, labels):
        h = np.asarray(f.frequency_response(freq_hz, ts))
        ax_m.semilogx(freq_hz, 20 * np.log10(np.maximum(np.abs(h), 1e-12)), label=label, lw=1.2)
        ax_p.semilogx(freq_hz, np.degrees(np.angle(h)), label=label, lw=1.2)
    ax_m.set_ylabel("magnitude [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    for ax in (ax_m, ax_p):
        ax.grid(True, which="both", alpha=0.3)
    ax_m.legend(loc="best", fontsize=8)
    fig.suptitle(title or "servobench: biquad frequency response", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig
