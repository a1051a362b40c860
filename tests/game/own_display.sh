# Sourced by the window tests: an X server (Xvfb) of the test's own, with DISPLAY pointing at it.
#
# Why not xvfb-run: it writes its own messages (e.g. "problem while cleaning up temporary
# directory") into the stderr the test reads as vox's, and `-a`/`-n` pick a display number by
# guessing, which two tests started together by `ctest -j2` can both guess. Xvfb's -displayfd
# makes the server itself claim the first free display (the kernel's lock file decides), so no
# two servers can share one, and vox's streams hold only what vox printed.
#
# Usage (bash):
#   source own_display.sh
#   own_display_available || { echo "SKIP: ..."; exit 77; }
#   start_own_display 1024x768 || exit 1     # exports DISPLAY; the server stops when the shell exits
#   ... "$vox" play ...

own_display_available() { command -v Xvfb >/dev/null 2>&1; }
# Ends the test as skipped (ctest's SKIP_RETURN_CODE 77) when there is no Xvfb to start.
skip_without_own_display() {
    own_display_available && return 0
    echo "SKIP: Xvfb not found (apt-get install xvfb; tools/setup.sh installs it)"
    exit 77
}

OWN_DISPLAY_PID=""
OWN_DISPLAY_DIR=""

stop_own_display() {
    [ -n "$OWN_DISPLAY_PID" ] && kill "$OWN_DISPLAY_PID" 2>/dev/null && wait "$OWN_DISPLAY_PID" 2>/dev/null
    [ -n "$OWN_DISPLAY_DIR" ] && rm -rf "$OWN_DISPLAY_DIR"
    OWN_DISPLAY_PID=""
    OWN_DISPLAY_DIR=""
}

# start_own_display WxH: starts Xvfb on a free display and exports DISPLAY. Chains onto any EXIT
# trap the test set before, so both run.
start_own_display() {
    local size="${1:-1024x768}"
    OWN_DISPLAY_DIR=$(mktemp -d)
    Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp -noreset \
        3>"$OWN_DISPLAY_DIR/display" >"$OWN_DISPLAY_DIR/xvfb.log" 2>&1 &
    OWN_DISPLAY_PID=$!
    local previous
    previous=$(trap -p EXIT | sed -e "s/^trap -- '//" -e "s/' EXIT\$//")
    # shellcheck disable=SC2064
    trap "stop_own_display; $previous" EXIT
    # The server writes its display number once it accepts connections (at most ~10 s here).
    local _
    for _ in $(seq 200); do
        [ -s "$OWN_DISPLAY_DIR/display" ] && break
        kill -0 "$OWN_DISPLAY_PID" 2>/dev/null || break
        sleep 0.05
    done
    if [ ! -s "$OWN_DISPLAY_DIR/display" ]; then
        echo "FAIL: Xvfb did not start: $(tail -3 "$OWN_DISPLAY_DIR/xvfb.log" | tr '\n' ' ')"
        return 1
    fi
    export DISPLAY=":$(head -1 "$OWN_DISPLAY_DIR/display")"
}
