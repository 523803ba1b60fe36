#!/usr/bin/env bash
# Regenerates the convergence study of the RK discretisation with nodal integration
# (Lame sphere under internal pressure): docs/figures/convergence.csv, the plots
# docs/figures/convergence-*.png and the generated part of docs/verification/convergence.md.
# Usage: bash scripts/convergence-study.sh [extra rkpm_convergence options]
# The build directory is build/ unless RKPM_BUILD_DIR says otherwise.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${RKPM_BUILD_DIR:-"$here/build"}
figures="$here/docs/figures"
doc="$here/docs/verification/convergence.md"

command -v gnuplot >/dev/null || { echo "convergence-study.sh: gnuplot is required for the plots" >&2; exit 1; }
grep -q '<!-- BEGIN GENERATED' "$doc" && grep -q '<!-- END GENERATED' "$doc" ||
  { echo "convergence-study.sh: $doc lacks the BEGIN/END GENERATED markers" >&2; exit 1; }

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target rkpm_convergence -j"$(nproc)"
program="$build/bench/rkpm_convergence"
[ -x "$program" ] || { echo "convergence-study.sh: $program was not built (is Google Benchmark installed?)" >&2; exit 1; }

mkdir -p "$figures"
# Idle OpenMP threads sleep instead of spinning: the solver runs many short
# parallel loops, and on a machine shared with other work spinning threads steal
# the cores the working ones need (measured: up to 10x slower solves).
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
csv="$figures/convergence.csv"
table=$(mktemp)
trap 'rm -f "$table" "$doc.tmp"' EXIT
"$program" --csv "$csv" --markdown "$table" "$@"

# Replace the text between the markers with the fresh table.
awk -v table="$table" '
  /<!-- BEGIN GENERATED/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /<!-- END GENERATED/   { skip = 0 }
  !skip                  { print }' "$doc" > "$doc.tmp"
mv "$doc.tmp" "$doc"

# Reference slopes h^2 and h^1 (N^-2/3, N^-1/3), drawn through the coarsest
# stabilized run so the measured lines can be compared with them by eye.
read -r n0 l20 en0 t0 < <(awk -F, '$1 == "scni-stabilized" { print $4, $6, $7, $8 + $9; exit }' "$csv")

gnuplot <<GNUPLOT
set datafile separator ","
set terminal png size 1200,520 font ",11"
set logscale xy
set grid
set key bottom left
set format y "10^{%L}"
schemes = "scni-stabilized scni direct"
titles = "'SCNI + stabilization (alpha 0.1)' 'SCNI' 'direct nodal integration'"
pick(s, col) = strcol(1) eq s && strcol(14) eq "" ? column(col) : NaN

set output "$figures/convergence-error-vs-particles.png"
set multiplot layout 1,2
set xlabel "particles N"
set ylabel "relative L2 displacement error"
plot for [i=1:3] "$csv" using 4:(pick(word(schemes,i),6)) every ::1 with linespoints lw 2 pt 7 title word(titles,i), \
     $l20 * (x / $n0)**(-2.0/3) dt 2 lc rgb "gray40" title "slope h^2"
set ylabel "relative energy-norm error"
plot for [i=1:3] "$csv" using 4:(pick(word(schemes,i),7)) every ::1 with linespoints lw 2 pt 7 title word(titles,i), \
     $en0 * (x / $n0)**(-1.0/3) dt 2 lc rgb "gray40" title "slope h^1"
unset multiplot

set output "$figures/convergence-error-vs-time.png"
set multiplot layout 1,2
set xlabel "wall time, set-up + solve [s]"
set ylabel "relative L2 displacement error"
plot for [i=1:3] "$csv" using (column(8) + column(9)):(pick(word(schemes,i),6)) every ::1 with linespoints lw 2 pt 7 title word(titles,i)
set ylabel "relative energy-norm error"
plot for [i=1:3] "$csv" using (column(8) + column(9)):(pick(word(schemes,i),7)) every ::1 with linespoints lw 2 pt 7 title word(titles,i)
unset multiplot
GNUPLOT
echo "wrote $csv, $figures/convergence-error-vs-particles.png, $figures/convergence-error-vs-time.png and $doc"
