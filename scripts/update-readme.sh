#!/usr/bin/env bash
# Regenerates the parameter reference in README.md from `rkpm params --markdown`.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
rkpm=${RKPM:-"$here/build/src/app/rkpm"}
python3 - "$here/README.md" "$("$rkpm" params --markdown)" <<'PY'
import sys
path, table = sys.argv[1], sys.argv[2]
text = open(path).read()
begin, end = "<!-- BEGIN PARAMETER REFERENCE -->", "<!-- END PARAMETER REFERENCE -->"
head, rest = text.split(begin)
_, tail = rest.split(end)
open(path, "w").write(head + begin + "\n" + table.rstrip("\n") + "\n" + end + tail)
PY
