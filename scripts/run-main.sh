#!/usr/bin/env bash
# README command (a): install what is missing, build the simulator (the rkpm program
# only), run the main job (the red-blood-cell relaxation) and print where ParaView
# should open its output.
# Usage: scripts/run-main.sh [SCENE.toml] [rkpm run options...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/install-deps.sh"
bash "$here/scripts/build.sh" "$here/build" rkpm  # the simulator only: the tests are command (b)
scene=${1:-"$here/examples/rbc/rbc.toml"}
shift || true
"$here/build/src/app/rkpm" run "$scene" --out "$here/out/$(basename "$scene" .toml)" "$@"
