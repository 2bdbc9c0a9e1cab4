import os
import pathlib
import re
import subprocess
import sys
import time
from dataclasses import dataclass

import matplotlib
import pytest

matplotlib.use("Agg")
os.environ.setdefault("MPLBACKEND", "Agg")
# the EMPS record for the guides and notebooks that run in temporary folders (servobench.examples.emps_path)
os.environ.setdefault("SERVOBENCH_EMPS_MAT", str(pathlib.Path(__file__).resolve().parents[1] / "data" / "emps" /
                                                 "DATA_EMPS.mat"))

ROOT = pathlib.Path(__file__).resolve().parents[2]


@dataclass
class DocsSite:
    """One build of the documentation site (docs/conf.py), shared by test_docs.py and test_notebooks.py."""

    html: pathlib.Path  # the site
    executed: pathlib.Path  # the notebooks as myst-nb executed them (<html>/../jupyter_execute)
    returncode: int
    log: str  # sphinx-build's stdout + stderr
    seconds: float

    @property
    def warnings(self) -> list[str]:
        """Sphinx's and docutils' warnings ("<where>: WARNING: ..."), not the kernels' own log lines."""
        return [line for line in self.log.splitlines() if re.search(r"(^|: )(WARNING|ERROR|CRITICAL|SEVERE): ", line)]


@pytest.fixture(scope="session")
def docs_site(tmp_path_factory) -> DocsSite:
    """Builds the site ONCE per test run: warnings as errors, every notebook of the tour executed by myst-nb (which
    fails the build on a cell error). The notebooks are executed here and nowhere else in the suite."""
    out = tmp_path_factory.mktemp("docs")
    html = out / "html"
    cmd = [sys.executable, "-m", "sphinx", "-E", "-W", "--keep-going", "-j", "auto", "-q", "-b", "html",
           str(ROOT / "docs"), str(html)]
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)  # the kernels must draw inline images, not into Agg
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=1800)
    seconds = time.perf_counter() - t0
    return DocsSite(html=html, executed=out / "jupyter_execute", returncode=proc.returncode,
                    log=proc.stdout + proc.stderr, seconds=seconds)
