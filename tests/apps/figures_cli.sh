#!/usr/bin/env bash
# The figures as files other tools read: `covsim run --format` and `covsim plot --format`
# write well-formed SVG, valid PDF and PNG of the requested width; --layers leaves out what
# it removes (elements counted in the SVG); a Gaussian density is an
# image (with its colour bar), not a grid of shapes; office's scene stays under 1 MB;
# thinned recordings still draw; bad options are errors naming them.
# Usage: figures_cli.sh COVSIM SOURCE WORK OFFICE_RUN (office_run.sh's folder)
set -euo pipefail
covsim=$1 source=$2 work=$3 office_run=$4
py=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
bad() {  # bad REGEX ARGS...
  local want=$1; shift
  set +e; err=$("$covsim" "$@" 2>&1 >/dev/null); rc=$?; set -e
  [ $rc -eq 2 ] && [[ $err =~ $want ]] || fail "$* gave exit $rc: $err"
}

check_svg() { "$py" -c 'import sys, xml.etree.ElementTree as E
root = E.parse(sys.argv[1]).getroot()
assert root.tag == "{http://www.w3.org/2000/svg}svg", root.tag' "$1" || fail "$1 is not well-formed SVG"; }
check_pdf() { "$py" - "$1" <<'PY' || fail "$1 is not a valid PDF"
import re, sys
data = open(sys.argv[1], "rb").read()
assert data.startswith(b"%PDF-1."), "header"
assert data.rstrip().endswith(b"%%EOF"), "trailer"
# The cross-reference table points at each object where it is.
start = int(re.findall(rb"startxref\s+(\d+)", data)[-1])
assert data[start:start + 4] == b"xref", "startxref"
entries = re.findall(rb"(\d{10}) 00000 n", data[start:])
for k, off in enumerate(entries, start=1):
    assert re.match(rb"\d+ 0 obj", data[int(off):int(off) + 20]), f"object at {int(off)}"
assert b"/Type /Page" in data or b"/Type/Page" in data, "no page"
PY
}
png_size() { "$py" - "$1" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "signature"
pos, size = 8, None
while pos < len(data):  # every chunk's CRC holds
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    assert zlib.crc32(kind + body) == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0], kind
    if kind == b"IHDR": size = struct.unpack(">II", body[:8])
    pos += 12 + n
    if kind == b"IEND": break
print(f"{size[0]}x{size[1]}")
PY
}

# u_shape: run writes PDF figures; plot redraws them in each format.
"$covsim" run "$source/scenarios/u_shape.json" --out u --format pdf > /dev/null
[ -f u/scene.pdf ] && [ -f u/cost.pdf ] && [ ! -e u/scene.svg ] || fail "run --format pdf wrote $(ls u)"
check_pdf u/scene.pdf
check_pdf u/cost.pdf
"$covsim" plot u > /dev/null
check_svg u/scene.svg
check_svg u/cost.svg
grep -q "glyph" u/scene.svg || fail "scene.svg has no text"
# Robot paths lie above the obstacles, unclipped: a walk along a wall lies on ∂Ω, where a clip
# to Ω would hide half of it (robot 0's path: its colour #cc6677, solid, not filled).
"$py" - u/scene.svg <<'PY' || fail "scene.svg clips robot 0's path to Ω"
import sys, xml.etree.ElementTree as E
colour = "stroke:rgb(80%,40%,46.666667%);stroke-opacity:1;"
found = []
def walk(node, clipped):
    clipped = clipped or "clip-path" in node.attrib
    style = node.get("style", "")
    if node.tag.endswith("path") and style.startswith("fill:none;") and colour in style:
        found.append(clipped)
    for child in node:
        walk(child, clipped)
walk(E.parse(sys.argv[1]).getroot(), False)
assert found and not any(found), found
PY
"$covsim" plot u --format png --png-width 900 > /dev/null
case "$(png_size u/scene.png)" in 900x*) ;; *) fail "scene.png is $(png_size u/scene.png), not 900 wide" ;; esac
case "$(png_size u/cost.png)" in 900x*) ;; *) fail "cost.png is $(png_size u/cost.png), not 900 wide" ;; esac
"$covsim" plot u --format png > /dev/null
case "$(png_size u/scene.png)" in 1020x*) ;; *) fail "default scene.png (page: 180 mm, two pixels a point) is $(png_size u/scene.png)" ;; esac

# --layers removes what it leaves out: the paths, dashed virtual paths and IDs are gone from
# the SVG (counted as elements), the rest stays; a removal is the same as listing the others.
svg_count() {  # svg_count FILE WHAT: elements of a kind in an SVG
  "$py" - "$1" "$2" <<'PY'
import sys, xml.etree.ElementTree as E
root = E.parse(sys.argv[1]).getroot()
ns = "{http://www.w3.org/2000/svg}"
paths = [e for e in root.iter(ns + "path")]
robot0 = "stroke:rgb(80%,40%,46.666667%)"  # robot 0's colour
what = sys.argv[2]
if what == "elements":
    n = sum(1 for _ in root.iter())
elif what == "robot0-solid":  # robot 0's path (solid)
    n = sum(1 for e in paths if robot0 in e.get("style", "") and "stroke-dasharray" not in e.get("style", ""))
elif what == "robot0-dashed":  # robot 0's virtual generator's path (dashed)
    n = sum(1 for e in paths if robot0 in e.get("style", "") and "stroke-dasharray" in e.get("style", ""))
elif what == "glyphs":  # text drawn (each glyph a <use>)
    n = sum(1 for e in root.iter(ns + "use"))
print(n)
PY
}
"$covsim" plot u --layers all > /dev/null
cp u/scene.svg all.svg
"$covsim" plot u --layers=-virtual-paths > /dev/null
cp u/scene.svg no-virtual.svg
[ "$(svg_count all.svg robot0-dashed)" -ge 1 ] || fail "no virtual path of robot 0 in all layers"
[ "$(svg_count no-virtual.svg robot0-dashed)" -eq 0 ] || fail "--layers=-virtual-paths drew one"
[ "$(svg_count no-virtual.svg robot0-solid)" -eq "$(svg_count all.svg robot0-solid)" ] ||
  fail "--layers=-virtual-paths removed more than the virtual paths"
[ "$(svg_count no-virtual.svg elements)" -lt "$(svg_count all.svg elements)" ] ||
  fail "--layers=-virtual-paths left as many elements"
"$covsim" plot u --layers obstacles,paths,robots > /dev/null
cp u/scene.svg bare.svg
[ "$(svg_count bare.svg glyphs)" -eq 0 ] || fail "--layers obstacles,paths,robots drew text"
[ "$(svg_count bare.svg robot0-solid)" -ge 1 ] || fail "--layers obstacles,paths,robots lost the paths"
[ "$(svg_count bare.svg elements)" -lt "$(svg_count no-virtual.svg elements)" ] ||
  fail "three layers drew as many elements as twelve"
bad "--layers: unknown layer \"pathz\"" plot u --layers paths,pathz
bad "--layers" run "$source/scenarios/u_shape.json" --out v --layers=-all
bad "--size: expected column, page, talk" plot u --size 12cm
bad "--size" run "$source/scenarios/u_shape.json" --out v --size 5mm
bad "--font-size" plot u --font-size 2
[ ! -e v ] || fail "a bad figure option left a folder behind"

# The options: a window, a robot subset, a title, a log scale; bad values exit 2 naming them.
"$covsim" plot u --time-window 10,30 --robots 1,3 --title "two robots" --log-cost > /dev/null
check_svg u/scene.svg
bad "--time-window" plot u --time-window 30,10
bad "--time-window" plot u --time-window abc
bad "--robots: robot 9 does not exist" plot u --robots 1,9
bad "--robots" plot u --robots 1,-2
bad "--format" plot u --format jpg
bad "--format" run "$source/scenarios/u_shape.json" --out v --format gif
[ ! -e v ] || fail "a bad --format left a folder behind"

# A Gaussian density is one image with a colour bar, not thousands of shapes.
"$covsim" run "$source/scenarios/fig2d.json" --out g > /dev/null
check_svg g/scene.svg
[ "$(grep -c "<image" g/scene.svg)" -ge 1 ] || fail "fig2d's density is not an image"
[ "$(grep -c "<rect" g/scene.svg)" -lt 200 ] || fail "fig2d's scene draws a grid of rectangles"

# office: the scene stays under 1 MB as SVG.
size=$(stat -c %s "$office_run/office/scene.svg")
[ "$size" -lt 1000000 ] || fail "office's scene.svg is $size bytes"
check_svg "$office_run/office/scene.svg"

# A thinned recording: fewer rows, the same run, and it still draws and replays.
"$covsim" run "$source/scenarios/u_shape.json" --out thin --set recording.trajectory_period=1 > /dev/null
full=$(wc -l < u/trajectory.csv) thin=$(wc -l < thin/trajectory.csv)
[ "$thin" -lt $((full / 5)) ] || fail "trajectory_period 1 s kept $thin of $full rows"
fp() { "$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["fingerprint"])' "$1/final.json"; }
[ "$(fp thin)" = "$(fp u)" ] || fail "thinning the recording changed the run"
# Every robot's last row is where final.json has it.
"$py" - thin <<'PY' || fail "a thinned recording lost the robots' final positions"
import csv, json, sys
final = json.load(open(sys.argv[1] + "/final.json"))
last = {}
for row in csv.DictReader(open(sys.argv[1] + "/trajectory.csv")):
    last[int(row["robot"])] = (float(row["x"]), float(row["y"]))
for i, r in enumerate(final["robots"]):
    assert max(abs(a - b) for a, b in zip(last[i], r["position"])) < 1e-9, (i, last[i], r)
PY
"$covsim" plot thin > /dev/null
check_svg thin/scene.svg
bad "trajectory_period" run "$source/scenarios/u_shape.json" --out w --set recording.trajectory_period=-1
# A sweep's plots redraw from its folder in another format, nothing run again.
cat > sweep.json <<JSON
{"scenario": "$source/scenarios/u_shape.json", "grid": {"sensor.range": [0.1, 0.5]}, "seeds": [1]}
JSON
"$covsim" sweep sweep.json --out s --jobs 2 > /dev/null 2> s.err
# Off a terminal, a line per run: an estimate once a run has ended, the time taken at the end.
grep -q '^sweep: 1/2 runs done, 0 failed, about [0-9.]* s left$' s.err || fail "progress: $(cat s.err)"
grep -q '^sweep: 2/2 runs done, 0 failed, [0-9.]* s here$' s.err || fail "progress: $(cat s.err)"
# u_shape's positions are fixed and nothing in it is drawn: every seed runs the same run.
cat > same.json <<JSON
{"scenario": "$source/scenarios/u_shape.json", "grid": {"sensor.range": [0.5]}, "seeds": [1, 2]}
JSON
"$covsim" sweep same.json --out same --jobs 2 > /dev/null 2> same.err
grep -q 'warning: setting 0, sensor.range=0.5: 1 distinct run of 2 (seed 2 = seed 1' same.err ||
  fail "identical seeds: $(cat same.err)"
grep -q '^0,0.5,2,0,1,1,' same/summary.csv || fail "distinct_runs: $(cat same/summary.csv)"
bad "\"cost_reel\" is not a measure.*did you mean 'cost_real'" sweep sweep.json --out nope --measures cost_reel
[ ! -e nope ] || fail "a sweep with a bad --measures left its folder"
# docs/sweeps.md's worked example: planners by schedule on dead_ends, whose starts are drawn
# per seed: every seed its own run, charts by planner, by mode and against the ratio.
"$covsim" sweep "$source/examples/sweeps/dead_ends_planners.json" --out de --jobs 2 > /dev/null 2> de.err
! grep -q "distinct run" de.err || fail "dead_ends' seeds repeated a run: $(cat de.err)"
for chart in sim_time_by_planner.type sim_time_by_loops.mode sim_time_vs_loops.ratio; do
  check_svg "de/$chart.svg"
done
[ "$(cut -d, -f7 de/summary.csv | sort -u | tr '\n' ' ')" = "3 distinct_runs " ] ||
  fail "dead_ends' distinct runs: $(cut -d, -f1-8 de/summary.csv)"
svgs=$(ls s/*_vs_sensor.range.svg | wc -l)
[ "$svgs" -ge 5 ] || fail "the sweep drew $svgs plots"
for f in s/*.svg; do check_svg "$f"; done
cp s/summary.csv summary-before.csv
"$covsim" merge s --out s --format png > /dev/null
[ "$(ls s/*_vs_sensor.range.png | wc -l)" -eq "$svgs" ] || fail "merge --format png drew $(ls s/*.png | wc -l) of $svgs"
png_size "$(ls s/*_vs_sensor.range.png | head -1)" > /dev/null
cmp -s s/summary.csv summary-before.csv || fail "merging a sweep into itself changed its summary"
# Bodies drawn to scale: two robots of radius r in a 1 m room cover 4 times the ink at 2r.
for r in 0.08 0.16; do
  cat > bodies-$r.json <<JSON
{"environment": {"outer": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "density": {"type": "uniform"},
 "robots": {"positions": [[0.3, 0.5], [0.7, 0.5]], "radius": $r}, "seed": 1}
JSON
  "$covsim" run bodies-$r.json --out bodies-$r --format png --png-width 600 --layers robots > /dev/null
done
"$py" - bodies-0.08/scene.png bodies-0.16/scene.png <<'PY' || fail "bodies are not drawn to scale"
import sys
import matplotlib.image as mpimg
def ink(f):
    a = mpimg.imread(f)[..., :3]
    return int(((a < 0.97).any(axis=2)).sum())
small, large = ink(sys.argv[1]), ink(sys.argv[2])
assert small > 500, small
assert 3.6 < large / small < 4.4, (small, large)
PY
echo "figures ok"
