#!/usr/bin/env bash
# Walk mode in a real window under Xvfb: `vox play --script tests/game/walk.script` in
# tests/game/walk_world.toml with a walk log, then walk_check checks every walk frame's player
# box against the CPU grid and the raft posed at that frame's time, and what the walk must show
# (the step climbed, the wall not passed, the ride, the jump, the crouch). The place edit aimed
# at the player's own feet must be refused. Artifacts stay in OUT.
# Usage: walk_test.sh VOX CHECK SCRIPT WORLD OUT
set -u
vox="$1"; check="$2"; script="$3"; world="$4"; out="$5"

source "$(dirname "$0")/own_display.sh"
skip_without_own_display
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Render 128x72 (window 256x144 at scale 1/2), preview lighting.
start_own_display 1024x768 || exit 1
"$vox" play "$world" --script "$script" \
    --size 256x144 --render-scale 0.5 --method preview --indirect none --walk-log walk.csv --frame-log frames.csv \
    >play.out 2>play.err
rc=$?
cat play.out
[ -s play.err ] && { echo "--- stderr:"; cat play.err; }
[ $rc -eq 0 ] || fail "vox play exited $rc"
grep -q "validation error" play.err && fail "Vulkan validation errors"
grep -q "^frame 0: walk mode" play.out || fail "walk mode did not start"
grep -q "refused: it would enclose the player" play.out || fail "the place edit at the player's feet was not refused"
grep -q "presented .* edit" play.out && fail "an edit went through"
grep -q "fly mode" play.out || fail "F did not return to fly mode"
"$check" "$world" walk.csv || fail "walk_check"

[ $failures -eq 0 ] && echo "walk passed" || echo "$failures failure(s)"
exit $((failures > 0))
