#!/usr/bin/env bash
# Installs the dependencies, builds sinew twice and runs the whole test suite twice:
#   1. Release build with -Werror: every unit, example and command-line test (ctest);
#   2. AddressSanitizer + UndefinedBehaviorSanitizer build: the same suite again.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
JOBS="$(nproc)"

echo "== Release build and tests =="
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSINEW_WERROR=ON
cmake --build build -j "$JOBS"
ctest --test-dir build --output-on-failure -j "$JOBS"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests =="
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DSINEW_SANITIZE=ON -DSINEW_WERROR=ON \
  -DSINEW_BUILD_BENCH=OFF
cmake --build build-sanitize -j "$JOBS"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir build-sanitize --output-on-failure -j "$JOBS"
