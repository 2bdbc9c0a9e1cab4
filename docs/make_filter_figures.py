"""Draws the figures of docs/filters.md into docs/img/ (PNG) and prints the numbers the page quotes.

Run from the repository root:  PYTHONPATH=python python3 docs/make_filter_figures.py
"""

from __future__ import annotations

import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import servobench as sb  # noqa: E402
from servobench import design  # noqa: E402

TS = 100e-6  # the manual's examples (seed 004 L1919, L1948)
OUT = pathlib.Path(__file__).resolve().parent / "img"
MANUAL_LP = sb.AdlinkBiquad(a1=32767, a2=-11896, b0=1794, b1=3588, b2=1794, div=28046, sample_time_s=TS)
MANUAL_NOTCH = sb.AdlinkBiquad(a1=32767, a2=-16398, b0=16415, b1=-32767, b2=16415, div=16433, sample_time_s=TS)


def db(h):
    return 20 * np.log10(np.maximum(np.abs(h), 1e-12))


def sine_panel(ax, filt, f_hz, periods=4):
    n = 60000
    k = np.arange(n)
    x = 1000.0 * np.sin(2 * np.pi * f_hz * TS * k)
    y = filt.filter(x)
    m = int(round(periods / (f_hz * TS)))
    t_ms = k[-m:] * TS * 1e3
    ax.plot(t_ms - t_ms[0], x[-m:], label="input", lw=1.2)
    ax.plot(t_ms - t_ms[0], y[-m:], label="output", lw=1.2, ls="--")
    h = filt.frequency_response(f_hz)
    ax.set_title(f"{f_hz:g} Hz: |H| = {abs(h):.4f} ({db(h):+.2f} dB), phase {math.degrees(np.angle(h)):+.1f} deg",
                 fontsize=9)
    ax.set_xlabel("time [ms] (steady state)")
    ax.set_ylabel("counts")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)


def lowpass_figure():
    fig = plt.figure(figsize=(9, 7), constrained_layout=True)
    gs = fig.add_gridspec(2, 2)
    ax_m = fig.add_subplot(gs[0, :])
    f = np.logspace(0, math.log10(4999), 2000)
    ax_m.semilogx(f, db(design.lowpass(1000, TS).frequency_response(f)), label="float design (zeta 0.707)")
    ax_m.semilogx(f, db(MANUAL_LP.frequency_response(f)), "--", label="manual's integers (L1919)")
    ax_m.axvline(1000, color="k", lw=0.6, ls=":")
    ax_m.set_ylabel("magnitude [dB]")
    ax_m.set_xlabel("frequency [Hz]")
    ax_m.grid(True, which="both", alpha=0.3)
    ax_m.legend(fontsize=8)
    ax_m.set_title("ADLINK low-pass, 1000 Hz cutoff at Ts = 100 us", fontsize=10)
    sine_panel(fig.add_subplot(gs[1, 0]), MANUAL_LP, 30.0, periods=2)
    sine_panel(fig.add_subplot(gs[1, 1]), MANUAL_LP, 1200.0, periods=4)
    fig.savefig(OUT / "filters_lowpass.png", dpi=110)


def notch_figure():
    fig, (ax_m, ax_p) = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5), constrained_layout=True)
    f = np.linspace(80, 120, 4001)
    cases = [(design.notch(100, TS, q=30), "float design q = 30 (unquantised)"),
             (MANUAL_NOTCH, "manual's integers (L1948) = q 30 quantised"),
             (design.notch(100, TS, low_hz=95, high_hz=105).to_adlink(), "edges 95/105 Hz -> q = 10, quantised")]
    for filt, label in cases:
        h = filt.frequency_response(f)
        ax_m.plot(f, db(h), label=label, lw=1.2)
        ax_p.plot(f, np.degrees(np.angle(h)), label=label, lw=1.2)
    f_null = math.acos(32767 / (2 * 16415)) / (2 * math.pi * TS)
    for ax in (ax_m, ax_p):
        ax.axvline(100, color="k", lw=0.6, ls=":")
        ax.axvline(f_null, color="C1", lw=0.6, ls=":")
        ax.grid(True, alpha=0.3)
    ax_m.annotate(f"integer null {f_null:.2f} Hz", (f_null, -60), xytext=(82, -40), fontsize=8,
                  arrowprops=dict(arrowstyle="->", lw=0.6))
    h100 = MANUAL_NOTCH.frequency_response(100.0)
    ax_m.annotate(f"integers at 100 Hz: {db(h100):.2f} dB", (100, db(h100)), xytext=(104, -20), fontsize=8,
                  arrowprops=dict(arrowstyle="->", lw=0.6))
    ax_m.set_ylim(-70, 5)
    ax_m.set_ylabel("magnitude [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    ax_m.legend(fontsize=8, loc="lower right")
    ax_m.set_title("Notch at 100 Hz, Ts = 100 us: 16-bit quantisation moves the null to 98.61 Hz", fontsize=10)
    fig.savefig(OUT / "filters_notch_quantisation.png", dpi=110)


def notch_sines_figure():
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4), constrained_layout=True)
    for ax, f_hz in zip(axes, (50.0, 100.0, 200.0)):
        sine_panel(ax, MANUAL_NOTCH, f_hz, periods=2)
    fig.suptitle("The manual's notch integers (L1948) on 50 / 100 / 200 Hz sines (steady state)", fontsize=10)
    fig.savefig(OUT / "filters_notch_sines.png", dpi=110)


def numbers():
    print("low-pass 1000 Hz ->", design.lowpass(1000, TS).to_adlink())
    print("notch q=30       ->", design.notch(100, TS, q=30).to_adlink())
    print("notch 95..105 Hz ->", design.notch(100, TS, low_hz=95, high_hz=105).to_adlink())
    for name, filt, freqs in [("LP", MANUAL_LP, (0, 30, 1000, 1200)), ("NOTCH", MANUAL_NOTCH, (0, 50, 95, 100, 105, 200))]:
        for f in freqs:
            h = filt.frequency_response(float(f))
            print(f"  {name:5s} {f:6g} Hz |H| = {abs(h):.4f} ({db(h):+.2f} dB) phase {math.degrees(np.angle(h)):+.1f} deg")
    print("  float q=30 notch at 100 Hz:", f"{db(design.notch(100, TS, q=30).frequency_response(100.0)):.1f} dB")
    print("  integer notch null:", math.acos(32767 / (2 * 16415)) / (2 * math.pi * TS), "Hz")
    print("  pole radii: LP", abs(MANUAL_LP.poles()[0]), "notch", abs(MANUAL_NOTCH.poles()[0]))
    # measured (sine + single-bin DFT) vs computed response, the test's method
    worst = 0.0
    for filt, freqs in [(MANUAL_LP, (30.0, 1200.0)), (MANUAL_NOTCH, (50.0, 100.0, 200.0))]:
        for form in (filt, filt.to_float()):
            for f in freqs:
                k = np.arange(60000)
                x = np.sin(2 * np.pi * f * TS * k)
                y = form.filter(x)
                e = np.exp(-2j * np.pi * f * TS * k[40000:])
                hm = np.sum(y[40000:] * e) / np.sum(x[40000:] * e)
                h = form.frequency_response(f)
                worst = max(worst, abs(hm - h) / abs(h))
    print("  worst relative |H_measured - H| over the manual's sine cases:", worst)


if __name__ == "__main__":
    OUT.mkdir(exist_ok=True)
    lowpass_figure()
    notch_figure()
    notch_sines_figure()
    numbers()
