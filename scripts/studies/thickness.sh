#!/usr/bin/env bash
# Red-blood-cell relaxation at several wall thicknesses: shape against Evans-Fung.
# Runs examples/python/rbc_thickness_sweep.py (the scene examples/rbc/rbc.toml as
# shipped with only [body.cloud] thickness changed, each run to convergence, nested
# levels included; shape metrics against Evans-Fung, steps and wall time) into
# out/thickness/{study.csv, table.md, profiles.png}; the default thicknesses also
# rewrite docs/figures/rbc-thickness-* and the thickness table of
# docs/verification/rbc.md. About 13 minutes on 2 cores.
# Usage: scripts/study thickness [--coarse] [THICKNESSES_UM...]
#   --coarse: 0.3 and 0.5 um at face_cells 12 (about a minute); docs untouched.
#   THICKNESSES_UM default 0.3 0.4 0.5 0.75 1.0 (the seed gives 0.5 and "about 0.3").
#   RKPM_FACE_CELLS=N runs the shell at face_cells N instead of the scene's.
#   RKPM_MAX_STEPS caps each run's steps on its own cloud (default 10000): a wall that
#   does not come to rest within it is reported as not converged.
#   A directory that already holds a summary.json is kept, so the study can be
#   completed in several sittings.
set -euo pipefail
script_name="study thickness"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/thickness
update_docs=0
if [ "${1:-}" = --coarse ]; then
  shift; thicknesses=(0.3 0.5); : "${RKPM_FACE_CELLS:=12}"
elif [ $# -gt 0 ]; then
  thicknesses=("$@")
else
  thicknesses=(0.3 0.4 0.5 0.75 1.0); [ -z "${RKPM_FACE_CELLS:-}" ] && update_docs=1
fi
rkpm_build _rkpm >&2 || rkpm_die "building the Python module in $rkpm_build_dir failed"
PYTHONPATH="$rkpm_build_dir/python" OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} /usr/bin/python3 \
  "$here/examples/python/rbc_thickness_sweep.py" --out "$out" --max-steps "${RKPM_MAX_STEPS:-10000}" \
  ${RKPM_FACE_CELLS:+--face-cells "$RKPM_FACE_CELLS"} "${thicknesses[@]}"
if [ "$update_docs" = 1 ]; then
  cp "$out/study.csv" "$here/docs/figures/rbc-thickness-study.csv"
  cp "$out/profiles.png" "$here/docs/figures/rbc-thickness-profiles.png"
  rkpm_replace_generated "$here/docs/verification/rbc.md" "$out/table.md" "scripts/study thickness -->"
  echo "updated docs/figures/rbc-thickness-* and docs/verification/rbc.md"
fi
