#!/usr/bin/env bash
# replay.html in headless Chromium at 1400 × 900, as a user opens it. Opened as
# `replay.html?selftest#t=SECONDS`, the page moves its slider (an input event, as a user's
# drag sends), steps with the keys, draws, and writes into #status what it drew: the frame
# the address opened, the address it wrote, each robot's colour as drawn, the window and
# where the cost plot and the map lie in it, its title, and the time a new address (#t=5)
# moved it to. The test reads #status from the DOM Chromium dumps and checks: the address's
# time opens the page there and moves it when the address changes, the robots are the
# figures' colours, the cost plot and the map are beside each other inside the window with
# the map filling its height, the title is the scenario's name; an error in the page is
# reported; a sensed-map run's page draws the chosen robot's planner map as it grew. A
# screenshot is taken. Skipped (77) without Chromium.
# Usage: replay_browser.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] ||
  { echo "skipped: chromium not installed (scripts/install-deps installs Debian's chromium)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
# The virtual time budget lets the page's events after loading (an address change) run.
flags=(--headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0
  --virtual-time-budget=5000 --window-size=1400,900)

"$covsim" run "$source/scenarios/u_shape.json" --out run > /dev/null
"$covsim" plot run > /dev/null
page="file://$work/run/replay.html"
status() {  # status URL: the page's #status, Chromium's messages in err.log
  timeout 120 "$chromium" "${flags[@]}" --dump-dom "$1" 2> err.log |
    grep -o '<pre id="status">[^<]*' | sed 's/<pre id="status">//'
}

# u_shape converges after 285 motion steps: 286 frames; the slider moves to frame 142.
got=$(status "$page?selftest#t=20")
echo "$got"
want="selftest ok: frame 142 of 286, t=14.2, robots 5, cells 5, cost cursor t=14.2"
[[ $got == "$want, "* ]] || fail "the replay did not draw the frame the slider moved to: $got"
! grep -q "Uncaught" err.log || fail "the replay page reported errors: $(cat err.log)"
# The address's time opens the page at the nearest frame; the page writes the frame's time
# into the address as the slider moves.
[[ $got == *", opened t=20,"* ]] || fail "#t=20 did not open the page at t = 20 s: $got"
[[ $got == *", url #t=14.2,"* ]] || fail "the address does not say the frame's time: $got"
[[ $got == *", address t=5 showed t=5" ]] || fail "a new address #t=5 did not move to t = 5 s: $got"
[[ $(status "$page?selftest#t=3.14159") == *", opened t=3.1,"* ]] ||
  fail "#t=3.14159 did not open the page at the nearest frame, t = 3.1 s"
[[ $(status "$page?selftest") == *", opened t=0,"* ]] || fail "without #t the page did not open at t = 0"
[[ $got == *", keys ok, png ok,"* ]] || fail "keys or the PNG of the frame failed: $got"
# The robots are the figures' colours (Paul Tol's muted scheme, robots 0 to 4; scene.svg's
# strokes are the same colours).
[[ $got == *"robot colours 5 of 5 (#cc6677 #332288 #ddcc77 #117733 #88ccee)"* ]] ||
  fail "the robots are not the figures' colours: $got"
grep -q "stroke:rgb(80%,40%,46.666667%)" run/scene.svg || fail "scene.svg's robot 0 is not #cc6677"
[[ $got == *", title u_shape — covsim replay,"* ]] || fail "the page's title is not the scenario's name: $got"
# The layout: both in view, the cost plot right of the map, the map filling the window's
# height (no half-empty page), all within 1400 × 900.
/usr/bin/python3 - "$got" <<'PY' || fail "the replay's layout at 1400 × 900: $got"
import re, sys
s = sys.argv[1]
w, h = map(int, re.search(r"window (\d+)x(\d+)", s).groups())
cost = list(map(int, re.search(r"cost plot in view at (-?\d+),(-?\d+),(-?\d+),(-?\d+)", s).groups()))
view = list(map(int, re.search(r"map in view at (-?\d+),(-?\d+),(-?\d+),(-?\d+)", s).groups()))
assert w <= 1400 and h <= 900, (w, h)
assert cost[2] <= 1400 and cost[3] <= 900 and view[2] <= 1400 and view[3] <= 900
assert cost[0] >= view[2], "the cost plot is not beside the map"
assert view[3] >= 0.9 * h, "the map leaves the window's bottom empty"
assert cost[2] - cost[0] >= 300 and cost[3] - cost[1] >= 170, "the cost plot is too small"
PY
"$chromium" "${flags[@]}" --screenshot="$work/replay.png" "$page?selftest#t=20" 2> /dev/null
[ "$(stat -c %s replay.png)" -gt 10000 ] || fail "no screenshot of the replay"

# A narrow window puts the panel under the map: the check of the layout can fail.
narrow=$(timeout 120 "$chromium" "${flags[@]/--window-size=1400,900/--window-size=700,500}" \
  --dump-dom "$page?selftest" 2> /dev/null | grep -o '<pre id="status">[^<]*')
[[ $narrow == *"cost plot out of view"* ]] || fail "a 700 × 500 window shows the cost plot: $narrow"

# The check can fail: a page that throws is reported as such.
sed 's/^draw(hashTime() === null ? 0 : frameAt(hashTime()));$/& notDefined();/' run/replay.html > broken.html
cmp -s broken.html run/replay.html && fail "could not break the page"
got=$(status "file://$work/broken.html?selftest")
[[ $got == "errors: Uncaught ReferenceError"* ]] || fail "an error in the page went unreported: $got"
# A run whose planners plan on a sensed map: `plot --robots 1` opens the page on robot 1's
# planner map, its walls and way drawn as they were at the frame's time (fewer walls early).
"$covsim" run "$source/scenarios/u_shape.json" --out sensed --set planner.type=grid_astar \
  --set environment.known=none --set sensor.range=0.5 > /dev/null
"$covsim" plot sensed --robots 1 > /dev/null
walls() { sed -n 's/.*planner walls at open \([0-9]*\),.*/\1/p' <<< "$1"; }
early=$(status "file://$work/sensed/replay.html?selftest#t=1") late=$(status "file://$work/sensed/replay.html?selftest#t=25")
[ -n "$(walls "$early")" ] && [ -n "$(walls "$late")" ] && [ "$(walls "$late")" -gt "$(walls "$early")" ] ||
  fail "robot 1's planner map in the replay: at 1 s: $early; at 25 s: $late"
[[ $(status "file://$work/sensed/replay.html?selftest") == *"planner map of robot 1: walls "* ]] ||
  fail "the page did not open on robot 1's planner map"
[[ $(status "$page?selftest") != *"planner map"* ]] || fail "a run without planner maps offers one"
echo "replay ok"
