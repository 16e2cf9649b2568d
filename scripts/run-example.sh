#!/usr/bin/env bash
# The main job on the bundled examples: installs what is missing, builds in Release, and runs
# meshprep pipeline on
#   - examples/data/jacksboro_10k.xyz: 10,000 scattered elevation points -> a terrain surface ->
#     simplified -> enhanced -> closed into a block -> tets (out/terrain/);
#   - examples/data/fandisk.off: a closed CAD part -> simplified to 30 % -> enhanced -> tets
#     (out/fandisk/);
#   - examples/data/femur.off: a bone surface with slivers -> enhanced -> tets (out/femur/).
# Each folder gets surface.ply, tets.msh, report.html, report.json, report.vtu, pipeline.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
build/bin/meshprep pipeline examples/data/jacksboro_10k.xyz -o out/terrain
build/bin/meshprep pipeline examples/data/fandisk.off -o out/fandisk --ratio 0.3
build/bin/meshprep pipeline examples/data/femur.off -o out/femur
echo "Open out/terrain/report.html, out/fandisk/report.html and out/femur/report.html in a browser;"
echo "the tet meshes out/*/tets.msh in Gmsh, out/*/report.vtu in ParaView."
