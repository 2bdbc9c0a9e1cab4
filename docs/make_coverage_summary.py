"""Reads docs/coverage.md and the five manual digests (../shared/spec beside the checkout) and rewrites the summary
table at the end of docs/coverage.md: per manual, how many sections are implemented / partly / not / n/a.
tests/python/test_coverage.py imports this module and checks the table in the file equals the one computed here.

Run: python docs/make_coverage_summary.py            (rewrites the summary in place)
     python docs/make_coverage_summary.py --check    (exit 1 if the summary is stale)
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
COVERAGE_MD = REPO / "docs" / "coverage.md"

# Digest file -> the manual's label in the table, in the order the table groups them (decision K2).
MANUALS = {"gt": "GT", "ge": "GE", "guc-ecat": "GUC-ECAT", "ideabox": "iDEABOX", "adlink": "ADLINK"}
STATUSES = ("implemented", "partly", "not", "n/a")

SUMMARY_HEADING = "## Summary"

_HEADING = re.compile(r"^(#{2,3}) (.*\S)\s*$")
_NUMBERED = re.compile(r"^(\d+(?:\.\d+)?)\.?\s+(.*)$")
_LREF = re.compile(r"\bL(\d+)(?:\s*[-–]\s*(\d+))?")


def spec_dir() -> Path | None:
    """The digests: <repo>/../shared/spec (beside the checkout in CI and on the dev machine), or None."""
    for base in (REPO.parent / "shared", REPO.parent.parent / "shared"):
        if (base / "spec" / "gt.md").is_file():
            return base / "spec"
    return None


def line_refs(text: str) -> str:
    """The manual line references of a text, normalised: 'L1029–1090, L4407–4437'."""
    refs = []
    for m in _LREF.finditer(text):
        ref = f"L{m.group(1)}" + (f"–{m.group(2)}" if m.group(2) else "")
        if ref not in refs:
            refs.append(ref)
    return ", ".join(refs)


@dataclass
class Section:
    """One ## / ### heading of a digest (decision K1)."""
    manual: str          # "GT"
    key: str             # "GT §3.4" (numbered) or "GUC-ECAT Return codes" (unnumbered)
    heading: str         # the heading text without the #'s
    heading_lines: str   # line references in the heading ('' if none)
    body_lines: str      # the first line references of the section body (used when the heading has none)
    digest_line: int     # line of the heading in the digest


def unnumbered_key(manual: str, heading: str) -> str:
    name = re.split(r"[:(\[]", heading)[0].strip()
    return f"{manual} {name}"


def digest_sections(spec: Path) -> list[Section]:
    """Every ## and ### heading of the five digests, in digest order, grouped by manual."""
    out: list[Section] = []
    for stem, manual in MANUALS.items():
        lines = (spec / f"{stem}.md").read_text(encoding="utf-8").splitlines()
        heads = []
        in_code = False
        for i, line in enumerate(lines):
            if line.startswith("```"):
                in_code = not in_code
            m = None if in_code else _HEADING.match(line)
            if m:
                heads.append((i, m.group(2)))
        for n, (i, text) in enumerate(heads):
            end = heads[n + 1][0] if n + 1 < len(heads) else len(lines)
            num = _NUMBERED.match(text)
            key = f"{manual} §{num.group(1)}" if num else unnumbered_key(manual, text)
            body = line_refs("\n".join(lines[i + 1:end]))
            out.append(Section(manual, key, text, line_refs(text), ", ".join(body.split(", ")[:3]) if body else "",
                               i + 1))
    return out


@dataclass
class Row:
    section: str
    title: str
    lines: str
    status: str
    what: str
    proof: str
    line_no: int
    manual: str = field(default="")


def _cells(line: str) -> list[str]:
    body = line.strip()
    assert body.startswith("|") and body.endswith("|"), line
    return [c.strip() for c in body[1:-1].split("|")]


def coverage_rows(md: str) -> list[Row]:
    """The rows of the per-manual section tables (the tables whose header starts with '| section |')."""
    rows: list[Row] = []
    lines = md.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("| section |"):
            header = _cells(lines[i])
            assert header == ["section", "title", "manual lines", "status", "what is and is not implemented",
                              "proof"], f"coverage.md line {i + 1}: unexpected header {header}"
            i += 2  # header and the |---| line
            while i < len(lines) and lines[i].startswith("|"):
                c = _cells(lines[i])
                assert len(c) == 6, f"coverage.md line {i + 1}: {len(c)} cells, expected 6"
                rows.append(Row(c[0], c[1], c[2], c[3], c[4], c[5], i + 1, c[0].split(" ")[0]))
                i += 1
        else:
            i += 1
    return rows


def summary_table(rows: list[Row]) -> str:
    """Per manual: the count of rows in each status, and the total."""
    head = "| manual | " + " | ".join(STATUSES) + " | sections |"
    out = [head, "|---|" + "---:|" * (len(STATUSES) + 1)]
    totals = dict.fromkeys(STATUSES, 0)
    for manual in MANUALS.values():
        counts = {s: sum(1 for r in rows if r.manual == manual and r.status == s) for s in STATUSES}
        for s in STATUSES:
            totals[s] += counts[s]
        out.append(f"| {manual} | " + " | ".join(str(counts[s]) for s in STATUSES) + f" | {sum(counts.values())} |")
    out.append("| all | " + " | ".join(str(totals[s]) for s in STATUSES) + f" | {sum(totals.values())} |")
    return "\n".join(out)


def _summary_span(md: str) -> tuple[int, int] | None:
    """Line span [start, end) of the table that follows the '## Summary' heading, or None."""
    lines = md.splitlines()
    try:
        h = lines.index(SUMMARY_HEADING)
    except ValueError:
        return None
    start = next((i for i in range(h + 1, len(lines)) if lines[i].startswith("|")), None)
    if start is None:
        return None
    end = start
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    return start, end


def summary_in_file(md: str) -> str | None:
    """The summary table under '## Summary' in coverage.md, or None if there is none."""
    span = _summary_span(md)
    return None if span is None else "\n".join(md.splitlines()[span[0]:span[1]])


def with_summary(md: str) -> str:
    """coverage.md with its summary table recomputed from its rows."""
    start, end = _summary_span(md)
    lines = md.splitlines()
    lines[start:end] = summary_table(coverage_rows(md)).splitlines()
    return "\n".join(lines) + ("\n" if md.endswith("\n") else "")


def main(argv: list[str]) -> int:
    md = COVERAGE_MD.read_text(encoding="utf-8")
    if summary_in_file(md) is None:
        print(f"{COVERAGE_MD}: no table under {SUMMARY_HEADING!r}", file=sys.stderr)
        return 1
    new = with_summary(md)
    if "--check" in argv:
        if new != md:
            print("docs/coverage.md: the summary is stale; run python docs/make_coverage_summary.py", file=sys.stderr)
            return 1
        return 0
    if new != md:
        COVERAGE_MD.write_text(new, encoding="utf-8")
    print(summary_table(coverage_rows(new)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
