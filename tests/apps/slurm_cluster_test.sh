#!/usr/bin/env bash
# docs/cluster.md's Slurm job scripts, taken from the page itself, run on a single-node Slurm
# (scripts/slurm-local): an array of 4 shards and the dependent merge must give the rows of
# the same sweep run locally. Exits 77 (skipped) where Slurm cannot run.
# Usage: slurm_cluster_test.sh COVSIM SOURCE_DIR WORK_DIR
set -euo pipefail
covsim=$(realpath "$1")
src=$(realpath "$2")
work=$3
limit=600  # seconds for the jobs
# Columns that hold wall-clock times (docs/sweeps.md), in runs.csv and as summary.csv prefixes.
clock_columns="wall_time planner_step_time"

skip() { echo "skipped: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "not root (slurmd runs jobs as their users)"
export PATH=$PATH:/usr/sbin:/sbin
for cmd in munged slurmctld slurmd sbatch; do
  [ -x "$(command -v "$cmd")" ] || skip "$cmd not found: the Debian packages slurm-wlm and munge are needed"
done
# Settings from a surrounding Slurm job or the caller's shell must not reach sbatch.
while read -r v; do unset "$v"; done < <(compgen -e | grep -E '^(SLURM|SBATCH)_')

# One run at a time on the machine's one local cluster.
exec 9>>/tmp/covsim-slurm-test.lock
flock -w "$limit" 9 || fail "another run of this test held the lock for ${limit}s"

rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
cd "$work"

extract() {  # name: the code block just after `<!-- extract: name -->` in docs/cluster.md
  awk -v mark="<!-- extract: $1 -->" '
    $0 == mark { marks++; want = 1; next }
    want && /^```/ { if (inside) { want = 0; inside = 0 } else inside = 1; next }
    inside { print }
    END { if (marks != 1) exit 1 }' "$src/docs/cluster.md" >"$1" ||
    fail "docs/cluster.md must mark exactly one block <!-- extract: $1 -->"
  [ -s "$1" ] || fail "the block marked $1 in docs/cluster.md is empty"
}
extract sweep.sbatch
extract merge.sbatch

started=0
jobs=()
cleanup() {
  if [ "$started" -eq 1 ]; then
    "$src/scripts/slurm-local" stop || true
  elif [ ${#jobs[@]} -gt 0 ]; then
    scancel "${jobs[@]}" 2>/dev/null || true
  fi
}
trap cleanup EXIT
trap 'exit 1' INT TERM

if ! "$src/scripts/slurm-local" status 2>/dev/null; then
  started=1
  if ! "$src/scripts/slurm-local" >slurm-local.out 2>slurm-local.err; then
    cat slurm-local.err
    started=0  # slurm-local stops what it started when it fails
    skip "scripts/slurm-local could not start Slurm: $(tail -n 1 slurm-local.err)"
  fi
fi
export SLURM_CONF
SLURM_CONF=$("$src/scripts/slurm-local" | sed -n 's/^export SLURM_CONF=//p')
[ -n "$SLURM_CONF" ] || fail "scripts/slurm-local printed no SLURM_CONF"
logs_dir=$(dirname "$SLURM_CONF")/log

cat >sweep.json <<EOF
{"scenario": "$src/scenarios/u_shape.json",
 "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.3]},
 "seeds": {"count": 4}}
EOF

# As docs/cluster.md submits them, with 4 shards of 1 thread to fit this machine.
PATH=$(dirname "$covsim"):$PATH
export SWEEP=$work/sweep.json OUT=$work/results
mkdir -p logs
array=$(sbatch --parsable --array=0-3 --cpus-per-task=1 sweep.sbatch)
array=${array%%;*}
jobs+=("$array")
merge=$(sbatch --parsable --dependency="afterok:$array" merge.sbatch)
merge=${merge%%;*}
jobs+=("$merge")

show_jobs() {
  echo "--- jobs:" >&2
  for j in "$array" "$merge"; do
    scontrol show job "$j" 2>&1 | grep -E 'JobId=|JobState=' >&2 || true
  done
  for f in logs/* "$logs_dir"/slurmctld.log "$logs_dir"/slurmd.log; do
    [ -f "$f" ] || continue
    echo "--- $f:" >&2
    tail -n 30 "$f" >&2
  done
}

deadline=$((SECONDS + limit))
while [ -n "$(squeue -h -j "$array,$merge" 2>/dev/null)" ]; do
  if [ $SECONDS -ge $deadline ]; then
    show_jobs
    fail "the jobs did not finish in ${limit}s"
  fi
  sleep 1
done
states=$(for j in "$array" "$merge"; do scontrol -o show job "$j"; done |
  grep -o 'JobState=[A-Z_]*' | sort | uniq -c || true)
if [ "$(echo "$states" | grep -c .)" -ne 1 ] || ! grep -q ' 5 JobState=COMPLETED$' <<<"$states"; then
  show_jobs
  fail "not every job completed:$(tr -s ' \n' ' ' <<<"$states")"
fi

if ! "$covsim" sweep sweep.json --out local --jobs 2 >local.log 2>&1; then
  cat local.log >&2
  fail "the local sweep failed"
fi

without_clock() {  # csv: the file without its wall-clock columns
  awk -F, -v drop="$clock_columns" '
    NR == 1 {
      n = split(drop, d, " ")
      for (i = 1; i <= NF; i++) {
        skip = 0
        for (j = 1; j <= n; j++) if ($i == d[j] || index($i, d[j] "_") == 1) skip = 1
        if (!skip) keep[++k] = i
      }
    }
    { line = $keep[1]; for (i = 2; i <= k; i++) line = line "," $keep[i]; print line }' "$1"
}
for c in $clock_columns; do
  head -n 1 local/runs.csv | tr , '\n' | grep -qx "$c" || fail "runs.csv has no column $c"
done
[ "$(wc -l <local/runs.csv)" -eq 9 ] || fail "the local sweep has not 8 runs"
for f in runs.csv summary.csv; do
  [ -f "results/all/$f" ] || { show_jobs; fail "the merge wrote no $f"; }
  if ! diff <(without_clock "local/$f") <(without_clock "results/all/$f") >&2; then
    fail "$f merged from the Slurm shards differs from the local sweep's"
  fi
done
echo "slurm: 4 shards and the merge match the local sweep"
