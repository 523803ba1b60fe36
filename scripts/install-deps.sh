#!/usr/bin/env bash
# Installs the Debian 12 packages rkpm needs to build, test and plot (as root).
# Usage: scripts/install-deps.sh [--fuzz]
# ParaView's Python and Xvfb, for the pictures, conflict with libvtk9-dev: they are
# installed and removed again by scripts/render-pictures.sh around its rendering.
# Every dependency is a Debian package: nothing is downloaded at build time.
#   install-deps.sh          the build, the tests, the benchmarks and the plots
#   install-deps.sh --fuzz   also clang and libFuzzer for scripts/study fuzz (the
#                            normal build does not need them)
set -euo pipefail

fuzz=0
for arg in "$@"; do
  case "$arg" in
    -h | --help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    --fuzz) fuzz=1 ;;
    *) echo "install-deps: unknown option $arg (expected --fuzz)" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake g++ make   # toolchain (g++ 12, cmake 3.25)
  libeigen3-dev                    # Eigen 3.4: small dense algebra, sparse LU
  libnanoflann-dev                 # nanoflann 1.4.3: kd-trees for neighbours and contact pairs
  libvtk9-dev                      # VTK 9.1: .vtu/.pvd output and .vtu import
  libgmsh-dev                      # Gmsh 4.8 C++ API: .msh import and .geo meshing
  libtomlplusplus-dev              # toml++ 3.3: scene files
  libcli11-dev                     # CLI11: command line
  libopenmpi-dev openmpi-bin       # OpenMPI 4.1: distributed runs (mpirun), the 2-rank tests
  libmetis-dev                     # METIS 5.1: partition of the bodies over the ranks
  libfmt-dev                       # fmt: messages
  nlohmann-json3-dev               # nlohmann/json 3.11: summary.json
  libgtest-dev                     # GoogleTest: the test suite
  libbenchmark-dev                 # Google Benchmark: bench/
  gnuplot-nox                      # PNG plots of the studies
  python3 jq                       # the studies' tables (summary.json, history.csv)
  pybind11-dev python3-dev         # the Python module rkpm (python/)
  python3-numpy python3-pytest     # its arrays and its tests
  python3-mpi4py                   # the module under mpirun
  python3-matplotlib               # the Python examples' plots
  python3-scipy                    # the Helfrich reference solver (scripts/lib/helfrich.py)
)
if [ "$fuzz" = 1 ]; then
  packages+=(
    clang-14                       # the fuzz build's compiler
    libclang-rt-14-dev             # libFuzzer (-fsanitize=fuzzer), ASan and UBSan runtimes for clang
    libomp-14-dev                  # OpenMP for clang
    llvm-14                        # llvm-symbolizer: readable stacks in sanitizer reports
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run as root (or install them)" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
