"""Typed vendor return codes (cpp/include/servobench/vendor/) and the causes the card's exceptions carry as data,
so a dialect maps a refusal with a table and never reads a message (issue 24 point 2)."""

from __future__ import annotations

import pytest

import servobench as sb
from servobench.dialects import AdlinkCode, GeCode, GtCode, GucCode, gt


def test_codes_have_the_manuals_values():
    assert int(GtCode.SUCCESS) == 0 and int(GtCode.COMMAND_ERROR) == 1
    assert [int(GtCode.ARC_RADIUS_ERROR), int(GtCode.LINE_LENGTH_ERROR), int(GtCode.SYN_PARAM_ERROR),
            int(GtCode.ARC_END_POINT_ERROR), int(GtCode.MAP_AXIS_ERROR), int(GtCode.PARAMETER_ERROR),
            int(GtCode.COMM_ERROR)] == [2, 3, 4, 5, 6, 7, -1]  # GT Table 2-1 L393-408
    assert int(GeCode.REENTERED) == -3 and int(GeCode.PROGRAM_RUNNING) == 9 and int(GeCode.ARC_CHORD_ERROR) == 5
    assert [int(GucCode.LICENSE_ERROR), int(GucCode.OPEN_FAILED), int(GucCode.NO_RESPONSE)] == [2, -6, -7]
    assert int(AdlinkCode.ERR_NoError) == 0 and int(AdlinkCode.ERR_ParametersInvalid) == -10
    assert int(AdlinkCode.ERR_DistantNotEnough) == -22
    # the deprecated GUC/iDEABOX table keeps its values
    assert int(sb.ReturnCode.LICENSE_ERROR) == int(GucCode.LICENSE_ERROR)


def test_geometry_error_carries_its_code():
    with pytest.raises(sb.PathGeometryError) as info:
        sb.PathSegment.line([0.0, 0.0], [0.0, 0.0])
    assert isinstance(info.value, ValueError)
    assert info.value.gt_code == 3
    assert sb._core.ge_geometry_code(3) == GeCode.COMMAND_ERROR and int(sb._core.ge_geometry_code(3)) == 1  # a duplicate look-ahead point (GE L3374)
    assert sb._core.guc_geometry_code(3) == GucCode.PARAMETER_ERROR


def test_card_refusal_carries_its_cause():
    card = sb.Card(4)
    card.axis_on(1)
    card.set_mode(1, "jog")
    card.stage_acc(1, 0.05)
    card.stage_vel(1, 2.0)
    card.update(0b10)
    card.step(20)
    with pytest.raises(sb.CardCommandRefused) as info:
        card.set_mode(1, "t_curve")
    assert info.value.fault == "mode_change_in_motion"
    assert info.value.axis == 1
    assert isinstance(info.value, RuntimeError)


def test_dialects_return_the_typed_codes():
    gt.GT_Open(sb.Card(4))
    assert gt.GT_MapAxis(1, [0, 0, 0, 0, 5]) == int(GtCode.MAP_AXIS_ERROR)  # maps to no coordinate (L1528, L408)
