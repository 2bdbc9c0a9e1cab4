"""The README's code runs as a reader runs it: every fenced ```python block, top to bottom, in one namespace, in a
fresh folder (issue 23.1). A block that is meant to be read, not run, would carry ``# not run`` as its first line;
the README has none."""

from __future__ import annotations

from pathlib import Path

import pytest

from test_guides import python_blocks

README = Path(__file__).resolve().parents[2] / "README.md"


def test_readme_python_blocks_run_top_to_bottom(tmp_path, monkeypatch):
    blocks = python_blocks(README.read_text(encoding="utf-8"))
    assert len(blocks) >= 5, "the README's Use section has lost its examples"
    assert all(runs for _line, _code, runs in blocks), "every README block runs (none is marked 'not run')"
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    namespace: dict = {"__name__": "readme"}
    try:
        for line, code, _runs in blocks:
            try:
                exec(compile(code, f"{README}:{line}", "exec"), namespace)
            except Exception as e:  # name the block's line
                raise AssertionError(f"README.md, code block at line {line} failed: {type(e).__name__}: {e}") from e
    finally:
        plt.close("all")
    assert (tmp_path / "move.png").stat().st_size > 0
    assert namespace["meas"].margins().stable, "the README's reference axis is a stable loop"
