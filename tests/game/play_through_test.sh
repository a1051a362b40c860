#!/usr/bin/env bash
# The sandbox's window path, for real, under Xvfb: `vox play --script` flies, places 10
# voxels, removes 3, paints 2, undoes twice, meets the unsaved-changes prompt, saves and quits.
# Then play_through_check replays the edit log on the CPU against the saved world and compares
# the screenshot with headless renders. Artifacts stay in OUT (the window capture is the
# screenshot in docs/).
# Usage: play_through_test.sh VOX CHECK SCRIPT OUT
set -u
vox="$1"; check="$2"; script="$3"; out="$4"

source "$(dirname "$0")/own_display.sh"
skip_without_own_display
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
failures=0
start_own_display 1024x768 || exit 1
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

world=$("$vox" info sandbox --json >/dev/null 2>&1 && echo sandbox)
[ -n "$world" ] || { echo "FAIL: vox info sandbox"; exit 1; }

# Render 128x72 (window 768x432 at scale 1/6); autosave every 0.03 minutes of the script's
# clock (54 frames). Preview lighting without play's default indirect cache, the raw display at a
# fixed exposure: deterministic and at the render size, so the screenshot can be compared pixel
# for pixel with a headless render.
"$vox" play sandbox --script "$script" --size 768x432 \
    --render-scale 0.1667 --method preview --indirect none --display raw --auto-exposure off --save saved.toml --edit-log edits.log --autosave-minutes 0.03 \
    >play.out 2>play.err
rc=$?
cat play.out
[ -s play.err ] && { echo "--- stderr:"; cat play.err; }
[ $rc -eq 0 ] || fail "vox play exited $rc"
grep -q "validation error" play.err && fail "Vulkan validation errors"
[ -f saved.toml ] || fail "no saved.toml"
[ -f sandbox_window.png ] || fail "no window capture"
[ -f play.png ] || fail "no screenshot"
grep -q "screenshot resized.png (640x360, window with HUD)" play.out || fail "the window did not resize to 640x360"

# Quitting with unsaved changes asked first, and the quit after saving went through.
grep -q "unsaved changes: Y saves and quits" play.out || fail "no unsaved-changes prompt"
grep -q "quit cancelled" play.out || fail "the prompt did not cancel"
grep -q "saved saved.toml" play.out || fail "no save"
# Autosaves went to their own file, never over the save, and open as a world.
grep -q "autosaved to saved.autosave.toml" play.out || fail "no autosave"
"$vox" info saved.autosave.toml >/dev/null 2>&1 || fail "the autosave does not open"
grep -q "^# Saved by vox play" saved.toml || fail "saved.toml is not a save"
# The voxels went to the world store the save names (docs/WORLD_STORE.md), which opens on its
# own; the first save wrote the whole world, later ones only the regions edited since.
[ -f saved.db ] || fail "no saved.db store"
grep -q 'type = "store"' saved.toml && grep -q 'source = "saved.db"' saved.toml ||
    fail "saved.toml does not name saved.db"
ls saved.[0-9]*.vdb >/dev/null 2>&1 && fail "a VDB payload was written for the voxels"
"$vox" info saved.db 2>&1 | grep -q "^store .*region(s) stored" || fail "saved.db is not a world store"
grep -q "saved saved.toml (whole world: " play.out || fail "the first save did not write the whole world"

# Edit latency: every edit frame was presented with at most one brick and one cell uploaded
# per changed cell (the renderer's upload counter).
edits=$(grep -c "presented .* edit" play.out)
[ "$edits" -eq 15 ] || fail "$edits edit frames presented, expected 15"
bad=$(grep "presented .* edit" play.out | awk '{ changed=$6; bricks=$10; cells=$12; if (bricks > changed || cells > changed) print }')
[ -z "$bad" ] || fail "frames uploaded more than the edits touched: $bad"
echo "edit frames: $edits, each presented with only the touched bricks uploaded"

"$check" "$(dirname "$script")/../../worlds/sandbox.toml" saved.toml edits.log play.png 10 3 2 2 || fail "play_through_check"

# The save reopens in the sandbox at the saved view (a short second run, no edits), logging
# its frame times: a header and one row per frame at the render size (256x144 at scale 1/4).
"$vox" play saved.toml --frames 2 --size 256x144 --frame-log frames.csv >reopen.out 2>&1 ||
    fail "reopening the save: $(cat reopen.out)"
grep -q "saves to saved.toml" reopen.out || fail "reopened save does not save back to itself"
head -1 frames.csv | grep -q "^frame,wall_ms,render_call_ms,gpu_ms,present_gpu_ms,render_width,render_height,stream_regions,stream_in,stream_in_ms,stream_out,stream_out_ms$" ||
    fail "frames.csv header: $(head -1 frames.csv)"
rows=$(awk -F, 'NR > 1 && $2 > 0 && $3 > 0 && $4 > 0 && $6 == 64 && $7 == 36' frames.csv | wc -l)
[ "$rows" -eq 2 ] || fail "frames.csv: expected 2 frame rows at 64x36 with times, got: $(cat frames.csv)"

[ $failures -eq 0 ] && echo "play-through passed" || echo "$failures failure(s)"
exit $((failures > 0))
