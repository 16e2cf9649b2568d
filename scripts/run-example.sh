#!/usr/bin/env bash
# The main job on the bundled examples: installs what is missing, builds in Release, and writes
# to out/: the quality report of the bundled femur surface, before and after the triangle
# enhancement, and a terrain surface built from the bundled scattered elevation points
# (reconstruct -> simplify -> quality report).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
build/bin/meshprep quality examples/data/femur.off \
  --json out/femur_quality.json --html out/femur_quality.html --vtk out/femur_quality.vtk --csv out/femur_faces.csv
build/bin/meshprep enhance examples/data/femur.off -o out/femur_enhanced.off --json out/femur_enhance.json
build/bin/meshprep quality out/femur_enhanced.off --reference examples/data/femur.off \
  --json out/femur_enhanced_quality.json --html out/femur_enhanced_quality.html --vtk out/femur_enhanced_quality.vtk
build/bin/meshprep reconstruct examples/data/jacksboro_10k.xyz -o out/terrain.ply --json out/terrain_reconstruct.json
build/bin/meshprep simplify out/terrain.ply -o out/terrain_simplified.ply --ratio 0.2 --json out/terrain_simplify.json
build/bin/meshprep quality out/terrain_simplified.ply --reference out/terrain.ply \
  --json out/terrain_quality.json --html out/terrain_quality.html --vtk out/terrain_quality.vtk
echo "Reports written to out/ (open out/*_quality.html in a browser, out/*_quality.vtk and out/terrain.ply in ParaView)"
