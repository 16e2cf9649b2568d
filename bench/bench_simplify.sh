#!/usr/bin/env bash
# Simplification side by side, in three parts:
# 1. the single-thread speed rounds on bunny00 at 10 %, with CGAL's Garland-Heckbert collapse when
#    libcgal-dev is installed: first, since they are the figures the machine's hour moves most;
# 2. our bending and distance costs and OpenMesh's quadric decimater (--cost quadric, the baseline
#    linked into the same binary) on bunny00 and fandisk at 30 % and 10 %, with meshprep's own
#    quality report against the input (Hausdorff and RMS / bbox diagonal);
# 3. the scale run: bunny00 Loop-subdivided twice (1.2 M faces) to 10 %.
# Needs ../shared/data. Usage: [RUNS=8] bench/bench_simplify.sh [build-dir]   (default: build)
source "$(dirname "$0")/bench_setup.sh" "${1:-}" meshes

row() {  # mesh-file ratio cost label
  "$bin" simplify "$1" -o "$work/out.off" --ratio "$2" --cost "$3" --json "$work/r.json" > /dev/null
  python3 - "$work/r.json" "$4" "$2" "$3" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); q = j["quality"]; r = q["reference"]; t = j["input_topology"]
valid = q["closed"] == t["closed"] and q["manifold"] and q["genus"] == t["genus"] \
    and q["self_intersections"] <= t["self_intersections"]
print("| %s | %d %% | %s | %.2f | %d | %.3g | %.3g | %.1f %% | %.2f | %s |" % (
    sys.argv[2], round(100 * float(sys.argv[3])), sys.argv[4], j["time_seconds"], j["faces_after"],
    r["hausdorff_relative"], r["rms_relative"], 100 * q["faces_min_angle_below_20"], q["radius_ratio"]["p95"],
    "yes" if valid and j["reached_target"] else "NO"))
PY
}

# Single-threaded speed on bunny00 at 10 %: the goal compares bending with the quadric baseline
# "in the same run" and with the fastest valid peer (CGAL GH, 0.77 s in ../shared/anchors.md), and
# one run of each is at the mercy of the machine's hour (a shared VM swings by 30 %), so they
# alternate, RUNS rounds (default 8), and the medians are compared. CGAL's Garland-Heckbert
# collapse joins the rounds when libcgal-dev is installed (bench/cgal_gh_peer.cpp; it times the
# collapse alone, as the anchors do).
runs=${RUNS:-8}
peer=
if [ -f /usr/include/CGAL/Surface_mesh.h ] && [ -f /usr/include/eigen3/Eigen/Core ]; then
  echo "compiling the CGAL GH peer (about 30 s)..." >&2
  g++ -O3 -DNDEBUG -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 -std=c++17 -Wall -Wextra -Wno-maybe-uninitialized \
    "$root/bench/cgal_gh_peer.cpp" -o "$work/cgal_gh_peer" -lgmp -lmpfr && peer=$work/cgal_gh_peer
fi
for i in $(seq "$runs"); do
  for c in bending quadric; do
    "$bin" simplify "$data/bunny00.off" -o "$work/out.off" --ratio 0.1 --cost "$c" --threads 1 --samples 1000 \
      --json "$work/speed.json" > /dev/null
    python3 -c 'import json, sys; print(sys.argv[2], json.load(open(sys.argv[1]))["time_seconds"])' "$work/speed.json" "$c"
  done
  if [ -n "$peer" ]; then
    read -r seconds _ < <("$peer" "$data/bunny00.off" 0.1) && echo "cgal_gh $seconds"
  fi
done > "$work/speed.txt"
python3 - "$work/speed.txt" <<'PY'
import statistics, sys
times = {"bending": [], "quadric": [], "cgal_gh": []}
for line in open(sys.argv[1]):
    cost, seconds = line.split()
    times[cost].append(float(seconds))
b, q = statistics.median(times["bending"]), statistics.median(times["quadric"])
print()
print("Single-threaded, bunny00 to 10 %%, %d alternating rounds: bending median %.3f s (fastest %.3f), "
      "quadric median %.3f s; quadric / bending %.2f" % (len(times["bending"]), b, min(times["bending"]), q, q / b))
if times["cgal_gh"]:
    c = statistics.median(times["cgal_gh"])
    pairwise = statistics.median(x / y for x, y in zip(times["bending"], times["cgal_gh"]))
    print("CGAL GH (same rounds) median %.3f s; bending / CGAL GH %.2f (median of the rounds' ratios)" % (c, pairwise))
else:
    print("CGAL GH not timed: libcgal-dev is not installed")
PY

echo "| mesh | kept | cost | time (s) | faces | Hausdorff | RMS | min angle < 20° | radius ratio p95 | valid |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for m in bunny00 fandisk; do
  for r in 0.3 0.1; do
    for c in bending distance quadric; do row "$data/$m.off" "$r" "$c" "$m"; done
  done
done

# Scale: time per removed face at 1.2 M faces against 75 k (same cost, same ratio).
"$build/bin/subdivide_mesh" "$data/bunny00.off" "$work/bunny_x16.off" 2
for c in bending quadric; do row "$work/bunny_x16.off" 0.1 "$c" "bunny00 x16 (1.2 M)"; done
