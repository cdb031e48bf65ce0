#!/usr/bin/env bash
# The office run the CLI tests share (a ctest fixture: one run instead of one per test, since
# office is the longest shipped scenario): `covsim run` with stderr in a file, not a terminal.
# Usage: office_run.sh COVSIM SOURCE DIR (writes DIR/office/ and DIR/office.err)
set -euo pipefail
covsim=$1 source=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
"$covsim" run "$source/scenarios/office.json" --out "$dir/office" > "$dir/office.out" \
  2> "$dir/office.err"
