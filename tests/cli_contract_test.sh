#!/usr/bin/env bash
# The command-line contract on the real binary: exit codes, one clear error line naming the file,
# no output file left behind on failure, inputs never modified.
# Usage: cli_contract_test.sh MESHPREP_BINARY
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0 failed=0

check() {  # check NAME EXPECTED_EXIT ACTUAL_EXIT [condition...]
  local name=$1 want=$2 got=$3
  if [ "$want" = "$got" ]; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL: $name: exit $got, expected $want"; cat err.txt 2>/dev/null
  fi
}
expect_error() {  # expect_error NAME PATTERN: stderr is one line matching PATTERN
  local name=$1 pattern=$2
  if [ "$(wc -l < err.txt)" -eq 1 ] && grep -q -- "$pattern" err.txt; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL: $name: stderr does not match '$pattern':"; cat err.txt
  fi
}
expect_no_file() {
  if [ ! -e "$1" ] && [ -z "$(ls -A out 2>/dev/null)" ]; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL: $2: output $1 (or a temporary) exists"; ls -la out
  fi
}

mkdir -p out
cat > tet.off <<'EOM'
OFF
4 4 0
0 0 0
1 1 0
1 0 1
0 1 1
3 0 1 2
3 0 3 1
3 0 2 3
3 1 3 2
EOM

# A good run: summary on stdout, exit 0, JSON parseable and complete.
"$bin" quality tet.off --json out/q.json > summary.txt 2> err.txt; check "quality ok" 0 $?
grep -q "closed" summary.txt && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: no summary"; }
python3 - <<'PY' && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: json content"; }
import json, math
j = json.load(open("out/q.json"))
assert j["faces"] == 4 and j["closed"] and j["manifold"] and j["oriented"] and j["genus"] == 0
assert abs(j["volume"] - 1/3) < 1e-12, j["volume"]   # cube-corner tetrahedron of side 1: 1 - 4/6
assert j["input"]["format"] == "off"
for key in ("radius_ratio", "aspect_ratio", "min_angle_deg", "max_angle_deg", "face_area"):
    assert set(j[key]) >= {"min", "mean", "p5", "p50", "p95", "max"}, key
PY
"$bin" quality tet.off --json - > stdout.json 2> err.txt; check "json to stdout" 0 $?
python3 -c "import json; json.load(open('stdout.json'))" && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: --json - is not pure JSON"; }

# Quality gate: exit 1 naming the failed condition; a bad gate is a usage error.
"$bin" quality tet.off --fail-on "radius_ratio.p95>0.9,closed=false" > /dev/null 2> err.txt; check "gate fails" 1 $?
expect_error "gate message" "radius_ratio.p95>0.9"
"$bin" quality tet.off --fail-on "radius_ratio.p95>2" > /dev/null 2> err.txt; check "gate passes" 0 $?
"$bin" quality tet.off --fail-on "nonsense>2" > /dev/null 2> err.txt; check "gate unknown key" 2 $?

# Malformed inputs: exit 2, one line naming the file, nothing written.
rm -f out/*
printf 'OFF\n4 4 0\n0 0 0\n1 1 0\n1 0 1\n0 1 1\n3 0 1 2\n' > truncated.off
printf 'OFF\n3 1 0\n0 0 0\nnan 1 0\n1 0 1\n3 0 1 2\n' > nan.off
printf 'OFF\n3 1 0\n0 0 0\n1 1 0\n1 0 1\n3 0 1 7\n' > range.off
: > empty.off
printf 'solid x\nthis is not a mesh\n' > garbage.stl
printf 'hello\n' > mesh.xyz3
for f in truncated.off:truncated nan.off:non-finite range.off:range empty.off:empty garbage.stl:garbage.stl \
         missing.off:missing.off mesh.xyz3:mesh.xyz3; do
  file=${f%%:*} pattern=${f#*:}
  "$bin" quality "$file" --json out/bad.json --html out/bad.html > /dev/null 2> err.txt; check "bad input $file" 2 $?
  expect_error "message for $file" "$pattern"
  expect_no_file out/bad.json "bad input $file"
done

# A binary STL whose 80-byte header starts with "solid" is still read as binary.
python3 - <<'PY'
import struct
tris = [((0,0,0),(1,1,0),(1,0,1)), ((0,0,0),(0,1,1),(1,1,0)), ((0,0,0),(1,0,1),(0,1,1)), ((1,1,0),(0,1,1),(1,0,1))]
with open("solid_header.stl", "wb") as f:
    f.write(b"solid but actually binary".ljust(80, b" "))
    f.write(struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<3f", 0, 0, 0))
        for p in t: f.write(struct.pack("<3f", *p))
        f.write(b"\0\0")
PY
"$bin" quality solid_header.stl --json out/stl.json > /dev/null 2> err.txt; check "binary stl with solid header" 0 $?
python3 -c "
import json; j = json.load(open('out/stl.json'))
assert j['faces'] == 4 and j['vertices'] == 4 and j['closed'] and j['input']['format'] == 'stl-binary', j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: binary stl content"; }
rm -f out/*

# A non-manifold face (a fin on an edge) is reported with its index, not dropped silently.
cat > fin.off <<'EOM'
OFF
5 5 0
0 0 0
1 1 0
1 0 1
0 1 1
0.5 0.5 -1
3 0 1 2
3 0 3 1
3 0 2 3
3 1 3 2
3 0 1 4
EOM
"$bin" quality fin.off --json out/fin.json > /dev/null 2> err.txt; check "non-manifold face" 0 $?
expect_error "non-manifold face reported" "face 4 makes the edge 0-1 non-manifold.*(faces 4)"
python3 -c "
import json; j = json.load(open('out/fin.json'))
assert j['non_manifold_edges'] == 1 and not j['manifold'] and j['input']['faces_not_manifold_representable_indices'] == [4], j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: fin report"; }
rm -f out/*

# Usage errors: exit 2.
"$bin" quality > /dev/null 2> err.txt; check "missing argument" 2 $?
"$bin" quality tet.off --no-such-flag > /dev/null 2> err.txt; check "unknown flag" 2 $?
"$bin" frobnicate > /dev/null 2> err.txt; check "unknown command" 2 $?
"$bin" --help > /dev/null 2> err.txt; check "--help" 0 $?
"$bin" quality --help > /dev/null 2> err.txt; check "quality --help" 0 $?
"$bin" help > /dev/null 2> err.txt; check "help" 0 $?
"$bin" --version > version.txt 2> err.txt; check "--version" 0 $?
grep -q "meshprep [0-9]" version.txt && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: version"; }

# Outputs never clobber the input; convert round-trips; an output that cannot be written once the
# work is done is exit 1 (the input was fine), naming the file.
cp tet.off keep.off
"$bin" quality keep.off --json keep.off > /dev/null 2> err.txt; check "json over input" 2 $?
cmp -s tet.off keep.off && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: input modified"; }
"$bin" convert tet.off out/tet.ply --binary > /dev/null 2> err.txt; check "convert to binary ply" 0 $?
"$bin" convert out/tet.ply -o out/tet.stl --json out/convert.json > /dev/null 2> err.txt; check "convert -o to stl" 0 $?
python3 -c "
import json; j = json.load(open('out/convert.json')); assert j['kind'] == 'surface' and j['triangles'] == 4, j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: convert --json"; }
"$bin" convert out/tet.ply > /dev/null 2> err.txt; check "convert without an output" 2 $?
expect_error "convert without an output message" "give the output file with -o OUT"
"$bin" quality out/tet.stl --json out/rt.json > /dev/null 2> err.txt; check "quality of converted" 0 $?
python3 -c "
import json; j = json.load(open('out/rt.json')); assert j['faces'] == 4 and j['closed'] and abs(j['volume'] - 1/3) < 1e-6, j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: round trip"; }
"$bin" convert tet.off /nonexistent-dir/x.off > /dev/null 2> err.txt; check "unwritable output" 2 $?  # found before any work
expect_error "unwritable message" "nonexistent-dir"

# simplify: reaches the target, keeps the sphere closed, reports the output's quality against the input.
python3 - <<'PY'
import math
# UV sphere: 16 x 32, closed (poles as single vertices)
n, m = 16, 32
pts = [(0, 0, 1)] + [(math.sin(math.pi * i / n) * math.cos(2 * math.pi * j / m),
                       math.sin(math.pi * i / n) * math.sin(2 * math.pi * j / m),
                       math.cos(math.pi * i / n)) for i in range(1, n) for j in range(m)] + [(0, 0, -1)]
v = lambda i, j: 1 + (i - 1) * m + j % m
tris = [(0, v(1, j), v(1, j + 1)) for j in range(m)]
for i in range(1, n - 1):
    for j in range(m):
        tris += [(v(i, j), v(i + 1, j), v(i + 1, j + 1)), (v(i, j), v(i + 1, j + 1), v(i, j + 1))]
tris += [(len(pts) - 1, v(n - 1, j + 1), v(n - 1, j)) for j in range(m)]
with open("sphere.off", "w") as f:
    f.write(f"OFF\n{len(pts)} {len(tris)} 0\n")
    for p in pts: f.write("%r %r %r\n" % p)
    for t in tris: f.write("3 %d %d %d\n" % t)
PY
"$bin" simplify sphere.off -o out/sphere_small.off --ratio 0.25 --json out/simplify.json > /dev/null 2> err.txt
check "simplify" 0 $?
python3 -c "
import json; j = json.load(open('out/simplify.json'))
assert j['faces_before'] == 960 and j['reached_target'] and j['quality']['closed'] and j['quality']['genus'] == 0, j
assert j['quality']['reference']['hausdorff_relative'] < 0.05, j['quality']['reference']" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: simplify json"; }
"$bin" simplify sphere.off -o out/sphere_enhanced.off --ratio 0.25 --enhance --json out/s_enhance.json > /dev/null 2> err.txt
check "simplify --enhance" 0 $?
python3 -c "
import json; j = json.load(open('out/s_enhance.json'))
assert j['reached_target'] and j['enhance']['stages'] == 3 and j['quality']['closed'], j
assert j['quality']['self_intersections'] == 0 and j['quality']['faces_min_angle_below_20'] == 0, j['quality']" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: simplify --enhance json"; }
for cost in distance quadric; do
  "$bin" simplify sphere.off -o out/sphere_$cost.off --ratio 0.25 --cost $cost --json out/s_$cost.json > /dev/null 2> err.txt
  check "simplify --cost $cost" 0 $?
done
python3 -c "
import json
b, q = (json.load(open('out/' + f)) for f in ('simplify.json', 's_quadric.json'))
assert b['cost'] == 'bending' and q['cost'] == 'quadric' and b['input_topology']['genus'] == 0, b
# the guard: no angle under min(20 degrees, the input's smallest: 360 / 32 at the poles)
assert b['quality']['min_angle_deg']['min'] >= 11.25 - 1e-9, b['quality']['min_angle_deg']" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: simplify costs json"; }
"$bin" simplify sphere.off -o out/x.off --ratio 0.5 --faces 100 > /dev/null 2> err.txt; check "simplify ratio and faces" 2 $?
"$bin" simplify sphere.off -o out/x.off --ratio 0.5 --min-angle 70 > /dev/null 2> err.txt; check "simplify min angle out of range" 2 $?
"$bin" simplify sphere.off -o out/x.off --ratio 0.5 --cost magic > /dev/null 2> err.txt; check "simplify unknown cost" 2 $?
"$bin" simplify fin.off -o out/x.off --ratio 0.5 > /dev/null 2> err.txt; check "simplify non-manifold input" 2 $?
expect_error "simplify non-manifold message" "fin.off: face 4 .*non-manifold"
"$bin" simplify sphere.off -o out/x.off > /dev/null 2> err.txt; check "simplify without target" 2 $?
[ ! -e out/x.off ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: simplify wrote on a usage error"; }

# smooth: a noisy sphere gets closer to the sphere; the baselines run; bad input is exit 2, nothing written.
python3 - <<'PY'
import math
lines = open("sphere.off").read().split("\n")
nv = int(lines[1].split()[0])
out = lines[:2]
for i in range(nv):
    x, y, z = map(float, lines[2 + i].split())
    s = 1 + 0.01 * (2 * math.fmod(0.5 + i * 0.6180339887498949, 1.0) - 1)
    out.append("%r %r %r" % (s * x, s * y, s * z))
out += lines[2 + nv:]
open("noisy_sphere.off", "w").write("\n".join(out))
PY
"$bin" smooth noisy_sphere.off -o out/smooth.off --preserve-volume --json out/smooth.json > /dev/null 2> err.txt
check "smooth" 0 $?
python3 -c "
import json; j = json.load(open('out/smooth.json'))
assert j['method'] == 'rbf' and j['iterations'] == 1 and j['neighbors'] == 80, j
assert j['smoothing'] == 'inf' and j['relaxation'] == 0.5, j
assert abs(j['volume_change_relative']) < 1e-8 and j['quality']['self_intersections'] == 0, j
assert j['quality']['closed'] and j['max_displacement'] > 0, j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: smooth json"; }
"$bin" smooth noisy_sphere.off -o out/taubin.off --method taubin --iterations 5 > /dev/null 2> err.txt
check "smooth taubin" 0 $?
"$bin" smooth noisy_sphere.off -o out/x.off --method magic > /dev/null 2> err.txt; check "smooth unknown method" 2 $?
"$bin" smooth noisy_sphere.off -o out/x.off --smoothing -1 > /dev/null 2> err.txt; check "smooth negative smoothing" 2 $?
"$bin" smooth fin.off -o out/x.off > /dev/null 2> err.txt; check "smooth non-manifold input" 2 $?
expect_error "smooth non-manifold message" "fin.off: face 4 .*non-manifold"
[ ! -e out/x.off ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: smooth wrote on an error"; }

# enhance: a sphere with vertices pushed along it gets better triangles and stays closed; bad
# input or reference is exit 2, nothing written.
python3 - <<'PY'
import math
lines = open("sphere.off").read().split("\n")
nv = int(lines[1].split()[0])
out = lines[:2]
for i in range(nv):
    x, y, z = map(float, lines[2 + i].split())
    if i % 2 == 0 and abs(z) < 0.9:  # a tangential push (clear of the poles), back onto the sphere
        t = (y * 0.2 - z, z * 0.3 - x * 0.2, x - y * 0.3)
        x, y, z = x + 0.04 * t[0], y + 0.04 * t[1], z + 0.04 * t[2]
        r = math.sqrt(x * x + y * y + z * z); x, y, z = x / r, y / r, z / r
    out.append("%r %r %r" % (x, y, z))
out += lines[2 + nv:]
open("pushed_sphere.off", "w").write("\n".join(out))
PY
"$bin" enhance pushed_sphere.off -o out/enhanced.off --reference sphere.off --json out/enhance.json > /dev/null 2> err.txt
check "enhance" 0 $?
# Its vertices are off the reference's facets (on the true sphere): not remeshed by default.
python3 -c "
import json; j = json.load(open('out/enhance.json'))
assert not j['remesh']['remeshed'] and abs(j['faces_after'] / j['faces_before'] - 1) <= 0.02, j
assert j['tail_after']['q_p05'] > j['tail_before']['q_p05'], j
assert j['quality']['closed'] and j['quality']['self_intersections'] == 0 and j['reference'] == 'sphere.off', j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: enhance json"; }
# Remeshed on request (16 % of its faces are under 20 degrees): to the curvature's sizing, within the bound.
"$bin" enhance pushed_sphere.off -o out/remeshed.off --reference sphere.off --remesh on --json out/remeshed.json > /dev/null 2> err.txt
check "enhance --remesh on" 0 $?
python3 -c "
import json; j = json.load(open('out/remeshed.json'))
assert j['remesh']['remeshed'] and j['faces_after'] > j['faces_before'], j
assert j['tail_after']['under_target_fraction'] <= 0.01 and j['quality']['self_intersections'] == 0, j
assert j['quality']['reference']['hausdorff_relative'] <= j['parameters']['max_deviation'], j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: enhance --remesh on json"; }
"$bin" enhance pushed_sphere.off -o out/noflip.off --no-flips --json - > out/noflip.json 2> err.txt
check "enhance --no-flips" 0 $?
python3 -c "
import json; j = json.load(open('out/noflip.json')); assert j['flips'] == 0 and j['reference'] is None, j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: enhance --no-flips json"; }
rm -f out/*
"$bin" enhance pushed_sphere.off -o out/x.off --reference missing.off > /dev/null 2> err.txt; check "enhance missing reference" 2 $?
expect_error "enhance missing reference message" "missing.off"
"$bin" enhance pushed_sphere.off -o out/x.off --max-deviation 0 > /dev/null 2> err.txt; check "enhance zero deviation" 2 $?
"$bin" enhance fin.off -o out/x.off > /dev/null 2> err.txt; check "enhance non-manifold input" 2 $?
expect_error "enhance non-manifold message" "fin.off: face 4 .*non-manifold"
"$bin" enhance pushed_sphere.off -o sphere.off --reference sphere.off > /dev/null 2> err.txt; check "enhance over its reference" 2 $?
expect_no_file out/x.off "enhance on errors"

# reconstruct: a height field from scattered points; bad point files are exit 2, nothing written.
python3 -c "
import math
with open('terrain.xyz', 'w') as f:
    for i in range(400):
        x, y = math.fmod(0.5 + i * 0.7548776662466927, 1.0), math.fmod(0.5 + i * 0.5698402909980532, 1.0)
        f.write('%r %r %r\\n' % (x, y, 0.2 * math.sin(3 * x) * y))
"
"$bin" reconstruct terrain.xyz -o out/terrain.off --resolution 30 30 --json out/rec.json > /dev/null 2> err.txt
check "reconstruct" 0 $?
python3 -c "
import json; j = json.load(open('out/rec.json'))
assert j['points'] == 400 and j['faces'] > 1500 and j['patches'] > 10 and j['reference_normal'][2] > 0.99, j" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: reconstruct json"; }
head -30 terrain.xyz > few.xyz
"$bin" reconstruct few.xyz -o out/x.off > /dev/null 2> err.txt; check "reconstruct too few points" 2 $?
expect_error "reconstruct too few points message" "few.xyz: .*30 points, at least 40"
(head -5 terrain.xyz; echo "1 2 nan"; tail -100 terrain.xyz) > nan.xyz
"$bin" reconstruct nan.xyz -o out/x.off > /dev/null 2> err.txt; check "reconstruct NaN" 2 $?
expect_error "reconstruct NaN message" "nan.xyz"
(cat terrain.xyz; sed -n 7p terrain.xyz) > duplicate.xyz
"$bin" reconstruct duplicate.xyz -o out/x.off > /dev/null 2> err.txt; check "reconstruct duplicate point" 2 $?
expect_error "reconstruct duplicate point message" "duplicate.xyz: .*points 7 and 401 .*same place"
(for i in $(seq 1 60); do echo "$i $((2 * i)) $((3 * i))"; done) > line.xyz
"$bin" reconstruct line.xyz -o out/x.off > /dev/null 2> err.txt; check "reconstruct collinear points" 2 $?
expect_error "reconstruct collinear points message" "line.xyz: .*collinear"
[ ! -e out/x.off ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: reconstruct wrote on an error"; }
"$bin" reconstruct terrain.xyz -o out/x.off --variation-threshold p101 > /dev/null 2> err.txt
check "reconstruct bad variation threshold" 2 $?
expect_error "reconstruct bad variation threshold message" "variation-threshold: expected .*p101"
"$bin" reconstruct terrain.xyz -o out/x.off --vertices 900 --resolution 30 30 > /dev/null 2> err.txt
check "reconstruct --vertices with --resolution" 2 $?
[ ! -e out/x.off ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: reconstruct wrote on a usage error"; }
# sigma per vertex in the PLY; the percentile rule grows the patches above it; --vertices sizes the grid.
"$bin" reconstruct terrain.xyz -o out/terrain.ply --vertices 900 --variation-threshold p50 --json out/rec2.json \
  > /dev/null 2> err.txt
check "reconstruct ply with sigma" 0 $?
python3 -c "
import json; j = json.load(open('out/rec2.json'))
v = j['variation']; n = j['grid']['columns'] * j['grid']['rows']
assert v['rule'] == 'p50' and 0 < v['grown_patches'] < j['patches'] and abs(n - 900) < 80, j
assert v['patch_sigma']['min'] <= v['threshold'] <= v['patch_sigma']['max'], v
lines = open('out/terrain.ply').read().split('\n')
assert 'property double surface_variation' in lines, lines[:10]
body = lines[lines.index('end_header') + 1:][:j['vertices']]
sigma = [float(l.split()[3]) for l in body]
assert len(sigma) == j['vertices'] and min(sigma) >= 0 and max(sigma) <= v['patch_sigma']['max'] + 1e-12, sigma[:5]" \
  && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: reconstruct sigma in ply and json"; }

# ---- issue 45, items 7, 8, 12, 14, 16: every message says what is wrong, before any work -------
refused() {  # refused NAME PATTERN ARGS...: `meshprep ARGS` exits 2 with one error line matching PATTERN
  local name=$1 pattern=$2
  shift 2
  "$bin" "$@" > /dev/null 2> err.txt
  check "$name" 2 $?
  expect_error "$name" "$pattern"
}
refused "mistyped command" "unknown command 'pipelin' (did you mean 'pipeline'?)" pipelin tet.off -o out45/p
"$bin" help pipeline > help.txt 2> err.txt; check "help COMMAND" 0 $?
grep -q "Usage: pipeline" help.txt && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: help pipeline"; }
refused "help of a mistyped command" "unknown command 'pipelin' (did you mean 'pipeline'?)" help pipelin
mkdir -p folder out45
for command in "quality folder" "tetrahedralize folder -o out45/x.msh" "pipeline folder -o out45/p" "repair folder -o out45/x.off"; do
  # shellcheck disable=SC2086
  refused "a folder as input: $command" "folder: a folder, not a mesh file" $command
done
refused "quality of an unknown extension" "tet.abc: unknown extension '.abc' (quality reads surfaces: .off, .obj, .ply, .stl; and tet meshes: .msh" quality tet.abc
refused "output in a missing folder" "missing/x.off: cannot write: the folder .*missing does not exist" smooth tet.off -o missing/x.off
touch plain
refused "pipeline folder under a file" "plain/sub: cannot create the output folder: .*plain is not a folder" pipeline tet.off -o plain/sub
refused "--json to a folder" "folder: cannot write: it is a folder" quality tet.off --json folder
refused "--faces 0" "faces: must be positive, not 0" simplify tet.off -o out45/x.off --faces 0
echo '{"tetrahedralize": {"msh_version": 4.1}}' > number.json
refused "msh_version as a number" "msh_version: expected one of 4.1, 2.2 as a string (in quotes), not 4.1" pipeline tet.off -o out45/p --config number.json
printf 'OFF\n4 4 0\n0 0 0\n1e-34 1e-34 0\n1e-34 0 1e-34\n0 1e-34 1e-34\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n' > tiny.off
refused "a part spanning 1e-34" "tiny.off: the coordinates span only 1e-34, less than" quality tiny.off
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n' > short.msh
refused "msh with fewer nodes than announced" "short.msh: line 10: .*the section ends ('\$EndNodes'): it holds fewer entries than its header announces" quality short.msh
# Item 12: counts and structures that lie are refused like the other count lies.
printf '4 3 1000000000 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n' > lie.node
printf '1 4 0\n1 1 2 3 4\n' > lie.ele
refused ".node announcing 1e9 attributes" "lie.node: line 2: the header announces 1000000000 more attribute values" quality lie.node
printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 1 5 0\n$EndEntities\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 99 4 1\n1 1 2 3 4\n$EndElements\n' > entity.msh
refused "msh 4.1 block on an undeclared entity" "entity.msh: .*an element block on entity 99 of dimension 3, which \$Entities does not declare" quality entity.msh
echo '{"repair": {"enabled": true}, "repair": {"enabled": false}}' > twice.json
refused "a config key given twice" "twice.json: repair is given twice" pipeline tet.off -o out45/p --config twice.json
echo '{"repair": {"enabled": true, "enabled": false}}' > twice_inner.json
refused "a config key given twice inside" "twice_inner.json: repair.enabled is given twice" pipeline tet.off -o out45/p --config twice_inner.json
"$bin" tetrahedralize tet.off -o whole.vtu --ascii > /dev/null 2>&1
sed '/<\/Piece>/q' whole.vtu > cut.vtu  # every array of the piece there, the document cut after it
refused ".vtu cut after its piece" "cut.vtu: truncated: the file ends before </UnstructuredGrid>" quality cut.vtu
"$bin" tetrahedralize tet.off -o whole_binary.vtu > /dev/null 2>&1
head -c -12 whole_binary.vtu > cut_binary.vtu  # the appended data whole, </VTKFile> cut
refused "binary .vtu without its end" "cut_binary.vtu: truncated: the file does not end with </VTKFile>" quality cut_binary.vtu
"$bin" quality whole_binary.vtu > /dev/null 2> err.txt; check "the whole binary .vtu" 0 $?
[ -z "$(ls -A out45 2>/dev/null)" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAIL: files written on the errors above"; ls out45; }

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
