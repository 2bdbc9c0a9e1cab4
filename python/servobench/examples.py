"""Ready-made, documented axes for demos, notebooks and benchmarks."""

from __future__ import annotations

__all__ = ["demo_axis", "velocity_axis", "resonant_axis", "GUC_HEXAGON_PULSE", "program_guc_hexagon", "EMPS_ENV",
           "emps_path", "emps_log"]

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


def _linear_io() -> dict:
    """Encoder and DAC without quantisation: the loop is linear, so measured and analytic responses agree."""
    return {"encoder": _core.Encoder(counts_per_rev=10000, quantize=False), "dac": _core.Dac(quantize=False)}


def velocity_axis(plant: str = "rigid", *, servo_period_s: float = 100e-6) -> Axis:
    """A linear velocity-mode axis for tuning experiments (the relay auto-tune needs a velocity drive).

    ADLINK law with the manual's defaults; drive 31.4 rad/s per V (300 rpm/V), no current or torque limit;
    plant "rigid" (J = 1e-4 kg*m^2, viscous 1e-4 N*m*s/rad) or "two_mass" (Jm = Jl = 5e-5 kg*m^2, shaft
    300 N*m/rad, 0.01 N*m*s/rad: resonance 551 Hz); encoder 10000 counts/rev and DAC unquantised;
    `servo_period_s` in s (ADLINK range 50..2000 us).
    """
    if plant == "rigid":
        p = _core.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4)
    elif plant == "two_mass":
        p = _core.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01)
    else:
        raise ValueError(f"plant = {plant!r} must be 'rigid' or 'two_mass'")
    drive = _core.VelocityDrive(speed_per_volt_rad_s=31.4, current_limit_a=float("inf"), torque_limit_nm=1e9)
    return Axis(law=_core.ApsServoLaw(), plant=p, drive=drive, servo_period_s=servo_period_s, **_linear_io())


def resonant_axis(drive: str = "velocity", *, law=None, servo_period_s: float = 100e-6) -> Axis:
    """A linear two-mass axis whose resonance sits inside the loop's band, where it limits the crossover
    without a notch: Jm = Jl = 5e-5 kg*m^2, shaft 150 N*m/rad with 0.002 N*m*s/rad (0.2 % damping): resonance
    389.8 Hz, anti-resonance 275.6 Hz.

    drive "velocity" (31.4 rad/s per V, no limits) or "torque" (the default TorqueDrive without a current limit);
    `law` a GtServoLaw or ApsServoLaw (default ApsServoLaw()); encoder and DAC unquantised; `servo_period_s` in s.
    """
    if drive == "velocity":
        d = _core.VelocityDrive(speed_per_volt_rad_s=31.4, current_limit_a=float("inf"), torque_limit_nm=1e9)
    elif drive == "torque":
        d = _core.TorqueDrive(current_limit_a=float("inf"))
    else:
        raise ValueError(f"drive = {drive!r} must be 'velocity' or 'torque'")
    return Axis(law=law if law is not None else _core.ApsServoLaw(),
                plant=_core.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=150, c_nms_per_rad=0.002),
                drive=d, servo_period_s=servo_period_s, **_linear_io())


GUC_HEXAGON_PULSE = [(200000, 0), (100000, 173205), (-100000, 173205), (-200000, 0), (-100000, -173205),
                     (100000, -173205), (200000, 0)]
"""The GUC-ECAT manual's hexagon (L802-843, Fig 4-5; iDEABOX Ex 4-4 L1219-1370), pulse."""


def program_guc_hexagon(path):
    """Writes the GUC-ECAT manual's hexagon program (L802-843) into a PathGenerator `path` (pulse, ms): seven
    lines at 100 pulse/ms and 0.1 pulse/ms^2, BufIO 0x55 after line 2, 0xAA after line 3, BufDelay 400 ms after
    line 4, BufIO 0x55 and BufDelay 100 ms after line 5. Started, it ends at 21500 ms. Returns `path`."""
    for i, p in enumerate(GUC_HEXAGON_PULSE, start=1):
        path.line(p, vel=100, acc=0.1)
        if i == 2:
            path.buf_io(0, 0xFFFF, 0x55)
        elif i == 3:
            path.buf_io(0, 0xFFFF, 0xAA)
        elif i == 4:
            path.buf_delay(400)
        elif i == 5:
            path.buf_io(0, 0xFFFF, 0x55)
            path.buf_delay(100)
    return path


#: Environment variable naming the EMPS benchmark's DATA_EMPS.mat (set by the test and documentation builds).
EMPS_ENV = "SERVOBENCH_EMPS_MAT"


def emps_path() -> str:
    """The path of the EMPS benchmark's estimation record DATA_EMPS.mat (tests/data/emps/ in the repository, README
    there): $SERVOBENCH_EMPS_MAT, else tests/data/emps/DATA_EMPS.mat in the current directory or a parent of it or of
    this package. FileNotFoundError naming where it looked otherwise."""
    import os
    from pathlib import Path

    env = os.environ.get(EMPS_ENV)
    if env:
        if not Path(env).is_file():
            raise FileNotFoundError(f"${EMPS_ENV} = {env}: no such file")
        return env
    tried = []
    for start in (Path.cwd(), Path(__file__).resolve().parent):
        for d in (start, *start.parents):
            p = d / "tests" / "data" / "emps" / "DATA_EMPS.mat"
            if p.is_file():
                return str(p)
        tried.append(str(start))
    raise FileNotFoundError(f"DATA_EMPS.mat not found (set ${EMPS_ENV}, or run from the repository; searched above "
                            f"{', '.join(tried)})")


def emps_log():
    """The EMPS estimation record as an :class:`IdentificationLog` (linear axis: m, N; 1 kHz; reference kept; the
    record's kp, kv and gtau in ``extra``)."""
    from .idlog import IdentificationLog

    return IdentificationLog.from_mat(emps_path(), units={"t": "s", "qm": "m", "qg": "m", "vir": "V"},
                                      command_gain="gtau")
