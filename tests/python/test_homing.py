"""Homing: ADLINK home modes 0/1/2 (ORG, EL, single EZ; direction, EZ alignment, shift, HOME_POS) and GT
GT_Home/GT_Index, closed loop against a simulated axis. Manual lines: ADLINK seed 004 (adlink.md §6.3, §10),
GT seed 000 (gt.md §5, §9)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.homing import HOME_PHASES, pulse_to_rad

CPR = 10000
ORG = (10000, 14000)  # home switch window, pulse
EL = 50000  # limits at -EL and +EL, pulse
INDEX = 2500  # index marks at 2500 + k * CPR


def make_axis(start_pulse=0.0, org=ORG):
    base = sb.demo_axis()
    axis = sb.Axis(law=base.law, drive=base.drive, plant=base.plant, servo_period_s=200e-6,
                   encoder=sb.Encoder(counts_per_rev=CPR, index_angle_rad=pulse_to_rad(INDEX, CPR)),
                   switches=sb.Switches(home_min_rad=pulse_to_rad(org[0], CPR), home_max_rad=pulse_to_rad(org[1], CPR),
                                        neg_limit_rad=pulse_to_rad(-EL, CPR), pos_limit_rad=pulse_to_rad(EL, CPR)))
    axis.reset(pulse_to_rad(start_pulse, CPR))
    return axis


def phases(run):
    return [HOME_PHASES[int(p)] for p in dict.fromkeys(run.phase.astype(int))]


def test_t37_manual_example_ends_at_the_pel_side_edge_of_org_and_resets_the_position():
    # adlink.md §10 T37, seed L2295-2303 (example: MODE 0, DIR 1, CURVE 0, ACC 1e6, VM 1e5, VO 5e4, EZA 0,
    # SHIFT 0, POS 0) and L2372 (DIR negative -> the right, PEL-side, edge of ORG); L2252 (positions reset).
    p = sb.AdlinkHome()
    assert (p.mode, p.dir, p.curve, p.acc, p.vm, p.vo, p.eza, p.shift, p.pos) == (0, 1, 0, 1e6, 1e5, 5e4, False, 0, 0)
    axis = make_axis(start_pulse=0.0)  # start case C for DIR 1: between MEL... ORG lies ahead in + only
    res = sb.home(axis, p, max_ticks=200000)
    assert res.done and res.error_code == 0
    assert res.reference_pulse == ORG[1]  # the PEL-side edge, captured inside the tick
    assert res.run.pos[-1] == 0 and abs(res.run.actual_pos[-1]) <= 1  # command and feedback reset to HOME_POS 0
    assert res.offset_pulse == ORG[1]
    assert abs(axis.feedback_pulse - ORG[1]) <= 1  # the mechanism rests at the edge
    # the limit reversed the search (start case C), then leave / approach at VO (L2351)
    assert phases(res.run) == ["search", "search_reverse", "leave", "stop_after_leave", "approach", "stop_at_edge",
                               "move_to_edge", "done"]


@pytest.mark.parametrize("start,case", [(-30000, "A"), (12000, "B"), (30000, "C")])
@pytest.mark.parametrize("direction,edge", [(0, ORG[0]), (1, ORG[1])])
def test_mode0_org_edge_from_every_start_case(start, case, direction, edge):
    # ADLINK L2345-2351 (cases A, B, C; fast search, stop, leave at VM, approach at VO) and L2370-2372:
    # DIR 0 -> the MEL-side (left) edge, DIR 1 -> the PEL-side (right) edge.
    axis = make_axis(start_pulse=start)
    res = sb.home(axis, sb.AdlinkHome(mode=0, dir=direction), max_ticks=300000)
    assert res.done, (case, res.error_code)
    assert res.reference_pulse == edge
    assert abs(axis.feedback_pulse - edge) <= 1
    assert res.run.pos[-1] == 0
    # the last approach ran at VO = 5e4 pulse/s = 10 pulse/tick, the search at VM = 20 pulse/tick
    v = np.abs(np.diff(res.run.cmd_pos))  # raw counts: no jump at the reset
    assert v.max() <= 21
    if case != "B":
        assert v.max() == pytest.approx(20, abs=1)
    approach = res.run.phase == HOME_PHASES.index("approach")
    assert v[approach[1:]].max() == pytest.approx(10, abs=1)


def test_mode0_eza_shift_and_home_pos():
    # ADLINK L2391 (EZA = 1: continue in the home direction to the first EZ), L2436-2449 (HOME_SHIFT),
    # L2278 (HOME_POS: the command position set after homing).
    axis = make_axis(start_pulse=-30000)
    res = sb.home(axis, sb.AdlinkHome(mode=0, dir=0, eza=True), max_ticks=300000)
    assert res.done and res.reference_pulse == 12500  # the first index mark after the left ORG edge (10000)
    axis = make_axis(start_pulse=-30000)
    res = sb.home(axis, sb.AdlinkHome(mode=0, dir=0, shift=500, pos=100), max_ticks=300000)
    assert res.done and res.reference_pulse == ORG[0]
    assert res.run.pos[-1] == 100  # HOME_POS
    assert abs(axis.feedback_pulse - (ORG[0] + 500)) <= 1  # rests at the edge + shift
    assert res.offset_pulse == ORG[0] + 500 - 100


@pytest.mark.parametrize("direction,edge,eza,ref", [(0, EL, False, EL), (1, -EL, False, -EL),
                                                    (0, EL, True, 42500), (1, -EL, True, -47500)])
def test_mode1_el(direction, edge, eza, ref):
    # ADLINK L2459-2508: search PEL (DIR 0) or MEL (DIR 1), stop at its edge; EZA aligns with an EZ (M41:
    # the first index mark away from the limit).
    axis = make_axis(start_pulse=0.0)
    res = sb.home(axis, sb.AdlinkHome(mode=1, dir=direction, eza=eza), max_ticks=300000)
    assert res.done and res.reference_pulse == ref
    assert abs(axis.feedback_pulse - ref) <= 1


@pytest.mark.parametrize("direction,ref", [(0, 2500), (1, -7500)])
def test_mode2_single_ez(direction, ref):
    # ADLINK L2510-2556: search the EZ in the home direction and stop at it; EZA has no effect (L2556).
    for eza in (False, True):
        axis = make_axis(start_pulse=0.0)
        res = sb.home(axis, sb.AdlinkHome(mode=2, dir=direction, eza=eza), max_ticks=300000)
        assert res.done and res.reference_pulse == ref
        assert abs(axis.feedback_pulse - ref) <= 1


def test_s_curve_homing_ends_at_the_same_edge():
    # ADLINK L2229 (the profile rules apply to home moves), L2270 PRA_HOME_CURVE.
    axis = make_axis(start_pulse=-30000)
    res = sb.home(axis, sb.AdlinkHome(mode=0, dir=0, curve=0.7), max_ticks=300000)
    assert res.done and res.reference_pulse == ORG[0]


def test_no_org_fails_with_the_limit_stop_code():
    # ADLINK L2319-2326 (abnormal end, APS_get_stop_code), L3931-4023 (STOP_PEL 4, STOP_MEL 5).
    axis = make_axis(start_pulse=0.0, org=(1e9, 1e9 + 1))  # the home switch lies beyond the travel
    res = sb.home(axis, sb.AdlinkHome(mode=0, dir=0), max_ticks=400000)
    assert not res.done and res.error_code == 5  # reversed at PEL, then met MEL
    assert res.reference_pulse is None


@pytest.mark.parametrize("index,ref", [(False, ORG[0]), (True, 12500)])
def test_gt_home_and_index(index, ref):
    # gt.md §9 TV40 (Example 6-1 Home+Index, L2021-2099: Vel 4, Acc 1, home(200000)), TV41 (Example 6-2 Home
    # only, L2101-2150), TV42 (GT_Index(1); GT_Home(...), L4200-4206): the axis ends at the home (or index)
    # capture and ZeroPos sets the position 0 there.
    axis = make_axis(start_pulse=0.0)
    res = sb.home(axis, sb.GtHome(pos=200000, vel=4, acc=1, index=index), max_ticks=300000)
    assert res.done and res.reference_pulse == ref
    assert res.run.pos[-1] == 0
    after = res.loop.run(3000)  # settle: Acc 1 pulse/ST^2 is more than this motor can follow
    assert abs(after.actual_pos[-1]) <= 1 and after.pos[-1] == 0
    assert abs(axis.feedback_pulse - ref) <= 1


def test_gt_home_starting_on_the_switch_backs_off_first():
    # GT L4160: if the home signal is on when GT_Home is called, the axis first moves away from pos until it
    # leaves the switch, then homes.
    axis = make_axis(start_pulse=12000)
    res = sb.home(axis, sb.GtHome(pos=200000, vel=4, acc=1), max_ticks=300000)
    assert res.done and res.reference_pulse == ORG[0]
    assert res.run.fb_pos.min() < ORG[0]


def test_gt_home_without_a_switch_returns_1():
    # Example 6-1 step 2 (L2021-2099): motion complete before the home capture -> no home, return 1.
    axis = make_axis(start_pulse=0.0, org=(1e9, 1e9 + 1))
    res = sb.home(axis, sb.GtHome(pos=20000, vel=4, acc=1), max_ticks=300000)
    assert not res.done and res.error_code == 1


def test_homing_is_refused_while_moving_and_jog_is_ignored_during_homing():
    # ADLINK L2706-2708: while another motion (e.g. homing) runs, jog commands are ignored.
    loop = sb.MotionLoop(make_axis())
    loop.command(sb.GtJog(vel=1, acc=0.01))
    with pytest.raises(sb.MotionCommandRefused):
        loop.home(sb.AdlinkHome())
    loop.abrupt_stop()
    loop.home(sb.AdlinkHome())
    loop.run(10)
    with pytest.raises(sb.MotionCommandRefused, match="ADLINK L2708"):
        loop.jog(sb.AdlinkJog())
