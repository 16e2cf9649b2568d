#!/usr/bin/env bash
# The main job on the bundled example: installs what is missing, builds in Release, and writes
# the quality report of the bundled femur surface to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
build/bin/meshprep quality examples/data/femur.off \
  --json out/femur_quality.json --html out/femur_quality.html --vtk out/femur_quality.vtk --csv out/femur_faces.csv
echo "Reports written to out/ (open out/femur_quality.html in a browser, out/femur_quality.vtk in ParaView)"
