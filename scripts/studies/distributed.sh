#!/usr/bin/env bash
# Weak and strong scaling on 1 and 2 ranks, ghost fractions, a 64-rank model.
# docs/verification/distributed.md: weak and strong scaling of a clamped
# Mooney-Rivlin block under a body force (the sag example's physics, dynamic with
# damping) on 1 and 2 ranks of this machine, one thread per rank, and the strong case
# again as one rank with 2 threads (the same cores without MPI); the ghost fraction
# and the doubles each force evaluation exchanges, from summary.json; and a model of
# a step on 64 ranks x 1e6 particles built from these measured inputs.
#
# Time per step is measured as the difference of two runs of S1 and S2 steps
# (wall time from summary.json), so the set-up cancels; each figure is the median of
# REPEATS such differences. Writes out/distributed/distributed.{csv,md} and
# distributed-scaling.png; a full run also copies the CSV and PNG to docs/figures/ and
# the table with the model into docs/verification/distributed.md. About 15 minutes.
# Usage: scripts/study distributed [--coarse]
#   --coarse: a 13^3 block, no extra weak size, 1 repeat; docs untouched.
#   environment: RKPM_CELLS (default 24: the 1-rank block is 25 x 25 x 25 particles),
#                RKPM_WEAK_CELLS (default 40: the weak case again at 41^3 particles per
#                rank, whose operators no longer fit the shared 32 MB L3 cache of one
#                rank's run; "" = none), RKPM_REPEATS (default 3), RKPM_STEPS (default "40 240").
set -euo pipefail
script_name="study distributed"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/distributed
coarse=0
if [ "${1:-}" = --coarse ]; then
  coarse=1
  : "${RKPM_CELLS:=12}" "${RKPM_WEAK_CELLS=}" "${RKPM_REPEATS:=1}"
fi
cells=${RKPM_CELLS:-24}
read -r -a weak_cells <<<"${RKPM_WEAK_CELLS-40}"
repeats=${RKPM_REPEATS:-3}
read -r s1 s2 <<<"${RKPM_STEPS:-40 240}"
mkdir -p "$out"
out=$(cd "$out" && pwd)
rkpm_need gnuplot mpirun
rkpm=$(rkpm_program)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
revision=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$here" diff --quiet HEAD -- src include particles 2>/dev/null || revision+=" with uncommitted changes"
cores=$(nproc)  # before OMP_NUM_THREADS is set: nproc honours it
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=active

# scene NX [CELLS]: the block with NX x CELLS x CELLS cells (CELLS defaults to cells),
# spacing 0.4 um.
scene() {
  local nx=$1 cells=${2:-$cells}
  local file=$scratch/block_${nx}_$cells.toml
  cat >"$file" <<EOF
[scene]
name = "distributed_block"
[integrator]
mode = "dynamic"
t_end = 1.0
damping = 2e4
max_steps = 100000000
[output]
every = 1.0
[[body]]
name = "block"
density = 1000.0
[body.cloud]
generator = "block"
size = [$(awk -v n="$nx" 'BEGIN { printf "%.6g", 0.4e-6 * n }'), $(awk -v n="$cells" 'BEGIN { printf "%.6g", 0.4e-6 * n }'), $(awk -v n="$cells" 'BEGIN { printf "%.6g", 0.4e-6 * n }')]
cells = [$nx, $cells, $cells]
[body.material]
model = "mooney_rivlin"
c1 = 2.126e3
c2 = 1.7e2
lambda = 1.7e5
[[body.boundary]]
surface = "zmin"
type = "fixed"
[[term]]
type = "body_force"
body = "block"
acceleration = [0.0, 0.0, -2e5]
EOF
  echo "$file"
}

# run RANKS THREADS SCENE STEPS DIR: one run; prints its wall time.
run() {
  local ranks=$1 threads=$2 file=$3 steps=$4 dir=$5
  rm -rf "$dir"
  if [ "$ranks" = 1 ]; then
    "$rkpm" run "$file" --out "$dir" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null
  else
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" -x OMP_NUM_THREADS -x OMP_WAIT_POLICY \
      "$rkpm" run "$file" --out "$dir" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null
  fi
  sed -n 's/^ *"wall_time": *\([0-9.e+-]*\).*/\1/p' "$dir/summary.json"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : v[NR / 2 + 1] }'; }

# measure CASE RANKS THREADS NX: median step time and set-up time; ghosts from the last run.
csv=$out/distributed.csv
echo "case,ranks,threads,particles,particles_per_rank,step_s,setup_s,ghosts_max,ghost_fraction,doubles_per_force_evaluation_max" >"$csv"
measure() {
  local name=$1 ranks=$2 threads=$3 nx=$4 cells=${5:-$cells} file steps=() setups=() dir=$scratch/run
  file=$(scene "$nx" "$cells")
  for ((k = 0; k < repeats; k++)); do
    local w1 w2
    w1=$(run "$ranks" "$threads" "$file" "$s1" "$dir")
    w2=$(run "$ranks" "$threads" "$file" "$s2" "$dir")
    steps+=("$(awk -v a="$w1" -v b="$w2" -v s="$s1" -v t="$s2" 'BEGIN { printf "%.6g", (b - a) / (t - s) }')")
    setups+=("$(awk -v a="$w1" -v b="$w2" -v s="$s1" -v t="$s2" 'BEGIN { printf "%.6g", a - s * (b - a) / (t - s) }')")
  done
  local step setup particles ghosts
  step=$(printf '%s\n' "${steps[@]}" | median)
  setup=$(printf '%s\n' "${setups[@]}" | median)
  particles=$(( (nx + 1) * (cells + 1) * (cells + 1) ))
  ghosts=0 doubles=0
  if [ "$ranks" -gt 1 ]; then
    largest() { tr -d ' \n' <"$dir/summary.json" | sed -n "s/.*\"$1\":\\[\\([0-9,]*\\)\\].*/\\1/p" | tr ',' '\n' | sort -n | tail -1; }
    ghosts=$(largest ghosts)
    doubles=$(largest doubles_received_and_returned_per_force_evaluation)
  fi
  awk -v c="$name" -v r="$ranks" -v t="$threads" -v n="$particles" -v st="$step" -v su="$setup" -v g="$ghosts" -v d="$doubles" 'BEGIN {
    printf "%s,%d,%d,%d,%d,%s,%s,%d,%.4f,%d\n", c, r, t, n, n / r, st, su, g, g / (n / r), d }' >>"$csv"
  echo "study distributed: $name on $ranks rank(s) x $threads thread(s), $particles particles: $step s per step, set-up $setup s"
}

load=$(cut -d' ' -f1-3 /proc/loadavg)
measure weak 1 1 "$cells"
measure weak 2 1 $((2 * cells + 1))
measure strong 1 1 $((2 * cells + 1))
measure strong 2 1 $((2 * cells + 1))
measure threads 1 2 $((2 * cells + 1))
# The weak case at other sizes per rank (rows after the five above).
for c in "${weak_cells[@]}"; do
  measure weak 1 1 "$c" "$c"
  measure weak 2 1 $((2 * c + 1)) "$c"
done

# The table and the model: out/distributed/distributed.md, and the page for a full run.
md=$out/distributed.md
awk -F, -v rev="$revision" -v load="$load" -v reps="$repeats" -v s1="$s1" -v s2="$s2" -v cores="$cores" '
NR == 1 { next }
{ c[NR] = $1; r[NR] = $2; th[NR] = $3; n[NR] = $4; npr[NR] = $5; st[NR] = $6; su[NR] = $7; g[NR] = $8; gf[NR] = $9; d[NR] = $10; last = NR }
END {
  printf "Measured by `scripts/study distributed` on %d cores, load average before the runs %s; each time the median of %d differences of %d- and %d-step runs (the set-up cancels).\n\n", cores, load, reps, s1, s2
  print "| case | ranks x threads | particles | per rank | time per step [ms] | set-up [s] | ghosts (largest rank) | ghost fraction | doubles exchanged per force evaluation |"
  print "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  for (i = 2; i <= last; i++)
    printf "| %s | %d x %d | %d | %d | %.2f | %.2f | %d | %.3f | %d |\n", c[i], r[i], th[i], n[i], npr[i], 1000 * st[i], su[i], g[i], gf[i], d[i]
  weak = st[2] / st[3]; strong = st[4] / st[5]
  others = ""
  for (i = 7; i + 1 <= last; i += 2)
    others = others sprintf("; at %d particles per rank **%.1f %%**", npr[i], 100 * st[i] / st[i + 1])
  printf "\nWeak-scaling efficiency 1 -> 2 ranks (time per step at fixed particles per rank): **%.1f %%** at %d particles per rank%s.", 100 * weak, npr[2], others
  printf " Strong-scaling speed-up at %d particles: **%.2f** (efficiency %.0f %%). The same cores as one rank with 2 OpenMP threads: %.2f ms per step, so 2 ranks run at **%.2f x** the threaded speed. Where the weak case loses its time is discussed above the table (docs/verification/distributed.md).\n", n[4], strong, 50 * strong, 1000 * st[6], st[6] / st[5]
  # The model: a step on P ranks of m particles each costs m t_c (the measured
  # one-rank time per particle-step) plus the ghost exchange (two messages to each
  # neighbour: displacements in, force records out, as many doubles per ghost as
  # measured) plus the collective reductions.
  # Inputs from the largest weak size measured (the last pair of rows): a rank of 1e6
  # particles is far out of cache, as that one is.
  w1 = (last >= 8) ? last - 1 : 2; w2 = w1 + 1
  tc = st[w1] / n[w1]; weak = st[w1] / st[w2]
  g0 = gf[w2]; m0 = npr[w2]; m = 1e6; P = 64
  gm = g0 * (m0 / m) ^ (1.0 / 3.0)           # ghost fraction ~ surface / volume of a part
  per_ghost = (g[w2] > 0) ? d[w2] / g[w2] : 6  # doubles per ghost, in and out, measured
  bytes = 8 * per_ghost * gm * m             # per step
  alpha = 2e-6; beta = 1.0 / 10e9; nb = 12; reductions = 12
  comm = 2 * nb * alpha + bytes * beta + reductions * alpha * log(P) / log(2)
  compute = tc * m
  eff = compute / (compute + comm)
  printf "\n**Model, 64 ranks x 1e6 particles** (inputs measured above except the network): compute %.3f s per step (%.3g s per particle-step, measured with one rank alone on the machine); ghost fraction %.3f (measured %.3f at %d particles per rank, scaled as m^(-1/3)); %.1f MB exchanged per rank per step; with an assumed network of 2 us latency, 10 GB/s per rank, 12 neighbours and 12 reductions of log2(64) stages per step: communication %.2g s, so the exchange costs %.2f %% of a step if it does not overlap the compute. Ranks that share a node also share its memory bandwidth: with the loss measured here (weak efficiency %.1f %%) the expected efficiency is **%.1f %%**, the same as the node'\''s threads would reach.\n", compute, tc, gm, g0, m0, bytes / 1e6, comm, 100 * (1 - eff), 100 * weak, 100 * eff * weak
}' "$csv" >"$md"
cat "$md"

# One line per weak size, each from its own rows.
weak_plots=""
for c in "$cells" "${weak_cells[@]}"; do
  n=$(( (c + 1) ** 3 ))
  awk -F, -v n="$n" '$1 == "weak" && $5 == n' "$csv" >"$scratch/weak_$n.csv"
  weak_plots+="\"$scratch/weak_$n.csv\" using 2:(1000*\$6) with linespoints title \"weak: $n particles per rank\", "
done
gnuplot <<EOF
set terminal pngcairo size 800,500
set output "$out/distributed-scaling.png"
set title "Time per step, one thread per rank (scripts/study distributed)"
set xlabel "ranks"
set ylabel "time per step [ms]"
set xrange [0.5:2.5]
set xtics 1
set key top left
set datafile separator ","
plot $weak_plots \
     "< awk -F, '\$1==\"strong\"' $csv" using 2:(1000*\$6) with linespoints title "strong: fixed total", \\
     "< awk -F, '\$1==\"threads\"' $csv" using (2):(1000*\$6) with points pt 7 ps 1.5 title "1 rank x 2 threads, strong size"
EOF
# A full run also replaces the generated part of docs/verification/distributed.md.
doc=$here/docs/verification/distributed.md
if [ "$coarse" = 0 ]; then
  { echo; cat "$md"; echo; echo "![time per step](../figures/distributed-scaling.png)"; echo; } >"$scratch/block.md"
  rkpm_replace_generated "$doc" "$scratch/block.md" "scripts/study distributed -->"
  cp "$csv" "$out/distributed-scaling.png" "$here/docs/figures/"
  echo "$script_name: updated $doc, docs/figures/distributed.csv and docs/figures/distributed-scaling.png"
fi
echo "$script_name: wrote $csv, $md and $out/distributed-scaling.png"
