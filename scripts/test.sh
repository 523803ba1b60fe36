#!/usr/bin/env bash
# README command (b): install what is missing, build, test.
# Usage: scripts/test.sh [--fast | --sanitizers | --all]
#   (none)        the newcomer's check: the Release build and its whole test suite,
#                 then the installed library (cmake --install, examples/embedding built
#                 against it and run, the Python module's tests against the installed
#                 module) and one ParaView picture rendered headless and
#                 checked not blank (scripts/render-pictures.sh --check).
#   --fast        the Release build and the tests labelled `fast` only (about a minute
#                 once built): what a developer runs between edits.
#   --sanitizers  a Debug build under AddressSanitizer and UndefinedBehaviorSanitizer
#                 in RKPM_BUILD_DIR-asan (build-asan/) and its suite, but the tests
#                 labelled `sanitizer-skipped` (each says why in tests/).
#   --all         (none) and then --sanitizers: what CI runs (.ci/run).
# Exits non-zero if anything fails. docs/development/testing.md describes the labels.
set -euo pipefail
script_name=test.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
mode=${1:-default}
case "$mode" in
  default | --fast | --sanitizers | --all) ;;
  *) echo "test.sh: unknown option '$mode' (expected --fast, --sanitizers or --all)" >&2; exit 2 ;;
esac
here=$rkpm_root
build=$rkpm_build_dir
bash "$here/scripts/install-deps.sh"
jobs=$(nproc)
# ctest runs test programs side by side; OpenMP threads that spin at barriers while
# another process holds the core would slow them tenfold. Passive waiting avoids it.
export OMP_WAIT_POLICY=passive

release_suite() {
  echo "== Release build and tests${1:+ (label $1)}"
  rkpm_build
  ctest --test-dir "$build" --output-on-failure -j"$jobs" ${1:+-L "$1"}
}

installed_library() {
  echo "== Installed library: examples/embedding built against 'cmake --install' and run"
  rm -rf "$build/install" "$build/embedding"
  cmake --install "$build" --prefix "$build/install" >/dev/null
  cmake -S "$here/examples/embedding" -B "$build/embedding" -DCMAKE_PREFIX_PATH="$build/install" >/dev/null
  cmake --build "$build/embedding" -j"$jobs"
  "$build/embedding/embed_rkpm"
  echo "== Installed Python module: the pytest suite against 'cmake --install', with Debian's python3"
  local site
  site=$(cd "$build/install" && ls -d lib/python3*/dist-packages)
  (cd "$build" && PYTHONPATH="$build/install/$site" RKPM_SOURCE_DIR="$here" RKPM_BIN="$build/install/bin/rkpm" \
    /usr/bin/python3 -c 'import rkpm, sys; sys.exit(0 if rkpm.__file__.startswith(sys.argv[1]) else 1)' "$build/install" &&
    PYTHONPATH="$build/install/$site" RKPM_SOURCE_DIR="$here" RKPM_BIN="$build/install/bin/rkpm" \
    /usr/bin/python3 -m pytest -q -p no:cacheprovider "$here/python/tests")
}

paraview_check() {
  echo "== ParaView: the spread-cell example run, rendered headless by pvbatch and checked not blank"
  # Installs ParaView for the rendering and the build packages again afterwards (they
  # conflict on Debian 12).
  bash "$here/scripts/render-pictures.sh" --check "$build/pictures-run" "$build/pictures"
}

sanitizer_suite() {
  echo "== Debug build under AddressSanitizer + UndefinedBehaviorSanitizer and tests"
  local asan="$build-asan"
  cmake -S "$here" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DRKPM_SANITIZE=ON -DRKPM_BUILD_BENCH=OFF >/dev/null
  cmake --build "$asan" -j"$jobs"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$asan" --output-on-failure -j"$jobs" -LE sanitizer-skipped
}

case "$mode" in
  --fast) release_suite fast ;;
  --sanitizers) sanitizer_suite ;;
  default) release_suite; installed_library; paraview_check ;;
  --all) release_suite; installed_library; paraview_check; sanitizer_suite ;;
esac
