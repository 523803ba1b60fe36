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
#                rank's run; "" = none), RKPM_REPEATS (default 5), RKPM_STEPS (default "40 240").
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
repeats=${RKPM_REPEATS:-5}
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

# run RANKS THREADS SCENE STEPS DIR: one run; prints its wall time. RANKS = pair: two
# one-rank runs of the scene at the same time (DIR and DIR.b), no MPI between them; prints
# the mean of their wall times. What a pair loses against one run alone is what the two
# cores' shared cache and memory take, with no exchange and nothing serial.
run() {
  local ranks=$1 threads=$2 file=$3 steps=$4 dir=$5
  rm -rf "$dir" "$dir.b"
  if [ "$ranks" = pair ]; then
    "$rkpm" run "$file" --out "$dir" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null &
    "$rkpm" run "$file" --out "$dir.b" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null
    wait
    awk '/"wall_time"/ { gsub(/[^0-9.e+-]/, "", $2); t += $2; n++ } END { printf "%.9g\n", t / n }' "$dir/summary.json" "$dir.b/summary.json"
    return
  fi
  if [ "$ranks" = 1 ]; then
    "$rkpm" run "$file" --out "$dir" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null
  else
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" -x OMP_NUM_THREADS -x OMP_WAIT_POLICY \
      "$rkpm" run "$file" --out "$dir" --max-steps "$steps" --threads "$threads" --quiet 2>>"$scratch/runs.log" >/dev/null
  fi
  sed -n 's/^ *"wall_time": *\([0-9.e+-]*\).*/\1/p' "$dir/summary.json"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : v[NR / 2 + 1] }'; }

# The cases, one per line: CASE RANKS THREADS NX CELLS. Each is run REPEATS times, the
# cases taken in turn within each round, so that a slow spell of the machine falls on
# every case alike instead of on the one measured then (one run alone varied by about
# 15 % between spells of this 2-core machine, more than the losses measured).
cases=$(
  echo "weak 1 1 $cells $cells"
  echo "weak 2 1 $((2 * cells + 1)) $cells"
  echo "strong 1 1 $((2 * cells + 1)) $cells"
  echo "strong 2 1 $((2 * cells + 1)) $cells"
  echo "threads 1 2 $((2 * cells + 1)) $cells"
  # The weak case at other sizes per rank.
  for c in "${weak_cells[@]}"; do
    echo "weak 1 1 $c $c"
    echo "weak 2 1 $((2 * c + 1)) $c"
  done
  # At the largest size per rank, what the machine and the threads give without MPI:
  # the weak case's two halves as two independent processes at once (pair), and its
  # 2-rank block as one rank with 2 threads (weak_threads).
  largest_cells=$cells
  [ "${#weak_cells[@]}" -gt 0 ] && largest_cells=${weak_cells[-1]}
  echo "pair pair 1 $largest_cells $largest_cells"
  echo "weak_threads 1 2 $((2 * largest_cells + 1)) $largest_cells"
)
mapfile -t case_list <<<"$cases"

# One round: each case once; its step and set-up time appended to $scratch/case_I.
round() {
  local i=0 name ranks threads nx c file w1 w2 dir
  for line in "${case_list[@]}"; do
    read -r name ranks threads nx c <<<"$line"
    file=$(scene "$nx" "$c")
    dir=$scratch/run_$i
    w1=$(run "$ranks" "$threads" "$file" "$s1" "$dir")
    w2=$(run "$ranks" "$threads" "$file" "$s2" "$dir")
    awk -v a="$w1" -v b="$w2" -v s="$s1" -v t="$s2" 'BEGIN { printf "%.6g %.6g\n", (b - a) / (t - s), a - s * (b - a) / (t - s) }' >>"$scratch/case_$i"
    i=$((i + 1))
  done
}

# row I: the CSV row of case I, medians over the rounds; ghosts from its last run.
csv=$out/distributed.csv
echo "case,ranks,threads,particles,particles_per_rank,step_s,setup_s,ghosts_max,ghost_fraction,doubles_per_force_evaluation_max" >"$csv"
row() {
  local i=$1 name ranks threads nx c step setup particles ghosts=0 doubles=0 dir=$scratch/run_$1
  read -r name ranks threads nx c <<<"${case_list[$i]}"
  step=$(cut -d' ' -f1 "$scratch/case_$i" | median)
  setup=$(cut -d' ' -f2 "$scratch/case_$i" | median)
  particles=$(( (nx + 1) * (c + 1) * (c + 1) ))
  if [ "$ranks" != pair ] && [ "$ranks" -gt 1 ]; then
    largest() { tr -d ' \n' <"$dir/summary.json" | sed -n "s/.*\"$1\":\\[\\([0-9,]*\\)\\].*/\\1/p" | tr ',' '\n' | sort -n | tail -1; }
    ghosts=$(largest ghosts)
    doubles=$(largest doubles_received_and_returned_per_force_evaluation)
  fi
  awk -v c="$name" -v r="${ranks/pair/1}" -v t="$threads" -v n="$particles" -v st="$step" -v su="$setup" -v g="$ghosts" -v d="$doubles" 'BEGIN {
    printf "%s,%d,%d,%d,%d,%s,%s,%d,%.4f,%d\n", c, r, t, n, n / r, st, su, g, g / (n / r), d }' >>"$csv"
  echo "study distributed: $name on $ranks rank(s) x $threads thread(s), $particles particles: $step s per step, set-up $setup s"
}

load=$(cut -d' ' -f1-3 /proc/loadavg)
for ((k = 1; k <= repeats; k++)); do
  round
  echo "study distributed: round $k of $repeats done"
done
for ((i = 0; i < ${#case_list[@]}; i++)); do row "$i"; done

# The table and the model: out/distributed/distributed.md, and the page for a full run.
md=$out/distributed.md
awk -F, -v rev="$revision" -v load="$load" -v reps="$repeats" -v s1="$s1" -v s2="$s2" -v cores="$cores" '
NR == 1 { next }
{ c[NR] = $1; r[NR] = $2; th[NR] = $3; n[NR] = $4; npr[NR] = $5; st[NR] = $6; su[NR] = $7; g[NR] = $8; gf[NR] = $9; d[NR] = $10; last = NR
  row[$1 "," $2 "," $3 "," $5] = NR }
# The row of a case, its ranks x threads and its particles per rank (0 when not run).
function at(name, ranks, threads, per_rank) { return row[name "," ranks "," threads "," per_rank] + 0 }
END {
  printf "Measured by `scripts/study distributed` on %d cores, load average before the runs %s; each time the median of %d differences of %d- and %d-step runs (the set-up cancels). A pair is two one-rank runs of the same block at the same time, no MPI between them (the time per step is the mean of the two).\n\n", cores, load, reps, s1, s2
  print "| case | ranks x threads | particles | per rank | time per step [ms] | set-up [s] | ghosts (largest rank) | ghost fraction | doubles exchanged per force evaluation |"
  print "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  for (i = 2; i <= last; i++)
    printf "| %s | %s | %d | %d | %.2f | %.2f | %d | %.3f | %d |\n", c[i], (c[i] == "pair") ? "2 x (1 x 1)" : r[i] " x " th[i], (c[i] == "pair") ? 2 * n[i] : n[i], npr[i], 1000 * st[i], su[i], g[i], gf[i], d[i]
  # Weak efficiency at each size per rank, in the order measured; the last is the largest.
  sizes = ""; largest = 0
  for (i = 2; i <= last; i++)
    if (c[i] == "weak" && r[i] == 1 && at("weak", 2, 1, npr[i])) {
      e = st[i] / st[at("weak", 2, 1, npr[i])]
      sizes = sizes sprintf("%s**%.1f %%** at %d particles per rank", (sizes == "") ? "" : "; ", 100 * e, npr[i])
      largest = npr[i]; weak = e; w1 = i; w2 = at("weak", 2, 1, npr[i])
    }
  for (i = 2; i <= last; i++) { if (c[i] == "strong" && r[i] == 1) sa = i; if (c[i] == "strong" && r[i] == 2) sb = i; if (c[i] == "threads") tt = i }
  strong = st[sa] / st[sb]
  printf "\nWeak-scaling efficiency 1 -> 2 ranks (time per step at fixed particles per rank): %s.", sizes
  printf " Strong-scaling speed-up at %d particles: **%.2f** (efficiency %.0f %%). The same cores as one rank with 2 OpenMP threads: %.2f ms per step, so 2 ranks run at **%.2f x** the threaded speed.", n[sa], strong, 50 * strong, 1000 * st[tt], st[tt] / st[sb]
  p = at("pair", 1, 1, largest); wt = at("weak_threads", 1, 2, 2 * largest)
  if (p && wt)
    printf " At %d particles per rank, what no MPI is in: two independent one-rank runs at once keep **%.1f %%** of one run alone (the shared cache and memory), and one rank with 2 threads on the 2-rank block keeps **%.1f %%** (the threads pass the same seams and serial parts as the ranks).", largest, 100 * st[w1] / st[p], 100 * st[w1] / st[wt]
  print " Where the weak case loses its time is discussed above the table (docs/verification/distributed.md).\n"
  # The model: a step on P ranks of m particles each costs m t_c (the measured
  # one-rank time per particle-step) plus the ghost exchange (two messages to each
  # neighbour: displacements in, force records out, as many doubles per ghost as
  # measured) plus the collective reductions.
  # Inputs from the largest weak size measured: a rank of 1e6 particles is far out of
  # cache, as that one is.
  tc = st[w1] / n[w1]
  g0 = gf[w2]; m0 = npr[w2]; m = 1e6; P = 64
  gm = g0 * (m0 / m) ^ (1.0 / 3.0)           # ghost fraction ~ surface / volume of a part
  per_ghost = (g[w2] > 0) ? d[w2] / g[w2] : 6  # doubles per ghost, in and out, measured
  bytes = 8 * per_ghost * gm * m             # per step
  alpha = 2e-6; beta = 1.0 / 10e9; nb = 12; reductions = 12
  comm = 2 * nb * alpha + bytes * beta + reductions * alpha * log(P) / log(2)
  compute = tc * m
  eff = compute / (compute + comm)
  printf "\n**Model, 64 ranks x 1e6 particles** (inputs measured above except the network): compute %.3f s per step (%.3g s per particle-step, measured with one rank alone on the machine); ghost fraction %.3f (measured %.3f at %d particles per rank, scaled as m^(-1/3)); %.1f MB exchanged per rank per step; with an assumed network of 2 us latency, 10 GB/s per rank, 12 neighbours and 12 reductions of log2(64) stages per step: communication %.2g s, so the exchange costs %.2f %% of a step if it does not overlap the compute. With the loss measured here on one node (weak efficiency %.1f %%%s) the expected efficiency is **%.1f %%**.\n", compute, tc, gm, g0, m0, bytes / 1e6, comm, 100 * (1 - eff), 100 * weak, (p ? sprintf("; two independent runs at once keep %.1f %%", 100 * st[w1] / st[p]) : ""), 100 * eff * weak
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
