"""Draws the figures of docs/bode.md into docs/img/. Run: python docs/make_bode_figures.py"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

import servobench as sb  # noqa: E402
from servobench import frequency as fr  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")
TS = 100e-6


def axis(filters=None):
    return sb.Axis(law=sb.GtServoLaw(kp=38, ki=30, kd=1660),
                   plant=sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01),
                   drive=sb.TorqueDrive(current_limit_a=float("inf")),
                   encoder=sb.Encoder(counts_per_rev=10000, quantize=False), dac=sb.Dac(quantize=False),
                   servo_period_s=TS, filters=filters)


def main():
    IMG.mkdir(exist_ok=True)
    a = axis()
    meas = fr.sine_sweep(a, start_hz=10, end_hz=4000, amplitude_pulse=2, points=40, update_s=0.2)
    ana = fr.analytic_response(a, np.geomspace(10, 4000, 2000))
    sb.plot.bode([meas, ana], which=("plant", "open_loop", "closed_loop"), margins=False,
                 title="two-mass axis at 10 kHz: stepped sine (dots) on the analytic response (lines)",
                 path=IMG / "bode_measured_vs_analytic.png")
    sb.plot.bode([meas, ana], which="open_loop", title="open loop Y/E with its margins",
                 path=IMG / "bode_margins.png")
    sb.plot.nyquist([ana, meas], path=IMG / "bode_nyquist.png")
    notch = sb.design.notch(a.plant.resonance_hz, TS, q=2.0, prewarp=True)
    an = fr.analytic_response(axis((notch, None)), ana.freq_hz)
    sb.plot.bode(ana.freq_hz, {"without notch": ana.loop_gain, "notch at the resonance": an.loop_gain},
                 markers={"resonance": a.plant.resonance_hz}, title="loop gain: a notch at the resonance",
                 path=IMG / "bode_notch.png")
    print("wrote", sorted(p.name for p in IMG.glob("bode_*.png")))


if __name__ == "__main__":
    main()
