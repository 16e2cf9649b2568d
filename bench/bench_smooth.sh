#!/usr/bin/env bash
# Smoothing side by side: meshprep's RBF smoothing (defaults and variants) and the in-tree Taubin
# and Laplace baselines in the same binary, on the noisy meshes of ../shared/data/meshes/noisy/ (the
# clean mesh plus Gaussian noise along the normals, 0.1 % of the diagonal). Distances are to the
# CLEAN mesh (meshprep quality --reference, / bbox diagonal); time is the smoothing itself
# (time_seconds, which includes the self-intersection checks), the best of 3 runs on 2 threads (a
# shared VM's timings vary by up to 1.5x). Usage: bench/bench_smooth.sh [build-dir]
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
    for run in 1 2 3; do
      # shellcheck disable=SC2086
      "$bin" smooth "$data/noisy/${mesh}_noisy.off" -o "$work/out.off" --json "$work/s$run.json" --threads 2 \
        --samples 1000 $args > /dev/null
    done
    "$bin" quality "$work/out.off" --reference "$clean" --json "$work/q.json" > /dev/null
    python3 - "$work" "$mesh" "${label//_/ }" <<'PY'
import json, sys
work = sys.argv[1]
runs = [json.load(open("%s/s%d.json" % (work, i))) for i in (1, 2, 3)]
s = runs[0]; q = json.load(open(work + "/q.json")); r = q["reference"]
print("| %s | %s | %.3g | %.3g | %.2g %% | %.3f | %.2f |" % (sys.argv[2], sys.argv[3], r["rms_relative"],
      r["hausdorff_relative"], 100 * s["volume_change_relative"], q["radius_ratio"]["p95"],
      min(run["time_seconds"] for run in runs)))
PY
  done <<'ROWS'
rbf_(defaults:_1_iteration)
rbf_--preserve-volume --preserve-volume
rbf_--relaxation_0_(along_the_normal_only) --relaxation 0
rbf_2_iterations --iterations 2
rbf_--smoothing_1_(thin-plate_smoothing_spline) --smoothing 1
taubin_10 --method taubin --iterations 10
taubin_30 --method taubin --iterations 30
laplace_3 --method laplace --iterations 3
ROWS
done
