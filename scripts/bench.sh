#!/usr/bin/env bash
# Installs servobench with its benchmark peers from PyPI (the `bench` extra: SciPy, python-control, Ruckig), then runs
# every benchmark, each in its own process, and writes bench/results/summary.md (each figure against its peer in the
# same run and against its goal) beside the detailed tables. Arguments go to bench/run_all.py (e.g. --quick,
# --only axis,motion). Takes a few minutes; the figures depend on how busy the machine is (the summary records it).
set -euo pipefail
cd "$(dirname "$0")/.."
SERVOBENCH_EXTRAS=bench bash scripts/install.sh
exec "${PYTHON:-python3}" bench/run_all.py --command "bash scripts/bench.sh" "$@"
