#!/usr/bin/env bash
# Screenshots from `vox play` (F12 / script `screenshot` and `capture`) on a full disk: the HUD
# message names the file and the reason, the previous file is byte-identical and no temporary is
# left. (The frame log is a journal, not written atomically: game.frame_log_journal.)
# VOX_FAIL_WRITES=after:N (core/atomic_file.h) stands in for the full disk.
# Usage: screenshot_full_disk_test.sh VOX
set -u
vox="$1"
source "$(dirname "$0")/own_display.sh"
skip_without_own_display
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
start_own_display 640x480 || exit 1

printf '[world]\nname = "tiny"\nsize = [32, 16, 32]\n[[material]]\nname = "a"\n[[generator]]\ntype = "box"\nmin = [0, 0, 0]\nmax = [32, 4, 32]\nmaterial = "a"\n' > tiny.toml
printf '2 screenshot shot.png\n+1 capture window.png\n+1 quit\n' > shots.script
echo "previous shot" > shot.png
echo "previous window" > window.png

VOX_FAIL_WRITES=after:0 "$vox" play tiny.toml --script shots.script --size 320x180 --method preview --indirect none \
    >play.out 2>play.err
rc=$?
grep -q "screenshot failed: shot.png: cannot write: No space left on device" play.out || fail "no message for shot.png"
grep -q "screenshot failed: window.png: cannot write: No space left on device" play.out || fail "no message for window.png"
[ "$(cat shot.png)" = "previous shot" ] || fail "shot.png changed"
[ "$(cat window.png)" = "previous window" ] || fail "window.png changed"
[ "$rc" -eq 0 ] || fail "exit $rc, stderr: $(cat play.err)"
ls -A | grep -q 'tmp-' && fail "a temporary was left: $(ls -A)"
if [ $failures -eq 0 ]; then
    grep "screenshot failed" play.out
    echo "ok: screenshots on a full disk keep the previous files"
fi
exit $((failures > 0))
