#!/usr/bin/env bash
# A sweep's index.html in headless Chromium, as a user opens it: the page holds the settings,
# the summary table (one row per setting) and a figure for every chart the sweep drew, each
# chart file there; no chart is of a measure the same in every run. Skipped (77) without
# Chromium.
# Usage: sweep_index_browser.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] ||
  { echo "skipped: chromium not installed (scripts/install-deps installs Debian's chromium)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
cat > loss.json <<JSON
{"scenario": "$source/scenarios/u_shape.json",
 "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.3, 0.6]},
 "seeds": [1, 2]}
JSON
"$covsim" sweep loss.json --out sweep > out.txt 2> err.txt || fail "sweep: $(cat err.txt)"
grep -q "sweep/index.html" out.txt || fail "the sweep does not name index.html: $(cat out.txt)"
charts=$(ls sweep/*.svg | wc -l)
[ "$charts" -gt 0 ] || fail "no charts"
for idle in turn_time contact_time map_bytes deadlocks phy_drops; do
  [ ! -e "sweep/${idle}_vs_network.loss.p.svg" ] || fail "a chart of $idle, 0 in every run"
done
timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --dump-dom \
  "file://$work/sweep/index.html" > dom.html 2> chromium.log || fail "chromium: $(tail -3 chromium.log)"
figures=$(grep -o '<figure class="chart">' dom.html | wc -l)
[ "$figures" -eq "$charts" ] || fail "the page shows $figures charts; the folder holds $charts"
for f in sweep/*.svg; do
  grep -q "<img src=\"$(basename "$f")\"" dom.html || fail "the page does not show $f"
done
rows=$(sed -n '/<table id="summary">/,/<\/table>/p' dom.html | grep -c '<td>')
[ "$rows" -gt 0 ] || fail "the summary table is empty"
data=$(sed -n '/<table id="summary">/,/<\/table>/p' dom.html | grep -o '<tr><td>' | wc -l)
[ "$data" -eq 3 ] || fail "the summary table has $data rows of settings, expected 3"
grep -q '<table id="settings">' dom.html || fail "no settings table"
echo "ok: $charts charts"
