"""ZeroPos / SetAtlPos do what the Googol manuals say (issue 25 point 4; decisions VF1-VF4).

GT (seed 000) L4613-4622 GT_SetAtlPos: "modify the actual and target positions of the current axis and the planned
position ... to the specified values. This function is only effective when the current axis stops. Otherwise, it
will be considered as an illegal command"; L5196-5202 GT_ZeroPos: the same with 0; L1421-1429: invalid in gear mode.
GE (seed 001) L5457-5463 / L5907-5913: actual, target and planned position set; only at rest, else invalid and
return 1; range [-2^30, 2^30-1]. GTS/iDEABOX (seed 003) L647, L848 call GT_ZeroPos(axis, count) only.

The point the card used to miss: a following error left at rest (a P-only law against Coulomb friction) was
carried into the new coordinates (actual = pos - error). Now actual = target = profile = pos, the error is 0 and the
mechanism does not move."""

import numpy as np
import pytest

import servobench as sb
from servobench.dialects.ge import GeController
from servobench.dialects.gt import GtController
from servobench.dialects.gts import GtsController

# A PD law (no integrator) against Coulomb friction: the axis stops 9 pulses short of its target and stays there
# (a following error at rest; the actual position does not change over 500 ticks).
STICKY = dict(law=sb.GtServoLaw(kp=10, kd=200), plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-3, coulomb_nm=0.02))


def residual_card():
    """A GT-style 4-axis card whose axis 1 ends a 5000-pulse move at rest with a following error of some pulses."""
    card = sb.Card(4, **STICKY)
    card.axis_on(0)
    card.stage_vel(0, 10)
    card.stage_acc(0, 0.1)
    card.stage_pos(0, 5000)
    card.update(1)
    card.run(3000)
    assert not card.moving(0)
    still = card.run(300, signals=["actual_pos"])[0].actual_pos
    assert np.ptp(still) == 0  # the mechanism is at rest, not only the profile
    return card


def test_gt_set_atl_pos_sets_actual_target_and_profile_and_drops_the_residual_error():
    # GT L4613-4622: actual, target and planned position := actl_pos; the mechanism does not move.
    g = GtController()
    assert g.GT_Open(residual_card()) == 0
    g.GT_Axis(1)
    error_before = g.card.profile_pos(0) - g.card.actual_pos(0)
    assert abs(error_before) >= 3  # the case the card used to get wrong: a following error at rest
    assert g.GT_SetAtlPos(1000) == 0
    assert g.GT_GetAtlPos() == (0, 1000)          # actual
    assert g.GT_GetPos() == (0, 1000)             # target
    assert g.card.profile_pos(0) == 1000          # planned
    assert g.card.profile_pos(0) - g.card.actual_pos(0) == 0   # planned = actual at once
    g.card.run(200)
    assert abs(g.GT_GetAtlErr()[1]) <= 1          # profile - actual: nothing left to correct (was 9 before)
    assert abs(g.GT_GetAtlPos()[1] - 1000) <= 1   # the axis did not travel to "correct" the old error
    # GT L5196-5202 ZeroPos: the same with 0
    assert g.GT_ZeroPos() == 0
    assert g.GT_GetAtlPos() == (0, 0) and g.GT_GetPos() == (0, 0) and g.card.profile_pos(0) == 0


def test_gt_only_at_rest_else_illegal_command_bit_11_and_nothing_changes():
    # GT L4617-4618, L5200-5201: "only effective when the current axis stops. Otherwise ... an illegal command".
    g = GtController()
    assert g.GT_Open(sb.Card(4, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870))) == 0
    g.GT_Axis(1)
    g.GT_AxisOn()
    g.GT_SetAcc(0.5)
    g.GT_SetVel(10)
    g.GT_SetPos(10000)
    g.GT_Update()
    g.card.run(20)
    before = (g.GT_GetAtlPos(), g.card.profile_pos(0))
    assert g.GT_SetAtlPos(7) == 1 and g.GT_GetCmdSts() == (0, 1 << 11)
    assert g.GT_ZeroPos() == 1 and g.GT_GetCmdSts() == (0, 1 << 11)
    assert g.card.profile_pos(0) == before[1] and g.GT_GetAtlPos()[1] != 7
    # range: GT L1415 (+-2^30) for the position registers; beyond it rtn 7 / cmd bit 0 at rest
    g.card.run(3000)
    assert g.GT_SetAtlPos(2**30) == 7


def test_ge_set_atl_pos_and_zero_pos_example_t30():
    # GE L5457-5490 (T30): after the move stops, SetAtlPos(1, 0); actual = target = profile = 0.
    ge = GeController()
    assert ge.GT_Open(residual_card()) == 0
    err = ge.card.profile_pos(0) - ge.card.actual_pos(0)
    assert abs(err) >= 3
    assert ge.GT_SetAtlPos(1, 0) == 0
    assert ge.GT_GetAtlPos(1) == (0, 0) and ge.GT_GetPrfPos(1) == (0, 0)
    ge.card.run(200)
    assert abs(ge.GT_GetAtlErr(1)[1]) <= 1 and abs(ge.GT_GetAtlPos(1)[1]) <= 1   # the 9-pulse error is gone
    assert ge.GT_SetAtlPos(1, 2**30) == 7 and ge.GT_SetAtlPos(1, -(2**30)) == 0   # [-2^30, 2^30-1] (L5461)
    assert ge.GT_ZeroPos(1) == 0 and ge.GT_GetAtlPos(1) == (0, 0) and ge.GT_GetPrfPos(1) == (0, 0)


def test_gts_zero_pos_count_is_all_or_nothing():
    # iDEABOX L647: GT_ZeroPos(axis, count); Googol meaning (VF3): only at rest, else 1 with nothing changed.
    c = GtsController()
    card = residual_card()
    assert c.GT_Open(card) == 0
    card.axis_on(1)
    card.stage_vel(1, 10)
    card.stage_acc(1, 0.1)
    card.stage_pos(1, 100000)
    card.update(2)
    card.run(50)
    assert card.moving(1)
    p1, a1 = card.profile_pos(0), card.actual_pos(0)
    assert c.GT_ZeroPos(1, 2) == 1                       # axis 2 moves: refused ...
    assert card.profile_pos(0) == p1 and card.actual_pos(0) == a1   # ... and axis 1 untouched
    assert c.GT_ZeroPos(1, 1) == 0                       # axis 1 alone is at rest
    assert card.profile_pos(0) == 0 and card.actual_pos(0) == 0
    assert c.GT_ZeroPos(1, 0) == 7 and c.GT_ZeroPos(4, 2) == 7 and c.GT_ZeroPos(0, 1) == 7
    card.abrupt_stop(1)
    card.run(20)
    assert c.GT_ZeroPos(1, 2) == 0
    assert [card.actual_pos(a) for a in (0, 1)] == [0, 0] and [card.profile_pos(a) for a in (0, 1)] == [0, 0]


def test_card_zero_pos_range_refuses_bad_counts():
    card = sb.Card(4)
    with pytest.raises(ValueError, match="count"):
        card.zero_pos_range(0, 5)
    with pytest.raises(ValueError, match="count"):
        card.zero_pos_range(1, 0.5)
    card.zero_pos_range(0, 4)
    assert np.all([card.actual_pos(a) == 0 for a in range(4)])
