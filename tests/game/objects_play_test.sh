#!/usr/bin/env bash
# The object tool for real, under Xvfb: `vox play sandbox --model crate.toml --script` places the crate
# at the crosshair, keys it, moves and turns it (so its path has four keys), undoes and redoes
# the turn and saves. The save must hold it (crate_2: the sandbox has a cart) with those keys, looping, its model in
# a payload of its own that `vox info` opens with the save. A model beyond the cap is refused
# with a message naming the cap.
# Usage: objects_play_test.sh VOX SCRIPT OUT
set -u
vox="$1"; script="$2"; out="$3"

source "$(dirname "$0")/own_display.sh"
skip_without_own_display
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
failures=0
start_own_display 1024x768 || exit 1
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# A 3 x 3 x 2 crate with a lamp on one corner (13 voxels), the unit tests' model too.
cp "$(dirname "$script")/crate.toml" crate.toml || exit 1

"$vox" play sandbox --model crate.toml --script "$script" --size 512x288 --render-scale 0.25 \
    --method preview --indirect none --save saved.toml >play.out 2>play.err
rc=$?
cat play.out
[ -s play.err ] && { echo "--- stderr:"; cat play.err; }
[ $rc -eq 0 ] || fail "vox play exited $rc"
grep -q "validation error" play.err && fail "Vulkan validation errors"
grep -q "place crate_2 (13 voxels)" play.out || fail "no object placed"
grep -q "key crate_2 at" play.out || fail "no key set"
grep -q "move crate_2 by 1 0 0" play.out || fail "no move"
grep -q "turn crate_2 to 90 degrees" play.out || fail "no turn"
grep -q "undo: turn crate_2" play.out || fail "the turn was not undone"
grep -q "redo: turn crate_2" play.out || fail "the turn was not redone"
grep -q "saved saved.toml" play.out || fail "no save"
[ -f objects_window.png ] || fail "no window capture"

# The save: the sandbox's own object (the cart) and crate_2 with four keys (place, K, move,
# turn), looping, the last turned 90 degrees, the move one voxel along +X; its model in a
# payload of its own.
crate=$(awk '/^\[\[object\]\]/ { o = 0 } /^name = "crate_2"/ { o = 1 } /^\[\[camera\]\]/ { o = 0 } o' saved.toml)
[ "$(grep -c '^\[\[object\]\]' saved.toml)" -eq 2 ] || fail "expected two [[object]]s in saved.toml (cart, crate_2)"
[ -n "$crate" ] || fail "no crate_2 in saved.toml"
[ "$(echo "$crate" | grep -c '^\[\[object.key\]\]')" -eq 4 ] || fail "expected 4 keys of crate_2"
echo "$crate" | grep -q '^loop = true' || fail "the path does not loop"
[ "$(echo "$crate" | grep -c '^rotation = \[90.0, 0.0, 0.0\]')" -eq 1 ] || fail "expected one key turned 90 degrees"
x=$(echo "$crate" | awk -F'[][, ]+' '/^position = / { print $3 }')
set -- $x
[ $# -eq 4 ] && [ "$1" = "$2" ] && awk -v a="$2" -v b="$3" 'BEGIN { exit !(b - a == 1) }' ||
    fail "key x positions: $x (expected a, a, a+1, ...)"
model=$(echo "$crate" | sed -n 's/^source = "\(saved.object-.*\.vdb\)"$/\1/p')
[ -n "$model" ] && [ -f "$model" ] || fail "crate_2's model payload is missing: '$model'"
[ "$(ls saved.object-*.vdb | wc -l)" -eq 2 ] || fail "expected two object payloads: $(ls saved.object-*.vdb)"
"$vox" info saved.toml >info.out 2>&1 || fail "the save does not open: $(cat info.out)"
echo "$crate"

# A model beyond the cap is refused, before any window opens.
"$vox" play sandbox --model sandbox --frames 1 >big.out 2>big.err
rc=$?
[ $rc -ne 0 ] || fail "a model of the whole sandbox world was accepted"
grep -q "a model holds at most 16384" big.err || fail "no cap message: $(cat big.err)"

[ $failures -eq 0 ] && echo "objects test passed" || echo "$failures failure(s)"
exit $((failures > 0))
