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
    print("wrote", sorted(p.name for p in IMG.glob("motion_*.png")))


if __name__ == "__main__":
    main()
