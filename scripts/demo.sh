#!/usr/bin/env bash
# Installs servobench and runs the demo: a point-to-point move on the reference axis (rise time, overshoot, settling
# time, following error), a Bode sweep of its loop, then identification of its plant, model-based tuning and a Bode
# sweep of the tuned loop; plots go to ./out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install.sh
exec "${PYTHON:-python3}" -m servobench demo "$@"
