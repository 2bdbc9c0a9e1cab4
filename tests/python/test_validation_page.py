"""docs/validation.md cannot go stale: its tables are recomputed here by docs/make_validation.py (the same calls
as the tests each row names) and must equal the page, character for character; every row must be within its
tolerance."""

import importlib.util
from pathlib import Path

import numpy as np

DOCS = Path(__file__).resolve().parents[2] / "docs"


def load_generator():
    spec = importlib.util.spec_from_file_location("make_validation", DOCS / "make_validation.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_validation_tables_are_fresh_and_within_tolerance():
    gen = load_generator()
    tables, curves = gen.compute()
    rows = [r for rs in tables.values() for r in rs]
    assert len(rows) >= 30
    bad = [(r["quantity"], r["difference"], r["tolerance"]) for r in rows if not r["ratio"] <= 1.0]
    assert not bad, f"rows out of tolerance: {bad}"
    for r in rows:
        assert r["test"] and r["source"], r["quantity"]
    page = (DOCS / "validation.md").read_text(encoding="utf-8")
    on_page = gen.page_tables(page)
    fresh = gen.render(tables)
    if on_page != fresh:
        a, b = on_page.splitlines(), fresh.splitlines()
        diff = next((f"page: {x}\nfresh: {y}" for x, y in zip(a, b) if x != y), f"{len(a)} vs {len(b)} lines")
        raise AssertionError("docs/validation.md is stale; run PYTHONPATH=python python3 docs/make_validation.py\n"
                             + diff)
    # the figure's data: every point of every curve inside the tolerances
    for f, err in curves.values():
        assert max(e[0].max() for e in err.values()) < 0.1 and max(e[1].max() for e in err.values()) < 1.0
        assert f[0] == 10 and np.isclose(f[-1], 4000)
    assert (DOCS / "img" / "validation_bode_error.png").exists()
