#!/usr/bin/env bash
# `meshprep tetrahedralize` on the real binary: success, solver targets, diagnoses of surfaces
# that are not FEM-ready (exit 1, offending faces named, no tet mesh written), tets that do not
# meet the verdict's thresholds (exit 1, each failed threshold named, the tets written), usage
# errors (exit 2); then `meshprep quality` and `meshprep convert` on the tet meshes it wrote.
# Usage: cli_fem_test.sh MESHPREP_BINARY
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/cli_harness.sh"

python3 "$here/cli_meshes.py" cube open_box two_boxes duplicate fin sliver split_cube
python=""  # a python3 with meshio and numpy, for the checks that read tet meshes back
for p in python3 /usr/bin/python3; do $p -c "import meshio, numpy" 2>/dev/null && { python=$p; break; }; done

# TetGen alone (-pq1.414a0.01, --no-improve) leaves an 8.9-degree sliver in the cube: written, but
# not FEM-ready.
"$bin" tetrahedralize cube.off -o cube.msh --max-volume 0.01 --no-improve --json out.json > stdout.txt 2> err.txt
expect_exit "cube" 1 $?
grep -qE "^meshprep: cube.off: not FEM-ready: smallest dihedral angle [0-9.]+ deg < 10 deg \(min_dihedral_deg\)$" err.txt &&
  ok || bad "cube: the failed threshold is not named with its figure"
grep -qx "meshprep: not ready: cube.off: not FEM-ready: the tets fail min_dihedral_deg (above); cube.msh is written" err.txt &&
  ok || bad "cube: the failure line"
[ "$(grep -c "^meshprep: not ready:" err.txt)" = 1 ] && ok || bad "cube: one failure line"
python3 -c "
import json; j = json.load(open('out.json')); q = j['tet_quality']
assert abs(q['volume'] - 1) < 1e-9 and q['tetrahedra'] >= 100 and q['radius_edge_ratio']['max'] <= 1.414 + 1e-9, q
assert j['fem_ready'] is False, j['fem_ready']
t = {c['check']: c for c in j['thresholds']}
assert t['min_dihedral_deg'] == {'check': 'min_dihedral_deg', 'threshold': 10, 'value': q['min_dihedral_deg']['min'], 'ok': False}, t
assert t['max_dihedral_deg']['ok'] and t['max_inverted_tets']['ok'], t
assert len(q['worst_tets']) == 10 and q['worst_tets'][0]['min_dihedral_deg'] == q['min_dihedral_deg']['min'], q['worst_tets'][0]
" && ok || bad "cube json"
head -2 cube.msh | grep -q "^4.1" && ok || bad "default msh version"
# The same tets improved (the default): the sliver gone, the boundary and the volume kept.
"$bin" tetrahedralize cube.off -o cube_improved.msh --max-volume 0.01 --json out.json > stdout.txt 2> err.txt
expect_exit "cube improved" 0 $?
grep -qE "^  improved: smallest dihedral [0-9.]+ -> [0-9.]+ deg" stdout.txt && ok || bad "cube improved: no improvement line"
python3 -c "
import json; j = json.load(open('out.json')); q, g, i = j['tet_quality'], j['tetgen_quality'], j['improvement']
assert g['min_dihedral_deg']['min'] < 10 and q['min_dihedral_deg']['min'] >= 15 and q['max_dihedral_deg']['max'] <= 160, (g, q)
assert i['stopped_by'] == 'goal reached' and i['below_goal_after'] == 0 and i['limiting_edge_count'] == 0, i
assert abs(q['volume'] - 1) < 1e-12 and q['inverted_tets'] == 0 and j['fem_ready'] is True, q
" && ok || bad "cube improved json"
# meshprep improve on TetGen's own tets (cube.msh above): the same, read from a file, any format out.
"$bin" improve cube.msh -o cube_improved.vtu --json improve.json > stdout.txt 2> err.txt
expect_exit "improve cube.msh" 0 $?
grep -q "^  before: " stdout.txt && grep -q "^  after : " stdout.txt && ok || bad "improve: before and after not printed"
"$bin" quality cube.msh --json before.json > /dev/null 2>&1 && "$bin" quality cube_improved.vtu --json after.json > /dev/null 2>&1
python3 -c "
import json
j = json.load(open('improve.json')); b, a = json.load(open('before.json')), json.load(open('after.json'))
assert j['tet_quality_before']['min_dihedral_deg']['min'] < 10 <= j['tet_quality']['min_dihedral_deg']['min'], j
assert j['fem_ready'] is True and j['format'] == 'msh 4.1 ascii', j['format']
assert a['boundary']['faces'] == b['boundary']['faces'] and a['boundary']['closed'], (a['boundary'], b['boundary'])
assert abs(a['tet_quality']['volume'] - b['tet_quality']['volume']) < 1e-12, (a['tet_quality']['volume'], b['tet_quality']['volume'])
assert a['tet_quality']['min_dihedral_deg']['min'] == j['tet_quality']['min_dihedral_deg']['min']
" && ok || bad "improve: figures, boundary or volume"
"$bin" improve cube.off -o x.msh > /dev/null 2> err.txt; expect_exit "improve a surface" 2 $?
grep -qx "meshprep: error: cube.off: not a tet mesh file (.msh, .vtu, .vtk, .mesh, .node, .ele, .xdmf); for a surface use meshprep tetrahedralize" err.txt &&
  [ ! -e x.msh ] && ok || bad "improve a surface: the message or a file written"
# A tangled mesh (issue 45, item 10): the interior vertex with the most tets pushed through its
# star, twice as far as its farthest neighbour, so that tets fold over their neighbours. Its
# negative tets are not turned over one by one (that hid the tangle: "inverted 0" and the volume of
# every tet's absolute value): quality counts them and gives the enclosed volume; improve refuses.
if [ -n "$python" ]; then
"$python" - cube_improved.msh tangled.msh > tangled.txt <<'PY'
import sys, numpy as np, meshio
m = meshio.read(sys.argv[1]); p = m.points.copy(); t = m.cells_dict["tetra"]
faces = np.sort(np.concatenate([t[:, [0, 1, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 3]], t[:, [1, 2, 3]]]), axis=1)
unique, counts = np.unique(faces, axis=0, return_counts=True)
boundary = set(unique[counts == 1].ravel())
inner = [v for v in np.argsort(-np.bincount(t.ravel())) if v not in boundary][0]
star = t[(t == inner).any(axis=1)]
far = max(np.linalg.norm(p[w] - p[inner]) for w in set(star.ravel()) - {inner})
p[inner] += np.array([2 * far, 0.3 * far, 0.1 * far])
signed = lambda q: np.einsum("ij,ij->i", q[t[:, 1]] - q[t[:, 0]], np.cross(q[t[:, 2]] - q[t[:, 0]], q[t[:, 3]] - q[t[:, 0]])) / 6
print(int((signed(p) < 0).sum()), repr(float(signed(p).sum())))
meshio.write(sys.argv[2], meshio.Mesh(p, [("tetra", t)]), file_format="gmsh22", binary=False)
PY
read -r negative volume < <(tail -n 1 tangled.txt)  # meshio may print lines of its own first
"$bin" quality tangled.msh --json tangled.json > /dev/null 2> err.txt; expect_exit "quality of a tangled mesh" 0 $?
python3 -c "
import json, sys; j = json.load(open('tangled.json')); q = j['tet_quality']; n = $negative
assert n > 0 and q['inverted_tets'] == n and j['input']['tets_inverted'] == n and j['input']['tets_reoriented'] == 0, (n, q['inverted_tets'], j['input'])
assert abs(q['volume'] - $volume) <= 1e-9 * abs($volume), (q['volume'], $volume)" && ok || bad "quality of a tangled mesh: inverted tets and volume"
grep -q "tets have negative volume among positive neighbours: left as they are, inverted (the mesh is tangled)" err.txt &&
  ok || bad "quality of a tangled mesh: the note"
"$bin" improve tangled.msh -o untangled.msh > /dev/null 2> err.txt; expect_exit "improve a tangled mesh" 2 $?
grep -q "tangled.msh: tet mesh: [0-9]* tets have negative volume among positive ones: the mesh is tangled" err.txt &&
  [ ! -e untangled.msh ] && ok || bad "improve a tangled mesh: the message or a file written"
else
  echo "skipped: the tangled mesh (no python3 with meshio and numpy)"
fi
# A flat tet on the boundary (issue 45, item 3): a pyramid whose planar base is triangulated on the
# boundary by one diagonal and inside by the other, the flat tet of its four corners between them.
# No command writes it; the improvement removes it (a flip of the base's two triangles).
printf 'MeshVersionFormatted 2\nDimension 3\nVertices 5\n0 0 0 0\n1 0 0 0\n1.1 1 0 0\n0 1 0 0\n0.5 0.5 -0.8 0\n' > flat.mesh
printf 'Tetrahedra 3\n1 2 3 4 1\n1 2 5 3 1\n1 3 5 4 1\nTriangles 6\n1 2 4 1\n2 3 4 1\n1 5 2 2\n2 5 3 2\n3 5 4 2\n4 5 1 2\nEnd\n' >> flat.mesh
"$bin" convert flat.mesh -o flat.msh > /dev/null 2> err.txt; expect_exit "convert a flat tet" 2 $?
one_line "convert a flat tet" "flat.msh: cannot export: 1 tet is flat or inverted (the volume is not positive beyond rounding); the first, tet 0, at (0.525, 0.5, 0)"
[ ! -e flat.msh ] && ok || bad "convert a flat tet: a file written"
"$bin" improve flat.mesh -o flat_improved.msh --json flat.json > stdout.txt 2> err.txt; expect_exit "improve a flat tet" 0 $?
grep -q "1 flat tet(s) on the boundary removed" stdout.txt && ok || bad "improve a flat tet: the summary"
python3 -c "
import json; j = json.load(open('flat.json'))
assert j['improvement']['flat_boundary_tets_removed'] == 1, j['improvement']
q = j['tet_quality']; assert q['tetrahedra'] == 2 and q['inverted_tets'] == 0 and q['min_dihedral_deg']['min'] > 0.5, q
assert abs(q['volume'] - 0.28) <= 1e-12, q['volume']" && ok || bad "improve a flat tet: removed, the volume kept"
# A triangle inside a region (issue 45, item 11): two tets of one region and their shared face
# listed: kept as an internal surface with its tag, and said so.
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n' > internal.msh
printf '$Elements\n3\n1 4 2 4 1 1 2 3 4\n2 4 2 4 1 2 3 4 5\n3 2 2 9 1 4 3 2\n$EndElements\n' >> internal.msh
"$bin" convert internal.msh -o internal.mesh --json internal.json > /dev/null 2> err.txt; expect_exit "an internal triangle" 0 $?
one_line "an internal triangle" "internal.msh: 1 triangles lie inside a region (each a face of two of its tets): kept with their tags"
grep -A1 "^Triangles" internal.mesh | tail -1 | grep -qx 7 && ok || bad "an internal triangle: written with the six boundary faces"

# Split mode and the volume (issue 45, item 4): TetGen merges the ridge's two top triangles (within
# its 0.1-degree tolerance) and cuts the ridge tet away, d / 3 of the volume: reported with its
# cause; --keep-surface keeps the surface and the volume to rounding.
python3 "$here/cli_meshes.py" ridge
"$bin" tetrahedralize ridge.off -o ridge.msh --no-improve --json ridge.json > /dev/null 2> err.txt
grep -q "ridge.off: the tets' volume differs from the surface's by -3.33e-05 of it: without keep-surface TetGen" err.txt &&
  python3 -c "
import json; c = json.load(open('ridge.json'))['volume_change_relative']
assert abs(c + (1e-4 / 3) / (1 + 2e-4 / 3)) < 1e-12, c  # the ridge tet over the volume" && ok || bad "split mode: the volume change and its note"
"$bin" tetrahedralize ridge.off -o ridge.msh --no-improve --keep-surface --json ridge.json > /dev/null 2> err.txt
! grep -q "volume differs" err.txt && python3 -c "
import json; c = json.load(open('ridge.json'))['volume_change_relative']
assert abs(c) <= 1e-12, c" && ok || bad "--keep-surface: the volume kept"
"$bin" improve missing.msh -o x.msh > /dev/null 2> err.txt; expect_exit "improve a missing file" 2 $?
printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n' > broken.msh
"$bin" improve broken.msh -o x.msh > /dev/null 2> err.txt; expect_exit "improve a broken file" 2 $?
[ "$(wc -l < err.txt)" = 1 ] && grep -q "broken.msh" err.txt && [ ! -e x.msh ] && ok || bad "improve a broken file: $(cat err.txt)"
"$bin" improve cube.msh -o cube.msh > /dev/null 2> err.txt; expect_exit "improve onto its input" 2 $?
"$bin" improve cube.msh -o x.msh --goal-min-dihedral 70 > /dev/null 2> err.txt; expect_exit "improve --goal-min-dihedral 70" 2 $?
# TetGen's own dihedral target (-q/12) meets the verdict; so does a threshold below the figure.
"$bin" tetrahedralize cube.off -o cube12.msh --max-volume 0.01 --min-dihedral 12 --json out.json > stdout.txt 2> err.txt
expect_exit "cube with TetGen's -q/12" 0 $?
grep -q "FEM-ready: every threshold holds" stdout.txt && ok || bad "cube -q/12: the verdict is not printed"
python3 -c "
import json; j = json.load(open('out.json'))
assert j['fem_ready'] is True and all(c['ok'] for c in j['thresholds']), j['thresholds']" && ok || bad "cube -q/12 json"
"$bin" tetrahedralize cube.off -o cube8.msh --max-volume 0.01 --min-dihedral-threshold 8 > /dev/null 2> err.txt
expect_exit "--min-dihedral-threshold 8" 0 $?
"$bin" tetrahedralize cube.off -o cube8.msh --min-dihedral-threshold 200 > /dev/null 2> err.txt
expect_exit "--min-dihedral-threshold 200" 2 $?
"$bin" tetrahedralize cube.off -o cube8.msh --max-inverted-tets -1 > /dev/null 2> err.txt
expect_exit "--max-inverted-tets -1" 2 $?

# One 2-degree tet (no refinement, its triangles kept): both angle thresholds fail, with their
# figures; the tets are written. Thresholds it meets make it FEM-ready.
"$bin" tetrahedralize sliver.off -o sliver.vtu --radius-edge 0 --keep-surface --json out.json > /dev/null 2> err.txt
expect_exit "sliver" 1 $?
has_sliver_verdict && ok || bad "sliver: the failed thresholds"
grep -qx "meshprep: not ready: sliver.off: not FEM-ready: the tets fail min_dihedral_deg, max_dihedral_deg (above); sliver.vtu is written" err.txt &&
  ok || bad "sliver: the failure line"
[ -s sliver.vtu ] && ok || bad "sliver: sliver.vtu not written"
python3 -c "
import json; j = json.load(open('out.json')); q = j['tet_quality']
assert q['tetrahedra'] == 1 and j['fem_ready'] is False, j
assert [c['ok'] for c in j['thresholds']] == [False, False, True], j['thresholds']
assert abs(j['thresholds'][0]['value'] - 2.0048) < 1e-4, j['thresholds']
assert q['worst_tets'][0]['centre'] == [0.5, 0.5, 0.00875], q['worst_tets']" && ok || bad "sliver json"
"$bin" tetrahedralize sliver.off -o sliver2.vtu --radius-edge 0 --keep-surface --min-dihedral-threshold 2 \
  --max-dihedral-threshold 178 > /dev/null 2> err.txt
expect_exit "sliver within relaxed thresholds" 0 $?

"$bin" tetrahedralize cube.off -o cube22.msh --target mfem > /dev/null 2> err.txt; expect_exit "mfem target" 0 $?
head -2 cube22.msh | grep -q "^2.2" && ok || bad "mfem wants msh 2.2"
"$bin" tetrahedralize cube.off -o cube.inp --target calculix > /dev/null 2> err.txt; expect_exit "calculix target" 0 $?
"$bin" tetrahedralize cube.off -o cube.msh --target calculix > /dev/null 2> err.txt; expect_exit "target/extension mismatch" 2 $?
"$bin" tetrahedralize cube.off -o cube.msh --target abaqus > /dev/null 2> err.txt; expect_exit "unknown target" 2 $?
"$bin" tetrahedralize cube.off -o cube.xyz > /dev/null 2> err.txt; expect_exit "unknown format" 2 $?
"$bin" tetrahedralize cube.off -o cube.msh --max-volume 1 --max-volume-relative 0.1 > /dev/null 2> err.txt
expect_exit "exclusive volume bounds" 2 $?

for case in open_box:closed two_boxes:self_intersections duplicate:duplicate_faces fin:manifold split_cube:welded; do
  name=${case%%:*} check=${case#*:}
  rm -f out.json
  "$bin" tetrahedralize $name.off -o $name.msh --diagnose $name-bad.off --json out.json > /dev/null 2> err.txt
  expect_exit "$name" 2 $?
  grep -q "not FEM-ready: $check" err.txt && ok || bad "$name: no '$check' diagnosis"
  [ ! -e $name.msh ] && ok || bad "$name: a tet mesh was written"
  [ -s $name-bad.off ] && ok || bad "$name: no diagnosis mesh"
  python3 -c "
import json; j = json.load(open('out.json')); assert not j['readiness']['ready']
assert any(p['check'] == '$check' and p['faces'] for p in j['readiness']['problems']), j" && ok || bad "$name json"
done

# Split vertices are the one problem named: the welded cube is closed and does not cross itself.
"$bin" tetrahedralize split_cube.off -o split_cube.msh > /dev/null 2> err.txt
grep -q "not FEM-ready: welded: 28 vertices lie exactly on another vertex" err.txt &&
  ! grep -qE "closed|self_intersections" err.txt && ok || bad "split_cube: welding is not the one diagnosis"
# meshprep repair welds it into the closed cube, which TetGen then takes. The crossing boxes
# become their union: 1 + 1 - 0.5 x 0.75 x 0.7 of volume, one closed component.
"$bin" repair split_cube.off -o split_repaired.off --json repair.json > /dev/null 2> err.txt
expect_exit "repair split_cube" 0 $?
python3 -c "
import json; j = json.load(open('repair.json'))
assert j['welded_vertices'] == 28 and j['faces'] == 12 and j['vertices'] == 8 and j['readiness']['ready'], j" &&
  ok || bad "repair split_cube: counts or readiness"
"$bin" tetrahedralize split_repaired.off -o split_repaired.msh --max-volume 0.01 > /dev/null 2> err.txt
expect_exit "tets of the repaired cube" 0 $?
"$bin" repair two_boxes.off -o boxes_repaired.off --json boxes.json > /dev/null 2> err.txt
expect_exit "repair crossing boxes" 0 $?
"$bin" quality boxes_repaired.off --json boxes_quality.json > /dev/null 2>&1
python3 -c "
import json; r = json.load(open('boxes.json')); q = json.load(open('boxes_quality.json'))
assert r['intersecting_pairs'] > 0 and r['removed_faces'] > 0 and r['readiness']['ready'], r
assert q['components'] == 1 and q['self_intersections'] == 0 and abs(q['volume'] - (2 - 0.5 * 0.75 * 0.7)) < 1e-12, q" &&
  ok || bad "repair crossing boxes: the union's counts or volume"
# The open box is a bowl, every face turned up or sideways: a sheet's outline by default (left
# open, named, nothing written), a hole with --max-hole 3 (filled: the closed cube, 12 faces).
"$bin" repair open_box.off -o box_filled.off > stdout.txt 2> err.txt; expect_exit "repair open box" 3 $?
grep -q "filled 0 holes (1 left open)" err.txt && grep -q "not mended yet: 4 border edges" err.txt &&
  [ ! -e box_filled.off ] && ok || bad "repair open box: the message, or a file written"
"$bin" repair open_box.off -o box_filled.off --max-hole 3 --json box.json > stdout.txt 2> err.txt
expect_exit "repair open box --max-hole 3" 0 $?
grep -q "filled 1 holes (0 left open)" stdout.txt && grep -q "; closed, manifold" stdout.txt && python3 -c "
import json; j = json.load(open('box.json')); h = j['holes']
assert j['faces'] == 12 and j['filled_holes'] == 1 and len(h) == 1 and h[0]['rim_vertices'] == 4, j
assert h[0]['patch_faces'] == 2 and abs(h[0]['patch_area'] - 1) < 1e-12 and h[0]['plane_distance'] < 1e-12, h" &&
  ok || bad "repair open box --max-hole 3: the done line or the holes"
# Without one of its top's two faces the cube is a solid missing a part, filled by default (and by
# --max-hole auto) although its rim is 2.0 x the diagonal, which --max-hole 0.5 leaves open.
grep -vx "3 4 5 6" cube.off | sed "2s/8 12 0/8 11 0/" > half_top.off
for auto in "" "--max-hole auto"; do
  "$bin" repair half_top.off -o half_top_filled.off $auto > stdout.txt 2> err.txt
  expect_exit "repair half top $auto" 0 $?
  grep -q "filled 1 holes (0 left open)" stdout.txt &&
    grep -q "; closed, manifold, oriented, no self-intersections (12 faces)" stdout.txt &&
    ok || bad "repair half top $auto: the done line"
done
"$bin" repair half_top.off -o half_top_filled.off --max-hole 0.5 > stdout.txt 2> err.txt
expect_exit "repair half top --max-hole 0.5" 3 $?

# Real TetGen output in every format, read back by meshio and gmsh with the counts and the volume.
mkdir -p formats
for out in formats/c41.msh formats/c22.msh formats/c.vtu formats/c.vtk formats/c.mesh formats/c.node formats/c.inp \
           formats/c.xdmf; do
  extra=""; [ "$out" = formats/c22.msh ] && extra="--msh-version 2.2"
  "$bin" tetrahedralize cube.off -o $out --max-volume 0.01 --min-dihedral 12 $extra --json formats.json > /dev/null 2> err.txt ||
    bad "write $out"
done
"$bin" tetrahedralize cube.off -o formats/c41b.msh --max-volume 0.01 --min-dihedral 12 --binary > /dev/null 2> err.txt ||
  bad "write binary msh"
"$bin" tetrahedralize cube.off -o formats/ca.vtu --max-volume 0.01 --min-dihedral 12 --ascii > /dev/null 2> err.txt ||
  bad "write ascii vtu"
grep -q 'compressor="vtkZLibDataCompressor"' formats/c.vtu && grep -q '<AppendedData encoding="raw">' formats/c.vtu &&
  ! grep -q 'format="appended"' formats/ca.vtu && ok || bad "vtu: binary (appended, zlib) by default, ASCII on --ascii"
counts=$(python3 -c "
import json; q = json.load(open('formats.json'))['tet_quality']; print(q['points'], q['tetrahedra'], q['volume'])")
if [ -n "$python" ] && command -v gmsh > /dev/null; then
  $python "$here/fem_readback.py" formats $counts > readback.txt 2>&1 && ok || { bad "read-back"; cat readback.txt; }
else
  echo "note: read-back skipped: no python3 with meshio or no gmsh (scripts/install-deps.sh installs them)"
fi

# --binary or --ascii that the output's format cannot honour: refused before any work, in one
# line naming the output and its format (exit 2), nothing written.
refused_encoding() {  # DESCRIPTION EXPECTED_LINE ARGS...
  local what=$1 line=$2
  shift 2
  rm -rf refused && mkdir refused
  "$bin" "$@" > /dev/null 2> err.txt
  expect_exit "$what" 2 $?
  grep -qx "$line" err.txt && [ "$(wc -l < err.txt)" -eq 1 ] && ok || bad "$what: not the one line '$line'"
  [ -z "$(ls -A refused)" ] && ok || bad "$what: wrote $(ls refused)"
}
text_format="it is a text format (binary: .msh .vtu .xdmf)"
refused_encoding "tetrahedralize --binary .inp" "meshprep: error: refused/t.inp: cannot write Abaqus/CalculiX (.inp) binary: $text_format" \
  tetrahedralize cube.off -o refused/t.inp --binary
refused_encoding "tetrahedralize --ascii .xdmf" \
  "meshprep: error: refused/t.xdmf: cannot write XDMF + HDF5 (.xdmf) as ASCII: its data is binary (ASCII: .msh .vtu .vtk .mesh .node .inp)" \
  tetrahedralize cube.off -o refused/t.xdmf --ascii
refused_encoding "tetrahedralize --binary --target calculix" "meshprep: error: refused/t.inp: --binary: target calculix reads ASCII .inp files" \
  tetrahedralize cube.off -o refused/t.inp --target calculix --binary
refused_encoding "improve --binary .mesh" "meshprep: error: refused/t.mesh: cannot write Medit (.mesh) binary: $text_format" \
  improve formats/c41.msh -o refused/t.mesh --binary
refused_encoding "convert --binary .node" "meshprep: error: formats/c41.msh -> refused/t.node: cannot write TetGen (.node) binary: $text_format" \
  convert formats/c41.msh -o refused/t.node --binary
refused_encoding "convert --binary .vtk" "meshprep: error: formats/c41.msh -> refused/t.vtk: cannot write VTK legacy (.vtk) binary: $text_format" \
  convert formats/c41.msh -o refused/t.vtk --binary
refused_encoding "convert --binary .obj" "meshprep: error: refused/t.obj: cannot write OBJ binary: it is a text format (binary: .ply .stl)" \
  convert cube.off -o refused/t.obj --binary
refused_encoding "pipeline --format inp --binary" \
  "meshprep: error: tetrahedralize: binary: tets.inp: cannot write Abaqus/CalculiX (.inp) binary: $text_format" \
  pipeline cube.off -o refused/run --format inp --binary
refused_encoding "--binary and --ascii" "meshprep: error: --binary excludes --ascii (see meshprep --help)" \
  tetrahedralize cube.off -o refused/t.vtu --binary --ascii
# convert to .vtu: binary unless --ascii (--binary, accepted, asks the same); the mesh is kept.
"$bin" convert formats/c.vtu -o conv_binary.vtu --binary > /dev/null 2> err.txt; expect_exit "convert vtu --binary" 0 $?
"$bin" convert formats/c.vtu -o conv_ascii.vtu --ascii > /dev/null 2> err.txt; expect_exit "convert vtu --ascii" 0 $?
cmp -s formats/c.vtu conv_binary.vtu && cmp -s formats/c_boundary.vtu conv_binary_boundary.vtu && ok ||
  bad "convert vtu --binary: not the binary file tetrahedralize wrote"
"$bin" quality conv_ascii.vtu --json qa.json > /dev/null 2> err.txt && "$bin" quality formats/c.vtu --json qb.json > /dev/null 2>&1
python3 -c "
import json; a = json.load(open('qa.json')); b = json.load(open('qb.json'))
assert a['tet_quality'] == b['tet_quality'] and a['boundary'] == b['boundary'], (a, b)
assert a['input']['format'] == 'vtu ascii + conv_ascii_boundary.vtu', a['input']
assert b['input']['format'] == 'vtu appended raw zlib + c_boundary.vtu', b['input']" && ok || bad "convert vtu --ascii keeps the mesh"

# A terrain-like open surface closes into a block with --extrude-base. TetGen alone leaves a
# 6-degree sliver in it, which the improvement removes: FEM-ready.
python3 "$here/cli_meshes.py" terrain
"$bin" tetrahedralize terrain.off -o terrain.vtu --extrude-base 2 --json out.json > /dev/null 2> err.txt
expect_exit "terrain block" 0 $?
[ -s terrain.vtu ] && ok || bad "terrain block: terrain.vtu not written"
python3 -c "
import json; j = json.load(open('out.json')); q = j['tet_quality']; assert q['tetrahedra'] > 0 and q['inverted_tets'] == 0, q
assert j['fem_ready'] == (q['min_dihedral_deg']['min'] >= 10 and q['max_dihedral_deg']['max'] <= 165), j" && ok || bad "terrain json"
"$bin" tetrahedralize terrain.off -o terrain.msh > /dev/null 2> err.txt; expect_exit "terrain without extrusion" 2 $?
"$bin" tetrahedralize cube.off -o cube2.msh --extrude-base 1 > /dev/null 2> err.txt; expect_exit "extruding a closed surface" 2 $?
grep -q "cube.off: cannot extrude" err.txt && ok || bad "extrusion error names the file"

# `quality` on tet meshes: the tets and volume tetrahedralize reported, the closed boundary of the
# cube (TetGen may split its 12 triangles, tag 1), the surface-only options refused.
for mesh in formats/c41.msh formats/c.vtu formats/c41b.msh formats/c.node formats/c.xdmf; do
  rm -f q.json
  "$bin" quality $mesh --json q.json > stdout.txt 2> err.txt
  expect_exit "quality $mesh" 0 $?
  python3 -c "
import json; f = json.load(open('formats.json'))['tet_quality']; j = json.load(open('q.json')); q = j['tet_quality']
assert q['tetrahedra'] == f['tetrahedra'] and q['points'] == f['points'] and abs(q['volume'] - 1) < 1e-12, q
b = j['boundary']; assert b['closed'] and b['manifold'] and b['oriented'] and b['faces'] >= 12 and b['genus'] == 0, b
assert q['inverted_tets'] == 0 and j['input']['tets_reoriented'] == 0, j" && ok || bad "quality $mesh json"
  grep -q "^Tet mesh quality: $mesh" stdout.txt && grep -q "min dihedral (deg)" stdout.txt && ok || bad "quality $mesh text"
done
"$bin" quality formats/c.vtu --json - > stdout.txt 2> err.txt; expect_exit "quality --json -" 0 $?
python3 -c "import json; json.load(open('stdout.txt'))" && ok || bad "quality --json - is JSON alone"
"$bin" quality formats/c41.msh --fail-on "boundary.closed=true" > /dev/null 2> err.txt
expect_exit "quality gate on a tet mesh" 1 $?
grep -q "quality gate failed: boundary.closed=true" err.txt && ok || bad "gate names the condition"
"$bin" quality formats/c41.msh --fail-on "tet_quality.inverted_tets>0" > /dev/null 2> err.txt
expect_exit "passing gate" 0 $?
for option in "--csv q.csv" "--vtk q.vtk" "--html q.html" "--reference cube.off"; do
  "$bin" quality formats/c41.msh $option > /dev/null 2> err.txt; expect_exit "quality $option on tets" 2 $?
  grep -q "is for surface meshes" err.txt && ok || bad "$option: no clear message"
done
[ ! -e q.csv ] && [ ! -e q.vtk ] && [ ! -e q.html ] && ok || bad "a surface-only output was written"

# A broken or surface-only volume file: exit 2, one line naming the file, no report written.
head -c 300 formats/c41.msh > broken.msh
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n' > surface.msh
for mesh in broken.msh surface.msh; do
  rm -f q.json
  "$bin" quality $mesh --json q.json > stdout.txt 2> err.txt; expect_exit "quality $mesh" 2 $?
  [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "^meshprep: error: $mesh: " err.txt && ok || bad "$mesh: not one line naming the file"
  [ ! -e q.json ] && [ ! -s stdout.txt ] && ok || bad "$mesh: something was written"
done
grep -q "no tetrahedra" err.txt && ok || bad "surface.msh: the message says there are no tets"

# `convert` between tet formats keeps the mesh: the converted file's report is the same.
"$bin" convert formats/c41.msh conv.vtk > /dev/null 2> err.txt; expect_exit "convert msh -> vtk" 0 $?
"$bin" convert conv.vtk conv.msh --msh-version 2.2 --binary > /dev/null 2> err.txt; expect_exit "convert vtk -> msh 2.2" 0 $?
"$bin" quality conv.msh --json conv.json > /dev/null 2> err.txt
"$bin" quality formats/c41.msh --json orig.json > /dev/null 2> err.txt
python3 -c "
import json; a = json.load(open('conv.json')); b = json.load(open('orig.json'))
assert a['tet_quality'] == b['tet_quality'] and a['boundary']['faces'] == b['boundary']['faces'], (a, b)
assert a['input']['format'] == 'msh 2.2 binary', a" && ok || bad "convert keeps the mesh"
# ... and to XDMF + HDF5 and back: the same report, the .h5 beside the .xdmf.
"$bin" convert formats/c41.msh conv.xdmf > /dev/null 2> err.txt; expect_exit "convert msh -> xdmf" 0 $?
"$bin" convert conv.xdmf conv2.msh > /dev/null 2> err.txt; expect_exit "convert xdmf -> msh" 0 $?
"$bin" quality conv2.msh --json conv2.json > /dev/null 2> err.txt
python3 -c "
import json; a = json.load(open('conv2.json')); b = json.load(open('orig.json'))
assert a['tet_quality'] == b['tet_quality'] and a['boundary'] == b['boundary'], (a, b)" && [ -s conv.h5 ] && ok ||
  bad "convert through xdmf keeps the mesh"
"$bin" convert broken.msh conv2.vtu > /dev/null 2> err.txt; expect_exit "convert a broken tet mesh" 2 $?
[ ! -e conv2.vtu ] && ok || bad "convert wrote from a broken input"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
