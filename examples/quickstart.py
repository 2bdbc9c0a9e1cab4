"""Quick start, typed: a demo axis, a trapezoidal move, its step figures and the loop's margins.

Run it with ``python examples/quickstart.py``; mypy checks it in the suite (tests/python/test_typing.py).
Units: positions in pulse, velocities in pulse/tick, accelerations in pulse/tick^2, times in s, frequencies in Hz.
"""

from __future__ import annotations

import numpy as np

import servobench as sb


def main() -> sb.MoveMetrics:
    """Runs a 10,000-pulse move on the demo axis with stiffer gains and prints its figures and margins."""
    axis: sb.Axis = sb.demo_axis()
    law: sb.GtServoLaw = axis.law
    axis.set_law(law.replace(kp=float(round(law.kp * 1.2))))  # GT gains are whole numbers
    move: sb.Trajectory = sb.trapezoid_move(distance_pulse=10000.0, vel_pulse_per_tick=20.0,
                                            acc_pulse_per_tick2=0.1, dwell_after=1000)
    run: sb.AxisRun = axis.run(move)
    metrics: sb.MoveMetrics = sb.move_metrics(run)
    print(metrics)
    freq_hz = np.geomspace(1.0, 0.45 / axis.servo_period_s, 200)
    margins: sb.Margins = sb.analytic_response(axis, freq_hz).margins()
    print(margins)
    return metrics


if __name__ == "__main__":
    main()
