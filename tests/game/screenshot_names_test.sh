#!/usr/bin/env bash
# F12 names its screenshot after the world (issue 41, item 5): `screenshots/NAME-FRAME.png` with
# NAME the scene's `name` as given, so a name like "../outside" or an absolute path wrote outside
# screenshots/ (a name of "/" wrote at the filesystem root). Each hostile name here must leave
# exactly one PNG, inside screenshots/, and nothing anywhere else.
# Usage: screenshot_names_test.sh VOX
set -u
vox="$1"
source "$(dirname "$0")/own_display.sh"
skip_without_own_display
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
start_own_display 640x480 || exit 1

printf '2 tap F12\n+2 quit\n' > "$tmp/f12.script"
i=0
for name in "../outside" "$tmp/absolute" "/" "a/../../b" ".hidden"; do
    i=$((i + 1))
    run="$tmp/run$i/cwd"
    mkdir -p "$run"
    printf '[world]\nname = "%s"\nsize = [32, 16, 32]\n[[material]]\nname = "a"\n[[generator]]\ntype = "box"\nmin = [0, 0, 0]\nmax = [32, 4, 32]\nmaterial = "a"\n' \
        "$name" > "$run/world.toml"
    atRoot=$(find / -xdev -maxdepth 1 -name '*.png' 2>/dev/null | sort)
    (cd "$run" && "$vox" play world.toml --script "$tmp/f12.script" --size 320x180 --method preview --indirect none >play.out 2>play.err)
    rc=$?
    stray=$(comm -13 <(echo "$atRoot") <(find / -xdev -maxdepth 1 -name '*.png' 2>/dev/null | sort))
    [ -n "$stray" ] && rm -f -- $stray
    all=$( (find "$tmp" -name '*.png'; echo "$stray") | grep . | sort)
    inside=$(find "$run/screenshots" -maxdepth 1 -type f -name '*.png' 2>/dev/null)
    if [ "$rc" -ne 0 ]; then
        fail "'$name': vox play exited $rc: $(cat "$run/play.err")"
    elif [ "$(echo "$all" | grep -c .)" -eq 1 ] && [ "$all" = "$inside" ]; then
        echo "ok: '$name' -> ${inside#$run/}"
    else
        fail "'$name': screenshots at: $(echo ${all:-none}) (want one file in $run/screenshots/)"
    fi
    find "$tmp" -name '*.png' -delete
done
exit $((failures > 0))
