#!/usr/bin/env bash
# README command (b): install what is missing, build, run the whole test suite twice:
# an optimised Release build, then a Debug build under AddressSanitizer and
# UndefinedBehaviorSanitizer; between the two, install the Release build into
# build/install and build and run examples/embedding against it, and render one
# ParaView picture headless (scripts/render-pictures.sh --check). Exits non-zero if
# anything fails.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/install-deps.sh"
jobs=$(nproc)
# ctest runs test programs side by side; OpenMP threads that spin at barriers while
# another process holds the core would slow them tenfold. Passive waiting avoids it.
export OMP_WAIT_POLICY=passive

echo "== Release build and tests"
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$here/build" -j"$jobs"
ctest --test-dir "$here/build" --output-on-failure -j"$jobs"

echo "== Installed library: examples/embedding built against 'cmake --install' and run"
rm -rf "$here/build/install" "$here/build/embedding"
cmake --install "$here/build" --prefix "$here/build/install" >/dev/null
cmake -S "$here/examples/embedding" -B "$here/build/embedding" -DCMAKE_PREFIX_PATH="$here/build/install" >/dev/null
cmake --build "$here/build/embedding" -j"$jobs"
"$here/build/embedding/embed_rkpm"

echo "== ParaView: the spread-cell example run, rendered headless by pvbatch and checked not blank"
# Installs ParaView for the rendering and the build packages again afterwards (they
# conflict on Debian 12), before the sanitizer build needs them.
bash "$here/scripts/render-pictures.sh" --check "$here/build/pictures-run" "$here/build/pictures"

if [ "${RKPM_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "== Debug build under AddressSanitizer + UndefinedBehaviorSanitizer and tests"
  cmake -S "$here" -B "$here/build-asan" -DCMAKE_BUILD_TYPE=Debug -DRKPM_SANITIZE=ON -DRKPM_BUILD_BENCH=OFF >/dev/null
  cmake --build "$here/build-asan" -j"$jobs"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$here/build-asan" --output-on-failure -j"$jobs"
fi
