"""Writes notebooks/09_identify.ipynb (no outputs stored). Run: python notebooks/make_09_identify.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 09 Identify a two-mass axis, tune from the model, compare with the relay\n\n"
        "A commissioning session in simulation. The *machine* is a motor coupled to a load through a compliant\n"
        "shaft, with Coulomb friction, whose numbers we pretend not to know. We\n\n"
        "1. run an identification experiment in torque mode (the drive's commissioning mode): a reversing speed sweep\n"
        "   for the friction and a PRBS injection for the inertias and the resonance;\n"
        "2. read the resonance off the log's spectrum, then fit the two-mass model to the log in the time domain\n"
        "   (Ceres; the fit's model is the simulator's own plant code);\n"
        "3. design the velocity-mode loop from the identified model (`model_based_tune`) and, for comparison, tune it\n"
        "   with the ADLINK relay experiment on the machine itself;\n"
        "4. measure both tunings on the machine with the Bode sweep and a move."),
    nbf.v4.new_code_cell(
        "import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n"
        "from servobench import frequency as fr\n\n"
        "# The machine (hidden truth). All viscous friction is on the motor side.\n"
        "TRUE = dict(jm_kgm2=5e-5, jl_kgm2=1e-4, k_nm_per_rad=400.0, c_nms_per_rad=0.01,\n"
        "            motor_viscous_nms=2e-4, motor_coulomb_nm=0.02)\n"
        "machine = sb.TwoMassPlant(load_viscous_nms=0.0, **TRUE)\n"
        "print(f'true resonance {machine.resonance_hz:.0f} Hz')\n\n"
        "def encoder(seed):  # 10000 counts/rev with 0.5 count rms of noise\n"
        "    return sb.Encoder(counts_per_rev=10000, noise_counts=0.5, seed=seed)\n\n"
        "# Commissioning set-up: torque-mode drive, a soft PD holding the axis, 5 kHz.\n"
        "ident_axis = sb.Axis(law=sb.GtServoLaw(kp=20, kd=400), plant=machine,\n"
        "                     drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500.0),\n"
        "                     encoder=encoder(7), servo_period_s=200e-6)\n\n"
        "# Production set-up: velocity-mode drive, ADLINK law at 10 kHz, a timid hand tuning to start from.\n"
        "def production(plant, law=None):\n"
        "    return sb.Axis(law=law or sb.ApsServoLaw(kp=8000, kd=2000), plant=plant,\n"
        "                   drive=sb.VelocityDrive(speed_per_volt_rad_s=31.4), encoder=encoder(4),\n"
        "                   servo_period_s=100e-6)"),
    nbf.v4.new_markdown_cell(
        "## 1. The experiment\nThe speed amplitude grows from 10 to 60 rad/s over 5 s with 2 Hz reversals, so the\n"
        "friction is seen at every speed; 0.2 V of PRBS rides on the controller output. The log holds the drive's\n"
        "torque command and the encoder reading, as a real drive's monitor would; `log.to_csv` writes it and\n"
        "`IdentificationLog.from_csv` reads a real machine's log the same way."),
    nbf.v4.new_code_cell(
        "log = sb.run_experiment(ident_axis, amplitude_v=0.2, speed_rad_s=(10, 60), seed=1)\n"
        "t = log.time_s\n"
        "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(9, 4))\n"
        "ax[0].plot(t, np.gradient(log.measured, log.sample_period_s), lw=0.4); ax[0].set_ylabel('speed [rad/s]')\n"
        "ax[1].plot(t, log.torque_nm, lw=0.4); ax[1].set_ylabel('torque cmd [N m]'); ax[1].set_xlabel('s')\n"
        "plt.show()"),
    nbf.v4.new_markdown_cell(
        "## 2a. The resonance from the log's spectrum\nThe torque-to-speed response estimated with the injected PRBS\n"
        "as instrument (the closed loop does not bias it). Its *apparent inertia* 1/(|V/T| w) is flat at the total\n"
        "inertia for a rigid body; here it peaks at the anti-resonance and dips at the resonance. A grid fit of\n"
        "the two-mass shape gives the starting inertias and stiffness for the time-domain fit, so that a first\n"
        "guess 30 % off in resonance cannot lead the fit into another minimum."),
    nbf.v4.new_code_cell(
        "sp = sb.identify.log_spectrum(log)\nrg = sb.identify.resonance_guess(log)\nprint(rg)\n"
        "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 5))\n"
        "ax[0].loglog(sp.freq_hz, sp.apparent_inertia_kgm2, lw=0.8)\n"
        "ax[0].axhline(rg.total_inertia_kgm2, color='k', lw=0.5)\n"
        "for f in (rg.anti_resonance_hz, rg.resonance_hz):\n"
        "    ax[0].axvline(f, color='r', lw=0.6)\n"
        "ax[0].set_ylabel('apparent inertia [kg m^2]')\n"
        "ax[1].semilogx(sp.freq_hz, sp.coherence, lw=0.8); ax[1].set_ylabel('coherence'); ax[1].set_xlabel('Hz')\n"
        "ax[0].set_xlim(5, 2000); plt.show()"),
    nbf.v4.new_markdown_cell(
        "## 2b. The time-domain fit\nFrom a rough guess (each value off by 50-100 %). The summary explains the\n"
        "problem Ceres solved: shooting segments over the stretches of one-way motion, their number of states, the\n"
        "continuation over segment lengths, and the fit quality; every estimate has a standard error."),
    nbf.v4.new_code_cell(
        "guess = dict(jm_kgm2=1e-4, jl_kgm2=1e-4, k_nm_per_rad=200.0, c_nms_per_rad=0.005,\n"
        "             motor_viscous_nms=1e-4, motor_coulomb_nm=0.01)\n"
        "fit = sb.fit_time(log, 'two_mass', guess=guess)\nprint(fit)\nprint()\n"
        "print(f\"{'parameter':22s} {'true':>11s} {'estimate':>11s} {'error':>8s} {'std err':>8s}\")\n"
        "for k, v in TRUE.items():\n"
        "    e = fit.parameters[k]\n"
        "    print(f'{k:22s} {v:11.4g} {e.value:11.4g} {100 * (e.value / v - 1):7.2f}% '\n"
        "          f'{100 * e.std_error / abs(e.value):7.2f}%')\n"
        "fig = fit.plot_residuals(); plt.show()"),
    nbf.v4.new_markdown_cell(
        "## 3. Tune from the model, and with the relay\n`model_based_tune` works on an axis whose plant is the\n"
        "identified one (`fit.to_plant()`) and the production drive; the gains go to the machine. The relay\n"
        "experiment runs on the machine itself with the manual's defaults (hysteresis raised to 150 pulse)."),
    nbf.v4.new_code_cell(
        "model = sb.model_based_tune(production(fit.to_plant()))\nprint(model)\n"
        "tuned_model = production(machine)\nmodel.apply(tuned_model)\n\n"
        "tuned_relay = production(machine)\n"
        "relay = sb.relay_autotune(tuned_relay, hysteresis_pulse=150, sampling_time_s=100e-6)\n"
        "print(relay.status, '-', relay.message)\nrelay.apply(tuned_relay)"),
    nbf.v4.new_markdown_cell(
        "## 4. Both tunings measured on the machine\nStepped-sine Bode sweeps of the open loop (markers) against\n"
        "the analytic loop of the *identified* model with the model-based gains (line): where they agree, the\n"
        "model was good enough to tune from."),
    nbf.v4.new_code_cell(
        "sweeps = {}\nfor name, ax_ in (('model-based', tuned_model), ('relay', tuned_relay)):\n"
        "    sweeps[name] = fr.sine_sweep(ax_, start_hz=5, end_hz=2000, amplitude_pulse=20, points=50, update_s=0.3)\n"
        "    m = sweeps[name].margins()\n"
        "    print(f'{name:12s} PM {m.phase_margin_deg:5.1f} deg at {m.pm_freq_hz:6.1f} Hz, '\n"
        "          f'GM {m.gain_margin_db:5.1f} dB, bandwidth {m.bandwidth_hz:6.1f} Hz, Ms {m.ms:.2f}')\n"
        "model_axis = production(fit.to_plant())\nmodel.apply(model_axis)\n"
        "ana = fr.analytic_response(model_axis, np.geomspace(5, 2000, 1000))\n"
        "sb.plot.bode([sweeps['model-based'], sweeps['relay'], ana], which='open_loop',\n"
        "             title='open loop on the machine: model-based, relay; line: identified model')\nplt.show()"),
    nbf.v4.new_code_cell(
        "move = sb.trapezoid_move(distance_pulse=2000, vel_pulse_per_tick=5, acc_pulse_per_tick2=0.05,\n"
        "                         dwell_before=20, dwell_after=3000)\n"
        "for name, ax_ in (('model-based', tuned_model), ('relay', tuned_relay)):\n"
        "    a = production(machine, ax_.law)\n    a.set_filters(ax_.filters)\n    run = a.run(move)\n"
        "    print(name, sb.move_metrics(run, settle_band_pulse=10))\n"
        "    plt.plot(run.time_s * 1e3, run.error, label=name)\n"
        "plt.ylabel('following error [pulse]'); plt.xlabel('ms'); plt.legend(); plt.show()"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                               "language": "python"}})
path = pathlib.Path(__file__).with_name("09_identify.ipynb")
nbf.write(nb, path)
print("wrote", path)
