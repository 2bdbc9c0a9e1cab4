"""Prints the tables of docs/autotune.md: the trend tables (simulated counterparts of ADLINK L1798-1810) and the rules
compared (relay phase-margin design, Ziegler-Nichols, Tyreus-Luyben, model-based), each measured with the Bode sweep.
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


def linear_axis(plant):
    # Noise-free linear velocity-mode axes of the tests: rigid, and a two-mass with its resonance (390 Hz) in band.
    p = sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4) if plant == "rigid" else \
        sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=150, c_nms_per_rad=0.002)
    return sb.Axis(law=sb.ApsServoLaw(), plant=p,
                   drive=sb.VelocityDrive(speed_per_volt_rad_s=31.4, current_limit_a=float("inf"),
                                          torque_limit_nm=1e9),
                   encoder=sb.Encoder(counts_per_rev=10000, quantize=False), dac=sb.Dac(quantize=False),
                   servo_period_s=100e-6)


def rules_table():
    print("| Plant | Rule | Crossover Hz (measured) | PM deg (measured) | GM dB (measured) | Ms | Bandwidth Hz | Notch |")
    print("|---|---|---|---|---|---|---|---|")
    for plant in ("rigid", "two_mass"):
        relay = sb.relay_autotune(linear_axis(plant), hysteresis_pulse=150, sampling_time_s=100e-6)
        rules = [("relay, 60 deg design", relay), ("relay, Ziegler-Nichols", relay.rule("ziegler_nichols")),
                 ("relay, Tyreus-Luyben", relay.rule("tyreus_luyben")),
                 ("model-based", sb.model_based_tune(linear_axis(plant)))]
        for name, r in rules:
            a = linear_axis(plant)
            r.apply(a)
            m = fr.sine_sweep(a, start_hz=5, end_hz=4000, amplitude_pulse=2, points=150, update_s=0.4).margins()
            notch = "-"
            if getattr(r, "notch", None) and r.notch["used"]:
                notch = f"{r.notch['center_hz']:.0f} Hz, q {r.notch['q']:g}"
            print(f"| {plant} | {name} | {m.pm_freq_hz:.1f} | {m.phase_margin_deg:.1f} | {m.gain_margin_db:.1f} | "
                  f"{m.ms:.2f} | {m.bandwidth_hz:.1f} | {notch} |")


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
    print()
    rules_table()


if __name__ == "__main__":
    main()
