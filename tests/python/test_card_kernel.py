"""The card kernel's Python face (issue 24 points 1 and 5): integer axis indices with one check, the public
``Card.kernel`` the dialects read through, and a card tick whose recorded error is the one its checks use."""

from __future__ import annotations

import numpy as np
import pytest

import servobench as sb
from servobench import _core


def test_axis_arguments_have_one_check():
    card = sb.Card(4)
    # the one check (cpp/bindings/card_axis.hpp) behind every card axis argument, in each binding file
    calls = [card.axis_on, card.smooth_stop, lambda i: card.set_gear(1, i), lambda i: card.capture_armed(i),
             lambda i: _core.gt_axis_status(card.kernel, i)]
    for call in calls:
        for bad in (4, -1, 1.5, float("nan")):
            with pytest.raises(ValueError, match=r"Card\.axis = .* (outside|not)"):
                call(bad)
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
