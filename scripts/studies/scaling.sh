#!/usr/bin/env bash
# Particle-count scaling: set-up, step, bandwidth bound and memory up to 1e6 particles.
# docs/verification/performance.md: for a Mooney-Rivlin block, an
# LCE sphere and the RBC shell from 1e3 to --max particles, the set-up time (split by
# stage), the time per step with 1 and 2 threads, the internal force against the
# STREAM-triad bandwidth bound, peak memory per particle and the fitted exponents;
# then the default RBC relaxation's wall time. Each size runs in its own process.
# Also the machine's arithmetic peak and the internal force's counted operations: the
# roofline (perf-roofline.png) and, after a --native run, the two builds side by side.
# Writes out/scaling/perf-scaling.{csv,md} and perf-{step,setup,memory}-vs-particles.png;
# a full run (--max 1000000 with the RBC run, the default) also copies them to
# docs/figures/ and the tables into docs/verification/performance.md.
# Usage: scripts/study scaling [--native] [--coarse] [--max N] [--no-rbc-run] [rkpm_scaling options...]
#   --max defaults to 1000000 (about 7 minutes on 2 cores; 100000 takes a few).
#   --coarse: --max 100000 --no-rbc-run; docs untouched.
#   --no-rbc-run skips the default RBC relaxation's timing.
#   --native: the same study with a build for this machine's instruction set
#     (-DRKPM_NATIVE=ON, in the build folder's name with -native appended), into
#     out/scaling-native/; a full run copies its CSV to docs/figures/perf-scaling-native.csv
#     and its tables stay in out/. Either full run redraws the roofline and the
#     side-by-side table in docs/verification/performance.md from the two CSV files.
set -euo pipefail
script_name="study scaling"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
build=$rkpm_build_dir
out=$rkpm_out_root/scaling
max=1000000
rbc_run=1
extra=()
coarse=0
native=0
while [ $# -gt 0 ]; do
  case $1 in
    --native) native=1; shift ;;
    --coarse) coarse=1; max=100000; rbc_run=0; shift ;;
    --max) max=$2; shift 2 ;;
    --max=*) max=${1#--max=}; shift ;;
    --no-rbc-run) rbc_run=0; shift ;;
    *) extra+=("$1"); shift ;;
  esac
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
doc=$here/docs/verification/performance.md
update_doc=0
[ "$coarse" = 0 ] && [ "$max" = 1000000 ] && [ "$rbc_run" = 1 ] && [ ${#extra[@]} -eq 0 ] && update_doc=1

rkpm_need gnuplot python3
rkpm_need_python_modules matplotlib
if [ $native = 1 ]; then
  build=$rkpm_build_dir-native
  out=$rkpm_out_root/scaling-native
  mkdir -p "$out"
  out=$(cd "$out" && pwd)
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRKPM_NATIVE=ON -DRKPM_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$build" -j"$(nproc)" --target rkpm_scaling rkpm
else
  rkpm_build rkpm_scaling rkpm
fi
program=$build/bench/rkpm_scaling
[ -x "$program" ] || rkpm_die "$program was not built (is Google Benchmark installed?)"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
native_flag=""
[ $native = 0 ] || native_flag=" --native"
command_text="scripts/study scaling$native_flag --max $max${extra[*]:+ ${extra[*]}}"

# The default RBC relaxation, as command (a) of the README runs it but with 2 threads.
rbc_args=()
if [ $rbc_run = 1 ]; then
  echo "RBC relaxation (examples/rbc/rbc.toml, 2 threads): running"
  OMP_NUM_THREADS=2 "$build/src/app/rkpm" run "$here/examples/rbc/rbc.toml" --out "$scratch/rbc" --quiet ||
    echo "RBC relaxation: exit $?"
  if [ -f "$scratch/rbc/summary.json" ]; then
    read -r wall steps status < <(python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
print(s["wall_time"], s["steps"], s["status"].replace(" ", "_"))' "$scratch/rbc/summary.json")
    rbc_args=(--rbc-relaxation-wall "$wall" --rbc-relaxation-steps "$steps" --rbc-relaxation-status "${status//_/ }")
  fi
else
  command_text+=" --no-rbc-run"
fi

csv=$out/perf-scaling.csv
table=$out/perf-scaling.md
"$program" --max "$max" --csv "$csv" --markdown "$table" --rbc-scene "$here/examples/rbc/rbc.toml" \
  --command "$command_text" "${rbc_args[@]}" "${extra[@]}"


gnuplot <<GNUPLOT
set datafile separator ","
set terminal png size 900,600 font ",11" noenhanced
set logscale xy
set grid
set key top left
set xlabel "particles N"
geometries = "block sphere shell"
titles = "'Mooney-Rivlin block' 'LCE sphere' 'RBC shell'"
pick(g, value) = strcol("geometry") eq g && strcol("status") eq "ok" ? value : NaN

set output "$out/perf-step-vs-particles.png"
set ylabel "time per step [s]"
plot for [i=1:3] "$csv" using "particles":(pick(word(geometries,i), column("step_2t_s"))) \
       with linespoints lw 2 pt 7 lc i title word(titles,i)." (2 threads)", \
     for [i=1:3] "$csv" using "particles":(pick(word(geometries,i), column("step_1t_s"))) \
       with linespoints lw 1 dt 2 pt 6 lc i title word(titles,i)." (1 thread)"

set output "$out/perf-setup-vs-particles.png"
set ylabel "set-up: build_world + initialize [s]"
plot for [i=1:3] "$csv" using "particles":(pick(word(geometries,i), column("setup_total_s"))) \
       with linespoints lw 2 pt 7 lc i title word(titles,i), \
     2.0 * x / 1e5 dt 3 lc rgb "gray40" title "target: 2 s per 100k particles"

set output "$out/perf-memory-vs-particles.png"
set ylabel "bytes per particle"
plot for [i=1:3] "$csv" using "particles":(pick(word(geometries,i), column("peak_bytes_per_particle"))) \
       with linespoints lw 2 pt 7 lc i title word(titles,i)." (peak RSS)", \
     for [i=1:3] "$csv" using "particles":(pick(word(geometries,i), column("array_bytes_per_particle"))) \
       with linespoints lw 1 dt 2 pt 6 lc i title word(titles,i)." (Body arrays)", \
     2048 dt 3 lc rgb "gray40" title "target: 2 KB per particle"
GNUPLOT
echo "wrote $csv, $out/perf-{step,setup,memory}-vs-particles.png and $table"

# The roofline and the two builds side by side: from the docs' CSV files after a full
# run (the other build's from its own last full run), else from out/ alone.
figures=$here/docs/figures
if [ $update_doc = 1 ]; then
  if [ $native = 1 ]; then
    cp "$csv" "$figures/perf-scaling-native.csv"
  else
    rkpm_replace_generated "$doc" "$table" "scripts/study scaling -->"
    cp "$csv" "$out"/perf-{step,setup,memory}-vs-particles.png "$figures/"
  fi
  portable_csv=$figures/perf-scaling.csv native_csv=$figures/perf-scaling-native.csv
  roofline_png=$figures/perf-roofline.png
else
  portable_csv=$rkpm_out_root/scaling/perf-scaling.csv native_csv=$rkpm_out_root/scaling-native/perf-scaling.csv
  roofline_png=$out/perf-roofline.png
fi
if [ -f "$portable_csv" ]; then
  /usr/bin/python3 "$here/scripts/lib/roofline.py" --portable "$portable_csv" \
    $([ ! -f "$native_csv" ] || echo --native "$native_csv") --png "$roofline_png" --table "$out/builds.md"
  echo "wrote $roofline_png and $out/builds.md"
  if [ $update_doc = 1 ]; then
    rkpm_replace_generated "$doc" "$out/builds.md" "scripts/lib/roofline.py -->"
    echo "updated docs/figures/perf-* and $doc"
  fi
fi
