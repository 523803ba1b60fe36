#!/usr/bin/env bash
# Configures and builds rkpm (Release) in RKPM_BUILD_DIR (default build/).
# Usage: scripts/build.sh [TARGET...]
#   With targets, builds only those (README command (a) builds only `rkpm`); without,
#   everything: the program, the tests and the benchmarks.
set -euo pipefail
script_name=build.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
rkpm_build "$@"
