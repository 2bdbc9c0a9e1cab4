"""Makes docs/img/widgets_tuner.png: notebook 13 (the tuning panel) served by Voila and photographed in headless
Chromium, and docs/img/widgets_tuner.json, what the browser measured on the page (how many sliders were visible and
how wide, the versions, the PNG's SHA-256). Run once by hand after a change to the panel's look, then commit both
files; the test suite does not need a browser (tests/python/test_widgets.py drives the panel headless and checks the
committed picture against its record).

Works offline: Voila (PyPI) serves the notebook with its own bundled widget manager (no CDN; the only failed requests
are Font Awesome's CSS on jsdelivr, which the panel does not use), and playwright (PyPI) drives Debian's Chromium
through `executable_path` (no browser download).

Needs: `apt-get install -y chromium` and `pip install voila playwright` in the environment where servobench is
installed. Run from the source tree:  python docs/make_widgets_screenshot.py [--chromium /usr/bin/chromium]
"""

from __future__ import annotations

import argparse
import hashlib
import json
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "13_tuning_panel.ipynb"
OUT = ROOT / "docs" / "img" / "widgets_tuner.png"
RECORD = OUT.with_suffix(".json")
#: Every slider of the panel on the page: its width and height in CSS px (0 x 0 when hidden or collapsed).
_MEASURE = """() => Array.from(document.querySelectorAll('.widget-vbox .widget-slider')).map(e => {
    const r = e.getBoundingClientRect(); return [Math.round(r.width), Math.round(r.height)]; })"""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    ap.add_argument("--timeout-s", type=float, default=600.0)
    args = ap.parse_args(argv)
    from playwright.sync_api import sync_playwright

    port = _free_port()
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(NOTEBOOK, work)
        voila = subprocess.Popen([sys.executable, "-m", "voila", NOTEBOOK.name, "--no-browser", f"--port={port}",
                                  "--Voila.ip=127.0.0.1", "--theme=light", "--show_tracebacks=True"], cwd=work)
        try:
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                try:
                    socket.create_connection(("127.0.0.1", port), timeout=1).close()
                    break
                except OSError:
                    time.sleep(0.5)
            with sync_playwright() as p:
                browser = p.chromium.launch(executable_path=args.chromium, headless=True,
                                            args=["--no-sandbox", "--disable-gpu"])
                page = browser.new_page(viewport={"width": 1280, "height": 900}, device_scale_factor=1)
                page.goto(f"http://127.0.0.1:{port}/", timeout=args.timeout_s * 1e3)
                # the last cell's table appears when every cell has run; the panel then shows its final state
                page.wait_for_selector("table.dataframe", timeout=args.timeout_s * 1e3)
                page.wait_for_selector(".widget-vbox img", timeout=60e3)
                time.sleep(2.0)
                sliders = page.evaluate(_MEASURE)
                panel = page.locator(".widget-vbox").first
                panel.screenshot(path=str(OUT))
                chromium_version = browser.version
                browser.close()
        finally:
            voila.terminate()
            voila.wait(timeout=30)
    import voila

    visible = [wh for wh in sliders if wh[0] >= 100 and wh[1] > 0]
    record = {"png_sha256": hashlib.sha256(OUT.read_bytes()).hexdigest(), "sliders": len(sliders),
              "visible_sliders": len(visible), "slider_px": sliders, "chromium": chromium_version,
              "voila": voila.__version__, "viewport_px": [1280, 900], "notebook": NOTEBOOK.name}
    RECORD.write_text(json.dumps(record, indent=1) + "\n")
    print("wrote", OUT, f"({len(visible)} of {len(sliders)} sliders visible)")
    if len(visible) != len(sliders) or not sliders:
        print("warning: not every slider is visible in the picture", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
