#!/usr/bin/env bash
# A long fuzzing soak of the sinew command (tests/app/test_cli_fuzz.cpp with more cases):
# mutated scenes through `sinew validate` and mutated physical values through small runs.
# Fails on any signal, hang or undocumented exit code; prints the outcome counts.
#   scripts/fuzz-soak.sh [VALIDATE_CASES [RUN_CASES [SEED]]]    (defaults 3000 200 18)
# Environment: BUILD (default build), SINEW_FUZZ_BINARY (another sinew to test, e.g. an older
# build), SINEW_FUZZ_KEEP (a directory to keep the failing cases in).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${BUILD:-build}"
if [ ! -x "$BUILD/tests/test_app" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD" --target sinew test_app
fi
export SINEW_FUZZ_VALIDATE="${1:-3000}" SINEW_FUZZ_RUN="${2:-200}" SINEW_FUZZ_SEED="${3:-18}"
exec "$BUILD/tests/test_app" --gtest_filter='Fuzz.*'
