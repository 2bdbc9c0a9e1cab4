#!/usr/bin/env bash
# Installs servobench and runs every test: the C++ unit tests through ctest, then pytest (which also builds the
# documentation site once, executing the notebooks), then the sanitizer builds (issue 21.6), each in its own build
# folder: the C++ tests and a pytest subset against an ASan+UBSan build of the module (build/asan), and the thread
# stress test under ThreadSanitizer (build/tsan). SERVOBENCH_SANITIZERS=0 skips the sanitizer part (the plain
# suite only).
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

if [ "${SERVOBENCH_SANITIZERS:-1}" = "0" ]; then exit 0; fi
sanitized() {  # folder, sanitizers, build the module (ON/OFF)
  cmake -S . -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" -DSERVOBENCH_SANITIZE="$2" \
    -DSERVOBENCH_NO_LTO=ON \
    -DSERVOBENCH_BUILD_PYTHON="$3" -DSERVOBENCH_BUILD_TESTS=ON \
    -DPython_EXECUTABLE="$(command -v "$py")" -Dpybind11_DIR="$("$py" -m pybind11 --cmakedir)" >/dev/null
}
echo "== C++ unit tests under ASan+UBSan (build/asan)"
sanitized build/asan address,undefined ON
cmake --build build/asan -j "$(nproc)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/asan --output-on-failure -j "$(nproc)"

echo "== pytest subset against the ASan+UBSan module (build/asan)"
# libasan and libstdc++ preloaded: the interpreter links neither, and ASan's __cxa_throw interceptor needs the real one.
rm -rf build/asan/pkg && mkdir -p build/asan/pkg && cp -r python/servobench build/asan/pkg/
cp build/asan/_core*.so build/asan/pkg/servobench/
(cd build/asan && LD_PRELOAD="$(${CXX:-g++} -print-file-name=libasan.so) $(${CXX:-g++} -print-file-name=libstdc++.so)" \
  ASAN_OPTIONS=detect_leaks=0:detect_odr_violation=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 PYTHONPATH="$PWD/pkg" \
  "$py" -m pytest -q -p no:cacheprovider --rootdir ../.. \
  ../../tests/python/test_robust_threads.py ../../tests/python/test_robust_inputs.py \
  ../../tests/python/test_axis.py ../../tests/python/test_card_scope.py ../../tests/python/test_card_gt.py \
  -k "not (ctrl_c and fit_time)")
# (that case times a 0.5 s bound; under ASan one solver iteration of its 100,000-sample fit alone takes ~0.6 s)

echo "== C++ thread stress under ThreadSanitizer (build/tsan)"
sanitized build/tsan thread OFF
cmake --build build/tsan -j "$(nproc)" --target servobench_stress
TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 build/tsan/tests/cpp/servobench_stress
