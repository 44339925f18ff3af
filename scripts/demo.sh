#!/usr/bin/env bash
# The main job: set up and build everything, install the FreeCAD workbench, then build every example
# under examples/, export it (OpenSCAD, STL, STEP), check it (CGAL, OpenCASCADE) and render PNGs into out/demo.
# Run as root on Debian 12: bash scripts/demo.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh

# The RatBez workbench and the ratbez module beside it, into FreeCAD's Mod folder
# (/usr/share/freecad/Mod/RatBez as root; see freecad_workbench/CMakeLists.txt).
cmake --install build --component freecad

out=out/demo
mkdir -p "$out"
build/cli/ratbez demo "$out"

echo
echo "demo: pictures and files are in $PWD/$out"
find "$out" -name '*.png' | sort | sed 's/^/  /'
