#!/usr/bin/env bash
# Runs the step benchmarks (bench_sim: internal force per material, director
# update, contact pair list and forces, surface tension, one frame of output, whole
# steps) and the operator benchmarks (bench_rk), and writes Google Benchmark's CSV
# into OUT_DIR: bench_sim.csv, bench_rk.csv. docs/verification/performance.md explains the counters.
# Usage: bash scripts/bench.sh [BUILD_DIR] [OUT_DIR] [Google Benchmark options...]
#   e.g. bash scripts/bench.sh build out/bench --benchmark_min_time=0.1 --benchmark_filter=Contact
# Threads: OMP_NUM_THREADS (default 2, the threads the scaling study's bound uses).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$here/build
out=$here/out/bench
[ $# -gt 0 ] && [[ $1 != --* ]] && { build=$1; shift; }
[ $# -gt 0 ] && [[ $1 != --* ]] && { out=$1; shift; }

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target bench_sim bench_rk -j"$(nproc)"
for program in bench_sim bench_rk; do
  [ -x "$build/bench/$program" ] ||
    { echo "bench.sh: $build/bench/$program was not built (is Google Benchmark installed?)" >&2; exit 1; }
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
