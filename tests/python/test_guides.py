"""The docs' code runs: every fenced ```python block of every page of docs/ (getting started, concepts, the how-to
guides and the reference pages: each page that has Python code, found by scanning docs/, issue 23.1) is executed,
page by page (one namespace per page, blocks in order, in a fresh folder), so a page cannot show code that fails.

A block that is meant to be read, not run (it needs a real card, a file the reader brings, or is a fragment),
is marked by the MyST comment line ``% not run`` right above its fence, or by ``# not run`` as its first line.
Such blocks are counted: each page keeps only a few of them."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"
#: The pages known to carry Python code; every other page with a ```python block is found by the scan below.
GUIDES = ["getting-started.md", "concepts.md", "howto-tune.md", "howto-bode.md", "howto-identify.md",
          "howto-port.md", "identify-emps.md", "howto-batch.md", "card.md", "filters.md", "identify.md", "motion.md",
          "paths.md", "widgets.md", "lti-plant.md", "results-io.md"]
MAX_NOT_RUN = 3  # per page

FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>```+|~~~+)\s*(?P<lang>[^\s`]*)[^\n]*$")


def python_blocks(text: str):
    """The page's fenced code blocks in Python: list of (line number, code, runs?)."""
    lines = text.splitlines()
    out, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, lang, start = m["fence"], m["lang"].strip("{}").lower(), i
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            j += 1
        body = "\n".join(lines[start + 1:j])
        if lang in ("python", "py", "python3"):
            prev = next((lines[k].strip() for k in range(start - 1, -1, -1) if lines[k].strip()), "")
            first = body.lstrip().splitlines()[0].strip() if body.strip() else ""
            runs = not (prev.lower().startswith("% not run") or first.lower().startswith("# not run"))
            out.append((start + 1, body, runs))
        i = j + 1
    return out


def _pages_with_code() -> list[str]:
    """Every docs page (docs/**/*.md) with at least one ```python block, relative to docs/."""
    found = [p.relative_to(DOCS).as_posix() for p in sorted(DOCS.rglob("*.md"))
             if "_build" not in p.parts and python_blocks(p.read_text(encoding="utf-8"))]
    return sorted(set(found) | set(GUIDES), key=lambda p: (p not in GUIDES, GUIDES.index(p) if p in GUIDES else 0, p))


PAGES = _pages_with_code()


def test_every_page_with_code_is_run():
    assert set(GUIDES) <= set(PAGES), "a guide lost its code or its file"
    assert len(PAGES) >= len(GUIDES)
    # issue 23.1: every block runs as a reader runs it -- none opted out with "% not run" / "# not run"
    skipped = [(page, line) for page in PAGES for line, _, runs in python_blocks((DOCS / page).read_text("utf-8"))
               if not runs]
    assert not skipped, f"code blocks that do not run: {skipped}"


@pytest.mark.parametrize("page", PAGES)
def test_page_code_runs(page, tmp_path, monkeypatch):
    path = DOCS / page
    blocks = python_blocks(path.read_text(encoding="utf-8"))
    assert blocks, f"{page} has no python code"
    skipped = [line for line, _code, runs in blocks if not runs]
    assert len(skipped) <= MAX_NOT_RUN, f"{page}: too many blocks marked 'not run' (lines {skipped})"
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    namespace: dict = {"__name__": f"docs_{path.stem.replace('-', '_')}"}
    try:
        for line, code, runs in blocks:
            if not runs:
                continue
            try:
                exec(compile(code, f"{path}:{line}", "exec"), namespace)
            except Exception as e:  # name the page and the block's line
                raise AssertionError(f"{page}, code block at line {line} failed: {type(e).__name__}: {e}") from e
    finally:
        plt.close("all")


@pytest.mark.parametrize("page", PAGES)
def test_page_structure(page):
    # One top-level heading, no skipped levels, relative links only to docs pages or images that exist.
    text = (DOCS / page).read_text(encoding="utf-8")
    in_code, levels = False, []
    for line in text.splitlines():
        if FENCE.match(line):
            in_code = not in_code
            continue
        if not in_code and (m := re.match(r"^(#{1,6}) ", line)):
            levels.append(len(m[1]))
    assert levels and levels[0] == 1 and levels.count(1) == 1, f"{page}: one '# ' heading, first"
    for a, b in zip(levels, levels[1:]):
        assert b <= a + 1, f"{page}: heading level jumps from {a} to {b}"
    no_code = re.sub(r"```.*?```", "", text, flags=re.S)
    for target in re.findall(r"\]\(([^)\s]+)\)", no_code):
        if re.match(r"^[a-z]+://", target) or target.startswith("#"):
            continue
        file = target.split("#")[0]
        assert (DOCS / file).exists(), f"{page}: link to {target} does not exist"
        assert (DOCS / file).resolve().is_relative_to(DOCS), f"{page}: link {target} leaves docs/"


def test_block_extraction():
    text = "# T\n\n```python\nx = 1\n```\n\n% not run\n```python\nraise SystemExit\n```\n```bash\nls\n```\n" \
           "```python\n# not run\nboom()\n```\n"
    blocks = python_blocks(text)
    assert [(b[1], b[2]) for b in blocks] == [("x = 1", True), ("raise SystemExit", False),
                                            ("# not run\nboom()", False)]
