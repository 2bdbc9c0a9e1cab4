"""Generates the homing / capture / breakpoint / jog figures of docs/motion.md into docs/img/.
Run: PYTHONPATH=python python docs/make_homing_plots.py"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import servobench as sb  # noqa: E402
from servobench.homing import pulse_to_rad  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")
IMG.mkdir(exist_ok=True)
CPR, ORG, EL, INDEX = 10000, (10000, 14000), 50000, 2500


def make_axis(start_pulse=0.0):
    base = sb.demo_axis()
    axis = sb.Axis(law=base.law, drive=base.drive, plant=base.plant, servo_period_s=200e-6,
                   encoder=sb.Encoder(counts_per_rev=CPR, index_angle_rad=pulse_to_rad(INDEX, CPR)),
                   switches=sb.Switches(home_min_rad=pulse_to_rad(ORG[0]), home_max_rad=pulse_to_rad(ORG[1]),
                                        neg_limit_rad=pulse_to_rad(-EL), pos_limit_rad=pulse_to_rad(EL)))
    axis.reset(pulse_to_rad(start_pulse))
    return axis


def homing_modes(path):
    cases = [("mode 0 (ORG), DIR 1: T37, manual example", sb.AdlinkHome(), 0.0),
             ("mode 0 (ORG) + EZA, DIR 0", sb.AdlinkHome(dir=0, eza=True), -30000.0),
             ("mode 1 (EL), DIR 0", sb.AdlinkHome(mode=1, dir=0), 0.0),
             ("mode 2 (single EZ), DIR 1", sb.AdlinkHome(mode=2, dir=1), 0.0)]
    fig, axes = plt.subplots(len(cases), 1, figsize=(7.5, 9))
    for ax, (title, params, start) in zip(axes, cases):
        res = sb.home(make_axis(start), params, max_ticks=10**6)
        run = res.run
        t = run.time_s * 1e3
        ax.plot(t, run.fb_pos, lw=1.2, label="actual (raw encoder count)")
        ax.axhspan(*ORG, color="tab:orange", alpha=0.2, label="ORG (home switch) on")
        for lim in (EL, -EL):
            if run.fb_pos.min() - 2000 < lim < run.fb_pos.max() + 2000:
                ax.axhline(lim, color="tab:red", ls=":", label="limit switch edge")
        k = np.flatnonzero(run.index)
        ax.plot(t[k], run.fb_pos[k], "k|", ms=10, label="index mark (EZ)")
        ax.axhline(res.reference_pulse, color="tab:green", ls="--", lw=1,
                   label=f"reference {res.reference_pulse:.0f} (captured)")
        ax.set_title(f"{title}: done={res.done}, ends at position {run.pos[-1]:.0f}", fontsize=9)
        ax.set_ylabel("pulse", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, loc="best")
    axes[-1].set_xlabel("time [ms]")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def breakpoint_and_jog(path):
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 5.5))
    loop = sb.MotionLoop(make_axis())
    loop.command(sb.GtTCurve(pos=50000, vel=1, acc=0.1))
    loop.auto_update = True
    loop.set_brk_cn(20000)
    loop.pos_brk()
    loop.stage(sb.GtTCurve(pos=50000, vel=4, acc=0.1))
    run = loop.run_until_done(100000)
    t = run.time_s * 1e3
    ax = axes[0]
    ax.plot(t, run.actual_pos, label="actual position [pulse]")
    ax.axhline(20000, color="tab:red", ls=":", label="BrkCn 20000")
    k = int(np.argmax(run.breakpoint))
    ax.axvline(t[k], color="tab:green", ls="--", label=f"breakpoint fires (tick {k}), Vel 1 -> 4")
    ax.set_title(f"GT TV18: PosBrk + auto-update, {len(run)} ST (ideal tracking 27 536)", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax = axes[1]
    loop = sb.MotionLoop(make_axis())
    loop.jog(sb.AdlinkJog(mode=1, dir=1, offset=1000, delay_us=20000))
    loop.jog_on = True
    a = loop.run(1700)
    loop.jog_on = False
    b = loop.run_until_done()
    pos = np.concatenate([a.pos, b.pos])
    on = np.concatenate([np.ones(len(a)), np.zeros(len(b))])
    t = np.arange(len(pos)) * 0.2
    ax.plot(t, pos, label="command position [pulse]")
    for m in range(0, int(pos[-1]) + 1000, 1000):
        ax.axhline(m, color="gray", lw=0.5, alpha=0.5)
    ax.plot(t, on * 1000, color="tab:orange", label="JOG-ON x 1000")
    ax.set_title(f"ADLINK T36: jog step, offset 1000 -> total {pos[-1]:.0f} = ceil(n) x offset", fontsize=9)
    ax.set_xlabel("time [ms]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    homing_modes(IMG / "homing_adlink_modes.png")
    breakpoint_and_jog(IMG / "homing_breakpoint_jog.png")
    print("wrote", IMG / "homing_adlink_modes.png", IMG / "homing_breakpoint_jog.png")
