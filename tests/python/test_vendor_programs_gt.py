"""The GT manual's programs (examples/vendor_programs/gt_*.py, seed 000) run as printed, in program mode, against
their simulated machine; each test asserts what the manual says the program achieves (Lnnn = the seed's lines)
and that a second run gives bit-identical results. A program that would poll forever fails quickly: every GT call
of the program goes through a guard that stops it once the card has run a tick budget."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

import pytest

from servobench.dialects import gt

PROGRAMS = Path(__file__).resolve().parents[2] / "examples" / "vendor_programs"


@pytest.fixture(autouse=True)
def _a_fresh_process():
    """Each program starts as in a fresh process: the module's default controller closed, no machine set (a test
    elsewhere may leave them; the vendor's open call then answers 'already open')."""
    gt.GT_Close()
    gt.use_machine(None)
    yield
    gt.GT_Close()
    gt.use_machine(None)


class ProgramRanTooLong(BaseException):
    """Raised by the guard (a BaseException, so no vendor-call guard turns it into a return code)."""


def load(name: str):
    if str(PROGRAMS) not in sys.path:
        sys.path.insert(0, str(PROGRAMS))
    return importlib.import_module(name)


@pytest.fixture
def run_program(monkeypatch):
    """Runs ``module.main()`` against ``module.machine`` with every GT_* name the program (and _gt_init) calls
    guarded by a budget of card ticks; returns the machine's cards and the calls' return codes."""

    def run(name: str, max_ticks: int = 2_000_000):
        program, init = load(name), load("_gt_init")
        codes, values = [], []
        for mod in (program, init):
            for attr in [a for a in vars(mod) if a.startswith("GT_")]:
                fn = getattr(mod, attr)
                fn = getattr(fn, "guard_of", fn)          # a second run wraps the program's own function again

                def guarded(*args, _fn=fn, _name=attr):
                    c = gt.card()
                    if c is not None and c.tick > max_ticks:
                        raise ProgramRanTooLong(f"{name}: still polling after {max_ticks} ticks ({_name})")
                    out = _fn(*args)
                    codes.append((_name, out if isinstance(out, int) else out[0]))
                    if not isinstance(out, int):
                        values.append((_name, out[1]))
                    return out

                guarded.guard_of = fn
                monkeypatch.setattr(mod, attr, guarded)
        cards = []
        gt.use_machine(lambda: cards.extend(init.machine()) or cards)
        try:
            program.main()
        finally:
            gt.use_machine(None)
        return cards, codes, values

    yield run
    gt.GT_Close()


def snapshot(cards) -> list:
    return [(c.tick, [a.feedback_pulse for a in c.axes], [c.profile_pos(k) for k in range(4)]) for c in cards]


def test_example_6_1_home_index_reaches_the_index_and_zeroes_it(run_program):
    cards, codes, values = run_program("gt_home_index_6_1")
    first = snapshot(cards)
    init = load("_gt_init")
    # every call of Examples 3-3/3-4/3-6 and 6-1 returned 0: SwitchtoCardNo(1) found card 1, SetSmplTm(200) is its
    # period, EncSns(0xF) corrects the machine's reversed encoders, CtrlMode(1) / StepDir / StepPulse act on the
    # pulse axes 3 and 4 (L760-766)
    assert [c for c in codes if c[1] != 0] == []
    assert gt.GT_GetCurrentCardNo() == 1 and gt.card() is cards[1]
    assert {"GT_SwitchtoCardNo", "GT_SetSmplTm", "GT_EncSns", "GT_StepDir", "GT_StepPulse"} <= {c[0] for c in codes}
    # home(200000) on card 1 axis 1: Home captured at the switch's edge (+-1 pulse, L2015), then the first Index
    # mark 8000 pulse past it: marks at 2000 + 8000 k, the first past 30000 is 34000; the axis stands there and
    # reads 0 (L2017, L2079-2080)
    edge, idx = init.HOME_EDGE, init.HOME_EDGE + (init.INDEX_AT - init.HOME_EDGE) % init.COUNTS_PER_REV
    assert idx == 34000
    gt.GT_Axis(1)
    assert gt.GT_GetPos() == (0, 0) and gt.card().profile_pos(0) == 0
    assert not gt.GT_GetSts()[1] & 0x400                             # not moving (bit 0 was cleared, L2079)
    # the program zeroes as soon as the profile ends (L2080): the stiff axis stands on the Index mark then, and
    # actual and target read 0 there; it stays
    assert abs(cards[1].axes[0].feedback_pulse - idx) <= 1 and abs(gt.GT_GetAtlPos()[1]) <= 1
    gt.delay(500)
    rtn, atl = gt.GT_GetAtlPos()
    assert rtn == 0 and abs(atl) <= 1
    assert abs(cards[1].axes[0].feedback_pulse - idx) <= 1
    # the captures the program read: Home at the switch's edge, Index at the mark, +-1 pulse (L2015)
    capt = [v for name, v in values if name == "GT_GetCapt"]
    assert len(capt) == 2 and abs(capt[0] - edge) <= 1 and abs(capt[1] - idx) <= 1
    # the other card of the PC was never commanded: its axes stand at 0, drives off
    assert all(cards[0].axes[k].feedback_pulse == 0 and not cards[0].servo_on(k) for k in range(4))
    # program mode: the polling loops ended after the simulated time the motion takes (30000 pulse at 4 pulse/ST
    # = 7500 ST at the least), and the card ran no longer than the calls' bus time and the motions
    assert 7500 < cards[1].tick < 40000
    assert edge == 30000
    gt.GT_Close()
    cards2, codes2, _ = run_program("gt_home_index_6_1")
    assert snapshot(cards2) == first and codes2 == codes              # same program, same result, bit for bit


def follow_to_the_end(card):
    """The host's loop after the program: every ms the profile velocity and actual position, until bit 10 clears."""
    vel, pos = [], []
    while gt.GT_GetSts()[1] & 0x400:
        gt.delay(1)
        vel.append(card.profile_vel(0))
        pos.append(gt.GT_GetAtlPos()[1])
        assert len(vel) < 20000
    return vel, pos


def test_example_4_7_breakpoint_changes_the_velocity_at_20000(run_program):
    cards, codes, _ = run_program("gt_breakpoint_4_7")
    assert [c for c in codes if c[1] != 0] == []
    card = cards[1]
    at_end = snapshot(cards)
    gt.GT_Axis(1)
    assert gt.GT_GetMode()[1] & 0x400                                # auto-update at a breakpoint on (L1261)
    # the program ended with the axis moving at 1 pulse/ST toward 50000; the card goes on
    vel, pos = follow_to_the_end(card)
    # before the breakpoint 1 pulse/ST, after it 4 pulse/ST (L1267); the switch came at actual >= 20000 (L1263)
    k = next(i for i, v in enumerate(vel) if v > 1.0 + 1e-9)
    assert vel[k - 1] == pytest.approx(1.0) and pos[k - 1] < 20000 and pos[k] >= 20000
    assert max(vel) == pytest.approx(4.0)
    assert gt.GT_GetSts()[1] & 0x4                                   # breakpoint triggered (L1263)
    assert card.profile_pos(0) == 50000 and abs(gt.GT_GetAtlPos()[1] - 50000) <= 100
    gt.GT_Close()
    cards2, _, _ = run_program("gt_breakpoint_4_7")
    assert snapshot(cards2) == at_end
    gt.GT_Axis(1)
    assert follow_to_the_end(cards2[1]) == (vel, pos)


def test_a_program_that_polls_forever_fails_quickly(run_program, monkeypatch):
    # the capture loop of home() (L2034-2039) on an axis whose capture was never armed: status bit 3 never comes;
    # the guard stops the program after its tick budget instead of hanging the suite
    program = load("gt_home_index_6_1")

    def home(pos):
        while not (program.GT_GetSts()[1] & 0x8):
            pass

    monkeypatch.setattr(program, "home", home)
    with pytest.raises(ProgramRanTooLong):
        run_program("gt_home_index_6_1", max_ticks=20_000)
