"""S-curve replanned from a moving state (issue 25 point 5): time-optimal, checked against Ruckig (PyPI `ruckig`,
the community version) on 20,000 seeded random states, within the card's own rules.

The card's rule (GT L909-912, GE L1179-1183, decision M5): during an S-curve only the target may change; the
move keeps its own vel/macc/jerk. So the states a change starts from are the states a profile planned with those
limits passes through: |a| <= A and |v + a|a|/(2J)| <= V (decision MO3). Units per tick: pulse, pulse/tick,
pulse/tick^2, pulse/tick^3.
"""

import math

import numpy as np
import pytest

import servobench as sb

ruckig = pytest.importorskip("ruckig", reason="ruckig is in the test extra (pyproject.toml)")

N_CASES = 20000
REL_TOL = 1e-6


def random_replans(n: int, seed: int):
    """Random moving states reachable under their limits and random targets (either side, up to 1e6 pulse).
    Limits log-uniform: vel 0.1..100 pulse/tick, acc 1e-3..1 pulse/tick^2, jerk 1e-5..0.1 pulse/tick^3."""
    rng = np.random.default_rng(seed)
    lu = lambda lo, hi: np.exp(rng.uniform(np.log(lo), np.log(hi), n))  # noqa: E731
    V, A, J = lu(0.1, 100), lu(1e-3, 1), lu(1e-5, 0.1)
    a0 = rng.uniform(-1, 1, n) * A
    shift = a0 * np.abs(a0) / (2 * J)  # v* - v0
    lo, hi = np.maximum(-V, -V - shift), np.minimum(V, V - shift)
    ok = lo < hi
    v0 = np.where(ok, lo + rng.uniform(0, 1, n) * (hi - lo), 0.0)
    a0 = np.where(ok, a0, 0.0)
    pos = np.round(rng.uniform(-1e6, 1e6, n))
    target = pos + np.round(np.exp(rng.uniform(0, np.log(1e6), n))) * rng.choice([-1.0, 1.0], n)
    return pos, v0, a0, target, V, A, J


def ruckig_durations(pos, vel, acc, target, V, A, J):
    otg, inp, traj = ruckig.Ruckig(1), ruckig.InputParameter(1), ruckig.Trajectory(1)
    out = np.empty(len(pos))
    for i in range(len(pos)):
        inp.current_position, inp.current_velocity, inp.current_acceleration = [pos[i]], [vel[i]], [acc[i]]
        inp.target_position, inp.target_velocity, inp.target_acceleration = [target[i]], [0.0], [0.0]
        inp.max_velocity, inp.max_acceleration, inp.max_jerk = [V[i]], [A[i]], [J[i]]
        assert otg.calculate(inp, traj).value >= 0
        out[i] = traj.duration
    return out


def test_replan_duration_matches_ruckig_on_20000_random_states():
    cases = random_replans(N_CASES, seed=25)
    ours = sb.motion.plan_s_curve_replan_batch(*cases)
    ref = ruckig_durations(*cases)
    rel = np.abs(ours - ref) / ref
    worst = int(np.argmax(rel))
    print(f"replan vs Ruckig: {N_CASES} states, worst relative difference {rel.max():.2e}")
    assert rel.max() <= REL_TOL, [c[worst] for c in cases] + [ours[worst], ref[worst]]
    # the cases cover what used to be slow: the axis braking (a against v) towards a target past its stop
    pos, v0, a0, target, V, A, J = cases
    braking = (v0 * a0 < 0) & ((target - pos) * v0 > 0)
    assert braking.sum() > 2000


def test_replan_from_outside_the_limits_brakes_first_and_ends_on_target():
    # Decision MO2: a state the limits do not reach (|a| > A, or v that would overshoot V) is braked at full
    # jerk back inside, then planned as above; the plan is finite and ends on its target.
    d = sb.motion.plan_s_curve_replan_batch([0.0, 0.0, 0.0], [5.0, -9.0, 0.5], [2.0, 0.3, -0.5], [100.0, -50.0, 3.0],
                                            [1.0, 2.0, 1.0], [0.5, 0.2, 0.1], [0.1, 0.05, 0.01])
    assert np.all(np.isfinite(d)) and np.all(d > 0)


@pytest.mark.parametrize("field,bad,match", [
    ("vmax", 0.0, "vel"), ("amax", -1.0, "acc"), ("jmax", math.inf, "jerk"), ("vel", math.nan, "from.vel"),
    ("acc", math.inf, "from.acc"), ("target", math.nan, "target"), ("pos", 1e13, "from.pos"),
])
def test_replan_batch_rejects_bad_input(field, bad, match):
    args = dict(pos=[0.0], vel=[1.0], acc=[0.1], target=[100.0], vmax=[2.0], amax=[0.5], jmax=[0.1])
    args[field] = [bad]
    with pytest.raises(ValueError, match=match):
        sb.motion.plan_s_curve_replan_batch(**args)


def test_replan_batch_rejects_unequal_lengths():
    with pytest.raises(ValueError, match="equal lengths"):
        sb.motion.plan_s_curve_replan_batch([0.0], [1.0, 2.0], [0.1], [100.0], [2.0], [0.5], [0.1])
