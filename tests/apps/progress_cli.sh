#!/usr/bin/env bash
# A long run on a terminal shows a progress line on stderr and clears it at the end; with
# stderr in a file it writes none. The terminal is a pseudo-terminal from util-linux's
# `script`; without it the test is skipped (exit 77) and says why.
# Usage: progress_cli.sh COVSIM SOURCE WORK OFFICE_RUN (office_run.sh's folder: the same run
# with stderr in a file)
set -euo pipefail
covsim=$1 source=$2 work=$3 office_run=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v script > /dev/null || { echo "SKIP: util-linux's script is not installed"; exit 77; }
# office's run lasts a few seconds: longer than the first quiet second.
script -qec "$covsim run $source/scenarios/office.json --out tty" typescript > /dev/null
grep -q "run: t = .* of 4000 s simulated (.*%), .*/30 robots settled" typescript ||
  fail "no progress line on a terminal: $(tr '\r' '\n' < typescript | head -5)"
# Cleared before the summary: the summary starts its line after a carriage return.
tr '\r' '\n' < typescript | grep -q "^converged after" || fail "the progress line was not cleared"
# (A sanitizer's report may be there; the progress line may not.)
err="$office_run/office.err"
[ -f "$err" ] || fail "no $err: the office run fixture did not run"
! grep -q "run: t =" "$err" || fail "progress written to a file: $(head -c 200 "$err")"
echo "progress ok"
