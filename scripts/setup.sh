#!/usr/bin/env bash
# Prepares a Debian 12 machine and builds ratbez into build/ (Release, every part, tests included).
#  1. installs, as root, only the Debian packages that are missing (one `apt-get update` when needed);
#  2. configures build/ with Ninja for /usr/bin/python3 (the interpreter FreeCAD embeds);
#  3. builds with ccache. Idempotent: with everything installed and built it takes a few seconds.
# Usage: bash scripts/setup.sh [--no-build]     (RATBEZ_BUILD_DIR overrides build/, RATBEZ_JOBS the -j 2)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(
  build-essential cmake ninja-build pkg-config ccache           # toolchain (gcc 12 ships ASan/UBSan)
  libocct-foundation-dev libocct-modeling-data-dev              # OpenCASCADE 7.6 (kernel/occt)
  libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libtbb-dev                                                    # OCCT's TKernel target links libtbb.so
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev              # CGAL mesh checks (openscad_export)
  pybind11-dev python3-dev python3-pytest python3-numpy         # the Python module and its tests
  nlohmann-json3-dev                                            # the CLI's JSON shape specs
  libgtest-dev libbenchmark-dev                                 # C++ tests, bench/
  clang libclang-rt-14-dev                                      # libFuzzer targets (fuzz/, scripts/fuzz.sh)
  openscad xvfb xauth                                           # OpenSCAD checks and PNG renders
  lib3mf-dev                                                    # 3MF writing (openscad_export; pkg-config lib3MF)
  freecad                                                       # the workbench and its tests
)

missing=()
for package in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null)" != installed ]; then
    missing+=("$package")
  fi
done
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup.sh: these packages are missing; run as root to install them: ${missing[*]}" >&2
    exit 1
  fi
  echo "setup.sh: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
fi

[ "${1:-}" = "--no-build" ] && exit 0

# ccache hits across clones in other directories (CI builds a fresh clone every run).
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
jobs="${RATBEZ_JOBS:-2}"
build="${RATBEZ_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPYBIND11_FINDPYTHON=ON -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$build" -j "$jobs"
