"""Every notebook in notebooks/ runs top to bottom without error (executed with a real kernel) and draws a plot.

The notebooks are executed once per test run, by the documentation build (the session fixture ``docs_site`` in
conftest.py; myst-nb with nb_execution_raise_on_error, decision S5); these tests read the executed copies it
writes to ``jupyter_execute/tour/``.
"""

import pathlib

import nbformat
import pytest

NOTEBOOKS = sorted((pathlib.Path(__file__).resolve().parents[2] / "notebooks").glob("*.ipynb"))


def test_there_are_notebooks():
    assert NOTEBOOKS, "no notebooks found"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_title_is_numbered_like_its_file(path):
    """Issue 23.7: every title reads "# NN Title", NN the file's own number (01_quickstart.ipynb -> "# 01 ...")."""
    nb = nbformat.read(path, as_version=4)
    title = next(c for c in nb.cells if c.cell_type == "markdown").source.splitlines()[0]
    number = path.name.split("_")[0]
    assert number.isdigit() and len(number) == 2, path.name
    assert title.startswith(f"# {number} ") and title[len(number) + 3:][:1].isupper(), title


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, docs_site):
    executed = docs_site.executed / "tour" / path.name
    assert executed.exists(), f"the docs build did not execute {path.name}:\n{docs_site.log[-4000:]}"
    nb = nbformat.read(executed, as_version=4)
    source = nbformat.read(path, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code" and c.source.strip()]
    assert len(code) == sum(1 for c in source.cells if c.cell_type == "code" and c.source.strip())
    not_run = [i for i, c in enumerate(code) if c.get("execution_count") is None]
    assert not not_run, f"code cells {not_run} did not run"
    errors = [o for c in code for o in c.get("outputs", []) if o.output_type == "error"]
    assert not errors, "\n".join(f"{o.ename}: {o.evalue}" for o in errors)
    images = [o for c in code for o in c.get("outputs", [])
              if o.output_type in ("display_data", "execute_result") and "image/png" in o.get("data", {})]
    assert images, f"{path.name} drew no plot"
