"""A typed use of servobench's public API, checked by mypy in the suite (tests/python/test_typing.py) and run there
too. ``assert_type`` fails the mypy run wherever an expression is ``Any`` instead of the stated type: with the
stubs (servobench/_core.pyi) and py.typed missing, every line below would be ``Any``."""

from __future__ import annotations

import numpy as np
from typing_extensions import assert_type

import servobench as sb
from servobench import _core
from servobench.dialects import gt
from servobench.margins import analytic_margins


def parameter_objects() -> float:
    """The C++ parameter classes: explicit typed keywords, typed properties, replace() keeps the type."""
    law = sb.GtServoLaw(kp=8.0, kd=40.0, ki=0.0, kvff=0.0, kaff=0.0, ilmt=32767.0, bias=0.0, mtr_lmt=32767.0,
                        fractional_gains=False)
    assert_type(law, sb.GtServoLaw)
    assert_type(law.kp, float)
    assert_type(law.fractional_gains, bool)
    stiffer: sb.GtServoLaw = law.replace(kp=12.0)
    aps = sb.ApsServoLaw(kp=100.0, kp_shift=-5.0, v_limit=10.0, v_inverse=False)
    plant = sb.RigidPlant(inertia_kgm2=2e-4, viscous_nms=1e-4)
    two_mass = sb.TwoMassPlant()
    drive = sb.TorqueDrive()
    assert_type(plant.inertia_kgm2, float)
    gains: dict[str, float] = {name: float(value) for name, value in stiffer.to_dict().items()
                               if not isinstance(value, bool)}
    assert isinstance(two_mass, _core.TwoMassPlant) and isinstance(drive, _core.TorqueDrive)
    assert aps.kp == 100.0
    return gains["kp"]


def step_response() -> sb.MoveMetrics:
    """An axis, a move, a run, its metrics: typed end to end."""
    axis: sb.Axis = sb.demo_axis()
    move = sb.trapezoid_move(distance_pulse=2000.0, vel_pulse_per_tick=20.0, acc_pulse_per_tick2=0.5,
                             dwell_after=500)
    assert_type(move, sb.Trajectory)
    run = axis.run(move, signals=("time_s", "cmd_pos", "fb_pos", "error"))
    assert_type(run, sb.AxisRun)
    error: np.ndarray = run.error
    metrics = sb.move_metrics(run)
    assert_type(metrics, sb.MoveMetrics)
    assert_type(metrics.overshoot_pulse, float)
    assert error.shape == (len(move),)
    return metrics


def frequency_analysis() -> float:
    """The analytic loop response and its margins."""
    axis = sb.demo_axis()
    response = sb.analytic_response(axis, np.geomspace(10.0, 1000.0, 50), filters=True)
    assert_type(response, sb.FrequencyResponse)
    margins = response.margins()
    assert_type(margins, sb.Margins)
    # options read from the C++ structs are typed keywords (generated signatures, decision OQ5)
    analytic = analytic_margins(axis, filters=False)
    assert_type(analytic, sb.Margins)
    io = sb.MechanicsIO(sample_period_s=1e-4, delay_samples=1, counts_per_rev=10000.0)
    assert_type(io.torque_per_input, float)
    return float(margins.phase_margin_deg)


def core_module() -> float:
    """The compiled module's own functions are typed too (the stubs)."""
    pos, vel, acc = _core.trapezoid_move(start_pulse=0.0, distance_pulse=100.0, vel_pulse_per_tick=5.0,
                                         acc_pulse_per_tick2=0.5, dwell_before=0, dwell_after=0)
    return float(np.asarray(pos)[-1] + np.asarray(vel)[-1] + np.asarray(acc)[-1])


def vendor_dialect() -> int:
    """A vendor dialect's controller class."""
    controller = gt.GtController()
    assert_type(controller, gt.GtController)
    return gt.RTN_SUCCESS


if __name__ == "__main__":
    parameter_objects()
    print(step_response())
    print(f"phase margin {frequency_analysis():.1f} deg")
    core_module()
    vendor_dialect()
