#!/usr/bin/env bash
# Crawling on a graded substrate (seed 4.3): drift of graded, uniform, mirrored runs.
# Runs examples/crawling/crawling.toml on the
# graded substrate of Eq. 18 (moduli x (4 y/L0 + 0.5), stiffer towards +y), on a
# uniform substrate of the same mean stiffness (x 2.5) and on the mirrored gradient
# (x (4.5 - 4 y/L0)), and writes
#   docs/figures/crawling_drift.csv   time and centroid drift along y of the three runs
#   docs/figures/crawling_drift.png   the drift against time (gnuplot)
#   the generated table of docs/verification/crawling.md
# The runs go to out/crawling/. The default run takes a few minutes on 2 cores.
# Usage: scripts/study crawling [--coarse]
#   --coarse: an 11-cell sphere on a 30 x 30 x 3 block (s0 = 1 um), about 1 minute;
#             writes into out/crawling/ only (the docs keep the default run).
# RKPM_THREADS sets the thread count (default 2).
set -euo pipefail
script_name="study crawling"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
threads=${RKPM_THREADS:-2}
out=$rkpm_out_root/crawling
scene="$here/examples/crawling/crawling.toml"
doc="$here/docs/verification/crawling.md"
coarse=0
[ "${1:-}" = "--coarse" ] && coarse=1

rkpm_need jq gnuplot
rkpm=$(rkpm_program)
mkdir -p "$out"
if [ "$coarse" = 1 ]; then
  figures="$out"
else
  figures="$here/docs/figures"
fi

# variant NAME GRADE_A GRADE_B: the scene with the substrate's grading replaced.
variant() {
  local file="$out/$1.toml"
  sed -e "s/^grade_a = .*/grade_a = $2/" -e "s/^grade_b = .*/grade_b = $3/" "$scene" > "$file"
  if [ "$coarse" = 1 ]; then
    # s0 = lateral spacing / 1.25 = 1 um; eps keeps |W(d0)| = 1e-3 J/m^2; release 200 nm beyond 0.6368 s0.
    sed -i -e 's/^cells = 17 .*/cells = 11/' -e 's/^cells = \[40, 40, 4\].*/cells = [30, 30, 3]/' \
      -e 's/^s0 = .*/s0 = 1e-6/' -e 's/^epsilon = .*/epsilon = 1.0331e-15/' \
      -e 's/^center = .*/center = [0.0, 0.0, 10.3368e-6]/' "$file"
  fi
  # The scene's directory is where relative paths would resolve: none are used.
  grep -q "^grade_a = $2\$" "$file" && grep -q "^grade_b = $3\$" "$file" ||
    { echo "study crawling: could not set the grading in $file" >&2; exit 1; }
}
variant graded 4.0 0.5
variant uniform 0.0 2.5
variant mirrored -4.0 4.5

for run in graded uniform mirrored; do
  echo "== $run"
  OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=passive "$rkpm" run "$out/$run.toml" --out "$out/$run" --threads "$threads" --quiet
done

# Columns of history.csv by name.
column() { head -1 "$1" | tr ',' '\n' | grep -n "^$2\$" | cut -d: -f1; }
for run in graded uniform mirrored; do
  h="$out/$run/history.csv"
  t=$(column "$h" time); y=$(column "$h" centroid_y)
  awk -F, -v t="$t" -v y="$y" 'NR == 2 { y0 = $y } NR > 1 { printf "%.6g,%.6g\n", $t * 1e6, ($y - y0) * 1e9 }' "$h" > "$out/$run.drift"
done
csv="$figures/crawling_drift.csv"
{
  echo "time_us,drift_y_nm_graded,drift_y_nm_uniform,drift_y_nm_mirrored"
  paste -d, "$out/graded.drift" <(cut -d, -f2 "$out/uniform.drift") <(cut -d, -f2 "$out/mirrored.drift")
} > "$csv"

gnuplot <<GNUPLOT
set terminal pngcairo size 800,500
set output "$figures/crawling_drift.png"
set datafile separator ","
set key top left
set xlabel "time [us]"
set ylabel "centroid drift along y [nm]"
set title "Cell centroid drift on graded, uniform and mirrored substrates"
set grid
plot "$csv" using 1:2 skip 1 with linespoints title "graded (stiffer at +y)", \
     "$csv" using 1:3 skip 1 with linespoints title "uniform (mean stiffness)", \
     "$csv" using 1:4 skip 1 with linespoints title "mirrored (stiffer at -y)"
GNUPLOT

# Table: final drifts and the sign and symmetry criteria.
value() { jq -r ".\"contact cell substrate\".report.$2" "$out/$1/summary.json"; }
g=$(value graded 'drift[1]'); u=$(value uniform 'drift[1]'); m=$(value mirrored 'drift[1]')
table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
  echo "| run | substrate moduli x | drift along y [nm] | drift along x [nm] | contact radius [um] | smallest gap [s0] | energy error | steps | wall [s] |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for run in graded uniform mirrored; do
    case $run in graded) f="4 y/L0 + 0.5";; uniform) f="2.5";; mirrored) f="4.5 - 4 y/L0";; esac
    s0=$(grep '^s0 = ' "$out/$run.toml" | sed 's/s0 = //')
    jq -r --arg run "$run" --arg f "$f" --argjson s0 "$s0" \
      '.["contact cell substrate"].report as $r |
       "| \($run) | \($f) | \($r.drift[1] * 1e9 | . * 100 | round / 100) | \($r.drift[0] * 1e9 | . * 100 | round / 100) | \($r.contact_radius * 1e6 | . * 1000 | round / 1000) | \($r.min_gap_over_frames / $s0 | . * 1000 | round / 1000) | \(.energy.relative_error | . * 1e6 | round / 1e6) | \(.steps) | \(.wall_time | round) |"' \
      "$out/$run/summary.json"
  done
  echo
  awk -v g="$g" -v u="$u" -v m="$m" 'BEGIN {
    printf "- toward the stiffer side (graded drift > 0): %s\n", (g > 0 ? "yes" : "NO");
    printf "- mirrored drift / graded drift: %.4f (criterion: -1 within 10 %%): %s\n", m / g, ((m / g < -0.9 && m / g > -1.1) ? "met" : "NOT met");
    printf "- |uniform drift| / |graded drift|: %.4f (criterion: < 0.1): %s\n", (u < 0 ? -u : u) / (g < 0 ? -g : g), (((u < 0 ? -u : u) < 0.1 * (g < 0 ? -g : g)) ? "met" : "NOT met");
  }'
} > "$table"
cat "$table"
if [ "$coarse" = 0 ]; then
  rkpm_replace_generated "$doc" "$table" "scripts/study crawling -->"
  echo "wrote $csv, $figures/crawling_drift.png and the table of $doc"
else
  echo "wrote $csv and $figures/crawling_drift.png (coarse: docs untouched)"
fi
