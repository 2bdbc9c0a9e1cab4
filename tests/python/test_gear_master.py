"""Electronic gear master selection: another axis's profile, its encoder, or an auxiliary encoder (GT seed 000
L1029-1090, L4407-4437; gt.md §3.4, §9 TV10, TV11)."""

import numpy as np
import pytest

import servobench as sb


def _master_run():
    axis = sb.demo_axis()
    move = sb.move_trajectory(sb.GtTCurve(pos=30000, vel=9, acc=0.05), dwell_after=500)
    return axis.run(move)


def test_tv10_ratio_minus_one_from_the_master_profile_and_encoder():
    # gt.md §9 TV10 (L1055-1059): axis 1 PrflG(2), Ratio -1 -> delta pos1 = -delta pos2 (L1078).
    run = _master_run()
    for source, master in (("profile", run.cmd_pos), ("encoder", run.fb_pos)):
        slave = sb.gear_trajectory(run, gear=sb.GtGear(master=2, ratio=-1), source=source, slave_start=100)
        assert np.array_equal(slave.pos - 100, -(master - master[0]))
    assert not np.array_equal(run.cmd_pos, run.fb_pos)  # the two sources differ (following error)


def test_tv11_chained_gears_are_drift_free():
    # gt.md §9 TV11 (L4425-4435): axis 1 = -1.5 x axis 4, axis 3 = 0.5 x axis 1 -> -0.75 x axis 4; the remainder
    # is kept inside the gear, so a long run does not drift (gt.md §10 item 4).
    run = _master_run()
    axis1 = sb.gear_trajectory(run, ratio=-1.5, source="profile")
    axis3 = sb.gear_trajectory(axis1, ratio=0.5, source="profile")
    d4 = run.cmd_pos - run.cmd_pos[0]
    assert np.all(np.abs(axis1.pos + 1.5 * d4) <= 0.5)
    assert np.all(np.abs(axis3.pos - 0.5 * axis1.pos) <= 0.5)
    assert axis3.pos[-1] == pytest.approx(-0.75 * d4[-1], abs=0.5)
    # a slave Axis can run the geared command
    slave_run = sb.demo_axis().run(axis3)
    assert abs(slave_run.fb_pos[-1] - axis3.pos[-1]) <= 2


def test_aux_encoder_master_and_bad_input():
    # GT L1042: masters 5-6 are the auxiliary encoders.
    aux = np.arange(0, 1000, 3)
    slave = sb.gear_trajectory(aux, gear=sb.GtGear(master=5, ratio=2))
    assert np.array_equal(slave.pos, 2 * aux)
    with pytest.raises(ValueError, match="auxiliary encoder"):
        sb.gear_trajectory(aux, gear=sb.GtGear(master=6, ratio=2), source="encoder")
    with pytest.raises(ValueError, match="is an axis"):
        sb.gear_trajectory(aux, gear=sb.GtGear(master=1, ratio=2), source="aux")
    with pytest.raises(ValueError, match="source"):
        sb.gear_trajectory(aux, ratio=1, source="motor")
    with pytest.raises(ValueError, match="ElectronicGear.ratio"):
        sb.gear_trajectory(aux, ratio=20000, source="aux")
