"""Function-level coverage of the manuals (issue 25.3, decision K9): the committed name lists are exactly the
tokens of the manuals (when ../shared/seeds is beside the checkout), every token is classified, the table in
docs/coverage.md is current, and per manual at least 95 % of the named functions exist in the dialect and at least
90 % are exercised by a test or by a manual program the tests run. A function the simulation cannot carry out is
listed, with its reason, in its dialect's ``UNSUPPORTED`` table and returns the vendor's error code."""

import importlib
import importlib.util
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("make_function_coverage", REPO / "docs" / "make_function_coverage.py")
fc = importlib.util.module_from_spec(_spec)
sys.modules.setdefault(_spec.name, fc)
_spec.loader.exec_module(fc)

SEEDS = fc.seeds_dir()
MANUALS = list(fc.MANUALS)


@pytest.mark.skipif(SEEDS is None, reason="../shared/seeds is not beside the checkout")
@pytest.mark.parametrize("manual", MANUALS)
def test_the_lists_are_the_manuals_tokens(manual):
    tokens = fc.seed_tokens(manual, SEEDS)
    listed = {e.name: e.line for e in fc.load_list(manual)}
    assert sorted(listed) == sorted(tokens), (set(tokens) ^ set(listed))
    assert listed == tokens  # the first line each appears on


def test_extraction_reads_markdown_escapes_and_first_lines():
    text = "intro\nI32 APS\\_vel\\_all (...); and APS_vel\nGT_SetKp(1); GT_SetKp(2) GT_Foo_\n"
    assert fc.extract(text, "APS_") == {"APS_vel_all": 2, "APS_vel": 2}
    assert fc.extract(text, "GT_") == {"GT_SetKp": 3, "GT_Foo": 3}


@pytest.mark.parametrize("manual", MANUALS)
def test_every_token_is_classified(manual):
    entries = fc.load_list(manual)
    names = {e.name for e in entries}
    assert len(names) == len(entries), "a name is listed twice"
    funcs = {e.name for e in entries if e.kind == "function"}
    for e in entries:
        assert e.kind in fc.KINDS, (e.name, e.kind)
        if e.kind == "typo":
            assert e.note in funcs, f"{e.name}: a misspelling of {e.note!r}, which is not a listed function"
        if e.kind == "not-a-function":
            assert e.note, f"{e.name}: say what it is"


@pytest.mark.parametrize("manual", MANUALS)
def test_unsupported_functions_say_why(manual):
    module = importlib.import_module(fc.MANUALS[manual][2])
    table = getattr(module, "UNSUPPORTED", {})
    for name, why in table.items():
        assert callable(getattr(module, name, None)), f"{name} is listed as unsupported but not defined"
        assert isinstance(why, str) and len(why) > 15, f"{name}: the reason is missing or too short"


def test_the_table_in_coverage_md_is_current():
    md = fc.COVERAGE_MD.read_text(encoding="utf-8")
    assert fc.BEGIN in md and fc.END in md
    expected = fc.with_section(md, fc.section([fc.measure(m) for m in MANUALS]))
    assert md == expected, "docs/coverage.md is stale: run python docs/make_function_coverage.py"


@pytest.mark.parametrize("manual", MANUALS)
def test_thresholds(manual):
    c = fc.measure(manual)
    assert c.pct(c.exist) >= 95.0, f"{manual}: {c.exist}/{len(c.names)} exist; missing {c.missing}"
    assert c.pct(c.exercised) >= 90.0, (f"{manual}: {c.exercised}/{len(c.names)} exercised; "
                                        f"not exercised {c.unexercised}")
