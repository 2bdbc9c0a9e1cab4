"""The iDEABOX manual's FollowEx examples (seed 003 = ../shared/seeds/003_*.txt, ``Lnnn`` its lines) run as
printed, Structured Text -> Python syntax only, in program mode (examples/vendor_programs/ideabox_*.py), and reach
what the manual states (例程 4-1 L556-742, 例程 4-2 L746-929). The PLC program starts the motion in one task cycle;
the card then runs on (the PLC task has nothing more to do) and the test watches it. Each runs twice: bit-identical."""

import numpy as np
import pytest

from servobench.dialects import gts
from test_vendor_programs_guc import load


@pytest.fixture(autouse=True)
def _a_fresh_process():
    """Each program starts as in a fresh process: the module's default controller closed, no machine set (a test
    elsewhere may leave them; the vendor's open call then answers 'already open')."""
    gts.GT_Close()
    gts.use_machine(None)
    yield
    gts.GT_Close()
    gts.use_machine(None)


def run(stem, follow_ms):
    """main() against the program's machine, then ``follow_ms`` more of card time. Returns (main's code,
    GT_GetFollowLoopEx(2), GT_GetJogPrm(1), per tick (master profile position, slave profile position, slave actual
    position), the tick in ms)."""
    mod = load(stem)
    if gts.card() is not None:
        gts.GT_Close()
    rec = []

    def machine():
        card = mod.machine()
        card.on_event(lambda c, _e: rec.append((c.profile_pos(0), c.profile_pos(1), c.actual_pos(1))),
                      timer_ticks=1)
        return card

    gts.use_machine(machine)
    try:
        rtn = mod.main()
        gts.controller().run_ms(follow_ms)
        out = (rtn, gts.GT_GetFollowLoopEx(2), gts.GT_GetJogPrm(1), np.asarray(rec), gts.card().servo_period_s * 1e3)
    finally:
        gts.use_machine(None)
        gts.GT_Close()
    return out


def test_ideabox_ex4_1_percent_follow_starts_past_50000_and_gains_40000_per_pass():
    rtn, (rl, loops), (rj, jog), rec, tick_ms = run("ideabox_followex_percent", 3600)
    m, s, s_act = rec.T
    # the program's last call (GT_UpdateMx) succeeded; the jog acc is the one it set (L726-730)
    assert rtn == 0 and rj == 0 and jog.acc == 1
    # L558-562: the slave stays until the master has passed 50000 pulse (PASS event, positive direction)
    cross = int(np.argmax(m >= 50000))
    assert m[cross - 1] < 50000 and np.all(s[:cross] == 0) and s[cross + round(20 / tick_ms)] > 0
    # one pass = 60000 master pulses -> +40000 slave pulses (Table 4-2: 10000 + 1000 x 20 + 10000)
    k1 = int(np.argmax(m >= m[cross] + 60000))
    assert s[k1] == pytest.approx(40000, abs=2)
    # S curve in, 1:1 in the middle (the master's 50 pulse/ms), S curve out: ratio 0 at the pass ends
    mid = int(np.argmax(m >= m[cross] + 30000))
    assert s[mid + 1] - s[mid] == pytest.approx(m[mid + 1] - m[mid], abs=1)
    # the passes repeat (loop 0 = infinite, L7302): 3600 ms after the start at 50 pulse/ms -> at least 2 passes
    k2 = int(np.argmax(m >= m[cross] + 120000))
    assert k2 > 0 and s[k2] == pytest.approx(80000, abs=2) and rl == 0 and loops == 2
    assert np.abs(s - s_act).max() < 60  # the slave's drive tracks the cam


def test_ideabox_ex4_2_complete_follow_passes_every_knot():
    mod = load("ideabox_followex_complete")
    rtn, (rl, loops), _jog, rec, tick_ms = run("ideabox_followex_complete", 23500)
    m, s, s_act = rec.T
    assert rtn == 0
    # L748-750: the slave follows as soon as the master starts (START event), at ratio 1.0 (velRatioBegin)
    k0 = int(np.argmax(m > 0))
    assert np.all(s[:k0] == 0) and np.all(s[k0 + 10: k0 + 100] > 0)
    k = k0 + round(40 / tick_ms)                 # the first 40 ms: the slave moves as much as the master
    assert s[k] == pytest.approx(m[k], rel=0.01)
    # the slave passes every knot as the master passes its knot (cumulative from the curve start, M31); one tick
    # of the master (50 pulse/ms) times the ratio bounds the sampling error
    for mk, sk in zip(mod.lrMPos[1:], mod.lrSPos[1:]):
        k = int(np.argmax(m >= mk - mod.lrMPos[0]))
        assert s[k] == pytest.approx(sk - mod.lrSPos[0], abs=1.1 * 50 * tick_ms + 1), (mk, sk)
    assert np.all(np.diff(s[k0:]) >= 0)
    # one pass done after 1132347.6 master pulses (~22.7 s), the next one runs (loop 0 = infinite)
    assert rl == 0 and loops == 1
    assert np.abs(s - s_act).max() < 60


@pytest.mark.parametrize("stem,ms", [("ideabox_followex_percent", 1500), ("ideabox_followex_complete", 1500)])
def test_ideabox_programs_twice_bit_identical(stem, ms):
    a, b = run(stem, ms), run(stem, ms)
    assert a[:3] == b[:3] and np.array_equal(a[3], b[3])
