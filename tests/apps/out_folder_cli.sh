#!/usr/bin/env bash
# Rerunning into an --out folder that holds a user's own entries keeps them, or refuses with
# exit 2 before the run and changes nothing; never moves them away and deletes them.
#   out_folder_cli.sh COVSIM SOURCE_DIR WORK_DIR user|mount|link
# user: a note and a read-only folder of the user's (kept by root, who may move it; refused
# otherwise). mount: a file system mounted inside the folder, which no rename can move, and
# --out naming a mount point itself (needs root and mount; skipped with exit 77 otherwise).
# link: --out is a symbolic link to the folder; it stays a link, the folder is rewritten.
set -euo pipefail
covsim=$1 src=$2 work=$3 mode=$4
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
if [ "$mode" = link ]; then
  mkdir real && ln -s real out
fi
"$covsim" run "$src/scenarios/u_shape.json" --out out >/dev/null
echo "my notes" > out/notes.txt
mkdir -p out/mine; echo "kept" > out/mine/data.txt
case "$mode" in
  user)
    chmod 555 out/mine
    set +e; "$covsim" run "$src/scenarios/u_shape.json" --out out >/dev/null 2>err.txt; rc=$?; set -e
    chmod 755 out/mine
    if [ "$(id -u)" -eq 0 ]; then
      [ $rc -eq 0 ] || fail "rerun as root: exit $rc: $(cat err.txt)"
    else
      [ $rc -eq 2 ] && grep -q "holds mine, which is not covsim's" err.txt ||
        fail "rerun with a read-only folder: expected exit 2 naming it, got $rc: $(cat err.txt)"
    fi
    ;;
  mount)
    [ "$(id -u)" -eq 0 ] || { echo "skipped: not root (mounting a file system needs root)"; exit 77; }
    mkdir -p out/mnt
    mount -t tmpfs covsim-test out/mnt 2>mount.txt ||
      { echo "skipped: cannot mount a tmpfs here: $(cat mount.txt)"; exit 77; }
    trap 'umount "$work/out/mnt" 2>/dev/null || true' EXIT
    echo "on its own disk" > out/mnt/file.txt
    set +e; "$covsim" run "$src/scenarios/u_shape.json" --out out >/dev/null 2>err.txt; rc=$?; set -e
    [ $rc -eq 2 ] && grep -q "holds mnt, which is not covsim's .*nothing was changed" err.txt ||
      fail "rerun with a mount point inside: expected exit 2 naming it, got $rc: $(cat err.txt)"
    mountpoint -q out/mnt && [ "$(cat out/mnt/file.txt)" = "on its own disk" ] ||
      fail "the mount point or its file is gone"
    set +e; "$covsim" run "$src/scenarios/u_shape.json" --out out/mnt >/dev/null 2>err.txt; rc=$?; set -e
    [ $rc -eq 2 ] && grep -q "out/mnt: is a mount point.*nothing was changed" err.txt ||
      fail "--out naming a mount point: expected exit 2 naming it, got $rc: $(cat err.txt)"
    [ "$(ls out/mnt)" = "file.txt" ] && [ ! -e out/mnt.partial ] ||
      fail "--out naming a mount point changed it: $(ls out out/mnt)"
    ;;
  link)
    "$covsim" run "$src/scenarios/u_shape.json" --out out >/dev/null 2>err.txt ||
      fail "rerun through a link: $(cat err.txt)"
    [ -L out ] && [ "$(readlink out)" = real ] || fail "the link was replaced: $(ls -l)"
    [ -f real/final.json ] && [ "$(cat real/notes.txt)" = "my notes" ] ||
      fail "the linked folder lacks the run or the note: $(ls real)"
    [ ! -e real.partial ] && [ ! -e real.replaced ] || fail "staging folders left: $(ls)"
    ;;
  *) fail "unknown mode $mode" ;;
esac
[ "$(cat out/notes.txt)" = "my notes" ] || fail "the user's note is gone"
[ "$(cat out/mine/data.txt)" = "kept" ] || fail "the user's folder is gone"
[ -f out/final.json ] || fail "the run folder lost its final.json"
[ ! -e out.partial ] || fail "out.partial was left behind"
echo "ok: $mode"
