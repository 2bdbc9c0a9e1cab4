"""The GUC-ECAT motion program (seed 002 Chapter 5, L2100-2560; decisions GS13-GS14): compile, download, function
and variable ids, threads bound to functions and data pages that run on the card's servo ticks beside the
application program, their status, pause / resume / stop, and the variables the application reads and writes.
The manual's own examples (additions in one and two threads) are examples/vendor_programs/guc_motion_sum*.py."""

import pytest

from servobench.dialects.gts import GtsController, TCompileInfo, TThreadSts, TVarInfo
from test_card_modes import LAW, TS, gts, tick_of_ms  # noqa: F401 (gts: the fixture)

PROGRAM = '''
count = 0
flag = 0
done = 0


def mover(axis, target):
    global count
    GT_PrfTrap(axis)
    GT_SetTrapPrm(axis, 1)
    GT_SetVel(axis, 10)
    GT_SetPos(axis, target)
    GT_UpdateMx(1, 1 << (axis - 1))
    while True:
        rtn, sts = GT_GetSts(axis)
        if not sts & 0x400:
            break
        count = count + 1
        yield
    return target


def waiter(n):
    global done
    while not flag:
        yield
    k = 0
    while k < n:
        k = k + 1
        yield
    done = k
    return k


def bad():
    return 1 / 0
'''


@pytest.fixture
def prog(gts, tmp_path):
    path = tmp_path / "prog.py"
    path.write_text(PROGRAM, encoding="utf-8")
    rtn, info = gts.GT_Compile(str(path))
    assert rtn == 0 and info == TCompileInfo(fileName=str(path))
    assert gts.GT_Download(str(tmp_path / "prog.bin")) == 0
    return gts


def test_function_and_variable_ids_guc_l2150_2166(prog):
    assert [prog.GT_GetFunId(n) for n in ("mover", "waiter", "bad", "nope")] == [(0, 1), (0, 2), (0, 3), (1, 0)]
    assert prog.GT_GetVarId(0, "count") == (0, TVarInfo(id=0, function="", name="count"))
    assert prog.GT_GetVarId(None, "done")[1].id == 2
    assert prog.GT_GetVarId("mover", "target") == (0, TVarInfo(id=1, function="mover", name="target"))
    assert prog.GT_GetVarId("mover", "nope")[0] == 1 and prog.GT_GetVarId("nope", "x")[0] == 1
    assert prog.GT_GetVarId(0, "GT_Update")[0] == 1          # the library is not a variable


def test_a_thread_runs_a_motion_function_on_the_card_ticks_guc_l2170_2213(prog):
    _, axis = prog.GT_GetVarId("mover", "axis")
    _, count = prog.GT_GetVarId(0, "count")
    assert prog.GT_Bind(0, 1, 0) == 0
    assert prog.GT_SetVarValue(0, axis, [1, 2000], 2) == 0       # axis, target: consecutive locals
    assert prog.GT_GetVarValue(0, axis, 2) == (0, [1, 2000])
    assert prog.GT_GetThreadSts(0) == (0, TThreadSts())
    assert prog.GT_RunThread(0) == 0
    assert prog.GT_GetThreadSts(0)[1].run == 1 and prog.GT_RunThread(0) == 1   # already running
    prog.run(tick_of_ms(100))
    rtn, sts = prog.GT_GetThreadSts(0)
    assert rtn == 0 and sts.run == 1 and sts.error == 0 and sts.line > 0
    # one poll per tick from the first (bit 10 is set while the Update waits for its commit, V34)
    assert prog.GT_GetVarValue(-1, count)[1] == tick_of_ms(100)
    assert prog.GT_Bind(0, 2, 0) == 1                            # not while it runs (L2256)
    prog.run(tick_of_ms(200))
    rtn, sts = prog.GT_GetThreadSts(0)
    assert (sts.run, sts.error, sts.result) == (0, 0, 2000.0)
    assert prog.GT_GetPrfPos(1) == (0, 2000.0)
    # 2000 pulse at 10 pulse/ms, 1 pulse/ms^2: 210 ms of motion, one count per tick while it moved
    assert prog.GT_GetVarValue(-1, count)[1] == pytest.approx(tick_of_ms(210), abs=3)


def test_pause_resume_stop_and_live_locals_guc_l2185_2196(prog):
    _, flag = prog.GT_GetVarId(0, "flag")
    _, done = prog.GT_GetVarId(0, "done")
    _, n = prog.GT_GetVarId("waiter", "n")
    _, k = prog.GT_GetVarId("waiter", "k")
    assert prog.GT_Bind(1, 2, 5) == 0 and prog.GT_SetVarValue(5, n, 50) == 0
    assert prog.GT_RunThread(1) == 0
    prog.run(10)
    line = prog.GT_GetThreadSts(1)[1].line
    assert prog.GT_SetVarValue(-1, flag, 1) == 0
    prog.run(10)
    assert prog.GT_GetVarValue(5, k) == (0, 10)                 # the running thread's local, live
    assert prog.GT_PauseThread(1) == 0 and prog.GT_GetThreadSts(1)[1].run == 2
    assert prog.GT_PauseThread(1) == 1
    prog.run(100)
    assert prog.GT_GetVarValue(5, k) == (0, 10)                 # paused where it stood
    assert prog.GT_RunThread(1) == 0                            # resumes
    prog.run(100)
    sts = prog.GT_GetThreadSts(1)[1]
    assert (sts.run, sts.result) == (0, 50.0) and sts.line != line
    assert prog.GT_GetVarValue(-1, done) == (0, 50)
    # a stopped thread starts again from the beginning
    assert prog.GT_SetVarValue(-1, flag, 0) == 0 and prog.GT_RunThread(1) == 0
    prog.run(5)
    assert prog.GT_StopThread(1) == 0 and prog.GT_GetThreadSts(1)[1].run == 0
    assert prog.GT_PauseThread(1) == 1 and prog.GT_StopThread(1) == 0


def test_bind_refusals_and_a_failing_function(prog):
    assert prog.GT_Bind(0, 1, 0) == 0
    assert prog.GT_Bind(1, 1, 0) == 1                           # one page, one thread (L2258)
    assert [prog.GT_Bind(32, 1, 1), prog.GT_Bind(1, 1, 32), prog.GT_Bind(1, 0, 1)] == [7, 7, 7]
    assert prog.GT_Bind(1, 9, 1) == 1 and prog.GT_RunThread(2) == 1   # unknown function; unbound thread
    assert prog.GT_Bind(3, 3, 3) == 0 and prog.GT_RunThread(3) == 0
    prog.run(2)
    assert prog.GT_GetThreadSts(3)[1] == TThreadSts(run=0, error=1, result=0.0, line=prog.GT_GetThreadSts(3)[1].line)
    assert [prog.GT_RunThread(32), prog.GT_StopThread(-1), prog.GT_PauseThread(40), prog.GT_GetThreadSts(32)[0]] \
        == [7] * 4


def test_variable_values_checked_guc_l2215_2233(prog):
    _, count = prog.GT_GetVarId(0, "count")
    assert prog.GT_SetVarValue(-1, count, [7, 8, 9], 3) == 0
    assert prog.GT_GetVarValue(-1, count, 3) == (0, [7, 8, 9])
    assert [prog.GT_SetVarValue(-1, count, 2**31), prog.GT_SetVarValue(-1, count, [1] * 9, 9),
            prog.GT_SetVarValue(32, count, 1), prog.GT_SetVarValue(-1, count, [1, 2], 3)] == [7] * 4
    assert prog.GT_SetVarValue(-1, count, [1] * 4, 4) == 1        # past the last global
    assert prog.GT_GetVarValue(-1, TVarInfo(id=0, function="mover", name="axis"))[0] == 1  # a local on page -1


def test_compile_and_download_refusals_guc_l2143_2145(gts, tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("x = 1\ndef f(:\n", encoding="utf-8")
    rtn, info = gts.GT_Compile(str(bad))
    assert rtn == 1 and info.lineNo == 2 and info.message
    c = tmp_path / "sum.c"
    c.write_text("int sum;\n", encoding="utf-8")
    assert gts.GT_Compile(str(c))[0] == 1 and "MCT2008" in gts.GT_Compile(str(c))[1].message
    assert gts.GT_Compile(str(tmp_path / "missing.py"))[0] == 1
    assert gts.GT_Download(str(tmp_path / "bad.bin")) == 1      # never compiled
    assert gts.GT_GetFunId("f") == (1, 0) and gts.GT_GetVarId(0, "x")[0] == 1
    ok = tmp_path / "ok.py"
    ok.write_text("x = 3\ndef f():\n    return x\n", encoding="utf-8")
    assert gts.GT_Download(str(ok)) == 0 and gts.GT_GetFunId("f") == (0, 1)   # a .py is compiled on download
    g = GtsController()
    assert g.GT_Download(str(ok)) == -1 and g.GT_Bind(0, 1, 0) == -1 and g.GT_RunThread(0) == -1
    assert g.GT_SetVarValue(-1, TVarInfo(id=0, name="x"), 1) == -1 and g.GT_GetThreadSts(0)[0] == -1


def test_reset_stops_the_threads_and_keeps_the_program(prog):
    assert prog.GT_Bind(0, 2, 0) == 0 and prog.GT_RunThread(0) == 0
    prog.run(3)
    assert prog.GT_Reset() == 0
    assert prog.GT_GetThreadSts(0)[1].run == 0 and prog.GT_GetFunId("waiter") == (0, 2)


def test_motion_program_calls_cost_no_bus_time_in_program_mode(prog):
    # GS13: a motion program runs on the controller (L2109: "without communication with PC"): its GT calls are
    # not vendor calls over the bus, so in program mode they neither advance the card nor count as calls
    clock = prog.card.set_clock("program")
    _, axis = prog.GT_GetVarId("mover", "axis")
    assert prog.GT_Bind(0, 1, 0) == 0 and prog.GT_SetVarValue(0, axis, [2, 500], 2) == 0
    assert prog.GT_RunThread(0) == 0
    calls, tick = clock.stats().calls, prog.card.tick
    prog.run_ms(100)                                     # the thread polls GT_GetSts every tick meanwhile
    assert clock.stats().calls == calls and prog.card.tick == tick + tick_of_ms(100)
    assert prog.GT_GetThreadSts(0)[1].run == 0 and prog.GT_GetPrfPos(2) == (0, 500.0)
