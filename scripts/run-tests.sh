#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds in Release into build/, runs ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh -DMESHPREP_WERROR=ON
cd build
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
