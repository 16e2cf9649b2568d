# Shared by the CLI test scripts (sourced): a scratch folder removed on exit, pass/fail counters
# and the checks every script uses. err.txt holds the last command's stderr.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; cat err.txt 2>/dev/null; }
expect_exit() { [ "$2" = "$3" ] && ok || bad "$1: exit $3, expected $2"; }
# Whether err.txt has the two lines of the verdict on cli_meshes.py's 2-degree sliver (one per
# failed threshold, figure against threshold).
has_sliver_verdict() {
  # The tet is the whole solid: each of its edges is a boundary edge of interior angle 2.005 or
  # 177.2 degrees, and the four sharp ones cap any tets of this surface (the improvement says so).
  grep -qx "meshprep: sliver.off: not FEM-ready: smallest dihedral angle 2.005 deg < 10 deg (min_dihedral_deg); the surface itself allows at most 2.005 deg: 4 boundary edge(s) too sharp, the first at (0, 0.5, 0.00875) with an interior angle of 2.005 deg" err.txt &&
    grep -qx "meshprep: sliver.off: not FEM-ready: largest dihedral angle 177.2 deg > 165 deg (max_dihedral_deg)" err.txt
}
# The stderr of the last command is one line holding $2 ($1 names the case).
one_line() { [ "$(wc -l < err.txt)" = 1 ] && grep -q "$2" err.txt && ok || bad "$1: expected one line with '$2'"; }
# Sets $py to a python3 that has meshio and numpy, or fails the script: Debian's python3-meshio
# serves /usr/bin/python3, not a venv's python3 first on PATH.
require_meshio_python() {
  py=
  for p in python3 /usr/bin/python3; do $p -c "import meshio, numpy" 2>/dev/null && { py=$p; return; }; done
  echo "FAIL: no python3 with meshio and numpy (scripts/install-deps.sh installs python3-meshio)"
  exit 1
}
