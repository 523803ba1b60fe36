#!/usr/bin/env bash
# What a run driven from Python costs against the rkpm program, on the RBC scene.
# Runs examples/rbc/rbc.toml (the default relaxation, nested levels included) with
# `rkpm run` and with `rkpm.Simulation.run()` plus a progress callback at every step,
# alternately, 3 times each on 2 threads; writes out/python/overhead.csv and, unless
# --coarse, the table of docs/guide/python.md ("Cost"). About 5 minutes on 2 cores.
# Usage: scripts/study python [--coarse]
#   --coarse: the sag scene (examples/sag), 3 times each (seconds); docs untouched.
set -euo pipefail
script_name="study python"
source "$(dirname "$0")/../lib/common.sh"
rkpm_help_if_asked "$@"
here=$rkpm_root
out=$rkpm_out_root/python
scene=$here/examples/rbc/rbc.toml
update_docs=1
if [ "${1:-}" = --coarse ]; then scene=$here/examples/sag/sag.toml; update_docs=0; fi
rkpm=$(rkpm_program)
rkpm_build _rkpm >&2 || rkpm_die "building the Python module in $rkpm_build_dir failed"
rm -rf "$out" && mkdir -p "$out"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
PYTHONPATH="$rkpm_build_dir/python" /usr/bin/python3 "$here/python/bench/callback_overhead.py" \
  "$rkpm" "$scene" "$out" 3 2 | tee "$out/overhead.csv"
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
if [ "$update_docs" = 1 ]; then
  summary=$(grep '^# medians' "$out/overhead.csv" | sed 's/^# medians: //')
  {
    echo "Measured by \`scripts/study python\` on $(basename "$scene") (2 threads, 3 runs of each,"
    echo "alternating; load average before $load_before, after $load_after). Each wall time is"
    echo "the whole run, set-up and nested levels included, from the outside."
    echo
    echo "| run | repeat | wall [s] | steps |"
    echo "|---|---:|---:|---:|"
    grep -v '^#\|^tool' "$out/overhead.csv" | awk -F, '{ printf "| %s | %d | %.2f | %d |\n", $1, $2, $3, $4 }'
    echo
    echo "Medians: $summary."
  } > "$out/table.md"
  rkpm_replace_generated "$here/docs/guide/python.md" "$out/table.md" "python overhead"
  echo "updated docs/guide/python.md"
fi
