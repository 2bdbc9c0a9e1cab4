"""The card kernel's Python face (issue 24 points 1 and 5): integer axis indices with one check, the public
``Card.kernel`` the dialects read through, and a card tick whose recorded error is the one its checks use."""

from __future__ import annotations

import re

import numpy as np
import pytest

import servobench as sb
from servobench import _core


def test_axis_arguments_are_integers_with_one_check():
    card = sb.Card(4)
    # every axis argument of the bindings reads `int` in its signature (none `float`)
    for name in ("axis_on", "stage_pos", "set_mode", "abrupt_stop", "following_error", "set_limits"):
        doc = getattr(_core.Card, name).__doc__
        assert re.search(r"axis: int", doc), (name, doc.splitlines()[0])
    assert "master: int" in _core.Card.set_gear.__doc__
    for bad in (4, -1, 1.5, float("nan")):
        with pytest.raises(ValueError, match=r"Card\.axis = .* (outside|not)"):
            card.axis_on(bad)
    card.axis_on(2.0)  # a whole float is still an axis, as before
    assert card.servo_on(2)


def test_kernel_is_public():
    card = sb.Card(4)
    assert isinstance(card.kernel, _core.Card)
    assert card.kernel.axis_count == 4
    assert _core.gt_axis_status(card.kernel, 0) == _core.gt_axis_status(card._card, 0)


def test_recorded_error_is_the_checked_error():
    card = sb.Card(4, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870))
    card.axis_on(0)
    card.stage_acc(0, 0.05)
    card.stage_vel(0, 2.0)
    card.stage_pos(0, 3000)
    card.update(1)
    run = card.run(500, signals=["error"])
    err = run[0].error
    assert np.all(np.isfinite(err)) and np.max(np.abs(err)) > 0
    assert card.following_error(0) == err[-1]
