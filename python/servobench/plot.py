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
