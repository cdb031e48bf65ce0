#!/usr/bin/env bash
# A long run on a terminal shows a progress line on stderr and clears it when the run ends or is
# stopped; with stderr in a file it writes none. The terminal is a pseudo-terminal from util-linux's
# `script`; without it the test is skipped (exit 77) and says why.
# Usage: progress_cli.sh COVSIM SOURCE WORK OFFICE_RUN (office_run.sh's folder: the same run
# with stderr in a file)
set -euo pipefail
covsim=$1 source=$2 work=$3 office_run=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v script > /dev/null || { echo "SKIP: util-linux's script is not installed"; exit 77; }
# A run long on any machine (finer motion steps, tolerances it settles to late), stopped by
# SIGTERM once its line shows: the line is cleared before what the run prints last. (A fixed
# run is not long enough everywhere: office converges in a second on a fast machine.)
long="--set loops.loop2_period=0.02 --set convergence.position_tolerance=1e-9"
long="$long --set convergence.virtual_tolerance=1e-9"
script -qfec "$covsim run $source/scenarios/office.json --out $work/tty $long" typescript \
  > /dev/null &
k=0
until grep -q "run: t = " typescript 2> /dev/null || [ $k -ge 1200 ]; do
  sleep 0.05
  k=$((k + 1))
done
# (To covsim itself: `script` ends its session on a signal.)
pkill -TERM -f "^$covsim run .* --out $work/tty " || true
wait
grep -q "run: t = .* of 4000 s simulated (.*%), .*/30 robots settled, [0-9]* s, at most [0-9]* s more at this pace" typescript ||
  fail "no progress line on a terminal: $(tr '\r' '\n' < typescript | head -5)"
# Cleared before the last message: that starts its line after a carriage return.
tr '\r' '\n' < typescript | grep -Eq "^(converged after|covsim: interrupted by SIGTERM)" ||
  fail "the progress line was not cleared: $(tr '\r' '\n' < typescript | tail -3)"
# (A sanitizer's report may be there; the progress line may not.)
err="$office_run/office.err"
[ -f "$err" ] || fail "no $err: the office run fixture did not run"
! grep -q "run: t =" "$err" || fail "progress written to a file: $(head -c 200 "$err")"
echo "progress ok"
