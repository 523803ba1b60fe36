#!/usr/bin/env bash
# Regenerates docs/reference/parameters.md from `rkpm params --markdown`.
# Usage: scripts/update-params.sh
# The test suite fails when the page and the program disagree
# (tests/scene: the parameter reference is up to date).
set -euo pipefail
script_name=update-params.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
rkpm=$(rkpm_program)
page="$rkpm_root/docs/reference/parameters.md"
{
  echo "# Parameter reference"
  echo
  echo "Every key a scene file may set, generated from the program's own parameter tables by"
  echo "\`scripts/update-params.sh\` (\`rkpm params --markdown\`; \`rkpm params\` prints the same in"
  echo "a terminal). [Scene files](../guide/scenes.md) explains the format, the sections with"
  echo "variants and the consistency rules between keys."
  echo
  echo "<!-- BEGIN PARAMETER REFERENCE -->"
  "$rkpm" params --markdown | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'
  echo "<!-- END PARAMETER REFERENCE -->"
} >"$page.tmp"
mv "$page.tmp" "$page"
echo "wrote $page"
