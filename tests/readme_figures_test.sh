#!/usr/bin/env bash
# The figures the README and docs quote from the bundled examples are what the code gives now:
# the examples of examples/pipeline_examples.txt run as scripts/run-example.sh runs them, and
# every figure marked <!--fig:NAME--> in README.md and docs/*.md is compared with the run at the
# precision quoted (scripts/doc-figures.py). On failure, run the examples and
# `python3 scripts/doc-figures.py out --update README.md docs/*.md`, and read the prose around.
# Usage: readme_figures_test.sh MESHPREP_BINARY SOURCE_DIR
set -uo pipefail
bin=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$src"
while read -r -a line; do
  [ ${#line[@]} -eq 0 ] || [[ ${line[0]} == \#* ]] && continue
  name=${line[0]}
  "$bin" pipeline "${line[@]:1}" -o "$work/$name" --quiet < /dev/null 2> "$work/$name.err"
  status=$?
  # 0 FEM-ready, 1 written but not ready: both are results the README may quote.
  if [ $status -gt 1 ] || [ ! -s "$work/$name/report.json" ]; then
    echo "FAIL: the example $name exits $status"; cat "$work/$name.err"; exit 1
  fi
done < examples/pipeline_examples.txt
python3 scripts/doc-figures.py "$work" --check README.md docs/*.md
