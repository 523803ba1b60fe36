#!/usr/bin/env bash
# Adhered sphere at rest against JKR / DMT / Maugis-Dugdale contact theory (seed 4.2).
# Runs examples/adhesion/sphere_at_rest.toml (a neo-Hookean sphere on a 100x stiffer
# block, relaxed to rest) at 16, 22, 32 and 44 cells across the sphere and at three moduli
# (E = 30, 10 and 90 kPa: Tabor parameters 0.23, 0.49 and 0.11), and a sphere twice as
# large at 15 kPa (Tabor 0.47 with the contact radius 0.3 R, as at 30 kPa; 22 to 60
# cells), the others' approach measured against the 30 kPa sphere's on the same clouds,
# and compares the edge of the compressive zone and the approach with Maugis-Dugdale for
# the scene's own contact law and with the self-consistent solution for the law's own
# traction (scripts/lib/adhesion_at_rest.py, contact_theory.py, derjaguin_contact.py).
# Writes
#   docs/figures/adhesion_theory.csv   one row per case and resolution
#   docs/figures/adhesion_theory.png   error against particles and against wall time
#   the generated table of docs/verification/adhesion.md
# The runs go to out/adhesion-theory/ (a run folder holding a summary.json is kept:
# delete it to rerun). About 35 minutes on 2 cores.
# Usage: scripts/study adhesion-theory [--coarse]
#   --coarse: 16 and 22 cells only (about 2 minutes); docs untouched.
# RKPM_THREADS sets the thread count (default 2); RKPM_BIN names a built rkpm.
set -euo pipefail
script_name="study adhesion-theory"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
out=$rkpm_out_root/adhesion-theory
coarse=()
for arg in "$@"; do
  case "$arg" in
    --coarse) coarse=(--coarse) ;;
    *) rkpm_die "unknown argument $arg (expected --coarse)" ;;
  esac
done
full=1
[ ${#coarse[@]} -eq 0 ] || full=0
rkpm_python_study adhesion_study.py "$out" adhesion_theory verification/adhesion.md "scripts/study adhesion-theory -->" "$full" "${coarse[@]}"
