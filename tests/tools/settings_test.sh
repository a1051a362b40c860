#!/usr/bin/env bash
# One settings path: `vox render`, `vox capture` and `vox play` merge a world's lighting with the
# same flags into the same settings, and refuse out-of-range values with the same message.
source "$(dirname "$0")/test_setup.sh"

# A world whose [indirect] table asks for the cache with its own alpha.
cp "$(dirname "$0")/../../worlds/cornell.toml" "$tmp/lit.toml"
printf '\n[indirect]\nmode = "cache"\nalpha = 0.1\n' >> "$tmp/lit.toml"

# The display's knobs given too: each command has its own defaults for them (docs/DISPLAY.md).
flags=(--cache-rays 8 --candidates 12 --spatial 3,20 --display denoised --auto-exposure on)
render=$("$vox" render "$tmp/lit.toml" "${flags[@]}" --show-settings) || fail "render --show-settings exited $?"
play=$("$vox" play "$tmp/lit.toml" "${flags[@]}" --show-settings) || fail "play --show-settings exited $?"
capture=$("$vox" capture "$tmp/lit.toml" "${flags[@]}" --show-settings --out "$tmp/cap") || fail "capture --show-settings exited $?"
[ "$render" = "$play" ] || fail "render and play differ:$(diff <(echo "$render") <(echo "$play"))"
[ "$render" = "$capture" ] || fail "render and capture differ:$(diff <(echo "$render") <(echo "$capture"))"
for want in "--indirect cache" "--cache-alpha 0.1" "--cache-rays 8" "--candidates 12" "--spatial 3,20"; do
    grep -qx -- "$want" <<< "$render" || fail "render settings lack '$want':"$'\n'"$render"
done
[ "$failures" -eq 0 ] && echo "ok: render, play and capture agree ($(wc -l <<< "$render") knobs)"

# Each command's own defaults: play lights fully (the cache) and reconstructs; render reconstructs
# but stays direct; a scene's [indirect] mode wins over play's default.
cp "$(dirname "$0")/../../worlds/cornell.toml" "$tmp/plain.toml"
cp "$tmp/plain.toml" "$tmp/direct.toml"
printf '\n[indirect]\nmode = "none"\n' >> "$tmp/direct.toml"
play=$("$vox" play "$tmp/plain.toml" --show-settings) || fail "play --show-settings exited $?"
render=$("$vox" render "$tmp/plain.toml" --show-settings) || fail "render --show-settings exited $?"
direct=$("$vox" play "$tmp/direct.toml" --show-settings) || fail "play --show-settings exited $?"
for want in "--indirect cache" "--display denoised" "--auto-exposure on"; do
    grep -qx -- "$want" <<< "$play" || fail "play's defaults lack '$want':"$'\n'"$play"
done
grep -qx -- "--indirect none" <<< "$render" || fail "render's default is not direct light only"
grep -qx -- "--indirect none" <<< "$direct" || fail "the scene's [indirect] mode = none lost to play's default"
[ "$failures" -eq 0 ] && echo "ok: play defaults to the cache, render to direct light, a scene's mode wins"

# Out of range: refused by every entry point with the same one line.
for bad in "--candidates 0" "--cache-rays 7" "--cache-alpha 2" "--spatial 40,10" "--mode spot"; do
    read -r -a args <<< "$bad"
    r=$("$vox" render "$tmp/lit.toml" "${args[@]}" --show-settings 2>&1 >/dev/null); rr=$?
    p=$("$vox" play "$tmp/lit.toml" "${args[@]}" --show-settings 2>&1 >/dev/null); pr=$?
    if [ $rr -eq 0 ] || [ $pr -eq 0 ] || [ "$r" != "$p" ] || [ "$(grep -c . <<< "$r")" -ne 1 ]; then
        fail "'$bad': render exit $rr '$r', play exit $pr '$p'"
    else
        echo "ok: '$bad' refused: $r"
    fi
done

# A scene file's out-of-range [indirect] value is refused naming the file and line.
cp "$(dirname "$0")/../../worlds/cornell.toml" "$tmp/bad.toml"
printf '\n[indirect]\nrays = 7\n' >> "$tmp/bad.toml"
err=$("$vox" render "$tmp/bad.toml" --show-settings 2>&1 >/dev/null) && fail "a scene with rays = 7 was accepted"
grep -q "bad.toml" <<< "$err" || fail "the error does not name the file: $err"
echo "ok: $err"
exit $((failures > 0))
