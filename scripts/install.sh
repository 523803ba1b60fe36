#!/usr/bin/env bash
# Installs rkpm for use: the Debian packages, a Release build of the `rkpm` program and
# the Python module, and `cmake --install` into PREFIX (default /usr/local, as root):
# then `rkpm` is on the PATH and Debian's python3 imports `rkpm` from
# PREFIX/lib/python3.X/dist-packages, which it searches for /usr/local.
# Usage: scripts/install.sh [PREFIX]
#   Another PREFIX needs PYTHONPATH=PREFIX/lib/python3.X/dist-packages.
set -euo pipefail
script_name=install.sh
source "$(dirname "$0")/lib/common.sh"
rkpm_help_if_asked "$@"
prefix=${1:-/usr/local}
bash "$rkpm_root/scripts/install-deps.sh"
rkpm_build rkpm _rkpm
cmake --install "$rkpm_build_dir" --prefix "$prefix" >/dev/null
site=$(cd "$prefix" && ls -d lib/python3*/dist-packages)
echo "installed $prefix/bin/rkpm and the Python module in $prefix/$site"
if [ "$prefix" = /usr/local ]; then
  /usr/bin/python3 -c 'import rkpm; print("python3 -c \"import rkpm\":", rkpm.__file__)'
else
  echo "use it with: PYTHONPATH=$prefix/$site /usr/bin/python3"
fi
