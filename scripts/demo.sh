#!/usr/bin/env bash
# Installs servobench and runs the demo: a point-to-point move on the reference axis; prints rise time,
# overshoot, settling time and peak following error and writes the response plot to ./out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install.sh
exec "${PYTHON:-python3}" -m servobench demo "$@"
