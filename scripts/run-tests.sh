#!/usr/bin/env bash
# The whole test suite, as CI runs it: installs what is missing, then
#   1. Release (warnings are errors) into build/, every test;
#   2. ASan + UBSan (clang, Debug at -O1 -g1, with libFuzzer's instrumentation, warnings are
#      errors) into build-sanitize/: the readers' and the quality module's tests (meshprep_tests),
#      then each reader's fuzz target 10 s on its seeds: the surface readers and the tet mesh
#      readers (compiled alone, without the rest of meshprep::fem: ~40 s more to build, 50 s to run),
#      and the three geometric stages on tiny decoded meshes, 10 s each: the self-intersection
#      search against its exact reference, simplify, and repair (meshprep::preprocess under the
#      sanitizers; the repair's exact cuts meet every degenerate case of a grid).
# The second pass is kept to the modules every input goes through first, so that both passes fit
# CI's 15-minute budget on 2 cores (a sanitizer build of everything takes ~12 minutes there).
# `--sanitize-all` builds everything under the sanitizers and runs every test and fuzz target.
# Usage: scripts/run-tests.sh [--release-only | --sanitize-all]
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
case $mode in "" | --release-only | --sanitize-all) ;; *) echo "usage: scripts/run-tests.sh [--release-only | --sanitize-all]" >&2; exit 2 ;; esac
jobs=$(nproc 2>/dev/null || echo 2)
bash scripts/install-deps.sh

echo "== Release build and every test"
bash scripts/build.sh -DMESHPREP_WERROR=ON
(cd build && ctest --output-on-failure -j "$jobs")
[ "$mode" != --release-only ] || exit 0

echo "== ASan + UBSan build, tests and fuzz targets"
launcher=()  # as in scripts/build.sh
! command -v ccache >/dev/null || launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR=$PWD
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ -DMESHPREP_BUILD_FUZZERS=ON "${launcher[@]}" \
  -DMESHPREP_WERROR=ON -DMESHPREP_BUILD_BENCH=OFF -DMESHPREP_BUILD_EXAMPLES=OFF -DMESHPREP_INSTALL=OFF >/dev/null
if [ "$mode" = --sanitize-all ]; then
  cmake --build build-sanitize -j "$jobs"
  (cd build-sanitize && ctest --output-on-failure -j "$jobs")
  FUZZ_BUILD_DIR=build-sanitize bash scripts/fuzz.sh 10
else
  readers=(off obj ply stl xyz msh vtu vtk medit tetgen)
  stages=(self_intersections simplify repair)
  cmake --build build-sanitize -j "$jobs" --target meshprep_tests "${readers[@]/#/fuzz_}" "${stages[@]/#/fuzz_}"
  build-sanitize/bin/meshprep_tests --gtest_brief=1
  FUZZ_BUILD_DIR=build-sanitize bash scripts/fuzz.sh 10 "${readers[@]}" "${stages[@]}"
fi
