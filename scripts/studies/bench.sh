#!/usr/bin/env bash
# Step and operator benchmarks (Google Benchmark), CSV in out/bench/.
# Runs the step benchmarks (bench_sim: internal force per material, director
# update, contact pair list and forces, surface tension, one frame of output, whole
# steps) and the operator benchmarks (bench_rk), and writes Google Benchmark's CSV
# into out/bench/: bench_sim.csv, bench_rk.csv. docs/verification/performance.md
# explains the counters. A few minutes on 2 cores.
# Usage: scripts/study bench [Google Benchmark options...]
#   e.g. scripts/study bench --benchmark_min_time=0.1 --benchmark_filter=Contact
# Threads: OMP_NUM_THREADS (default 2, the threads the scaling study's bound uses).
set -euo pipefail
script_name="study bench"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
build=$rkpm_build_dir
out=$rkpm_out_root/bench

rkpm_build bench_sim bench_rk
for program in bench_sim bench_rk; do
  [ -x "$build/bench/$program" ] ||
    { echo "study bench: $build/bench/$program was not built (is Google Benchmark installed?)" >&2; exit 1; }
done

mkdir -p "$out"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
# The fixtures read examples/ from the source tree this script belongs to.
export RKPM_SOURCE_DIR=$here
for program in bench_sim bench_rk; do
  echo "== $program ($OMP_NUM_THREADS threads)"
  "$build/bench/$program" --benchmark_out="$out/$program.csv" --benchmark_out_format=csv "$@"
done
echo "wrote $out/bench_sim.csv and $out/bench_rk.csv"
