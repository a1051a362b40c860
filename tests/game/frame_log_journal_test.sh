#!/usr/bin/env bash
# `vox play --frame-log` is a journal: every presented frame's row is in the file while the
# session runs, so a session stopped early (here kill -9) keeps its rows, each complete. A write
# error (full.csv, a link to /dev/full) is one line and a non-zero exit at the end. The link, not
# /dev/full itself: a binary that writes its logs atomically renames over the path it is given,
# which would put a regular file in place of /dev/full.
# Usage: frame_log_journal_test.sh VOX
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
ln -s /dev/full full.csv

printf '[world]\nname = "tiny"\nsize = [32, 16, 32]\n[[material]]\nname = "a"\n[[generator]]\ntype = "box"\nmin = [0, 0, 0]\nmax = [32, 4, 32]\nmaterial = "a"\n' > tiny.toml
header="frame,wall_ms,render_call_ms,gpu_ms,present_gpu_ms,render_width,render_height,stream_regions,stream_in,stream_in_ms,stream_out,stream_out_ms"
rows() { if [ -f frames.csv ]; then awk 'NR > 1 && NF' frames.csv | wc -l; else echo 0; fi; }

# Killed once 5 rows are in the file; a log written only at exit never gets there while the
# session runs (it would end after its 3000 frames, failing the test).
"$vox" play tiny.toml --frames 3000 --size 160x90 --method preview --indirect none \
    --frame-log frames.csv >play.out 2>&1 &
pid=$!
while kill -0 "$pid" 2>/dev/null && [ "$(rows)" -lt 5 ]; do sleep 0.2; done
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
rc=$?
# 137: killed (128 + SIGKILL); anything else: the session ended on its own, having written its
# rows only then (a process that has exited still answers kill -0 until waited for).
if [ "$rc" -eq 137 ]; then
    [ "$(head -1 frames.csv)" = "$header" ] || fail "frames.csv header: $(head -1 frames.csv)"
    bad=$(awk -F, 'NR > 1 && (NF != 12 || $1 != NR - 2 || $2 <= 0)' frames.csv)
    [ -z "$bad" ] || fail "incomplete or misnumbered rows: $bad"
    [ -z "$(tail -c 1 frames.csv)" ] || fail "the last row is cut short: $(tail -1 frames.csv)"
else
    fail "the session ended (exit $rc) before its frame log had 5 rows (rows written only at exit?): $(rows) rows"
fi

"$vox" play tiny.toml --frames 2 --size 160x90 --method preview --indirect none \
    --frame-log full.csv >full.out 2>full.err
rc=$?
[ "$rc" -ne 0 ] && [ "$(grep -c . full.err)" -eq 1 ] &&
    grep -q "^vox play: full.csv: cannot write the frame log (disk full?)$" full.err ||
    fail "a frame log on a full disk: exit $rc, stderr: $(cat full.err)"

if [ $failures -eq 0 ]; then
    echo "ok: $(rows) rows kept by a killed session; $(cat full.err)"
fi
exit $((failures > 0))
