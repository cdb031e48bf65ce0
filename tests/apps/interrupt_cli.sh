#!/usr/bin/env bash
# SIGINT and SIGTERM stop a run or a sweep at the next event, leave no partial file and no
# folder a run created (a run folder is written as DIR.partial and appears whole at the end,
# over an existing one by an atomic exchange), and exit 130 / 143; the interrupted sweep
# resumes to the same results; a run replaces an earlier run in its folder whole.
# Usage: interrupt_cli.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
office="$source/scenarios/office.json"
# An interrupted run is made long on any machine (finer motion steps): office alone converges
# in about a second on a fast one, which may be before the signal.
long="--set loops.loop2_period=0.02"

# Sends SIG to a command once its folder shows it has started; prints its exit code.
interrupt() {  # SIG WAIT-FOR ARGS...
  local sig=$1 wait_for=$2; shift 2
  "$covsim" "$@" > out.txt 2> err.txt &
  local pid=$! k=0
  until [ -e "$wait_for" ] || [ $k -ge 200 ]; do sleep 0.05; k=$((k + 1)); done
  sleep 0.3
  kill -"$sig" $pid
  set +e; wait $pid; local rc=$?; set -e
  echo $rc
}

rc=$(interrupt TERM run1.partial/trajectory.csv.partial run "$office" --out run1 $long)
[ "$rc" -eq 143 ] || fail "SIGTERM: exit $rc: $(cat err.txt)"
grep -q "interrupted by SIGTERM" err.txt || fail "no message: $(cat err.txt)"
[ ! -e run1 ] && [ ! -e run1.partial ] || fail "an interrupted run left its folder: $(ls -d run1*)"
# Uninterrupted, the folder appears whole, and only at the end.
"$covsim" run "$office" --out run3 --set convergence.max_time=200 > /dev/null &
pid=$!
k=0
until [ -e run3.partial ] || [ $k -ge 200 ]; do sleep 0.05; k=$((k + 1)); done
[ ! -e run3 ] || fail "run3 appeared before the run ended"
wait $pid
[ -f run3/final.json ] && [ -f run3/trajectory.csv ] && [ ! -e run3.partial ] ||
  fail "run3 did not appear whole: $(ls -d run3*)"

# Into an existing folder: an interrupted run leaves it exactly as it was (its run, the
# user's files), and no partial file anywhere.
"$covsim" run "$office" --out run2 --set convergence.max_time=20 > /dev/null
echo keep > run2/notes.txt
before=$(cd run2 && ls && cat final.json scenario.json | md5sum)
echo stale > run2/final.json.partial  # what a killed `covsim plot` leaves
rc=$(interrupt INT run2.partial/trajectory.csv.partial run "$office" --out run2 \
  $long)
[ "$rc" -eq 130 ] && grep -q "interrupted by SIGINT" err.txt || fail "SIGINT: exit $rc: $(cat err.txt)"
[ -z "$(find . -name '*.partial')" ] || fail "partial files left: $(find . -name '*.partial')"
[ "$(cd run2 && ls && cat final.json scenario.json | md5sum)" = "$before" ] ||
  fail "the interrupted run changed the folder it was to replace: $(ls run2)"
# Completed, a run replaces the earlier run whole: its figures in another format go, the
# user's file stays, every run file is the new run's.
"$covsim" run "$office" --out run2 --set convergence.max_time=40 --format png > new.txt
[ -f run2/scene.png ] && [ ! -e run2/scene.svg ] && [ ! -e run2/cost.svg ] ||
  fail "the earlier run's figures stayed: $(ls run2)"
[ "$(cat run2/notes.txt)" = keep ] || fail "the folder's own file went"
fp=$(sed -n 's/^fingerprint //p' new.txt)
grep -q "\"fingerprint\": \"$fp\"" run2/final.json || fail "final.json is not the new run's"
awk -F, 'NR > 1 && $1 > 30 { found = 1 } END { exit !found }' run2/trajectory.csv ||
  fail "trajectory.csv is the earlier run's (20 s, not 40 s)"
[ ! -e run2.partial ] && [ ! -e run2.replaced ] || fail "staging folders left: $(ls -d run2*)"

# A sweep stops, keeps whole results only, and resumes to what an uninterrupted one gives.
cat > sweep.json <<JSON
{"scenario": "$office", "grid": {"convergence.max_time": [400]}, "seeds": [1, 2, 3, 4]}
JSON
rc=$(interrupt INT s sweep sweep.json --out s --jobs 2)
[ "$rc" -eq 130 ] && grep -q "interrupted by SIGINT" err.txt ||
  fail "sweep SIGINT: exit $rc: $(cat err.txt)"
[ -z "$(find s -name '*.partial')" ] || fail "sweep left partial files: $(find s)"
for f in s/runs/*.json; do
  [ -e "$f" ] || continue
  /usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert "error" not in r or not r["error"], r' "$f" ||
    fail "an interrupted run was recorded as failed: $(cat "$f")"
done
"$covsim" sweep sweep.json --out s --jobs 2 > /dev/null 2>&1
"$covsim" sweep sweep.json --out whole --jobs 2 > /dev/null 2>&1
/usr/bin/python3 - s/runs.csv whole/runs.csv <<'PY' || fail "the resumed sweep differs"
import csv, sys
clock = {"wall_time", "planner_step_time"}
a, b = ([{k: v for k, v in r.items() if k not in clock} for r in csv.DictReader(open(f))]
        for f in sys.argv[1:])
assert len(a) == 4 and a == b, (a, b)
PY
# Checking a large grid before anything runs stops at SIGINT too, within seconds (20 000
# settings of the office scenario take about a minute to check).
ranges=$(seq -s, 1 200)
speeds=$(awk 'BEGIN { for (k = 1; k <= 100; ++k) printf "%s%g", (k > 1 ? "," : ""), k / 1000 }')
printf '{"scenario": "%s", "grid": {"sensor.range": [%s], "robots.max_speed": [%s]}, "seeds": [1]}\n' \
  "$office" "$ranges" "$speeds" > big.json
"$covsim" sweep big.json --out big > out.txt 2> err.txt &
pid=$!
sleep 2
kill -INT $pid
signalled=$(date +%s)
set +e; wait $pid; rc=$?; set -e
[ "$rc" -eq 130 ] && grep -q "interrupted by SIGINT" err.txt ||
  fail "SIGINT while a sweep is checked: exit $rc: $(tail -2 err.txt)"
[ $(( $(date +%s) - signalled )) -le 5 ] ||
  fail "the sweep took $(( $(date +%s) - signalled )) s to stop after SIGINT"
[ ! -e big/sweep.json ] || fail "the check was over before the signal: make the grid larger"
echo "interrupts ok"
