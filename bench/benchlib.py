"""Shared pieces of the benchmarks in bench/: the Figure record, peer imports and the result files.

Every bench_<topic>.py has a function ``run(quick=False, ...) -> Result`` that measures and returns its figures (each
servobench figure with its peer's figure from the same run and the goal from its issue) and its Markdown table. Run
as a script, a bench prints the table and writes ``bench/results/<name>.md`` and ``bench/results/<topic>.json``
(the figures, read by ``bench/run_all.py`` for ``bench/results/summary.md``).

Peers (SciPy, python-control, Ruckig) come from PyPI. ``bash scripts/bench.sh`` installs them all with the package
(``pip install ".[bench]"``). A bench run on its own installs a missing peer into build/bench-deps (never into the
shared site-packages, never vendored). With the environment variable ``SERVOBENCH_BENCH_NO_INSTALL=1`` (set by
run_all.py) nothing is installed: a missing peer is reported as "not installed" and its rows stay in the tables.
``SERVOBENCH_BENCH_HIDE_PEERS=ruckig,scipy`` makes the named modules look missing (for tests of that path).
"""

from __future__ import annotations

import dataclasses
import datetime
import importlib
import json
import math
import os
import pathlib
import platform
import subprocess
import sys
from typing import Optional

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "results"
DEPS = ROOT / "build" / "bench-deps"

NOT_INSTALLED = "not installed"
MEASURED = "measured"
NO_PEER = "none"


@dataclasses.dataclass
class Figure:
    """One servobench figure against its peer in the same run and against its goal.

    value, peer_value and goal are in ``unit``. ``ratio`` is the speed-up of servobench over the peer (> 1: servobench
    is faster): value / peer_value when higher is better (a rate), peer_value / value when lower is better (a time).
    ``goal_on`` says whether the goal bounds the value ("value": <= goal for a time, >= goal for a rate) or the
    speed-up ("ratio": ratio >= goal).
    """

    benchmark: str
    figure: str
    unit: str
    value: float
    higher_is_better: bool
    peer: Optional[str] = None
    peer_value: Optional[float] = None
    peer_status: str = NO_PEER  # "measured", "not installed", or "none" (no peer does this work)
    goal: Optional[float] = None
    goal_on: str = "value"
    goal_source: str = ""
    note: str = ""

    def __post_init__(self):
        if self.peer_status not in (MEASURED, NOT_INSTALLED, NO_PEER):
            raise ValueError(f"Figure.peer_status = {self.peer_status!r} is not measured/not installed/none")
        if self.goal_on not in ("value", "ratio"):
            raise ValueError(f"Figure.goal_on = {self.goal_on!r} is not 'value' or 'ratio'")
        if self.peer_status == MEASURED and self.peer_value is None:
            raise ValueError(f"{self.figure}: a measured peer needs a peer_value")

    @property
    def ratio(self) -> Optional[float]:
        if self.peer_status != MEASURED or not self.peer_value or not self.value:
            return None
        return self.value / self.peer_value if self.higher_is_better else self.peer_value / self.value

    @property
    def goal_met(self) -> Optional[bool]:
        if self.goal is None:
            return None
        if self.goal_on == "ratio":
            r = self.ratio
            return None if r is None else r >= self.goal
        return self.value >= self.goal if self.higher_is_better else self.value <= self.goal

    def to_dict(self) -> dict:
        d = dataclasses.asdict(self)
        d["ratio"] = self.ratio
        d["goal_met"] = self.goal_met
        return d

    @classmethod
    def from_dict(cls, d: dict) -> "Figure":
        names = {f.name for f in dataclasses.fields(cls)}
        return cls(**{k: v for k, v in d.items() if k in names})


def peer_figure(peer: str, module, fn) -> dict:
    """Figure keywords for a peer: {peer, peer_value, peer_status} -- ``fn()`` gives the value when ``module`` (the
    imported peer, or None when it is not installed) is there."""
    if module is None:
        return dict(peer=peer, peer_value=None, peer_status=NOT_INSTALLED)
    return dict(peer=peer, peer_value=float(fn()), peer_status=MEASURED)


@dataclasses.dataclass
class Result:
    """What one bench run returns: its topic, its figures, its Markdown table (file name and text) and the peers'
    versions ("not installed" for a missing one)."""

    topic: str
    script: str
    markdown_name: str
    markdown: str
    figures: list
    quick: bool = False
    peers: dict = dataclasses.field(default_factory=dict)
    generated: str = dataclasses.field(
        default_factory=lambda: datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"))

    def to_dict(self) -> dict:
        return dict(topic=self.topic, script=self.script, markdown=self.markdown_name, generated=self.generated,
                    quick=self.quick, peers=self.peers, figures=[f.to_dict() for f in self.figures])


def write_result(result: Result, results_dir=None) -> pathlib.Path:
    """Writes <markdown_name> and <topic>.json into results_dir (default bench/results); returns the JSON path."""
    out = pathlib.Path(results_dir) if results_dir else RESULTS
    out.mkdir(parents=True, exist_ok=True)
    (out / result.markdown_name).write_text(result.markdown)
    path = out / f"{result.topic}.json"
    path.write_text(json.dumps(result.to_dict(), indent=1, allow_nan=False) + "\n")
    return path


def add_common_args(ap) -> None:
    ap.add_argument("--quick", action="store_true",
                    help="tiny sizes and one repeat (for the tests: the figures say nothing about speed)")
    ap.add_argument("--results-dir", default=None, help="where the .md and .json go (default bench/results)")


def sizes(args, full: dict, quick: dict) -> dict:
    """The run's sizes: the quick or full defaults, overridden by any size given on the command line."""
    out = dict(quick if args.quick else full)
    for k in full:
        v = getattr(args, k, None)
        if v is not None:
            out[k] = v
    return out


def _hidden() -> set:
    return {s.strip() for s in os.environ.get("SERVOBENCH_BENCH_HIDE_PEERS", "").split(",") if s.strip()}


def install_allowed() -> bool:
    return os.environ.get("SERVOBENCH_BENCH_NO_INSTALL", "") not in ("1", "true", "yes")


def import_peer(name: str, pip_name: str):
    """Imports a peer module (e.g. "scipy.signal"). Missing: installed with pip into build/bench-deps when installs
    are allowed (a bench run on its own), else None (run_all.py, SERVOBENCH_BENCH_NO_INSTALL=1)."""
    if name.split(".")[0] in _hidden():
        return None
    try:
        return importlib.import_module(name)
    except ImportError:
        pass
    if str(DEPS) not in sys.path:
        sys.path.insert(0, str(DEPS))
    try:
        return importlib.import_module(name)
    except ImportError:
        if not install_allowed():
            return None
    subprocess.check_call([sys.executable, "-m", "pip", "install", "--quiet", "--target", str(DEPS), pip_name])
    importlib.invalidate_caches()  # the path entry was cached before the install created the package
    return importlib.import_module(name)


def version(module) -> str:
    if module is None:
        return NOT_INSTALLED
    top = importlib.import_module(module.__name__.split(".")[0])
    return str(getattr(top, "__version__", "?"))


def machine() -> str:
    """CPU model and platform, for the tables' headers."""
    model = platform.processor() or platform.machine()
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {platform.machine()}"


def fmt(v: Optional[float]) -> str:
    """Three significant digits, never in exponent form (1234 -> "1,234", 9.104 -> "9.10", 0.06342 -> "0.0634")."""
    if v is None or not math.isfinite(v):
        return "-"
    if v == 0:
        return "0"
    decimals = max(0, 2 - int(math.floor(math.log10(abs(v)))))
    return f"{v:,.{decimals}f}"
