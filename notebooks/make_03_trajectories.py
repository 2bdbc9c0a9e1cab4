"""Writes notebooks/03_trajectories.ipynb (no outputs stored). Run: python notebooks/make_03_trajectories.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 03 Trajectories: the manuals' single-axis motion generators\n\n"
        "T-curve, S-curve, jog, smooth and abrupt stops and on-the-fly changes, with each manual's units:\n"
        "GT per sample time (pulse/ST), GE/GUC/iDEABOX pulse/ms, ADLINK pulse/s with an S-factor.\n"
        "Every plot shows position, velocity, acceleration and jerk per tick. At the end: PVT tables in each\n"
        "description mode (PVT, complete, percent, continuous) and a FollowEx electronic cam."),
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
    nbf.v4.new_markdown_cell(
        "## PVT tables (GUC-ECAT §4.2, iDEABOX §4.4)\n"
        "Points in the manuals' units (ms, pulse, pulse/ms). Each description mode turns them into cubic pieces;\n"
        "`pvt_trajectory` runs the table on a PVT axis at the tick (1 ms here), so velocities are pulse/tick =\n"
        "pulse/ms. **PVT mode** (GUC Tab 4-23, L1506-1604): time, position and velocity per point."),
    nbf.v4.new_code_cell(
        "pvt = sb.pvt_table(time_ms=[0, 1200, 2000, 3000, 3800, 5000],\n"
        "                   pos=[0, 9750, 24483, 44483, 59216, 68966], vel=[1, 15.25, 20, 20, 15.25, 1])\n"
        "print(pvt)\n"
        "tr = sb.pvt_trajectory(pvt, period_s=1e-3, whole_pulses=False)\n"
        "print('p(600) =', tr.pos[600], ' v(600) =', tr.vel[600], '(manual-derived 2737.5, 8.125)')\n"
        "show(tr, 'PVT mode: GUC Tab 4-23', 1e-3)"),
    nbf.v4.new_markdown_cell(
        "**Complete mode** (GUC Tab 4-20): only times and positions; the card chooses the interior velocities so\n"
        "velocity and acceleration are continuous (a clamped spline). Here 50000·sin²(πt/2000) from 5 points,\n"
        "looped twice: the node velocities are 75, 0, -75 (the true slope is 78.5)."),
    nbf.v4.new_code_cell(
        "t = np.arange(0, 2001, 500.0)\n"
        "comp = sb.pvt_table_complete(time_ms=t, pos=np.round(50000 * np.sin(np.pi * t / 2000) ** 2))\n"
        "print('node velocities', comp.vel)\n"
        "show(sb.pvt_trajectory(comp, period_s=1e-3, loop=2, whole_pulses=False), 'Complete mode, 2 passes', 1e-3)"),
    nbf.v4.new_markdown_cell(
        "**Percent mode** (GUC Tab 4-21): the node velocities come from the linear-average recursion; the percent\n"
        "of each point shapes the acceleration of the segment after it (0 = constant, 100 = triangle) without\n"
        "moving any point. Two tables, two percents: the positions at the points agree."),
    nbf.v4.new_code_cell(
        "t4, p4 = [0, 1000, 2000, 3000], [0, 5000, 15000, 20000]\n"
        "print('velocities', sb.pvt_percent_calculate(time_ms=t4, pos=p4, percent=[60, 0, 100, 0]))\n"
        "a = sb.pvt_trajectory(sb.pvt_table_percent(time_ms=t4, pos=p4, percent=[60, 0, 100, 0]), whole_pulses=False)\n"
        "b = sb.pvt_trajectory(sb.pvt_table_percent(time_ms=t4, pos=p4, percent=[0, 0, 0, 0]), whole_pulses=False)\n"
        "print('at the points:', a.pos[t4], b.pos[t4])\n"
        "show(a, 'Percent mode 60/0/100/0', 1e-3)\n"
        "show(b, 'Percent mode 0/0/0/0 (constant acceleration per segment)', 1e-3)"),
    nbf.v4.new_markdown_cell(
        "**Continuous mode** (GUC example L1946-2098): no times; each segment accelerates, cruises at <= vel_max\n"
        "and decelerates. `pvt_continuous_calculate` gives the times; delaying the shorter axis by the difference\n"
        "makes both end together. `acc` is read as the peak acceleration (decision M24; 'average' is the option)."),
    nbf.v4.new_code_cell(
        "def cont(d, **kw):\n"
        "    return dict(pos=[0, d], vel=[0, 0], percent=[100, 100], vel_max=[10, 10], acc=[0.01, 0.01],\n"
        "                dec=[0.01, 0.01], **kw)\n"
        "tx = sb.pvt_continuous_calculate(**cont(30000))[1]\n"
        "ty = sb.pvt_continuous_calculate(**cont(20000))[1]\n"
        "print('tx, ty =', tx, ty, 'ms; Y starts', tx - ty, 'ms later')\n"
        "x = sb.pvt_trajectory(sb.pvt_table_continuous(**cont(30000)), whole_pulses=False)\n"
        "y = sb.pvt_trajectory(sb.pvt_table_continuous(**cont(20000), time_begin_ms=tx - ty), whole_pulses=False)\n"
        "print('samples:', len(x), len(y))\n"
        "show(x, 'Continuous mode, X 30000 pulse', 1e-3)\n"
        "show(y, 'Continuous mode, Y 20000 pulse, delayed so both end together', 1e-3)"),
    nbf.v4.new_markdown_cell(
        "## FollowEx electronic cam (iDEABOX Ex 4-1, L554-742)\n"
        "The master jogs at 50 pulse/ms. The slave starts when the master passes 50000 and follows a cam written\n"
        "as cumulative positions (decision M30): NORMAL 60 % (ratio 0 -> 1), 1000 EVEN segments (ratio 1), STOP\n"
        "60 % (ratio 1 -> 0), looping forever. The master array stands for the signal the card feeds (here the\n"
        "master's planned profile, `master_type=2`)."),
    nbf.v4.new_code_cell(
        "g = sb.ProfileGenerator(period_s=1e-3)\n"
        "g.command(sb.GeJog(vel=50, acc=1))\n"
        "master = np.concatenate([[0.0], g.run(3500)['pos_exact']])\n"
        "cam = sb.FollowEx(sb.FollowExSetup(memory=2, max_segment=5000, event=2, master_dir=1, event_pos=50000,\n"
        "                                   loop=0))\n"
        "m, s = 20000, 10000\n"
        "cam.data_percent(m, s, sb.FollowSegment.NORMAL, 60)\n"
        "for _ in range(1000):\n"
        "    m, s = m + 20, s + 20\n"
        "    cam.data_percent(m, s, sb.FollowSegment.EVEN)\n"
        "cam.data_percent(m + 20000, s + 10000, sb.FollowSegment.STOP, 60)\n"
        "print(cam.size(0), 'segments,', cam.space(0), 'free')\n"
        "slave = sb.follow_trajectory(cam, master, whole_pulses=False)\n"
        "print(cam, 'completed loops:', cam.loop_count)\n"
        "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(7, 4))\n"
        "ax[0].plot(master, label='master'); ax[0].plot(slave.pos, label='slave'); ax[0].legend()\n"
        "ax[1].plot(slave.vel); ax[1].set_ylabel('slave vel [pulse/ms]'); ax[1].set_xlabel('time [ms]')\n"
        "plt.show()\n"
        "show(slave, 'FollowEx slave', 1e-3)"),
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
