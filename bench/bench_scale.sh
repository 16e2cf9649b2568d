#!/usr/bin/env bash
# Scale and threads (issue #9): bunny00 Loop-subdivided 0-3 times (75 k to 4.8 M faces) through
# `meshprep quality`, `simplify --ratio 0.1`, `pipeline --ratio 0.1` (the tets grow with the
# input) and `pipeline --target-faces 7540` (the FEM mesh of bunny00 at 10 %, whatever the input's
# size), each timed as a user runs it (/usr/bin/time: wall time and peak memory of the whole
# process, reading and writing included). Prints per run the time and memory per input face, the
# growth of the time per face against the 75 k mesh (goal <= 1.5x) and the memory per face (goal
# < 1 KiB); then the speed-up of 2 threads over 1 on the 1.2 M mesh.
# Usage: bench/bench_scale.sh [build-dir] [max-level (default 3)] [command...]
#   (commands: quality simplify pipeline pipeline-fixed; default all)
source "$(dirname "$0")/bench_setup.sh" "${1:-}" meshes
max_level=${2:-3}
shift $(($# > 2 ? 2 : $#))
commands=("$@")
[ ${#commands[@]} -gt 0 ] || commands=(quality simplify pipeline pipeline-fixed)

mesh() { echo "$work/bunny_l$1.off"; }
cp "$data/bunny00.off" "$(mesh 0)"
for level in $(seq 1 "$max_level"); do "$build/bin/subdivide_mesh" "$data/bunny00.off" "$(mesh "$level")" "$level"; done

# measure COMMAND LEVEL THREADS: runs it and prints "faces wall_s peak_kb".
measure() {
  local command=$1 level=$2 threads=$3 input
  input=$(mesh "$level")
  case $command in
    quality) set -- quality "$input" --json "$work/out.json" ;;
    simplify) set -- simplify "$input" -o "$work/out.off" --ratio 0.1 --json "$work/out.json" ;;
    pipeline) set -- pipeline "$input" -o "$work/out" --ratio 0.1 --quiet --json "$work/out.json" ;;
    pipeline-fixed) set -- pipeline "$input" -o "$work/out" --target-faces 7540 --quiet --json "$work/out.json" ;;
  esac
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$bin" "$@" --threads "$threads" > /dev/null || not_fem_ready $?
  echo "$(awk 'NR > 1 && !/^#/ && NF { print $2; exit }' "$input") $(tail -1 "$work/time.txt")"  # time's last line: a non-zero exit adds one before
}

echo "| command | faces | wall (s) | µs per face | growth vs 75 k | peak memory | bytes per face | stages (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for command in "${commands[@]}"; do
  base=
  for level in $(seq 0 "$max_level"); do
    read -r faces wall peak_kb < <(measure "$command" "$level" 2)
    per_face=$(python3 -c "print($wall / $faces * 1e6)")
    [ -n "$base" ] || base=$per_face
    python3 - "$work/out.json" <<PY
import json, sys
stages = ""
if "$command".startswith("pipeline"):
    j = json.load(open(sys.argv[1]))
    stages = ", ".join("%s %.1f" % (s["name"], s["seconds"]) for s in j["stages"] if s["ran"])
    stages += "; %d tets" % j["tets"]["tet_quality"]["tetrahedra"]
print('| $command | {:,} | {:.2f} | {:.2f} | {:.2f}x | {:.0f} MB | {:.0f} | {} |'.format(
    $faces, $wall, $per_face, $per_face / $base, $peak_kb / 1024, $peak_kb * 1024 / $faces, stages))
PY
  done
done

echo
echo "| command (1.2 M faces) | 1 thread (s) | 2 threads (s) | speed-up |"
echo "| --- | --- | --- | --- |"
level=$((max_level < 2 ? max_level : 2))
for command in "${commands[@]}"; do
  read -r _ one _ < <(measure "$command" "$level" 1)
  read -r _ two _ < <(measure "$command" "$level" 2)
  python3 -c "print('| $command | {:.2f} | {:.2f} | {:.2f}x |'.format($one, $two, $one / $two))"
done
