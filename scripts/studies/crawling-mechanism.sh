#!/usr/bin/env bash
# What moves the crawling cell: the shipped graded run with one ingredient changed at a time.
# Runs examples/crawling/crawling.toml as shipped and with: activity zeta = -2 kPa and
# +2 kPa, a uniform adhesion constant (stiffness_law = "none"), no surface tension, the
# Eq. 18 slope 0, 1, 2 and 8 instead of 4, eps x 2 and x 4 (x 4 stops: the bodies interpenetrate), damping / 10
# (scripts/lib/crawling_mechanism.py), and writes
#   docs/figures/crawling_mechanism.csv   drift and drift velocity of each variant
#   docs/figures/crawling_mechanism.png   drift velocity against the slope
#   the generated table (crawling-mechanism) of docs/verification/crawling.md
# The runs go to out/crawling-mechanism/ (a run folder holding a summary.json is kept:
# delete it to rerun). About 10 minutes on 2 cores.
# Usage: scripts/study crawling-mechanism [--only VARIANT...]
#   --only: run only these variants besides the shipped one; docs untouched.
# RKPM_THREADS sets the thread count (default 2); RKPM_BIN names a built rkpm.
set -euo pipefail
script_name="study crawling-mechanism"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
out=$rkpm_out_root/crawling-mechanism
only=()
if [ $# -gt 0 ]; then
  [ "$1" = --only ] || rkpm_die "unknown argument $1 (expected --only VARIANT...)"
  only=("$@")
fi
full=1
[ ${#only[@]} -eq 0 ] || full=0
rkpm_python_study crawling_mechanism.py "$out" crawling_mechanism verification/crawling.md "scripts/study crawling-mechanism -->" "$full" "${only[@]}"
