"""Ready-made, documented axes for demos, notebooks and benchmarks."""

from __future__ import annotations

from . import _core
from .axis import Axis


def demo_axis(*, law: str = "gt", coulomb_nm: float = 0.005) -> Axis:
    """The reference axis of the demo: a 400 W class servo motor in torque mode on a rigid load.

    Plant: J = 1e-4 kg*m^2, viscous 1e-4 N*m*s/rad, Coulomb `coulomb_nm` N*m. Drive: 0.8 A/V, kt 0.5 N*m/A,
    8 A limit, 1500 Hz current loop. Encoder 10000 counts/rev. DAC 16 bit +-10 V.

    law="gt": GT servo filter at 200 us with Kp 38, Ki 60, Kd 830, Kaff 12870 (about 60 Hz crossover,
    55 deg phase margin; Kaff = 1/plant gain in counts per pulse/tick^2, the inertia feed-forward).
    law="aps": the same per-tick gains in the ADLINK law at 200 us with the manual's default shifts
    where they fit (KP 38*2^10, KD 830*2^5), and shifted where they do not (KI_SHIFT -13, KAFF_SHIFT 5).
    """
    plant = _core.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, coulomb_nm=coulomb_nm)
    drive = _core.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=8.0, current_bw_hz=1500.0)
    encoder = _core.Encoder(counts_per_rev=10000)
    if law == "gt":
        servo_law = _core.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)
    elif law == "aps":
        # Effective gain = K * 2^(K_SHIFT + PID_SHIFT); default shifts give KP*2^-10, KI*2^-20, KD*2^-5, KAFF*2^-5.
        # GT's Ki/256 = 60/256 per tick: KI * 2^(KI_SHIFT-5) with KI_SHIFT -13 gives KI = 61440 (fits 0..65535).
        # Kaff 12870 per tick: KAFF * 2^(KAFF_SHIFT-5) with KAFF_SHIFT 5 gives KAFF = 12870.
        servo_law = _core.ApsServoLaw(kp=38 * 1024, ki=61440, ki_shift=-13, kd=830 * 32, kaff=12870, kaff_shift=5)
    else:
        raise ValueError(f"law = {law!r} must be 'gt' or 'aps'")
    return Axis(law=servo_law, drive=drive, plant=plant, encoder=encoder, servo_period_s=200e-6)
