#!/usr/bin/env bash
# Two writers of one output folder: the second run, sweep or merge exits 2 at once naming the
# folder and the first's process id, and leaves the folder alone; killing the first with
# SIGKILL leaves no stale lock.
#   output_lock_cli.sh COVSIM SOURCE_DIR WORK_DIR
set -euo pipefail
covsim=$1 src=$2 work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
# A long run (office for a simulated hour) holds "same".
"$covsim" run "$src/scenarios/office.json" --out same --set convergence.max_time=3600 \
  >/dev/null 2>first.txt &
first=$!
trap 'kill -9 $first 2>/dev/null || true' EXIT
for _ in $(seq 1 300); do
  [ -s .same.lock ] && [ "$(cat .same.lock)" = "$first" ] && break
  kill -0 $first 2>/dev/null || fail "the first run ended early: $(cat first.txt)"
  sleep 0.1
done
[ "$(cat .same.lock)" = "$first" ] || fail ".same.lock does not name the first run ($first)"
expect_refused() {  # what, then the command
  local what=$1; shift
  set +e; "$@" >/dev/null 2>err.txt; local rc=$?; set -e
  [ $rc -eq 2 ] || fail "$what: expected exit 2, got $rc: $(cat err.txt)"
  grep -q "same: another covsim (process $first) is writing this folder" err.txt ||
    fail "$what: the message names neither the folder nor process $first: $(cat err.txt)"
}
expect_refused "a second run" "$covsim" run "$src/scenarios/u_shape.json" --out same
[ ! -e same ] || fail "the refused run wrote same/"
cat > sweep.json <<JSON
{"scenario": "$src/scenarios/u_shape.json", "seeds": [1], "grid": {"sensor.range": [2.0]}}
JSON
expect_refused "a sweep" "$covsim" sweep sweep.json --out same
[ ! -e same ] || fail "the refused sweep wrote same/"
"$covsim" sweep sweep.json --out shard >/dev/null
expect_refused "a merge" "$covsim" merge shard --out same
[ ! -e same ] || fail "the refused merge wrote same/"
# SIGKILL: the kernel releases the lock; the next run takes it.
kill -9 $first; wait $first 2>/dev/null || true
"$covsim" run "$src/scenarios/u_shape.json" --out same >/dev/null 2>err.txt ||
  fail "after the holder was killed: $(cat err.txt)"
[ -f same/final.json ] || fail "the run after the kill wrote no final.json"
echo "ok"
