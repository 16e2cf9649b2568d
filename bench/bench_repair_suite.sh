#!/usr/bin/env bash
# The repair suite of issue 48 (item 5): `meshprep pipeline --repair` on seeded dirty triangle soups.
# Generates the cases with tests/dirty_cases.py (/usr/bin/python3, standard library only) into
# OUT_DIR/cases (manifest.json lists them: kind, seed, sources, parameters), then runs on each, one
# at a time and under `timeout`:
#   MESHPREP pipeline CASE -o OUT_DIR/runs/NAME --repair --threads 1 --quiet --json OUT_DIR/runs/NAME.json
# recording its exit code and wall seconds (OUT_DIR/results.tsv; stderr in OUT_DIR/runs/NAME.err),
# and prints a Markdown table by defect kind (bench/repair_suite_table.py): cases, FEM-ready (exit
# 0) count and share, the exit-code histogram, how many final surfaces are closed, manifold and
# without self-intersections, median and worst seconds, a totals row, then the first stderr line
# of every case that did not exit 0. Exit codes: 0 ready, 1 written but not ready, 2 bad input
# (nothing written), 3 failed while working, 124 time limit (timeout's kill too: 'hang' when the
# run lasted the whole limit), 130 interrupted. No case stops the script.
# Usage: bench/bench_repair_suite.sh MESHPREP OUT_DIR [--quick] [--count N] [--timeout S]
#   --quick      22 cases (two of each of the 11 kinds) from the meshes bundled in the repository;
#                without it, --count N cases (default 120) also from ../shared/data/cad when present
#   --timeout S  seconds per run (default 300)
# Nothing of an earlier run in OUT_DIR is reused: its cases and runs are written again.
set -euo pipefail

usage() {
  echo "Usage: bench/bench_repair_suite.sh MESHPREP OUT_DIR [--quick] [--count N] [--timeout S]" >&2
  exit 2
}
[ $# -ge 2 ] || usage
meshprep=$(realpath "$1")
out=$(realpath -m "$2")
shift 2
generate=()
limit=300
while [ $# -gt 0 ]; do
  case $1 in
    --quick) generate+=(--quick) ;;
    --count) [ $# -ge 2 ] || usage; generate+=(--count "$2"); shift ;;
    --timeout) [ $# -ge 2 ] || usage; limit=$2; shift ;;
    *) usage ;;
  esac
  shift
done
[ -x "$meshprep" ] || { echo "bench_repair_suite.sh: $meshprep is not an executable" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
py=/usr/bin/python3

rm -rf "$out/cases" "$out/runs"
mkdir -p "$out/cases" "$out/runs"
echo "generating the cases into $out/cases ..." >&2
"$py" "$root/tests/dirty_cases.py" "$out/cases" "${generate[@]}" 2> "$out/generate.log" >&2 \
  || { cat "$out/generate.log" >&2; exit 1; }

records=$out/results.tsv
printf 'name\tkind\texit\tseconds\tfaces\tpath\n' > "$records"
"$py" - "$out/cases/manifest.json" > "$out/cases.tsv" <<'PY'
import json, sys
for c in json.load(open(sys.argv[1])):
    print("%s\t%s\t%s\t%d" % (c["name"], c["kind"], c["file"], c["faces"]))
PY
total=$(wc -l < "$out/cases.tsv")
n=0
start=$SECONDS
while IFS=$'\t' read -r name kind file faces; do
  n=$((n + 1))
  case_path=$out/cases/$file
  t0=$(date +%s.%N)
  rc=0
  timeout -k 10 "$limit" "$meshprep" pipeline "$case_path" -o "$out/runs/$name" --repair --threads 1 --quiet \
    --json "$out/runs/$name.json" < /dev/null > "$out/runs/$name.out" 2> "$out/runs/$name.err" || rc=$?
  t1=$(date +%s.%N)
  seconds=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$kind" "$rc" "$seconds" "$faces" "$case_path" >> "$records"
  echo "[$((SECONDS - start)) s] $n/$total $name ($faces faces): exit $rc, $seconds s" >&2
done < "$out/cases.tsv"

"$py" "$root/bench/repair_suite_table.py" "$records" "$out/runs" --timeout "$limit"
