#!/usr/bin/env bash
# ParaView pictures of the example runs (scripts/pictures/render.py), as root.
# Usage: scripts/render-pictures.sh [--run] [--check] [OUT_DIR] [PICTURE_DIR]
#   OUT_DIR      where the runs are: OUT_DIR/rbc, OUT_DIR/adhesion, OUT_DIR/crawling,
#                OUT_DIR/spread_cell (default out/)
#   PICTURE_DIR  where the PNGs go (default docs/figures/pictures)
#   --run        first run the example scenes whose runs are missing with
#                the build's rkpm (on 2 cores: rbc about a minute, adhesion 70 s,
#                crawling 50 s, spread_cell 10 s)
#   --check      the CI check: run spread_cell only, render it, fail on a blank picture
# Debian's python3-paraview conflicts with libvtk9-dev, the build dependency: when
# pvbatch is missing, this installs ParaView and a virtual X display (Xvfb), renders,
# then removes ParaView and installs the build packages again (scripts/install-deps.sh).
set -euo pipefail
script_name=render-pictures.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
run=0 check=0 args=()
for a in "$@"; do
  case "$a" in
    --run) run=1 ;;
    --check) check=1; run=1 ;;
    -*) echo "render-pictures.sh: unknown option $a (expected --run or --check)" >&2; exit 2 ;;
    *) args+=("$a") ;;
  esac
done
out=${args[0]:-"$rkpm_out_root"}
pictures=${args[1]:-"$here/docs/figures/pictures"}
views=(rbc adhesion crawling spread_cell)
[ "$check" = 1 ] && views=(spread_cell)

if [ "$run" = 1 ]; then
  rkpm=$(rkpm_program)
  for v in "${views[@]}"; do
    scene="$here/examples/$v/$v.toml"
    [ -f "$out/$v/summary.json" ] || "$rkpm" run "$scene" --out "$out/$v" --quiet
  done
fi

installed=0
if ! command -v pvbatch >/dev/null || ! command -v Xvfb >/dev/null; then
  [ "$(id -u)" -eq 0 ] || { echo "render-pictures: pvbatch or Xvfb missing; run as root to install them" >&2; exit 1; }
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends python3-paraview xvfb xauth
  installed=1
fi
restore() {
  if [ "$installed" = 1 ]; then
    apt-get remove -y -q python3-paraview paraview
    bash "$here/scripts/install-deps.sh"
  fi
}
trap restore EXIT

# A virtual X display of our own, waited for (xvfb-run's fixed wait is not enough on a
# loaded machine).
display=99
while [ -e "/tmp/.X11-unix/X$display" ] || [ -e "/tmp/.X$display-lock" ]; do display=$((display + 1)); done
Xvfb ":$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
for _ in $(seq 1 300); do [ -S "/tmp/.X11-unix/X$display" ] && break; sleep 0.1; done
code=0
DISPLAY=":$display" pvbatch "$here/scripts/pictures/render.py" "$out" "$pictures" "${views[@]}" || code=$?
kill "$xvfb" 2>/dev/null || true
exit "$code"
