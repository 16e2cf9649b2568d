#!/usr/bin/env bash
# Triangle enhancement (issue #7): `meshprep enhance` with its defaults on the decimated bunny00
# (10 %, OpenMesh quadric) and fandisk (30 %, CGAL GH), each against its ORIGINAL full mesh, and on
# femur against itself. Each input gets an "input" row (`meshprep quality IN --reference ORIG`) and
# an "enhanced" row. Distances are relative to the reference's bounding-box diagonal; time is the
# enhancement itself (time_seconds). Then TetGen (`meshprep tetrahedralize`, its defaults, and with
# --keep-surface, the pipeline's choice for a closed surface) on the raw and on the enhanced femur:
# the smallest dihedral angle of the tets.
# Usage: bench/bench_enhance.sh [build-dir]
source "$(dirname "$0")/bench_setup.sh" "${1:-}" meshes/decimated

# row LABEL JSON: one table row from the JSON of `meshprep enhance` (quality nested, with a time)
# or of `meshprep quality` (the report itself).
row() {
  python3 - "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[2]))
q = j.get("quality", j); r = q["reference"]; volume = r.get("volume_change_percent")
print("| %s | %.3g | %.3g | %.2f %% | %.3f | %s | %.2f° | %s |" % (
    sys.argv[1], r["hausdorff_relative"], r["rms_relative"], 100 * q["faces_min_angle_below_20"],
    q["radius_ratio"]["p95"], "" if volume is None else "%.3g %%" % volume, q["min_angle_deg"]["min"],
    "%.2f s" % j["time_seconds"] if "quality" in j else ""))
PY
}

echo "| input | Hausdorff | RMS | faces min angle < 20° | radius ratio p95 | volume change % | smallest angle | time |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
while read -r name input reference; do
  label=${name//_/ }
  "$bin" quality "$data/$input" --reference "$data/$reference" --json "$work/q.json" > /dev/null
  row "$label: input" "$work/q.json"
  "$bin" enhance "$data/$input" -o "$work/${name%%_*}.off" --reference "$data/$reference" --json "$work/e.json" > /dev/null
  row "$label: enhanced" "$work/e.json"
done <<'ROWS'
bunny00_10_% decimated/bunny00_0.1_openmesh.off bunny00.off
fandisk_30_% decimated/fandisk_0.3_cgal_gh.off fandisk.off
femur femur.off femur.off
ROWS

echo
echo "| femur surface for TetGen | tets | smallest dihedral | tets under 10° | TetGen time |"
echo "| --- | --- | --- | --- | --- |"
for surface in "raw:$data/femur.off" "enhanced:$work/femur.off"; do
  for keep in "" --keep-surface; do
    "$bin" tetrahedralize "${surface#*:}" -o "$work/tets.vtu" --json "$work/t.json" $keep > /dev/null ||
      not_fem_ready $?
    python3 - "${surface%%:*}${keep:+ $keep}" "$work/t.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[2])); t = j["tet_quality"]
print("| %s | %d | %.2f° | %.2f %% | %.1f s |" % (sys.argv[1], t["tetrahedra"], t["min_dihedral_deg"]["min"],
      100 * t["tets_min_dihedral_below_10"], j["tetgen_seconds"]))
PY
  done
done
