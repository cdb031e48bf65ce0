#!/usr/bin/env bash
# `covsim run --compress` and "recording": {"compress": true} write trajectory.csv.gz, a gzip
# stream that inflates to the very bytes of the uncompressed run's trajectory.csv; `covsim
# plot` redraws the same figures from it; a rerun into the folder replaces the other name and
# keeps other files; a non-boolean setting, a damaged .gz and a folder holding both files are
# errors naming them (exit 2).
# Usage: compress_cli.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
u=$source/scenarios/u_shape.json
fp() { sed -n 's/.*"fingerprint": "\([0-9a-f]*\)".*/\1/p' "$1/final.json"; }

"$covsim" run "$u" --out plain > /dev/null
said=$("$covsim" run "$u" --out packed --compress)
[[ $said == *"packed/trajectory.csv.gz,"* ]] || fail "run --compress said: $said"
[ -f packed/trajectory.csv.gz ] && [ ! -e packed/trajectory.csv ] ||
  fail "run --compress wrote: $(ls packed)"
gzip -t packed/trajectory.csv.gz || fail "trajectory.csv.gz is not a whole gzip file"
gzip -dc packed/trajectory.csv.gz | cmp -s - plain/trajectory.csv ||
  fail "trajectory.csv.gz does not inflate to the uncompressed run's trajectory.csv"
plain_size=$(stat -c %s plain/trajectory.csv) packed_size=$(stat -c %s packed/trajectory.csv.gz)
[ "$packed_size" -lt $((plain_size / 3)) ] ||
  fail "trajectory.csv.gz is $packed_size bytes, trajectory.csv $plain_size"
[ "$(fp packed)" = "$(fp plain)" ] || fail "compressing changed the run"
for f in metrics.csv scene.svg cost.svg; do
  cmp -s plain/$f packed/$f || fail "$f differs when the trajectory is compressed"
done

# The scenario's setting does the same, to the byte.
"$covsim" run "$u" --out set --set recording.compress=true > /dev/null
cmp -s set/trajectory.csv.gz packed/trajectory.csv.gz ||
  fail "recording.compress wrote another trajectory.csv.gz than --compress"
grep -q '"compress": true' set/scenario.json || fail "scenario.json lost recording.compress"

# covsim plot reads the .gz and redraws the figures the run drew.
mkdir drawn && mv packed/scene.svg packed/cost.svg drawn/
"$covsim" plot packed > /dev/null
for f in scene.svg cost.svg; do
  cmp -s drawn/$f packed/$f || fail "covsim plot drew another $f from trajectory.csv.gz"
done
grep -q "<canvas" packed/replay.html || fail "no replay.html from trajectory.csv.gz"

# A rerun replaces the other name's file (and keeps what is not a run's output).
echo kept > plain/notes.txt
"$covsim" run "$u" --out plain --compress > /dev/null
[ -f plain/trajectory.csv.gz ] && [ ! -e plain/trajectory.csv ] && [ -f plain/notes.txt ] ||
  fail "a compressed rerun left: $(ls plain)"
"$covsim" run "$u" --out plain > /dev/null
[ -f plain/trajectory.csv ] && [ ! -e plain/trajectory.csv.gz ] && [ -f plain/notes.txt ] ||
  fail "an uncompressed rerun left: $(ls plain)"

bad() {  # bad REGEX ARGS...
  local want=$1; shift
  set +e; err=$("$covsim" "$@" 2>&1 >/dev/null); rc=$?; set -e
  [ $rc -eq 2 ] && [[ $err =~ $want ]] || fail "$* gave exit $rc: $err"
}
bad 'recording\.compress: expected true or false' run "$u" --out nope --set recording.compress=1
[ ! -e nope ] || fail "a bad recording.compress left a folder"
# Both files: which one is the run's is unknown.
cp plain/trajectory.csv packed/
bad 'holds both trajectory.csv and trajectory.csv.gz' plot packed
rm packed/trajectory.csv
# A truncated .gz is an error, not a shorter run.
head -c $((packed_size / 2)) set/trajectory.csv.gz > half.gz && mv half.gz set/trajectory.csv.gz
bad 'trajectory.csv.gz: cannot read' plot set
echo "compress ok"
