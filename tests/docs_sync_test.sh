#!/usr/bin/env bash
# The docs that the binary defines are current: docs/cli.md (every --help) and the key table of
# docs/pipeline.md. On failure, run scripts/update-docs.sh and commit the result.
# Usage: docs_sync_test.sh path/to/meshprep path/to/source
set -uo pipefail
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/docs" "$work/scripts"
cp "$src/docs/pipeline.md" "$work/docs/"
cp "$src/scripts/update-docs.sh" "$work/scripts/"
(cd "$work" && bash scripts/update-docs.sh "$bin") || { echo "FAIL: scripts/update-docs.sh failed"; exit 1; }
status=0
for doc in docs/cli.md docs/pipeline.md; do
  if ! diff -u "$src/$doc" "$work/$doc"; then
    echo "FAIL: $doc is stale: run scripts/update-docs.sh"
    status=1
  fi
done
[ $status -eq 0 ] && echo "docs/cli.md and docs/pipeline.md match the binary"
exit $status
