"""Issue 24 points 3 and 6 for the GT and GTS (GUC-ECAT / iDEABOX) dialects: every public signature as it was
before the dialects were thinned (tests/data/dialect_signatures/{gt,gts}.json, dumped from main at the start of
session 11), and the layout the thin dialects keep (line counts against the aims, no private reach into the C++
card, no message parsing, no mutable state beyond the card handles)."""

from __future__ import annotations

import ast
import importlib
import inspect
import json
import math
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DIALECTS = ROOT / "python" / "servobench" / "dialects"
SIGNATURES = ROOT / "tests" / "data" / "dialect_signatures"


def _signatures(module: str, cls_name: str) -> dict[str, str | None]:
    """{qualified name: str(inspect.signature)} of every public callable of the module and its controller class,
    as tests/data/dialect_signatures/*.json was dumped."""
    mod = importlib.import_module(f"servobench.dialects.{module}")
    out: dict[str, str | None] = {}
    for prefix, owner, names in ((module, mod, dir(mod)), (cls_name, getattr(mod, cls_name), None)):
        for name in sorted(names if names is not None else dir(owner)):
            if name.startswith("_"):
                continue
            obj = getattr(owner, name)
            if inspect.ismodule(obj) or not callable(obj):
                continue
            if owner is mod and not str(getattr(obj, "__module__", "") or "").startswith("servobench.dialects"):
                continue
            try:
                out[f"{prefix}.{name}"] = str(inspect.signature(obj))
            except (TypeError, ValueError):
                out[f"{prefix}.{name}"] = None
    return out


@pytest.mark.parametrize("family, module, cls_name", [("gt", "gt", "GtController"), ("gts", "gts", "GtsController")])
def test_every_public_signature_is_unchanged(family, module, cls_name):
    before = json.loads((SIGNATURES / f"{family}.json").read_text())
    now = _signatures(module, cls_name)
    missing = sorted(set(before) - set(now))
    changed = {k: (before[k], now[k]) for k in before if k in now and before[k] != now[k]}
    assert not missing, f"public callables lost: {missing}"
    assert not changed, f"signatures changed (before, now): {changed}"


# -- layout (issue 24.3): the aims are 40 % of the lines the dialects had when issue 24 was filed ---------------------
AIMS = {"gt.py": 431}
# The handles a GT controller keeps (decision GT3): which Card objects are open and which is current, the machine a
# program runs against, the ISA address the program set. Every register is the C++ GT module's.
HANDLES = {"_card", "_cards", "_card_no", "_machine", "_isa_addr"}
GT_FILES = ("gt.py", "_gt_system.py")
# GTS: the look-ahead windows and the configuration registers are the card's GtsCard (decision GT11); the motion
# program's threads (_gts_program.py) are the host's Python code and stay (GT12, GU6); the set-up and configuration
# commands are rows over C++ vendor functions (GU1-GU4); gts.py is not at its aim yet (GU5).
GTS_FILES = ("gts.py", "_gts_config.py")
# What session 12 reached: the line counts may only go down.
CEILINGS = {"gts.py": 594, "_gts_config.py": 244}
# The GTS commands still written out as methods: the open/close/reset of the card handle (they also stop the
# motion-program threads, GT12/GU6).
GTS_WRITTEN_OUT = {"GT_Open", "GT_Close", "GT_Reset"}
# Rows over a C++ vendor function (gts_commands.hpp, gts_config.hpp) that checks every argument: any value gives
# a code, never an exception.
GTS_CPP_ROWS = ("GT_SetTrapPrm", "GT_SetJogPrm", "GT_Stop", "GT_SetCrdPrm", "GT_GetCrdPrm", "GT_InitLookAhead",
                "GT_CrdData", "GT_PvtTable", "GT_PvtTableEx", "GT_PvtTableComplete", "GT_PvtTablePercent",
                "GT_PvtTableContinuous", "GT_PvtTableContinuousEx", "GT_PvtPercentCalculate",
                "GT_PvtContinuousCalculate", "GT_AlarmOn", "GT_AlarmOff", "GT_LmtsOn", "GT_LmtsOff", "GT_LmtSns",
                "GT_EncSns", "GT_ProfileScale", "GT_EncScale", "GT_GpiSns", "GT_GetDi", "GT_SetAdcFilter",
                "GT_SetStopDec", "GT_GetStopDec", "GT_GetCrdStopDec", "GT_SetStopIo", "GT_GetTrapPrm",
                "GT_GetJogPrm", "GT_SetAxisPrfVelFilter", "GT_GetAxisPrfVelFilter", "GT_SetAxisEncVelFilter",
                "GT_GetAxisEncVelFilter", "GT_GetEncVel")


def _tree(name: str) -> ast.Module:
    return ast.parse((DIALECTS / name).read_text(), filename=name)


@pytest.mark.parametrize("name, aim", [*sorted(AIMS.items()), pytest.param(
    "gts.py", 341, marks=pytest.mark.xfail(strict=True, reason="gts.py is a table (594 lines): decision GU5"))])
def test_dialect_file_within_its_line_aim(name, aim):
    lines = len((DIALECTS / name).read_text().splitlines())
    assert lines <= aim, f"{name}: {lines} lines, aim <= {aim} (40 % of the lines at issue 24)"


@pytest.mark.parametrize("name, ceiling", sorted(CEILINGS.items()))
def test_gts_files_within_their_ceiling(name, ceiling):
    lines = len((DIALECTS / name).read_text().splitlines())
    assert lines <= ceiling, f"{name}: {lines} lines, more than the {ceiling} session 12 reached"


@pytest.mark.parametrize("name", GTS_FILES)
def test_gts_commands_are_table_rows(name):
    """No GT_* method written out in a GTS class body beyond the card handle's open/close/reset: every command is
    a row (``_row``/``_raw`` over the card, ``gts_row`` over a C++ vendor function)."""
    written = {f.name for c in ast.walk(_tree(name)) if isinstance(c, ast.ClassDef) for f in c.body
               if isinstance(f, ast.FunctionDef) and f.name.startswith("GT_")}
    assert written <= GTS_WRITTEN_OUT, f"{name}: written-out commands {sorted(written - GTS_WRITTEN_OUT)}"


@pytest.mark.parametrize("name", GTS_CPP_ROWS)
def test_gts_vendor_rows_return_codes_for_any_argument(name):
    """The C++ vendor function checks every argument: NaN, a string, None or a negative value in every position
    gives a code (7 or 1) -- never an exception, never a crash -- and -1 without a card (the two PVT calculations
    need no card: they compute, nothing is downloaded)."""
    from servobench import Card
    from servobench.dialects import gts

    c = gts.GtsController()
    fn = getattr(c, name)
    n = sum(1 for p in inspect.signature(fn).parameters.values() if p.default is inspect.Parameter.empty)
    none = fn(*([1] * n))
    if not name.endswith("Calculate"):
        assert (none[0] if isinstance(none, tuple) else none) == gts.RTN_COMM_ERROR
    assert c.GT_Open(Card(4)) == 0
    for bad in (math.nan, "x", None, -1, 2.5):
        rtn = fn(*([bad] * n))
        code = rtn[0] if isinstance(rtn, tuple) else rtn
        assert code in (gts.RTN_PARAMETER_ERROR, gts.RTN_COMMAND_ERROR), (name, bad, rtn)


@pytest.mark.parametrize("name", GT_FILES + GTS_FILES)
def test_no_private_reach_into_the_card(name):
    """No ``x._card._y`` / ``card._card`` / ``kernel._y``: the dialect uses the Card's and the GT module's public
    API only."""
    bad = []
    for node in ast.walk(_tree(name)):
        if isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__"):
            base = node.value
            if isinstance(base, ast.Attribute) and base.attr in ("_card", "kernel", "_cards"):
                bad.append(f"L{node.lineno}: .{base.attr}.{node.attr}")
            if isinstance(base, ast.Name) and base.id in ("c", "card", "g") and node.attr != "_clock":
                bad.append(f"L{node.lineno}: {base.id}.{node.attr}")
    assert not bad, f"{name}: private reaches {bad}"


@pytest.mark.parametrize("name", GT_FILES + GTS_FILES)
def test_no_message_parsing(name):
    """No ``except ... as e`` whose handler reads ``str(e)`` / ``e.args``: codes are typed (return_code.hpp)."""
    bad = []
    for node in ast.walk(_tree(name)):
        if isinstance(node, ast.ExceptHandler) and node.name:
            for sub in ast.walk(node):
                if isinstance(sub, ast.Name) and sub.id == node.name and sub is not node:
                    bad.append(f"L{node.lineno}")
    assert not bad, f"{name}: exception text read at {bad}"


@pytest.mark.parametrize("name", GT_FILES + GTS_FILES)
def test_no_mutable_state_beyond_the_handles(name):
    """Every ``self.x = ...`` in the GT dialect sets a handle (HANDLES); no ``self.__dict__`` juggling, no
    ``self.x[k] = ...`` / ``self.x.update(...)`` on a dialect attribute: the registers live in the C++ module."""
    bad = []
    for node in ast.walk(_tree(name)):
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AugAssign, ast.AnnAssign)) else []
        for t in targets:
            for el in (t.elts if isinstance(t, ast.Tuple) else [t]):
                if isinstance(el, ast.Attribute) and isinstance(el.value, ast.Name) and el.value.id == "self" \
                        and el.attr not in HANDLES:
                    bad.append(f"L{node.lineno}: self.{el.attr}")
                if isinstance(el, ast.Subscript) and isinstance(el.value, ast.Attribute) \
                        and isinstance(el.value.value, ast.Name) and el.value.value.id == "self":
                    bad.append(f"L{node.lineno}: self.{el.value.attr}[...]")
        if isinstance(node, ast.Attribute) and node.attr == "__dict__":
            bad.append(f"L{node.lineno}: __dict__")
    assert not bad, f"{name}: dialect state {bad}"


def test_gt_registers_are_the_cards():
    """Two GT cards in one PC: the current axis, LmtSns and the coordinated list are each card's (the C++ module's),
    so switching cards switches them, with nothing copied by the dialect."""
    from servobench import Card, _core
    from servobench.dialects import gt

    c = gt.GtController()
    cards = [Card(4), Card(4)]
    assert c.GT_Open(cards[0]) == 0
    c._open_cards(cards)
    assert c.GT_Axis(3) == 0 and c.GT_LmtSns(0b1010) == 0 and c.GT_SetSynVel(5) == 0
    assert c.GT_SwitchtoCardNo(1) == 0
    assert c._axis == 0 and _core.gt_card(cards[1].kernel).limit_sense == 0
    assert c.GT_SwitchtoCardNo(0) == 0
    g0 = _core.gt_card(cards[0].kernel)
    assert (c._axis, g0.axis, g0.limit_sense, g0.crd_registers()["vel"]) == (2, 2, 0b1010, 5.0)
    assert c.GT_Reset() == 0 and g0.limit_sense == 0 and g0.crd_registers()["vel"] == 0.0 and g0.axis == 2


def test_gts_registers_are_the_cards():
    """The GTS look-ahead window of a (crd, fifo) and the stop decelerations are the card's GtsCard registers: a
    second controller opening the same card sees them; GT_Reset drops the windows."""
    from servobench import Card, _core
    from servobench.dialects import gts

    card = Card(8)
    a, b = gts.GtsController(), gts.GtsController()
    assert a.GT_Open(card) == 0 and b.GT_Open(card) == 0
    for k in (1, 2):
        assert a.GT_AxisOn(k) == 0
    prm = gts.TCrdPrm(dimension=2, profile=[1, 2, 0, 0, 0, 0, 0, 0], synVelMax=500, synAccMax=1)
    assert a.GT_SetCrdPrm(1, prm) == 0
    assert a.GT_InitLookAhead(1, 0, 5, 1, 200) == 0 and a.GT_SetStopDec(2, 0.5, 4) == 0
    g = _core.gts_card(card.kernel)
    assert g.lookahead(1, 0) == 200 and b.GT_GetStopDec(2) == (0, 0.5, 4.0)
    assert b.GT_Reset() == 0 and g.lookahead(1, 0) == 0
