#!/usr/bin/env bash
# Soak: `vox play` under Xvfb for EDITS + 200 frames of scripted edits at a 320x180 window, with
# the undo history held to 1 MiB so it fills during the warm-up. The run repeats one cycle that
# leaves the world as it found it: ten voxel edits (a voxel placed and removed again on
# alternate frames), then the object tool on the --model crate (tests/game/crate.toml): place
# it, move it there and back, turn it, set a key, undo and redo the key, delete it. The
# process's resident memory (VmRSS from /proc/PID/status) is sampled through the run, each sample
# with the number of voxel edits done by then; after the warm-up (the first quarter of the voxel
# edits: counted in edits, not in samples, so a slow start on a loaded machine does not end the
# warm-up before the first edit) it must stay flat: its largest sample in the second half at most
# BOUND_MIB above the largest in the second quarter. Largest against largest: a
# cycle's crate (its model and the objects' grid, a 4.3 MiB brick page each) comes and goes, so
# a sample lands with it or without it. Memory, not time, is asserted.
# Usage: soak_test.sh VOX OUT [EDITS=2000]
set -u
vox="$1"; out="$2"; edits="${3:-2000}"
bound_mib=8
crate="$(cd "$(dirname "$0")" && pwd)/crate.toml"

source "$(dirname "$0")/own_display.sh"
skip_without_own_display
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
failures=0

# Fly in and look down at the meadow (as tests/game/play_through.script), then the cycles. Voxel
# tool (1): left places a voxel on the face under the crosshair, right removes the voxel under
# it (the one just placed); each click presses on its frame and releases on the next. Object
# tool (4): left places the crate there (and selects it), Right and Left move it one voxel and
# back, R turns it a quarter, K sets a key, Ctrl+Z and Ctrl+Y undo and redo the key, Delete
# deletes it. 22 frames a cycle, as many cycles as the --frames limit (EDITS + 200) holds; the
# limit ends the run (with unsaved changes: nothing is saved).
cycles=$(((edits + 200 - 60) / 22))
{
    echo "0 move 0 60"
    echo "0 key W down"
    echo "0 key LeftShift down"
    echo "24 key LeftShift up"
    echo "36 key W up"
    echo "37 move 0 100"
    echo "44 tap 1"
    for ((c = 0; c < cycles; c++)); do
        [ $c -gt 0 ] && echo "+1 tap 1"
        for ((i = 0; i < 5; i++)); do echo "+1 click left"; echo "+1 click right"; done
        echo "+1 tap 4"
        echo "+1 click left"
        echo "+1 tap Right"
        echo "+1 tap Left"
        echo "+1 tap R"
        echo "+1 tap K"
        echo "+1 key LeftCtrl down"
        echo "+1 tap Z"
        echo "+1 tap Y"
        echo "+1 key LeftCtrl up"
        echo "+1 tap Delete"
    done
} >soak.script

# Sample VmRSS (KiB) of vox itself every 0.2 s while it runs.
start_own_display 640x480 || exit 1
bash -c '"$0" "$@" & echo $! >vox.pid; wait $!' "$vox" play sandbox --script soak.script --size 320x180 \
    --render-scale 0.5 --method preview --indirect none --undo-mb 1 --autosave-minutes 0 --frames $((edits + 200)) --model "$crate" \
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
echo "voxel edits: $placed placed, $removed removed (of $((cycles * 10)) scripted)"
[ $((placed + removed)) -eq $((cycles * 10)) ] || fail "expected $((cycles * 10)) voxel edits, got $((placed + removed))"
grep -q "nothing changed" play.out && fail "an edit changed nothing: $(grep -m1 'nothing changed' play.out)"
# Every object command of every cycle, each with its own message.
declare -A want=([place]="place crate_" [move]="move crate_" [turn]="turn crate_" [key]="key crate_"
                 [undo]="undo: key crate_" [redo]="redo: key crate_" [delete]="delete crate_")
declare -A per_cycle=([place]=1 [move]=2 [turn]=1 [key]=1 [undo]=1 [redo]=1 [delete]=1)
counts=""
for command in place move turn key undo redo delete; do
    n=$(grep -cE -- "^frame [0-9]+: ${want[$command]}" play.out)
    counts+="$n $command, "
    [ "$n" -eq $((cycles * per_cycle[$command])) ] ||
        fail "expected $((cycles * per_cycle[$command])) object ${command}s, got $n"
done
echo "object commands: ${counts%, } ($cycles cycles)"

samples=$(grep -c . rss.txt)
total=$((cycles * 10))
after=$(awk -v warm=$((total / 4)) '$1 >= warm' rss.txt | grep -c .)
[ "$after" -ge 20 ] || fail "only $after RSS samples after the warm-up (of $samples)"
# After the warm-up, in MiB: the largest sample of the second quarter of the voxel edits, of the
# second half, and the last.
read -r first peak last < <(awk -v q=$((total / 4)) -v h=$((total / 2)) '
    $1 >= q && $1 < h { if ($2 > f) f = $2 }
    $1 >= h { if ($2 > m) m = $2; l = $2 }
    END { printf "%.1f %.1f %.1f\n", f / 1024, m / 1024, l / 1024 }' rss.txt)
startup=$(awk 'NR == 1 { printf "%.1f", $2 / 1024 }' rss.txt)
echo "RSS: $samples samples; first $startup MiB; after warm-up: second quarter's peak $first, second half's peak $peak, last $last MiB (bound +$bound_mib MiB)"
awk -v a="$first" -v b="$peak" -v bound="$bound_mib" 'BEGIN { exit !(b - a <= bound) }' ||
    fail "RSS grew by more than $bound_mib MiB after the warm-up ($first -> $peak MiB)"

[ $failures -eq 0 ] && echo "soak passed" || echo "$failures failure(s)"
exit $((failures > 0))
