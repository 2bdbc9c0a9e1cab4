#!/usr/bin/env bash
# Installs servobench and runs every test: the C++ unit tests through ctest, then pytest (which also builds the
# documentation site once, executing the notebooks).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install.sh
py=${PYTHON:-python3}

echo "== C++ unit tests (ctest)"
cmake -S . -B build/ctest -G Ninja -DSERVOBENCH_BUILD_PYTHON=OFF -DSERVOBENCH_BUILD_TESTS=ON >/dev/null
cmake --build build/ctest -j "$(nproc)"
ctest --test-dir build/ctest --output-on-failure -j "$(nproc)"

echo "== Python tests (pytest)"
"$py" -m pytest tests/python -q
