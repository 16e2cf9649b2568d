#!/usr/bin/env bash
# The installed package works for another CMake project: `cmake --install` into a fresh prefix
# under the build directory must hold every module's static library and headers, the CLI and the
# package config (and the Python module, when built); tests/install_consumer, configured with only CMAKE_PREFIX_PATH pointing there,
# must find meshprep in that prefix (not in the source or build tree), build, and measure the
# bundled femur (7,798 faces, closed).
# Usage: install_consumer_test.sh CMAKE BUILD_DIR SOURCE_DIR MODULE_TARGETS (comma-separated)
set -euo pipefail
cmake=$1 build=$2 source=$3
IFS=, read -r -a modules <<< "$4"
work=$build/install_test
prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }

[ ${#modules[@]} -ge 4 ] || fail "only ${#modules[@]} modules registered: ${modules[*]}"
for target in "${modules[@]}"; do
  module=${target#meshprep_}
  compgen -G "$prefix/lib*/lib$target.a" > /dev/null || fail "lib$target.a not installed"
  compgen -G "$prefix/include/meshprep/$module/*.h" > /dev/null || compgen -G "$prefix/include/meshprep/$module/*/*.h" > /dev/null \
    || fail "no headers in include/meshprep/$module"
done
config=$(compgen -G "$prefix/lib*/cmake/meshprep" | head -1) || fail "no lib/cmake/meshprep"
for file in meshprepConfig.cmake meshprepConfigVersion.cmake meshprepTargets.cmake FindTetGen.cmake FindGMP.cmake; do
  [ -f "$config/$file" ] || fail "$file not installed"
done
"$prefix/bin/meshprep" --version > /dev/null || fail "the installed CLI does not run"
# The Python module, when it was built: installed into the prefix's Python folder, importable from there.
if [ -d "$build/python/meshprep" ]; then
  installed=$(compgen -G "$prefix/lib/python3*/*-packages/meshprep/__init__.py" | head -1) \
    || fail "the Python module is built but not installed"
  site=$(dirname "$(dirname "$installed")")
  (cd "$work" && PYTHONPATH=$site /usr/bin/python3 -c \
    "import sys, meshprep; assert meshprep.__file__.startswith(sys.argv[1]), meshprep.__file__" "$site") \
    || fail "the installed Python module does not import from $site"
fi

"$cmake" -S "$source/tests/install_consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON > "$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; fail "the consumer does not configure"; }
grep -q "^meshprep_DIR:PATH=$config\$" "$work/consumer/CMakeCache.txt" \
  || fail "meshprep found elsewhere: $(grep '^meshprep_DIR' "$work/consumer/CMakeCache.txt")"
"$cmake" --build "$work/consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "the consumer does not build"; }
python3 - "$work/consumer/compile_commands.json" "$source" "$prefix" <<'PY' || fail "the consumer sees the source tree's headers"
import json, shlex, sys
commands, source, prefix = json.load(open(sys.argv[1])), sys.argv[2] + "/", sys.argv[3] + "/"
for entry in commands:
    words = shlex.split(entry["command"])
    paths = [path for flag, path in zip(words, words[1:]) if flag in ("-I", "-isystem")]
    paths += [word[2:] for word in words if word.startswith("-I") and len(word) > 2]
    for path in paths:
        if path.startswith(source) and not path.startswith(prefix):
            sys.exit(f"include path {path}")
PY

output=$("$work/consumer/install_consumer" "$source/examples/data/femur.off") || fail "the consumer failed: $output"
echo "$output"
python3 - "$output" <<'PY' || fail "unexpected consumer output"
import sys
words = sys.argv[1].split()
values = dict(zip(words[::2], words[1::2]))
assert values["faces"] == "7798" and values["closed"] == "1", values
assert 1.0 <= float(values["radius_ratio_p95"]) < 100, values
PY
echo "install consumer: OK"
