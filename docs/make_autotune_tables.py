"""Prints the trend tables of docs/autotune.md (simulated counterparts of ADLINK L1798-1810).
Run: python docs/make_autotune_tables.py"""

import numpy as np

import servobench as sb
from servobench import frequency as fr


def axis(noise_counts=10.0):
    # Velocity-mode servo on a rigid load with a little Coulomb friction, quantised encoder with 10 counts of noise
    # (the disturbance that makes the cycles differ), 10 kHz servo rate.
    return sb.Axis(law=sb.ApsServoLaw(), plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, coulomb_nm=0.002),
                   drive=sb.VelocityDrive(speed_per_volt_rad_s=31.4),
                   encoder=sb.Encoder(counts_per_rev=10000, noise_counts=noise_counts, seed=1), servo_period_s=100e-6)


def row(**kw):
    a = axis()
    r = sb.relay_autotune(a, **kw)
    r.apply(a)
    m = fr.analytic_response(a, np.geomspace(1, 4900, 4000)).margins()
    return (f"| {100 * r.kp_spread:.2f} | {100 * r.ki_spread:.2f} | {100 * r.kd_spread:.2f} | {m.bandwidth_hz:.1f} | "
            f"{m.phase_margin_deg:.1f} | {r.status} |")


def main():
    print("| Hysteresis (pulse) | KP std % | KI std % | KD std % | Bandwidth Hz | PM deg | status |")
    print("|---|---|---|---|---|---|---|")
    for eps in (150, 250, 350, 450):
        print(f"| {eps} " + row(hysteresis_pulse=eps, sampling_time_s=500e-6))
    print()
    print("| Sampling time (us) | KP std % | KI std % | KD std % | Bandwidth Hz | PM deg | status |")
    print("|---|---|---|---|---|---|---|")
    for st in (500, 300, 200, 100):
        print(f"| {st} " + row(hysteresis_pulse=150, sampling_time_s=st / 1e6))


if __name__ == "__main__":
    main()
