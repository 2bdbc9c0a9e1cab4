"""The manuals' example programs in examples/vendor_programs (issue 25.2): at least two per manual, each citing its
manual and lines, each run (in program mode) by a test of tests/python/test_vendor_programs_<vendor>.py that
checks the states and positions the manual states. The per-vendor test files hold those assertions; this file
checks the set is complete."""

import ast
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1].parent
PROGRAMS = REPO / "examples" / "vendor_programs"
# file-name prefix of a program -> its manual
MANUALS = {"gt_": "GT", "ge_": "GE", "guc_": "GUC-ECAT", "ideabox_": "iDEABOX", "adlink_": "ADLINK"}


def programs() -> list[Path]:
    return sorted(p for p in PROGRAMS.glob("*.py") if not p.name.startswith("_"))


def test_at_least_two_programs_per_manual():
    counts = {m: sum(p.name.startswith(prefix) for p in programs()) for prefix, m in MANUALS.items()}
    assert all(n >= 2 for n in counts.values()), counts
    assert all(p.name.startswith(tuple(MANUALS)) for p in programs()), [p.name for p in programs()]


@pytest.mark.parametrize("path", programs(), ids=lambda p: p.stem)
def test_each_program_cites_its_manual_and_is_run_by_a_test(path):
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")))
    assert doc and re.search(r"\bL\d+", doc), f"{path.name}: the docstring names the manual's example and lines"
    tests = "".join(p.read_text(encoding="utf-8") for p in (REPO / "tests" / "python").glob("test_vendor_programs_*.py"))
    assert re.search(rf"\b{path.stem}\b", tests), f"{path.name} is not run by a tests/python/test_vendor_programs_*.py"
