"""Writes notebooks/11_identify_real_machine.ipynb (no outputs stored). Run: python notebooks/make_11_identify_real_machine.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 11 Identify a real machine: the EMPS benchmark\n\n"
        "The EMPS is a real drive of a prismatic joint -- a DC motor, a ball screw and a load -- position-controlled\n"
        "by a PD loop and recorded at 1 kHz (Janot, Gautier & Brunot, *Data Set and Reference Models of EMPS*, 2019\n"
        "Workshop on Nonlinear System Identification Benchmarks). Its estimation record ships with the repository\n"
        "(`tests/data/emps/`), with published IDIM-LS answers. We\n\n"
        "1. read the MATLAB record as it comes (metres, volts, a jittery time vector);\n"
        "2. run the benchmark's own procedure (`idim_ls`) and compare with the published numbers;\n"
        "3. look at what the error bars and the model check say;\n"
        "4. identify on 60 % of the record and validate on the other 40 %, open and closed loop."),
    nbf.v4.new_code_cell(
        "import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n\n"
        "log = sb.examples.emps_log()   # IdentificationLog.from_mat(path, units={'t': 's', 'qm': 'm', 'qg': 'm', "
        "'vir': 'V'}, command_gain='gtau')\n"
        "print(f'{len(log)} samples, Ts = {log.sample_period_s * 1e3:.6f} ms (jitter {log.time_jitter_ppm:.0f} ppm), '\n"
        "      f'linear axis: {log.units}, one count = {log.count_m:.3g} m')\n"
        "print('controller and drive gains kept from the file:', {k: log.extra[k] for k in ('kp', 'kv', 'gtau')})\n"
        "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(9, 4))\n"
        "ax[0].plot(log.time_s, log.measured, lw=0.8, label='measured qm')\n"
        "ax[0].plot(log.time_s, log.reference, '--', lw=0.8, label='reference qg'); ax[0].set_ylabel('position, m')\n"
        "ax[0].legend()\nax[1].plot(log.time_s, log.force_n, lw=0.5); ax[1].set_ylabel('force, N')\n"
        "ax[1].set_xlabel('time, s'); plt.show()"),
    nbf.v4.new_markdown_cell(
        "## 1. The benchmark's procedure: IDIM-LS\n"
        "Zero-phase Butterworth on the position at 5 x the loop's 20 Hz, central differences, decimation by 10, least\n"
        "squares. Without `dynamics_hz` the closed loop's natural frequency is estimated from the reference ->\n"
        "position response (its -90 degree crossing)."),
    nbf.v4.new_code_cell(
        "PUBLISHED = {'M': 95.1089, 'Fv': 203.5034, 'Fc': 20.3935, 'offset': -3.1648}\n"
        "PUBLISHED_ASYM = {'M': 95.1540, 'Fv+': 166.7061, 'Fc+': 20.1440, 'Fv-': 240.4236, 'Fc-': 20.6277}\n"
        "ls = sb.idim_ls(log, dynamics_hz=20.0)\nprint(ls)\n"
        "print('vs published, %:', {k: round(100 * v, 4) for k, v in ls.relative_errors(PUBLISHED).items()})\n"
        "auto = sb.idim_ls(log)\n"
        "print(f'dynamics estimated: {auto.dynamics_hz:.2f} Hz ->', "
        "{k: round(100 * v, 3) for k, v in auto.relative_errors(PUBLISHED).items()})\n"
        "asym = sb.idim_ls(log, friction='asymmetric', dynamics_hz=20.0)\nprint(asym)\n"
        "print('vs published, %:', {k: round(100 * v, 4) for k, v in asym.relative_errors(PUBLISHED_ASYM).items()})\n"
        "fig, ax = plt.subplots(figsize=(9, 3.5)); ls.plot(ax=ax); plt.show()"),
    nbf.v4.new_markdown_cell(
        "## 2. Error bars and the model check\n"
        "The benchmark prints textbook standard errors, which assume white residuals. The IDIM residual is coloured\n"
        "(filtered, decimated, fed back by the controller); `idim_ls` reports a prewhitened Newey-West (HAC)\n"
        "estimate and keeps the textbook one for comparison. The residual's autocorrelation shows why. The symmetric\n"
        "model's warning comes from a HAC Wald test of Fv+ = Fv-."),
    nbf.v4.new_code_cell(
        "for k, e in ls.parameters.items():\n"
        "    print(f'{k:7s} HAC {e.std_error:8.4f}   textbook {ls.std_error_iid[k]:8.4f}   ratio '\n"
        "          f'{e.std_error / ls.std_error_iid[k]:.2f}')\n"
        "r = ls.residual - ls.residual.mean()\n"
        "acf = np.correlate(r, r, 'full')[len(r) - 1:][:60] / (r @ r)\n"
        "plt.figure(figsize=(7, 3)); plt.plot(np.arange(60) * ls.decimation, acf, '.-')\n"
        "plt.xlabel('lag, samples (1 ms)'); plt.ylabel('residual autocorrelation'); plt.axhline(0, color='k', lw=0.5)\n"
        "plt.show()\nprint(ls.warnings)"),
    nbf.v4.new_markdown_cell(
        "## 3. The one-call path and the output-error cross-check\n"
        "`identify_rigid` runs IDIM-LS (both friction models), IDIM-IV from the reference, and the output-error fit\n"
        "(`fit_time`: started from the IDIM answer, segments from the data, three starts) and says which model to use\n"
        "and where the estimators disagree."),
    nbf.v4.new_code_cell(
        "res = sb.identify_rigid(log)\nprint(res.output_error)\nprint()\nprint(res.model)\n"
        "for n in res.notes:\n    print('note:', n)"),
    nbf.v4.new_markdown_cell(
        "## 4. Validation on a 60/40 split\n"
        "Identify on the first 60 %, simulate the last 40 % open loop from the measured force (starting from the\n"
        "measured position and speed) and closed loop from the reference with the record's controller. Published\n"
        "parameters, fitted on the whole record, for comparison."),
    nbf.v4.new_code_cell(
        "est, val = log.split(0.6)\n"
        "models = {'ours, asymmetric': sb.RigidModel.from_result(sb.idim_ls(est, friction='asymmetric')),\n"
        "          'ours, symmetric': sb.RigidModel.from_result(sb.idim_ls(est)),\n"
        "          'published, symmetric': sb.RigidModel(95.1089, 203.5034, 20.3935, offset=-3.1648),\n"
        "          'published, asymmetric': sb.RigidModel(95.1540, 166.7061, 20.1440, 240.4236, 20.6277)}\n"
        "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(9, 5))\n"
        "for name, m in models.items():\n"
        "    v = sb.validate(m, val)\n"
        "    print(f'{name:22s} open loop RMS {v.rms * 1e3:.2f} mm (R^2 {v.r2:.5f}), '\n"
        "          f'closed loop RMS {v.closed_loop[\"rms\"] * 1e6:.2f} um')\n"
        "    ax[1].plot(v.series['time_s'], (v.series['measured'] - v.series['open_loop']) * 1e3, lw=0.8, label=name)\n"
        "ax[0].plot(val.time_s, val.measured, lw=0.8); ax[0].set_ylabel('position, m')\n"
        "ax[1].set_ylabel('open loop: measured - simulated, mm'); ax[1].set_xlabel('time, s'); ax[1].legend(fontsize=8)\n"
        "plt.show()"),
    nbf.v4.new_markdown_cell(
        "The open-loop position of an integrating axis is the double integral of its force error, so tenths of a\n"
        "newton of friction decide it; on this split the identified models do not beat the published ones, which\n"
        "saw the validation part. In closed loop the controller hides those differences (microns)."),
    nbf.v4.new_markdown_cell(
        "## 5. Why: the machine drifts\n"
        "The record repeats one trajectory four times. The mean force on each constant-speed plateau, cycle by\n"
        "cycle, shows the friction balance moving: the negative direction needs more force as the record goes on.\n"
        "A model of the first 60 % cannot know the last 40 %'s balance; the same estimator fitted on the last 40 %\n"
        "simulates it to about a millimetre."),
    nbf.v4.new_code_cell(
        "from scipy.signal import savgol_filter\n"
        "v = savgol_filter(log.measured, 51, 2, deriv=1, delta=log.sample_period_s)\n"
        "a = savgol_filter(log.measured, 51, 2, deriv=2, delta=log.sample_period_s)\n"
        "flat = np.abs(a) < 0.01                              # m/s^2: a speed plateau\n"
        "edges = np.flatnonzero(np.diff(np.r_[0, flat.astype(int), 0]))\n"
        "plateaus = {}\n"
        "for s0, s1 in zip(edges[::2], edges[1::2]):\n"
        "    if s1 - s0 > 250:                                  # >= 0.25 s, 50 samples trimmed at each end\n"
        "        sl = slice(s0 + 50, s1 - 50)\n"
        "        plateaus.setdefault(round(float(v[sl].mean()), 3), []).append(round(float(log.force_n[sl].mean()), 2))\n"
        "for speed in sorted(plateaus):\n"
        "    print(f'{speed:+.3f} m/s: force per pass, N: {plateaus[speed]}')\n"
        "own = sb.validate(sb.RigidModel.from_result(sb.idim_ls(val, friction='asymmetric', dynamics_hz=20.0)), val)\n"
        "print(f'IDIM-LS fitted on the last 40 % itself: open loop RMS {own.rms * 1e3:.2f} mm')"),
    nbf.v4.new_markdown_cell(
        "## 6. The benchmark's own validation\n"
        "The EMPS description validates an estimate by cross-test (its eq. 11: the force of data the fit did not use,\n"
        "reconstructed through the same filtering, `IdimResult.cross_test`) and by the closed-loop simulation -- never\n"
        "open loop. On those measures the fit on the first 60 % is within about 1 % of the published asymmetric set\n"
        "and better than the published symmetric one (`docs/identify-emps.md`, decisions J49-J53)."),
    nbf.v4.new_code_cell(
        "import dataclasses\n"
        "def published(result, values):\n"
        "    return dataclasses.replace(result, parameters={k: dataclasses.replace(e, value=values[k])\n"
        "                                                   for k, e in result.parameters.items()})\n"
        "a = sb.idim_ls(est, friction='asymmetric', dynamics_hz=20.0)\n"
        "s = sb.idim_ls(est, dynamics_hz=20.0)\n"
        "PUBLISHED = {'M': 95.1089, 'Fv': 203.5034, 'Fc': 20.3935, 'offset': -3.1648}\n"
        "for name, r in (('ours, asymmetric (60 %)', a), ('published, asymmetric', published(a, PUBLISHED_ASYM)),\n"
        "                ('ours, symmetric (60 %)', s), ('published, symmetric', published(s, PUBLISHED))):\n"
        "    print(f'{name:24s} cross-test force error on the last 40 %: {r.cross_test(val):.3f} %')"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                               "language": "python"}})
path = pathlib.Path(__file__).with_name("11_identify_real_machine.ipynb")
nbf.write(nb, path)
print("wrote", path)
