#!/usr/bin/env bash
# Stability of the explicit integrator on stiff and extreme cases; energy ledger.
# Writes docs/figures/stability.csv and the generated table of
# docs/verification/stability.md (with --coarse: out/stability/ only, and 1,000 steps
# per case instead of 10,000). About 10 minutes on 2 cores.
# Every case is a scene file generated into a temporary directory and run with
# `rkpm run` for a fixed number of steps (free bodies, undamped except the releases run
# to rest; the energy ledger, dissipation included, must balance); the columns come
# from each run's summary.json and history.csv (one row per frame).
# Usage: scripts/study stability [--coarse]
# RKPM_THREADS sets the thread count (default 2).
set -euo pipefail
script_name="study stability"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
threads=${RKPM_THREADS:-2}
coarse=0
[ "${1:-}" = --coarse ] && coarse=1
figures="$here/docs/figures"
[ "$coarse" = 1 ] && figures=$rkpm_out_root/stability
doc="$here/docs/verification/stability.md"
mkdir -p "$figures"
csv="$figures/stability.csv"

rkpm_need jq
rkpm=$(rkpm_program)

work=$(mktemp -d)
table=$(mktemp)
trap 'rm -rf "$work" "$table" "$doc.tmp"' EXIT

size=1e-5       # block edge [m]
rho=1000        # [kg/m^3]
steps=10000     # steps per case
[ "$coarse" = 1 ] && steps=1000

# scene NAME CELLS RK_TOML INITIAL_TOML [INTEGRATOR_TOML]: a free block of side $size made
# of $MATERIAL; INTEGRATOR_TOML adds keys to [integrator].
# The frame interval is steps/20 times a step estimate from the P-wave speed of
# the material (MU and KBULK below), so history.csv gets about 20 rows.
scene() {
  local name=$1 cells=$2 rk=$3 initial=$4 integrator=${5:-}
  local dt_est every
  dt_est=$(awk -v h="$size" -v n="$cells" -v mu="$MU" -v k="$KBULK" -v rho="$rho" \
    'BEGIN { printf "%.6g", 0.5 * h / n / sqrt((k + 4 * mu / 3) / rho) }')
  every=$(awk -v dt="$dt_est" -v s="$steps" 'BEGIN { printf "%.6g", dt * s / 20 }')
  cat > "$work/$name.toml" <<TOML
[scene]
name = "$name"
[integrator]
t_end = $(awk -v dt="$dt_est" -v s="$steps" 'BEGIN { printf "%.6g", 100 * dt * s }')
$integrator
[output]
every = $every
cells = "points"
[[body]]
name = "block"
density = $rho
[body.cloud]
generator = "block"
size = [$size, $size, $size]
cells = [$cells, $cells, $cells]
jitter = 0.1
[body.material]
$MATERIAL
[body.rk]
$rk
[body.initial]
$initial
TOML
}

# mooney C1 LAMBDA / lce MU BULK ZETA: set MATERIAL (the [body.material] keys) and the
# small-strain moduli MU, KBULK that the step estimate of `scene` uses.
mooney() {
  MU=$(awk -v c="$1" 'BEGIN { print 2.5 * c }'); KBULK=$(awk -v l="$2" 'BEGIN { print 4 * l }')
  MATERIAL=$(printf 'model = "mooney_rivlin"\nc1 = %s\nc2 = %s\nlambda = %s' "$1" "$(awk -v c="$1" 'BEGIN { print c / 4 }')" "$2")
}
lce() {
  MU=$1; KBULK=$2
  MATERIAL=$(printf 'model = "lce"\nmu = %s\nbulk = %s\nmobility = 1e-3\nzeta = %s\n[body.director]\ninitial = "fixed"\nvector = [0, 0, 1]\nboundary = "free"' "$1" "$2" "$3")
}

scni='integration = "scni"'
wiggle='stretch = [1.05, 0.97, 1.0]'   # the reference case is released from a small stretch

echo "case,description,status,exit_code,steps,dt,max_energy_error,min_J,energy_left,steps_per_second,diagnosis" > "$csv"
{
  echo "| case | description | result | steps | dt [s] | max energy error | min J | energy left | steps/s |"
  echo "|---|---|---|---|---|---|---|---|---|"
} > "$table"

run_case() {
  local name=$1 description=$2 max_steps=${3:-$steps}
  local out="$work/out-$name" code=0
  "$rkpm" run "$work/$name.toml" --out "$out" --threads "$threads" --quiet --max-steps "$max_steps" \
    > "$work/$name.log" 2>&1 || code=$?
  local s="$out/summary.json"
  if [ ! -f "$s" ]; then
    echo "study stability: case $name wrote no summary (exit $code):" >&2; cat "$work/$name.log" >&2; exit 1
  fi
  local status nsteps dt wall diagnosis maxerr minj rate
  status=$(jq -r .status "$s"); nsteps=$(jq -r .steps "$s"); dt=$(jq -r .dt "$s"); wall=$(jq -r .wall_time "$s")
  diagnosis=$(jq -r '.diagnosis // ""' "$s")
  # Largest energy error and smallest J over the frames (history.csv), and the final state.
  # The columns by their names in the header (history.csv gains columns over time).
  read -r maxerr minj < <(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) { if ($c == "energy_error") ce = c; if ($c == "min_J") cj = c }; next }
                                   { e = ($ce < 0 ? -$ce : $ce); if (e > m) m = e; if (j == "" || $cj < j) j = $cj }
                                   END { printf "%.3g %.4g\n", m, j }' "$out/history.csv")
  if [ "$code" -ne 3 ]; then
    local final_err final_j
    final_err=$(jq -r '.energy.relative_error' "$s"); final_j=$(jq -r .min_J "$s")
    read -r maxerr minj < <(awk -v a="$maxerr" -v b="$final_err" -v c="$minj" -v d="$final_j" \
      'BEGIN { printf "%.3g %.4g\n", (a > b ? a : b), (c < d ? c : d) }')
  fi
  rate=$(awk -v n="$nsteps" -v w="$wall" 'BEGIN { printf "%.0f", (w > 0 ? n / w : 0) }')
  # Kinetic plus stored energy at the end over that at the start: 1 for an undamped run
  # that balances, near 0 for one that came to rest (below 1e-12 it is round-off); "-"
  # after a blow-up.
  local left="-"
  [ "$code" -ne 3 ] && left=$(jq -r '.energy | (.kinetic + .strain + .interface) / .initial | tostring' "$s" |
                               awk '{ if ($1 < 1e-12 && $1 > -1e-12) print "< 1e-12"; else printf "%.2g", $1 }')
  local result="stable"
  if [ "$code" -eq 3 ]; then result="blew up: ${diagnosis%%;*}"; elif [ "$code" -ne 0 ]; then result="exit $code ($status)"; fi
  printf '%s,"%s",%s,%s,%s,%s,%s,%s,%s,%s,"%s"\n' "$name" "$description" "$status" "$code" "$nsteps" "$dt" "$maxerr" \
    "$minj" "$left" "$rate" "${diagnosis//\"/\'}" >> "$csv"
  printf '| %s | %s | %s | %s | %.3g | %s | %s | %s | %s |\n' "$name" "$description" "$result" "$nsteps" "$dt" "$maxerr" \
    "$minj" "$left" "$rate" >> "$table"
  echo "$name: $result, $nsteps steps, max energy error $maxerr, min J $minj, energy left $left, $rate steps/s"
}

# Near-incompressible Mooney-Rivlin: lambda / c1 = 1e2, 1e3, 1e4 (c1 = 400 Pa, c2 = c1 / 4).
mooney 400 4000; scene reference 6 "$scni" "$wiggle";            run_case reference "Mooney-Rivlin, lambda/c1 = 10, 6^3 cells"
for r in 1e2 1e3 1e4; do
  mooney 400 "$(awk -v r="$r" 'BEGIN { print 400 * r }')"
  scene "mr_lambda_$r" 6 "$scni" "$wiggle"
  run_case "mr_lambda_$r" "Mooney-Rivlin, lambda/c1 = $r"
done
# LCE bulk modulus K = 1e2, 1e3, 1e4 mu (mu = 1000 Pa, s = 2, director along z).
for r in 1e2 1e3 1e4; do
  lce 1000 "$(awk -v r="$r" 'BEGIN { print 1000 * r }')" 0
  scene "lce_bulk_$r" 6 "$scni" "$wiggle"
  run_case "lce_bulk_$r" "LCE, K/mu = $r"
done
# Large initial stretch and compression, released (Mooney-Rivlin, lambda/c1 = 10).
mooney 400 4000; scene stretch_3 6 "$scni" 'stretch = [3.0, 1.0, 1.0]';    run_case stretch_3 "released from stretch 3 along x"
mooney 400 4000; scene compress_0.3 6 "$scni" 'stretch = [0.3, 1.0, 1.0]'; run_case compress_0.3 "released from compression 0.3 along x"
mooney 400 4000; scene stretch_3_all 6 "$scni" 'stretch = [3.0, 3.0, 3.0]'; run_case stretch_3_all "released from stretch 3 in all directions"
mooney 400 4000; scene compress_0.3_all 6 "$scni" 'stretch = [0.3, 0.3, 0.3]'; run_case compress_0.3_all "released from compression 0.3 in all directions"
# The same releases with the stable step estimated every step (stable_step_interval = 1).
per_step='stable_step_interval = 1'
mooney 400 4000; scene stretch_3_every 6 "$scni" 'stretch = [3.0, 1.0, 1.0]' "$per_step"; run_case stretch_3_every "released from stretch 3 along x, stable step every step"
mooney 400 4000; scene compress_0.3_every 6 "$scni" 'stretch = [0.3, 1.0, 1.0]' "$per_step"; run_case compress_0.3_every "released from compression 0.3 along x, stable step every step"
mooney 400 4000; scene stretch_3_all_every 6 "$scni" 'stretch = [3.0, 3.0, 3.0]' "$per_step"; run_case stretch_3_all_every "released from stretch 3 in all directions, stable step every step"
mooney 400 4000; scene compress_0.3_all_every 6 "$scni" 'stretch = [0.3, 0.3, 0.3]' "$per_step"; run_case compress_0.3_all_every "released from compression 0.3 in all directions, stable step every step"
# The releases run to rest: mass-proportional damping 3e6 / s (ten times an estimate of
# the block's slowest angular frequency, pi c_s / L ~ 3e5 rad/s) with the stable step
# every step; and the two settings next to it that do not hold the releases in all
# directions.
damped=$'damping = 3e6\nstable_step_interval = 1'
mooney 400 4000; scene stretch_3_damped 6 "$scni" 'stretch = [3.0, 1.0, 1.0]' "$damped"; run_case stretch_3_damped "released from stretch 3 along x, damping 3e6 / s, stable step every step"
mooney 400 4000; scene compress_0.3_damped 6 "$scni" 'stretch = [0.3, 1.0, 1.0]' "$damped"; run_case compress_0.3_damped "released from compression 0.3 along x, damping 3e6 / s, stable step every step"
mooney 400 4000; scene stretch_3_all_damped 6 "$scni" 'stretch = [3.0, 3.0, 3.0]' "$damped"; run_case stretch_3_all_damped "released from stretch 3 in all directions, damping 3e6 / s, stable step every step"
mooney 400 4000; scene compress_0.3_all_damped 6 "$scni" 'stretch = [0.3, 0.3, 0.3]' "$damped"; run_case compress_0.3_all_damped "released from compression 0.3 in all directions, damping 3e6 / s, stable step every step"
mooney 400 4000; scene stretch_3_all_damped_10 6 "$scni" 'stretch = [3.0, 3.0, 3.0]' 'damping = 3e6'; run_case stretch_3_all_damped_10 "released from stretch 3 in all directions, damping 3e6 / s, stable step every 10 steps"
mooney 400 4000; scene compress_0.3_all_damped_1e6 6 "$scni" 'stretch = [0.3, 0.3, 0.3]' $'damping = 1e6\nstable_step_interval = 1'; run_case compress_0.3_all_damped_1e6 "released from compression 0.3 in all directions, damping 1e6 / s, stable step every step"
# High activity: |zeta| = 0.5, 2, 10 mu, contractile and extensile (LCE, K = 100 mu).
for z in 0.5 2 10 -2 -10; do
  lce 1000 1e5 "$(awk -v z="$z" 'BEGIN { print 1000 * z }')"
  scene "lce_zeta_$z" 6 "$scni" "$wiggle"
  run_case "lce_zeta_$z" "LCE, K = 100 mu, zeta = $z mu"
done
# Random initial velocities of 0.1 and 1 times the shear-wave speed (1 m/s).
mooney 400 4000; scene random_0.1 6 "$scni" 'random_velocity = 0.1'; run_case random_0.1 "random velocities, amplitude 0.1 c_s"
mooney 400 4000; scene random_1 6 "$scni" 'random_velocity = 1.0';   run_case random_1 "random velocities, amplitude 1 c_s"
# Very coarse and very fine clouds.
mooney 400 4000; scene coarse 2 "$scni" "$wiggle"; run_case coarse "very coarse cloud, 2^3 cells (27 particles)"
mooney 400 4000; scene fine 16 "$scni" "$wiggle"; run_case fine "fine cloud, 16^3 cells (4913 particles)" 3000
# Contrasts: no stabilization, and direct nodal integration with and without it.
mooney 400 4000; scene scni_unstabilized 6 "$scni"$'\nstabilization = 0' 'random_velocity = 0.1'
run_case scni_unstabilized "SCNI without stabilization, random velocities 0.1 c_s"
mooney 400 4000; scene direct 6 'integration = "direct"' 'random_velocity = 0.1'
run_case direct "direct nodal integration, stabilization 0.1, random velocities 0.1 c_s"
mooney 400 4000; scene direct_unstabilized 6 $'integration = "direct"\nstabilization = 0' 'random_velocity = 0.1'
run_case direct_unstabilized "direct nodal integration without stabilization, random velocities 0.1 c_s"

if [ "$coarse" = 1 ]; then
  cp "$table" "$figures/stability.md"
  echo "wrote $csv and $figures/stability.md"
else
  rkpm_replace_generated "$doc" "$table"
  echo "wrote $csv and the table in $doc"
fi
