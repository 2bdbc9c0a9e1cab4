"""docs/coverage.md against the five manual digests (../shared/spec beside the checkout) and the test sources:
one row per digest section in digest order, a valid status, a proof for every implemented or partly row, every
proof an existing test, the manual lines of the digest heading, and a current summary table (decisions K1-K8)."""

import importlib.util
import re
import sys
from collections import Counter
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("make_coverage_summary", REPO / "docs" / "make_coverage_summary.py")
cov = importlib.util.module_from_spec(_spec)
sys.modules.setdefault(_spec.name, cov)
_spec.loader.exec_module(cov)

SPEC = cov.spec_dir()
MD = cov.COVERAGE_MD.read_text(encoding="utf-8")
ROWS = cov.coverage_rows(MD)

needs_spec = pytest.mark.skipif(SPEC is None, reason=f"the manual digests are not beside the checkout "
                                                     f"({REPO.parent / 'shared' / 'spec'} is missing)")

_PY_PROOF = re.compile(r"^tests/python/(test_\w+\.py)::(test_\w+)(\[[^\]]*\])?$")
_CPP_FILE = re.compile(r"^tests/cpp/(test_\w+\.cpp)$")
_CPP_TEST = re.compile(r"^([A-Za-z_]\w*)\.(\*|[A-Za-z_]\w*)$")
_TEST_MACRO = re.compile(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)")


def _python_tests(name: str) -> set[str]:
    path = REPO / "tests" / "python" / name
    return set(re.findall(r"^\s*(?:async\s+)?def (test_\w+)\s*\(", path.read_text(encoding="utf-8"), re.M))


def _cpp_tests(name: str) -> set[tuple[str, str]]:
    return set(_TEST_MACRO.findall((REPO / "tests" / "cpp" / name).read_text(encoding="utf-8")))


def proofs(row) -> list[str]:
    """The proofs of a row as 'tests/python/f.py::name' or 'tests/cpp/f.cpp::Suite.Name' (one per test named).
    Raises AssertionError on a malformed proof cell."""
    cell = row.proof
    tokens = re.findall(r"`([^`]*)`", cell)
    rest = re.sub(r"`[^`]*`", "", cell)
    assert re.fullmatch(r"[\s;,]*", rest), f"{row.section}: text outside backticks in the proof cell: {rest!r}"
    out, cpp_file = [], None
    for tok in tokens:
        if (m := _PY_PROOF.match(tok)):
            out.append(f"tests/python/{m.group(1)}::{m.group(2)}")
            cpp_file = None
        elif (m := _CPP_FILE.match(tok)):
            cpp_file = m.group(1)
        elif (m := _CPP_TEST.match(tok)):
            assert cpp_file, f"{row.section}: C++ test `{tok}` without a preceding `tests/cpp/<file>`"
            out.append(f"tests/cpp/{cpp_file}::{tok}")
        else:
            raise AssertionError(f"{row.section}: `{tok}` is not a test (tests/python/<file>::<test> or "
                                 f"tests/cpp/<file> followed by Suite.Name)")
    if cell.strip():
        assert not tokens or not _CPP_FILE.match(tokens[-1]), f"{row.section}: `{tokens[-1]}` names no test"
    return out


def unresolved(proof: str) -> str | None:
    """Why the proof does not name an existing test, or None."""
    path, name = proof.split("::")
    file = REPO / path
    if not file.is_file():
        return f"{path} does not exist"
    if path.endswith(".py"):
        return None if name in _python_tests(file.name) else f"{path} has no `def {name}`"
    suite, test = name.split(".")
    found = _cpp_tests(file.name)
    if test == "*":
        return None if any(s == suite for s, _ in found) else f"{path} has no TEST({suite}, ...)"
    return None if (suite, test) in found else f"{path} has no TEST({suite}, {test})"


def test_every_row_is_well_formed():
    assert len(ROWS) > 0, "docs/coverage.md has no '| section |' table"
    bad_status = [(r.line_no, r.section, r.status) for r in ROWS if r.status not in cov.STATUSES]
    assert not bad_status, f"status must be one of {cov.STATUSES}: {bad_status}"
    for r in ROWS:
        assert r.manual in cov.MANUALS.values(), f"line {r.line_no}: unknown manual in {r.section!r}"
        assert r.title and r.lines and r.what, f"line {r.line_no}: {r.section} has an empty cell"


@needs_spec
def test_every_digest_section_has_exactly_one_row_in_digest_order():
    sections = cov.digest_sections(SPEC)
    keys = [s.key for s in sections]
    assert len(set(keys)) == len(keys), "two digest headings give the same section key"
    counts = Counter(r.section for r in ROWS)
    duplicated = sorted(k for k, n in counts.items() if n > 1)
    missing = [k for k in keys if k not in counts]
    unknown = [r.section for r in ROWS if r.section not in set(keys)]
    assert not duplicated, f"sections with more than one row: {duplicated}"
    assert not missing, f"digest sections without a row in docs/coverage.md: {missing}"
    assert not unknown, f"rows for sections the digests do not have: {unknown}"
    assert [r.section for r in ROWS] == keys, "the rows are not in digest order"


@needs_spec
def test_manual_lines_are_the_digest_headings():
    by_key = {s.key: s for s in cov.digest_sections(SPEC)}
    wrong = [(r.section, r.lines, by_key[r.section].heading_lines) for r in ROWS
             if r.section in by_key and by_key[r.section].heading_lines
             and r.lines != by_key[r.section].heading_lines]
    assert not wrong, f"manual lines differ from the digest heading (row, table, heading): {wrong}"


def test_implemented_and_partly_rows_have_a_proof():
    bare = [r.section for r in ROWS if r.status in ("implemented", "partly") and not proofs(r)]
    assert not bare, f"implemented / partly rows without a test: {bare}"


def test_partly_rows_say_what_is_missing():
    vague = [r.section for r in ROWS if r.status == "partly" and "Not:" not in r.what]
    assert not vague, f"partly rows must say what is missing ('Not: ...'): {vague}"


def test_every_proof_names_an_existing_test():
    problems = []
    for r in ROWS:
        for p in proofs(r):
            if (why := unresolved(p)):
                problems.append(f"{r.section}: {why}")
    assert not problems, "proofs that name no test:\n" + "\n".join(problems)


def test_summary_table_is_current():
    in_file = cov.summary_in_file(MD)
    assert in_file is not None, "docs/coverage.md has no table under '## Summary'"
    assert in_file == cov.summary_table(ROWS), "the summary is stale: run python docs/make_coverage_summary.py"
    print("\n" + cov.summary_table(ROWS))
