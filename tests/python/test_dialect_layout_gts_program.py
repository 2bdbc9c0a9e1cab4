"""The GUC motion program's layout (issue 24 points 2-3; decisions GT12, GU6, GY1-): the card's part -- the symbol
tables, the 32 threads and their TThreadSts words, the data pages and globals, the checks and codes, the scheduling
-- is the C++ card module ``_core.guc_program(card)`` (vendor/googol/guc_program.hpp); ``_gts_program.py`` keeps
only what is Python (compiling and loading the .py, the generators of the running threads, the per-tick stepping
hook) and rows of one-line adapters. Checked statically with ``ast`` where it can be, and by behaviour."""

import ast
from pathlib import Path

import pytest

import servobench as sb
from servobench import _core
from servobench.dialects import gts

FILE = Path(__file__).resolve().parents[2] / "python" / "servobench" / "dialects" / "_gts_program.py"
# Session 13 left 409 lines (the whole machinery in Python); what session 14 reached: the count may only go down.
CEILING = 330
# The classes the file may define: the manual's C structs (dataclasses) and the host's part of a downloaded program
# (its namespace, functions and generator frames: what IS Python, GS13), plus the mixin the rows are set on.
STRUCTS = {"TCompileInfo", "TVarInfo", "TThreadSts"}
ALLOWED_CLASSES = STRUCTS | {"_Host", "GtsProgramMixin"}
PROGRAM_FUNCTIONS = ("GT_Compile", "GT_Download", "GT_GetFunId", "GT_GetVarId", "GT_Bind", "GT_RunThread",
                     "GT_StopThread", "GT_PauseThread", "GT_GetThreadSts", "GT_SetVarValue", "GT_GetVarValue")


def _tree() -> ast.Module:
    return ast.parse(FILE.read_text(), filename=FILE.name)


def test_program_file_within_its_ceiling():
    lines = len(FILE.read_text().splitlines())
    assert lines <= CEILING, f"_gts_program.py: {lines} lines, more than the {CEILING} session 14 reached"


def test_no_thread_state_class_and_no_state_on_the_controller():
    """The threads, pages and status words are C++'s: no ``_Thread`` class, no per-controller ``_mp_state`` dict,
    no ``__dict__`` writes; the only classes are the manual's structs, the host's frames and the mixin."""
    tree = _tree()
    classes = {c.name for c in ast.walk(tree) if isinstance(c, ast.ClassDef)}
    assert classes <= ALLOWED_CLASSES, sorted(classes - ALLOWED_CLASSES)
    source = FILE.read_text()
    for reach in ("_mp_state", "__dict__", "_card._card", "sts.run", "sts.error", ".paused"):
        assert reach not in source, reach
    mixin = next(c for c in ast.walk(tree) if isinstance(c, ast.ClassDef) and c.name == "GtsProgramMixin")
    written = {f.name for f in mixin.body if isinstance(f, ast.FunctionDef)}
    assert written == {"_close_program"}, written  # every GT_* is a row of _ROWS


def test_no_argument_check_and_no_message_parsing_in_python():
    """The ranges (thread/page 0..31, funId, count 1..8, DINT) are the C++ module's; no code is read from a
    message."""
    tree = _tree()
    funcs = {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}
    assert not funcs & {"_int_in", "_thread", "_var_names", "_step_each", "_mp"}, funcs
    names = {t.id for n in ast.walk(tree) if isinstance(n, ast.Assign) for t in n.targets if isinstance(t, ast.Name)}
    assert "_DINT" not in names
    for handler in (n for n in ast.walk(tree) if isinstance(n, ast.ExceptHandler)):
        body = ast.unparse(handler)
        assert "str(e)" not in body and ".args" not in body, body


@pytest.mark.parametrize("name", PROGRAM_FUNCTIONS)
def test_each_program_function_is_a_row_with_its_manual_line(name):
    fn = getattr(gts.GtsController, name)
    assert fn.__doc__ and "L2" in fn.__doc__, name
    assert getattr(gts, name).__doc__ == fn.__doc__


def test_the_program_module_is_the_cards_and_shares_its_locks(tmp_path):
    card = sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=1e-3)
    other = sb.Card(4)
    module = _core.guc_program(card.kernel)
    assert _core._shares_card_locks(module, card.kernel)
    assert not _core._shares_card_locks(module, other.kernel)
    # the dialect's calls land in the card's module: its status word is what GT_GetThreadSts returns
    path = tmp_path / "p.py"
    path.write_text("total = 0\n\ndef count(n):\n    global total\n    while total < n:\n        total = total + 1\n"
                    "        yield\n    return total\n", encoding="utf-8")
    c = gts.GtsController()
    assert c.GT_Open(card) == 0 and c.GT_Download(str(path)) == 0
    _, n = c.GT_GetVarId("count", "n")
    assert c.GT_Bind(4, 1, 9) == 0 and c.GT_SetVarValue(9, n, 5) == 0 and c.GT_RunThread(4) == 0
    card.run(3)
    assert module.thread_status(4)[:2] == (0, 1) and module.global_values == [3.0]
    assert c.GT_GetVarValue(-1, c.GT_GetVarId(0, "total")[1]) == (0, 3)
    card.run(5)
    assert module.thread_status(4) == (0, 0, 0, 5.0, module.thread_status(4)[4])
    assert c.GT_GetThreadSts(4)[1] == gts.TThreadSts(*module.thread_status(4)[1:])
    assert not module.any_active()


@pytest.mark.parametrize("name", PROGRAM_FUNCTIONS)
def test_program_functions_return_codes_for_any_argument(name, tmp_path):
    """NaN, a string, None, -1 or 2.5 in every position gives a code (7 or 1) -- never an exception -- with a
    program downloaded, and -1 without a card (GT_Compile needs none: it compiles on the PC)."""
    import inspect
    import math

    c = gts.GtsController()
    fn = getattr(c, name)
    n = sum(1 for p in inspect.signature(fn).parameters.values() if p.default is inspect.Parameter.empty)
    if name != "GT_Compile":
        none = fn(*([1] * n))
        assert (none[0] if isinstance(none, tuple) else none) == gts.RTN_COMM_ERROR
    path = tmp_path / "p.py"
    path.write_text("x = 1\n\ndef f(a):\n    yield\n", encoding="utf-8")
    assert c.GT_Open(sb.Card(4)) == 0 and c.GT_Download(str(path)) == 0
    for bad in (math.nan, "x", None, -1, 2.5):
        rtn = fn(*([bad] * n))
        code = rtn[0] if isinstance(rtn, tuple) else rtn
        assert code in (gts.RTN_PARAMETER_ERROR, gts.RTN_COMMAND_ERROR), (name, bad, rtn)
