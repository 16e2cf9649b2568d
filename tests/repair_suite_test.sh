#!/usr/bin/env bash
# The generated dirty soups of issue 48 (tests/dirty_cases.py --quick: two of each of 11 kinds from
# the bundled meshes) through `pipeline --repair`. Every run ends by itself with a code of the
# contract (0 ready, 1 written but not ready, 2 bad input, 3 what the repair could not mend; never a
# signal or the time limit); a failure leaves one line naming the case and no output; a run that
# writes leaves its tets. Every kind is mended (the surface closed, manifold, free of crossings:
# exit 0 or 1; the exact cut's leftovers on CAD overlaps by the envelope route), and unwelded,
# flipped, duplicate and internal faces are FEM-ready; the others' tets are the issue's work
# (bench/RESULTS.md, "Repair suite", "Envelope route").
# Usage: repair_suite_test.sh MESHPREP SOURCE_DIR
bin=$1 src=$2
. "$(dirname "$0")/cli_harness.sh"
/usr/bin/python3 "$src/tests/dirty_cases.py" cases --quick > /dev/null || { echo "FAIL: dirty_cases.py"; exit 1; }
for case in cases/*.off cases/*.stl; do
  name=$(basename "${case%.*}") kind=${name%%-*}
  timeout 300 "$bin" pipeline "$case" -o "out/$name" --repair --threads 1 --quiet > /dev/null 2> err.txt
  rc=$?
  case $rc in
    0 | 1) [ -s "out/$name/tets.msh" ] && ok || bad "$name: exit $rc without its tets" ;;
    2 | 3)
      [ ! -e "out/$name" ] && ok || bad "$name: exit $rc left out/$name"
      one_line "$name: exit $rc" "^meshprep: \(error\|failed\): .*$name" ;;
    *) bad "$name: exit $rc (a signal or the time limit)" ;;
  esac
  case $kind in
    unwelded | flipped | duplicate | internal) expect_exit "$name, a kind the repair mends" 0 $rc ;;
    # Mended too, but example004's own edges (9.8 deg) keep its tets under the verdict's 10 deg,
    # and the improvement stops short on some overlaps.
    *) { [ $rc = 0 ] || [ $rc = 1 ]; } && ok || bad "$name: exit $rc, the surface not mended" ;;
  esac
done
echo "repair_suite: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
