"""Writes notebooks/03_trajectories.ipynb (no outputs stored). Run: python notebooks/make_03_trajectories.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 03 Trajectories: the manuals' single-axis motion generators\n\n"
        "T-curve, S-curve, jog, smooth and abrupt stops and on-the-fly changes, with each manual's units:\n"
        "GT per sample time (pulse/ST), GE/GUC/iDEABOX pulse/ms, ADLINK pulse/s with an S-factor.\n"
        "Every plot shows position, velocity, acceleration and jerk per tick. PVT tables (description modes\n"
        "PVT, complete, percent, continuous) are not implemented yet in this version."),
    nbf.v4.new_code_cell(
        "import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n\n"
        "def show(traj, title, period_s):\n"
        "    t = np.arange(len(traj)) * period_s * 1e3\n"
        "    fig, ax = plt.subplots(4, 1, sharex=True, figsize=(7, 6))\n"
        "    for a, y, lab in zip(ax, [traj.pos, traj.vel, traj.acc, traj.jerk],\n"
        "                         ['pos [pulse]', 'vel [pulse/tick]', 'acc [pulse/tick²]', 'jerk [pulse/tick³]']):\n"
        "        a.plot(t, y); a.set_ylabel(lab, fontsize=8); a.grid(alpha=.3)\n"
        "    ax[-1].set_xlabel('time [ms]'); ax[0].set_title(title)\n"
        "    plt.show()"),
    nbf.v4.new_markdown_cell("## GT T-curve (GT manual L942-951, scaled down): Acc 0.01, Vel 1, Pos 2000"),
    nbf.v4.new_code_cell(
        "tc = sb.move_trajectory(sb.GtTCurve(pos=2000, vel=1, acc=0.01), dwell_after=50)\n"
        "print(tc)\nshow(tc, 'GT T-curve', 200e-6)"),
    nbf.v4.new_markdown_cell(
        "## GT S-curve: all seven phases, and the 'deformed' S without constant acceleration or cruise"),
    nbf.v4.new_code_cell(
        "full = sb.move_trajectory(sb.GtSCurve(pos=3000, vel=4, macc=0.04, jerk=0.002), whole_pulses=False)\n"
        "show(full, 'GT S-curve, 7 phases', 200e-6)\n"
        "deformed = sb.move_trajectory(sb.GtSCurve(pos=300, vel=4, macc=0.04, jerk=0.002), whole_pulses=False)\n"
        "show(deformed, 'GT S-curve, short move: phases 2, 4, 6 missing', 200e-6)"),
    nbf.v4.new_markdown_cell("## GE S-curve in pulse/ms (GE manual L1103-1158): MAcc is never reached"),
    nbf.v4.new_code_cell(
        "ge = sb.move_trajectory(sb.GeSCurve(pos=200000, vel=166.7, macc=4, jerk=0.001), period_s=1e-3)\n"
        "print(ge, 'peak acc', np.abs(ge.acc).max(), 'pulse/ms²')\nshow(ge, 'GE S-curve (1 ms tick)', 1e-3)"),
    nbf.v4.new_markdown_cell(
        "## On-the-fly changes\nT-curve: the velocity rises at a breakpoint (GT L1265-1295); a target behind the\n"
        "braking point decelerates to zero and reverses (GE L1067-1071). S-curve: only the target may change."),
    nbf.v4.new_code_cell(
        "g = sb.ProfileGenerator()\n"
        "g.command(sb.GtTCurve(pos=5000, vel=1, acc=0.05))\n"
        "a = g.run(1500)\n"
        "g.command(sb.GtTCurve(pos=5000, vel=3, acc=0.05))   # new velocity\n"
        "b = g.run(600)\n"
        "g.command(sb.GtTCurve(pos=2500, vel=3, acc=0.05))   # target behind the braking point\n"
        "c = g.run_until_done()\n"
        "parts = [a, b, c]\n"
        "traj = sb.Trajectory(*(np.concatenate([p[k] for p in parts]) for k in ('pos_exact', 'vel', 'acc', 'jerk')))\n"
        "show(traj, 'T-curve: velocity change, then a target behind the braking point', 200e-6)\n"
        "g = sb.ProfileGenerator()\n"
        "g.command(sb.GtSCurve(pos=4000, vel=3, macc=0.03, jerk=0.001))\n"
        "a = g.run(400)\n"
        "try:\n"
        "    g.command(sb.GtSCurve(pos=4000, vel=5, macc=0.03, jerk=0.001))\n"
        "except sb.MotionCommandRefused as e:\n"
        "    print('refused:', e)\n"
        "g.command(sb.GtSCurve(pos=500, vel=3, macc=0.03, jerk=0.001))  # new target only\n"
        "b = g.run_until_done()\n"
        "traj = sb.Trajectory(*(np.concatenate([p[k] for p in (a, b)]) for k in ('pos_exact', 'vel', 'acc', 'jerk')))\n"
        "show(traj, 'S-curve: new target behind the braking point', 200e-6)"),
    nbf.v4.new_markdown_cell("## Jog with a smooth stop, and an abrupt stop"),
    nbf.v4.new_code_cell(
        "g = sb.ProfileGenerator()\n"
        "g.command(sb.GtJog(vel=2, acc=0.02))\n"
        "a = g.run(500)\n"
        "g.command(sb.GtJog(vel=-1, acc=0.01))   # velocity, acceleration and direction may change\n"
        "b = g.run(800)\n"
        "g.smooth_stop()\n"
        "c = g.run(300)\n"
        "traj = sb.Trajectory(*(np.concatenate([p[k] for p in (a, b, c)]) for k in ('pos_exact', 'vel', 'acc', 'jerk')))\n"
        "show(traj, 'GT jog, reversal, smooth stop', 200e-6)\n"
        "g.command(sb.GtJog(vel=2, acc=0.02)); a = g.run(300); g.abrupt_stop(); b = g.run(50)\n"
        "print('after the abrupt stop: vel', g.state[1], 'moving', g.moving)"),
    nbf.v4.new_markdown_cell(
        "## ADLINK PTP with the S-factor and the short-move rule (ADLINK L2176-2244)\n"
        "ACC, DEC and S are kept; a short move lowers the peak velocity and so raises the jerk."),
    nbf.v4.new_code_cell(
        "for sf in (0.0, 0.5, 1.0):\n"
        "    p = sb.AdlinkPtp(pos=20000, vs=0, vm=50000, ve=0, acc=1e6, dec=5e5, sf=sf)\n"
        "    show(sb.move_trajectory(p, period_s=250e-6, whole_pulses=False), f'ADLINK PTP, S = {sf}', 250e-6)\n"
        "short = sb.move_trajectory(sb.AdlinkPtp(pos=800, vm=50000, acc=1e6, dec=5e5, sf=0.5), period_s=250e-6)\n"
        "print('short move peak', short.vel.max() / 250e-6, 'pulse/s (VM = 50000)')"),
    nbf.v4.new_markdown_cell("## A generated move on the simulated axis"),
    nbf.v4.new_code_cell(
        "axis = sb.demo_axis()\n"
        "run = axis.run(sb.move_trajectory(sb.GtSCurve(pos=2000, vel=5, macc=0.05, jerk=0.002), dwell_after=500))\n"
        "print(sb.move_metrics(run))"),
]
nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                               "language": "python"}})
out = pathlib.Path(__file__).with_name("03_trajectories.ipynb")
nbf.write(nb, out)
print("wrote", out)
