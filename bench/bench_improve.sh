#!/usr/bin/env bash
# Tet improvement (issue 29), three parts, each side by side in one run:
#  1. `meshprep pipeline` with defaults on the acceptance meshes (bunny00, fandisk at 30 %, femur,
#     elephant, blade, turbine, the bundled terrain, 13 closed scans of ../shared/data/corpus):
#     TetGen's tets and the improved ones (smallest / largest dihedral), the bound the surface
#     imposes where it forbids the goal, the tets' volume against the surface's (a terrain's block:
#     against TetGen's tets'), the two times.
#  2. `meshprep improve` on TetGen's own -pq1.414 and -pYq1.414 tets of the same final surfaces
#     (tetrahedralize --no-improve): the same figures, and the boundary faces and volume checked
#     unchanged (tests/fem_readback.py's reader, meshio).
#  3. Speed: bench_improve (one thread, TetGen and the improvement in one process) on bunny00 at
#     10 % and on bunny00 Loop-subdivided twice (1.2 M faces) with -pYq1.414; then the pipeline on
#     bunny00 at 10 % with the stage on and off, three runs each.
# Usage: bench/bench_improve.sh [build-dir] [parts, default "1 2 3"]
source "$(dirname "$0")/bench_setup.sh" "${1:-}" corpus
parts=${2:-1 2 3}
corpus=$root/../shared/data/corpus
out=$work/out
meshes=(
  "bunny00 $data/bunny00.off" "fandisk $data/fandisk.off --ratio 0.3" "femur $data/femur.off"
  "elephant $data/elephant.off" "blade $data/blade.off" "turbine $data/turbine.off"
  "terrain $root/examples/data/jacksboro_10k.xyz"
)
for m in bear dino homer triceratops knot1 knot2 blobby helmet hand cactus eight retinal cube-meshed; do
  meshes+=("$m $corpus/$m.off")
done

if [[ " $parts " == *" 1 "* ]]; then
  echo "## 1. pipeline, defaults"
  echo "| mesh | tets | TetGen min / max | improved min / max | below goal | surface bound | volume error | TetGen s | improve s | ratio | FEM-ready |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  for entry in "${meshes[@]}"; do
    read -r name input options <<<"$entry"
    code=0
    # shellcheck disable=SC2086 # options are words
    "$bin" pipeline "$input" -o "$out/$name" $options --quiet > "$work/$name.log" 2>&1 || code=$?
    if [ ! -f "$out/$name/report.json" ]; then
      echo "| $name | refused (exit $code): $(tail -1 "$work/$name.log" | cut -c1-120) |"
      continue
    fi
    python3 - "$name" "$out/$name/report.json" <<'PY'
import json, sys
name, path = sys.argv[1:3]
r = json.load(open(path))
t = r["tets"]
stage = {s["name"]: s for s in r["stages"]}
q, g, i = t["tet_quality"], t["tetgen_quality"] or t["tet_quality"], t["improvement"] or {}
bound = ""
if i.get("limiting_edge_count", 0):
    e = i["limiting_edges"][0]
    bound = "%.2f at (%s), %d edges" % (i["surface_bound_deg"], ", ".join("%.3g" % c for c in e["midpoint"]), i["limiting_edge_count"])
# The closed surface's volume; a terrain's block has no closed surface in the report: TetGen's tets'.
surface_volume = r["quality"]["volume"] or g["volume"]
volume_error = abs(q["volume"] - surface_volume) / abs(surface_volume)
tg = stage["tetrahedralize"]["seconds"]
im = stage.get("improve", {}).get("seconds", 0.0)
print("| %s | %d | %.2f / %.1f | %.2f / %.1f | %s | %s | %.1e | %.2f | %.2f | %.2f | %s |" % (
    name, q["tetrahedra"], g["min_dihedral_deg"]["min"], g["max_dihedral_deg"]["max"], q["min_dihedral_deg"]["min"],
    q["max_dihedral_deg"]["max"], i.get("below_goal_after", ""), bound or "-", volume_error, tg, im, im / tg if tg else 0,
    "yes" if r["fem_ready"] else "no"))
PY
  done
fi

if [[ " $parts " == *" 2 "* ]]; then
  py=  # a python with meshio (Debian's python3-meshio), as tests/cli_pipeline_test.sh finds it
  for p in python3 /usr/bin/python3; do $p -c "import meshio, numpy" 2> /dev/null && { py=$p; break; }; done
  [ -n "$py" ] || { echo "part 2 skipped: no python3 with meshio (scripts/install-deps.sh installs it)"; parts=${parts/2/}; }
fi
if [[ " $parts " == *" 2 "* ]]; then
  echo
  echo "## 2. meshprep improve on TetGen's own tets of the final surfaces"
  echo "| mesh | TetGen | tets | TetGen min / max | improved min / max | boundary faces | volume change | improve s |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  for entry in "${meshes[@]}"; do
    read -r name input options <<<"$entry"
    surface=$out/$name/surface.ply
    # shellcheck disable=SC2086 # options are words
    [ -f "$surface" ] || "$bin" pipeline "$input" -o "$out/$name" $options --quiet > /dev/null 2>&1 || true
    [ -f "$surface" ] && [ "$name" != terrain ] || continue
    for switches in "-pq1.414" "-pYq1.414"; do
      keep=(); [ "$switches" = "-pYq1.414" ] && keep=(--keep-surface)
      "$bin" tetrahedralize "$surface" -o "$work/tetgen.msh" "${keep[@]}" --no-improve > /dev/null 2>&1 || not_fem_ready $?
      "$bin" improve "$work/tetgen.msh" -o "$work/improved.msh" --json "$work/improve.json" > /dev/null 2>&1 || not_fem_ready $?
      # (meshio prints blank lines when it reads: only the table's row is kept)
      "$py" - "$name" "$switches" "$work/tetgen.msh" "$work/improved.msh" "$work/improve.json" 2> /dev/null <<'PY' | grep '^|'
import json, sys
import meshio, numpy as np
name, switches, before_path, after_path, report = sys.argv[1:6]
def boundary(path):
    m = meshio.read(path)
    tets = np.concatenate([c.data for c in m.cells if c.type == "tetra"])
    faces = {}
    for t in tets:
        for f in ((t[1], t[2], t[3]), (t[0], t[2], t[3]), (t[0], t[1], t[3]), (t[0], t[1], t[2])):
            key = tuple(sorted(f))
            faces[key] = faces.get(key, 0) + 1
    pts = m.points
    return sorted(tuple(sorted(tuple(pts[v]) for v in f)) for f, n in faces.items() if n == 1)
j = json.load(open(report))
b, a, i = j["tet_quality_before"], j["tet_quality"], j["improvement"]
same = "same" if boundary(before_path) == boundary(after_path) else "CHANGED"
print("| %s | %s | %d | %.2f / %.1f | %.2f / %.1f | %s | %.1e | %.2f |" % (
    name, switches, a["tetrahedra"], b["min_dihedral_deg"]["min"], b["max_dihedral_deg"]["max"],
    a["min_dihedral_deg"]["min"], a["max_dihedral_deg"]["max"], same, abs(a["volume"] - b["volume"]) / b["volume"],
    i["seconds"]))
PY
    done
  done
fi

if [[ " $parts " == *" 3 "* ]]; then
  echo
  echo "## 3. speed: TetGen -pYq1.414 and the improvement in one process, one thread"
  "$bin" pipeline "$data/bunny00.off" --ratio 0.1 -o "$work/bunny_10" --quiet > /dev/null 2>&1 || not_fem_ready $?
  "$build/bin/subdivide_mesh" "$data/bunny00.off" "$work/bunny_1200k.off" 2
  "$build/bin/bench_improve" "$work/bunny_10/surface.ply" "$work/bunny_1200k.off"
  echo
  echo "pipeline bunny00 --ratio 0.1, improvement on and off, alternating (wall s of the whole run):"
  for run in 1 2 3; do
    for stage in on off; do
      flag=(); [ $stage = off ] && flag=(--no-improve)
      /usr/bin/time -f "%e" -o "$work/time.txt" "$bin" pipeline "$data/bunny00.off" --ratio 0.1 -o "$work/p" --quiet \
        "${flag[@]}" > /dev/null 2>&1 || not_fem_ready $?
      echo "  run $run, improve $stage: $(tail -1 "$work/time.txt") s"
    done
  done
fi
