"""Motion generators from Python: parameter ranges (ValueError naming parameter, value and range), the
manuals' on-the-fly rules, trajectories for Axis.run, the batch planner. Manual files are in
../shared/seeds/: GT = 000_0c49d4aa9b235bd5.txt, GE = 001_b26ef06a365efe59.txt, ADLINK = 004_b417b1b5a6e5a740.txt.
The C++ tests (tests/cpp/test_motion_*.cpp) hold the full test-vector list and the 10^5-move property tests."""

import math
import pickle

import numpy as np
import pytest

import servobench as sb

NAN, INF = math.nan, math.inf
GOOD = {
    sb.GtTCurve: dict(pos=1000, vel=1, acc=0.01),
    sb.GtSCurve: dict(pos=1000, vel=1, macc=0.01, jerk=0.001),
    sb.GtJog: dict(vel=1, acc=0.01),
    sb.GeTCurve: dict(pos=1000, vel=10, acc=1),
    sb.GeSCurve: dict(pos=1000, vel=10, macc=1, jerk=0.1),
    sb.GeJog: dict(vel=10, acc=1),
    sb.AdlinkPtp: dict(pos=1000, vs=0, vm=1000, ve=0, acc=1e4, dec=1e4, sf=0.5, sd_dec=0),
    sb.GtGear: dict(master=2, ratio=-1),
}

# (class, field, bad values, text expected in the message); ranges: GT L854-858, L929-930, L994-995;
# GE L991-996, L1095-1101, L1202-1206; ADLINK L2213-2219, L2744-2751.
BAD = [
    (sb.GtTCurve, "pos", [1073741824, -1073741825, 0.5, NAN], "-1073741824..1073741823 (GT L854)"),
    (sb.GtTCurve, "vel", [-1, 16384.5, 0, NAN], "0..16384 (GT L930)"),
    (sb.GtTCurve, "acc", [-0.1, 16385, 0, INF], "0..16384 (GT L929)"),
    (sb.GtSCurve, "pos", [2**30, 1.5], "-1073741824..1073741823"),
    (sb.GtSCurve, "vel", [-1, 16385, 0], "0..16384 (GT L858)"),
    (sb.GtSCurve, "macc", [0.5, -0.1, 0, NAN], "0 <= x < 0.5 (GT L857)"),
    (sb.GtSCurve, "jerk", [0.5, 1, 0, NAN], "0 <= x < 0.5 (GT L856)"),
    (sb.GtJog, "vel", [16385, -16385, NAN], "-16384..16384 (GT L994)"),
    (sb.GtJog, "acc", [0, -1, 16385], "0..16384 (GT L995)"),
    (sb.GeTCurve, "pos", [2**30, 0.25], "-1073741824..1073741823"),
    (sb.GeTCurve, "vel", [0, -1, 40958], "0..40957"),
    (sb.GeTCurve, "acc", [0, 102401, NAN], "0..102400"),
    (sb.GeSCurve, "pos", [-(2**30) - 1], "-1073741824..1073741823"),
    (sb.GeSCurve, "vel", [0, 40957.5], "0..40957"),
    (sb.GeSCurve, "macc", [0, 102400.5], "0..102400"),
    (sb.GeSCurve, "jerk", [0, 256001, INF], "0..256000"),
    (sb.GeJog, "vel", [40958, -40959, NAN], "-40958..40957"),
    (sb.GeJog, "acc", [0, 102401], "0..102400"),
    (sb.AdlinkPtp, "pos", [2**31, NAN], "-2147483647..2147483647"),
    (sb.AdlinkPtp, "vs", [-1, 1001], "0..vm"),
    (sb.AdlinkPtp, "vm", [0, -5, 2e9], "0..1000000000"),
    (sb.AdlinkPtp, "ve", [-1, 1000.5], "0..vm"),
    (sb.AdlinkPtp, "acc", [0, -1, 2e12], "0..1e+12"),
    (sb.AdlinkPtp, "dec", [0, NAN], "0..1e+12"),
    (sb.AdlinkPtp, "sf", [-0.1, 1.1, NAN], "0..1 (ADLINK L2213-2219)"),
    (sb.AdlinkPtp, "sd_dec", [-1, 2e12], "0..1e+12"),
    (sb.GtGear, "master", [0, 7, 1.5, NAN], "1..6 (GT L1042)"),
    (sb.GtGear, "ratio", [16384.5, -16385, INF], "-16384..16384 (GT L1043)"),
]


@pytest.mark.parametrize("cls,field,bad,expect", [(c, f, v, e) for c, f, vals, e in BAD for v in vals],
                         ids=lambda x: repr(x) if not isinstance(x, type) else x.__name__)
def test_motion_parameters_reject(cls, field, bad, expect):
    with pytest.raises(ValueError) as info:
        cls(**{**GOOD[cls], field: bad})
    msg = str(info.value)
    assert f"{cls.__name__}.{field} = " in msg
    assert expect in msg


def test_every_motion_field_has_a_bad_input_test():
    covered = {(c, f) for c, f, _v, _e in BAD}
    for cls in GOOD:
        for field in cls.FIELDS:
            assert (cls, field) in covered, f"{cls.__name__}.{field} has no bad-input test"


def test_motion_parameters_are_value_types():
    p = sb.GtSCurve(**GOOD[sb.GtSCurve])
    assert p == pickle.loads(pickle.dumps(p))
    assert p.replace(pos=2000).pos == 2000
    assert repr(p) == "GtSCurve(pos=1000, vel=1, macc=0.01, jerk=0.001)"
    with pytest.raises(ValueError, match="GtSCurve.jerk = 0.6"):
        p.jerk = 0.6
    assert p.jerk == 0.001


def test_period_is_required_for_per_ms_and_per_s_units():
    with pytest.raises(ValueError, match="period_s"):
        sb.move_trajectory(sb.GeTCurve(**GOOD[sb.GeTCurve]))
    with pytest.raises(ValueError, match="period_s = 0"):
        sb.move_trajectory(sb.GeTCurve(**GOOD[sb.GeTCurve]), period_s=0)


def test_gt_tv8_t_curve_trajectory():
    # GT TV8, 000 L942-951: Acc 0.01, Vel 1, Pos 80000 -> 80100 ST; whole pulses reported.
    t = sb.move_trajectory(sb.GtTCurve(pos=80000, vel=1, acc=0.01))
    assert len(t) == 80101
    assert t.pos[-1] == 80000 and t.vel[-1] == 0
    assert np.all(t.pos == np.round(t.pos))
    assert t.vel.max() == pytest.approx(1.0)
    assert np.abs(t.acc).max() == pytest.approx(0.01)


def test_ge_t2_s_curve_trajectory_in_ms_units():
    # GE T2, 001 L1103-1158: jerk 0.001 pulse/ms^3, acc 4, vel 166.7, pos 200000 -> about 2016 ms.
    t = sb.move_trajectory(sb.GeSCurve(pos=200000, vel=166.7, macc=4, jerk=0.001), period_s=1e-3,
                           whole_pulses=False)
    assert len(t) - 1 == pytest.approx(2016, abs=1)
    assert np.abs(t.acc).max() == pytest.approx(0.408, abs=1e-3)
    assert np.abs(t.jerk).max() == pytest.approx(0.001)
    assert t.pos[-1] == 200000


def test_on_the_fly_rules():
    g = sb.ProfileGenerator()
    g.command(sb.GtTCurve(pos=100000, vel=10, acc=0.1))
    g.run(200)
    g.command(sb.GtTCurve(pos=100000, vel=5, acc=0.1))  # velocity may change (GT L974-978)
    with pytest.raises(sb.MotionCommandRefused, match="acceleration may not change"):
        g.command(sb.GtTCurve(pos=100000, vel=5, acc=0.2))  # GE L315
    with pytest.raises(RuntimeError, match="mode can change only when the motion has ended"):
        g.command(sb.GtJog(vel=1, acc=0.1))  # GT L837
    g.smooth_stop()
    with pytest.raises(sb.MotionCommandRefused, match="smooth stop"):
        g.command(sb.GtTCurve(pos=0, vel=5, acc=0.1))  # GE L1312
    g.run_until_done()
    assert not g.moving and g.state[1] == 0
    g.command(sb.GtJog(vel=-3, acc=0.5))  # after the end, the mode may change
    g.run(10)
    g.command(sb.GtJog(vel=2, acc=0.25))  # jog: velocity and acceleration may change (GT L1025)
    g.run(40)
    assert g.state[1] == pytest.approx(2)
    g.abrupt_stop()
    assert g.state[1] == 0 and not g.moving


def test_adlink_t38_velocity_example():
    # ADLINK T38, 004 L2613-2630: 500 -> 1000 -> 600 pulse/s -> stop, ACC = DEC = SD_DEC = 10000, S = 0.5.
    p = sb.AdlinkPtp(pos=0, vm=1000, acc=1e4, dec=1e4, sf=0.5, sd_dec=1e4)
    g = sb.ProfileGenerator(period_s=1e-3)
    g.adlink_velocity(500, p)
    assert g.duration_ticks == math.inf
    first = g.run(2000)
    assert np.argmax(first["vel"] >= 0.5 - 1e-12) + 1 == 75  # 0.075 s
    g.adlink_velocity(1000, p)
    g.run(2000)
    g.adlink_velocity(600, p)
    g.run(2000)
    g.adlink_stop_move(p)
    assert len(g.run_until_done()["vel"]) == 90
    with pytest.raises(ValueError, match="vel_pulse_per_s = 2000"):
        g.adlink_velocity(2000, p)


def test_trajectory_drives_the_axis():
    axis = sb.demo_axis()
    move = sb.move_trajectory(sb.GtSCurve(pos=2000, vel=5, macc=0.05, jerk=0.002), dwell_after=500)
    run = axis.run(move)
    assert np.array_equal(run.cmd_pos, move.pos)
    assert abs(run.fb_pos[-1] - 2000) < 5  # the demo axis settles on the target


def test_batch_planner_matches_the_closed_form():
    rng = np.random.default_rng(1)
    n = 1000
    start = np.zeros(n)
    target = rng.integers(-10**6, 10**6, n).astype(float)
    vel, acc, jerk = rng.uniform(1, 100, n), rng.uniform(0.01, 1, n), rng.uniform(1e-4, 0.1, n)
    d = sb.motion.plan_s_curve_batch(start, target, vel, acc, jerk)
    for i in range(0, n, 97):
        assert d[i] == pytest.approx(sb.motion.s_curve_min_time(target[i], vel[i], acc[i], jerk[i]), rel=1e-12)
    with pytest.raises(ValueError, match="index 3"):
        sb.motion.plan_s_curve_batch(start[:5], target[:5], vel[:5], np.array([1, 1, 1, 0, 1.0]), jerk[:5])


def test_gear_tv10_tv11_from_python():
    # GT TV10 (000 L1055-1059) and TV11 (000 L4425-4435): ratio -1; chained -1.5 then 0.5.
    master = sb.move_trajectory(sb.GtTCurve(pos=40000, vel=7, acc=0.1)).pos.astype(np.int64)
    s1 = sb.ElectronicGear(ratio=-1.5).follow(master)
    s3 = sb.ElectronicGear(ratio=0.5).follow(s1.astype(np.int64))
    assert s1[-1] == -60000 and s3[-1] == -30000
    assert np.array_equal(sb.ElectronicGear(ratio=-1).follow(master), -master)
    with pytest.raises(ValueError, match="ElectronicGear.ratio = 20000"):
        sb.ElectronicGear(ratio=20000)
