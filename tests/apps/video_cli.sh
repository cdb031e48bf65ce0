#!/usr/bin/env bash
# `covsim plot DIR --video` and `covsim run --video`: an MP4 and a GIF that ffprobe decodes
# with the expected frame count and size; the legend under the map (a frame without it is
# shorter); on a terminal a progress line on stderr while encoding; a bad extension is an
# error and leaves no file; with --robots I, robot I's planner map over time. Skipped (77)
# without ffmpeg. Usage: video_cli.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
command -v ffmpeg > /dev/null && command -v ffprobe > /dev/null ||
  { echo "skipped: ffmpeg/ffprobe not installed (scripts/install-deps installs Debian's ffmpeg)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
"$covsim" run "$source/scenarios/u_shape.json" --out u > /dev/null
# u_shape converges at 28.5 s: at 10 simulated seconds per video second and 5 frames per
# second, 14.25 frame intervals, rounded up to 15, from t = 0 to the end: 16 frames.
"$covsim" plot u --video u.mp4 --fps 5 --speed 10 --video-width 480 > /dev/null
probe() {
  ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 "$1"
}
got=$(probe u.mp4)
[ "$got" = "h264,480,$(echo "$got" | cut -d, -f3),16" ] || fail "u.mp4: $got"
height=$(echo "$got" | cut -d, -f3)
[ $((height % 2)) -eq 0 ] && [ "$height" -gt 300 ] || fail "u.mp4 height $height"
"$covsim" plot u --video u.gif --fps 5 --speed 20 --video-width 320 > /dev/null
got=$(probe u.gif)
# At 20 simulated seconds per video second: 7.125 intervals, rounded up to 8: 9 frames.
case "$got" in gif,320,*,9) ;; *) fail "u.gif: $got (expected 9 frames, 320 wide)" ;; esac
# The legend takes rows under the map: without it (--layers) a frame is shorter.
"$covsim" plot u --video bare.mp4 --fps 5 --speed 10 --video-width 480 --layers=-legend > /dev/null
bare=$(probe bare.mp4 | cut -d, -f3)
[ "$bare" -lt $((height - 20)) ] || fail "a frame without its legend is $bare high, with it $height"

# covsim run --video: the run's outputs, then the video; on a terminal (util-linux's script
# gives one) a progress line on stderr while it encodes, and nothing of it on stdout.
command -v script > /dev/null || { echo "skipped: util-linux's script is not installed"; exit 77; }
script -qec "$covsim run $source/scenarios/u_shape.json --out r --video r.mp4 > r.out" typescript \
  > /dev/null
got=$(probe r.mp4)
# 28.5 s in about 20 s of video at 25 frames per second: 501 frames, 960 wide by default.
case "$got" in h264,960,*,501) ;; *) fail "run --video r.mp4: $got" ;; esac
[ -f r/final.json ] && [ -f r/scene.svg ] || fail "run --video left no run folder: $(ls r)"
grep -q "^wrote .*, r.mp4$" r.out || fail "run --video did not name the video: $(cat r.out)"
tr '\r' '\n' < typescript | grep -Eq "^video: frame [0-9]+ of 501 \([0-9]+%\)" ||
  fail "no progress line while encoding: $(tr '\r' '\n' < typescript | head -5)"
! grep -q "video: frame" r.out || fail "the progress line went to stdout"
# Piped, no progress line; a bad extension stops the run before it starts, leaving nothing.
"$covsim" run "$source/scenarios/u_shape.json" --out p --video p.gif --fps 5 --speed 20 \
  > /dev/null 2> p.err
case "$(probe p.gif)" in gif,960,*,9) ;; *) fail "run --video p.gif: $(probe p.gif)" ;; esac
! grep -q "video:" p.err || fail "progress written to a file: $(head -c 200 p.err)"
set +e
err=$("$covsim" run "$source/scenarios/u_shape.json" --out q --video q.webm 2>&1 >/dev/null)
rc=$?
set -e
[ $rc -eq 2 ] && [[ $err =~ "--video" ]] && [ ! -e q ] && [ ! -e q.webm ] ||
  fail "run --video q.webm: exit $rc: $err"

set +e
err=$("$covsim" plot u --video u.avi 2>&1 >/dev/null)
rc=$?
set -e
[ $rc -eq 2 ] && [[ $err =~ "--video" ]] && [ ! -e u.avi ] && [ ! -e u.avi.partial ] ||
  fail "a .avi video: exit $rc: $err"

# One robot's planner map (--robots I on a run whose planners plan on a sensed map): its walls
# in dark orange (#d95f02) in the frames, growing as the map does; none without --robots.
"$covsim" run "$source/scenarios/u_shape.json" --out s --set planner.type=grid_astar \
  --set environment.known=none --set sensor.range=0.5 > /dev/null
orange() {  # orange pixels in frame $2 (0-based) of video $1
  ffmpeg -v error -i "$1" -vf "select=eq(n\\,$2)" -frames:v 1 -f rawvideo -pix_fmt rgb24 - |
    od -An -v -tu1 -w3 | awk '$1 > 190 && $1 < 240 && $2 > 70 && $2 < 120 && $3 < 40 {n++} END {print n + 0}'
}
"$covsim" plot s --robots 1 --video s1.mp4 --fps 5 --speed 10 --video-width 480 > /dev/null
"$covsim" plot s --video s.mp4 --fps 5 --speed 10 --video-width 480 > /dev/null
frames=$(probe s1.mp4 | cut -d, -f4)
first=$(orange s1.mp4 1) last=$(orange s1.mp4 $((frames - 1))) none=$(orange s.mp4 $((frames - 1)))
[ "$last" -gt $((none + 200)) ] && [ "$last" -gt "$first" ] ||
  fail "robot 1's planner map: $first orange pixels in frame 1, $last in the last ($none without --robots)"
echo "video ok"
