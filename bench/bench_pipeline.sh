#!/usr/bin/env bash
# The whole pipeline (issue #8), timed as a user runs it: `meshprep pipeline` on bunny00 -> 10 %
# -> tets, and on the bundled Jacksboro points -> terrain -> simplified -> block tets, three runs
# each. Prints per run the wall time of the whole process (reading and every output file
# included, /usr/bin/time), peak memory, the run's own time (time_seconds) and each stage's time.
# Usage: bench/bench_pipeline.sh [build-dir]
source "$(dirname "$0")/bench_setup.sh" "${1:-}" meshes

echo "| input | run | wall (s) | peak memory | pipeline (s) | stages (s) | faces out | tets | Hausdorff |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
while read -r label input options; do
  for run in 1 2 3; do
    # shellcheck disable=SC2086 # options are words
    /usr/bin/time -f "%e %M" -o "$work/time.txt" "$bin" pipeline "$input" -o "$work/out" $options --quiet \
      --json "$work/summary.json" || not_fem_ready $?
    python3 - "$label" "$run" "$work/time.txt" "$work/summary.json" <<'PY'
import json, sys
label, run, timing, summary = sys.argv[1:5]
wall, peak_kb = open(timing).read().split()[-2:]  # after "Command exited with non-zero status 1"
j = json.load(open(summary))
stages = ", ".join("%s %.2f" % (s["name"], s["seconds"]) for s in j["stages"] if s["ran"])
q = j["quality"]
print("| %s | %s | %s | %.0f MB | %.2f | %s | %d | %d | %.2e |" % (
    label, run, wall, int(peak_kb) / 1024, j["time_seconds"], stages, q["faces"],
    j["tets"]["tet_quality"]["tetrahedra"], q["reference"]["hausdorff_relative"]))
PY
  done
done <<EOF_INPUTS
bunny00_10% $data/bunny00.off --ratio 0.1
jacksboro_10k $root/examples/data/jacksboro_10k.xyz
EOF_INPUTS
