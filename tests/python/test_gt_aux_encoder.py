"""The GT auxiliary encoders in the card's C++ module (issue 24.2, decisions GT8, GZ1-GZ5;
vendor/googol/gt_aux_encoder.hpp): the index arithmetic gives what the Python arithmetic gave, the host evaluates
only the machine's position source (the same times as before), and neither the dialect nor card_io keeps any of the
arithmetic or registers."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest

import servobench as sb
from servobench import _core, card_io
from servobench.dialects.gt import GtController
from test_card_gt import LAW

ROOT = Path(__file__).resolve().parents[2]
PKG = ROOT / "python" / "servobench"


def _index_between_before(a: int, b: int, n: int, off: float) -> int | None:
    """card_io.AuxEncoder.index_between as it was written in Python before session 14 (the oracle)."""
    if n == 0 or a == b:
        return None
    if b > a:
        k = math.floor((a - off) / n) + 1
        mark = off + k * n
        return math.floor(mark) if mark <= b else None
    k = math.ceil((a - off) / n) - 1
    mark = off + k * n
    return math.floor(mark) if mark >= b else None


def test_index_between_gives_what_the_python_arithmetic_gave():
    rng = np.random.default_rng(24)
    cases = 0
    for _ in range(4000):
        n = int(rng.choice([0, 1, 3, 7, 1000, 4000, 2**20, 2**31]))
        off = float(rng.choice([0.0, 0.5, 1000.0, -2.5, rng.uniform(-1e9, 1e9)]))
        a = int(rng.integers(-2**31, 2**31))
        b = a + int(rng.choice([-1, 1]) * rng.integers(0, 3 * max(n, 1)))
        enc = card_io.AuxEncoder(counts_per_index=n, index_offset=off)
        assert enc.index_between(a, b) == _index_between_before(a, b, n, off), (a, b, n, off)
        cases += enc.index_between(a, b) is not None
    assert cases > 500  # the marks are met in a good part of the cases, not only the None branch


def test_the_capture_asks_the_machine_for_the_same_times_as_before():
    """The C++ scan asks the position source for encoder 1 at k x ST for each tick since the last look, and
    stops at the first mark, as the Python scan did; the velocity reads t and t - ST."""
    card = sb.Card(4, law=LAW)
    asked: list[float] = []

    def pos(t_s: float) -> float:
        asked.append(t_s)
        return -30.0 + 20000.0 * t_s  # 4 pulse/ST; marks every 40 from 10: the first at 10, tick 10

    card_io.of(card).aux_encoders[0] = card_io.AuxEncoder(pos, counts_per_index=40, index_offset=10.0)
    c = GtController()
    assert c.GT_Open(card) == 0 and c.GT_SetEncCapt() == 0
    assert asked == [0.0]
    card.run(20)
    asked.clear()
    assert c.GT_GetEncSts() == (0, 0x8) and c.GT_GetEncCapt() == (0, 10)
    ts = card.servo_period_s
    assert asked == [k * ts for k in range(1, 11)]   # ticks 1..10, then the mark: no more (the second read: none)
    asked.clear()
    assert c.GT_EncVel(1) == (0, 4.0) and asked == [20 * ts, max(0.0, 20 * ts - ts)]


def test_the_registers_are_the_modules():
    card = sb.Card(4, law=LAW)
    card_io.of(card).aux_encoders[1] = card_io.AuxEncoder(1234.0)
    c = GtController()
    assert c.GT_Open(card) == 0 and c.GT_ClrEncPos(2) == 0
    assert _core.gt_card(card.kernel).aux_zero == [0, 1234]
    assert not any(k.startswith("enc_zero") or k.startswith("capt") for k in dir(_core.gt_card(card.kernel).system))


_GONE = {"_aux_raw", "_aux_sign", "_aux_value", "_enc_read", "_capt_scan"}


@pytest.mark.parametrize("name", ["dialects/_gt_system.py", "card_io.py"])
def test_no_encoder_arithmetic_left_in_python(name):
    tree = ast.parse((PKG / name).read_text())
    defined = {n.name for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))}
    assert not defined & _GONE
    for fn in (n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef) and n.name == "index_between"):
        assert len(fn.body) == 2 and isinstance(fn.body[-1], ast.Return)  # docstring + the C++ call
    # the dialect's encoder commands are table rows (gt_adapter), no method of their own
    if name.endswith("_gt_system.py"):
        methods = {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef) and n.name.startswith("GT_")}
        assert not methods & {"GT_EncSns", "GT_EncPos", "GT_EncVel", "GT_ClrEncPos", "GT_SetEncCapt",
                              "GT_GetEncSts", "GT_GetEncCapt"}


def test_gt_system_line_ceiling():
    """What session 14 reached for _gt_system.py (393 lines before): it may only go down."""
    assert len((PKG / "dialects" / "_gt_system.py").read_text().splitlines()) <= 342


def test_a_bad_source_raises_on_the_machine_side_and_the_gt_function_returns_a_code():
    card = sb.Card(4, law=LAW)
    card_io.of(card).aux_encoders[0] = card_io.AuxEncoder(lambda t: math.inf)
    with pytest.raises(ValueError, match="finite number of pulses"):
        card_io.of(card).aux_counts(0, 0.0)
    c = GtController()
    assert c.GT_Open(card) == 0
    assert c.GT_EncPos(1) == (7, 0)  # a GT function never raises: the dialect's wrapper returns 7, as before
    with pytest.raises(TypeError):
        _core.aux_index_mark_between(0, 10, 1.5, 0.0)
    with pytest.raises(ValueError, match="counts_per_index"):
        _core.aux_index_mark_between(0, 10, -1, 0.0)
