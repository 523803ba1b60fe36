#!/usr/bin/env bash
# Crawling drift at four resolutions of cell and substrate together, with its controls.
# Runs examples/crawling/crawling.toml with 17, 21, 25 and 29 cells across the cell and
# the block refined with it (40 x 40 x 4 to 68 x 68 x 7 cells), each on the graded,
# uniform and mirrored substrate (scripts/lib/crawling_convergence.py), and writes
#   docs/figures/crawling_convergence.csv   one row per run and resolution
#   docs/figures/crawling_convergence.png   drift against particles; its estimated error
#                                           against wall time
#   the generated table (crawling-convergence) of docs/verification/crawling.md
# The runs go to out/crawling-convergence/ (a run folder holding a summary.json is kept:
# delete it to rerun). About 50 minutes on 2 cores.
#   --registry [--cells N ...]: the graded runs to 30 us with the cell's start at 0, 1/4,
#           1/2 and 3/4 of the block's spacing along y at every resolution (or those
#           named), the velocity averaged over the registry with its standard error
#           (about 100 minutes for the four; the runs shared with --long and --split),
#           writing docs/figures/crawling_convergence_registry.{csv,png} and the
#           generated table (crawling-convergence --registry) of
#           docs/verification/crawling.md.
#   --fine: what sets the velocity: the ladder on a block 0.5 s0 apart along x and y,
#           its coarsest with the cell's start moved by half a spacing, the two finest
#           on a block 0.5 s0 apart along z too, each run's contact energy with the
#           overdamped velocity it implies and the layered bodies' adhesion energy at
#           its spacings (scripts/lib/layered_contact.py); reuses the --split and
#           --registry runs (about 90 minutes beyond them), writing
#           docs/figures/crawling_convergence_fine.{csv,png} and the generated table
#           (crawling-convergence --fine) of docs/verification/crawling.md.
# Usage: scripts/study crawling-convergence [--coarse] [--long | --split | --registry [--cells N ...] | --fine]
#   --coarse: 17 and 21 cells only (about 8 minutes); docs untouched.
#   --long: the graded runs alone, to 30 us instead of 12 (about 30 minutes), writing
#           docs/figures/crawling_convergence_long.{csv,png} and the generated table
#           (crawling-convergence --long) of docs/verification/crawling.md.
#   --split: the graded run to 30 us with the cell and the substrate resolved on their
#           own (the cell at 17 cells across on blocks of 40 to 68 cells, at 29 on 40 and
#           68; the matched pairs shared with --long; about 35 minutes), writing
#           docs/figures/crawling_convergence_split.{csv,png} and the generated table
#           (crawling-convergence --split) of docs/verification/crawling.md.
# RKPM_THREADS sets the thread count (default 2); RKPM_BIN names a built rkpm.
set -euo pipefail
script_name="study crawling-convergence"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
out=$rkpm_out_root/crawling-convergence
options=()
full=1
stem=crawling_convergence
key="scripts/study crawling-convergence -->"
for arg in "$@"; do
  case "$arg" in
    --coarse) options+=(--coarse); full=0 ;;
    --long) options+=(--long); stem=crawling_convergence_long; key="scripts/study crawling-convergence --long -->" ;;
    --split) options+=(--split); stem=crawling_convergence_split; key="scripts/study crawling-convergence --split -->" ;;
    --registry) options+=(--registry); stem=crawling_convergence_registry; key="scripts/study crawling-convergence --registry -->" ;;
    --fine) options+=(--fine); stem=crawling_convergence_fine; key="scripts/study crawling-convergence --fine -->" ;;
    --cells|[0-9]*) options+=("$arg") ;;
    *) rkpm_die "unknown argument $arg (expected --coarse, --long, --split, --registry, --fine or --cells N ...)" ;;
  esac
done
rkpm_python_study crawling_convergence.py "$out" "$stem" verification/crawling.md "$key" "$full" "${options[@]}"
