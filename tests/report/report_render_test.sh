#!/usr/bin/env bash
# The pipeline's report.html and meshprep quality's page in a real browser: headless Chromium
# renders each to a PNG without a console error or a failed request, and the screenshot is not
# blank. Exits 77 (skipped) when Chromium is not installed.
# Usage: report_render_test.sh MESHPREP_BINARY SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIP: Chromium is not installed (apt-get install chromium; scripts/install-deps.sh does it)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# TetGen alone leaves a 5.5-degree sliver in the femur: the report is written, not FEM-ready (exit 1);
# its red headline is rendered too.
"$bin" pipeline "$src/examples/data/femur.off" -o femur --quiet 2> err.txt
[ $? -le 1 ] && [ -s femur/report.html ] || { bad "pipeline failed"; cat err.txt; }
"$bin" quality "$src/examples/data/femur.off" --html quality.html > /dev/null 2> err.txt || { bad "quality failed"; cat err.txt; }

# Chromium as the machine allows it (root, no GPU, no network): logging on stderr shows the page's
# console messages and failed loads.
render() {  # PAGE PNG
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --user-data-dir="$work/profile" \
    --hide-scrollbars --window-size=1280,3200 --enable-logging=stderr --v=0 \
    --screenshot="$work/$2" "file://$work/$1" > "$work/$2.log" 2>&1
}

for page in femur/report.html quality.html; do
  png=$(basename "$page" .html).png
  render "$page" "$png" || { bad "$page: Chromium exited $?"; tail -5 "$png.log"; continue; }
  [ -s "$png" ] && ok || { bad "$page: no screenshot"; continue; }
  if grep -E "CONSOLE|Uncaught|Failed to load|net::ERR" "$png.log" | grep -v "dbus" > problems.txt; then
    bad "$page: console errors or failed loads"
    cat problems.txt
  else
    ok
  fi
  # Not blank: the picture and the badges give many distinct colours.
  python3 - "$png" <<'PY' && ok || bad "$page: the screenshot looks blank"
import sys, zlib, struct
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat, width, height = 8, b"", 0, 0
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR": width, height, depth, colour = struct.unpack(">IIBB", body[:10])
    if kind == b"IDAT": idat += body
    pos += 12 + length
raw = zlib.decompress(idat)
assert width >= 1000 and height >= 1000, (width, height)
# Count distinct byte values in the first 800 rows' raw scanlines (filters included): a blank page
# compresses to almost nothing and uses a handful.
assert len(idat) > 50000, len(idat)
assert len(set(raw[: len(raw) // 4])) > 64
PY
done

echo "report_render: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
