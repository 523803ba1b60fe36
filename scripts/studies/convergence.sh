#!/usr/bin/env bash
# Convergence of the RK discretisation (Lame sphere): rates, error against run time.
# Regenerates the convergence study of the RK discretisation with nodal integration
# (Lame sphere under internal pressure): docs/figures/convergence.csv, the plots
# docs/figures/convergence-*.png and the generated part of docs/verification/convergence.md.
# With --coarse, the same into out/convergence/ only (the docs keep the full run).
# Usage: scripts/study convergence [--coarse] [extra rkpm_convergence options]
#   (rkpm_convergence --help lists them; --coarse passes its smallest ladder)
set -euo pipefail
script_name="study convergence"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
build=$rkpm_build_dir
figures="$here/docs/figures"
doc="$here/docs/verification/convergence.md"
coarse=0
coarse_options=()
if [ "${1:-}" = --coarse ]; then
  coarse=1; shift; figures=$rkpm_out_root/convergence
  coarse_options=(--resolutions 5x3,7x4,9x5 --contrast-resolutions 5x3,7x4)
fi

rkpm_need gnuplot
rkpm_build rkpm_convergence
program="$build/bench/rkpm_convergence"
[ -x "$program" ] || rkpm_die "$program was not built (is Google Benchmark installed?)"

mkdir -p "$figures"
# Idle OpenMP threads sleep instead of spinning: the solver runs many short
# parallel loops, and on a machine shared with other work spinning threads steal
# the cores the working ones need (measured: up to 10x slower solves).
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
csv="$figures/convergence.csv"
table=$(mktemp)
trap 'rm -f "$table" "$doc.tmp"' EXIT
"$program" --csv "$csv" --markdown "$table" "${coarse_options[@]}" "$@"

if [ "$coarse" = 1 ]; then cp "$table" "$figures/convergence.md"; doc=$figures/convergence.md
else rkpm_replace_generated "$doc" "$table"; fi

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
