"""Writes notebooks/06_bode.ipynb (no outputs stored). Run: python notebooks/make_06_bode.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 06 Bode: measure the loop, check it against its model, read the margins, add a notch\n\n"
        "The ADLINK card's Bode tool (manual L1978-2045) injects a sine into the command of the closed loop and\n"
        "reads four signals: R (the command sine), E = R - Y (following error), U (the controller output into the\n"
        "DAC) and Y (the encoder). From one run it gives three responses: **plant Y/U**, **open loop Y/E**,\n"
        "**closed loop Y/R**. servobench runs the same measurement on a simulated axis and computes the same three\n"
        "responses analytically from the same parameter objects; on a linear axis they agree to 0.1 dB and 1 deg,\n"
        "which is the product's proof that the simulator is what it claims."),
    nbf.v4.new_code_cell(
        "import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n"
        "from servobench import frequency as fr\n\n"
        "TS = 100e-6  # 10 kHz servo rate\n"
        "plant = sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01)\n"
        "print(f'two-mass plant: anti-resonance {plant.antiresonance_hz:.1f} Hz, resonance {plant.resonance_hz:.1f} Hz')\n"
        "def make_axis(filters=None):\n"
        "    # a linear configuration: no friction, no saturation, no quantisation, so that the model is exact\n"
        "    return sb.Axis(law=sb.GtServoLaw(kp=38, ki=30, kd=1660), plant=plant,\n"
        "                   drive=sb.TorqueDrive(current_limit_a=float('inf'), current_bw_hz=1500),\n"
        "                   encoder=sb.Encoder(counts_per_rev=10000, quantize=False), dac=sb.Dac(quantize=False),\n"
        "                   servo_period_s=TS, filters=filters)\n"
        "axis = make_axis()"),
    nbf.v4.new_markdown_cell(
        "## The stepped-sine sweep with the card's parameters\n"
        "Start/end frequency, sine amplitude (pulse), data length (points), update time per point (s), deviation\n"
        "limit (pulse). The feed-forward is off during the measurement by default, so that Y/E is the loop gain;\n"
        "the biquads stay in the loop (docs/decisions.md B1-B2). Each point discards its first quarter as settling\n"
        "time: 0.2 s per point gives the 10 Hz point two periods, one of them clean (with the manual's 0.1 s the\n"
        "first point's single period still holds the start-up transient: try it)."),
    nbf.v4.new_code_cell(
        "meas = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=60, update_s=0.2,\n"
        "                     deviation_limit_pulse=50)\n"
        "print(meas, meas.message)\n"
        "print('worst coherence', meas.coherence.min().round(5), ' worst distortion', meas.distortion.max())\n"
        "ana = fr.analytic_response(axis, np.geomspace(10, 4000, 2000))\n"
        "for which in ('plant', 'open_loop', 'closed_loop'):\n"
        "    sb.plot.bode([meas, ana], which=which, title=f'{which}: measured (dots) vs analytic (line)', margins=False)\n"
        "plt.show()"),
    nbf.v4.new_markdown_cell("## How close are they?"),
    nbf.v4.new_code_cell(
        "ana_pts = fr.analytic_response(axis, meas.freq_hz)\n"
        "for which in ('plant', 'open_loop', 'closed_loop'):\n"
        "    q = meas.response(which) / ana_pts.response(which)\n"
        "    print(f'{which:12s} max |gain error| {np.abs(20*np.log10(np.abs(q))).max():.2e} dB, '\n"
        "          f'max |phase error| {np.abs(np.degrees(np.angle(q))).max():.2e} deg')"),
    nbf.v4.new_markdown_cell(
        "## Margins and figures of merit\nRead off the measured open loop and off the model: gain and phase margins,\n"
        "closed-loop bandwidth, peak sensitivity Ms, and the plant's resonance and anti-resonance."),
    nbf.v4.new_code_cell(
        "print('measured:\\n' + str(meas.margins()))\nprint('\\nanalytic:\\n' + str(ana.margins()))\n"
        "for p in ana.resonances():\n    print(p)\n"
        "sb.plot.bode([meas, ana], which='open_loop', title='open loop with margins')\n"
        "sb.plot.nyquist([ana, meas])\nplt.show()"),
    nbf.v4.new_markdown_cell(
        "## A notch at the resonance\nThe resonance peak of the plant crosses 0 dB in the open loop and eats the gain\n"
        "margin. A notch in biquad 0 (ADLINK integer form, designed at the servo rate) removes it; the same sweep\n"
        "shows the effect."),
    nbf.v4.new_code_cell(
        "notch = sb.design.notch(plant.resonance_hz, TS, q=2.0, prewarp=True)\n"
        "axis_n = make_axis(filters=(notch, None))\n"
        "meas_n = fr.sine_sweep(axis_n, start_hz=10, end_hz=4000, amplitude_pulse=2, points=60, update_s=0.2)\n"
        "ana_n = fr.analytic_response(axis_n, np.geomspace(10, 4000, 2000))\n"
        "before, after = ana.margins(), ana_n.margins()\n"
        "print(f'gain margin {before.gain_margin_db:.1f} dB -> {after.gain_margin_db:.1f} dB; '\n"
        "      f'phase margin {before.phase_margin_deg:.1f} -> {after.phase_margin_deg:.1f} deg; '\n"
        "      f'Ms {before.ms:.2f} -> {after.ms:.2f}')\n"
        "sb.plot.bode(ana.freq_hz, {'without notch': ana.loop_gain, 'with notch': ana_n.loop_gain,\n"
        "                           'with notch, measured': meas_n}, which='open_loop',\n"
        "             markers={'resonance': plant.resonance_hz}, title='open loop: the notch at the resonance')\n"
        "plt.show()"),
    nbf.v4.new_markdown_cell(
        "## One run, a thousand points\nA Schroeder multisine in the command gives the whole curve from one run\n"
        "(H1 with R as the reference, coherence from the spread between periods)."),
    nbf.v4.new_code_cell(
        "bb = fr.broadband_response(axis_n, excitation='multisine', start_hz=10, amplitude_pulse=2, lines=1000)\n"
        "print(bb, bb.message, 'coherence >=', bb.coherence.min().round(6))\n"
        "sb.plot.bode([bb, ana_n], which='plant', margins=False, title='plant Y/U: multisine vs analytic')\n"
        "plt.show()"),
    nbf.v4.new_markdown_cell(
        "## The same loop in python-control\n`linear_model` exports the loop blocks as discrete-time python-control\n"
        "systems, `to_frd` exports any measured curve."),
    nbf.v4.new_code_cell(
        "import control\nmodel = fr.linear_model(axis_n)\n"
        "t, y = control.step_response(model['closed_loop'], T=np.arange(0, 0.05, TS))\n"
        "plt.plot(t * 1e3, y); plt.xlabel('time [ms]'); plt.ylabel('Y/R step'); plt.grid(alpha=.3); plt.show()\n"
        "frd = meas_n.to_frd('open_loop')\nprint(type(frd).__name__, len(frd.omega), 'points,', frd.omega[0].round(2), '..', frd.omega[-1].round(1), 'rad/s')"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                               "language": "python"}})
path = pathlib.Path(__file__).with_name("06_bode.ipynb")
nbf.write(nb, path)
print("wrote", path)
