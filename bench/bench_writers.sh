#!/usr/bin/env bash
# Writing the femur's tets in every format, side by side (bench_writers.cpp): each format's time
# over .msh's and the files' sizes. Usage: bench/bench_writers.sh [BUILD_DIR] (default build).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
femur=$root/../shared/data/meshes/femur.off
[ -f "$femur" ] || femur=$root/examples/data/femur.off
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/meshprep" tetrahedralize "$femur" -o "$work/femur.msh" --no-improve > /dev/null 2>&1 || [ $? = 1 ]  # 1: written, not FEM-ready
# Repetitions in random order, so that the machine's drift falls on every format alike.
"$build/bin/bench_writers" --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true "$work/femur.msh"
