# Shared by the CLI test scripts (sourced): a scratch folder removed on exit, pass/fail counters
# and the checks every script uses. err.txt holds the last command's stderr.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; cat err.txt 2>/dev/null; }
expect_exit() { [ "$2" = "$3" ] && ok || bad "$1: exit $3, expected $2"; }
