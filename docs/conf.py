"""Sphinx configuration of the servobench documentation site (issue 11; decisions S1-S20 in decisions.md).

Build: ``bash scripts/docs.sh`` (or ``python -m sphinx -W --keep-going -b html docs build/site``).

The pages are MyST Markdown; the numbered notebooks of ``notebooks/`` are copied into ``docs/tour/`` (git-ignored)
when the build starts and executed by myst-nb, so their plots are in the site (S4, S5).
"""

from __future__ import annotations

import os
import pathlib
import shutil
import sys

DOCS = pathlib.Path(__file__).resolve().parent
ROOT = DOCS.parent
NOTEBOOKS = ROOT / "notebooks"
TOUR = DOCS / "tour"

# -- the package: from the source tree when its C++ module has been built there, else the installed one (S3) --------
_src = ROOT / "python"
if any((_src / "servobench").glob("_core*.so")) or any((_src / "servobench").glob("_core*.pyd")):
    sys.path.insert(0, str(_src))
    # The notebook kernels are separate processes: they must find the same package.
    _pp = os.environ.get("PYTHONPATH", "")
    if str(_src) not in _pp.split(os.pathsep):
        os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (str(_src), _pp) if p)
# Plots must come out of the kernels as images: a non-interactive backend inherited from the caller (pytest sets
# MPLBACKEND=Agg) would swallow them.
os.environ.pop("MPLBACKEND", None)
# The EMPS benchmark's record for the identification notebook (servobench.examples.emps_path).
os.environ.setdefault("SERVOBENCH_EMPS_MAT", str(ROOT / "tests" / "data" / "emps" / "DATA_EMPS.mat"))

import servobench  # noqa: E402  (after the path set-up above)

# -- project ----------------------------------------------------------------------------------------------------
project = "servobench"
author = "the servobench authors"
copyright = "the servobench authors"
release = servobench.__version__
version = release

# -- general ----------------------------------------------------------------------------------------------------
extensions = [
    "myst_nb",  # MyST Markdown pages and executed notebooks (includes myst_parser)
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}
root_doc = "index"
exclude_patterns = ["_build", "**.ipynb_checkpoints"]
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
# S8: the API objects are not entries of the pages' tables of contents: with them every page's navigation copies
# ~1000 entries and the build takes twice as long; the API pages have their own section headings.
toc_object_entries = False
nitpicky = False  # S7: references to NumPy/matplotlib types would each need an intersphinx round trip

# -- autodoc (S6) ---------------------------------------------------------------------------------------------------
autodoc_default_options = {"members": True}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_docstring_signature = True  # pybind11 puts the signature on the docstring's first line
autoclass_content = "class"
napoleon_numpy_docstring = True
napoleon_google_docstring = True

# -- notebooks (S4, S5) -----------------------------------------------------------------------------------------------
nb_execution_mode = "force"  # the committed notebooks carry no outputs
nb_execution_timeout = 600
nb_execution_raise_on_error = True  # a broken notebook fails the build, loudly
nb_execution_in_temp = True  # files a notebook writes go to a temporary directory, not into docs/
nb_execution_show_tb = True
nb_merge_streams = True

# -- HTML -------------------------------------------------------------------------------------------------------
html_theme = "furo"
html_title = f"servobench {release}"
html_static_path = ["_static"]
html_css_files = ["wrap.css"]  # long code lines wrap (issue 23.7)
html_show_sourcelink = False


def _copy_tour(app):
    """Copies notebooks/*.ipynb into docs/tour/ (git-ignored), only when changed so incremental builds stay
    incremental; removes copies whose notebook is gone."""
    TOUR.mkdir(exist_ok=True)
    wanted = {p.name: p for p in sorted(NOTEBOOKS.glob("*.ipynb"))}
    for stale in TOUR.glob("*.ipynb"):
        if stale.name not in wanted:
            stale.unlink()
    for name, src in wanted.items():
        dst = TOUR / name
        if not dst.exists() or dst.read_bytes() != src.read_bytes():
            shutil.copyfile(src, dst)


def _skip_member(app, what, name, obj, skip, options):
    """S6: a submodule's member that ``servobench`` re-exports is documented once, under its top-level name (the
    API pages list those explicitly); a dialect's free vendor functions (``GT_*``, ``APS_*``) are the controller's
    methods again (with a ``*args, **kwargs`` signature), so only the controller class documents them."""
    if what != "module":
        return None
    if name in servobench.__all__ and getattr(servobench, name, None) is obj:
        return True
    if callable(obj) and getattr(obj, "__module__", "") == "servobench.dialects._controller" and name[:1].isupper():
        return True
    return None


def setup(app):
    app.connect("builder-inited", _copy_tour)
    app.connect("autodoc-skip-member", _skip_member)
