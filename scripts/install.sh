#!/usr/bin/env bash
# Installs everything servobench needs on a fresh Debian machine (run as root), then the package itself.
# Idempotent: what is already there is not installed again.
set -euo pipefail
cd "$(dirname "$0")/.."

apt_packages=(g++ libeigen3-dev libceres-dev libgtest-dev)
missing=()
for pkg in "${apt_packages[@]}"; do
  dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "== installing Debian packages: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

py=${PYTHON:-python3}
# Build tools on PATH for the C++ test build (scikit-build-core fetches its own for the wheel if needed).
command -v cmake >/dev/null 2>&1 || "$py" -m pip install -q "cmake>=3.18"
command -v ninja >/dev/null 2>&1 || "$py" -m pip install -q ninja

extras=${SERVOBENCH_EXTRAS:-test}  # scripts/bench.sh asks for "bench" (the benchmark peers)
echo "== building and installing servobench (C++ core + Python package) with the [$extras] extra"
"$py" -m pip install -q --disable-pip-version-check ".[$extras]" 2>&1 | grep -v -E "^WARNING: (Running pip as|Location .* is ignored)" || true
"$py" -c "import servobench" || { echo "servobench failed to install" >&2; exit 1; }
