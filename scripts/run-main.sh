#!/usr/bin/env bash
# README command (a): install what is missing, build, run the main job (the
# red-blood-cell relaxation) and print where ParaView should open its output.
# Usage: scripts/run-main.sh [SCENE.toml] [rkpm run options...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/install-deps.sh"
bash "$here/scripts/build.sh" "$here/build"
scene=${1:-"$here/examples/rbc/rbc.toml"}
shift || true
"$here/build/src/app/rkpm" run "$scene" --out "$here/out/$(basename "$scene" .toml)" "$@"
