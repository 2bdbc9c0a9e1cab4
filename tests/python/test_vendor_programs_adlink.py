"""The ADLINK manual's example programs (examples/vendor_programs/adlink_*.py, issue 25.2) run in program mode
against their simulated machines, and reach what the manual states. `Lnnnn` = lines of the ADLINK PCI-8254/8258
manual (seed 004). Each program runs twice from a fresh machine: program mode is deterministic, so both runs give
bit-identical results. A program whose polling never ends fails fast: the guard below bounds its Sleep calls."""

import importlib.util
from pathlib import Path

import pytest

from servobench import _core
from servobench.dialects import aps

PROGRAMS = Path(__file__).resolve().parents[2] / "examples" / "vendor_programs"
TS = 250e-6   # the machines' servo period (L1733)


@pytest.fixture(autouse=True)
def _a_fresh_process():
    """Each program starts as in a fresh process: the module's default controller closed, no machine set (a test
    elsewhere may leave them; the vendor's open call then answers 'already open')."""
    aps.APS_close()
    aps.use_machine(None)
    yield
    aps.APS_close()
    aps.use_machine(None)


def load(stem):
    spec = importlib.util.spec_from_file_location(stem, PROGRAMS / f"{stem}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


class Guard:
    """Wraps the default controller's Sleep: records (tick, profile velocities pulse/s, status word of axis 0)
    after each Sleep and stops a program that sleeps more than `max_sleeps` times (an endless poll)."""

    def __init__(self, monkeypatch, max_sleeps=1000):
        self.ctl = aps.controller()
        self.inner = type(self.ctl).Sleep.__get__(self.ctl)   # the dialect's own Sleep (not an earlier guard's)
        self.log = []
        self.max_sleeps = max_sleeps
        monkeypatch.setattr(self.ctl, "Sleep", self.sleep)

    def sleep(self, ms):
        if len(self.log) >= self.max_sleeps:
            raise AssertionError(f"the program slept {len(self.log)} times: its wait loop does not end")
        r = self.inner(ms)
        c = self.ctl.card
        # read through the card, not through an APS call: a vendor call would cost bus time and shift the program
        self.log.append((c.tick, [c.profile_vel(i) / TS for i in range(2)],
                         int(_core.aps_group_motion_status(c.kernel, 0))))
        return r


def run_program(stem, monkeypatch, settle_ms=0, max_sleeps=1000):
    """Runs a program's main() as its __main__ does (use_machine + main()); lets the card run settle_ms more;
    returns (module, main's return value, the guard, the final snapshot)."""
    mod = load(stem)
    guard = Guard(monkeypatch, max_sleeps)
    aps.use_machine(mod.machine)
    try:
        out = mod.main()
        if settle_ms:
            guard.inner(settle_ms)
        c = aps.card()
        snap = {"tick": c.tick, "cmd": [aps.APS_get_command(i)[1] for i in range(4)],
                "fbk": [aps.APS_get_position(i)[1] for i in range(4)],
                "msts": [aps.APS_motion_status(i) for i in range(4)],
                "stop": [aps.APS_get_stop_code(i)[1] for i in range(4)], "log": list(guard.log)}
    finally:
        aps.APS_close()
        aps.use_machine(None)
    return mod, out, guard, snap


def bit(word, b):
    return (word >> b) & 1


def test_adlink_home_move_example_waits_for_the_end_of_homing_and_homes(monkeypatch):
    _mod, _out, guard, s = run_program("adlink_home_move_example", monkeypatch)
    # the wait loop (L2312-2317) ran while homing ran: every status it read but the last had NSTP and HMV set
    words = [w for _t, _v, w in s["log"]]
    assert len(words) >= 3
    assert all(bit(w, aps.MTS_NSTP) and bit(w, aps.MTS_HMV) for w in words[:-1])
    assert not bit(words[-1], aps.MTS_NSTP) and not bit(words[-1], aps.MTS_HMV) and bit(words[-1], aps.MTS_MDN)
    # "Homing success" (L2319-2326): ASTP clear, stop code normal; command and feedback reset to HOME_POS = 0
    # (L2252, L2278) at the ORG edge on the PEL side (start case C, L2366-2372)
    m = s["msts"][0]
    assert not bit(m, aps.MTS_ASTP) and bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_HMV)
    assert s["stop"][0] == aps.STOP_NORMAL
    assert s["cmd"][0] == 0 and abs(s["fbk"][0]) <= 2
    # the loop ended within one Sleep(100) of the end of homing: the poll before the last still saw it running
    assert s["log"][-1][0] - s["log"][-2][0] == pytest.approx(0.1 / TS, abs=1)
    _mod, _out, _g, again = run_program("adlink_home_move_example", monkeypatch)
    assert again == s                                       # program mode: bit-identical


def test_adlink_home_move_example_read_as_mdn_would_exit_while_homing(monkeypatch):
    # The finding, kept as a check of the constant: MTS_NSTP is not MDN. With the MDN bit the loop's test
    # `(msts >> bit) & 1 == 1` is false at the first poll (homing runs, MDN = 0) and the program reports success
    # while HMV is still set.
    assert aps.MTS_NSTP != aps.MTS_MDN and aps.MTS_NSTP == 7
    _mod, _out, _guard, s = run_program("adlink_home_move_example", monkeypatch)
    first = s["log"][0][2]
    assert bit(first, aps.MTS_HMV) and not bit(first, aps.MTS_MDN) and bit(first, aps.MTS_NSTP)


def test_adlink_velocity_move_example_runs_each_speed_and_stops(monkeypatch):
    _mod, _out, guard, s = run_program("adlink_velocity_move_example", monkeypatch, settle_ms=1000)
    # after each Sleep(2000): the speed set 2 s before (L2620-2626), reached and held (ACC 10000, S 0.5)
    speeds = [round(v[0], 6) for _t, v, _w in s["log"]]
    assert speeds == pytest.approx([500.0, 1000.0, 600.0], abs=1e-6)
    ticks = [t for t, _v, _w in s["log"]]
    assert [b - a for a, b in zip(ticks, ticks[1:])] == [pytest.approx(2.0 / TS, abs=1)] * 2
    # stopped by deceleration (L2627): at rest, motion done, normal stop; the command moved on with the velocity
    # (L2634): 500 + 1000 + 600 pulse/s for 2 s each, less the ramps, plus the stop ramp
    m = s["msts"][0]
    assert bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_NSTP) and not bit(m, aps.MTS_ASTP)
    assert s["stop"][0] == aps.STOP_NORMAL
    assert 4150 < s["cmd"][0] < 4250                                # 2 s each at 500, 1000, 600: 4200, +- ramps
    _mod, _out, _g, again = run_program("adlink_velocity_move_example", monkeypatch, settle_ms=1000)
    assert again == s


def test_adlink_simultaneous_move_example_starts_both_axes_together(monkeypatch):
    mod = load("adlink_simultaneous_move_example")
    aps.use_machine(mod.machine)
    try:
        assert mod.main() == aps.ERR_NoError                  # APS_move_trigger's code (L3789)
        c = aps.card()
        assert c.tick == 0                                    # three calls of 10 us: within the first servo tick
        aps.Sleep(5)
        # started in the same servo tick (L3789): identical profiles until axis 0 decelerates
        assert c.profile_pos(0) == c.profile_pos(1) > 0
        assert not bit(aps.APS_motion_status(0), aps.MTS_WAIT) and not bit(aps.APS_motion_status(1), aps.MTS_WAIT)
        aps.Sleep(1000)
        # each at its own target (L2566: "the end time varies")
        assert [aps.APS_get_command(i)[1] for i in (0, 1)] == [10000, 20000]
        assert all(bit(aps.APS_motion_status(i), aps.MTS_MDN) for i in (0, 1))
        first = (c.tick, [c.profile_pos(i) for i in range(2)])
    finally:
        aps.APS_close()
    try:
        assert mod.main() == aps.ERR_NoError
        aps.Sleep(5)
        aps.Sleep(1000)
        c = aps.card()
        assert (c.tick, [c.profile_pos(i) for i in range(2)]) == first
    finally:
        aps.APS_close()
        aps.use_machine(None)


def test_adlink_pt_move_example_runs_the_line_of_the_point_table(monkeypatch):
    _mod, _out, guard, s = run_program("adlink_pt_move_example", monkeypatch, settle_ms=1000)
    # the buffer point was executed (L3870-3872): both axes at (10000, 10000), the table done
    assert s["cmd"][:2] == [10000, 10000]
    assert all(bit(s["msts"][i], aps.MTS_MDN) and not bit(s["msts"][i], aps.MTS_PTB) for i in (0, 1))
    assert all(abs(s["fbk"][i] - 10000) <= 2 for i in (0, 1))
    _mod, _out, _g, again = run_program("adlink_pt_move_example", monkeypatch, settle_ms=1000)
    assert again == s


def test_adlink_pt_move_example_moves_as_a_point_table(monkeypatch):
    # while it runs: MTS PTB on, MDN off (L3656), and the status shows one point in use, working (PTSTS b0)
    mod = load("adlink_pt_move_example")
    aps.use_machine(mod.machine)
    try:
        mod.main()
        aps.Sleep(20)
        m = aps.APS_motion_status(0)
        assert bit(m, aps.MTS_PTB) and not bit(m, aps.MTS_MDN) and bit(m, aps.MTS_NSTP)
        rtn, st = aps.APS_get_pt_status(0, 0)
        assert rtn == 0 and st.BitSts & aps.PTB_WORKING and st.PntBufUsageSpace == 1 and st.RunningCnt == 1
        assert st.PntBufFreeSpace == aps.PT_BUFFER_POINTS - 1
    finally:
        aps.APS_close()
        aps.use_machine(None)
