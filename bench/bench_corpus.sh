#!/usr/bin/env bash
# The corpus bench of issue 32: the surface stages on every mesh we did not tune on, with defaults.
# For every mesh at the top level of ../shared/data/cad/*.stl, corpus/*.off and meshes/*.off:
#  - `meshprep quality IN`: the input's faces, closed, self-intersections, share of faces with a
#    min angle < 20°, radius ratio p95;
#  - `meshprep enhance IN -o OUT` (defaults): the same shape figures of OUT, Hausdorff distance (both
#    ways, / the input's bbox diagonal) and volume change against the input (enhance's own quality
#    section, 1 M samples), faces before/after, time_seconds;
#  - CGAL's isotropic remeshing (bench/cgal_remesh_peer.cpp, compiled here when libcgal-dev is
#    installed; uniform target edge chosen for enhance's face count, as issue 32's time goal asks
#    (the input's mean edge when enhance failed), 3 iterations, edges > 45° constrained, one
#    thread, the remeshing alone timed), measured by `meshprep quality OUT --reference IN`;
#  - `meshprep pipeline IN -o DIR` (defaults): exit code, fem_ready, the final surface's figures, the
#    tets' smallest dihedral, self-intersections; a refusal (exit 1/2 without tets) is a row with
#    its first error line; PIPELINE_TIMEOUT seconds (default 600) at most per mesh (--timeout);
#  - smoothing, on each closed mesh without self-intersections of meshes/ and corpus/: seeded noisy
#    copies (vertices moved along their area-weighted normals by a Gaussian of sigma = 0.1 % and
#    0.2 % of the bbox diagonal, the seed from the mesh's name), smoothed by `meshprep smooth` with
#    its defaults (rbf) and with `--method taubin --iterations 10`; RMS distance to the CLEAN mesh
#    (`meshprep quality OUT --reference CLEAN`, rms_relative) of the noisy copy and of each result.
# Every exit code is recorded; no mesh stops the script. One meshprep process at a time, each with
# --threads 1. Writes one CSV row per mesh (CSV, default ./bench_corpus.csv, and the table beside it
# as .md), then prints one Markdown table: median and worst of each figure for cad, corpus, meshes
# (the worst with its mesh), counts of meshes, refusals and fem_ready.
# Usage: [SETS="cad corpus meshes"] [LIMIT=N] [PIPELINE_TIMEOUT=600] [ONLY=smooth] bench/bench_corpus.sh [build-dir] [csv]
#   LIMIT=N takes the first N meshes of each set (a trial run). ONLY=smooth runs the input's quality
#   and the smoothing rows only (no enhance, CGAL or pipeline; about 8 minutes with SETS="corpus meshes"). About 47 minutes in full with
#   PIPELINE_TIMEOUT=180 (the CAD parts' pipelines are most of it: 8 of them time out).
# shellcheck source-path=SCRIPTDIR
source "$(dirname "$0")/bench_setup.sh" "${1:-}" .
data=$root/../shared/data
csv=$(realpath -m "${2:-bench_corpus.csv}")
helper=$root/bench/corpus_table.py
py=python3
python3 -c 'import numpy' 2> /dev/null || py=/usr/bin/python3  # a pyenv python may lack numpy
"$py" -c 'import numpy' 2> /dev/null || { echo "numpy is missing: the smoothing rows are skipped" >&2; py=; }

peer=
if [ "${ONLY:-}" = smooth ]; then
  :  # smoothing rows only: no peer to compile
elif [ -f /usr/include/CGAL/Polygon_mesh_processing/remesh.h ] && [ -f /usr/include/eigen3/Eigen/Core ]; then
  echo "compiling the CGAL isotropic remeshing peer (about 30 s)..." >&2
  g++ -O3 -DNDEBUG -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 -std=c++17 -Wall -Wextra -Wno-maybe-uninitialized \
    "$root/bench/cgal_remesh_peer.cpp" -o "$work/cgal_remesh_peer" -lgmp -lmpfr && peer=$work/cgal_remesh_peer
else
  echo "CGAL peer skipped: libcgal-dev is not installed" >&2
fi

# run NAME COMMAND...: run it, its exit code to $dir/NAME.rc, its stderr to $dir/NAME.err.
run() {
  local name=$1 rc=0
  shift
  "$@" > /dev/null 2> "$dir/$name.err" || rc=$?
  echo "$rc" > "$dir/$name.rc"
  return 0
}
# field JSON KEY...: a value of a JSON file (nested keys), or nothing.
field() {
  python3 - "$@" <<'PY' 2> /dev/null || true
import json, sys
v = json.load(open(sys.argv[1]))
for k in sys.argv[2:]:
    v = v[k]
print(v)
PY
}

"$py" "$helper" header > "$csv"
start=$SECONDS
for set in ${SETS:-cad corpus meshes}; do
  [ -d "$data/$set" ] || { echo "skipped: $data/$set not found" >&2; continue; }
  ext=$([ "$set" = cad ] && echo stl || echo off)
  n=0
  for input in "$data/$set"/*."$ext"; do
    n=$((n + 1))
    [ -n "${LIMIT:-}" ] && [ "$n" -gt "$LIMIT" ] && break
    mesh=$(basename "$input")
    dir=$work/$set/${mesh%.*}
    mkdir -p "$dir"
    echo "[$((SECONDS - start)) s] $set/$mesh" >&2
    run q "$bin" quality "$input" --json "$dir/q.json" --threads 1
    [ "${ONLY:-}" = smooth ] || run e "$bin" enhance "$input" -o "$dir/enhanced.off" --json "$dir/e.json" --threads 1
    if [ -n "$peer" ]; then
      run convert "$bin" convert "$input" "$dir/in.off"
      rc=0
      faces=$(field "$dir/e.json" faces_after)
      "$peer" "$dir/in.off" "$dir/cgal.off" ${faces:+"$faces"} > "$dir/c.txt" 2> "$dir/c.err" || rc=$?
      echo "$rc" > "$dir/c.rc"
      [ "$rc" != 0 ] || run cq "$bin" quality "$dir/cgal.off" --reference "$dir/in.off" --json "$dir/cq.json" --threads 1
    fi
    [ "${ONLY:-}" = smooth ] || run p "$bin" pipeline "$input" -o "$dir/pipeline" --json "$dir/p.json" --quiet \
      --threads 1 --timeout "${PIPELINE_TIMEOUT:-600}"
    rm -rf "$dir/pipeline"
    if [ -n "$py" ] && [ "$set" != cad ] && [ "$(field "$dir/q.json" closed)" = True ] &&
      [ "$(field "$dir/q.json" self_intersections)" = 0 ]; then
      seed=$(cksum <<< "$set/$mesh" | cut -d' ' -f1)
      for s in 1 2; do
        noisy=$dir/noisy$s.off
        "$py" "$helper" noise "$input" "$noisy" "0.00$s" "$((seed + s))"
        run s${s}_noisy_q "$bin" quality "$noisy" --reference "$input" --json "$dir/s${s}_noisy.json" --threads 1
        for method in rbf taubin; do
          args=()
          [ "$method" = taubin ] && args=(--method taubin --iterations 10)
          run "s${s}_$method" "$bin" smooth "$noisy" -o "$dir/s${s}_$method.off" --samples 1000 --threads 1 "${args[@]}"
          [ "$(cat "$dir/s${s}_$method.rc")" != 0 ] ||
            run "s${s}_${method}_q" "$bin" quality "$dir/s${s}_$method.off" --reference "$input" \
              --json "$dir/s${s}_$method.json" --threads 1
        done
      done
    fi
    "$py" "$helper" row "$dir" "$set" "$mesh" >> "$csv"
    rm -f "$dir"/*.off
  done
done

echo "$((SECONDS - start)) s for $(($(wc -l < "$csv") - 1)) meshes" >&2
"$py" "$helper" table "$csv" | tee "${csv%.csv}.md"
echo
echo "per-mesh figures: $csv (the table: ${csv%.csv}.md)"
