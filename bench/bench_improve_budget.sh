#!/usr/bin/env bash
# The tet improvement's time budget (issue 47): TetGen's own tets of every part of a folder
# (tetrahedralize --no-improve), then `meshprep improve` on them under each time limit given, one
# thread; one line per part and limit: tets, smallest dihedral angle before -> after, what the
# surface allows, why the run stopped, seconds. "auto" is the default automatic limit.
# Usage: bench/bench_improve_budget.sh MESHPREP FOLDER OUT_DIR [LIMIT...]   (default limits: auto 0)
set -uo pipefail
bin=$1 folder=$2 out=$3
shift 3
limits=("$@")
[ ${#limits[@]} -eq 0 ] && limits=(auto 0)
mkdir -p "$out"
for surface in "$folder"/*.stl "$folder"/*.off; do
  [ -e "$surface" ] || continue
  name=$(basename "${surface%.*}")
  "$bin" tetrahedralize "$surface" -o "$out/$name.raw.msh" --no-improve --threads 1 > /dev/null 2>&1
  [ -f "$out/$name.raw.msh" ] || { echo "$name: TetGen made no tets"; continue; }
  for limit in "${limits[@]}"; do
    flag=()
    [ "$limit" != auto ] && flag=(--improve-time-limit "$limit")
    "$bin" improve "$out/$name.raw.msh" -o "$out/$name.$limit.msh" --threads 1 "${flag[@]}" \
      --json "$out/$name.$limit.json" > /dev/null 2>&1
    python3 - "$out/$name.$limit.json" "$name" "$limit" <<'PY' || echo "$2 limit $limit: no report"
import json, sys
i = json.load(open(sys.argv[1]))["improvement"]
print(f"{sys.argv[2]:18} limit {sys.argv[3]:>4}  {i['tets_before']:7} tets  min {i['min_dihedral_before_deg']:5.2f} -> "
      f"{i['min_dihedral_after_deg']:5.2f} deg  bound {i['surface_bound_deg']:5.2f}  {i['stopped_by']:11} {i['seconds']:6.1f} s")
PY
  done
done
