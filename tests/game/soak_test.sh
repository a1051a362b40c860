#!/usr/bin/env bash
# Soak: `vox play` under Xvfb for 2000 scripted edits — a voxel placed and removed again on
# alternate frames, so the world returns to the same state — at a 320x180 window, with the undo
# history held to 1 MiB so it fills during the warm-up. The process's resident memory (VmRSS
# from /proc/PID/status) is sampled through the run, each sample with the number of edits done
# by then; after the warm-up (the first quarter of the edits: counted in edits, not in samples, so
# a slow start on a loaded machine does not end the warm-up before the first edit) it must stay
# flat: its largest sample at most BOUND_MIB above the first sample after the warm-up. Memory, not
# time, is asserted.
# Usage: soak_test.sh VOX OUT [EDITS=2000]
set -u
vox="$1"; out="$2"; edits="${3:-2000}"
bound_mib=8

source "$(dirname "$0")/own_display.sh"
if ! own_display_available; then
    echo "SKIP: Xvfb not found (apt-get install xvfb; tools/setup.sh installs it)"
    exit 77
fi
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
failures=0

# Fly in and look down at the meadow (as tests/game/play_through.script), then click: left
# places a voxel on the face under the crosshair, right removes the voxel under it (the one just
# placed). Each click presses on its frame and releases on the next. The script ends the run
# (with unsaved changes: nothing is saved).
{
    echo "0 move 0 60"
    echo "0 key W down"
    echo "0 key LeftShift down"
    echo "24 key LeftShift up"
    echo "36 key W up"
    echo "37 move 0 100"
    echo "45 click left"
    for ((i = 1; i < edits / 2; i++)); do echo "+1 click right"; echo "+1 click left"; done
    echo "+1 click right"
} >soak.script

# Sample VmRSS (KiB) of vox itself every 0.2 s while it runs.
start_own_display 640x480 || exit 1
bash -c '"$0" "$@" & echo $! >vox.pid; wait $!' "$vox" play sandbox --script soak.script --size 320x180 \
    --render-scale 0.5 --method preview --undo-mb 1 --autosave-minutes 0 --frames $((edits + 200)) \
    >play.out 2>play.err &
runner=$!
for _ in $(seq 50); do [ -s vox.pid ] && break; sleep 0.1; done
pid=$(cat vox.pid 2>/dev/null)
: >rss.txt
while [ -n "$pid" ] && [ -e "/proc/$pid/status" ]; do
    rss=$(awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
    [ -n "$rss" ] && echo "$(grep -c -e ': place voxel' -e ': remove voxel' play.out) $rss" >>rss.txt
    sleep 0.2
done
wait "$runner"
rc=$?
[ $rc -eq 0 ] || { fail "vox play exited $rc"; tail -5 play.err; }
grep -q "validation error" play.err && fail "Vulkan validation errors"

placed=$(grep -c ": place voxel" play.out)
removed=$(grep -c ": remove voxel" play.out)
echo "edits: $placed placed, $removed removed (of $edits scripted)"
[ $((placed + removed)) -eq "$edits" ] || fail "expected $edits edits, got $((placed + removed))"
grep -q "nothing changed" play.out && fail "an edit changed nothing: $(grep -m1 'nothing changed' play.out)"

samples=$(grep -c . rss.txt)
after=$(awk -v warm=$((edits / 4)) '$1 >= warm' rss.txt | grep -c .)
[ "$after" -ge 20 ] || fail "only $after RSS samples after the warm-up (of $samples)"
# After the warm-up (samples taken once a quarter of the edits were done): the first sample, the
# largest and the last, in MiB.
read -r first peak last < <(awk -v warm=$((edits / 4)) '$1 >= warm { if (!f) f = $2; if ($2 > m) m = $2; l = $2 }
    END { printf "%.1f %.1f %.1f\n", f / 1024, m / 1024, l / 1024 }' rss.txt)
startup=$(awk 'NR == 1 { printf "%.1f", $2 / 1024 }' rss.txt)
echo "RSS: $samples samples; first $startup MiB; after warm-up first $first, peak $peak, last $last MiB (bound +$bound_mib MiB)"
awk -v a="$first" -v b="$peak" -v bound="$bound_mib" 'BEGIN { exit !(b - a <= bound) }' ||
    fail "RSS grew by more than $bound_mib MiB after the warm-up ($first -> $peak MiB)"

[ $failures -eq 0 ] && echo "soak passed" || echo "$failures failure(s)"
exit $((failures > 0))
