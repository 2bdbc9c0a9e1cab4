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


_LABELS = {"plant": "plant Y/U", "open_loop": "open loop Y/E", "closed_loop": "closed loop Y/R",
           "loop_gain": "loop gain L", "sensitivity": "sensitivity E/R"}


def _phase_deg(h, unwrap: bool = True) -> np.ndarray:
    """Phase in degrees, unwrapped and shifted by whole turns so that the first point lies in (-270, 90] (a PID
    loop on an integrating plant then starts near -180 deg, not +180)."""
    ph = np.degrees(np.unwrap(np.angle(h)) if unwrap else np.angle(h))
    if unwrap and ph.size:
        ph = ph - 360.0 * np.ceil((ph[0] - 90.0) / 360.0)
    return ph


def _series(freq_hz, responses, which):
    """Normalises bode()'s inputs to a list of (label, freq, H, measured?)."""
    from .frequency import FrequencyResponse

    def from_fr(fr, prefix):
        out = []
        names = (which,) if isinstance(which, str) else tuple(which)
        for w in names:
            label = _LABELS.get(w, w) if not prefix else f"{prefix}: {_LABELS.get(w, w)}"
            out.append((label, fr.freq_hz, fr.response(w), fr.method != "analytic"))
        return out

    if isinstance(freq_hz, FrequencyResponse):
        return from_fr(freq_hz, "" if responses is None else str(responses)), [freq_hz]
    if isinstance(freq_hz, (list, tuple)) and freq_hz and all(isinstance(x, FrequencyResponse) for x in freq_hz):
        return [s for fr in freq_hz for s in from_fr(fr, fr.method)], list(freq_hz)
    f = np.asarray(freq_hz, dtype=float)
    if responses is None:
        raise ValueError("bode(freq_hz, responses): responses is missing")
    if not isinstance(responses, dict):
        responses = {"response": responses}
    out, frs = [], []
    for label, h in responses.items():
        if isinstance(h, FrequencyResponse):
            w = which if isinstance(which, str) else "open_loop"
            out.append((label, h.freq_hz, h.response(w), h.method != "analytic"))
            frs.append(h)
            continue
        if isinstance(h, tuple) and len(h) == 2:
            fh, hh = np.asarray(h[0], dtype=float), np.asarray(h[1], dtype=complex)
        else:
            fh, hh = f, np.asarray(h, dtype=complex)
        if hh.shape != fh.shape:
            raise ValueError(f"response '{label}' has shape {hh.shape}; its frequencies have {fh.shape}")
        out.append((label, fh, hh, False))
    return out, frs


def bode(freq_hz, responses=None, *, which=("plant", "open_loop", "closed_loop"), title: str | None = None,
         markers: dict | None = None, margins=None, path: str | None = None, unwrap: bool = True):
    """Bode plot: gain (dB) and phase (deg) over log frequency (Hz), several responses overlaid.

    Accepted inputs:

    - ``bode(freq_hz, H)`` or ``bode(freq_hz, {label: H, ...})``: complex arrays on the frequencies `freq_hz` (Hz);
      a dict value may also be a ``(freq_hz, H)`` pair or a :class:`servobench.frequency.FrequencyResponse`.
    - ``bode(response)`` or ``bode([measured, analytic, ...])``: :class:`FrequencyResponse` objects; `which` picks
      the responses to draw ("plant", "open_loop", "closed_loop", and for analytic data "loop_gain",
      "sensitivity"). Measured data are drawn as dots, analytic data as lines, so a measurement sits on its
      model.

    margins
        None (default: annotate when an open loop is drawn from a FrequencyResponse), False, True, or a
        :class:`servobench.frequency.Margins`: the gain and phase crossovers are marked and the margins written.
    markers
        optional {label: frequency_hz} drawn as vertical lines (e.g. resonances).

    Returns the matplotlib Figure; writes it to `path` (PNG, SVG, ...) if given.
    """
    from .frequency import Margins

    plt = _pyplot()
    series, frs = _series(freq_hz, responses, which)
    fig, (ax_mag, ax_ph) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), constrained_layout=True)
    for i, (label, f, h, measured) in enumerate(series):
        phase = _phase_deg(h, unwrap)
        style = dict(ls="none", marker="o", ms=3.5, mfc="none") if measured else dict(lw=1.4)
        ax_mag.semilogx(f, 20 * np.log10(np.abs(h)), label=label, **style)
        ax_ph.semilogx(f, phase, label=label, **style)
    for label, fm in (markers or {}).items():
        for ax in (ax_mag, ax_ph):
            ax.axvline(fm, color="0.4", ls=":", lw=1)
        ax_mag.annotate(f"{label}\n{fm:.4g} Hz", (fm, 1.0), xycoords=("data", "axes fraction"), fontsize=8,
                        ha="left", va="top")
    m = None
    if isinstance(margins, Margins):
        m = margins
    elif margins is None or margins is True:
        draws_open = (isinstance(which, str) and which in ("open_loop", "loop_gain")) or \
            (not isinstance(which, str) and ("open_loop" in which or "loop_gain" in which))
        if frs and draws_open:
            try:
                m = frs[-1].margins()
            except ValueError:
                m = None
        if margins is True and m is None:
            raise ValueError("margins=True needs a FrequencyResponse with an open loop taken without feed-forward")
    if m is not None:
        if np.isfinite(m.pm_freq_hz):
            ax_mag.axvline(m.pm_freq_hz, color="C3", ls="--", lw=0.9)
            ax_ph.axvline(m.pm_freq_hz, color="C3", ls="--", lw=0.9)
            ax_ph.plot([m.pm_freq_hz, m.pm_freq_hz], [-180, -180 + m.phase_margin_deg], color="C3", lw=2.5)
        if np.isfinite(m.gm_freq_hz):
            ax_mag.axvline(m.gm_freq_hz, color="C4", ls="--", lw=0.9)
            ax_ph.axvline(m.gm_freq_hz, color="C4", ls="--", lw=0.9)
            ax_mag.plot([m.gm_freq_hz, m.gm_freq_hz], [0, -m.gain_margin_db], color="C4", lw=2.5)
        ax_ph.axhline(-180, color="0.5", lw=0.8)
        ax_mag.axhline(0, color="0.5", lw=0.8)
        text = (f"PM {m.phase_margin_deg:.1f} deg @ {m.pm_freq_hz:.4g} Hz\n"
                f"GM {m.gain_margin_db:.1f} dB @ {m.gm_freq_hz:.4g} Hz\n"
                f"BW {m.bandwidth_hz:.4g} Hz, Ms {m.ms:.2f}")
        ax_mag.text(0.01, 0.02, text, transform=ax_mag.transAxes, fontsize=8, va="bottom", ha="left",
                    bbox=dict(boxstyle="round", fc="white", alpha=0.8))
    ax_mag.set_ylabel("gain [dB]")
    ax_ph.set_ylabel("phase [deg]")
    ax_ph.set_xlabel("frequency [Hz]")
    for ax in (ax_mag, ax_ph):
        ax.grid(True, which="both", alpha=0.3)
    if len(series) > 1:
        ax_mag.legend(fontsize=8)
    if title:
        fig.suptitle(title, fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig


def nyquist(response, *, which: str = "loop_gain", title: str | None = None, path: str | None = None):
    """Nyquist plot of a loop gain: Re/Im of L over the frequencies given, with the critical point -1 and the
    circle of radius 1/Ms around it (the stability margin in one number).

    response: a :class:`servobench.frequency.FrequencyResponse` (analytic: "loop_gain" by default; measured: use
    ``which="open_loop"``), a list of them (overlaid), or a pair ``(freq_hz, L)``. Returns the Figure.
    """
    from .frequency import FrequencyResponse, margins as _margins

    plt = _pyplot()
    items = response if isinstance(response, (list, tuple)) and response and \
        isinstance(response[0], FrequencyResponse) else [response]
    fig, ax = plt.subplots(figsize=(6, 6), constrained_layout=True)
    ms = None
    for item in items:
        if isinstance(item, FrequencyResponse):
            w = which if (which != "loop_gain" or item.loop_gain is not None) else "open_loop"
            f, l_, label = item.freq_hz, item.response(w), f"{item.method}: {_LABELS.get(w, w)}"
            measured = item.method != "analytic"
        else:
            f, l_ = (np.asarray(item[0], dtype=float), np.asarray(item[1], dtype=complex))
            label, measured = "L", False
        style = dict(ls="none", marker="o", ms=3, mfc="none") if measured else dict(lw=1.4)
        ax.plot(l_.real, l_.imag, label=label, **style)
        ax.plot(l_.real, -l_.imag, color="0.6", lw=0.6, ls=":")
        ms = _margins(f, l_).ms if ms is None else ms
    ax.plot([-1], [0], "r+", ms=12, mew=2)
    if ms and np.isfinite(ms) and ms > 0:
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot(-1 + np.cos(t) / ms, np.sin(t) / ms, "r--", lw=0.8, label=f"1/Ms = {1 / ms:.2f}")
    ax.set_xlim(-3, 1.5)
    ax.set_ylim(-2.5, 2.5)
    ax.set_aspect("equal")
    ax.axhline(0, color="0.5", lw=0.6)
    ax.axvline(0, color="0.5", lw=0.6)
    ax.set_xlabel("Re L")
    ax.set_ylabel("Im L")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title(title or "Nyquist plot of the loop gain", fontsize=10)
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


def scope(data, *, title: str | None = None, path: str | None = None):
    """The card sampler's block (:class:`~servobench.card.ScopeData`): one panel per unit, every channel of that
    unit over time (ms), the trigger instant marked. Returns the Figure; writes it to `path` if given."""
    plt = _pyplot()
    t_ms = np.asarray(data.time_s) * 1e3
    units = list(dict.fromkeys(data.units))
    fig, axes = plt.subplots(len(units), 1, sharex=True, figsize=(8, 2.2 * len(units) + 1), constrained_layout=True,
                             squeeze=False)
    for ax, unit in zip(axes[:, 0], units):
        for k, (name, u) in enumerate(zip(data.names, data.units)):
            if u == unit:
                ax.plot(t_ms, data.values[:, k], lw=1.0, label=name)
        if data.trigger_tick >= 0:
            ax.axvline(data.trigger_tick * data.servo_period_s * 1e3, color="k", lw=0.8, ls=":")
        ax.set_ylabel(f"[{unit}]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    axes[-1, 0].set_xlabel("time [ms]")
    fig.suptitle(title or f"card scope: {len(data)} samples", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig
