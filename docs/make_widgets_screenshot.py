"""Makes docs/img/widgets_tuner.png: notebook 13 (the tuning panel) served by Voila and photographed in headless
Chromium. Run once by hand after a change to the panel's look, then commit the PNG; the test suite does not need a
browser (tests/python/test_widgets.py drives the panel headless).

Needs: `apt-get install chromium` (Debian's browser) and `pip install voila playwright` (playwright drives the
system's Chromium through `executable_path`; no browser download). Run from the source tree with servobench
installed:  python docs/make_widgets_screenshot.py [--chromium /usr/bin/chromium]
"""

from __future__ import annotations

import argparse
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
                panel = page.locator(".widget-vbox").first
                panel.screenshot(path=str(OUT))
                browser.close()
        finally:
            voila.terminate()
            voila.wait(timeout=30)
    print("wrote", OUT)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
