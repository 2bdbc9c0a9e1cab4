"""Writes examples/logs/machine.csv, the log of the docs' `servobench identify --log examples/logs/machine.csv`
example: what a logging session on a real torque-mode servo axis gives (issue 23.1).

The "machine" is a rigid load that the docs do not tell the reader (inertia 2.3e-4 kg*m^2, viscous 1.4e-4
N*m*s/rad, Coulomb 0.018 N*m, static 0.022 N*m), read by a 10000-count encoder with 1 count of noise, driven by a GT
card's servo filter at 200 us through a torque-mode drive (0.8 A/V, 0.5 N*m/A, 1.5 kHz current loop). The standard
experiment (`servobench.run_experiment`: reversing motion over a decade of speeds plus a PRBS injection) runs for 2 s.
Columns: time_s [s], torque_nm [N*m] (the drive's torque command), position_pulse [pulse] (whole encoder counts).
Run: python examples/logs/make_machine_log.py  (deterministic: seeded)."""

from pathlib import Path

import numpy as np
import pandas as pd

import servobench as sb

PLANT = sb.RigidPlant(inertia_kgm2=2.3e-4, viscous_nms=1.4e-4, coulomb_nm=0.018, static_nm=0.022)


def machine_axis() -> sb.Axis:
    return sb.Axis(law=sb.GtServoLaw(kp=60, ki=60, kd=1500, kaff=0), plant=PLANT,
                   drive=sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=8.0, current_bw_hz=1500.0),
                   encoder=sb.Encoder(counts_per_rev=10000, noise_counts=1.0, seed=7), servo_period_s=200e-6)


def main(path: Path = Path(__file__).with_name("machine.csv")) -> Path:
    log = sb.run_experiment(machine_axis(), duration_s=2.0, seed=3)
    pulse = np.rint(log.measured * 10000 / (2 * np.pi)).astype(np.int64)
    df = pd.DataFrame({"time_s [s]": np.round(log.time_s, 7), "torque_nm [N*m]": log.torque_nm,
                       "position_pulse [pulse]": pulse})
    df.to_csv(path, index=False, float_format="%.8g")
    print("wrote", path, f"({len(df)} rows)")
    return path


if __name__ == "__main__":
    main()
