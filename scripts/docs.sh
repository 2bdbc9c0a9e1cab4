#!/usr/bin/env bash
# Installs servobench (with the documentation tools, the `docs` extra) and builds the documentation site into
# build/site: the pages of docs/, the API reference from the docstrings and the notebook tour, every notebook
# executed against the current code. Any warning fails the build. Extra arguments go to sphinx-build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install.sh
py=${PYTHON:-python3}

echo "== building the documentation site (Sphinx, myst-nb; notebooks executed)"
# -E: a fresh build every time, so that the API pages and the notebooks' plots are those of the code as it is now.
"$py" -m sphinx -E -W --keep-going -j auto -q -b html docs build/site "$@"
echo "== the site: $PWD/build/site/index.html"
