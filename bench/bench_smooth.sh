#!/usr/bin/env bash
# Smoothing side by side: meshprep's RBF smoothing (defaults) and the in-tree Taubin and Laplace
# baselines in the same binary, on the noisy meshes of ../shared/data/meshes/noisy/ (the clean
# mesh plus Gaussian noise along the normals, 0.1 % of the diagonal). Distances are to the CLEAN
# mesh (meshprep quality --reference, / bbox diagonal); time is the smoothing itself
# (time_seconds, which includes the self-intersection checks). Usage: bench/bench_smooth.sh [build-dir]
source "$(dirname "$0")/bench_setup.sh" "${1:-}" meshes/noisy

echo "| mesh | method | RMS to clean | Hausdorff to clean | volume change | radius ratio p95 | time (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for mesh in bunny fandisk; do
  clean=$data/$([ $mesh = bunny ] && echo bunny00 || echo fandisk).off
  "$bin" quality "$data/noisy/${mesh}_noisy.off" --reference "$clean" --json "$work/q.json" > /dev/null
  python3 - "$work/q.json" "$mesh" <<'PY'
import json, sys
q = json.load(open(sys.argv[1])); r = q["reference"]
print("| %s | noisy input | %.3g | %.3g | | %.3f | |" % (sys.argv[2], r["rms_relative"], r["hausdorff_relative"], q["radius_ratio"]["p95"]))
PY
  while read -r label args; do
    # shellcheck disable=SC2086
    "$bin" smooth "$data/noisy/${mesh}_noisy.off" -o "$work/out.off" --json "$work/s.json" $args > /dev/null
    "$bin" quality "$work/out.off" --reference "$clean" --json "$work/q.json" > /dev/null
    python3 - "$work/s.json" "$work/q.json" "$mesh" "$label" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); q = json.load(open(sys.argv[2])); r = q["reference"]
print("| %s | %s | %.3g | %.3g | %.2g %% | %.3f | %.2f |" % (sys.argv[3], sys.argv[4], r["rms_relative"],
      r["hausdorff_relative"], 100 * s["volume_change_relative"], q["radius_ratio"]["p95"], s["time_seconds"]))
PY
  done <<'ROWS'
rbf_(defaults)
rbf_--preserve-volume --preserve-volume
rbf_1_iteration --iterations 1
taubin_10 --method taubin --iterations 10
taubin_30 --method taubin --iterations 30
laplace_3 --method laplace --iterations 3
ROWS
done
