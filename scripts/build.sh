#!/usr/bin/env bash
# Configures and builds rkpm (Release). Usage: scripts/build.sh [BUILD_DIR] [TARGET...]
# With targets, builds only those (README command (a) builds only the `rkpm` program);
# without, everything: the program, the tests and the benchmarks.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$here/build"}
shift || true
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
