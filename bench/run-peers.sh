#!/usr/bin/env bash
# Issue 50's comparisons in one go, each pair of runs alternating (A B A B ...) so that the
# machine's drift falls on both sides, and each ratio the median of the pairs' ratios:
#  1. simplify: bunny00 to 10 %, `meshprep simplify --threads 1` (its time_seconds) against CGAL's
#     Garland-Heckbert collapse (bench/cgal_gh_peer.cpp, the collapse alone), with both results'
#     Hausdorff distance to the input (meshprep quality OUT --reference IN);
#  2. enhance: every part of ../shared/data/cad/, `meshprep enhance --threads 1` (time_seconds)
#     against CGAL's isotropic remeshing (bench/cgal_remesh_peer.cpp) aimed at enhance's face count;
#  3. threads: quality, simplify --ratio 0.1, enhance and pipeline on the femur and on bunny00
#     Loop-subdivided twice (1.2 M faces; pipeline --ratio 0.1, and enhance only with
#     ENHANCE_LARGE=1: about 4 minutes a run), --threads 2 against --threads 1, wall time of the
#     whole process;
#  4. memory: peak resident memory per input face of `simplify --ratio 0.01` and `quality` on
#     bunny00 Loop-subdivided LEVEL times (default 2: 1.2 M faces; 3 gives 4.8 M), then SQRT3
#     times by sqrt(3) (default 0; LEVEL=2 SQRT3=2 gives issue 50's 10 M: 10.9 M faces), with 2 threads.
# The CGAL peers are compiled here when libcgal-dev is installed (sections 1 and 2 are skipped
# otherwise). Writes the tables to OUT (default ./peers.md) and prints them.
# Usage: [RUNS=5] [ONLY="simplify enhance threads memory"] [LEVEL=2] [SQRT3=0] [PARTS=N] [ENHANCE_LARGE=1]
#        bench/run-peers.sh [build-dir] [OUT]
# About 35 minutes in full with RUNS=5 on a 2-core machine (the threads section is half of it).
# shellcheck source-path=SCRIPTDIR
source "$(dirname "$0")/bench_setup.sh" "${1:-}" .
out=$(realpath -m "${2:-peers.md}")
runs=${RUNS:-5}
only=" ${ONLY:-simplify enhance threads memory} "
level=${LEVEL:-2}
sqrt3=${SQRT3:-0}
meshes=$root/../shared/data/meshes
cad=$root/../shared/data/cad
: > "$out"
say() { echo "$@" | tee -a "$out"; }

# json FILE KEY...: a value of a JSON file (nested keys).
json() { python3 -c 'import json, sys; v = json.load(open(sys.argv[1]))
for k in sys.argv[2:]: v = v[k]
print(v)' "$@"; }
# wall COMMAND...: runs it, prints its wall seconds (to the microsecond: /usr/bin/time gives
# hundredths, too coarse for a 30 ms run) and its peak KB (/usr/bin/time); exit 1 (written, not
# FEM-ready) counts as a run.
wall() {
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f "%M" -o "$work/time.txt" "$@" > /dev/null 2> "$work/stderr.txt" || not_fem_ready $?
  end=$(date +%s.%N)
  echo "$(python3 -c 'import sys; print("%.6f" % (float(sys.argv[2]) - float(sys.argv[1])))' "$start" "$end") $(tail -1 "$work/time.txt")"
}
# median_ratio FILE: FILE has lines "a b"; prints the median of a/b, then the medians of a and of b.
median_ratio() {
  python3 -c 'import statistics, sys
pairs = [tuple(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
print("%.3f %.3f %.3f" % (statistics.median(a / b for a, b in pairs), statistics.median(a for a, _ in pairs),
                          statistics.median(b for _, b in pairs)))' "$1"
}

cgal_flags=(-O3 -DNDEBUG -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 -std=c++17 -Wno-maybe-uninitialized -lgmp -lmpfr)
gh_peer=''
remesh_peer=''
if [[ $only == *" simplify "* || $only == *" enhance "* ]]; then
  if [ -f /usr/include/CGAL/Surface_mesh.h ]; then
    echo "compiling the CGAL peers (about a minute)..." >&2
    g++ "$root/bench/cgal_gh_peer.cpp" -o "$work/cgal_gh_peer" "${cgal_flags[@]}" && gh_peer=$work/cgal_gh_peer
    g++ "$root/bench/cgal_remesh_peer.cpp" -o "$work/cgal_remesh_peer" "${cgal_flags[@]}" && remesh_peer=$work/cgal_remesh_peer
  else
    say "CGAL peers skipped: libcgal-dev is not installed (sections 1 and 2)"
  fi
fi
say "meshprep $(git -C "$root" rev-parse --short HEAD), $(date -u +%Y-%m-%d), $(nproc) cores, $runs alternating pairs per ratio"

if [[ $only == *" simplify "* && -n $gh_peer ]]; then
  bunny=$meshes/bunny00.off
  for _ in $(seq "$runs"); do
    "$bin" simplify "$bunny" -o "$work/ours.off" --ratio 0.1 --threads 1 --json "$work/s.json" > /dev/null
    read -r cgal _ < <("$gh_peer" "$bunny" 0.1 "$work/cgal.off")
    echo "$(json "$work/s.json" time_seconds) $cgal"
  done > "$work/simplify.txt"
  read -r ratio ours cgal < <(median_ratio "$work/simplify.txt")
  fidelity() { "$bin" quality "$1" --reference "$bunny" --json "$work/q.json" > /dev/null || true; printf '%.3g' "$(json "$work/q.json" reference hausdorff_relative)"; }
  say
  say "| simplify bunny00 to 10 % | meshprep (s) | CGAL GH (s) | meshprep / CGAL | Hausdorff meshprep | Hausdorff CGAL |"
  say "| --- | ---: | ---: | ---: | ---: | ---: |"
  say "| one thread, $runs pairs | $ours | $cgal | **$ratio** | $(fidelity "$work/ours.off") | $(fidelity "$work/cgal.off") |"
fi

if [[ $only == *" enhance "* && -n $remesh_peer ]]; then
  say
  # The remeshing alone (JSON remesh.seconds) against the same CGAL run: what the rounds after it cost
  # is the rest of enhance's time. A part enhance does not remesh has no such ratio.
  say "| enhance (remeshing) | faces | meshprep (s) | CGAL remesh (s) | meshprep / CGAL | its remeshing alone (s) | remeshing / CGAL |"
  say "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
  parts=("$cad"/*.stl)
  [ -z "${PARTS:-}" ] || parts=("${parts[@]:0:$PARTS}")
  : > "$work/enhance_ratios.txt"
  : > "$work/remesh_ratios.txt"
  for part in "${parts[@]}"; do
    name=$(basename "$part" .stl)
    "$bin" convert "$part" -o "$work/in.off" > /dev/null
    : > "$work/pairs.txt"
    : > "$work/remesh_pairs.txt"
    for _ in $(seq "$runs"); do
      "$bin" enhance "$part" -o "$work/ours.ply" --threads 1 --json "$work/e.json" > /dev/null 2>&1 || true
      faces=$(json "$work/e.json" faces_after)
      read -r cgal _ < <("$remesh_peer" "$work/in.off" "$work/cgal.off" "$faces")
      echo "$(json "$work/e.json" time_seconds) $cgal" >> "$work/pairs.txt"
      echo "$(json "$work/e.json" remesh seconds) $cgal" >> "$work/remesh_pairs.txt"
    done
    read -r ratio ours cgal < <(median_ratio "$work/pairs.txt")
    echo "$ratio" >> "$work/enhance_ratios.txt"
    read -r remesh_ratio remesh _ < <(median_ratio "$work/remesh_pairs.txt")
    if [ "$(json "$work/e.json" remesh remeshed)" = True ]; then
      echo "$remesh_ratio" >> "$work/remesh_ratios.txt"
    else
      remesh='(none)' remesh_ratio=''
    fi
    say "| $name | $faces | $ours | $cgal | $ratio | $remesh | $remesh_ratio |"
  done
  median_of() { python3 -c 'import statistics, sys
print("%.2f" % statistics.median(float(l) for l in open(sys.argv[1])))' "$1"; }
  say "| **median over $(wc -l < "$work/enhance_ratios.txt") parts** | | | | **$(median_of "$work/enhance_ratios.txt")** | | **$(median_of "$work/remesh_ratios.txt")** ($(wc -l < "$work/remesh_ratios.txt") remeshed) |"
fi

large=$work/bunny_l${level}_s$sqrt3.off
if [[ $only == *" threads "* || $only == *" memory "* ]]; then
  "$build/bin/subdivide_mesh" "$meshes/bunny00.off" "$work/bunny_l2.off" 2
  [ "$level$sqrt3" = 20 ] || "$build/bin/subdivide_mesh" "$meshes/bunny00.off" "$large" "$level" "$sqrt3"
  [ "$level$sqrt3" != 20 ] || large=$work/bunny_l2.off
fi

if [[ $only == *" threads "* ]]; then
  say
  say "| 2 threads against 1 (wall, whole process) | input | 1 thread (s) | 2 threads (s) | speed-up |"
  say "| --- | --- | ---: | ---: | ---: |"
  for input in "$meshes/femur.off" "$work/bunny_l2.off"; do
    commands=(quality simplify enhance pipeline)
    # Enhancing 1.2 M faces takes about 4 minutes a run: only when asked.
    [ "$input" = "$meshes/femur.off" ] || [ -n "${ENHANCE_LARGE:-}" ] || commands=(quality simplify pipeline)
    for command in "${commands[@]}"; do
      case $command in
        quality) args=(quality "$input" --json "$work/t.json") ;;
        simplify) args=(simplify "$input" -o "$work/t.off" --ratio 0.1) ;;
        enhance) args=(enhance "$input" -o "$work/t.ply") ;;
        pipeline) args=(pipeline "$input" -o "$work/t" --quiet) ;;
      esac
      # The large mesh goes to tets at a tenth of its faces, as a user would take it.
      [ "$command" != pipeline ] || [ "$input" = "$meshes/femur.off" ] || args+=(--ratio 0.1)
      : > "$work/pairs.txt"
      for _ in $(seq "$runs"); do
        rm -rf "$work/t"
        read -r one _ < <(wall "$bin" "${args[@]}" --threads 1)
        rm -rf "$work/t"
        read -r two _ < <(wall "$bin" "${args[@]}" --threads 2)
        echo "$one $two" >> "$work/pairs.txt"
      done
      read -r ratio one two < <(median_ratio "$work/pairs.txt")
      say "| $command | $(basename "$input") | $one | $two | **${ratio}x** |"
    done
  done
fi

if [[ $only == *" memory "* ]]; then
  faces=$(awk 'NR > 1 && !/^#/ && NF { print $2; exit }' "$large")
  say
  say "| peak memory, 2 threads | input faces | peak (MB) | bytes per input face |"
  say "| --- | ---: | ---: | ---: |"
  for command in quality simplify; do
    case $command in
      quality) args=(quality "$large" --json "$work/t.json") ;;
      simplify) args=(simplify "$large" -o "$work/t.off" --ratio 0.01) ;;
    esac
    read -r _ peak_kb < <(wall "$bin" "${args[@]}" --threads 2)
    say "| $command | $faces | $((peak_kb / 1024)) | $((peak_kb * 1024 / faces)) |"
  done
fi
