#!/usr/bin/env bash
# Installs the dependencies, builds sinew, and runs the main job: the knee flexion of
# examples/knee-flexion.json (the seed's 150-degree flexion of a generated right leg), then
# renders it. Results in ./out/<scene name>.
#
#   bash scripts/run-main.sh           the knee on a 16 mm mesh (4.5k nodes, 19k tets): about 2 minutes
#   bash scripts/run-main.sh --full    the knee on the scene's own 9 mm mesh (9.1k nodes, 41k tets,
#                                      like the seed's; about 5 minutes)
#   bash scripts/run-main.sh SCENE     any other scene, as written
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE=examples/knee-flexion.json
SIZE=(--element-size 16)
for arg in "$@"; do
  case "$arg" in
    --full) SIZE=() ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) SCENE="$arg"; SIZE=() ;;
  esac
done
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCH=OFF
cmake --build build -j "$(nproc)" --target sinew
NAME="$(basename "$SCENE" .json)"
# --overwrite: each run of the main job replaces the previous one's results in out/NAME.
./build/sinew run "$SCENE" -o "out/$NAME" --overwrite "${SIZE[@]}"
if [ "$NAME" = knee-flexion ]; then
  /usr/bin/python3 scripts/render_knee.py "out/$NAME"
fi
echo "Results in out/$NAME: open out/$NAME/sinew.pvd in ParaView; logs in steps.csv, newton.csv,"
echo "rigid_bodies.csv (the patella's path) and summary.json; pictures: out/$NAME/*.png."
