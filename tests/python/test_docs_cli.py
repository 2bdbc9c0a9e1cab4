"""The command lines shown in README.md and docs/ run (issue 23.1): every line of a ```bash block that starts with
``servobench `` is executed as a reader types it, from a folder that holds a copy of the source tree's examples/
(axis files and examples/logs/machine.csv), and must exit 0 and write its files."""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FENCE = re.compile(r"^ {0,3}(```+|~~~+)\s*([^\s`]*)")


def cli_lines(text: str) -> list[str]:
    """The `servobench ...` command lines of a page's shell blocks (comments after '#' removed)."""
    out, in_shell, fence = [], False, None
    for line in text.splitlines():
        m = FENCE.match(line)
        if m and fence is None:
            fence, in_shell = m[1], m[2].strip("{}").lower() in ("bash", "sh", "shell", "console")
            continue
        if m and fence is not None and line.strip().startswith(fence):
            fence, in_shell = None, False
            continue
        if in_shell:
            cmd = line.split(" #")[0].strip()
            if cmd.startswith("$ "):
                cmd = cmd[2:]
            if cmd.startswith("servobench "):
                out.append(cmd)
    return out


def _commands() -> list[tuple[str, str]]:
    pages = [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))
    seen, out = set(), []
    for page in pages:
        for cmd in cli_lines(page.read_text(encoding="utf-8")):
            if cmd not in seen:
                seen.add(cmd)
                out.append((page.relative_to(ROOT).as_posix(), cmd))
    return out


COMMANDS = _commands()


def test_the_docs_show_commands():
    assert len(COMMANDS) >= 8, COMMANDS
    assert any("--log examples/logs/machine.csv" in c for _p, c in COMMANDS)
    assert (ROOT / "examples" / "logs" / "machine.csv").is_file()


def test_block_parsing():
    text = "```bash\nservobench simulate a.toml   # move\nls\n```\n```python\nservobench x\n```\n"
    assert cli_lines(text) == ["servobench simulate a.toml"]


@pytest.mark.parametrize("page,cmd", COMMANDS, ids=[c for _p, c in COMMANDS])
def test_cli_example_runs(page, cmd, tmp_path):
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    args = shlex.split(cmd)[1:]
    env = {**os.environ, "MPLBACKEND": "Agg"}
    proc = subprocess.run([sys.executable, "-m", "servobench", *args], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=600)
    assert proc.returncode == 0, f"{page}: `{cmd}` exited {proc.returncode}:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    files = re.findall(r"^wrote (\S+)", proc.stdout, flags=re.M) + re.findall(r"written to (\S+)", proc.stdout)
    assert files, f"{page}: `{cmd}` wrote nothing:\n{proc.stdout[-2000:]}"
    for name in files:
        written = tmp_path / name
        assert written.is_file() and written.stat().st_size > 0, name
        if written.suffix == ".json":
            text = written.read_text(encoding="utf-8")
            assert "Infinity" not in text and "NaN" not in text, f"{written.name} is not standard JSON"
