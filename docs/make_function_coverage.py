"""Function-level coverage of the five vendor manuals (issue 25.3): every function a manual names, whether its
dialect defines it, whether it is a call the simulation cannot carry out (it then returns the vendor's error code,
with the reason), and whether a test or a vendor program run by the tests calls it. Writes the tables into
docs/coverage.md between the two markers below; tests/python/test_function_coverage.py checks them and the
thresholds (>= 95 % of the names exist, >= 90 % are exercised, per manual).

Where the names come from (decision K9): every ``GT_<Name>`` / ``APS_<name>`` token of the manual's text in
``../shared/seeds/`` (Markdown escapes ``\\_`` read as ``_``), with the line it first appears on. The OCR of the
manuals misspells some names (``GT_ClosLp`` for ``GT_CloseLp``) and uses the prefix for things that are not
functions (the card model ``GT_PX``, a user's ISR ``GT_ISR``); these are classified once, by hand, in
``tests/data/manual_functions/<manual>.tsv`` with the manual line, and left out of the counts. The repository does
not need ``../shared``: the classified lists are committed; when the seeds are beside the checkout, the test checks
the lists name exactly the tokens the seeds contain.

Run: python docs/make_function_coverage.py            (rewrites the section of docs/coverage.md)
     python docs/make_function_coverage.py --check    (exit 1 if it is stale)
     python docs/make_function_coverage.py --extract  (prints the tokens of the seeds not yet classified)
"""

from __future__ import annotations

import ast
import csv
import importlib
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
COVERAGE_MD = REPO / "docs" / "coverage.md"
LISTS = REPO / "tests" / "data" / "manual_functions"
BEGIN = "<!-- function-coverage:begin (python docs/make_function_coverage.py) -->"
END = "<!-- function-coverage:end -->"

# manual label -> (seed file prefix, list stem, dialect module, name prefix)
MANUALS = {
    "GT": ("000_", "gt", "servobench.dialects.gt", "GT_"),
    "GE": ("001_", "ge", "servobench.dialects.ge", "GT_"),
    "GUC-ECAT": ("002_", "guc-ecat", "servobench.dialects.gts", "GT_"),
    "iDEABOX": ("003_", "ideabox", "servobench.dialects.gts", "GT_"),
    "ADLINK": ("004_", "adlink", "servobench.dialects.aps", "APS_"),
}
KINDS = ("function", "typo", "not-a-function")
_TOKEN = re.compile(r"\b(GT|APS)_[A-Za-z][A-Za-z0-9_]*")


def seeds_dir() -> Path | None:
    """The manuals: <repo>/../shared/seeds (beside the checkout in CI and on the dev machine), or None."""
    for base in (REPO.parent / "shared", REPO.parent.parent / "shared"):
        if (base / "seeds" / "README.md").is_file():
            return base / "seeds"
    return None


def extract(text: str, prefix: str) -> dict[str, int]:
    """Every ``prefix``-token of a manual's text -> the 1-based line it first appears on."""
    first: dict[str, int] = {}
    for n, line in enumerate(text.splitlines(), 1):
        for m in _TOKEN.finditer(line.replace("\\_", "_")):
            name = m.group(0).rstrip("_")
            if name.startswith(prefix) and name not in first:
                first[name] = n
    return first


def seed_tokens(manual: str, seeds: Path) -> dict[str, int]:
    prefix_file, _, _, prefix = MANUALS[manual]
    (path,) = sorted(seeds.glob(prefix_file + "*.txt"))
    return extract(path.read_text(encoding="utf-8"), prefix)


@dataclass
class Entry:
    """One classified token of a manual: a function, a misspelling of one (`note` = the name meant), or a token
    that is not a function (`note` = what it is)."""
    name: str
    line: int
    kind: str
    note: str = ""


def load_list(manual: str) -> list[Entry]:
    path = LISTS / f"{MANUALS[manual][1]}.tsv"
    with path.open(encoding="utf-8", newline="") as f:
        rows = [r for r in csv.reader(f, delimiter="\t") if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    assert header == ["name", "line", "kind", "note"], f"{path}: header {header}"
    return [Entry(r[0], int(r[1]), r[2], r[3] if len(r) > 3 else "") for r in body]


# ---------------------------------------------------------------------------------------------------------- calls
_SOURCES = ("tests/python", "examples/vendor_programs")


def _imports_dialect(tree: ast.AST, module: str) -> bool:
    """Whether a file imports `module` (``from servobench.dialects.gt import ...``, ``from servobench.dialects import
    gt``), the dialects package (``from servobench import dialects``) or any dialect module by ``import``."""
    short = module.rsplit(".", 1)[1]
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            if node.module == module or (node.module == "servobench.dialects"
                                         and any(a.name == short for a in node.names)):
                return True
            if node.module == "servobench" and any(a.name == "dialects" for a in node.names):
                return True
        if isinstance(node, ast.Import) and any(a.name.startswith("servobench.dialects") for a in node.names):
            return True
    return False


def called_names(module: str) -> dict[str, list[str]]:
    """Name -> the files (repo-relative) that call it, among the test files and vendor programs that import the
    dialect `module` as :func:`_imports_dialect` reads it (a call ``f(...)``, ``gt.f(...)`` or ``ctl.f(...)``)."""
    out: dict[str, list[str]] = {}
    for base in _SOURCES:
        for path in sorted((REPO / base).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
            if not _imports_dialect(tree, module):
                continue
            rel = str(path.relative_to(REPO))
            for node in ast.walk(tree):
                if isinstance(node, ast.Call):
                    f = node.func
                    name = f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else None
                    if name and name.startswith(("GT_", "APS_")):
                        files = out.setdefault(name, [])
                        if rel not in files:
                            files.append(rel)
    return out


# -------------------------------------------------------------------------------------------------------- figures
@dataclass
class ManualCoverage:
    manual: str
    module: str
    names: list[str]
    missing: list[str]
    unsupported: dict[str, str]        # defined, returns the vendor's error code: name -> reason
    unexercised: list[str]
    typos: list[Entry] = field(default_factory=list)
    others: list[Entry] = field(default_factory=list)

    @property
    def exist(self) -> int:
        return len(self.names) - len(self.missing)

    @property
    def exercised(self) -> int:
        return len(self.names) - len(self.unexercised)

    def pct(self, n: int) -> float:
        return 100.0 * n / len(self.names)


def measure(manual: str) -> ManualCoverage:
    _, _, module_name, _ = MANUALS[manual]
    module = importlib.import_module(module_name)
    entries = load_list(manual)
    names = [e.name for e in entries if e.kind == "function"]
    missing = [n for n in names if not callable(getattr(module, n, None))]
    table = getattr(module, "UNSUPPORTED", {})
    unsupported = {n: table[n] for n in names if n in table and n not in missing}
    calls = called_names(module_name)
    unexercised = [n for n in names if n not in calls]
    return ManualCoverage(manual, module_name, names, missing, unsupported, unexercised,
                          [e for e in entries if e.kind == "typo"], [e for e in entries if e.kind == "not-a-function"])


def _names(items) -> str:
    return ", ".join(f"`{n}`" for n in items) if items else "none"


def section(cov: list[ManualCoverage]) -> str:
    out = [BEGIN, "## Functions named in the manuals", "",
           "Every function name of the five manuals (issue 25.3; decision K9 says how the names are extracted and "
           "classified), against its dialect module. **exist**: the dialect defines it; **error code**: of those, "
           "the calls the simulation cannot carry out, which return the vendor's error code (the reasons are listed "
           "below); **exercised**: called by a test in `tests/python/` or by a manual program in "
           "`examples/vendor_programs/` (run by the tests) that imports the dialect. "
           "Rewritten by `python docs/make_function_coverage.py`; `tests/python/test_function_coverage.py` checks "
           "it is current and that, per manual, at least 95 % exist and 90 % are exercised.", "",
           "| manual | dialect | names | exist | error code | exercised | misspellings | not functions |",
           "|---|---|---:|---:|---:|---:|---:|---:|"]
    for c in cov:
        out.append(f"| {c.manual} | `{c.module}` | {len(c.names)} | {c.exist} ({c.pct(c.exist):.1f} %) | "
                   f"{len(c.unsupported)} | {c.exercised} ({c.pct(c.exercised):.1f} %) | {len(c.typos)} | "
                   f"{len(c.others)} |")
    for c in cov:
        out += ["", f"### {c.manual} functions", "",
                f"- missing from `{c.module}`: {_names(c.missing)}",
                f"- not exercised by a test: {_names(c.unexercised)}"]
        if c.unsupported:
            out.append("- return the vendor's error code:")
            out += [f"  - `{n}`: {why}" for n, why in sorted(c.unsupported.items())]
        if c.typos:
            out.append("- misspelt in the manual (line: as printed → as meant): "
                       + "; ".join(f"L{e.line} `{e.name}` → `{e.note}`" for e in c.typos))
        if c.others:
            out.append("- not functions: " + "; ".join(f"L{e.line} `{e.name}` ({e.note})" for e in c.others))
    out.append(END)
    return "\n".join(out)


def with_section(md: str, text: str) -> str:
    if BEGIN in md:
        head, rest = md.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        return head + text + tail
    return md.rstrip("\n") + "\n\n" + text + "\n"


def main(argv: list[str]) -> int:
    if "--extract" in argv:
        seeds = seeds_dir()
        if seeds is None:
            print("../shared/seeds is not beside the checkout", file=sys.stderr)
            return 1
        for manual, (_, stem, _, _) in MANUALS.items():
            path = LISTS / f"{stem}.tsv"
            known = {e.name for e in load_list(manual)} if path.is_file() else set()
            for name, line in sorted(seed_tokens(manual, seeds).items()):
                if name not in known:
                    print(f"{manual}\t{name}\t{line}")
        return 0
    cov = [measure(m) for m in MANUALS]
    md = COVERAGE_MD.read_text(encoding="utf-8")
    new = with_section(md, section(cov))
    if "--check" in argv:
        if new != md:
            print("docs/coverage.md: the function coverage is stale; run python docs/make_function_coverage.py",
                  file=sys.stderr)
            return 1
        return 0
    if new != md:
        COVERAGE_MD.write_text(new, encoding="utf-8")
    for c in cov:
        print(f"{c.manual:9s} names {len(c.names):3d}  exist {c.pct(c.exist):5.1f} %  error-code "
              f"{len(c.unsupported):2d}  exercised {c.pct(c.exercised):5.1f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
