#!/usr/bin/env bash
# libFuzzer on the scene loader, the .vtu and Gmsh importers and the checkpoint reader;
# minimised corpus.
# Usage: scripts/study fuzz [--coarse] [SECONDS] [TARGET...]
#   SECONDS per target, default 1800. TARGETs among scene, vtu, msh, geo, checkpoint
#   (default: all five); they run side by side, one process each.
#   --coarse: 60 s per target, and the report is not written into the docs.
#
# Installs clang and libFuzzer (install-deps.sh --fuzz), builds the fuzz programs
# with ASan and UBSan in RKPM_BUILD_DIR-fuzz (build-fuzz/), runs each from the seeds
# and the committed corpus, minimises what they reached into tests/fuzz/corpus/, and
# prints a report whose rows also replace those targets' rows of the "Last run"
# section of docs/verification/fuzzing.md. Inputs that crash, hang or exhaust memory
# are kept in out/fuzz/<target>/artifacts/. Exits non-zero if a fuzzer found anything.
set -euo pipefail
script_name="study fuzz"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
coarse=0
if [ "${1:-}" = --coarse ]; then coarse=1; shift; fi
seconds=$([ "$coarse" = 1 ] && echo 60 || echo 1800)
case "${1:-}" in [0-9]*) seconds=$1; shift ;; esac
case "$seconds" in '' | *[!0-9]*) echo "$script_name: SECONDS must be a positive integer, got '$seconds'" >&2; exit 2 ;; esac
all_targets=(scene vtu msh geo checkpoint)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  case " ${all_targets[*]} " in *" $t "*) ;; *) echo "$script_name: unknown target '$t', expected one of: ${all_targets[*]}" >&2; exit 2 ;; esac
done

bash "$here/scripts/install-deps.sh" --fuzz

build="$rkpm_build_dir-fuzz"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
echo "== Fuzz build (clang, ASan, UBSan, libFuzzer) in $build"
CC=clang-14 CXX=clang++-14 cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRKPM_FUZZ=ON \
  -DRKPM_BUILD_TESTS=OFF -DRKPM_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
if [ -x "$symbolizer" ]; then export ASAN_SYMBOLIZER_PATH="$symbolizer"; fi
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fuzz_dir="$here/tests/fuzz"
run="$rkpm_out_root/fuzz"
# The file targets write each input to a temporary file; a crashing worker leaves its file.
mkdir -p "$run/tmp"
export TMPDIR="$run/tmp"

# Per target: maximum input length and extra options. The .vtu and Gmsh fuzzers run
# without leak detection: VTK's reader leaks on some malformed files (see
# tests/fuzz/known_vtk_leaks.cpp), Gmsh keeps a process-wide model, and telling those
# leaks apart needs full stacks on every allocation, which costs a factor of ten in
# speed. test_fuzz_replay checks the minimised corpus for leaks under the sanitized
# build instead. A checkpoint seed is about 18 KB.
max_len() { case "$1" in scene | geo) echo 4096 ;; vtu | msh) echo 16384 ;; checkpoint) echo 32768 ;; esac; }
leaks() { case "$1" in scene | checkpoint) echo 1 ;; *) echo 0 ;; esac; }
asan_options() { if [ "$(leaks "$1")" = 1 ]; then echo "detect_leaks=1"; else echo "detect_leaks=0:fast_unwind_on_malloc=1"; fi; }
leak_flag() { echo "-detect_leaks=$(leaks "$1")"; }

pids=()
# An interrupted study stops its fuzzers (and they their workers).
trap 'kill "${pids[@]}" 2>/dev/null; exit 130' INT TERM
for t in "${targets[@]}"; do
  rm -rf "${run:?}/$t"
  mkdir -p "$run/$t/corpus" "$run/$t/artifacts"
  # The fuzzer writes into its first directory: give it copies, never the sources.
  cp "$fuzz_dir/seeds/$t/"* "$run/$t/corpus/"
  if [ -d "$fuzz_dir/corpus/$t" ]; then cp "$fuzz_dir/corpus/$t/"* "$run/$t/corpus/" 2>/dev/null || true; fi
  echo "== fuzz_$t for ${seconds} s ($(ls "$run/$t/corpus" | wc -l) starting inputs), log in $run/$t/fuzz.log"
  ASAN_OPTIONS=$(asan_options $t) nice -n 10 "$build/tests/fuzz/fuzz_$t" \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 "$(leak_flag $t)" \
    -max_total_time="$seconds" -max_len="$(max_len $t)" -timeout=10 -rss_limit_mb=2048 \
    -dict="$fuzz_dir/dict/$t.dict" -artifact_prefix="$run/$t/artifacts/" \
    "$run/$t/corpus" >"$run/$t/fuzz.log" 2>&1 &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=$?; done
[ "$status" = 0 ] || echo "fuzz.sh: a fuzzer exited with status $status (see the logs)" >&2

# Minimise: the corpus keeps only inputs that reach something the seeds do not.
# Hand-named files (regression inputs for fixed bugs) are kept as they are.
for t in "${targets[@]}"; do
  merged="$run/$t/merged"
  rm -rf "$merged" && mkdir -p "$merged"
  for f in "$fuzz_dir/seeds/$t/"*; do cp "$f" "$merged/seed-$(basename "$f")"; done
  ASAN_OPTIONS=$(asan_options $t) nice -n 10 "$build/tests/fuzz/fuzz_$t" -merge=1 "$(leak_flag $t)" \
    -max_len="$(max_len $t)" -timeout=10 -rss_limit_mb=2048 "$merged" "$run/$t/corpus" >"$run/$t/merge.log" 2>&1
  rm -f "$merged"/seed-*
  mkdir -p "$fuzz_dir/corpus/$t"
  find "$fuzz_dir/corpus/$t" -maxdepth 1 -type f -regextype posix-extended -regex '.*/[0-9a-f]{40}' -delete
  cp "$merged/"* "$fuzz_dir/corpus/$t/" 2>/dev/null || true
done

# Report from the last status line of each log:
#   #EXECS: cov: C ft: F corp: N exec/s E oom/timeout/crash: O/T/X time: Ss job: J
report() {
  local t=$1 line execs cov ft oom timeouts crashes secs artifacts
  line=$(grep -E '^#[0-9]+: cov:' "$run/$t/fuzz.log" | tail -n 1 || true)
  execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$line")
  cov=$(sed -E 's/.* cov: ([0-9]+).*/\1/' <<<"$line")
  ft=$(sed -E 's/.* ft: ([0-9]+).*/\1/' <<<"$line")
  IFS=/ read -r oom timeouts crashes < <(sed -E 's/.*oom\/timeout\/crash: ([0-9]+\/[0-9]+\/[0-9]+).*/\1/' <<<"$line")
  secs=$(sed -E 's/.* time: ([0-9]+)s.*/\1/' <<<"$line")
  artifacts=$(ls "$run/$t/artifacts" | wc -l)
  execs=${execs:-0} secs=${secs:-0}
  printf '| fuzz_%s | %s | %s s | %s | %s | %s | %s | %s | %s / %s / %s | %s |\n' "$t" "$(date -u +%Y-%m-%d)" "$secs" \
    "$execs" "$(( execs / (secs > 0 ? secs : 1) ))" "${cov:-?}" "${ft:-?}" \
    "$(ls "$fuzz_dir/corpus/$t" | wc -l) files, $(( $(cat "$fuzz_dir/corpus/$t/"* | wc -c) / 1024 )) KiB" \
    "${crashes:-?}" "${timeouts:-?}" "${oom:-?}" "$artifacts"
}
header='| target | run of | time | executions | exec/s | coverage (edges) | features | minimised corpus | crashes / timeouts / OOMs | artifacts |'
rows=$(for t in "${targets[@]}"; do report "$t"; done)
echo
echo "${#targets[@]} target(s) side by side, ${seconds} s each, one process each (ASan + UBSan):"
echo
echo "$header"
echo "$rows"
doc="$here/docs/verification/fuzzing.md"
if [ "$coarse" = 0 ] && [ -f "$doc" ] && grep -q '<!-- fuzz-report:begin -->' "$doc"; then
  # This run's rows replace the same targets' rows; the other targets keep theirs.
  kept=$(sed -n '/<!-- fuzz-report:begin -->/,/<!-- fuzz-report:end -->/p' "$doc" | grep '^| fuzz_' || true)
  for t in "${targets[@]}"; do kept=$(grep -v "^| fuzz_$t |" <<<"$kept" || true); done
  {
    echo "$header"
    echo "|---|---|---|---|---|---|---|---|---|---|"
    for t in "${all_targets[@]}"; do grep -h "^| fuzz_$t |" <(echo "$rows") <(echo "$kept") || true; done
  } >"$run/report.md"
  awk -v report="$run/report.md" '
    /<!-- fuzz-report:end -->/ { skipping = 0 }
    !skipping { print }
    /<!-- fuzz-report:begin -->/ { while ((getline line < report) > 0) print line; skipping = 1 }
  ' "$doc" >"$run/fuzzing.md" && cp "$run/fuzzing.md" "$doc"
  echo "(written to docs/verification/fuzzing.md)"
fi

found=0
for t in "${targets[@]}"; do found=$(( found + $(ls "$run/$t/artifacts" | wc -l) )); done
if [ "$found" -gt 0 ]; then
  echo "$script_name: $found input(s) crashed, hung or ran out of memory: see $run/<target>/artifacts/" >&2
  exit 1
fi
