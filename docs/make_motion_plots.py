"""Generates the figures of docs/motion.md into docs/img/. Run: PYTHONPATH=python python docs/make_motion_plots.py"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import servobench as sb  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")
IMG.mkdir(exist_ok=True)


def panel(trajs, labels, title, path, period_s=200e-6):
    fig, ax = plt.subplots(4, 1, sharex=True, figsize=(7, 6.5))
    for traj, lab in zip(trajs, labels):
        t = np.arange(len(traj)) * period_s * 1e3
        for a, y in zip(ax, [traj.pos, traj.vel, traj.acc, traj.jerk]):
            a.plot(t, y, label=lab)
    for a, lab in zip(ax, ["pos [pulse]", "vel [pulse/tick]", "acc [pulse/tick²]", "jerk [pulse/tick³]"]):
        a.set_ylabel(lab, fontsize=8)
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    ax[0].set_title(title)
    ax[-1].set_xlabel("time [ms]")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    full = sb.move_trajectory(sb.GtSCurve(pos=3000, vel=4, macc=0.04, jerk=0.002), whole_pulses=False)
    short = sb.move_trajectory(sb.GtSCurve(pos=300, vel=4, macc=0.04, jerk=0.002), whole_pulses=False)
    tcur = sb.move_trajectory(sb.GtTCurve(pos=3000, vel=4, acc=0.04), whole_pulses=False)
    panel([full, short, tcur], ["S-curve 3000 pulse (7 phases)", "S-curve 300 pulse (deformed)",
                                "T-curve 3000 pulse"], "GT S-curve and T-curve", IMG / "motion_s_t_curves.png")
    g = sb.ProfileGenerator()
    g.command(sb.GtSCurve(pos=4000, vel=3, macc=0.03, jerk=0.001))
    a = g.run(400)
    g.command(sb.GtSCurve(pos=500, vel=3, macc=0.03, jerk=0.001))
    b = g.run_until_done()
    tr = sb.Trajectory(*(np.concatenate([p[k] for p in (a, b)]) for k in ("pos_exact", "vel", "acc", "jerk")))
    panel([tr], ["target 4000 -> 500 at tick 400"], "S-curve: new target behind the braking point reverses",
          IMG / "motion_s_curve_retarget.png")
    pvt_figures()
    print("wrote", sorted(p.name for p in IMG.glob("motion_*.png")))


def pvt_figures():
    """PVT description modes (GUC Tabs 4-17, 4-19, 4-21, 4-22) and the FollowEx cam of iDEABOX Ex 4-1."""
    t4, p4 = [0, 1000, 2000, 3000], [0, 5000, 15000, 20000]
    kw = dict(pos=[0, 20000], vel=[0, 0], percent=[60, 0], vel_max=[10, 10], acc=[0.01, 0.01], dec=[0.01, 0.01])
    curves = [
        ("PVT, v = 0/10/10/0 (Tab 4-17 set 1)", sb.pvt_table(time_ms=t4, pos=p4, vel=[0, 10, 10, 0])),
        ("PVT, v = 0/5/5/0 (Tab 4-18, improper)", sb.pvt_table(time_ms=t4, pos=p4, vel=[0, 5, 5, 0])),
        ("Complete (Tab 4-19): 0/9/9/0", sb.pvt_table_complete(time_ms=t4, pos=p4)),
        ("Percent 60/0/100/0 (Tab 4-21)", sb.pvt_table_percent(time_ms=t4, pos=p4, percent=[60, 0, 100, 0])),
        ("Continuous, peak acc (Tab 4-22)", sb.pvt_table_continuous(**kw)),
        ("Continuous, average acc", sb.pvt_table_continuous(**kw, acc_meaning="average")),
    ]
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    for label, c in curves:
        t = np.linspace(c.time_ms[0], c.time_ms[-1], 3001)
        s = c.evaluate(t)
        for a, k in zip(ax, ("pos", "vel", "acc")):
            a.plot(t, s[k], label=label)
    for a, lab in zip(ax, ["pos [pulse]", "vel [pulse/ms]", "acc [pulse/ms²]"]):
        a.set_ylabel(lab, fontsize=8)
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=7)
    ax[0].set_title("PVT description modes (GUC-ECAT §4.2, 4 points 0/5000/15000/20000)")
    ax[-1].set_xlabel("table time [ms]")
    fig.tight_layout()
    fig.savefig(IMG / "motion_pvt_modes.png", dpi=90)
    plt.close(fig)

    g = sb.ProfileGenerator(period_s=1e-3)
    g.command(sb.GeJog(vel=50, acc=1))
    master = np.concatenate([[0.0], g.run(4000)["pos_exact"]])
    f = sb.FollowEx(sb.FollowExSetup(max_segment=5000, memory=2, event=2, master_dir=1, event_pos=50000, loop=0))
    m, s = 20000, 10000
    f.data_percent(m, s, sb.FollowSegment.NORMAL, 60)
    for _ in range(1000):
        m, s = m + 20, s + 20
        f.data_percent(m, s, sb.FollowSegment.EVEN)
    f.data_percent(m + 20000, s + 10000, sb.FollowSegment.STOP, 60)
    f.start(master[0])
    out = f.follow(master[1:])
    t = np.arange(1, len(master))
    fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 6))
    ax[0].plot(t, master[1:], label="master (jog 50 pulse/ms)")
    ax[0].plot(t, out["pos_exact"], label="slave")
    ax[0].axhline(50000, color="grey", lw=0.5)
    ax[1].plot(t, out["ratio"])
    ax[2].plot(t, out["vel"])
    for a, lab in zip(ax, ["pos [pulse]", "velocity ratio", "slave vel [pulse/ms]"]):
        a.set_ylabel(lab, fontsize=8)
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    ax[0].set_title("FollowEx Ex 4-1: NORMAL / 1000 x EVEN / STOP, start on PASS 50000, loops")
    ax[-1].set_xlabel("time [ms]")
    fig.tight_layout()
    fig.savefig(IMG / "motion_follow_ex.png", dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
