#!/usr/bin/env bash
# Times `meshprep tetrahedralize` against Debian's `tetgen` command-line tool on the same input,
# same switches (-pq1.414), same run. Our overhead must stay within 1.2x (readiness check,
# conversion, forked child, export). Needs ../shared/data and the tetgen package (installed here
# if missing, as root). Usage: bench/bench_tetrahedralize.sh [build/bin/meshprep]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/bin/meshprep}
data=$root/../shared/data/meshes
[ -d "$data" ] || { echo "skipped: $data not found"; exit 0; }
command -v tetgen >/dev/null || apt-get install -y -qq tetgen >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "%-12s %12s %12s %8s %10s %10s\n" mesh "tetgen (s)" "meshprep (s)" ratio "tets" "tets (mp)"
for m in femur bunny00; do
  cp "$data/$m.off" "$work/$m.off"
  t0=$(date +%s.%N); tetgen -pq1.414Q "$work/$m.off" > /dev/null; t1=$(date +%s.%N)
  tets=$(head -1 "$work/$m.1.ele" | awk '{print $1}')
  # Exit 1 with the tets written: not FEM-ready (TetGen's slivers, issue 29), still a run to time.
  "$bin" tetrahedralize "$work/$m.off" -o "$work/$m.mp.node" --json "$work/$m.json" > /dev/null || [ $? -eq 1 ]
  t2=$(date +%s.%N)
  mp_tets=$(python3 -c "import json; print(json.load(open('$work/$m.json'))['tet_quality']['tetrahedra'])")
  python3 -c "
a, b = $t1 - $t0, $t2 - $t1
print('%-12s %12.2f %12.2f %8.2f %10s %10s' % ('$m', a, b, b / a, '$tets', '$mp_tets'))"
done
