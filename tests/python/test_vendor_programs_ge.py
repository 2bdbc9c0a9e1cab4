"""The GE manual's programs (examples/vendor_programs/ge_*.py, seed 001) run as printed, in program mode, against
their simulated machine; each test asserts what the manual says the program achieves (Lnnn = the seed's lines)
and that a second run gives bit-identical results. Every GE call of a program goes through a guard that stops it
once the card has run a tick budget, so a program that would poll forever fails quickly."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

import numpy as np
import pytest

from servobench import card_io
from servobench.dialects import ge

PROGRAMS = Path(__file__).resolve().parents[2] / "examples" / "vendor_programs"


@pytest.fixture(autouse=True)
def _a_fresh_process():
    """Each program starts as in a fresh process: the module's default controller closed, no machine set (a test
    elsewhere may leave them; the vendor's open call then answers 'already open')."""
    ge.GT_Close()
    ge.use_machine(None)
    yield
    ge.GT_Close()
    ge.use_machine(None)


class ProgramRanTooLong(BaseException):
    """Raised by the guard (a BaseException, so no vendor-call guard turns it into a return code)."""


def load(name: str):
    if str(PROGRAMS) not in sys.path:
        sys.path.insert(0, str(PROGRAMS))
    return importlib.reload(importlib.import_module(name))


def guard(monkeypatch, module, controller, max_ticks):
    """Every GT_* / delay name of `module` checks the card's tick budget before the call."""
    for attr in [a for a in vars(module) if a.startswith("GT_") or a == "delay"]:
        fn = getattr(module, attr)

        def guarded(*args, _fn=fn, _name=attr):
            c = controller.card
            if c is not None and c.tick > max_ticks:
                raise ProgramRanTooLong(f"{module.__name__}: still polling after {max_ticks} ticks ({_name})")
            return _fn(*args)

        monkeypatch.setattr(module, attr, guarded)


def run_5_1(monkeypatch):
    program = load("ge_trapezoid_5_1")
    guard(monkeypatch, program, ge.controller(), 10**6)
    ge.use_machine(program.machine)
    try:
        program.main()
    finally:
        ge.use_machine(None)
    card = ge.card()
    # the program ends after AxisRunT's Update; the host waits on the card, as a program would: every ms the
    # profile velocity and the card's time (ms since the Update), until bit 10 clears
    t0 = card.tick
    vel = []
    while ge.GT_GetSts(1)[1] & 0x400:
        ge.delay(1)
        vel.append(((card.tick - t0) * 0.2, ge.GT_GetPrfVel(1)[1]))
        assert len(vel) < 5000
    ge.delay(300)
    return program, card, vel


def test_example_5_1_trapezoid_reaches_200000_at_166_7_pulse_per_ms(monkeypatch):
    program, card, vel = run_5_1(monkeypatch)
    try:
        assert program.errors == []                                      # CommandHandle reported nothing
        assert ge.GT_GetPos(1) == (0, 200000) and ge.GT_GetVel(1) == (0, 166.7) and ge.GT_GetAcc(1) == (0, 4)
        assert ge.GT_GetPrfPos(1) == (0, 200000)                          # 200 mm at 1 um/pulse (L1006-1008)
        assert abs(ge.GT_GetAtlPos(1)[1] - 200000) <= 2
        t_ms, v = np.asarray(vel).T
        assert v.max() == pytest.approx(166.7)                            # 10 m/min (L1003-1005)
        # accelerate, hold, decelerate (L1052-1062): 166.7 / 4 = 41.7 ms each way, 200000 / 166.7 + 41.7 ms in all
        # (the host samples every 1.04 ms: a 1 ms delay and two 20 us calls)
        assert t_ms[-1] == pytest.approx(200000 / 166.7 + 166.7 / 4, abs=1.1)
        assert t_ms[np.flatnonzero(v >= 166.7 - 1e-9)[0]] == pytest.approx(166.7 / 4, abs=1.1)
        assert np.all(np.diff(v[v < 166.7 - 1e-9][:30]) > 0)             # the ramp up is monotonic
        first = (card.tick, card.axes[0].feedback_pulse, vel)
    finally:
        ge.GT_Close()
    _p, card2, vel2 = run_5_1(monkeypatch)
    try:
        assert (card2.tick, card2.axes[0].feedback_pulse, vel2) == first  # bit for bit
    finally:
        ge.GT_Close()


def run_7_1(monkeypatch, max_ticks=10**6):
    program = load("ge_home_7_1")            # a fresh module: its own SX library object (lib)
    guard(monkeypatch, program, program.lib, max_ticks)
    log = []
    handler = program.CommandHandle
    monkeypatch.setattr(program, "CommandHandle", lambda command, error: (log.append((command, error)),
                                                                          handler(command, error))[1])
    program.lib.use_machine(program.machine)
    program.main()
    return program, program.lib.card, log


def test_example_7_1_home_stops_1000_pulse_past_the_home_signal_and_zeroes(monkeypatch):
    program, card, log = run_7_1(monkeypatch)
    lib = program.lib
    assert program.printed == [] and log and all(err == 0 for _c, err in log), [e for e in log if e[1]]
    # the table entered the Home switch at -2000 on its way to -1000000; it came back there and went 1000 pulse
    # further (toward +), settled, and that place is the machine's zero (L2053-2069)
    assert abs(card.axes[0].feedback_pulse - (program.HOME_EDGE + 1000)) <= 2
    assert card.profile_pos(0) == 0 and abs(lib.GT_GetAtlPos(1)[1]) <= 2
    assert lib.GT_GetCrdSts()[1] & 1                                     # no path motion
    first = (card.tick, card.axes[0].feedback_pulse)
    _p, card2, _log = run_7_1(monkeypatch)
    assert (card2.tick, card2.axes[0].feedback_pulse) == first


def test_example_7_1_without_a_home_switch_returns_1(monkeypatch):
    # Home's first loop (L2142-2150): the path ends (crd bit 0) with no Home signal: Home returns 1 (main then
    # prints "Home Error !", L2188-2191); a 20000-pulse search instead of the manual's 1000000 keeps it short
    import servobench as sb

    program = load("ge_home_7_1")
    guard(monkeypatch, program, program.lib, 10**6)

    def no_switch():
        card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True), drive=sb.ServoPositionDrive(),
                       servo_period_s=200e-6)
        card.set_clock("program")
        return card

    program.lib.use_machine(no_switch)
    program.GT_HookCommand(program.CommandHandle)
    assert [program.GT_Open(), program.GT_Reset()] == [0, 0]
    program.AxisInitial(1, 0)
    assert program.Home(1, -20000, 1000, 20, 2) == 1
    assert program.lib.card.profile_pos(0) == -20000 and program.printed == []


def run_10_4(monkeypatch):
    program = load("ge_adc_10_4")
    guard(monkeypatch, program, ge.controller(), 10**5)
    cards = []
    ge.use_machine(lambda: cards.append(program.machine()) or cards[-1])
    try:
        program.main()
    finally:
        ge.use_machine(None)
    return program, cards[0]


def test_example_10_4_reads_channel_1_as_table_10_4_says(monkeypatch):
    program, card = run_10_4(monkeypatch)
    # 5 V on channel 1: 2048 x 5 / 10 = 1024 counts (Table 10-4: +10 V 2047, 0 V 0, -10 V -2048)
    assert program.CHANNEL_1_VOLTS == 5.0 and program.out == ["\n Channel 1 Voltage : 1024"]
    assert ge.card() is not card                                         # GT_Close closed it
    program2, card2 = run_10_4(monkeypatch)
    assert program2.out == program.out and card2.tick == card.tick


def run_10_6(monkeypatch):
    program = load("ge_spindle_10_6")
    guard(monkeypatch, program, program.lib, 10**6)
    seen = []

    def machine():
        card = program.machine()
        # the machine's spindle amplifier sees the output every 100 ms
        card.on_event(lambda c, _f: seen.append((c.tick, card_io.of(c).spindle_volts)), timer_ticks=500)
        return card

    program.lib.use_machine(machine)
    program.main()
    return program, seen


def test_example_10_6_spindle_at_10_v_for_10_s_then_off(monkeypatch):
    program, seen = run_10_6(monkeypatch)
    assert program.out == ["\n GT_SetSpindleVel OK!", "\n GT_ CloseSpindle OK!"]
    volts = [v for _t, v in seen]
    assert len(volts) == 100 and all(v == pytest.approx(10.0, abs=1e-3) for v in volts)   # +10 V for 10 s
    assert program.lib.card is None                                      # GT_Close
    assert run_10_6(monkeypatch)[1] == seen                              # bit for bit
