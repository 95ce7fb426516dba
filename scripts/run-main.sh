#!/usr/bin/env bash
# Installs the dependencies, builds sinew, and runs the main job into ./out/<scene name>.
# The main job is the twisted Veronda-Westmann cylinder until the knee scene lands.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCH=OFF
cmake --build build -j "$(nproc)" --target sinew
SCENE="${1:-examples/twisted-cylinder.json}"
NAME="$(basename "$SCENE" .json)"
./build/sinew run "$SCENE" -o "out/$NAME"
echo "Results in out/$NAME: open out/$NAME/sinew.pvd in ParaView; logs in out/$NAME/steps.csv and newton.csv."
