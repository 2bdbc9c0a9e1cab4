"""Draws the figures of docs/identify.md into docs/img/. Run: python docs/make_identify_figures.py"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import servobench as sb  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")
TRUE = dict(jm_kgm2=1e-4, jl_kgm2=2e-4, k_nm_per_rad=300.0, c_nms_per_rad=0.01, motor_viscous_nms=2e-4,
            motor_coulomb_nm=0.03)


def main():
    IMG.mkdir(exist_ok=True)
    axis = sb.Axis(law=sb.GtServoLaw(kp=20, kd=400), plant=sb.TwoMassPlant(load_viscous_nms=0.0, **TRUE),
                   drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_bw_hz=1500.0),
                   encoder=sb.Encoder(counts_per_rev=10000), servo_period_s=200e-6)
    log = sb.run_experiment(axis, amplitude_v=0.3, seed=0)
    sp = sb.identify.log_spectrum(log)
    h1 = sb.identify.log_spectrum(log, instrument=log.torque_nm)
    rg = sb.identify.resonance_guess(log)
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
    ax[0].loglog(h1.freq_hz, h1.apparent_inertia_kgm2, lw=0.7, color="0.6", label="H1 = S_uv/S_uu (biased by the loop)")
    ax[0].loglog(sp.freq_hz, sp.apparent_inertia_kgm2, lw=0.9, label="S_rv/S_ru, PRBS as instrument")
    ax[0].axhline(rg.total_inertia_kgm2, color="k", lw=0.5)
    for f, name, ha in ((rg.anti_resonance_hz, "anti-resonance", "right"), (rg.resonance_hz, "resonance", "left")):
        ax[0].axvline(f, color="r", lw=0.6)
        ax[0].text(f * (0.97 if ha == "right" else 1.03), 1.2e-3, f"{name}\n{f:.0f} Hz", fontsize=8, color="r",
                   ha=ha)
    ax[0].set_ylabel("apparent inertia [kg m^2]")
    ax[0].set_ylim(3e-6, 5e-3)
    ax[0].legend(fontsize=8, loc="lower left")
    ax[1].semilogx(sp.freq_hz, sp.coherence, lw=0.8)
    ax[1].set_ylabel("coherence")
    ax[1].set_xlabel("frequency [Hz]")
    ax[0].set_xlim(10, 2000)
    fig.suptitle("two-mass log (jm 1e-4, jl 2e-4, k 300): 1/(|V/T| w) from a 5 s closed-loop experiment")
    fig.tight_layout()
    fig.savefig(IMG / "identify_spectrum.png", dpi=110)
    print("wrote", IMG / "identify_spectrum.png")


if __name__ == "__main__":
    main()
