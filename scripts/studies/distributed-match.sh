#!/usr/bin/env bash
# Every example scene on 2 and 4 ranks against one process, bit for bit.
# docs/verification/distributed.md: each scene
# runs as one process and on each rank count of RKPM_RANKS (mpirun, one thread per
# rank), and `rkpm compare` gives the largest distance between the final positions over
# the largest displacement. Relaxations run to the scene's own convergence (the same
# step count is expected); dynamic scenes run RKPM_DYNAMIC_STEPS steps, as the
# matching target states. Writes out/distributed-match/distributed-match.{csv,md}; a
# full run also copies the CSV to docs/figures/ and the table into
# docs/verification/distributed.md. About 20 minutes on 2 cores.
# Usage: scripts/study distributed-match [--coarse]
#   --coarse: 2 ranks only, the sag and spread_cell scenes; docs untouched.
#   environment: RKPM_RANKS (default "2 4"), RKPM_DYNAMIC_STEPS (default 200),
#                RKPM_SCENES (default: every example scene, paths under examples/),
#                RKPM_TABLE_ONLY=1 (no runs: the table again from the CSV).
set -euo pipefail
script_name="study distributed-match"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/distributed-match
coarse=0
[ "${1:-}" = --coarse ] && coarse=1
ranks_list=${RKPM_RANKS:-2 4}
scenes=${RKPM_SCENES:-sag/sag.toml rbc/rbc.toml rbc/control.toml spread_cell/spread_cell.toml adhesion/adhesion.toml crawling/crawling.toml}
if [ "$coarse" = 1 ]; then ranks_list=${RKPM_RANKS:-2}; scenes=${RKPM_SCENES:-sag/sag.toml spread_cell/spread_cell.toml}; fi
dynamic_steps=${RKPM_DYNAMIC_STEPS:-200}
mkdir -p "$out"
out=$(cd "$out" && pwd)
rkpm_need mpirun
if [ -n "${RKPM_TABLE_ONLY:-}" ]; then
  rkpm=""
else
  rkpm=$(rkpm_program)
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
revision=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$here" diff --quiet HEAD -- src include particles 2>/dev/null || revision+=" with uncommitted changes"
load=$(cut -d' ' -f1 /proc/loadavg)
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive

# summary_value DIR KEY: a top-level value of DIR/summary.json.
summary_value() { sed -n "s/^  \"$2\": *\"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$1/summary.json"; }
# run RANKS SCENE DIR [MAX_STEPS]: one run (RANKS = 1: one process without mpirun).
run() {
  local ranks=$1 scene=$2 dir=$3 steps=${4:-}
  local args=(run "$scene" --out "$dir" --quiet)
  [ -n "$steps" ] && args+=(--max-steps "$steps")
  if [ "$ranks" = 1 ]; then
    "$rkpm" "${args[@]}" >"$dir.log" 2>&1
  else
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" -x OMP_NUM_THREADS -x OMP_WAIT_POLICY "$rkpm" "${args[@]}" \
      >"$dir.log" 2>&1
  fi
}

csv=$out/distributed-match.csv
if [ -z "${RKPM_TABLE_ONLY:-}" ]; then
  echo "# revision $revision, load $load" >"$csv"
  echo "scene,mode,ranks,particles,steps,converged,wall_time,largest_difference,largest_displacement,relative_difference" >>"$csv"
  for scene in $scenes; do
    file=$here/examples/$scene
    mode=$(sed -n 's/^mode *= *"\([a-z]*\)".*/\1/p' "$file")
    steps=""
    [ "$mode" = dynamic ] && steps=$dynamic_steps
    name=$(echo "$scene" | tr '/.' '__')
    (cd "$(dirname "$file")" && run 1 "$file" "$scratch/${name}_1" "$steps")
    for ranks in 1 $ranks_list; do
      dir=$scratch/${name}_$ranks
      [ "$ranks" = 1 ] || (cd "$(dirname "$file")" && run "$ranks" "$file" "$dir" "$steps")
      compared=$("$rkpm" compare "$scratch/${name}_1" "$dir")
      field() { echo "$compared" | sed -n "s/.*\"$1\": *\([^,}]*\).*/\1/p"; }
      converged=$(summary_value "$dir" converged)
      echo "$scene,$mode,$ranks,$(summary_value "$dir" total_particles),$(summary_value "$dir" steps),${converged:-n/a},$(summary_value "$dir" wall_time),$(field largest_difference),$(field largest_displacement),$(field relative_difference)" >>"$csv"
      tail -1 "$csv"
    done
  done

fi
# The runs' revision and load, recorded in the CSV's first line.
read -r revision load < <(sed -n '1s/^# revision \(.*\), load \(.*\)$/\1 \2/p' "$csv" | sed 's/ with uncommitted changes/+/')

md=$out/distributed-match.md
awk -F, -v rev="$revision" -v load="$load" -v dyn="$dynamic_steps" '
/^#/ || /^scene,/ { next }
{ rows[NR] = $0; last = NR }
END {
  printf "Measured by `scripts/study distributed-match`, one thread per rank on 2 cores (4 ranks oversubscribe them), load average %s before the runs. Relaxations run to convergence; dynamic scenes %d steps. The difference is the largest distance between a particle'\''s final positions in the two runs over the one-process run'\''s largest displacement (`rkpm compare`).\n\n", load, dyn
  print "| scene | mode | ranks | particles | steps | converged | wall time [s] | largest displacement [m] | largest difference [m] | difference / largest displacement |"
  print "|---|---|---:|---:|---:|---|---:|---:|---:|---:|"
  for (i = 3; i <= last; i++) {
    split(rows[i], f, ",")
    printf "| `%s` | %s | %d | %d | %d | %s | %.1f | %.3g | %s | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[9], (f[3] == 1 ? "(reference)" : sprintf("%.2g", f[8])), (f[3] == 1 ? "" : sprintf("%.2g", f[10]))
  }
}' "$csv" >"$md"
cat "$md"
doc=$here/docs/verification/distributed.md
if [ "$coarse" = 0 ]; then
  { echo; cat "$md"; echo; } >"$scratch/block.md"
  rkpm_replace_generated "$doc" "$scratch/block.md" "scripts/study distributed-match -->"
  cp "$csv" "$here/docs/figures/distributed-match.csv"
  echo "$script_name: updated $doc and docs/figures/distributed-match.csv"
fi
echo "$script_name: wrote $csv and $md"
