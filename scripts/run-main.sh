#!/usr/bin/env bash
# README command (a): install what is missing, build the simulator, run the main job.
# Builds the rkpm program only (the tests are command (b)), runs the red-blood-cell
# relaxation (examples/rbc/rbc.toml) into out/rbc/ and prints where ParaView should
# open its output.
# Usage: scripts/run-main.sh [SCENE.toml] [rkpm run options...]
#   SCENE.toml runs another scene instead, into out/<scene name>/.
set -euo pipefail
script_name=run-main.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
bash "$rkpm_root/scripts/install-deps.sh"
rkpm=$(rkpm_program)
scene=${1:-"$rkpm_root/examples/rbc/rbc.toml"}
shift || true
"$rkpm" run "$scene" --out "$rkpm_out_root/$(basename "$scene" .toml)" "$@"
