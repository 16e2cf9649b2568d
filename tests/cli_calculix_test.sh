#!/usr/bin/env bash
# CalculiX (ccx, Debian's calculix-ccx) runs a static job on the .inp decks meshprep writes of the
# bundled examples' tets (fandisk, femur): calculix.py includes the deck, fixes a patch's node set,
# loads its surface and the regions, and checks exit 0, no *ERROR or *WARNING, a displacement for
# every node, the patch's reaction and one stress row per tet of its element set. The coordinates
# of fandisk's tets need 21-24 characters in round-trip form, which ccx 2.20 refused (exit 201):
# each field is checked to hold at most 20 and the rounding note to be printed.
# Skips (exit 77) when ccx is not on PATH.
# Usage: cli_calculix_test.sh MESHPREP_BINARY SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
here=$(cd "$(dirname "$0")" && pwd)
command -v ccx > /dev/null || { echo "SKIP: ccx is not on PATH (scripts/install-deps.sh installs calculix-ccx)"; exit 77; }
source "$here/cli_harness.sh"

# The longest field of the *NODE block.
longest_node_field() {
  awk -F', ' '/^\*/ { nodes = ($0 == "*NODE"); next } nodes { for (i = 1; i <= NF; ++i) if (length($i) > n) n = length($i) }
              END { print n + 0 }' "$1"
}

"$bin" tetrahedralize "$src/examples/data/fandisk.off" -o fandisk.inp > /dev/null 2> err.txt
expect_exit "tetrahedralize fandisk" 0 $?
grep -qE "^meshprep: note: fandisk.inp: [0-9]+ coordinates rounded to fit the format's 20-character fields \(relative error at most [0-9.e-]+\)$" err.txt &&
  ok || bad "fandisk: no note on the rounded coordinates"
[ "$(longest_node_field fandisk.inp)" -le 20 ] && ok || bad "fandisk.inp: a field of $(longest_node_field fandisk.inp) characters"
python3 "$here/calculix.py" fandisk.inp > ccx.txt 2>&1 && ok || bad "ccx on fandisk.inp: $(cat ccx.txt)"
cat ccx.txt

# TetGen's tets alone (--no-improve: the improvement's 20 s change no part of the deck); they miss
# the verdict (exit 1) and are written.
"$bin" tetrahedralize "$src/examples/data/femur.off" -o femur.inp --no-improve > /dev/null 2> err.txt
status=$?
[ "$status" -le 1 ] && [ -s femur.inp ] && ok || bad "tetrahedralize femur: exit $status"
[ "$(longest_node_field femur.inp)" -le 20 ] && ok || bad "femur.inp: a field of $(longest_node_field femur.inp) characters"
python3 "$here/calculix.py" femur.inp > ccx.txt 2>&1 && ok || bad "ccx on femur.inp: $(cat ccx.txt)"
cat ccx.txt

echo "cli_calculix: $passed passed, $failed failed"
[ "$failed" = 0 ]
