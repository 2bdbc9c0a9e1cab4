"""The GUC-ECAT manual's programs (seed 002 = ../shared/seeds/002_*.txt, ``Lnnn`` its lines) run as printed, C/ST
-> Python syntax only, in program mode (examples/vendor_programs/guc_*.py), and reach what the manual states:
the hexagon with buffered IO and delays (L736-857, Fig 4-5) and the motion-program additions in one and in two
threads (§5.2.3, L2262-2535). Each program runs twice: the same result bit for bit (program mode is deterministic).
A program that polls forever fails fast: the machine carries a tick budget."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from servobench.dialects import gts

PROGRAMS = Path(__file__).resolve().parents[2] / "examples" / "vendor_programs"


@pytest.fixture(autouse=True)
def _a_fresh_process():
    """Each program starts as in a fresh process: the module's default controller closed, no machine set (a test
    elsewhere may leave them; the vendor's open call then answers 'already open')."""
    gts.GT_Close()
    gts.use_machine(None)
    yield
    gts.GT_Close()
    gts.use_machine(None)


class TickBudgetExceeded(RuntimeError):
    pass


def load(stem):
    spec = importlib.util.spec_from_file_location(stem, PROGRAMS / f"{stem}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def run(stem, budget_ticks, record=None):
    """Runs ``main()`` of the program against its ``machine()`` (use_machine, as its ``__main__`` does); every
    tick ``record(card)`` may sample the card; past ``budget_ticks`` the run fails. Returns (main's result,
    samples, the card)."""
    mod = load(stem)
    if gts.card() is not None:
        gts.GT_Close()
    samples = []

    def machine():
        card = mod.machine()

        def guard(c, _ev):
            if record is not None:
                samples.append(record(c))
            if c.tick > budget_ticks:
                raise TickBudgetExceeded(f"{stem}: still running after {budget_ticks} ticks")

        card.on_event(guard, timer_ticks=1)
        return card

    gts.use_machine(machine)
    try:
        out = mod.main()
        card = gts.card()
    finally:
        gts.use_machine(None)
    gts.GT_Close()
    return out, samples, card


HEX = [(200000, 0), (100000, 173205), (-100000, 173205), (-200000, 0), (-100000, -173205), (100000, -173205),
       (200000, 0)]


def hexagon_record(card):
    if not card.group_info(0)["set_up"]:  # before GT_SetCrdPrm
        return (np.nan, np.nan, 0.0, 0)
    return (*card.crd_pos(1), card.crd_vel(1), card.crd(1).fifo(0).state.gpo)


def test_guc_hexagon_with_buffered_io_draws_the_hexagon_and_sets_the_outputs_in_place():
    (rtn, run_, segment, space), rec, card = run("guc_hexagon_bufio", 150000, hexagon_record)
    tick_ms = card.servo_period_s * 1e3  # one sample per tick
    # L855-857: run 0 at the end, 7 segments done; 12 entries (7 lines, 3 BufIO, 2 BufDelay) of 4096 (L796)
    assert (rtn, run_, segment) == (0, 0, 7)
    assert space == 4096 - 12
    rec = np.asarray(rec)
    x, y, v, do = rec.T
    assert (x[-1], y[-1]) == (200000, 0)
    assert (card.profile_pos(0), card.profile_pos(1)) == (200100, 100)  # origin at profile (100, 100) (L760-762)
    # Fig 4-5: the path reaches the hexagon's vertices in order
    arrive, k = [], 0
    for vx, vy in HEX:
        k += int(np.argmax((np.round(x[k:]) == vx) & (np.round(y[k:]) == vy)))
        assert round(x[k]) == vx and round(y[k]) == vy, (vx, vy)
        arrive.append(k)
    # every line: 200000 pulse at 100 pulse/ms, 0.1 pulse/ms^2 -> 1000 ms up, 1000 at speed, 1000 down = 3000 ms
    # the buffered delays add 400 ms after line 4 and 100 ms after line 5
    legs_ms = np.diff(arrive) * tick_ms
    np.testing.assert_allclose(legs_ms, [3000, 3000, 3000, 3400, 3100, 3000], atol=2)
    at_rest = [np.sum((np.round(x) == vx) & (np.round(y) == vy) & (v == 0)) * tick_ms for vx, vy in HEX[3:5]]
    assert at_rest == pytest.approx([400, 100], abs=2)
    # the buffered outputs at their places in the FIFO: 0x55 after line 2, 0xaa after line 3, 0x55 after line 5
    # (a vertex rounds to its whole pulses 0.5 pulse, sqrt(2 x 0.5 / 0.1) = 3.2 ms, before the line ends)
    changes = [(k, int(do[k])) for k in range(1, len(do)) if do[k] != do[k - 1]]
    assert [w for _k, w in changes] == [0x55, 0xAA, 0x55]
    # ... when lines 2, 3 and 5 end: 6000, 9000 and 3000 x 5 + 400 = 15400 ms after the start; the path ends at
    # 7 x 3000 + 500 = 21500 ms
    start, stop = int(np.argmax(v > 0)), int(np.flatnonzero(v > 0)[-1]) + 1
    assert [(k - start) * tick_ms for k, _w in changes] == pytest.approx([6000, 9000, 15400], abs=1)
    assert (stop - start) * tick_ms == pytest.approx(21500, abs=1)
    assert all(0 <= (k - arrive[i]) * tick_ms <= 4 for (k, _w), i in zip(changes, (1, 2, 4)))
    assert do[-1] == 0x55


def test_guc_hexagon_twice_bit_identical():
    a = run("guc_hexagon_bufio", 150000, hexagon_record)
    b = run("guc_hexagon_bufio", 150000, hexagon_record)
    assert a[0] == b[0] and np.array_equal(np.asarray(a[1]), np.asarray(b[1]))


def test_guc_motion_program_addition_single_thread_sums_1_to_100():
    (rtn, thread, value), _rec, card = run("guc_motion_sum", 1000)
    # L2264: the thread adds begin..end (1..100) into the global sum and ends; add returns sum
    assert rtn == 0 and value == 5050
    assert (thread.run, thread.error, thread.result) == (0, 0, 5050.0)
    # the function runs to its end in the tick its thread starts: the PLC loop sees it ended after one cycle (1 ms)
    assert card.tick * card.servo_period_s * 1e3 <= 1.0 + 0.5


def test_guc_motion_program_addition_two_threads_sum_1_to_100():
    (rtn, t0, t1, value), _rec, _card = run("guc_motion_sum_threads", 1000)
    # L2408: two threads of the same function on data pages 0 (1..50) and 1 (51..100) complete the addition
    assert rtn == 0 and value == 5050
    assert (t0.run, t1.run) == (0, 0)
    assert t0.result == sum(range(1, 51)) and t1.result == 5050  # thread 0 runs first in the tick (thread order)


@pytest.mark.parametrize("stem", ["guc_motion_sum", "guc_motion_sum_threads"])
def test_guc_motion_programs_twice_bit_identical(stem):
    a, b = run(stem, 1000), run(stem, 1000)
    assert repr(a[0]) == repr(b[0]) and a[2].tick == b[2].tick


def test_a_program_polling_forever_fails_fast(tmp_path):
    # the guard: a motion program whose thread never ends keeps the sum example's PLC loop polling; the budget
    # stops it
    prog = tmp_path / "sum.py"
    prog.write_text("sum = 0\n\ndef add(begin, end):\n    while True:\n        yield\n", encoding="utf-8")
    mod = load("guc_motion_sum")
    mod.HERE = tmp_path
    (tmp_path / "guc_motion").mkdir()
    (tmp_path / "guc_motion" / "sum.py").write_text(prog.read_text(encoding="utf-8"), encoding="utf-8")
    if gts.card() is not None:
        gts.GT_Close()

    def machine():
        card = mod.machine()
        card.on_event(lambda c, _e: (_ for _ in ()).throw(TickBudgetExceeded()) if c.tick > 200 else None,
                      timer_ticks=1)
        return card

    gts.use_machine(machine)
    try:
        with pytest.raises(TickBudgetExceeded):
            mod.main()
    finally:
        gts.use_machine(None)
        gts.GT_Close()
