#!/usr/bin/env bash
# Configures and builds meshprep in Release into build/ (the binary lands at build/bin/meshprep).
# Extra arguments are passed to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# ccache, when installed, makes a rebuild from a fresh clone on a machine that built before cost
# seconds instead of minutes (CI's budget is 15 minutes on 2 cores).
launcher=()
! command -v ccache >/dev/null || launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR=$PWD  # paths inside the clone hashed relative: a clone elsewhere hits too
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build build -j "$jobs"
