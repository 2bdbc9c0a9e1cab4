"""The `servobench` command line (docs/cli.md).

Sub-commands: ``simulate``, ``bode``, ``tune``, ``identify`` (each reads an axis file, TOML or JSON, see
:mod:`servobench.axisfile`) and ``demo``. Each writes its data (CSV with units in the header, JSON) and its plots
(PNG or SVG) into ``--out`` (default ./out) and prints what it wrote.

Exit codes: 0 done; 1 the work failed (a tuning or a fit that did not succeed, a sweep that tripped, an output that
could not be written); 2 a usage error or bad input (options, axis file, log file). User errors never print a
traceback: ``servobench: error: <file>: <key>: <message>``.

One module per sub-command (``_simulate``, ``_bode``, ``_tune``, ``_identify``, ``_demo``), the shared output and
error helpers in ``_common`` and the parser and :func:`main` in ``_main``; data flows one way (``_main`` ->
sub-commands -> ``_common``; decision OR2). The names below are the package's, as they were when it was one file.
"""

from __future__ import annotations


__all__ = ["main", "build_parser", "LOG_COLUMNS", "UsageError", "WorkFailed", "Output", "cmd_simulate", "cmd_bode",
           "cmd_tune", "cmd_identify", "cmd_demo"]

from ._bode import cmd_bode
from ._common import (EXIT_FAILED, EXIT_OK, EXIT_USAGE, Output, UsageError, WorkFailed,  # noqa: F401 (re-exported)
                      _linearity_note)
from ._demo import cmd_demo
from ._identify import LOG_COLUMNS, cmd_identify
from ._main import _described, build_parser, main  # noqa: F401 (re-exported)
from ._simulate import cmd_simulate
from ._tune import cmd_tune
