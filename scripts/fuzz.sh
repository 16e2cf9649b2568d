#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang, ASan + UBSan) into build-fuzz/ and runs each, as
# many side by side as there are cores (each libFuzzer run is one process), for SECONDS_PER_TARGET
# (default 30) on a scratch copy of its seed corpus (fuzz/corpus/TARGET; nothing is written into the repository). Prints one row per
# target and fails if any found a crash, a leak, an input slower than 10 s or one needing more than
# 2 GB; the input is kept in build-fuzz/artifacts/TARGET/ (replay it: build-fuzz/bin/fuzz_TARGET FILE).
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]
#   (targets: off obj ply stl xyz, the tet mesh readers msh vtu vtk medit tetgen, config, and the
#   geometric stages on tiny decoded meshes self_intersections simplify repair)
# FUZZ_BUILD_DIR=DIR uses an existing fuzzer build (MESHPREP_BUILD_FUZZERS=ON) instead of build-fuzz/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift $(($# > 0 ? 1 : 0))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(off obj ply stl xyz msh vtu vtk medit tetgen config self_intersections simplify repair)
build=${FUZZ_BUILD_DIR:-build-fuzz}  # scripts/run-tests.sh points it at its sanitizer build

if ! grep -q '^MESHPREP_BUILD_FUZZERS:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ -DMESHPREP_BUILD_FUZZERS=ON \
    -DMESHPREP_BUILD_TESTS=OFF -DMESHPREP_BUILD_APPS=OFF -DMESHPREP_BUILD_BENCH=OFF -DMESHPREP_BUILD_EXAMPLES=OFF \
    -DMESHPREP_INSTALL=OFF >/dev/null
fi
cmake --build "$build" -j 2 --target "${targets[@]/#/fuzz_}" >/dev/null

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The value of libFuzzer's final statistic $1 in log $2 (-print_final_stats=1), or "-" if the run died first.
stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1 | grep . || echo -; }

# run_target TARGET: one libFuzzer run; its row of the table in $scratch/TARGET.row, and
# $scratch/TARGET.failed if it found something.
run_target() {
  local target=$1
  cp -r "fuzz/corpus/$target" "$scratch/$target"
  local artifacts="$build/artifacts/$target" log="$build/fuzz-$target.log" start status=0 crashes
  rm -rf "$artifacts" && mkdir -p "$artifacts"
  start=$(date +%s)
  local dictionary=()  # the readers' keywords; the geometric targets decode numbers and have none
  [ ! -f "fuzz/$target.dict" ] || dictionary=(-dict="fuzz/$target.dict")
  "$build/bin/fuzz_$target" "$scratch/$target" "${dictionary[@]}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1 || status=$?
  crashes=$(find "$artifacts" -type f | wc -l)
  printf '%-18s %12s %8s %9s %10s %7s %8s\n' "$target" "$(stat number_of_executed_units "$log")" \
    "$(($(date +%s) - start))" "$(stat average_exec_per_sec "$log")" "$(stat new_units_added "$log")" \
    "$(find "$scratch/$target" -type f | wc -l)" "$crashes" > "$scratch/$target.row"
  if [ "$status" -ne 0 ] || [ "$crashes" -ne 0 ]; then touch "$scratch/$target.failed"; fi
}

cores=$(nproc 2>/dev/null || echo 2)
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$cores" ]; do wait -n || true; done
  run_target "$target" &
done
wait
printf '%-18s %12s %8s %9s %10s %7s %8s\n' target executions seconds exec/s new_units corpus crashes
failed=()
for target in "${targets[@]}"; do
  cat "$scratch/$target.row"
  [ ! -e "$scratch/$target.failed" ] || failed+=("$target")
done
if [ ${#failed[@]} -gt 0 ]; then
  for target in "${failed[@]}"; do
    echo "fuzz: $target failed; the end of $build/fuzz-$target.log:" >&2
    tail -n 30 "$build/fuzz-$target.log" >&2
  done
  exit 1
fi
