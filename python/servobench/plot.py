"""matplotlib plots of servobench results. Every function accepts ``ax=`` (the axes to draw into; default: a new
figure) and returns a :class:`Plot`: the figure, the axes drawn into and the data drawn (arrays by label), so a
caller can check or re-plot exactly what is shown. A Plot passes attribute access on to its figure
(``p.savefig(...)``, ``p.axes``). Nothing is shown on screen by the functions themselves; pass `path` to write a
PNG/SVG."""

from __future__ import annotations

__all__ = ["Plot", "response", "bode", "nyquist", "plant_bode", "friction_curve", "filter_response", "scope"]

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Plot:
    """What a plot function drew: ``figure`` (matplotlib Figure), ``drawn_axes`` (the Axes drawn into, in order)
    and ``data`` ({label: {name: array}}: the frequencies, gains, phases, points ... exactly as drawn, plus the
    annotations such as ``"margins"``). Other attributes are the figure's (``savefig``, ``axes``, ``suptitle``)."""

    figure: object
    drawn_axes: tuple
    data: dict = field(default_factory=dict)

    def __getattr__(self, name):
        if name in ("figure", "drawn_axes", "data"):
            raise AttributeError(name)
        return getattr(self.figure, name)

    def __repr__(self) -> str:
        return f"Plot({len(self.drawn_axes)} axes, data: {', '.join(map(str, self.data)) or '-'})"


def _axes(ax, n: int, plt, **subplots_kw):
    """(figure, axes tuple) to draw into: the given `ax` (one Axes, or a sequence of n) or a new figure."""
    if ax is None:
        fig, axs = plt.subplots(n, 1, constrained_layout=True, squeeze=False, **subplots_kw)
        return fig, tuple(axs[:, 0])
    axs = (ax,) if n == 1 and not isinstance(ax, (list, tuple, np.ndarray)) else tuple(np.ravel(ax))
    if len(axs) != n:
        raise ValueError(f"ax must be {'an Axes' if n == 1 else f'a sequence of {n} Axes'}; got {len(axs)}")
    return axs[0].figure, axs


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


def response(run, *, metrics=None, title: str | None = None, path: str | None = None, ax=None):
    """Three stacked panels of a run: command and feedback position (pulse), following error (pulse) and the
    DAC output (V), over time (ms). `metrics` (a :class:`MoveMetrics`) is written into the title.
    ax: three Axes to draw into. Returns a :class:`Plot`; writes it to `path` (PNG, SVG, ...) if given."""
    plt = _pyplot()
    t_ms = np.asarray(run.time_s) * 1e3
    fig, (ax_pos, ax_err, ax_v) = _axes(ax, 3, plt, sharex=True, figsize=(8, 7))
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
    return Plot(fig, (ax_pos, ax_err, ax_v), {"time_ms": t_ms, "command": np.asarray(run.cmd_pos),
                                              "feedback": np.asarray(run.fb_pos), "error": np.asarray(run.error),
                                              "volts": np.asarray(run.volts)})


_LABELS = {"plant": "plant Y/U", "open_loop": "open loop Y/E", "closed_loop": "closed loop Y/R",
           "loop_gain": "loop gain L", "sensitivity": "sensitivity E/R"}


def _phase_deg(h, unwrap: bool = True) -> np.ndarray:
    """Phase in degrees, unwrapped and shifted by whole turns so that the first point lies in (-270, 90] (a PID
    loop on an integrating plant then starts near -180 deg, not +180)."""
    ph = np.degrees(np.unwrap(np.angle(h)) if unwrap else np.angle(h))
    if unwrap and ph.size:
        ph = ph - 360.0 * np.ceil((ph[0] - 90.0) / 360.0)
    return ph


def _source(fr) -> str:
    """"measured (stepped sine)" or "model (analytic)": what a FrequencyResponse is, for legends and boxes."""
    return "model (analytic)" if fr.method == "analytic" else f"measured ({fr.method})"


def _series(freq_hz, responses, which, labels=None):
    """Normalises bode()'s inputs to a list of (label, freq, H, measured?, usable mask or None, fr or None)."""
    from .frequency import FrequencyResponse

    names = (which,) if isinstance(which, str) else tuple(which)

    def from_fr(fr, prefix):
        out = []
        for w in names:
            label = _LABELS.get(w, w) if not prefix else f"{prefix}: {_LABELS.get(w, w)}"
            measured = fr.method != "analytic"
            out.append((label, fr.freq_hz, fr.response(w), measured, fr.usable if measured else None, fr))
        return out

    if isinstance(freq_hz, FrequencyResponse):
        prefix = str(responses) if responses is not None else (labels[0] if labels else _source(freq_hz))
        return from_fr(freq_hz, prefix), [freq_hz]
    if isinstance(freq_hz, (list, tuple)) and freq_hz and all(isinstance(x, FrequencyResponse) for x in freq_hz):
        frs = list(freq_hz)
        if labels is not None:
            if len(labels) != len(frs):
                raise ValueError(f"labels has {len(labels)} entries for {len(frs)} responses")
            prefixes = [str(x) for x in labels]
        else:
            prefixes = [_source(fr) for fr in frs]
            for p in set(prefixes):  # the same kind twice: number them (use labels= for names)
                idx = [i for i, q in enumerate(prefixes) if q == p]
                if len(idx) > 1:
                    for k, i in enumerate(idx):
                        prefixes[i] = f"{p} #{k + 1}"
        return [s for fr, p in zip(frs, prefixes) for s in from_fr(fr, p)], frs
    f = np.asarray(freq_hz, dtype=float)
    if responses is None:
        raise ValueError("bode(freq_hz, responses): responses is missing")
    if not isinstance(responses, dict):
        responses = {"response": responses}
    out, frs = [], []
    for label, h in responses.items():
        if isinstance(h, FrequencyResponse):
            w = which if isinstance(which, str) else "open_loop"
            measured = h.method != "analytic"
            out.append((label, h.freq_hz, h.response(w), measured, h.usable if measured else None, h))
            frs.append(h)
            continue
        if isinstance(h, tuple) and len(h) == 2:
            fh, hh = np.asarray(h[0], dtype=float), np.asarray(h[1], dtype=complex)
        else:
            fh, hh = f, np.asarray(h, dtype=complex)
        if hh.shape != fh.shape:
            raise ValueError(f"response '{label}' has shape {hh.shape}; its frequencies have {fh.shape}")
        out.append((label, fh, hh, False, None, None))
    return out, frs


def _margins_text(name: str, m) -> str:
    def hz(x):
        return f"{x:.4g} Hz" if np.isfinite(x) else "-"

    head = f"{name}: {m.verdict}"
    if not m.stable:
        head += " (margins meaningless)" if m.verdict == "UNSTABLE" else " (no verdict from the data)"
    lines = [head, f"PM {m.phase_margin_deg:.1f} deg @ {hz(m.pm_freq_hz)}",
             f"GM {m.gain_margin_db:.1f} dB @ {hz(m.gm_freq_hz)}"]
    if np.isfinite(m.lower_gain_margin_db):
        lines.append(f"lower GM {m.lower_gain_margin_db:.1f} dB @ {hz(m.lower_gm_freq_hz)}")
    lines.append(f"BW {hz(m.bandwidth_hz)}, Ms {m.ms:.2f}")
    return "\n".join(lines)


def bode(freq_hz, responses=None, *, which=("plant", "open_loop", "closed_loop"), title: str | None = None,
         markers: dict | None = None, margins=None, path: str | None = None, unwrap: bool = True, labels=None,
         ax=None):
    """Bode plot: gain (dB) and phase (deg) over log frequency (Hz), several responses overlaid.

    Accepted inputs:

    - ``bode(freq_hz, H)`` or ``bode(freq_hz, {label: H, ...})``: complex arrays on the frequencies `freq_hz` (Hz);
      a dict value may also be a ``(freq_hz, H)`` pair or a :class:`servobench.frequency.FrequencyResponse`.
    - ``bode(response)`` or ``bode([measured, analytic, ...])``: :class:`FrequencyResponse` objects; `which` picks
      the responses to draw ("plant", "open_loop", "closed_loop", and for analytic data "loop_gain",
      "sensitivity"). Legends say "measured (stepped sine)" or "model (analytic)" (`labels`: one name per
      response instead, e.g. ``["before", "after"]``; the same kind twice is numbered). Measured data are drawn
      as dots, filled where the point passed the sweep's checks and hollow where it was flagged (left out of the
      margins); analytic data as lines, so a measurement sits on its model.

    margins
        None (default: annotate when an open loop is drawn from FrequencyResponses: the margins of each measured
        and each model response drawn, named), False, True (the same, and an error if there are none), a
        :class:`servobench.frequency.Margins`, or {name: Margins}. The gain and phase crossovers are marked, the
        lower gain margin too, and the box says which response each figure comes from and whether the loop is
        stable ("UNSTABLE": margins meaningless).
    markers
        optional {label: frequency_hz} drawn as vertical lines (e.g. resonances).
    ax
        two Axes (gain, phase) to draw into; default a new figure.

    Returns a :class:`Plot` (data: {label: {"freq_hz", "gain_db", "phase_deg", "usable"}}, "margins": {name:
    Margins}); writes it to `path` (PNG, SVG, ...) if given.
    """
    from .frequency import Margins

    plt = _pyplot()
    series, frs = _series(freq_hz, responses, which, labels)
    fig, (ax_mag, ax_ph) = _axes(ax, 2, plt, sharex=True, figsize=(8, 6))
    data = {}
    for label, f, h, measured, usable, _fr in series:
        phase = _phase_deg(h, unwrap)
        gain = 20 * np.log10(np.abs(h))
        data[label] = {"freq_hz": np.asarray(f), "gain_db": gain, "phase_deg": phase,
                       "usable": None if usable is None else np.asarray(usable)}
        if measured:
            good = np.ones(len(f), dtype=bool) if usable is None else np.asarray(usable, dtype=bool)
            ln = ax_mag.semilogx(f[good], gain[good], ls="none", marker="o", ms=3.5, label=label)[0]
            ax_ph.semilogx(f[good], phase[good], ls="none", marker="o", ms=3.5, color=ln.get_color(), label=label)
            if (~good).any():
                kw = dict(ls="none", marker="o", ms=3.5, mfc="none", color=ln.get_color(),
                          label=f"{label} (flagged: left out of margins)")
                ax_mag.semilogx(f[~good], gain[~good], **kw)
                ax_ph.semilogx(f[~good], phase[~good], **kw)
        else:
            ax_mag.semilogx(f, gain, label=label, lw=1.4)
            ax_ph.semilogx(f, phase, label=label, lw=1.4)
    for label, fm in (markers or {}).items():
        for a in (ax_mag, ax_ph):
            a.axvline(fm, color="0.4", ls=":", lw=1)
        ax_mag.annotate(f"{label}\n{fm:.4g} Hz", (fm, 1.0), xycoords=("data", "axes fraction"), fontsize=8,
                        ha="left", va="top")
    boxes: dict = {}
    if isinstance(margins, Margins):
        boxes = {margins.source or "margins": margins}
    elif isinstance(margins, dict):
        boxes = dict(margins)
    elif margins is None or margins is True:
        draws_open = (isinstance(which, str) and which in ("open_loop", "loop_gain")) or \
            (not isinstance(which, str) and ("open_loop" in which or "loop_gain" in which))
        if draws_open:
            for label, *_rest, fr in series:
                if fr is None or label.split(":")[0] in boxes:
                    continue
                try:
                    boxes[label.split(":")[0]] = fr.margins()
                except ValueError:
                    continue
        if margins is True and not boxes:
            raise ValueError("margins=True needs a FrequencyResponse with an open loop taken without feed-forward")
    colours = ("C3", "C4", "C5", "C6")
    texts = []
    for k, (name, m) in enumerate(boxes.items()):
        c = colours[k % len(colours)]
        if np.isfinite(m.pm_freq_hz):
            for a in (ax_mag, ax_ph):
                a.axvline(m.pm_freq_hz, color=c, ls="--", lw=0.9)
            ax_ph.plot([m.pm_freq_hz, m.pm_freq_hz], [-180, -180 + m.phase_margin_deg], color=c, lw=2.5)
        if np.isfinite(m.gm_freq_hz):
            for a in (ax_mag, ax_ph):
                a.axvline(m.gm_freq_hz, color=c, ls="-.", lw=0.9)
            ax_mag.plot([m.gm_freq_hz, m.gm_freq_hz], [0, -m.gain_margin_db], color=c, lw=2.5)
        if np.isfinite(m.lower_gain_margin_db) and np.isfinite(m.lower_gm_freq_hz):
            for a in (ax_mag, ax_ph):
                a.axvline(m.lower_gm_freq_hz, color=c, ls=":", lw=0.9)
            ax_mag.plot([m.lower_gm_freq_hz, m.lower_gm_freq_hz], [0, -m.lower_gain_margin_db], color=c, lw=2.5)
        texts.append((_margins_text(name, m), "red" if not m.stable else "black"))
    if boxes:
        ax_ph.axhline(-180, color="0.5", lw=0.8)
        ax_mag.axhline(0, color="0.5", lw=0.8)
        y = 0.02
        for text, colour in texts:
            t = ax_mag.text(0.01, y, text, transform=ax_mag.transAxes, fontsize=7, va="bottom", ha="left",
                            color=colour, bbox=dict(boxstyle="round", fc="white", alpha=0.85))
            y += 0.06 * (text.count("\n") + 1) + 0.02
        if any(not m.stable for m in boxes.values()):
            ax_ph.text(0.5, 0.5, "UNSTABLE" if any(m.verdict == "UNSTABLE" for m in boxes.values())
                       else "stability undecided", transform=ax_ph.transAxes, fontsize=20, color="red", alpha=0.35,
                       ha="center", va="center")
    data["margins"] = boxes
    ax_mag.set_ylabel("gain [dB]")
    ax_ph.set_ylabel("phase [deg]")
    ax_ph.set_xlabel("frequency [Hz]")
    for a in (ax_mag, ax_ph):
        a.grid(True, which="both", alpha=0.3)
    if len(series) > 1 or any(d.get("usable") is not None for d in data.values() if isinstance(d, dict)):
        ax_mag.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return Plot(fig, (ax_mag, ax_ph), data)


def nyquist(response, *, which: str = "loop_gain", title: str | None = None, path: str | None = None, ax=None,
            arrows: int = 6):
    """Nyquist plot of a loop gain: Re/Im of L over the frequencies given (arrows in the direction of rising
    frequency, labelled in Hz), its mirror image (negative frequencies, dotted), the critical point -1 and the
    circle of radius 1/Ms around it (the stability margin in one number). The title carries the stability verdict
    of each response drawn.

    response: a :class:`servobench.frequency.FrequencyResponse` (analytic: "loop_gain" by default; measured: use
    ``which="open_loop"``), a list of them (overlaid), or a pair ``(freq_hz, L)``. ax: the Axes to draw into;
    arrows: frequency arrows per curve. Returns a :class:`Plot` (data: {label: {"freq_hz", "re", "im"}},
    "ms", "verdicts").
    """
    from .frequency import FrequencyResponse, margins as _margins

    plt = _pyplot()
    items = response if isinstance(response, (list, tuple)) and response and \
        isinstance(response[0], FrequencyResponse) else [response]
    fig, (ax,) = _axes(ax, 1, plt, figsize=(6, 6))
    ms, data, verdicts = None, {}, {}
    for item in items:
        if isinstance(item, FrequencyResponse):
            w = which if (which != "loop_gain" or item.loop_gain is not None) else "open_loop"
            f, l_, label = item.freq_hz, item.response(w), f"{_source(item)}: {_LABELS.get(w, w)}"
            measured = item.method != "analytic"
            try:
                m = item.margins()
            except ValueError:
                m = None
        else:
            f, l_ = (np.asarray(item[0], dtype=float), np.asarray(item[1], dtype=complex))
            label, measured = "L", False
            m = _margins(f, l_)
        style = dict(ls="none", marker="o", ms=3) if measured else dict(lw=1.4)
        line = ax.plot(l_.real, l_.imag, label=label, **style)[0]
        ax.plot(l_.real, -l_.imag, color="0.6", lw=0.6, ls=":")
        data[label] = {"freq_hz": np.asarray(f), "re": l_.real, "im": l_.imag}
        # arrows in the direction of rising frequency, at points inside the view
        inside = np.nonzero((l_.real > -3) & (l_.real < 1.5) & (np.abs(l_.imag) < 2.5))[0]
        if inside.size > 2 and arrows > 0:
            for i in inside[np.linspace(0, inside.size - 2, arrows).astype(int)]:
                j = min(i + 1, len(f) - 1)
                ax.annotate("", xy=(l_.real[j], l_.imag[j]), xytext=(l_.real[i], l_.imag[i]),
                            arrowprops=dict(arrowstyle="-|>", color=line.get_color(), lw=1.2, mutation_scale=12))
                ax.annotate(f"{f[i]:.3g} Hz", (l_.real[i], l_.imag[i]), fontsize=6, color=line.get_color(),
                            xytext=(3, 3), textcoords="offset points")
        if m is not None:
            verdicts[label] = m.verdict
            ms = m.ms if ms is None else ms
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
    head = title or "Nyquist plot of the loop gain"
    if verdicts:
        head += "\n" + "; ".join(f"{k.split(':')[0]}: {v}" for k, v in verdicts.items())
    ax.set_title(head, fontsize=9, color="red" if any(v != "stable" for v in verdicts.values()) else "black")
    if path is not None:
        fig.savefig(path, dpi=120)
    data.update(ms=ms, verdicts=verdicts)
    return Plot(fig, (ax,), data)


def plant_bode(plant, freq_hz=None, *, period_s: float | None = None, path: str | None = None, ax=None):
    """Bode plot of a plant from motor torque (N*m) to angle (rad): for a two-mass plant, motor and load side,
    with the anti-resonance and resonance marked. period_s: also overlay the zero-order-hold response sampled at
    that period (s). freq_hz defaults to 1 Hz .. 0.45/period_s (or 10 kHz). ax: two Axes (gain, phase). Returns a
    :class:`Plot` (see :func:`bode`)."""
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
    return bode(f, responses, markers=markers, title=f"{name}: angle [rad] per torque [N*m]", path=path, ax=ax)


def friction_curve(plant, speed_rad_s=None, *, side: str = "motor", path: str | None = None, ax=None):
    """Steady friction torque (N*m) against speed (rad/s): the Stribeck curve plus viscous friction, with the
    breakaway level marked. `side` selects the motor or load side of a two-mass plant. ax: the Axes to draw into.
    Returns a :class:`Plot` (data: "speed_rad_s", "torque_nm")."""
    plt = _pyplot()
    w = np.linspace(-1.0, 1.0, 801) if speed_rad_s is None else np.asarray(speed_rad_s, dtype=float)
    two_mass = hasattr(plant, "resonance_hz")
    t = plant.friction_torque(w, side=side) if two_mass else plant.friction_torque(w)
    fig, (ax,) = _axes(ax, 1, plt, figsize=(7, 4))
    ax.plot(w, t, lw=1.5)
    ax.axhline(0, color="0.5", lw=0.8)
    ax.axvline(0, color="0.5", lw=0.8)
    ax.set_xlabel("speed [rad/s]")
    ax.set_ylabel("friction torque [N*m]")
    ax.grid(True, alpha=0.3)
    ax.set_title(f"{type(plant).__name__} friction ({side} side)" if two_mass else "RigidPlant friction", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return Plot(fig, (ax,), {"speed_rad_s": w, "torque_nm": np.asarray(t)})


def filter_response(*filters, freq_hz=None, sample_time_s: float | None = None, labels=None,
                    title: str | None = None, path: str | None = None, ax=None):
    """Bode plot of one or more biquads (:class:`FloatBiquad` or :class:`AdlinkBiquad`): magnitude in dB and
    phase in degrees over frequency in Hz (log axis).

    freq_hz
        frequencies in Hz; default 2000 points log-spaced from Nyquist/10^4 to just below Nyquist.
    sample_time_s
        sample time in s for filters not bound to one (``sample_time_s == 0``); default: each filter's own.
    labels
        legend entries, one per filter (default: the class name and index).
    ax
        two Axes (magnitude, phase) to draw into; default a new figure.

    Returns a :class:`Plot` (data: {label: {"freq_hz", "gain_db", "phase_deg"}}); writes it to `path` if given.
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
    fig, (ax_m, ax_p) = _axes(ax, 2, plt, sharex=True, figsize=(8, 6))
    data = {}
    for f, ts, label in zip(filters, ts_all, labels):
        h = np.asarray(f.frequency_response(freq_hz, ts))
        g, ph = 20 * np.log10(np.maximum(np.abs(h), 1e-12)), np.degrees(np.angle(h))
        ax_m.semilogx(freq_hz, g, label=label, lw=1.2)
        ax_p.semilogx(freq_hz, ph, label=label, lw=1.2)
        data[label] = {"freq_hz": freq_hz, "gain_db": g, "phase_deg": ph}
    ax_m.set_ylabel("magnitude [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    for ax in (ax_m, ax_p):
        ax.grid(True, which="both", alpha=0.3)
    ax_m.legend(loc="best", fontsize=8)
    fig.suptitle(title or "servobench: biquad frequency response", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return Plot(fig, (ax_m, ax_p), data)


def scope(data, *, title: str | None = None, path: str | None = None, ax=None):
    """The card sampler's block (:class:`~servobench.card.ScopeData`): one panel per unit, every channel of that
    unit over time (ms), the trigger instant marked. ax: one Axes per unit. Returns a :class:`Plot` (data:
    "time_ms" and {channel name: values}); writes it to `path` if given."""
    plt = _pyplot()
    t_ms = np.asarray(data.time_s) * 1e3
    units = list(dict.fromkeys(data.units))
    fig, axs = _axes(ax, len(units), plt, sharex=True, figsize=(8, 2.2 * len(units) + 1))
    drawn = {"time_ms": t_ms}
    for k, name in enumerate(data.names):
        drawn[name] = data.values[:, k]
    for ax, unit in zip(axs, units):
        for k, (name, u) in enumerate(zip(data.names, data.units)):
            if u == unit:
                ax.plot(t_ms, data.values[:, k], lw=1.0, label=name)
        if data.trigger_tick >= 0:
            ax.axvline(data.trigger_tick * data.servo_period_s * 1e3, color="k", lw=0.8, ls=":")
        ax.set_ylabel(f"[{unit}]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    axs[-1].set_xlabel("time [ms]")
    fig.suptitle(title or f"card scope: {len(data)} samples", fontsize=10)
    if path is not None:
        fig.savefig(path, dpi=120)
    return Plot(fig, tuple(axs), drawn)
