#!/usr/bin/env bash
# The figures' sizes and text read back from the PDFs, as a journal's checker reads them:
# pdfinfo gives each --size preset's page in points (column 88 mm, page 180 mm, talk
# 960 × 540 pt; a width in mm), pdffonts shows DejaVu Sans embedded, and the text's size in
# the page's content (the Tm matrices cairo writes) is the preset's or --font-size's. Skipped
# (77) without poppler-utils. Usage: figure_pdf_cli.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
py=/usr/bin/python3
command -v pdfinfo > /dev/null && command -v pdffonts > /dev/null ||
  { echo "skipped: pdfinfo/pdffonts not installed (scripts/install-deps installs poppler-utils)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$covsim" run "$source/scenarios/u_shape.json" --out u --format pdf --size column > /dev/null

page_size() {  # "W H" in points
  pdfinfo "$1" | sed -n 's/^Page size: *\([0-9.]*\) x \([0-9.]*\) pts.*/\1 \2/p'
}
# The most used text size, and the largest, in points: from each text matrix "s 0 0 -s x y Tm"
# (text turned a quarter, the y labels, has a matrix "0 -s s 0"; its size counts too).
text_sizes() {
  "$py" - "$1" <<'PY'
import collections, re, sys, zlib
data = open(sys.argv[1], "rb").read()
sizes = collections.Counter()
for m in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
    try:
        content = zlib.decompress(m.group(1))
    except zlib.error:
        continue  # a font or an image
    for a, b, c, d in re.findall(rb"([-\d.]+) ([-\d.]+) ([-\d.]+) ([-\d.]+) [-\d.]+ [-\d.]+ Tm", content):
        sizes[round(max(abs(float(a)), abs(float(b))), 3)] += 1
assert sizes, "no text"
print(f"{sizes.most_common(1)[0][0]:g} {max(sizes):g}")
PY
}
near() {  # near A B: |A - B| < 0.01
  "$py" -c 'import sys; sys.exit(abs(float(sys.argv[1]) - float(sys.argv[2])) >= 0.01)' "$1" "$2"
}
# check FIGURE WIDTH HEIGHT(or "-": the figure's own) FONT
check() {
  local file=$1 width=$2 height=$3 font=$4
  read -r w h <<< "$(page_size "$file")"
  near "$w" "$width" || fail "$file is $w pt wide, not $width"
  if [ "$height" = "-" ]; then
    "$py" -c 'import sys; sys.exit(not 0.3 < float(sys.argv[1]) / float(sys.argv[2]) < 2)' "$h" "$w" ||
      fail "$file is $w × $h pt"
  else
    near "$h" "$height" || fail "$file is $h pt high, not $height"
  fi
  pdffonts "$file" | grep -Eq "DejaVuSans +.* yes +yes" ||
    fail "$file does not embed DejaVu Sans: $(pdffonts "$file")"
  ! pdffonts "$file" | tail -n +3 | grep -v DejaVuSans | grep -q . ||
    fail "$file uses other fonts: $(pdffonts "$file")"
  read -r most largest <<< "$(text_sizes "$file")"
  near "$most" "$font" || fail "$file's text is mostly $most pt, not $font"
  # Titles are one point larger than the text; nothing else is.
  "$py" -c 'import sys; sys.exit(float(sys.argv[1]) > float(sys.argv[2]) + 1.001)' "$largest" "$font" ||
    fail "$file has text of $largest pt with $font pt asked for"
}
# 88 mm = 249.449 pt, 180 mm = 510.236 pt, 120 mm = 340.157 pt.
check u/scene.pdf 249.449 - 8
check u/cost.pdf 249.449 - 8
"$covsim" plot u --format pdf --size page > /dev/null
check u/scene.pdf 510.236 - 9
check u/cost.pdf 510.236 - 9
"$covsim" plot u --format pdf > /dev/null  # the default: page
check u/scene.pdf 510.236 - 9
"$covsim" plot u --format pdf --size talk > /dev/null
check u/scene.pdf 960 540 16
check u/cost.pdf 960 540 16
"$covsim" plot u --format pdf --size 120mm --font-size 12 > /dev/null
check u/scene.pdf 340.157 - 12
check u/cost.pdf 340.157 - 12
# The check can fail: a column figure is not a page's.
( check u/scene.pdf 249.449 - 8 ) 2> /dev/null && fail "a 120 mm figure passed as a column's"
echo "figure pdf ok"
