"""Draws the figures of docs/concepts.md and docs/getting-started.md into docs/img/.

Run: PYTHONPATH=python python3 docs/make_concept_figures.py  (prints the numbers the pages quote)."""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import servobench as sb  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")


def getting_started_move():
    axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=10000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1,
                             dwell_after=1000)
    run = axis.run(move)
    m = sb.move_metrics(run, settle_band_pulse=5)
    print("getting started move:", m)
    sb.plot.response(run, metrics=m, title="the first axis: a one-revolution move (GT law, 200 us)",
                     path=IMG / "getting_started_move.png")


def tick_timing():
    """One servo tick's order of operations: a 10-pulse command step on an axis with an ideal current loop, so
    that the torque of tick k+1 is exactly kt * A/V * volts[k]."""
    axis = sb.Axis(law=sb.GtServoLaw(kp=20, kd=0, ki=0), plant=sb.RigidPlant(inertia_kgm2=1e-3, viscous_nms=0),
                   drive=sb.TorqueDrive(current_bw_hz=float("inf")), encoder=sb.Encoder(counts_per_rev=10000),
                   servo_period_s=200e-6)
    cmd = np.r_[np.zeros(3), np.full(9, 10.0)]
    run = axis.run(cmd)
    k = np.arange(len(cmd))
    fig, axs = plt.subplots(4, 1, sharex=True, figsize=(8, 6.5))
    axs[0].step(k, run.cmd_pos, where="post", label="cmd_pos (command, pulse)")
    axs[0].plot(k, run.fb_pos, "o", label="fb_pos (encoder read at the tick's start, pulse)")
    axs[0].legend(fontsize=8)
    axs[1].stem(k, run.u, basefmt=" ")
    axs[1].set_ylabel("u, counts")
    axs[1].set_title("law output u[k] = Kp E[k], computed from the encoder read of tick k", fontsize=9)
    axs[2].stem(k, run.volts, basefmt=" ")
    axs[2].set_ylabel("volts, V")
    axs[2].set_title("DAC voltage written at tick k (16-bit, 32767 counts = 10 V)", fontsize=9)
    axs[3].step(k, run.torque_nm, where="post", color="C3")
    axs[3].set_ylabel("torque, N*m")
    axs[3].set_title("drive torque: the voltage of tick k acts over tick k+1 (one-tick computation delay)",
                     fontsize=9)
    axs[3].set_xlabel("servo tick k")
    for a in axs:
        a.axvline(3, color="grey", lw=0.6, ls=":")
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(IMG / "concepts_tick.png", dpi=110)
    plt.close(fig)
    first = int(np.flatnonzero(run.volts)[0])
    print(f"tick timing: step at tick 3, u at tick {first} = {run.u[first]:g} counts, torque from tick "
          f"{int(np.flatnonzero(run.torque_nm)[0])}")


def plants():
    rigid = sb.RigidPlant(inertia_kgm2=1.5e-4, viscous_nms=1e-4, coulomb_nm=0.02, static_nm=0.04,
                          stribeck_speed_rad_s=1.0)
    two = sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=1e-4, k_nm_per_rad=400, c_nms_per_rad=0.01)
    f = np.geomspace(10, 2000, 1500)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.8))
    for plant, name in ((rigid, "rigid, J = 1.5e-4"), (two, "two-mass, motor side")):
        h = plant.frequency_response(f)
        a1.semilogx(f, 20 * np.log10(np.abs(h)), label=name)
    hz = two.frequency_response(f, period_s=200e-6)
    a1.semilogx(f[f < 2500], 20 * np.log10(np.abs(hz[f < 2500])), "--", lw=0.9, label="two-mass, ZOH at 200 us")
    for x, lab, y, ha in ((two.antiresonance_hz, "anti-resonance", -20, "right"),
                          (two.resonance_hz, "resonance", -20, "left")):
        a1.axvline(x, color="grey", lw=0.6, ls=":")
        a1.text(x, y, f" {lab} \n {x:.0f} Hz ", fontsize=7, ha=ha)
    a1.set_xlabel("frequency, Hz")
    a1.set_ylabel("torque -> motor angle, dB rad/(N*m)")
    a1.legend(fontsize=8)
    a1.grid(alpha=0.3, which="both")
    w = np.linspace(-6, 6, 1201)
    a2.plot(w, rigid.friction_torque(w))
    a2.set_xlabel("speed, rad/s")
    a2.set_ylabel("friction torque, N*m")
    a2.set_title("Stribeck friction: Fc 0.02, Fs 0.04 N*m, ws 1 rad/s, viscous 1e-4", fontsize=9)
    a2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(IMG / "concepts_plants.png", dpi=110)
    plt.close(fig)
    print(f"two-mass: anti-resonance {two.antiresonance_hz:.1f} Hz, resonance {two.resonance_hz:.1f} Hz")


def main():
    IMG.mkdir(exist_ok=True)
    getting_started_move()
    tick_timing()
    plants()


if __name__ == "__main__":
    main()
