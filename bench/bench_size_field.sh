#!/usr/bin/env bash
# Issue 49's size checks, side by side with Gmsh on the same part in the same run: the box with a
# hole (scripts/box-with-hole.py) exported coarse (size 3, a CAD export's strips) and fine (0.25),
# meshed by `meshprep pipeline --size 0.5` and by Gmsh at size 0.5; the share of tet edges within
# [0.7, 1.4] h for each (bench/size_conformity.py); the hole's wall with --curvature-points 12;
# then the parts of ../shared/data/cad/ at --size 3% (meshprep's own size_conformity figures).
# Needs python3-gmsh and python3-meshio (scripts/install-deps.sh).
# Usage: bench/bench_size_field.sh [build/bin/meshprep] [--no-cad]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/bin/meshprep}
py=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
$py "$root/scripts/box-with-hole.py" 3 "$work/coarse.stl" surface
$py "$root/scripts/box-with-hole.py" 0.25 "$work/fine.stl" surface
$py "$root/scripts/box-with-hole.py" 0.5 "$work/gmsh.msh" volume
$py "$root/bench/size_conformity.py" "$work/gmsh.msh" 0.5 "gmsh, size 0.5"
for export in coarse fine; do
  "$bin" pipeline "$work/$export.stl" -o "$work/$export" --size 0.5 --quiet
  $py "$root/bench/size_conformity.py" "$work/$export/tets.msh" 0.5 "meshprep, $export export"
done
"$bin" pipeline "$work/coarse.stl" -o "$work/curvature" --size 2 --curvature-points 12 --quiet
$py - "$work/curvature/tets.msh" <<'PY'
import math, sys
import meshio, numpy as np
m = meshio.read(sys.argv[1]); p, t = m.points, m.cells_dict["tetra"]
e = np.unique(np.sort(np.concatenate([t[:, [i, j]] for i in range(4) for j in range(i + 1, 4)]), axis=1), axis=0)
r, d = 1.5, lambda q: np.hypot(q[:, 0] - 5, q[:, 1] - 3)
wall = (d(p[e[:, 0]]) < 1.1 * r) & (d(p[e[:, 1]]) < 1.1 * r)
lengths = np.linalg.norm(p[e[:, 0]] - p[e[:, 1]], axis=1)[wall]
limit = 2 * math.pi * r / 12 * 1.4
print("--size 2 --curvature-points 12: %d edges at the hole (r = 1.5), longest %.3f, limit 2 pi r / 12 x 1.4 = %.3f"
      % (wall.sum(), lengths.max(), limit))
PY
[ "${2:-}" = "--no-cad" ] && exit 0
cad=$root/../shared/data/cad
[ -d "$cad" ] || { echo "cad parts skipped: $cad not found"; exit 0; }
printf "%-18s %9s %8s %12s %8s %9s\n" part "in band" median "grading p99" tets "min dih"
for f in "$cad"/*.stl; do
  n=$(basename "$f" .stl)
  "$bin" pipeline "$f" -o "$work/$n" --size 3% --quiet --json "$work/$n.json" > /dev/null 2>&1 || true
  python3 - "$work/$n.json" "$n" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))["tets"]; c = t["size_conformity"]
print("%-18s %8.1f%% %8.3f %12.3f %8d %9.2f" % (sys.argv[2], 100 * c["within_band"]["share"], c["ratio"]["median"],
      c["grading_excess"]["p99"], t["tet_quality"]["tetrahedra"], t["tet_quality"]["min_dihedral_deg"]["min"]))
PY
done
