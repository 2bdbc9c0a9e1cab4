"""The relay binding's result (issue 24.4, decisions OR1-OR5, GZ8): its single figures come from the one C++
description (RelayTuneResult::describe, published as _core.RELAY_TUNE_FIELDS) in ``figures``, with no hand-written
top-level copies beside it; the top-level ``kp``/``ki``/``kd`` are the per-set arrays, not the means."""

from __future__ import annotations

import numpy as np

from servobench import _core
from servobench.examples import velocity_axis


def test_relay_dict_holds_each_figure_once():
    d = _core.relay_autotune(velocity_axis()._axis, _core.RelayTuneOptions(hysteresis_pulse=150, data_length=10))
    described = [f["name"] for f in _core.RELAY_TUNE_FIELDS]
    assert list(d["figures"]) == described
    assert {"kp_spread", "ultimate_freq_hz", "ultimate_gain_v_per_pulse", "sampling_time_s"} <= set(described)
    repeated = (set(d) - {"figures"}) & set(described)
    assert repeated == {"kp", "ki", "kd"}
    assert all(np.ndim(d[k]) == 1 and len(d[k]) == len(d["period_s"]) for k in repeated)  # one value per set
    assert len(d["kp"]) > 0 and np.isclose(d["figures"]["kp"], np.mean(d["kp"]))  # the figure is their mean
