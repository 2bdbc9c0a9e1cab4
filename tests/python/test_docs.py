"""The documentation site (docs/, Sphinx + myst-nb, decisions S1-S20) builds without a warning, has every page,
shows the notebooks' plots and documents every public name of servobench.

The site is built once per test run by the session fixture ``docs_site`` (conftest.py); that build is also the one
execution of the notebooks that test_notebooks.py checks.
"""

import pathlib
import re

import pytest

import servobench

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))

PAGES = [
    "index", "getting-started", "concepts", "filters", "motion", "paths", "bode", "autotune", "identify",
    "identify-emps", "card",
    "howto-tune", "howto-bode", "howto-identify", "howto-port", "howto-batch", "tour/index", "api/index", "cli",
    "decisions",
    "coverage", "validation", "benchmarks",
]
API_PAGES = ["axis", "batch", "design", "motion", "paths", "frequency", "autotune", "identify", "card", "plot", "widgets",
             "dialects",
             "dialect-gt", "dialect-ge", "dialect-gts", "dialect-aps"]
MODULES = ["servobench.batch", "servobench.frequency", "servobench.identify", "servobench.design", "servobench.plot", "servobench.card",
           "servobench.card_clock", "servobench.card_io",
           "servobench.autotune", "servobench.motion", "servobench.homing", "servobench.gearing", "servobench.pvt",
           "servobench.paths", "servobench.widgets", "servobench.interop", "servobench.dialects", "servobench.dialects.gt", "servobench.dialects.ge",
           "servobench.dialects.gts", "servobench.dialects.aps"]


@pytest.fixture(scope="module")
def site(docs_site):
    assert docs_site.returncode == 0, f"sphinx-build failed:\n{docs_site.log[-6000:]}"
    return docs_site


def _api_ids(html: pathlib.Path) -> set[str]:
    ids = set()
    for page in (html / "api").glob("*.html"):
        ids.update(re.findall(r'\bid="([^"]+)"', page.read_text(encoding="utf-8")))
    return ids


def test_site_builds_without_warnings(docs_site):
    print(f"docs build: {docs_site.seconds:.1f} s")
    assert docs_site.returncode == 0, f"sphinx-build failed:\n{docs_site.log[-6000:]}"
    assert not docs_site.warnings, "\n".join(docs_site.warnings)


@pytest.mark.parametrize("page", PAGES + [f"api/{p}" for p in API_PAGES])
def test_page_exists(site, page):
    assert (site.html / f"{page}.html").is_file()


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_page_shows_its_plots(site, path):
    page = site.html / "tour" / f"{path.stem}.html"
    text = page.read_text(encoding="utf-8")
    images = re.findall(r'<img[^>]+src="([^"]+)"', text)
    assert images, f"{page.name} has no image"
    for src in images:  # each image the page shows is in the site
        assert (page.parent / src).resolve().is_file(), src


def test_tour_index_lists_every_notebook_in_order(site):
    text = (site.html / "tour" / "index.html").read_text(encoding="utf-8")
    positions = [text.find(f'href="{p.stem}.html"') for p in NOTEBOOKS]
    assert all(pos >= 0 for pos in positions), [p.name for p, pos in zip(NOTEBOOKS, positions) if pos < 0]
    assert positions == sorted(positions)


def test_api_reference_documents_every_public_name(site):
    ids = _api_ids(site.html)
    missing = [name for name in servobench.__all__
               if not any(re.fullmatch(rf"(module-)?servobench(\.\w+)*\.{re.escape(name)}", i) for i in ids)]
    assert not missing, f"public names without an API entry: {missing}"


def test_api_reference_documents_the_modules(site):
    ids = _api_ids(site.html)
    assert not [m for m in MODULES if f"module-{m}" not in ids]


def test_api_reference_documents_the_dialect_commands(site):
    """The vendor commands are documented once, as the controller classes' methods (decision S6)."""
    from servobench.dialects import aps, ge, gt, gts

    ids = _api_ids(site.html)
    for module, controller, names in [(gt, "GtController", gt.GT_FUNCTIONS), (ge, "GeController", ge.GE_FUNCTIONS),
                                      (gts, "GtsController", gts.GTS_FUNCTIONS),
                                      (aps, "ApsController", aps.APS_FUNCTIONS)]:
        missing = [n for n in names if f"{module.__name__}.{controller}.{n}" not in ids]
        assert not missing, (module.__name__, missing[:10])


def test_long_code_lines_wrap(site):
    """Issue 23.7: the site's code blocks and notebook cells wrap long lines (docs/_static/wrap.css, linked from
    every page) instead of scrolling sideways."""
    css = (site.html / "_static" / "wrap.css").read_text()
    assert "white-space: pre-wrap" in css and ".highlight pre" in css
    for page in ("index.html", "identify.html", "tour/11_identify_real_machine.html"):
        assert "_static/wrap.css" in (site.html / page).read_text(encoding="utf-8"), page
