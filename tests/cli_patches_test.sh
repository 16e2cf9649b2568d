#!/usr/bin/env bash
# Boundary patches on the real binary: `meshprep patches` (found, named, edited, written; refused
# edits exit 2 before any work), and the pipeline carrying a file's named groups (OBJ groups, the
# solids of an ASCII STL) and the patches found from the creases into the tets' physical names,
# read back by meshio.
# Usage: cli_patches_test.sh MESHPREP_BINARY SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/cli_harness.sh"
require_meshio_python

# A 4 x 1 x 1 bar as a subdivided OBJ: its end x = 0 in the group "fixed_end", its end x = 4 in
# "load", the rest in "walls".
"$py" - <<'PY'
n = (16, 4, 4)
size = (4.0, 1.0, 1.0)
points, index, faces = [], {}, []
def vertex(i, j, k):
    key = (i, j, k)
    if key not in index:
        index[key] = len(points) + 1
        points.append(tuple(size[a] * key[a] / n[a] for a in range(3)))
    return index[key]
def side(axis, at, flip):
    u, v = [a for a in range(3) if a != axis]
    group = "walls"
    if axis == 0: group = "fixed_end" if at == 0 else "load"
    for a in range(n[u]):
        for b in range(n[v]):
            corners = []
            for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                c = [0, 0, 0]
                c[axis] = at; c[u] = a + du; c[v] = b + dv
                corners.append(vertex(*c))
            if flip: corners.reverse()
            faces.append((group, corners))
for axis in range(3):
    u, v = [a for a in range(3) if a != axis]
    # outward: (u, v, axis) right-handed at the far side
    right = (axis == 1)
    side(axis, 0, not right)
    side(axis, n[axis], right)
with open("bar.obj", "w") as out:
    for p in points: out.write("v %r %r %r\n" % p)
    current = None
    for group, corners in faces:
        if group != current:
            out.write("g %s\n" % group); current = group
        out.write("f %d %d %d\nf %d %d %d\n" % (corners[0], corners[1], corners[2], corners[0], corners[2], corners[3]))
PY

"$bin" patches bar.obj --json table.json > stdout.txt 2> err.txt
expect_exit "patches bar.obj" 0 $?
grep -q "3 patches, named by the file (obj groups)" stdout.txt && ok ||
  bad "patches bar.obj: $(cat stdout.txt)"
"$py" - <<'PY' && ok || bad "patches table.json"
import json
t = {r["name"]: r for r in json.load(open("table.json"))["table"]}
assert sorted(t) == ["fixed_end", "load", "walls"], t
assert abs(t["fixed_end"]["area"] - 1) < 1e-12 and abs(t["walls"]["area"] - 16) < 1e-12, t
assert t["load"]["normal_spread_deg"] < 1e-6
PY

# Found from the creases when the groups are ignored: the bar's six sides.
"$bin" patches bar.obj --resegment --rename patch_1=side_a -o six.ply > stdout.txt 2> err.txt
expect_exit "patches --resegment" 0 $?
grep -q "6 patches, bounded by the creases sharper than 45 deg" stdout.txt && ok || bad "resegment: $(cat stdout.txt)"
"$bin" patches six.ply --json - > six.json 2> err.txt && "$py" -c "
import json; t = [r['name'] for r in json.load(open('six.json'))['table']]
assert 'side_a' in t and len(t) == 6, t" && ok || bad "six.ply keeps the names"

# Refused before any work, one line, exit 2, nothing written.
"$bin" patches bar.obj --rename inlet=x -o out.ply > /dev/null 2> err.txt
expect_exit "rename of an unknown patch" 2 $?
one_line "rename of an unknown patch" "no patch is named 'inlet' (the patches: fixed_end, load, walls)"
[ ! -e out.ply ] && ok || bad "out.ply written after a refused rename"
"$bin" patches bar.obj -o out.off > /dev/null 2> err.txt
expect_exit "patches -o .off" 2 $?
one_line "patches -o .off" "holds no patches"
"$bin" pipeline bar.obj -o refused --rename nowhere=x > /dev/null 2> err.txt
expect_exit "pipeline --rename unknown" 2 $?
one_line "pipeline --rename unknown" "no patch is named 'nowhere'"
[ ! -e refused ] && ok || bad "pipeline wrote a folder after a refused rename"
# A size for a patch the surface does not have: one line naming it and the surface's, nothing written.
"$bin" pipeline bar.obj -o refused --size 0.5 --size lod=0.1 > /dev/null 2> err.txt
expect_exit "pipeline --size unknown=" 2 $?
one_line "pipeline --size unknown=" "no patch named 'lod' (the surface's patches: "
[ ! -e refused ] && ok || bad "pipeline wrote a folder after a refused patch size"
"$bin" tetrahedralize bar.obj -o refused.msh --size 1st=0.1 > /dev/null 2> err.txt
expect_exit "tetrahedralize --size 1st=" 2 $?
one_line "tetrahedralize --size 1st=" "'1st' is no patch name"
[ ! -e refused.msh ] && ok || bad "tetrahedralize wrote refused.msh after a refused patch size"

# The pipeline carries the file's groups into the tets: physical names in the .msh, each face
# of the tets' boundary on its own side of the bar.
"$bin" pipeline bar.obj -o bar --merge walls,fixed_end --rename load=tip --quiet 2> err.txt
expect_exit "pipeline bar.obj" 0 $?
"$py" - <<'PY' && ok || bad "bar/tets.msh physical names"
import meshio, numpy
m = meshio.read("bar/tets.msh")
names = {name: tag for name, (tag, dim) in m.field_data.items() if dim == 2}
assert sorted(names) == ["tip", "walls"], m.field_data
tags = m.cell_data_dict["gmsh:physical"]["triangle"]
tri = m.cells_dict["triangle"]
tip = tri[tags == names["tip"]]
assert len(tip) > 0 and numpy.allclose(m.points[tip.ravel(), 0], 4.0), "the tip patch is the end x = 4"
walls = tri[tags == names["walls"]]
assert not numpy.any(numpy.all(numpy.isclose(m.points[walls][:, :, 0], 4.0), axis=1)), "no wall face at x = 4"
PY
"$py" - <<'PY' && ok || bad "bar/report.json patches"
import json
rows = {r["name"]: r for r in json.load(open("bar/report.json"))["patches"]}
assert sorted(rows) == ["tip", "walls"], rows
assert abs(rows["walls"]["area"] - 17) < 1e-9 and rows["tip"]["tet_boundary_faces"] > 0, rows
PY
grep -q "Boundary patches" bar/report.html && ok || bad "report.html has no patch section"

# A multi-solid ASCII STL keeps its solids' names (made to follow the naming rule, and said so);
# the fandisk's creases give its ten patches.
"$bin" convert bar.obj bar.stl 2> err.txt && grep -c "^solid " bar.stl | grep -qx 3 && ok || bad "bar.stl has three solids"
sed -i 's/^solid fixed_end$/solid fixed end/' bar.stl
"$bin" patches bar.stl > stdout.txt 2> err.txt && grep -q "renamed 'fixed end' -> 'fixed_end'" stdout.txt && ok ||
  bad "patches bar.stl: $(cat stdout.txt)"
"$bin" pipeline bar.stl -o barstl --quiet 2> err.txt
expect_exit "pipeline bar.stl" 0 $?
"$py" -c "
import meshio; m = meshio.read('barstl/tets.msh')
assert sorted(n for n, (t, d) in m.field_data.items() if d == 2) == ['fixed_end', 'load', 'walls'], m.field_data" && ok ||
  bad "barstl/tets.msh physical names"
"$bin" pipeline "$src/examples/data/fandisk.off" -o fandisk --ratio 0.3 --quiet 2> err.txt
expect_exit "pipeline fandisk" 0 $?
"$py" - <<'PY' && ok || bad "fandisk patches: each area within 0.5 % of the input's"
import json
rows = json.load(open("fandisk/report.json"))["patches"]
assert len(rows) == 10, len(rows)
for r in rows: assert abs(r["area_change_percent"]) < 0.5, r
PY

# improve and convert keep the names they read, through every format that holds names.
names_of() { "$bin" quality "$1" --json - 2> err.txt | "$py" -c "import json, sys; print(' '.join(sorted(json.load(sys.stdin)['boundary']['faces_per_patch'])))"; }
"$bin" tetrahedralize bar.obj -o bar.msh --no-improve > /dev/null 2> err.txt
expect_exit "tetrahedralize bar.obj --no-improve (its slivers left: written, not ready)" 1 $?
"$bin" improve bar.msh -o bar_improved.msh > /dev/null 2> err.txt
expect_exit "improve bar.msh" 0 $?
[ "$(names_of bar_improved.msh)" = "fixed_end load walls" ] && ok || bad "improve dropped names: $(names_of bar_improved.msh)"
previous=bar_improved.msh
for ext in xdmf vtu msh; do
  "$bin" convert $previous -o bar_converted.$ext > /dev/null 2> err.txt
  expect_exit "convert $previous -> .$ext" 0 $?
  [ "$(names_of bar_converted.$ext)" = "fixed_end load walls" ] && ok || bad "convert to .$ext dropped names: $(names_of bar_converted.$ext)"
  previous=bar_converted.$ext
done

# A tet mesh's boundary surface, with its patches where the format holds them.
for ext in obj ply stl; do
  "$bin" convert bar_converted.msh -o bar_boundary.$ext --json boundary.json > /dev/null 2> err.txt
  expect_exit "convert bar_converted.msh -> boundary .$ext" 0 $?
  "$bin" patches bar_boundary.$ext --json table.json > /dev/null 2> err.txt
  "$py" -c "
import json; t = json.load(open('table.json')); b = json.load(open('boundary.json'))
assert sorted(r['name'] for r in t['table']) == ['fixed_end', 'load', 'walls'], t['table']
assert b['kind'] == 'boundary' and b['patches'] == 3 and b['triangles'] == sum(r['faces'] for r in t['table']), b
assert abs(sum(r['area'] for r in t['table']) - 18) < 1e-9, t['table']  # the 4 x 1 x 1 bar's surface" &&
    ok || bad "bar_boundary.$ext: its patches $(cat table.json | head -c 300)"
done
"$bin" convert bar_converted.msh -o bar_boundary.off --order 2 > /dev/null 2> err.txt
expect_exit "convert to a surface with --order" 2 $?
one_line "convert to a surface with --order" "applies to tet outputs, not to the surface"
[ ! -e bar_boundary.off ] && ok || bad "a refused convert wrote bar_boundary.off"

echo "cli_patches: $passed passed, $failed failed"
[ "$failed" = 0 ]
