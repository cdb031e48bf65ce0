#!/usr/bin/env bash
# `covsim plot DIR --video`: an MP4 and a GIF that ffprobe decodes with the expected frame
# count and size; a bad extension is an error and leaves no file. Skipped (77) without
# ffmpeg. Usage: video_cli.sh COVSIM SOURCE WORK
set -euo pipefail
covsim=$1 source=$2 work=$3
command -v ffmpeg > /dev/null && command -v ffprobe > /dev/null ||
  { echo "skipped: ffmpeg/ffprobe not installed (scripts/install-deps installs Debian's ffmpeg)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
"$covsim" run "$source/scenarios/u_shape.json" --out u > /dev/null
# u_shape converges at 26.8 s: at 10 simulated seconds per video second and 5 frames per
# second, 13.4 frame intervals, rounded up to 14, from t = 0 to the end: 15 frames.
"$covsim" plot u --video u.mp4 --fps 5 --speed 10 --video-width 480 > /dev/null
probe() {
  ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 "$1"
}
got=$(probe u.mp4)
[ "$got" = "h264,480,$(echo "$got" | cut -d, -f3),15" ] || fail "u.mp4: $got"
height=$(echo "$got" | cut -d, -f3)
[ $((height % 2)) -eq 0 ] && [ "$height" -gt 300 ] || fail "u.mp4 height $height"
"$covsim" plot u --video u.gif --fps 5 --speed 20 --video-width 320 > /dev/null
got=$(probe u.gif)
# At 20 simulated seconds per video second: 6.7 intervals, rounded up to 7: 8 frames.
case "$got" in gif,320,*,8) ;; *) fail "u.gif: $got (expected 8 frames, 320 wide)" ;; esac
set +e
err=$("$covsim" plot u --video u.avi 2>&1 >/dev/null)
rc=$?
set -e
[ $rc -eq 2 ] && [[ $err =~ "--video" ]] && [ ! -e u.avi ] && [ ! -e u.avi.partial ] ||
  fail "a .avi video: exit $rc: $err"
echo "video ok"
